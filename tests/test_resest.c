/* tests/test_resest.c - resolution estimation (Ferko 2013,
   Sec. 3.1-3.2): sk_estimate_resolution.

   Depth buffers are rendered analytically here: for each pixel centre the
   camera ray is intersected (in double) with planes and boxes and the window
   depth of the hit is stored. Expected values come from
     - the seed's stated property: identical camera and light matrices over a
       full-screen receiver give the camera's own resolution (+/-1);
     - hand-derived scalings (zoomed camera, cropped light, half-screen light);
     - a naive double-precision re-implementation of Sec. 3.2 in this file
       (each pixel's four corners, each corner's depth the average of the valid
       pixels around it, unprojected, transformed to light clip space, patch
       extents, minimum over the samples inside the light's clip volume). */
#define SHADOWKIT_IMPLEMENTATION
#include "shadowkit.h"
#include "tests/sk_test.h"
#include <stdlib.h>

#define PI_D 3.14159265358979323846

/* ================================================================ double matrices */
typedef struct dm4 { double m[16]; } dm4;   /* column-major, like sk_mat4 */

static dm4 dm_identity(void) {
    dm4 r;
    int i;
    for (i = 0; i < 16; i++) r.m[i] = (i % 5 == 0) ? 1.0 : 0.0;
    return r;
}
static dm4 dm_mul(dm4 a, dm4 b) {
    dm4 r;
    int c, rr, k;
    for (c = 0; c < 4; c++)
        for (rr = 0; rr < 4; rr++) {
            double s = 0;
            for (k = 0; k < 4; k++) s += a.m[k * 4 + rr] * b.m[c * 4 + k];
            r.m[c * 4 + rr] = s;
        }
    return r;
}
static void dm_apply(const dm4 *m, const double p[4], double out[4]) {
    int r;
    for (r = 0; r < 4; r++)
        out[r] = m->m[r] * p[0] + m->m[4 + r] * p[1] + m->m[8 + r] * p[2] + m->m[12 + r] * p[3];
}
static dm4 dm_perspective(double fovy, double aspect, double n, double f) {
    dm4 r;
    double t = 1.0 / tan(fovy / 2);
    int i;
    for (i = 0; i < 16; i++) r.m[i] = 0;
    r.m[0] = t / aspect;
    r.m[5] = t;
    r.m[10] = (f + n) / (n - f);
    r.m[11] = -1;
    r.m[14] = 2 * f * n / (n - f);
    return r;
}
static dm4 dm_ortho(double l, double rt, double b, double t, double n, double f) {
    dm4 r = dm_identity();
    r.m[0] = 2 / (rt - l);
    r.m[5] = 2 / (t - b);
    r.m[10] = -2 / (f - n);
    r.m[12] = -(rt + l) / (rt - l);
    r.m[13] = -(t + b) / (t - b);
    r.m[14] = -(f + n) / (f - n);
    return r;
}
static void d3_norm(double v[3]) {
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    v[0] /= l; v[1] /= l; v[2] /= l;
}
static void d3_cross(const double a[3], const double b[3], double o[3]) {
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}
static dm4 dm_look_at(double ex, double ey, double ez, double tx, double ty, double tz,
                      double ux, double uy, double uz) {
    double f[3], s[3], u[3], up[3];
    dm4 r = dm_identity();
    f[0] = tx - ex; f[1] = ty - ey; f[2] = tz - ez;
    up[0] = ux; up[1] = uy; up[2] = uz;
    d3_norm(f);
    d3_cross(f, up, s);
    d3_norm(s);
    d3_cross(s, f, u);
    r.m[0] = s[0]; r.m[4] = s[1]; r.m[8] = s[2];
    r.m[1] = u[0]; r.m[5] = u[1]; r.m[9] = u[2];
    r.m[2] = -f[0]; r.m[6] = -f[1]; r.m[10] = -f[2];
    r.m[12] = -(s[0] * ex + s[1] * ey + s[2] * ez);
    r.m[13] = -(u[0] * ex + u[1] * ey + u[2] * ez);
    r.m[14] = f[0] * ex + f[1] * ey + f[2] * ez;
    return r;
}
/* Gauss-Jordan with partial pivoting */
static dm4 dm_inverse(dm4 a) {
    double t[4][8];
    dm4 r;
    int i, j, k;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) {
            t[i][j] = a.m[j * 4 + i];
            t[i][4 + j] = (i == j) ? 1.0 : 0.0;
        }
    for (k = 0; k < 4; k++) {
        int p = k;
        for (i = k + 1; i < 4; i++) if (fabs(t[i][k]) > fabs(t[p][k])) p = i;
        if (p != k) for (j = 0; j < 8; j++) { double x = t[k][j]; t[k][j] = t[p][j]; t[p][j] = x; }
        for (j = 7; j >= k; j--) t[k][j] /= t[k][k];
        for (i = 0; i < 4; i++)
            if (i != k) {
                double f = t[i][k];
                for (j = k; j < 8; j++) t[i][j] -= f * t[k][j];
            }
    }
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) r.m[j * 4 + i] = t[i][4 + j];
    return r;
}
static sk_mat4 to_f(dm4 a) { sk_mat4 r; int i; for (i = 0; i < 16; i++) r.m[i] = (float)a.m[i]; return r; }
static dm4 to_d(sk_mat4 a) { dm4 r; int i; for (i = 0; i < 16; i++) r.m[i] = a.m[i]; return r; }
/* rows-as-written 4x4 (for small hand-made clip-space transforms) */
static dm4 dm_rows(double a00, double a01, double a02, double a03, double a10, double a11, double a12, double a13,
                   double a20, double a21, double a22, double a23, double a30, double a31, double a32, double a33) {
    dm4 r;
    r.m[0] = a00; r.m[4] = a01; r.m[8] = a02; r.m[12] = a03;
    r.m[1] = a10; r.m[5] = a11; r.m[9] = a12; r.m[13] = a13;
    r.m[2] = a20; r.m[6] = a21; r.m[10] = a22; r.m[14] = a23;
    r.m[3] = a30; r.m[7] = a31; r.m[11] = a32; r.m[15] = a33;
    return r;
}

/* ================================================================ analytic scenes */
typedef struct scene {
    int nplanes, nboxes;
    double plane[2][4];        /* n.p + d = 0 */
    double box[3][6];          /* min xyz, max xyz */
} scene;

/* nearest hit parameter in [0,1] along o + t*d, or -1 */
static double scene_hit(const scene *s, const double o[3], const double d[3]) {
    double best = -1;
    int i, a;
    for (i = 0; i < s->nplanes; i++) {
        const double *p = s->plane[i];
        double den = p[0] * d[0] + p[1] * d[1] + p[2] * d[2];
        double t;
        if (den == 0) continue;
        t = -(p[0] * o[0] + p[1] * o[1] + p[2] * o[2] + p[3]) / den;
        if (t >= 0 && t <= 1 && (best < 0 || t < best)) best = t;
    }
    for (i = 0; i < s->nboxes; i++) {
        double t0 = 0, t1 = 1;
        int ok = 1;
        for (a = 0; a < 3 && ok; a++) {
            if (d[a] == 0) {
                if (o[a] < s->box[i][a] || o[a] > s->box[i][3 + a]) ok = 0;
            } else {
                double ta = (s->box[i][a] - o[a]) / d[a], tb = (s->box[i][3 + a] - o[a]) / d[a];
                if (ta > tb) { double x = ta; ta = tb; tb = x; }
                if (ta > t0) t0 = ta;
                if (tb < t1) t1 = tb;
                if (t0 > t1) ok = 0;
            }
        }
        if (ok && (best < 0 || t0 < best)) best = t0;
    }
    return best;
}

/* depth[j*w + i]: window depth of the hit through pixel (i, j)'s centre, row 0 at the bottom */
static void render_depth(const scene *s, dm4 vp, int w, int h, float *depth) {
    dm4 inv = dm_inverse(vp);
    int i, j;
    for (j = 0; j < h; j++)
        for (i = 0; i < w; i++) {
            double x = (i + 0.5) * 2.0 / w - 1.0, y = (j + 0.5) * 2.0 / h - 1.0;
            double pn[4] = { x, y, -1, 1 }, pf[4] = { x, y, 1, 1 }, a[4], b[4], o[3], d[3], t;
            int k;
            dm_apply(&inv, pn, a);
            dm_apply(&inv, pf, b);
            for (k = 0; k < 3; k++) { o[k] = a[k] / a[3]; d[k] = b[k] / b[3] - o[k]; }
            t = scene_hit(s, o, d);
            if (t < 0) {
                depth[j * w + i] = 1.0f;
            } else {
                double p[4], c[4];
                for (k = 0; k < 3; k++) p[k] = o[k] + t * d[k];
                p[3] = 1;
                dm_apply(&vp, p, c);
                depth[j * w + i] = (float)(0.5 * c[2] / c[3] + 0.5);
            }
        }
}

/* ================================================================ naive reference */
typedef struct ref_est {
    /* "strict": inside the light volume by a margin; "all": inside or within
       float noise of its boundary. The implementation must lie in between. */
    int n_strict, n_all;
    double bs[4], ba[4];                 /* bounds x0 y0 x1 y1 */
    double tw_strict, th_strict, tw_all, th_all;
} ref_est;

static int valid_depth(float d) { return d >= 0.0f && d < 1.0f; }

static void to_light_ndc(const dm4 *inv, const dm4 *light, double x, double y, double d, double out[2]) {
    double p[4] = { x, y, 2.0 * d - 1.0, 1.0 }, wp[4], c[4];
    dm_apply(inv, p, wp);
    wp[0] /= wp[3]; wp[1] /= wp[3]; wp[2] /= wp[3]; wp[3] = 1;
    dm_apply(light, wp, c);
    out[0] = c[0] / c[3];
    out[1] = c[1] / c[3];
}

static void naive_estimate(const float *depth, int w, int h, sk_mat4 cam_inv_f, sk_mat4 light_f, ref_est *r) {
    dm4 inv = to_d(cam_inv_f), light = to_d(light_f);
    int i, j;
    r->n_strict = r->n_all = 0;
    r->bs[0] = r->bs[1] = r->ba[0] = r->ba[1] = INFINITY;
    r->bs[2] = r->bs[3] = r->ba[2] = r->ba[3] = -INFINITY;
    r->tw_strict = r->th_strict = r->tw_all = r->th_all = INFINITY;
    for (j = 0; j < h; j++)
        for (i = 0; i < w; i++) {
            double x = (i + 0.5) * 2.0 / w - 1.0, y = (j + 0.5) * 2.0 / h - 1.0;
            double p[4], wp[4], c[4], margin, lx, ly, mnx = INFINITY, mny = INFINITY, mxx = -INFINITY, mxy = -INFINITY;
            int inside, amb, a, b;
            float d = depth[j * w + i];
            if (!valid_depth(d)) continue;
            p[0] = x; p[1] = y; p[2] = 2.0 * d - 1.0; p[3] = 1;
            dm_apply(&inv, p, wp);
            wp[0] /= wp[3]; wp[1] /= wp[3]; wp[2] /= wp[3]; wp[3] = 1;
            dm_apply(&light, wp, c);
            if (!(c[3] > 0)) continue;
            margin = c[3] - fabs(c[0]);
            if (c[3] - fabs(c[1]) < margin) margin = c[3] - fabs(c[1]);
            if (c[3] - fabs(c[2]) < margin) margin = c[3] - fabs(c[2]);
            amb = fabs(margin) <= 1e-5 * c[3];
            inside = margin >= 0;
            if (!inside && !amb) continue;
            /* the patch: four corners, depths averaged over the valid pixels around each */
            for (b = 0; b < 2; b++)
                for (a = 0; a < 2; a++) {
                    int cx = i + a, cy = j + b, u, v, cnt = 0;
                    double sum = 0, q[2];
                    for (v = cy - 1; v <= cy; v++)
                        for (u = cx - 1; u <= cx; u++)
                            if (u >= 0 && u < w && v >= 0 && v < h && valid_depth(depth[v * w + u])) {
                                sum += depth[v * w + u];
                                cnt++;
                            }
                    to_light_ndc(&inv, &light, cx * 2.0 / w - 1.0, cy * 2.0 / h - 1.0, sum / cnt, q);
                    if (q[0] < mnx) mnx = q[0];
                    if (q[0] > mxx) mxx = q[0];
                    if (q[1] < mny) mny = q[1];
                    if (q[1] > mxy) mxy = q[1];
                }
            lx = c[0] / c[3];
            ly = c[1] / c[3];
            /* "all" */
            r->n_all++;
            if (lx < r->ba[0]) r->ba[0] = lx;
            if (ly < r->ba[1]) r->ba[1] = ly;
            if (lx > r->ba[2]) r->ba[2] = lx;
            if (ly > r->ba[3]) r->ba[3] = ly;
            if (mxx - mnx < r->tw_all) r->tw_all = mxx - mnx;
            if (mxy - mny < r->th_all) r->th_all = mxy - mny;
            if (amb) continue;
            /* "strict" */
            r->n_strict++;
            if (lx < r->bs[0]) r->bs[0] = lx;
            if (ly < r->bs[1]) r->bs[1] = ly;
            if (lx > r->bs[2]) r->bs[2] = lx;
            if (ly > r->bs[3]) r->bs[3] = ly;
            if (mxx - mnx < r->tw_strict) r->tw_strict = mxx - mnx;
            if (mxy - mny < r->th_strict) r->th_strict = mxy - mny;
        }
}

static int res_of(double extent, double texel, int max_res) {
    double v = ceil(extent / texel);
    if (!(v >= 1)) v = 1;
    if (v > max_res) v = max_res;
    return (int)v;
}

/* crop must map bounds (x0,y0) -> (-1,-1) and (x1,y1) -> (1,1) */
static void check_crop(const sk_res_estimate *e, const char *what) {
    dm4 c = to_d(e->crop);
    double p0[4], p1[4], q0[4], q1[4];
    int i, finite = 1;
    for (i = 0; i < 16; i++) if (!isfinite(e->crop.m[i])) finite = 0;
    SK_CHECK_MSG(finite, "%s: crop not finite", what);
    if (!(e->bounds.x1 - e->bounds.x0 > 1e-3 && e->bounds.y1 - e->bounds.y0 > 1e-3)) return;
    p0[0] = e->bounds.x0; p0[1] = e->bounds.y0; p0[2] = 0; p0[3] = 1;
    p1[0] = e->bounds.x1; p1[1] = e->bounds.y1; p1[2] = 0; p1[3] = 1;
    dm_apply(&c, p0, q0);
    dm_apply(&c, p1, q1);
    SK_CHECK_MSG(fabs(q0[0] / q0[3] + 1) < 1e-4 && fabs(q0[1] / q0[3] + 1) < 1e-4,
                 "%s: crop maps (x0,y0) to (%g,%g)", what, q0[0] / q0[3], q0[1] / q0[3]);
    SK_CHECK_MSG(fabs(q1[0] / q1[3] - 1) < 1e-4 && fabs(q1[1] / q1[3] - 1) < 1e-4,
                 "%s: crop maps (x1,y1) to (%g,%g)", what, q1[0] / q1[3], q1[1] / q1[3]);
}

static void check_no_sample(const sk_res_estimate *e, const char *what) {
    int i, ident = 1;
    SK_CHECK_MSG(e->samples == 0, "%s: samples %d", what, e->samples);
    SK_CHECK_MSG(e->width == 0 && e->height == 0, "%s: %dx%d", what, e->width, e->height);
    SK_CHECK_MSG(e->texel_w == 0 && e->texel_h == 0, "%s: texel %g x %g", what, e->texel_w, e->texel_h);
    SK_CHECK_MSG(e->bounds.x0 == -1 && e->bounds.y0 == -1 && e->bounds.x1 == 1 && e->bounds.y1 == 1,
                 "%s: bounds [%g,%g]x[%g,%g]", what, e->bounds.x0, e->bounds.x1, e->bounds.y0, e->bounds.y1);
    for (i = 0; i < 16; i++)
        if (fabs(e->crop.m[i] - ((i % 5 == 0) ? 1.0 : 0.0)) > 1e-6) ident = 0;
    SK_CHECK_MSG(ident, "%s: crop is not the identity", what);
}

/* the implementation against the naive reference */
static void check_against_naive(const float *depth, int w, int h, sk_mat4 inv, sk_mat4 light, int max_res,
                                const char *what) {
    ref_est r;
    sk_res_estimate e;
    sk_result res;
    naive_estimate(depth, w, h, inv, light, &r);
    memset(&e, 0, sizeof e);
    res = sk_estimate_resolution(depth, w, h, inv, light, max_res, &e);
    SK_CHECK_MSG(res == SK_OK, "%s: result %d", what, (int)res);
    SK_CHECK_MSG(e.samples >= r.n_strict && e.samples <= r.n_all, "%s: samples %d, naive %d..%d",
                 what, e.samples, r.n_strict, r.n_all);
    if (r.n_strict == 0) return;
    SK_CHECK_MSG(e.bounds.x0 >= r.ba[0] - 1e-4 && e.bounds.x0 <= r.bs[0] + 1e-4 &&
                 e.bounds.y0 >= r.ba[1] - 1e-4 && e.bounds.y0 <= r.bs[1] + 1e-4 &&
                 e.bounds.x1 >= r.bs[2] - 1e-4 && e.bounds.x1 <= r.ba[2] + 1e-4 &&
                 e.bounds.y1 >= r.bs[3] - 1e-4 && e.bounds.y1 <= r.ba[3] + 1e-4,
                 "%s: bounds [%g,%g]x[%g,%g], naive [%g,%g]x[%g,%g]", what,
                 e.bounds.x0, e.bounds.x1, e.bounds.y0, e.bounds.y1, r.bs[0], r.bs[2], r.bs[1], r.bs[3]);
    SK_CHECK_MSG(e.bounds.x0 >= -1 && e.bounds.y0 >= -1 && e.bounds.x1 <= 1 && e.bounds.y1 <= 1,
                 "%s: bounds outside [-1,1]^2", what);
    SK_CHECK_MSG(e.texel_w >= r.tw_all * (1 - 2e-3) && e.texel_w <= r.tw_strict * (1 + 2e-3),
                 "%s: texel_w %.9g, naive %.9g", what, e.texel_w, r.tw_strict);
    SK_CHECK_MSG(e.texel_h >= r.th_all * (1 - 2e-3) && e.texel_h <= r.th_strict * (1 + 2e-3),
                 "%s: texel_h %.9g, naive %.9g", what, e.texel_h, r.th_strict);
    {
        /* the texel sizes may differ by the float slack above (2e-3), which
           ceil(extent / texel) turns into a relative slack of the counts */
        int w_lo = res_of(r.bs[2] - r.bs[0], r.tw_strict * (1 + 2e-3), max_res);
        int w_hi = res_of(r.ba[2] - r.ba[0], r.tw_all * (1 - 2e-3), max_res);
        int h_lo = res_of(r.bs[3] - r.bs[1], r.th_strict * (1 + 2e-3), max_res);
        int h_hi = res_of(r.ba[3] - r.ba[1], r.th_all * (1 - 2e-3), max_res);
        /* and the implementation's own fields agree: ceil(extent / texel), clamped */
        int w_own = res_of((double)e.bounds.x1 - e.bounds.x0, e.texel_w, max_res);
        int h_own = res_of((double)e.bounds.y1 - e.bounds.y0, e.texel_h, max_res);
        SK_CHECK_MSG(abs(e.width - w_own) <= 1 && abs(e.height - h_own) <= 1,
                     "%s: %dx%d, but its own bounds / texel give %dx%d", what, e.width, e.height, w_own, h_own);
        SK_CHECK_MSG(e.width >= w_lo - 1 && e.width <= w_hi + 1 && e.width >= 1 && e.width <= max_res,
                     "%s: width %d, naive %d..%d", what, e.width, w_lo, w_hi);
        SK_CHECK_MSG(e.height >= h_lo - 1 && e.height <= h_hi + 1 && e.height >= 1 && e.height <= max_res,
                     "%s: height %d, naive %d..%d", what, e.height, h_lo, h_hi);
    }
    check_crop(&e, what);
}

/* ================================================================ fixtures */
#define W 64
#define H 48

static dm4 cam_a_proj(void) { return dm_perspective(PI_D / 3, (double)W / H, 0.5, 50.0); }

/* plane through (0,0,-6), tilted towards +y: covers the whole screen of a
   camera at the origin looking down -z */
static scene tilted_plane(void) {
    scene s;
    double n[3] = { 0.0, 0.4, 1.0 };
    memset(&s, 0, sizeof s);
    d3_norm(n);
    s.nplanes = 1;
    s.plane[0][0] = n[0]; s.plane[0][1] = n[1]; s.plane[0][2] = n[2];
    s.plane[0][3] = 6.0 * n[2];
    return s;
}
static scene facing_plane(double dist) {
    scene s;
    memset(&s, 0, sizeof s);
    s.nplanes = 1;
    s.plane[0][2] = 1.0;
    s.plane[0][3] = dist;
    return s;
}
static int all_valid(const float *d, int n) {
    int i;
    for (i = 0; i < n; i++) if (!valid_depth(d[i])) return 0;
    return 1;
}

/* ================================================================ tests */
static void test_identical_frusta(void) {
    static const int sizes[][2] = { { 64, 48 }, { 128, 96 }, { 37, 53 }, { 1, 1 }, { 200, 7 } };
    int k;
    int width64 = 0;
    for (k = 0; k < 5; k++) {
        int w = sizes[k][0], h = sizes[k][1];
        dm4 vp = dm_mul(dm_perspective(PI_D / 3, (double)w / h, 0.5, 50.0), dm_identity());
        scene s = tilted_plane();
        float *depth = (float *)malloc(sizeof(float) * (size_t)(w * h));
        sk_res_estimate e;
        sk_result r;
        char what[128];
        render_depth(&s, vp, w, h, depth);
        SK_CHECK(all_valid(depth, w * h));
        memset(&e, 0, sizeof e);
        r = sk_estimate_resolution(depth, w, h, to_f(dm_inverse(vp)), to_f(vp), 4096, &e);
        SK_CHECK(r == SK_OK);
        /* Ferko 2013, Sec. 3.2: "If the camera viewing frustum and the light viewing
           frustum are identical, this returns ... the same as the resolution of
           the image generated by the camera" */
        SK_CHECK_MSG(abs(e.width - w) <= 1, "%dx%d: width %d", w, h, e.width);
        SK_CHECK_MSG(abs(e.height - h) <= 1, "%dx%d: height %d", w, h, e.height);
        SK_CHECK_MSG(e.samples == w * h, "%dx%d: samples %d", w, h, e.samples);
        /* every patch is exactly one pixel: 2/w x 2/h of NDC */
        SK_CHECK_NEAR(e.texel_w, 2.0 / w, 1e-3 * 2.0 / w);
        SK_CHECK_NEAR(e.texel_h, 2.0 / h, 1e-3 * 2.0 / h);
        /* the samples are the pixel centres */
        SK_CHECK_NEAR(e.bounds.x0, -1.0 + 1.0 / w, 1e-4);
        SK_CHECK_NEAR(e.bounds.x1, 1.0 - 1.0 / w, 1e-4);
        SK_CHECK_NEAR(e.bounds.y0, -1.0 + 1.0 / h, 1e-4);
        SK_CHECK_NEAR(e.bounds.y1, 1.0 - 1.0 / h, 1e-4);
        sprintf(what, "identical %dx%d", w, h);
        check_crop(&e, what);
        check_against_naive(depth, w, h, to_f(dm_inverse(vp)), to_f(vp), 4096, what);
        if (w == 64) width64 = e.width;
        if (w == 128) SK_CHECK_MSG(abs(e.width - 2 * width64) <= 2, "128 wide: %d vs 64 wide: %d", e.width, width64);
        free(depth);
    }
    /* same with a camera in a general pose and a plane facing it obliquely */
    {
        dm4 view = dm_look_at(2, 1, 3, -1, 0.5, -4, 0.2, 1, 0);
        dm4 vp = dm_mul(cam_a_proj(), view);
        dm4 inv_view = dm_inverse(view);
        scene s;
        double fwd[3], right[3], n[3], pt[3];
        float depth[W * H];
        sk_res_estimate e;
        int k2;
        /* camera axes in world space: columns of the inverse view */
        for (k2 = 0; k2 < 3; k2++) { right[k2] = inv_view.m[k2]; fwd[k2] = -inv_view.m[8 + k2]; }
        for (k2 = 0; k2 < 3; k2++) { n[k2] = -fwd[k2] + 0.3 * right[k2]; }
        d3_norm(n);
        pt[0] = 2 + 6 * fwd[0]; pt[1] = 1 + 6 * fwd[1]; pt[2] = 3 + 6 * fwd[2];
        memset(&s, 0, sizeof s);
        s.nplanes = 1;
        s.plane[0][0] = n[0]; s.plane[0][1] = n[1]; s.plane[0][2] = n[2];
        s.plane[0][3] = -(n[0] * pt[0] + n[1] * pt[1] + n[2] * pt[2]);
        render_depth(&s, vp, W, H, depth);
        SK_CHECK(all_valid(depth, W * H));
        SK_CHECK(sk_estimate_resolution(depth, W, H, to_f(dm_inverse(vp)), to_f(vp), 4096, &e) == SK_OK);
        SK_CHECK_MSG(abs(e.width - W) <= 1, "posed: width %d", e.width);
        SK_CHECK_MSG(abs(e.height - H) <= 1, "posed: height %d", e.height);
        SK_CHECK(e.samples == W * H);
        check_against_naive(depth, W, H, to_f(dm_inverse(vp)), to_f(vp), 4096, "posed identical");
    }
}

static void test_zoom_scalings(void) {
    /* camera A: fovy 60 deg; camera B: tan(fov/2) halved (2x zoom), same pose.
       Both look at a plane facing them at distance 6. The light is camera A. */
    dm4 pa = cam_a_proj();
    dm4 pb = dm_perspective(2 * atan(0.5 * tan(PI_D / 6)), (double)W / H, 0.5, 50.0);
    scene s = facing_plane(6.0);
    float da[W * H], db[W * H];
    sk_res_estimate ea, eb, ec;
    render_depth(&s, pa, W, H, da);
    render_depth(&s, pb, W, H, db);
    SK_CHECK(all_valid(da, W * H) && all_valid(db, W * H));
    SK_CHECK(sk_estimate_resolution(da, W, H, to_f(dm_inverse(pa)), to_f(pa), 4096, &ea) == SK_OK);
    SK_CHECK(sk_estimate_resolution(db, W, H, to_f(dm_inverse(pb)), to_f(pa), 4096, &eb) == SK_OK);
    /* B's pixels are half as large in the light's clip space: the light needs
       2x the resolution over its frustum (2/texel), while the crop over B's
       (half as large) footprint still gets the camera's resolution */
    SK_CHECK_NEAR(ea.texel_w, 2.0 / W, 2e-3 / W);
    SK_CHECK_NEAR(eb.texel_w, 1.0 / W, 1e-3 / W);
    SK_CHECK_NEAR(eb.texel_h, 1.0 / H, 1e-3 / H);
    SK_CHECK_NEAR((2.0 / eb.texel_w) / (2.0 / ea.texel_w), 2.0, 4e-3);
    SK_CHECK_NEAR((2.0 / eb.texel_h) / (2.0 / ea.texel_h), 2.0, 4e-3);
    SK_CHECK_NEAR(eb.bounds.x1 - eb.bounds.x0, 0.5 * (2.0 - 2.0 / W), 1e-4);
    SK_CHECK_NEAR(eb.bounds.y1 - eb.bounds.y0, 0.5 * (2.0 - 2.0 / H), 1e-4);
    SK_CHECK_MSG(abs(eb.width - W) <= 1 && abs(eb.height - H) <= 1, "zoomed camera: %dx%d", eb.width, eb.height);
    SK_CHECK(eb.samples == W * H);
    check_against_naive(db, W, H, to_f(dm_inverse(pb)), to_f(pa), 4096, "zoomed camera");
    /* crop zooming the light 2x (clip x,y doubled): only the middle quarter of
       the screen is inside (|ndc| <= 1/2: columns 16..47, rows 12..35), each
       pixel is 4/W x 4/H of the light's NDC, W/2 - 1 x H/2 - 1 texels needed */
    {
        dm4 lz = dm_mul(dm_rows(2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1), pa);
        SK_CHECK(sk_estimate_resolution(da, W, H, to_f(dm_inverse(pa)), to_f(lz), 4096, &ec) == SK_OK);
        SK_CHECK_MSG(ec.samples == (W / 2) * (H / 2), "zoomed light: samples %d", ec.samples);
        SK_CHECK_NEAR(ec.texel_w, 4.0 / W, 4e-3 / W);
        SK_CHECK_NEAR(ec.texel_h, 4.0 / H, 4e-3 / H);
        SK_CHECK_NEAR(ec.texel_w / ea.texel_w, 2.0, 4e-3);
        SK_CHECK_NEAR(ec.bounds.x0, -(1.0 - 2.0 / W), 1e-4);
        SK_CHECK_NEAR(ec.bounds.x1, 1.0 - 2.0 / W, 1e-4);
        SK_CHECK_NEAR(ec.bounds.y0, -(1.0 - 2.0 / H), 1e-4);
        SK_CHECK_NEAR(ec.bounds.y1, 1.0 - 2.0 / H, 1e-4);
        SK_CHECK_MSG(abs(ec.width - (W / 2 - 1)) <= 1 && abs(ec.height - (H / 2 - 1)) <= 1,
                     "zoomed light: %dx%d", ec.width, ec.height);
        check_against_naive(da, W, H, to_f(dm_inverse(pa)), to_f(lz), 4096, "zoomed light");
    }
}

static void test_left_half_light(void) {
    /* the light's clip x' = 2x + w: it sees only the left half of the screen */
    dm4 pa = cam_a_proj();
    dm4 l = dm_mul(dm_rows(2, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1), pa);
    scene s = tilted_plane();
    float d[W * H];
    sk_res_estimate e;
    render_depth(&s, pa, W, H, d);
    SK_CHECK(sk_estimate_resolution(d, W, H, to_f(dm_inverse(pa)), to_f(l), 4096, &e) == SK_OK);
    SK_CHECK_MSG(e.samples == (W / 2) * H, "samples %d", e.samples);
    /* left column centre -1 + 1/W -> 2(-1 + 1/W) + 1; last inside column centre -1/W -> 1 - 2/W */
    SK_CHECK_NEAR(e.bounds.x0, -1.0 + 2.0 / W, 1e-4);
    SK_CHECK_NEAR(e.bounds.x1, 1.0 - 2.0 / W, 1e-4);
    SK_CHECK_NEAR(e.bounds.y0, -1.0 + 1.0 / H, 1e-4);
    SK_CHECK_NEAR(e.bounds.y1, 1.0 - 1.0 / H, 1e-4);
    SK_CHECK_NEAR(e.texel_w, 4.0 / W, 4e-3 / W);
    SK_CHECK_NEAR(e.texel_h, 2.0 / H, 2e-3 / H);
    SK_CHECK_MSG(abs(e.width - (W / 2 - 1)) <= 1, "width %d", e.width);
    SK_CHECK_MSG(abs(e.height - (H - 1)) <= 1, "height %d", e.height);
    check_crop(&e, "left half");
    check_against_naive(d, W, H, to_f(dm_inverse(pa)), to_f(l), 4096, "left half");
}

/* a small world: ground, two boxes, sky above the horizon */
static scene yard(void) {
    scene s;
    static const double b0[6] = { -1, 0, -1, 1, 1.5, 1 }, b1[6] = { 1.5, 0, -3, 2.5, 3, -2 };
    memset(&s, 0, sizeof s);
    s.nplanes = 1;
    s.plane[0][1] = 1.0;              /* y = 0 */
    s.nboxes = 2;
    memcpy(s.box[0], b0, sizeof b0);
    memcpy(s.box[1], b1, sizeof b1);
    return s;
}

static void test_naive_agreement(void) {
    enum { NW = 96, NH = 64 };
    dm4 vp = dm_mul(dm_perspective(50 * PI_D / 180, (double)NW / NH, 0.5, 40.0),
                    dm_look_at(0, 3, 8, 0, 0.5, 0, 0, 1, 0));
    dm4 lights[4];
    static float d[NW * NH];
    int k, sky = 0, i;
    scene s = yard();
    render_depth(&s, vp, NW, NH, d);
    for (i = 0; i < NW * NH; i++) sky += !valid_depth(d[i]);
    SK_CHECK_MSG(sky > 0 && sky < NW * NH / 2, "fixture: %d background pixels", sky);
    /* spot light covering part of the view */
    lights[0] = dm_mul(dm_perspective(45 * PI_D / 180, 1.0, 1.0, 30.0), dm_look_at(5, 7, 4, 0, 0, 0, 0, 1, 0));
    /* directional light, orthographic, partial */
    lights[1] = dm_mul(dm_ortho(-4, 4, -3, 3, 1, 30), dm_look_at(-6, 10, 2, 0, 0, 0, 0, 1, 0));
    /* wide spot light seeing everything */
    lights[2] = dm_mul(dm_perspective(120 * PI_D / 180, 1.3, 0.5, 60.0), dm_look_at(-3, 12, 6, 0, 0, -1, 0, 1, 0));
    /* grazing directional light over the ground (orthographic: no w <= 0
       corners), turned so that no box face is exactly edge-on to it (an
       edge-on face has zero-width patches: float noise, tested elsewhere) */
    lights[3] = dm_mul(dm_ortho(-15, 15, -2, 2, 1, 100), dm_look_at(-40, 2, -12, 0, 0, -5, 0, 1, 0));
    for (k = 0; k < 4; k++) {
        char what[128];
        sprintf(what, "yard light %d", k);
        check_against_naive(d, NW, NH, to_f(dm_inverse(vp)), to_f(lights[k]), 4096, what);
        sprintf(what, "yard light %d max 64", k);
        check_against_naive(d, NW, NH, to_f(dm_inverse(vp)), to_f(lights[k]), 64, what);
    }
    /* partial-coverage fixture really is partial */
    {
        ref_est r;
        naive_estimate(d, NW, NH, to_f(dm_inverse(vp)), to_f(lights[0]), &r);
        SK_CHECK_MSG(r.n_strict > 100 && r.n_all < NW * NH - sky, "fixture: light 0 sees %d", r.n_strict);
    }
}

/* buffers wider than a few hundred pixels (an implementation may work in
   column strips: corners shared across a strip border must still be right) */
static void test_wide_buffers(void) {
    static const int sizes[][2] = { { 257, 9 }, { 300, 6 }, { 513, 5 }, { 777, 4 } };
    static float d[777 * 9];
    int k, l;
    for (k = 0; k < 4; k++) {
        int w = sizes[k][0], h = sizes[k][1];
        dm4 vp = dm_perspective(PI_D / 3, (double)w / h, 0.5, 50.0);
        scene s = tilted_plane();
        sk_res_estimate e;
        char what[128];
        render_depth(&s, vp, w, h, d);
        SK_CHECK(sk_estimate_resolution(d, w, h, to_f(dm_inverse(vp)), to_f(vp), 4096, &e) == SK_OK);
        SK_CHECK_MSG(abs(e.width - w) <= 1 && abs(e.height - h) <= 1 && e.samples == w * h,
                     "identical %dx%d: %dx%d, %d samples", w, h, e.width, e.height, e.samples);
        sprintf(what, "wide identical %dx%d", w, h);
        check_against_naive(d, w, h, to_f(dm_inverse(vp)), to_f(vp), 4096, what);
    }
    /* the yard, 600 x 9, with holes and lights that change the patch shapes */
    {
        enum { NW = 600, NH = 9 };
        dm4 vp = dm_mul(dm_perspective(20 * PI_D / 180, (double)NW / NH, 0.5, 40.0),
                        dm_look_at(0, 3, 8, 0, 0.5, 0, 0, 1, 0));
        dm4 lights[2];
        scene s = yard();
        int i;
        render_depth(&s, vp, NW, NH, d);
        for (i = 250; i < NW * NH; i += 263) d[i] = 1.0f;        /* holes near strip borders */
        lights[0] = dm_mul(dm_perspective(60 * PI_D / 180, 1.0, 1.0, 30.0), dm_look_at(5, 7, 4, 0, 0, 0, 0, 1, 0));
        lights[1] = dm_mul(dm_ortho(-6, 6, -6, 6, 1, 40), dm_look_at(-6, 10, 2, 0, 0, 0, 0, 1, 0));
        for (l = 0; l < 2; l++) {
            char what[128];
            sprintf(what, "wide yard light %d", l);
            check_against_naive(d, NW, NH, to_f(dm_inverse(vp)), to_f(lights[l]), 4096, what);
        }
    }
}

/* Arbitrary depth buffers (not from a scene): a few random valid pixels in a
   sea of background, placed at the screen edges, near column strip borders
   and in the middle, seen by an oblique orthographic light. With so few
   patches the minimum is decided by those pixels' corners, so every corner
   rule (neighbour averaging, missing neighbours, screen borders) shows. */
static unsigned rng_state = 2013u;
static double rnd(void) {
    rng_state = rng_state * 1664525u + 1013904223u;
    return (double)(rng_state >> 8) / 16777216.0;
}
static void test_sparse_blocks(void) {
    enum { SW = 600, SH = 8 };
    static float d[SW * SH];
    static const int xs[] = { 0, 1, 127, 128, 254, 255, 256, 257, 383, 510, 511, 512, 513, 598, 599 };
    dm4 cam = dm_perspective(PI_D / 3, 1.0, 0.5, 50.0);   /* non-square pixels are fine */
    dm4 l = dm_mul(dm_ortho(-20, 20, -20, 20, 0.1, 80), dm_look_at(10, 5, 10, 0, 0, -4, 0, 1, 0));
    int k, t, i;
    for (t = 0; t < 3; t++)
        for (k = 0; k < (int)(sizeof xs / sizeof xs[0]); k++) {
            char what[128];
            int bw = 1 + (int)(rnd() * 3), bh = 1 + (int)(rnd() * 3), y0 = (int)(rnd() * (SH - bh + 1));
            int x0 = xs[k] - (int)(rnd() * bw), x, y;
            if (x0 < 0) x0 = 0;
            if (x0 + bw > SW) x0 = SW - bw;
            for (i = 0; i < SW * SH; i++) d[i] = 1.0f;
            for (y = y0; y < y0 + bh; y++)
                for (x = x0; x < x0 + bw; x++) d[y * SW + x] = (float)(0.3 + 0.65 * rnd());
            sprintf(what, "sparse block %dx%d at (%d,%d)", bw, bh, x0, y0);
            check_against_naive(d, SW, SH, to_f(dm_inverse(cam)), to_f(l), 65536, what);
            check_against_naive(d, SW, SH, to_f(dm_inverse(cam)), to_f(l), 8, what);
        }
    /* dense random depths with holes, every pixel its own patch shape */
    for (t = 0; t < 4; t++) {
        char what[128];
        for (i = 0; i < SW * SH; i++) d[i] = rnd() < 0.2 ? 1.0f : (float)(0.3 + 0.65 * rnd());
        sprintf(what, "random depths %d", t);
        check_against_naive(d, SW, SH, to_f(dm_inverse(cam)), to_f(l), 65536, what);
    }
}

static void test_invalid_depths_skipped(void) {
    /* NaN, negatives, 1.0 and beyond, infinities: all skipped like background.
       The result equals that of the same buffer with those pixels set to 1.0. */
    enum { NW = 64, NH = 48 };
    dm4 vp = dm_mul(dm_perspective(50 * PI_D / 180, (double)NW / NH, 0.5, 40.0),
                    dm_look_at(0, 3, 8, 0, 0.5, 0, 0, 1, 0));
    dm4 l = dm_mul(dm_perspective(45 * PI_D / 180, 1.0, 1.0, 30.0), dm_look_at(5, 7, 4, 0, 0, 0, 0, 1, 0));
    static float d[NW * NH], dbg[NW * NH];
    static const float junk[] = { NAN, -NAN, INFINITY, -INFINITY, -0.5f, 1.5f, 1.0f, 2.0f };
    sk_res_estimate e1, e2;
    int i;
    scene s = yard();
    render_depth(&s, vp, NW, NH, d);
    memcpy(dbg, d, sizeof d);
    for (i = 0; i < NW * NH; i += 7) {
        d[i] = junk[(i / 7) % 8];
        dbg[i] = 1.0f;
    }
    SK_CHECK(sk_estimate_resolution(d, NW, NH, to_f(dm_inverse(vp)), to_f(l), 4096, &e1) == SK_OK);
    SK_CHECK(sk_estimate_resolution(dbg, NW, NH, to_f(dm_inverse(vp)), to_f(l), 4096, &e2) == SK_OK);
    SK_CHECK(e1.samples == e2.samples && e1.samples > 0);
    SK_CHECK(e1.width == e2.width && e1.height == e2.height);
    SK_CHECK_NEAR(e1.texel_w, e2.texel_w, 1e-6 * e2.texel_w);
    SK_CHECK_NEAR(e1.texel_h, e2.texel_h, 1e-6 * e2.texel_h);
    SK_CHECK_NEAR(e1.bounds.x0, e2.bounds.x0, 1e-6);
    SK_CHECK_NEAR(e1.bounds.x1, e2.bounds.x1, 1e-6);
    SK_CHECK_NEAR(e1.bounds.y0, e2.bounds.y0, 1e-6);
    SK_CHECK_NEAR(e1.bounds.y1, e2.bounds.y1, 1e-6);
    SK_CHECK_FINITE(e1.texel_w);
    SK_CHECK_FINITE(e1.texel_h);
    check_against_naive(d, NW, NH, to_f(dm_inverse(vp)), to_f(l), 4096, "junk depths");
    /* all junk: no sample */
    for (i = 0; i < NW * NH; i++) d[i] = junk[i % 8];
    SK_CHECK(sk_estimate_resolution(d, NW, NH, to_f(dm_inverse(vp)), to_f(l), 4096, &e1) == SK_OK);
    check_no_sample(&e1, "all junk");
}

static void test_no_sample(void) {
    dm4 pa = cam_a_proj();
    scene s = tilted_plane();
    float d[W * H];
    sk_res_estimate e;
    int i;
    /* empty depth buffer (all background) */
    for (i = 0; i < W * H; i++) d[i] = 1.0f;
    memset(&e, 0x5A, sizeof e);
    SK_CHECK(sk_estimate_resolution(d, W, H, to_f(dm_inverse(pa)), to_f(pa), 4096, &e) == SK_OK);
    check_no_sample(&e, "empty buffer");
    /* every sample right of the light frustum (clip x' = x + 3w) */
    render_depth(&s, pa, W, H, d);
    memset(&e, 0x5A, sizeof e);
    SK_CHECK(sk_estimate_resolution(d, W, H, to_f(dm_inverse(pa)),
                                    to_f(dm_mul(dm_rows(1, 0, 0, 3, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1), pa)),
                                    4096, &e) == SK_OK);
    check_no_sample(&e, "all outside (x)");
    /* every sample behind the light (w' = -w) */
    memset(&e, 0x5A, sizeof e);
    SK_CHECK(sk_estimate_resolution(d, W, H, to_f(dm_inverse(pa)),
                                    to_f(dm_mul(dm_rows(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1), pa)),
                                    4096, &e) == SK_OK);
    check_no_sample(&e, "all behind the light");
    /* every sample beyond the light's far plane (z' = z + 3w) */
    memset(&e, 0x5A, sizeof e);
    SK_CHECK(sk_estimate_resolution(d, W, H, to_f(dm_inverse(pa)),
                                    to_f(dm_mul(dm_rows(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 3, 0, 0, 0, 1), pa)),
                                    4096, &e) == SK_OK);
    check_no_sample(&e, "all beyond the far plane");
}

static void test_single_pixel(void) {
    dm4 pa = cam_a_proj();
    scene s = tilted_plane();
    float full[W * H], d[W * H];
    sk_res_estimate e;
    int i;
    render_depth(&s, pa, W, H, full);
    for (i = 0; i < W * H; i++) d[i] = 1.0f;
    d[7 * W + 10] = full[7 * W + 10];
    SK_CHECK(sk_estimate_resolution(d, W, H, to_f(dm_inverse(pa)), to_f(pa), 4096, &e) == SK_OK);
    SK_CHECK(e.samples == 1);
    SK_CHECK_MSG(e.width == 1 && e.height == 1, "%dx%d", e.width, e.height);
    SK_CHECK_FINITE(e.texel_w);
    SK_CHECK_FINITE(e.texel_h);
    /* its patch is its own four corners, all at its depth */
    SK_CHECK_NEAR(e.texel_w, 2.0 / W, 1e-3 * 2.0 / W);
    SK_CHECK_NEAR(e.texel_h, 2.0 / H, 1e-3 * 2.0 / H);
    SK_CHECK_NEAR(e.bounds.x0, 10.5 * 2.0 / W - 1.0, 1e-4);
    SK_CHECK_NEAR(e.bounds.x1, 10.5 * 2.0 / W - 1.0, 1e-4);
    SK_CHECK_NEAR(e.bounds.y0, 7.5 * 2.0 / H - 1.0, 1e-4);
    SK_CHECK_NEAR(e.bounds.y1, 7.5 * 2.0 / H - 1.0, 1e-4);
    check_crop(&e, "single pixel");
    check_against_naive(d, W, H, to_f(dm_inverse(pa)), to_f(pa), 4096, "single pixel");
    /* a corner pixel of the screen, seen by a different light */
    for (i = 0; i < W * H; i++) d[i] = 1.0f;
    d[W * H - 1] = full[W * H - 1];
    check_against_naive(d, W, H, to_f(dm_inverse(pa)),
                        to_f(dm_mul(dm_rows(0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1), pa)), 4096,
                        "single corner pixel");
}

static void test_max_res(void) {
    dm4 pa = cam_a_proj();
    scene s = tilted_plane();
    float d[W * H];
    sk_res_estimate e;
    render_depth(&s, pa, W, H, d);
    SK_CHECK(sk_estimate_resolution(d, W, H, to_f(dm_inverse(pa)), to_f(pa), 16, &e) == SK_OK);
    SK_CHECK_MSG(e.width == 16 && e.height == 16, "max 16: %dx%d", e.width, e.height);
    SK_CHECK(e.samples == W * H);
    SK_CHECK(sk_estimate_resolution(d, W, H, to_f(dm_inverse(pa)), to_f(pa), 50, &e) == SK_OK);
    SK_CHECK_MSG(e.width == 50 && abs(e.height - H) <= 1, "max 50: %dx%d", e.width, e.height);
    SK_CHECK(sk_estimate_resolution(d, W, H, to_f(dm_inverse(pa)), to_f(pa), 1, &e) == SK_OK);
    SK_CHECK_MSG(e.width == 1 && e.height == 1, "max 1: %dx%d", e.width, e.height);
    /* the clamp does not change what was measured */
    SK_CHECK_NEAR(e.texel_w, 2.0 / W, 1e-3 * 2.0 / W);
    SK_CHECK_NEAR(e.bounds.x1 - e.bounds.x0, 2.0 - 2.0 / W, 1e-4);
    /* a receiver seen exactly edge-on by the light: every patch (and the
       bounds) has zero light-space width, so width is 0/0 before the clamp:
       it must still land in [1, max_res]; height is the camera's */
    {
        scene fp = facing_plane(6.0);
        dm4 l = dm_mul(dm_ortho(-10, 10, -10, 10, 1, 40), dm_look_at(-20, 0, -6, 0, 0, -6, 0, 1, 0));
        render_depth(&fp, pa, W, H, d);
        SK_CHECK(sk_estimate_resolution(d, W, H, to_f(dm_inverse(pa)), to_f(l), 1024, &e) == SK_OK);
        SK_CHECK(e.samples == W * H);
        SK_CHECK_MSG(e.width >= 1 && e.width <= 1024, "edge-on: width %d", e.width);
        SK_CHECK_MSG(abs(e.height - (H - 1)) <= 1, "edge-on: height %d", e.height);
        SK_CHECK_MSG(isfinite(e.texel_w) && e.texel_w >= 0, "edge-on: texel_w %g", e.texel_w);
        SK_CHECK_FINITE(e.texel_h);
        SK_CHECK_FINITE(e.bounds.x0);
        SK_CHECK_FINITE(e.bounds.x1);
    }
}

static void test_bad_input(void) {
    dm4 pa = cam_a_proj();
    scene s = tilted_plane();
    float d[W * H];
    sk_mat4 inv = to_f(dm_inverse(pa)), lv = to_f(pa), bad;
    sk_res_estimate e, ref;
    sk_result r;
    int k;
    static const float nonfinite[] = { NAN, INFINITY, -INFINITY };
    render_depth(&s, pa, W, H, d);
    memset(&ref, 0x5A, sizeof ref);
#define BADR(call) do { memcpy(&e, &ref, sizeof e); r = (call); \
        SK_CHECK_MSG(r == SK_ERR_INVALID_ARG, "%s -> %d", #call, (int)r); \
        SK_CHECK_MSG(memcmp(&e, &ref, sizeof e) == 0, "%s wrote to out", #call); } while (0)
    BADR(sk_estimate_resolution(NULL, W, H, inv, lv, 1024, &e));
    BADR(sk_estimate_resolution(d, 0, H, inv, lv, 1024, &e));
    BADR(sk_estimate_resolution(d, W, 0, inv, lv, 1024, &e));
    BADR(sk_estimate_resolution(d, -W, H, inv, lv, 1024, &e));
    BADR(sk_estimate_resolution(d, W, -H, inv, lv, 1024, &e));
    BADR(sk_estimate_resolution(d, 65537, 1, inv, lv, 1024, &e));   /* beyond [1, 65536]: never read */
    BADR(sk_estimate_resolution(d, 1, 65537, inv, lv, 1024, &e));
    BADR(sk_estimate_resolution(d, W, H, inv, lv, 0, &e));
    BADR(sk_estimate_resolution(d, W, H, inv, lv, -16, &e));
    for (k = 0; k < 3; k++) {
        int idx;
        for (idx = 0; idx < 16; idx += 5) {
            bad = inv;
            bad.m[idx] = nonfinite[k];
            BADR(sk_estimate_resolution(d, W, H, bad, lv, 1024, &e));
            bad = lv;
            bad.m[idx] = nonfinite[k];
            BADR(sk_estimate_resolution(d, W, H, inv, bad, 1024, &e));
        }
    }
#undef BADR
    r = sk_estimate_resolution(d, W, H, inv, lv, 1024, NULL);
    SK_CHECK_MSG(r == SK_ERR_INVALID_ARG, "NULL out -> %d", (int)r);
    {   /* the limits themselves: a row and a column of 65536 pixels */
        static float line[65536];
        for (k = 0; k < 65536; k++) line[k] = 0.5f;
        r = sk_estimate_resolution(line, 65536, 1, inv, lv, 1024, &e);
        SK_CHECK_MSG(r == SK_OK && e.samples == 65536, "65536 x 1: %d, %d samples", (int)r, e.samples);
        r = sk_estimate_resolution(line, 1, 65536, inv, lv, 1024, &e);
        SK_CHECK_MSG(r == SK_OK && e.samples == 65536, "1 x 65536: %d, %d samples", (int)r, e.samples);
    }
}

SK_TEST_MAIN(test_identical_frusta, test_zoom_scalings, test_left_half_light, test_naive_agreement, test_wide_buffers,
             test_sparse_blocks,
             test_invalid_depths_skipped, test_no_sample, test_single_pixel, test_max_res, test_bad_input)
