/* fuzz_light_scissor: sk_light_scissor(light_pos, radius, view_proj, vp_w,
   vp_h, out_rect).
   Input: light_pos (vec3), radius (float), view_proj (fz_mat4), vp_w, vp_h
   (int 0..4096), a byte (bit 0: out_rect NULL).
   Checks: 0 or 1; NULL rect gives 0; bad input (non-finite, radius <= 0,
   viewport < 1, matrix not finite) gives 0 with the rect zeroed; 0 always
   zeroes the rect; 1 gives a rect of at least 1 x 1 inside the viewport;
   with every corner of the range box clearly in front of the eye (clip w
   in double, away from 0 beyond rounding) the rect holds each corner's window position
   clamped to the viewport, and a 0 means that clamped box is (nearly)
   empty; with corners clearly on both sides, the full viewport; with all
   clearly behind, 0. */
#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size};
    sk_vec3 lp = fz_vec3(&in);
    float radius = fz_float(&in);
    sk_mat4 vp = fz_mat4(&in);
    int vw = fz_int(&in, 0, 4096), vh = fz_int(&in, 0, 4096);
    int null_rect = fz_u8(&in) & 1;
    int rect[4] = {-7, -7, -7, -7}, r, i, front = 0, behind = 0, unsure = 0;
    int bad = !fz_v3_finite(lp) || !fz_finite(radius) || !(radius > 0.0f) || vw < 1 || vh < 1 || !fz_mat_finite(&vp);
    double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
    if (null_rect) {
        FZ_CHECK(sk_light_scissor(lp, radius, vp, vw, vh, NULL) == 0, "NULL rect");
        return 0;
    }
    r = sk_light_scissor(lp, radius, vp, vw, vh, rect);
    FZ_CHECK(r == 0 || r == 1, "r = %d", r);
    if (r == 0 || bad)
        FZ_CHECK(r == 0 && rect[0] == 0 && rect[1] == 0 && rect[2] == 0 && rect[3] == 0,
                 "r = %d (bad %d), rect {%d %d %d %d}", r, bad, rect[0], rect[1], rect[2], rect[3]);
    if (r == 1)
        FZ_CHECK(rect[0] >= 0 && rect[1] >= 0 && rect[2] >= 1 && rect[3] >= 1 && (long)rect[0] + rect[2] <= vw &&
                 (long)rect[1] + rect[3] <= vh,
                 "rect {%d %d %d %d} in %d x %d", rect[0], rect[1], rect[2], rect[3], vw, vh);
    if (bad) return 0;
    /* the box corners in double; only those whose clip w is clearly away
       from 0 (beyond the rounding of the sums) decide */
    for (i = 0; i < 8; i++) {
        double c[3], q[3], w, mag = 0.0;
        int k;
        c[0] = (double)lp.x + ((i & 1) ? radius : -radius);
        c[1] = (double)lp.y + ((i & 2) ? radius : -radius);
        c[2] = (double)lp.z + ((i & 4) ? radius : -radius);
        for (k = 0; k < 3; k++)
            q[k] = vp.m[k] * c[0] + vp.m[4 + k] * c[1] + vp.m[8 + k] * c[2] + vp.m[12 + k];
        w = vp.m[3] * c[0] + vp.m[7] * c[1] + vp.m[11] * c[2] + vp.m[15];
        for (k = 0; k < 4; k++) mag += fabs((double)vp.m[k * 4 + 3]) * (k < 3 ? fabs(c[k]) : 1.0);
        if (!(fabs(w) > 1e-5 * mag) || mag > 1e30) { unsure = 1; continue; }
        if (w < 0.0) { behind++; continue; }
        front++;
        {
            double x = (0.5 * q[0] / w + 0.5) * vw, y = (0.5 * q[1] / w + 0.5) * vh;
            if (x < xmin) xmin = x;
            if (x > xmax) xmax = x;
            if (y < ymin) ymin = y;
            if (y > ymax) ymax = y;
        }
    }
    if (unsure) return 0;
    if (behind == 8) FZ_CHECK(r == 0, "all behind, r = 1");
    else if (behind > 0)
        FZ_CHECK(r == 1 && rect[0] == 0 && rect[1] == 0 && rect[2] == vw && rect[3] == vh,
                 "straddling the eye: r %d rect {%d %d %d %d}", r, rect[0], rect[1], rect[2], rect[3]);
    else if (xmax - xmin < 1e9 && ymax - ymin < 1e9) {
        double cx0 = xmin < 0 ? 0 : xmin, cx1 = xmax > vw ? vw : xmax;
        double cy0 = ymin < 0 ? 0 : ymin, cy1 = ymax > vh ? vh : ymax;
        double tol = 1e-3 * (1.0 + vw + vh + fabs(xmin) + fabs(xmax) + fabs(ymin) + fabs(ymax));
        if (r == 1)
            FZ_CHECK(cx0 >= rect[0] - tol && cx1 <= rect[0] + rect[2] + tol && cy0 >= rect[1] - tol &&
                     cy1 <= rect[1] + rect[3] + tol,
                     "box [%g %g] x [%g %g] not inside rect {%d %d %d %d}", cx0, cx1, cy0, cy1, rect[0], rect[1],
                     rect[2], rect[3]);
        else
            FZ_CHECK(cx1 - cx0 <= tol || cy1 - cy0 <= tol, "box [%g %g] x [%g %g] on screen, r = 0", cx0, cx1, cy0, cy1);
    }
    return 0;
}

#ifdef FZ_SEED_MAIN
static void fz_seeds(void)
{
    static const float lights[][4] = {{0, 0, -10, 2}, {3, 1, -5, 1}, {0, 0, 0, 3}, {50, 0, -10, 1}, {0, 0, 10, 1}};
    size_t i;
    for (i = 0; i < sizeof lights / sizeof lights[0]; i++) {
        fz_out o = {{0}, 0};
        fz_put_vec3(&o, lights[i][0], lights[i][1], lights[i][2]);
        fz_put_float(&o, lights[i][3]);
        fz_put_persp(&o, 0, 0, 0, 0, 0, -1, 1.0f, 1.6f, 0.1f, 100.0f);
        fz_put_int(&o, 1280);
        fz_put_int(&o, 800);
        fz_put_u8(&o, 0);
        fz_seed(&o);
    }
}
#endif
