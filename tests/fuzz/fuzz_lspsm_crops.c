/* fuzz_lspsm_crops: sk_lspsm_crops(region, params, out_view_proj, out_rects, cap)
   on regions filled field by field (as a caller could), not only on what
   sk_lspsm_region_extract makes (fuzz_lspsm_region does that).
   Input: light_view (fz_mat4), origin (vec2), n, L, theta, zmin, zmax
   (float), fallback (int 0..1), zeta, sigma (float), h_max, nw_max (int
   0..12), cap (int -1..64), then a byte: bit 0 passes out_rects = NULL.
   Checks: -SK_ERR_INVALID_ARG on the documented bad input, nothing written;
   an error (also -SK_ERR_CAPACITY, -SK_ERR_DEGENERATE) writes nothing; a count is in [1, cap] (1 for a fallback region),
   every matrix and rect finite, nothing written past cap; the rects are
   sk_lspsm_partition's moved by the origin (the fallback's one rect is
   [-n/2, n/2] x [0, L] moved so), and for a rigid light view each matrix
   maps its rect at zmin and zmax into the clip cube. */
#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size};
    sk_lspsm_region reg;
    sk_lspsm_params p;
    sk_mat4 *vps;
    sk_rect *rects, *part;
    int cap, with_rects, r, i, valid, lv_mode;
    size_t vbytes, rbytes;
    memset(&reg, 0, sizeof reg);
    reg.light_view = fz_mat4_mode(&in, &lv_mode);
    reg.origin = fz_vec2(&in);
    reg.n = fz_float(&in);
    reg.L = fz_float(&in);
    reg.theta = fz_float(&in);
    reg.zmin = fz_float(&in);
    reg.zmax = fz_float(&in);
    reg.fallback = fz_int(&in, 0, 1);
    p.zeta = fz_float(&in);
    p.sigma = fz_float(&in);
    p.h_max = fz_int(&in, 0, 12);
    p.nw_max = fz_int(&in, 0, 12);
    cap = fz_int(&in, -1, 64);
    if (cap > 4096) cap = 4096;
    with_rects = !(fz_u8(&in) & 1);
    valid = fz_finite(p.zeta) && fz_finite(p.sigma) && p.zeta > 0.0f && p.zeta < 0.5f && p.sigma > 0.0f &&
            p.h_max >= 1 && p.nw_max >= 1 && fz_mat_finite(&reg.light_view) && fz_finite(reg.n) &&
            fz_finite(reg.L) && fz_finite(reg.theta) && reg.n > 0.0f && reg.L > 0.0f && reg.theta >= 0.0f &&
            (double)reg.theta < 0.5 * 3.14159265358979323846 && fz_finite(reg.zmin) && fz_finite(reg.zmax) &&
            fz_finite(reg.origin.x) && fz_finite(reg.origin.y) && cap >= 0;
    vbytes = (size_t)(cap > 0 ? cap : 0) * sizeof(sk_mat4);
    rbytes = (size_t)(cap > 0 ? cap : 0) * sizeof(sk_rect);
    vps = (sk_mat4 *)fz_alloc(vbytes);
    rects = (sk_rect *)fz_alloc(rbytes);
    part = (sk_rect *)fz_alloc(rbytes);
    r = sk_lspsm_crops(&reg, &p, vps, with_rects ? rects : NULL, cap);
    if (!valid || r < 0) {
        FZ_CHECK(valid || r == -(int)SK_ERR_INVALID_ARG, "r = %d on bad input", r);
        FZ_CHECK(r == -(int)SK_ERR_INVALID_ARG || r == -(int)SK_ERR_CAPACITY || r == -(int)SK_ERR_DEGENERATE,
                 "r = %d", r);
        FZ_CHECK(fz_untouched(vps, vbytes) && fz_untouched(rects, rbytes), "written on error %d", r);
    } else {
        int np = reg.fallback ? 1 : sk_lspsm_partition(reg.n, reg.L, reg.theta, &p, part, cap);
        FZ_CHECK(r >= 1 && r <= cap, "count %d, cap %d", r, cap);
        FZ_CHECK(!reg.fallback || r == 1, "fallback region gave %d maps", r);
        FZ_CHECK(np == r, "sk_lspsm_partition gives %d, sk_lspsm_crops %d", np, r);
        FZ_CHECK(fz_guard_ok(vps, (size_t)r * sizeof(sk_mat4)), "matrices written past %d", r);
        FZ_CHECK(with_rects ? fz_guard_ok(rects, (size_t)r * sizeof(sk_rect)) : fz_untouched(rects, rbytes),
                 "rects written past %d", r);
        if (reg.fallback) {
            part[0].x0 = (float)(-0.5 * reg.n); part[0].x1 = (float)(0.5 * reg.n);
            part[0].y0 = 0.0f; part[0].y1 = reg.L;
        }
        for (i = 0; i < r; i++) {
            sk_rect want = part[i];
            want.x0 += reg.origin.x; want.x1 += reg.origin.x;
            want.y0 += reg.origin.y; want.y1 += reg.origin.y;
            FZ_CHECK(fz_mat_finite(&vps[i]), "matrix %d not finite", i);
            if (with_rects) {
                const sk_rect *q = &rects[i];
                FZ_CHECK(fz_finite(q->x0) && fz_finite(q->y0) && fz_finite(q->x1) && fz_finite(q->y1),
                         "rect %d = (%g %g %g %g)", i, q->x0, q->y0, q->x1, q->y1);
                FZ_CHECK(q->x0 == want.x0 && q->x1 == want.x1 && q->y0 == want.y0 && q->y1 == want.y1,
                         "rect %d = (%g %g %g %g), partition + origin (%g %g %g %g)", i, q->x0, q->y0, q->x1,
                         q->y1, want.x0, want.y0, want.x1, want.y1);
            }
            /* the rect's corners at both depths, taken back to world space,
               land in the clip cube (a rigid view: its inverse is exact
               enough). Float rounding of the round trip is relative to the
               largest coordinate, the allowance per axis relative to that
               axis's extent (as widened by the library, 1e-4 of its
               magnitude at least). */
            if (lv_mode == FZ_M_VIEW && fz_is_rigid(&reg.light_view, 1e4f) && fz_moderate(want.x0, 1e4f) &&
                fz_moderate(want.x1, 1e4f) && fz_moderate(want.y0, 1e4f) && fz_moderate(want.y1, 1e4f) &&
                fz_moderate(reg.zmin, 1e4f) && fz_moderate(reg.zmax, 1e4f) && reg.zmin <= reg.zmax) {
                sk_mat4 inv;
                double lo[3], hi[3], tol[3], mag = 0.0;
                int c, k;
                lo[0] = want.x0; hi[0] = want.x1; lo[1] = want.y0; hi[1] = want.y1; lo[2] = reg.zmin; hi[2] = reg.zmax;
                for (k = 0; k < 3; k++) {
                    if (fabs(lo[k]) > mag) mag = fabs(lo[k]);
                    if (fabs(hi[k]) > mag) mag = fabs(hi[k]);
                    if (fabs(reg.light_view.m[12 + k]) > mag) mag = fabs(reg.light_view.m[12 + k]);
                }
                for (k = 0; k < 3; k++) {
                    double ext = hi[k] - lo[k], wide = 1e-4 * (1.0 + fabs(lo[k]) + fabs(hi[k]));
                    tol[k] = 1e-3 + 1e-5 * (1.0 + mag) / (ext > wide ? ext : wide);
                }
                FZ_CHECK(sk_mat4_inverse(reg.light_view, &inv), "rigid view not invertible");
                for (c = 0; c < 8; c++) {
                    sk_vec3 lp, wp;
                    double q[3], w;
                    lp.x = (float)((c & 1) ? hi[0] : lo[0]);
                    lp.y = (float)((c & 2) ? hi[1] : lo[1]);
                    lp.z = (float)((c & 4) ? hi[2] : lo[2]);
                    wp = sk_mat4_transform_point(inv, lp);
                    w = fz_xform(&vps[i], wp, q);
                    FZ_CHECK(fabs(w - 1.0) < 1e-3 && fabs(q[0]) <= 1.0 + tol[0] && fabs(q[1]) <= 1.0 + tol[1] &&
                             fabs(q[2]) <= 1.0 + tol[2],
                             "map %d: corner %d (%g %g %g) -> (%g %g %g; %g), tol %g %g %g", i, c, lp.x, lp.y, lp.z,
                             q[0], q[1], q[2], w, tol[0], tol[1], tol[2]);
                }
            }
        }
    }
    free(vps);
    free(rects);
    free(part);
    return 0;
}

#ifdef FZ_SEED_MAIN
static void fz_seeds(void)
{
    /* n, L, theta, fallback */
    static const float cases[][4] = {
        {1.0f, 10.0f, 0.4f, 0}, {2.0f, 30.0f, 1.0f, 0}, {5.0f, 5.0f, 0.0f, 1}, {0.1f, 100.0f, 1.4f, 0}
    };
    size_t i;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        fz_out o = {{0}, 0};
        fz_put_view(&o, 0, 10, 0, 1, 0, 0.5f);
        fz_put_vec2(&o, 0.5f, -2.0f);
        fz_put_float(&o, cases[i][0]);
        fz_put_float(&o, cases[i][1]);
        fz_put_float(&o, cases[i][2]);
        fz_put_float(&o, -20.0f);
        fz_put_float(&o, 5.0f);
        fz_put_int(&o, (int)cases[i][3]);
        fz_put_float(&o, 0.25f);
        fz_put_float(&o, 0.5f);
        fz_put_int(&o, 4);
        fz_put_int(&o, 2);
        fz_put_int(&o, 16);
        fz_put_u8(&o, (unsigned)i & 1);
        fz_seed(&o);
    }
}
#endif
