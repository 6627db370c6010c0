/* tests/test_crops.c - sections 2 and 3 of shadowkit.h: aliasing analysis
   (sk_aliasing_error, sk_rmsm_lod) and crops / parallel splits
   (sk_crop_matrix, sk_pssm_splits, sk_frustum_slice,
   sk_frustum_bounding_sphere, sk_light_view_directional, sk_fit_ortho,
   sk_stable_crop).

   Expected values come from the formulas of Romanick's VGP353 notes, evaluated here in double
   (d = ds (rs/ri) (N.V / N.L); l = log2 sqrt|dX x dY|; the practical split
   scheme C_i = lambda C_i^log + (1-lambda) C_i^uni), from the glOrtho-style
   crop definition, from camera geometry computed in double, or from hand
   computation; never from the library's output. */
#define SHADOWKIT_IMPLEMENTATION
#include "shadowkit.h"
#include "tests/sk_test.h"
#include "tests/sk_ref.h"
#include <stdlib.h>

/* ------------------------------------------------------------ helpers */
static inline sk_vec2 v2(float x, float y) { sk_vec2 r; r.x = x; r.y = y; return r; }
static inline sk_rect rect(float x0, float y0, float x1, float y1) {
    sk_rect r; r.x0 = x0; r.y0 = y0; r.x1 = x1; r.y1 = y1; return r;
}
static inline sk_sphere sphere(float x, float y, float z, float r) {
    sk_sphere s; s.c = v3(x, y, z); s.r = r; return s;
}

/* B * (A * p), both applied in double (no float product of the matrices) */
static inline dv3 mpoint2(const sk_mat4 *b, const sk_mat4 *a, dv3 p) { return mpoint(b, mpoint(a, p)); }
static inline dv3 mdir(const sk_mat4 *m, dv3 d) {
    double in[4], o[4];
    in[0] = d.x; in[1] = d.y; in[2] = d.z; in[3] = 0.0;
    mxv(m, in, o);
    return dv(o[0], o[1], o[2]);
}
/* fractional distance to the nearest integer */
static inline double frac_dist(double x) { return fabs(x - floor(x + 0.5)); }

/* a gluLookAt + gluPerspective camera, in double */
typedef struct cam_t { dv3 eye, s, u, f; double ty, aspect; } cam_t;
/* camera with orthonormal basis s (right), u (up), f (forward) */
static inline cam_t make_cam(dv3 eye, dv3 fwd, dv3 up, float fovy, float aspect) {
    cam_t c;
    c.eye = eye;
    c.f = dnorm(fwd);
    c.s = dnorm(dcross(c.f, up));
    c.u = dcross(c.s, c.f);
    c.ty = tan((double)fovy / 2.0);
    c.aspect = aspect;
    return c;
}
static inline dv3 cam_corner(const cam_t *c, int i, double d0, double d1) {
    double d = (i & 4) ? d1 : d0;
    double sx = (i & 1) ? 1.0 : -1.0, sy = (i & 2) ? 1.0 : -1.0;
    return dadd(dadd(dadd(c->eye, dmul(c->s, sx * d * c->ty * c->aspect)),
                     dmul(c->u, sy * d * c->ty)), dmul(c->f, d));
}
/* frustum of the camera between eye depths d0 and d1, corners rounded to float,
   planes by sk_frustum_from_corners */
static inline int cam_frustum(const cam_t *c, double d0, double d1, sk_frustum *out) {
    sk_vec3 k[8];
    int i;
    for (i = 0; i < 8; i++) k[i] = tof(cam_corner(c, i, d0, d1));
    return sk_frustum_from_corners(k, out) == SK_OK;
}
/* rotate v about unit axis a by angle t (Rodrigues), in double */
static inline dv3 drot(dv3 v, dv3 a, double t) {
    double ct = cos(t), st = sin(t);
    return dadd(dadd(dmul(v, ct), dmul(dcross(a, v), st)), dmul(a, ddot(a, v) * (1 - ct)));
}
static unsigned long long rng_state = 0x2545F4914F6CDD1Dull;
static inline double rnd(double a, double b) {
    rng_state = rng_state * 6364136223846793005ull + 1442695040888963407ull;
    return a + (b - a) * (double)(rng_state >> 11) * (1.0 / 9007199254740992.0);
}

/* ------------------------------------------------------------ aliasing error */
static void test_aliasing_error(void) {
    /* by hand: (1/1024) * (10/5) * (0.5/0.25) = 4/1024 exactly */
    SK_CHECK_NEAR(sk_aliasing_error(1.0f / 1024.0f, 10.0f, 5.0f, 0.5f, 0.25f), 0.00390625, 0.00390625 * 1e-6);
    {   /* d = ds rs/ri ndv/ndl in double from the float inputs; 4 float ops: 1e-6 rel */
        float ds = 0.002f, rs = 3.0f, ri = 7.0f, ndv = 0.9f, ndl = 0.6f;
        double e = (double)ds * ((double)rs / ri) * ((double)ndv / ndl);
        SK_CHECK_NEAR(sk_aliasing_error(ds, rs, ri, ndv, ndl), e, e * 1e-6);
        /* grazing light (N.L small): projection aliasing grows like 1/(N.L) */
        ndl = 0.01f;
        e = (double)ds * ((double)rs / ri) * ((double)ndv / ndl);
        SK_CHECK_NEAR(sk_aliasing_error(ds, rs, ri, ndv, ndl), e, e * 1e-6);
    }
    /* linear in ds and rs (power-of-two scaling is exact) */
    SK_CHECK(sk_aliasing_error(0.004f, 3.0f, 7.0f, 0.9f, 0.6f) == 2.0f * sk_aliasing_error(0.002f, 3.0f, 7.0f, 0.9f, 0.6f));
    SK_CHECK(sk_aliasing_error(0.002f, 6.0f, 7.0f, 0.9f, 0.6f) == 2.0f * sk_aliasing_error(0.002f, 3.0f, 7.0f, 0.9f, 0.6f));
    /* n_dot_v <= 0: 0 (a back-facing receiver is not seen) */
    SK_CHECK(sk_aliasing_error(0.01f, 1.0f, 1.0f, -0.5f, 0.5f) == 0.0f);
    SK_CHECK(sk_aliasing_error(0.01f, 1.0f, 1.0f, 0.0f, 0.5f) == 0.0f);
    /* +INFINITY: n_dot_l <= 0, ri <= 0, any NaN */
    {
        float r[12];
        int n = 0, i;
        r[n++] = sk_aliasing_error(0.01f, 1.0f, 1.0f, 0.5f, 0.0f);
        r[n++] = sk_aliasing_error(0.01f, 1.0f, 1.0f, 0.5f, -0.0f);
        r[n++] = sk_aliasing_error(0.01f, 1.0f, 1.0f, 0.5f, -0.3f);
        r[n++] = sk_aliasing_error(0.01f, 1.0f, 0.0f, 0.5f, 0.5f);
        r[n++] = sk_aliasing_error(0.01f, 1.0f, -2.0f, 0.5f, 0.5f);
        r[n++] = sk_aliasing_error(fnan(), 1.0f, 1.0f, 0.5f, 0.5f);
        r[n++] = sk_aliasing_error(0.01f, fnan(), 1.0f, 0.5f, 0.5f);
        r[n++] = sk_aliasing_error(0.01f, 1.0f, fnan(), 0.5f, 0.5f);
        r[n++] = sk_aliasing_error(0.01f, 1.0f, 1.0f, fnan(), 0.5f);
        r[n++] = sk_aliasing_error(0.01f, 1.0f, 1.0f, 0.5f, fnan());
        r[n++] = sk_aliasing_error(0.01f, 1.0f, 1.0f, -0.5f, -0.5f);  /* N.L <= 0 wins */
        for (i = 0; i < n; i++) SK_CHECK_MSG(isinf(r[i]) && r[i] > 0, "aliasing case %d = %g, expected +inf", i, r[i]);
    }
    /* infinities: never NaN */
    {
        float r[8];
        int n = 0, i;
        r[n++] = sk_aliasing_error(finf(), 1.0f, 1.0f, 0.5f, 0.5f);
        r[n++] = sk_aliasing_error(0.01f, finf(), finf(), 0.5f, 0.5f);
        r[n++] = sk_aliasing_error(0.01f, 1.0f, 1.0f, finf(), finf());
        r[n++] = sk_aliasing_error(0.0f, finf(), 1.0f, 0.5f, 0.5f);
        r[n++] = sk_aliasing_error(0.01f, 1.0f, finf(), 0.5f, 0.5f);
        r[n++] = sk_aliasing_error(0.01f, 1.0f, 1.0f, 0.5f, finf());
        r[n++] = sk_aliasing_error(-finf(), 1.0f, 1.0f, 0.5f, 0.5f);
        for (i = 0; i < n; i++) SK_CHECK_MSG(!isnan(r[i]), "aliasing inf case %d is NaN", i);
        SK_CHECK(r[0] > 0 && isinf(r[0]));
    }
}

/* ------------------------------------------------------------ RMSM LOD */
static void test_rmsm_lod(void) {
    /* l = log2(sqrt(|dX x dY|)) */
    SK_CHECK_NEAR(sk_rmsm_lod(v2(2, 0), v2(0, 2)), 1.0, 1e-6);
    SK_CHECK_NEAR(sk_rmsm_lod(v2(0.25f, 0), v2(0, 0.25f)), -2.0, 1e-6);
    SK_CHECK_NEAR(sk_rmsm_lod(v2(1, 0), v2(0, 1)), 0.0, 1e-6);
    SK_CHECK_NEAR(sk_rmsm_lod(v2(3, 1), v2(1, 2)), 0.5 * log2(5.0), 1e-6);   /* |6-1| */
    SK_CHECK_NEAR(sk_rmsm_lod(v2(1, 2), v2(3, 1)), 0.5 * log2(5.0), 1e-6);   /* |1-6|: absolute value */
    SK_CHECK_NEAR(sk_rmsm_lod(v2(8, 0), v2(0, 0.5f)), 1.0, 1e-6);            /* anisotropic, area 4 */
    SK_CHECK_NEAR(sk_rmsm_lod(v2(1024, 0), v2(0, 1024)), 10.0, 1e-5);
    SK_CHECK_NEAR(sk_rmsm_lod(v2(0.7f, -0.3f), v2(0.2f, 0.9f)),
                  0.5 * log2(fabs((double)0.7f * 0.9f - (double)-0.3f * 0.2f)), 1e-6);
    /* zero area or NaN: -INFINITY */
    {
        float r[8];
        int n = 0, i;
        r[n++] = sk_rmsm_lod(v2(1, 1), v2(2, 2));
        r[n++] = sk_rmsm_lod(v2(0, 0), v2(0, 0));
        r[n++] = sk_rmsm_lod(v2(0, 0), v2(3, 1));
        r[n++] = sk_rmsm_lod(v2(fnan(), 0), v2(0, 1));
        r[n++] = sk_rmsm_lod(v2(1, fnan()), v2(0, 1));
        r[n++] = sk_rmsm_lod(v2(1, 0), v2(fnan(), 1));
        r[n++] = sk_rmsm_lod(v2(1, 0), v2(0, fnan()));
        for (i = 0; i < n; i++) SK_CHECK_MSG(isinf(r[i]) && r[i] < 0, "lod case %d = %g, expected -inf", i, r[i]);
    }
    /* infinities and extreme magnitudes: never NaN, correct direction */
    {
        float a = sk_rmsm_lod(v2(finf(), 0), v2(0, 1));
        float b = sk_rmsm_lod(v2(finf(), finf()), v2(finf(), finf()));
        float c = sk_rmsm_lod(v2(1e-20f, 0), v2(0, 1e-20f));   /* true value -66.4 */
        float d = sk_rmsm_lod(v2(1e20f, 0), v2(0, 1e20f));     /* true value +66.4 */
        SK_CHECK(!isnan(a) && a > 0);
        SK_CHECK(!isnan(b));
        SK_CHECK_MSG(!isnan(c) && c < -60, "lod(1e-20) = %g", c);
        SK_CHECK_MSG(!isnan(d) && d > 60, "lod(1e20) = %g", d);
    }
}

/* ------------------------------------------------------------ crop matrix */
static void test_crop_matrix(void) {
    const float x0 = -0.5f, y0 = -0.25f, x1 = 0.75f, y1 = 0.5f, zmin = -0.8f, zmax = 0.6f;
    sk_mat4 C = sk_crop_matrix(rect(x0, y0, x1, y1), zmin, zmax);
    double E[16];
    dv3 q;
    memset(E, 0, sizeof E);
    E[0] = 2.0 / ((double)x1 - x0); E[12] = -((double)x1 + x0) / ((double)x1 - x0);
    E[5] = 2.0 / ((double)y1 - y0); E[13] = -((double)y1 + y0) / ((double)y1 - y0);
    E[10] = 2.0 / ((double)zmax - zmin); E[14] = -((double)zmax + zmin) / ((double)zmax - zmin);
    E[15] = 1.0;
    CHECK_MAT_NEAR(C, E, 1e-6, 1e-7);
    q = mpoint(&C, dv(x0, y0, zmin));
    SK_CHECK_NEAR(q.x, -1, 1e-6); SK_CHECK_NEAR(q.y, -1, 1e-6); SK_CHECK_NEAR(q.z, -1, 1e-6);
    q = mpoint(&C, dv(x1, y1, zmax));
    SK_CHECK_NEAR(q.x, 1, 1e-6); SK_CHECK_NEAR(q.y, 1, 1e-6); SK_CHECK_NEAR(q.z, 1, 1e-6);
    q = mpoint(&C, dv(0.5 * (x0 + x1), 0.5 * (y0 + y1), 0.5 * (zmin + zmax)));
    SK_CHECK_NEAR(q.x, 0, 1e-6); SK_CHECK_NEAR(q.y, 0, 1e-6); SK_CHECK_NEAR(q.z, 0, 1e-6);
    /* a tiny sub-rectangle (deep cascade) maps exactly as well */
    /* (the float matrix holds offsets of ~2000 here, so +-1 is reproduced only
       to a few ulp of that offset: tolerance 4 * 2^-24 * (|s x| + |o|)) */
    C = sk_crop_matrix(rect(0.1f, 0.2f, 0.1001f, 0.2002f), -1.0f, 1.0f);
    q = mpoint(&C, dv(0.1001f, 0.2f, 1.0f));
    SK_CHECK_NEAR(q.x, 1, 2.4e-7 * (fabs(C.m[0] * 0.1001f) + fabs(C.m[12])));
    SK_CHECK_NEAR(q.y, -1, 2.4e-7 * (fabs(C.m[5] * 0.2f) + fabs(C.m[13])));
    SK_CHECK_NEAR(q.z, 1, 1e-6);

    /* an empty or non-finite axis is left as the identity; the others still crop */
    {
        struct { sk_rect r; float zn, zf; int idx, xid, yid, zid; } cs[8];
        int n = 0, i;
        cs[n].r = rect(0.3f, y0, 0.3f, y1); cs[n].zn = zmin; cs[n].zf = zmax; cs[n].xid = 1; cs[n].yid = 0; cs[n].zid = 0; n++;
        cs[n].r = rect(0.5f, y0, 0.3f, y1); cs[n].zn = zmin; cs[n].zf = zmax; cs[n].xid = 1; cs[n].yid = 0; cs[n].zid = 0; n++;
        cs[n].r = rect(x0, fnan(), x1, y1); cs[n].zn = zmin; cs[n].zf = zmax; cs[n].xid = 0; cs[n].yid = 1; cs[n].zid = 0; n++;
        cs[n].r = rect(x0, y0, x1, finf()); cs[n].zn = zmin; cs[n].zf = zmax; cs[n].xid = 0; cs[n].yid = 1; cs[n].zid = 0; n++;
        cs[n].r = rect(x0, y0, x1, y1); cs[n].zn = 0.2f; cs[n].zf = 0.2f; cs[n].xid = 0; cs[n].yid = 0; cs[n].zid = 1; n++;
        cs[n].r = rect(x0, y0, x1, y1); cs[n].zn = 0.6f; cs[n].zf = -0.8f; cs[n].xid = 0; cs[n].yid = 0; cs[n].zid = 1; n++;
        cs[n].r = rect(x0, y0, x1, y1); cs[n].zn = -finf(); cs[n].zf = zmax; cs[n].xid = 0; cs[n].yid = 0; cs[n].zid = 1; n++;
        cs[n].r = rect(fnan(), fnan(), fnan(), fnan()); cs[n].zn = fnan(); cs[n].zf = fnan(); cs[n].xid = 1; cs[n].yid = 1; cs[n].zid = 1; n++;
        for (i = 0; i < n; i++) {
            double F[16];
            memcpy(F, E, sizeof F);
            if (cs[i].xid) { F[0] = 1; F[12] = 0; }
            if (cs[i].yid) { F[5] = 1; F[13] = 0; }
            if (cs[i].zid) { F[10] = 1; F[14] = 0; }
            C = sk_crop_matrix(cs[i].r, cs[i].zn, cs[i].zf);
            SK_CHECK_MSG(all_finite_mat(&C), "crop case %d not finite", i);
            SK_CHECK_MSG(mat_worst(&C, F, 1e-6, 1e-7) < 0, "crop case %d: wrong axis handling", i);
        }
    }
}

/* ------------------------------------------------------------ PSSM splits */
/* C_i in double from the float inputs */
static inline double pssm_expected(float zn, float zf, int m, float lambda, int i) {
    double n = zn, f = zf, l = lambda, t = (double)i / m;
    double clog = (l > 0) ? n * pow(f / n, t) : 0.0;
    return l * clog + (1.0 - l) * (n + (f - n) * t);
}
/* every value, endpoints exact, strictly increasing; tolerance: float
   rounding of i/m (6e-8 relative) is amplified by ln(zf/zn) in (zf/zn)^(i/m),
   plus a few ulps for pow, the product and the blend */
static int pssm_check(float zn, float zf, int m, float lambda, int strict) {
    float out[SK_MAX_SPLITS + 4];
    int i, bad = 0;
    double rel = 1e-6 + ((lambda > 0) ? 2e-7 * log((double)zf / zn) : 0.0);
    fill_sentinel(out, sizeof out);
    if (sk_pssm_splits(zn, zf, m, lambda, out) != SK_OK) {
        printf("    pssm(%g,%g,%d,%g) did not return SK_OK\n", zn, zf, m, lambda);
        return 1;
    }
    if (out[0] != zn || out[m] != zf) {
        bad++;
        printf("    pssm(%g,%g,%d,%g): endpoints %.9g, %.9g not exact\n", zn, zf, m, lambda, out[0], out[m]);
    }
    for (i = 0; i <= m; i++) {
        double e = pssm_expected(zn, zf, m, lambda, i);
        if (!isfinite(out[i]) || !(fabs(out[i] - e) <= rel * e + 1e-30)) {
            bad++;
            printf("    pssm(%g,%g,%d,%g): C_%d = %.9g, expected %.9g\n", zn, zf, m, lambda, i, out[i], e);
        }
        if (i > 0 && (strict ? !(out[i] > out[i - 1]) : !(out[i] >= out[i - 1]))) {
            bad++;
            printf("    pssm(%g,%g,%d,%g): not increasing at %d\n", zn, zf, m, lambda, i);
        }
    }
    if (!is_sentinel(out + m + 1, sizeof out - (size_t)(m + 1) * sizeof out[0])) {
        bad++;
        printf("    pssm(%g,%g,%d,%g): wrote past out[m]\n", zn, zf, m, lambda);
    }
    return bad;
}

static void test_pssm_splits(void) {
    float out[SK_MAX_SPLITS + 4];
    int m, i;
    /* hand-computed: zn 1, zf 16, m 4 */
    SK_CHECK(sk_pssm_splits(1.0f, 16.0f, 4, 1.0f, out) == SK_OK);   /* log: 1 2 4 8 16 */
    SK_CHECK_NEAR(out[1], 2.0, 2e-6); SK_CHECK_NEAR(out[2], 4.0, 4e-6); SK_CHECK_NEAR(out[3], 8.0, 8e-6);
    SK_CHECK(sk_pssm_splits(1.0f, 17.0f, 4, 0.0f, out) == SK_OK);   /* uniform: 1 5 9 13 17 */
    SK_CHECK(out[0] == 1.0f && out[4] == 17.0f);
    SK_CHECK_NEAR(out[1], 5.0, 5e-6); SK_CHECK_NEAR(out[2], 9.0, 9e-6); SK_CHECK_NEAR(out[3], 13.0, 1.3e-5);
    SK_CHECK(sk_pssm_splits(1.0f, 16.0f, 4, 0.5f, out) == SK_OK);   /* mean of 1 2 4 8 16 and 1 4.75 8.5 12.25 16 */
    SK_CHECK_NEAR(out[1], 3.375, 4e-6); SK_CHECK_NEAR(out[2], 6.25, 7e-6); SK_CHECK_NEAR(out[3], 10.125, 1.1e-5);

    /* the formula for typical and all m, lambda */
    SK_CHECK(pssm_check(0.1f, 100.0f, 4, 0.75f, 1) == 0);
    SK_CHECK(pssm_check(0.5f, 200.0f, 3, 0.5f, 1) == 0);
    for (m = 1; m <= SK_MAX_SPLITS; m++) {
        SK_CHECK_MSG(pssm_check(0.3f, 500.0f, m, 0.0f, 1) == 0, "uniform m=%d", m);
        SK_CHECK_MSG(pssm_check(0.3f, 500.0f, m, 1.0f, 1) == 0, "log m=%d", m);
        SK_CHECK_MSG(pssm_check(0.3f, 500.0f, m, 0.6f, 1) == 0, "practical m=%d", m);
    }
    /* zn = 0 is allowed for uniform splits */
    SK_CHECK(pssm_check(0.0f, 10.0f, 5, 0.0f, 1) == 0);
    /* the practical scheme lies between the uniform and logarithmic ones */
    {
        float u[SK_MAX_SPLITS + 1], l[SK_MAX_SPLITS + 1], p[SK_MAX_SPLITS + 1];
        SK_CHECK(sk_pssm_splits(0.1f, 1000.0f, 8, 0.0f, u) == SK_OK);
        SK_CHECK(sk_pssm_splits(0.1f, 1000.0f, 8, 1.0f, l) == SK_OK);
        SK_CHECK(sk_pssm_splits(0.1f, 1000.0f, 8, 0.3f, p) == SK_OK);
        for (i = 1; i < 8; i++) SK_CHECK(l[i] < p[i] && p[i] < u[i]);
    }

    /* stability (DESIGN.md): near -> 0 and far/near = 1e6 */
    {
        static const float lams[5] = { 0.0f, 0.25f, 0.5f, 0.9f, 1.0f };
        int li;
        for (li = 0; li < 5; li++)
            for (m = 1; m <= SK_MAX_SPLITS; m++) {
                SK_CHECK_MSG(pssm_check(1e-6f, 1.0f, m, lams[li], 1) == 0, "1e-6..1 m=%d lambda=%g", m, lams[li]);
                SK_CHECK_MSG(pssm_check(0.1f, 1e5f, m, lams[li], 1) == 0, "0.1..1e5 m=%d lambda=%g", m, lams[li]);
                SK_CHECK_MSG(pssm_check(1e-6f, 1e6f, m, lams[li], 1) == 0, "1e-6..1e6 m=%d lambda=%g", m, lams[li]);
            }
        /* adjacent floats: cannot be strictly increasing, must stay ordered and finite */
        SK_CHECK(pssm_check(1.0f, 1.00000012f, SK_MAX_SPLITS, 0.5f, 0) == 0);
        SK_CHECK(pssm_check(1e-30f, 3e38f, SK_MAX_SPLITS, 0.5f, 1) == 0);
    }

    /* bad input: INVALID_ARG, out untouched */
    {
        int bad = 0, r;
        struct { float zn, zf, lam; int m; } cs[24];
        int n = 0;
        cs[n].zn = 1; cs[n].zf = 10; cs[n].m = 0; cs[n].lam = 0.5f; n++;
        cs[n].zn = 1; cs[n].zf = 10; cs[n].m = -1; cs[n].lam = 0.5f; n++;
        cs[n].zn = 1; cs[n].zf = 10; cs[n].m = SK_MAX_SPLITS + 1; cs[n].lam = 0.5f; n++;
        cs[n].zn = 1; cs[n].zf = 10; cs[n].m = 1000000; cs[n].lam = 0.5f; n++;
        cs[n].zn = 1; cs[n].zf = 10; cs[n].m = 4; cs[n].lam = -0.01f; n++;
        cs[n].zn = 1; cs[n].zf = 10; cs[n].m = 4; cs[n].lam = 1.01f; n++;
        cs[n].zn = 1; cs[n].zf = 10; cs[n].m = 4; cs[n].lam = fnan(); n++;
        cs[n].zn = 1; cs[n].zf = 10; cs[n].m = 4; cs[n].lam = finf(); n++;
        cs[n].zn = fnan(); cs[n].zf = 10; cs[n].m = 4; cs[n].lam = 0.5f; n++;
        cs[n].zn = 1; cs[n].zf = fnan(); cs[n].m = 4; cs[n].lam = 0.5f; n++;
        cs[n].zn = 1; cs[n].zf = finf(); cs[n].m = 4; cs[n].lam = 0.5f; n++;
        cs[n].zn = 1; cs[n].zf = finf(); cs[n].m = 4; cs[n].lam = 0.0f; n++;
        cs[n].zn = -finf(); cs[n].zf = 10; cs[n].m = 4; cs[n].lam = 0.0f; n++;
        cs[n].zn = 10; cs[n].zf = 10; cs[n].m = 4; cs[n].lam = 0.5f; n++;
        cs[n].zn = 10; cs[n].zf = 10; cs[n].m = 4; cs[n].lam = 0.0f; n++;
        cs[n].zn = 10; cs[n].zf = 1; cs[n].m = 4; cs[n].lam = 0.5f; n++;
        cs[n].zn = 10; cs[n].zf = 1; cs[n].m = 4; cs[n].lam = 0.0f; n++;
        cs[n].zn = 0; cs[n].zf = 10; cs[n].m = 4; cs[n].lam = 0.5f; n++;
        cs[n].zn = 0; cs[n].zf = 10; cs[n].m = 4; cs[n].lam = 1e-6f; n++;
        cs[n].zn = -1; cs[n].zf = 10; cs[n].m = 4; cs[n].lam = 1.0f; n++;
        cs[n].zn = -1; cs[n].zf = 10; cs[n].m = 4; cs[n].lam = 0.5f; n++;
        for (i = 0; i < n; i++) {
            fill_sentinel(out, sizeof out);
            r = sk_pssm_splits(cs[i].zn, cs[i].zf, cs[i].m, cs[i].lam, out);
            if (r != SK_ERR_INVALID_ARG || !is_sentinel(out, sizeof out)) {
                bad++;
                printf("    pssm bad case %d (zn %g zf %g m %d lambda %g): result %d, out %s\n", i, cs[i].zn,
                       cs[i].zf, cs[i].m, cs[i].lam, r, is_sentinel(out, sizeof out) ? "untouched" : "WRITTEN");
            }
        }
        SK_CHECK_MSG(bad == 0, "%d bad-input cases of sk_pssm_splits wrong", bad);
        SK_CHECK(sk_pssm_splits(1.0f, 10.0f, 4, 0.5f, NULL) == SK_ERR_INVALID_ARG);
    }
}

/* ------------------------------------------------------------ frustum slice */
static void test_frustum_slice(void) {
    const float fovy = 0.9f, aspect = 1.5f, zn = 0.5f, zf = 50.0f;
    cam_t c = make_cam(dv(1, 2, 3), dv(3, -1, -8), dv(0, 1, 0), fovy, aspect);
    sk_frustum view, s;
    int i, bad;
    SK_CHECK(cam_frustum(&c, zn, zf, &view));

    /* slice [2, 10] of a frustum built from exact corners: corners on the
       analytic camera (the lerp adds ~1e-7 relative) and at eye depths d0, d1 */
    fill_sentinel(&s, sizeof s);
    SK_CHECK(sk_frustum_slice(&view, zn, zf, 2.0f, 10.0f, &s) == SK_OK);
    for (i = 0; i < 8; i++) {
        dv3 e = cam_corner(&c, i, 2.0, 10.0);
        double err = dlen(dsub(tod(s.corners[i]), e));
        double depth = ddot(dsub(tod(s.corners[i]), c.eye), c.f);
        SK_CHECK_MSG(err <= 2e-6 * (1 + dlen(dsub(e, c.eye))) * 4, "slice corner %d off by %g", i, err);
        SK_CHECK_NEAR(depth, (i & 4) ? 10.0 : 2.0, 1e-5);
    }
    /* its planes: normalised, through their corners, inward */
    bad = 0;
    {
        int k;
        dv3 cen = dv(0, 0, 0);
        for (i = 0; i < 8; i++) cen = dadd(cen, dmul(tod(s.corners[i]), 0.125));
        for (k = 0; k < 6; k++) {
            if (fabs(dlen(tod(s.planes[k].n)) - 1) > 1e-5) bad++;
            if (!(pdist(&s.planes[k], cen) > 0)) bad++;
        }
        for (i = 0; i < 8; i++) {
            /* near plane (4) holds corners 0-3, far (5) corners 4-7 */
            if (fabs(pdist(&s.planes[(i & 4) ? 5 : 4], tod(s.corners[i]))) > 1e-4) bad++;
            if (fabs(pdist(&s.planes[(i & 1) ? 1 : 0], tod(s.corners[i]))) > 1e-4) bad++;
            if (fabs(pdist(&s.planes[(i & 2) ? 3 : 2], tod(s.corners[i]))) > 1e-4) bad++;
        }
    }
    SK_CHECK_MSG(bad == 0, "slice planes: %d violations", bad);
    /* the whole range gives back the view's corners */
    SK_CHECK(sk_frustum_slice(&view, zn, zf, zn, zf, &s) == SK_OK);
    for (i = 0; i < 8; i++)
        SK_CHECK_MSG(dlen(dsub(tod(s.corners[i]), tod(view.corners[i]))) <= 1e-5 * (1 + dlen(tod(view.corners[i]))),
                     "full slice corner %d moved", i);
    /* through sk_frustum_from_matrix of the same camera (its corners carry the
       unprojection error ~1e-7 d^2/zn, see test_core.c): depths still d0, d1 */
    {
        sk_mat4 VP = sk_mat4_mul(sk_mat4_perspective(fovy, aspect, zn, zf),
                                 sk_mat4_look_at(tof(c.eye), tof(dadd(c.eye, c.f)), v3(0, 1, 0)));
        sk_frustum vm = sk_frustum_from_matrix(VP);
        SK_CHECK(sk_frustum_slice(&vm, zn, zf, 3.0f, 7.5f, &s) == SK_OK);
        for (i = 0; i < 8; i++) {
            double depth = ddot(dsub(tod(s.corners[i]), c.eye), c.f);
            SK_CHECK_NEAR(depth, (i & 4) ? 7.5 : 3.0, 2e-3);
        }
    }
    /* PSSM cascades tile the frustum: slice i's far corners = slice i+1's near corners */
    {
        float sp[5];
        sk_frustum a, b;
        int j;
        SK_CHECK(sk_pssm_splits(zn, zf, 4, 0.7f, sp) == SK_OK);
        for (j = 0; j < 3; j++) {
            SK_CHECK(sk_frustum_slice(&view, zn, zf, sp[j], sp[j + 1], &a) == SK_OK);
            SK_CHECK(sk_frustum_slice(&view, zn, zf, sp[j + 1], sp[j + 2], &b) == SK_OK);
            for (i = 0; i < 4; i++)
                SK_CHECK(dlen(dsub(tod(a.corners[i + 4]), tod(b.corners[i]))) <= 1e-5 * (1 + dlen(tod(b.corners[i]))));
        }
    }
    /* stability (DESIGN.md): near -> 0 and far/near = 1e6, through the whole
       PSSM pipeline. The float gluPerspective matrix itself places its far
       plane only to ~1% at this ratio (1 + m[10] ~ -2e-6 carries a float
       rounding of 6e-8), so slice depths are checked against the view's own
       near/far corners, not against the nominal zf. */
    {
        const float n6 = 0.01f, f6 = 1e4f;
        sk_mat4 VP = sk_mat4_mul(sk_mat4_perspective(1.0f, 1.0f, n6, f6),
                                 sk_mat4_look_at(v3(0, 0, 0), v3(0, 0, -1), v3(0, 1, 0)));
        sk_frustum v6 = sk_frustum_from_matrix(VP), sl, prev;
        float sp[SK_MAX_SPLITS + 1];
        double zfar = -(double)v6.corners[4].z;
        int m, j, li, bad6 = 0, have_prev;
        static const float lams[3] = { 0.0f, 0.5f, 1.0f };
        SK_CHECK(fabs(zfar - f6) <= 0.02 * f6);   /* precondition, see above */
        for (li = 0; li < 3; li++)
            for (m = 1; m <= 8; m++) {
                if (sk_pssm_splits(n6, f6, m, lams[li], sp) != SK_OK) { bad6++; continue; }
                have_prev = 0;
                for (j = 0; j < m; j++) {
                    sk_result r = sk_frustum_slice(&v6, n6, f6, sp[j], sp[j + 1], &sl);
                    double t0 = ((double)sp[j] - n6) / ((double)f6 - n6), t1 = ((double)sp[j + 1] - n6) / ((double)f6 - n6);
                    double e0 = n6 + t0 * (zfar - n6), e1 = n6 + t1 * (zfar - n6);
                    if (r != SK_OK) {
                        bad6++;
                        printf("    far/near 1e6: m=%d lambda=%g slice %d [%g,%g] -> %s\n", m, lams[li], j, sp[j],
                               sp[j + 1], sk_result_string(r));
                        have_prev = 0;
                        continue;
                    }
                    for (i = 0; i < 8; i++) {
                        double dep = -(double)sl.corners[i].z, e = (i & 4) ? e1 : e0;
                        if (!isfinite(sl.corners[i].x) || !isfinite(sl.corners[i].y) || !(fabs(dep - e) <= 1e-5 * e + 1e-9)) {
                            bad6++;
                            printf("    far/near 1e6: m=%d lambda=%g slice %d corner %d depth %.9g, expected %.9g\n",
                                   m, lams[li], j, i, dep, e);
                        }
                        if (have_prev && i < 4 && !(sl.corners[i].z == prev.corners[i + 4].z)) {
                            if (fabs((double)sl.corners[i].z - prev.corners[i + 4].z) > 1e-6 * e) bad6++;
                        }
                    }
                    prev = sl;
                    have_prev = 1;
                }
            }
        SK_CHECK_MSG(bad6 == 0, "far/near 1e6 PSSM slicing: %d failures", bad6);
        /* the first, thinnest slice of a 1e-3 .. 1e3 view */
        VP = sk_mat4_mul(sk_mat4_perspective(1.0f, 1.0f, 1e-3f, 1e3f),
                         sk_mat4_look_at(v3(0, 0, 0), v3(0, 0, -1), v3(0, 1, 0)));
        v6 = sk_frustum_from_matrix(VP);
        SK_CHECK(sk_frustum_slice(&v6, 1e-3f, 1e3f, 1e-3f, 2e-3f, &sl) == SK_OK);
        for (i = 0; i < 4; i++) {
            SK_CHECK(isfinite(sl.corners[i].x) && isfinite(sl.corners[i].y));
            SK_CHECK_NEAR(-sl.corners[i].z, 1e-3, 1e-9);
        }
    }

    /* bad input: INVALID_ARG, out untouched */
    {
        struct { float zn, zf, d0, d1; } cs[20];
        int n = 0, r;
        cs[n].zn = zn; cs[n].zf = zf; cs[n].d0 = 0.4f; cs[n].d1 = 10; n++;     /* d0 < zn */
        cs[n].zn = zn; cs[n].zf = zf; cs[n].d0 = 2; cs[n].d1 = 51; n++;        /* d1 > zf */
        cs[n].zn = zn; cs[n].zf = zf; cs[n].d0 = 5; cs[n].d1 = 5; n++;         /* d0 == d1 */
        cs[n].zn = zn; cs[n].zf = zf; cs[n].d0 = 10; cs[n].d1 = 2; n++;        /* d0 > d1 */
        cs[n].zn = zf; cs[n].zf = zn; cs[n].d0 = 2; cs[n].d1 = 10; n++;        /* zf < zn */
        cs[n].zn = 5; cs[n].zf = 5; cs[n].d0 = 5; cs[n].d1 = 5; n++;           /* zf == zn */
        /* (zn = 0 is accepted: a slice is a lerp, valid for an ortho view too,
           as PSSM accepts zn = 0 for uniform splits) */
        cs[n].zn = -1; cs[n].zf = zf; cs[n].d0 = 2; cs[n].d1 = 10; n++;
        cs[n].zn = fnan(); cs[n].zf = zf; cs[n].d0 = 2; cs[n].d1 = 10; n++;
        cs[n].zn = zn; cs[n].zf = fnan(); cs[n].d0 = 2; cs[n].d1 = 10; n++;
        cs[n].zn = zn; cs[n].zf = zf; cs[n].d0 = fnan(); cs[n].d1 = 10; n++;
        cs[n].zn = zn; cs[n].zf = zf; cs[n].d0 = 2; cs[n].d1 = fnan(); n++;
        cs[n].zn = zn; cs[n].zf = finf(); cs[n].d0 = 2; cs[n].d1 = 10; n++;
        cs[n].zn = zn; cs[n].zf = finf(); cs[n].d0 = 2; cs[n].d1 = finf(); n++;
        cs[n].zn = -finf(); cs[n].zf = zf; cs[n].d0 = 2; cs[n].d1 = 10; n++;
        bad = 0;
        for (i = 0; i < n; i++) {
            fill_sentinel(&s, sizeof s);
            r = sk_frustum_slice(&view, cs[i].zn, cs[i].zf, cs[i].d0, cs[i].d1, &s);
            if (r != SK_ERR_INVALID_ARG || !is_sentinel(&s, sizeof s)) {
                bad++;
                printf("    slice bad case %d (%g %g %g %g): result %d\n", i, cs[i].zn, cs[i].zf, cs[i].d0, cs[i].d1, r);
            }
        }
        SK_CHECK_MSG(bad == 0, "%d bad-input cases of sk_frustum_slice wrong", bad);
        fill_sentinel(&s, sizeof s);
        SK_CHECK(sk_frustum_slice(NULL, zn, zf, 2, 10, &s) == SK_ERR_INVALID_ARG);
        SK_CHECK(sk_frustum_slice(&view, zn, zf, 2, 10, NULL) == SK_ERR_INVALID_ARG);
        {
            sk_frustum nv = view;
            nv.corners[6].y = fnan();
            SK_CHECK(sk_frustum_slice(&nv, zn, zf, 2, 10, &s) == SK_ERR_INVALID_ARG);
        }
        SK_CHECK(is_sentinel(&s, sizeof s));
    }
}

/* ------------------------------------------------------------ bounding sphere */
static int sphere_contains_corners(sk_sphere sp, const sk_frustum *f, double *worst) {
    int i, ok = 1;
    *worst = 0;
    for (i = 0; i < 8; i++) {
        double d = dlen(dsub(tod(f->corners[i]), tod(sp.c)));
        if (d - sp.r > *worst) *worst = d - sp.r;
        if (d > (double)sp.r) ok = 0;
    }
    return ok;
}
static inline int same_radius(float a, float b) { return a == b || fabs((double)a - b) <= 1e-6 * fabs((double)a); }

static void test_frustum_bounding_sphere(void) {
    const float fovy = 0.6f, aspect = 1.0f;
    dv3 eye = dv(2, 1, -3), fwd = dv(0.3, -0.2, -1), up = dv(0, 1, 0);
    cam_t c = make_cam(eye, fwd, up, fovy, aspect);
    sk_frustum f, g;
    sk_sphere s, s2;
    double worst, k = c.ty * sqrt(1.0 + (double)aspect * aspect);
    int i;

    /* a slice [10, 30]: near half-diagonal a = 10k, far b = 30k, length L = 20.
       Balanced centre at t = (L^2 + b^2 - a^2)/(2L) from the near centre, here
       inside [0, L], radius sqrt(t^2 + a^2), then rounded up by at most 2^-9. */
    {
        double a = 10 * k, b = 30 * k, L = 20, t = (L * L + b * b - a * a) / (2 * L), r = sqrt(t * t + a * a);
        dv3 ce = dadd(eye, dmul(c.f, 10 + t));
        SK_CHECK(t > 0 && t < L);   /* precondition: minimal and balanced spheres coincide */
        SK_CHECK(cam_frustum(&c, 10, 30, &f));
        s = sk_frustum_bounding_sphere(&f);
        SK_CHECK_MSG(dlen(dsub(tod(s.c), ce)) <= 1e-4, "centre off by %g", dlen(dsub(tod(s.c), ce)));
        SK_CHECK_MSG(s.r >= r - 1e-5 && s.r <= r * (1 + 1.0 / 512) + 1e-5, "radius %.9g, expected %.9g (+2^-9)", s.r, r);
        SK_CHECK_MSG(sphere_contains_corners(s, &f, &worst), "corner outside by %g", worst);
        /* balanced: near and far corners equally far from the centre */
        SK_CHECK_NEAR(dlen(dsub(tod(f.corners[0]), tod(s.c))), dlen(dsub(tod(f.corners[7]), tod(s.c))), 1e-4);
    }

    /* a wide cascade [2, 10] (fovy 0.9, aspect 1.5): the balanced point lies
       beyond the far face; any reading of the contract contains all corners,
       keeps the centre on the axis, and is no bigger than the balanced sphere */
    {
        cam_t w = make_cam(eye, fwd, up, 0.9f, 1.5f);
        double kw = w.ty * sqrt(1.0 + 2.25), a = 2 * kw, b = 10 * kw, L = 8;
        double t = (L * L + b * b - a * a) / (2 * L), rb = sqrt(t * t + a * a);
        dv3 rel;
        SK_CHECK(t > L);  /* precondition */
        SK_CHECK(cam_frustum(&w, 2, 10, &f));
        s = sk_frustum_bounding_sphere(&f);
        SK_CHECK_MSG(sphere_contains_corners(s, &f, &worst), "wide: corner outside by %g", worst);
        SK_CHECK(s.r <= rb * (1 + 1.0 / 512) + 1e-5);
        SK_CHECK(s.r >= b - 1e-5);
        rel = dsub(tod(s.c), eye);
        SK_CHECK_MSG(dlen(dsub(rel, dmul(w.f, ddot(rel, w.f)))) <= 1e-4, "wide: centre off the axis");
    }

    /* invariance under rigid motion: same radius (bitwise or 1e-6 relative),
       centre moved by the same motion (1e-4) */
    SK_CHECK(cam_frustum(&c, 10, 30, &f));
    s = sk_frustum_bounding_sphere(&f);
    {
        int trial, rbad = 0, cbad = 0;
        for (trial = 0; trial < 40; trial++) {
            dv3 T = dv(rnd(-20, 20), rnd(-5, 5), rnd(-20, 20));
            dv3 ax = dnorm(dv(rnd(-1, 1), rnd(-1, 1), rnd(-1, 1)));
            double ang = rnd(-3, 3);
            /* move the camera: eye -> R eye + T, axes rotated */
            cam_t m = c;
            dv3 expc;
            m.eye = dadd(drot(eye, ax, ang), T);
            m.f = drot(c.f, ax, ang); m.s = drot(c.s, ax, ang); m.u = drot(c.u, ax, ang);
            SK_CHECK(cam_frustum(&m, 10, 30, &g));
            s2 = sk_frustum_bounding_sphere(&g);
            expc = dadd(drot(tod(s.c), ax, ang), T);
            if (!same_radius(s.r, s2.r)) {
                rbad++;
                printf("    rigid motion %d: radius %.9g -> %.9g\n", trial, s.r, s2.r);
            }
            if (dlen(dsub(tod(s2.c), expc)) > 1e-4) {
                cbad++;
                printf("    rigid motion %d: centre off by %g\n", trial, dlen(dsub(tod(s2.c), expc)));
            }
        }
        SK_CHECK_MSG(rbad == 0, "%d of 40 rigid motions changed the radius", rbad);
        SK_CHECK_MSG(cbad == 0, "%d of 40 rigid motions moved the centre wrongly", cbad);
    }
    /* the PSSM pipeline (from_matrix -> slice -> sphere) under sub-texel camera
       translations: the radius must not change */
    {
        int j, rbad = 0;
        sk_sphere base;
        for (j = 0; j < 30; j++) {
            dv3 e2 = dadd(eye, dv(0.0071 * j, -0.0033 * j, 0.0127 * j));
            sk_mat4 VP = sk_mat4_mul(sk_mat4_perspective(0.9f, 1.5f, 0.5f, 50.0f),
                                     sk_mat4_look_at(tof(e2), tof(dadd(e2, fwd)), v3(0, 1, 0)));
            sk_frustum vm = sk_frustum_from_matrix(VP), sl;
            sk_sphere sp;
            SK_CHECK(sk_frustum_slice(&vm, 0.5f, 50.0f, 2.0f, 10.0f, &sl) == SK_OK);
            sp = sk_frustum_bounding_sphere(&sl);
            if (j == 0) base = sp;
            else if (!same_radius(base.r, sp.r)) {
                rbad++;
                printf("    pipeline translation %d: radius %.9g -> %.9g\n", j, base.r, sp.r);
            }
            SK_CHECK(sphere_contains_corners(sp, &sl, &worst));
        }
        SK_CHECK_MSG(rbad == 0, "%d of 29 camera translations changed the cascade radius", rbad);
    }
    /* the same for a wide cascade whose exact radius, 10 tan(0.96) sqrt(3.25)
       = 25.7502, lies just above a rounding step (824/32): a pure camera
       translation must still leave the radius alone */
    {
        static const float eyes[4][3] = { { 0, 2, 0 }, { -8.04f, 2, 9.33f }, { 3.1f, 2, -4.4f }, { 55.5f, 2, 71.25f } };
        float r0 = 0;
        int j, rbad = 0;
        for (j = 0; j < 4; j++) {
            sk_vec3 e2 = v3(eyes[j][0], eyes[j][1], eyes[j][2]);
            sk_mat4 VP = sk_mat4_mul(sk_mat4_perspective(1.92f, 1.5f, 0.5f, 50.0f),
                                     sk_mat4_look_at(e2, v3(e2.x - 0.2f, e2.y - 0.3f, e2.z - 1.0f), v3(0, 1, 0)));
            sk_frustum vm = sk_frustum_from_matrix(VP), sl;
            sk_sphere sp;
            SK_CHECK(sk_frustum_slice(&vm, 0.5f, 50.0f, 2.0f, 10.0f, &sl) == SK_OK);
            /* sk_frustum_bounding_sphere rounds a noisy radius and may flip
               here, exactly at a rounding step (documented); the
               parameter-based sphere must not */
            sp = sk_cascade_sphere(sk_mat4_look_at(e2, v3(e2.x - 0.2f, e2.y - 0.3f, e2.z - 1.0f), v3(0, 1, 0)),
                                   1.92f, 1.5f, 2.0f, 10.0f);
            SK_CHECK(sphere_contains_corners(sp, &sl, &worst));
            /* exact radius 10 tan(0.96) sqrt(3.25), plus the documented 1e-4 relative margin */
            SK_CHECK_NEAR(sp.r, 10.0 * tan(0.96) * sqrt(1.0 + 1.5 * 1.5) * (1.0 + 1e-4), 1e-4);
            if (j == 0) r0 = sp.r;
            else if (!same_radius(r0, sp.r)) {
                rbad++;
                printf("    fovy 1.92 cascade, eye (%g,%g,%g): radius %.9g, at eye (0,2,0) %.9g\n", e2.x, e2.y, e2.z,
                       sp.r, r0);
            }
        }
        SK_CHECK_MSG(rbad == 0, "fovy 1.92 cascade (sk_cascade_sphere): %d of 3 camera translations changed the radius", rbad);
    }

    /* bad input: never NaN, never a crash */
    {
        sk_frustum z, nf;
        memset(&z, 0, sizeof z);
        s = sk_frustum_bounding_sphere(&z);
        SK_CHECK(!isnan(s.r) && !isnan(s.c.x) && !isnan(s.c.y) && !isnan(s.c.z) && s.r >= 0);
        nf = f;
        nf.corners[2].x = fnan();
        s = sk_frustum_bounding_sphere(&nf);
        SK_CHECK_MSG(!isnan(s.r) && !isnan(s.c.x) && !isnan(s.c.y) && !isnan(s.c.z), "NaN corner gives NaN sphere");
        nf = f;
        nf.corners[6].z = finf();
        s = sk_frustum_bounding_sphere(&nf);
        SK_CHECK_MSG(!isnan(s.r) && !isnan(s.c.x) && !isnan(s.c.y) && !isnan(s.c.z), "Inf corner gives NaN sphere");
        s = sk_frustum_bounding_sphere(NULL);
        SK_CHECK(!isnan(s.r) && !isnan(s.c.x) && !isnan(s.c.y) && !isnan(s.c.z));
    }
    (void)i;
}

/* ------------------------------------------------------------ light view */
static void test_light_view_directional(void) {
    static const float dirs[][3] = { { 0.3f, -1.0f, 0.2f }, { 1, 0, 0 }, { 0, -1, 0 }, { 0, 1, 0 }, { 0, 0, -1 },
                                     { 0, 0, 1 }, { 1e-7f, -1, 0 }, { -0.2f, -0.3f, -5.0f }, { 1e-20f, 1e-20f, -1e-20f },
                                     { 3e30f, -1e30f, 0 } };
    int i, k;
    sk_mat4 V, D;
    for (i = 0; i < (int)(sizeof dirs / sizeof dirs[0]); i++) {
        dv3 d = dnorm(dv(dirs[i][0], dirs[i][1], dirs[i][2])), q;
        V = sk_light_view_directional(v3(dirs[i][0], dirs[i][1], dirs[i][2]));
        SK_CHECK_MSG(all_finite_mat(&V), "light view %d not finite", i);
        SK_CHECK_MSG(rigid_error(&V) <= 1e-6, "light view %d not rigid (%g)", i, rigid_error(&V));
        q = mdir(&V, d);   /* looks along the light direction: d -> -z */
        SK_CHECK_MSG(fabs(q.x) <= 1e-6 && fabs(q.y) <= 1e-6 && fabs(q.z + 1) <= 1e-6,
                     "light view %d maps the light direction to (%g,%g,%g)", i, q.x, q.y, q.z);
    }
    /* continuity: a small change of direction is a small change of the view
       (a fixed world up axis, not re-derived per call from something unstable) */
    {
        sk_mat4 A = sk_light_view_directional(v3(0.3f, -1.0f, 0.2f));
        sk_mat4 B = sk_light_view_directional(v3(0.3001f, -1.0f, 0.2f));
        double w = 0;
        for (k = 0; k < 12; k++) if (fabs((double)A.m[k] - B.m[k]) > w) w = fabs((double)A.m[k] - B.m[k]);
        SK_CHECK_MSG(w <= 1e-3, "light view jumps by %g for a 1e-4 change of direction", w);
        /* scale invariance: only the direction matters */
        B = sk_light_view_directional(v3(3.0f, -10.0f, 2.0f));
        w = 0;
        for (k = 0; k < 16; k++) if (fabs((double)A.m[k] - B.m[k]) > w) w = fabs((double)A.m[k] - B.m[k]);
        SK_CHECK_MSG(w <= 1e-6, "light view depends on |dir| (%g)", w);
    }
    /* zero or non-finite: looks down -Y */
    D = sk_light_view_directional(v3(0, -1, 0));
    {
        sk_vec3 bad[6];
        int n = 0;
        bad[n++] = v3(0, 0, 0);
        bad[n++] = v3(fnan(), -1, 0);
        bad[n++] = v3(0, fnan(), 0);
        bad[n++] = v3(finf(), -1, 0);
        bad[n++] = v3(0, 0, -finf());
        for (i = 0; i < n; i++) {
            dv3 q;
            V = sk_light_view_directional(bad[i]);
            SK_CHECK_MSG(all_finite_mat(&V) && rigid_error(&V) <= 1e-6, "fallback light view %d invalid", i);
            q = mdir(&V, dv(0, -1, 0));
            SK_CHECK_MSG(fabs(q.x) <= 1e-6 && fabs(q.y) <= 1e-6 && fabs(q.z + 1) <= 1e-6,
                         "fallback light view %d does not look down -Y", i);
            {   /* the same view as an explicit -Y direction */
                double E[16];
                for (k = 0; k < 16; k++) E[k] = D.m[k];
                SK_CHECK_MSG(mat_worst(&V, E, 0, 1e-6) < 0, "fallback light view %d differs from dir (0,-1,0)", i);
            }
        }
    }
}

/* ------------------------------------------------------------ fit ortho */
static void test_fit_ortho(void) {
    dv3 eye = dv(0, 3, 12), target = dv(1, 0, 0);
    sk_mat4 VP = sk_mat4_mul(sk_mat4_perspective(0.8f, 1.5f, 0.5f, 30.0f),
                             sk_mat4_look_at(tof(eye), tof(target), v3(0, 1, 0)));
    sk_frustum view = sk_frustum_from_matrix(VP);
    sk_aabb scene = box3(-15, -1, -15, 15, 4, 15);
    sk_vec3 pts[SK_CLIP_MAX_POINTS];
    sk_mat4 L = sk_light_view_directional(v3(0.3f, -1.0f, 0.2f)), P, P0;
    int n = sk_clip_frustum_aabb(&view, scene, pts, SK_CLIP_MAX_POINTS), i;
    double lo[3] = { 1e9, 1e9, 1e9 }, hi[3] = { -1e9, -1e9, -1e9 };
    SK_CHECK_MSG(n >= 4, "precondition: clip gave %d points", n);
    if (n < 4) return;

    /* no casters: points in [-1,1]^3; x, y fitted (both extremes reached) */
    fill_sentinel(&P0, sizeof P0);
    SK_CHECK(sk_fit_ortho(pts, n, L, NULL, &P0) == SK_OK);
    SK_CHECK(all_finite_mat(&P0));
    SK_CHECK(P0.m[3] == 0 && P0.m[7] == 0 && P0.m[11] == 0 && P0.m[15] == 1);  /* orthographic */
    for (i = 0; i < n; i++) {
        dv3 q = mpoint2(&P0, &L, tod(pts[i]));
        if (q.x < lo[0]) lo[0] = q.x;
        if (q.y < lo[1]) lo[1] = q.y;
        if (q.z < lo[2]) lo[2] = q.z;
        if (q.x > hi[0]) hi[0] = q.x;
        if (q.y > hi[1]) hi[1] = q.y;
        if (q.z > hi[2]) hi[2] = q.z;
    }
    SK_CHECK_MSG(lo[0] >= -1 - 1e-5 && hi[0] <= 1 + 1e-5 && lo[1] >= -1 - 1e-5 && hi[1] <= 1 + 1e-5 &&
                 lo[2] >= -1 - 1e-5 && hi[2] <= 1 + 1e-5,
                 "points outside [-1,1]^3: x [%g,%g] y [%g,%g] z [%g,%g]", lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]);
    /* "fitted": the focused map is tight in x and y (1e-3 of the extent: a
       small safety margin is allowed, not a loose box) */
    SK_CHECK_MSG(lo[0] <= -1 + 1e-3 && hi[0] >= 1 - 1e-3 && lo[1] <= -1 + 1e-3 && hi[1] >= 1 - 1e-3,
                 "not fitted: x [%g,%g] y [%g,%g]", lo[0], hi[0], lo[1], hi[1]);

    /* casters between the light and the receivers, off to the side: their near
       side must not be clipped (z_ndc >= -1), receivers still inside */
    {
        dv3 ldir = dnorm(dv(0.3, -1, 0.2));
        dv3 cc = dsub(dv(0, 1, 0), dmul(ldir, 40));   /* 40 units up-light of the scene */
        sk_aabb cas = box3((float)cc.x - 2, (float)cc.y - 1, (float)cc.z - 2, (float)cc.x + 2, (float)cc.y + 1, (float)cc.z + 2);
        double zmin = 1e9, ptmin = 1e9, ptmax = -1e9;
        SK_CHECK(sk_fit_ortho(pts, n, L, &cas, &P) == SK_OK);
        SK_CHECK(all_finite_mat(&P));
        for (i = 0; i < 8; i++) {
            dv3 q = mpoint2(&P, &L, dv((i & 1) ? cas.max.x : cas.min.x, (i & 2) ? cas.max.y : cas.min.y,
                                       (i & 4) ? cas.max.z : cas.min.z));
            if (q.z < zmin) zmin = q.z;
        }
        SK_CHECK_MSG(zmin >= -1 - 1e-5, "caster near side clipped: z_ndc = %g", zmin);
        for (i = 0; i < n; i++) {
            dv3 q = mpoint2(&P, &L, tod(pts[i]));
            if (q.z < ptmin) ptmin = q.z;
            if (q.z > ptmax) ptmax = q.z;
            SK_CHECK(fabs(q.x) <= 1 + 1e-5 && fabs(q.y) <= 1 + 1e-5);
        }
        SK_CHECK_MSG(ptmin >= -1 - 1e-5 && ptmax <= 1 + 1e-5, "receivers z [%g,%g] with casters", ptmin, ptmax);
        /* x and y are still fitted to the points, not to the casters */
        SK_CHECK(fabs(P.m[0] - P0.m[0]) <= 1e-6 * fabs(P0.m[0]) && fabs(P.m[5] - P0.m[5]) <= 1e-6 * fabs(P0.m[5]));
        SK_CHECK(fabs(P.m[12] - P0.m[12]) <= 1e-6 && fabs(P.m[13] - P0.m[13]) <= 1e-6);
        /* casters behind the receivers (further along the light) change nothing that matters */
        {
            dv3 bc = dadd(dv(0, 1, 0), dmul(ldir, 40));
            sk_aabb behind = box3((float)bc.x - 1, (float)bc.y - 1, (float)bc.z - 1, (float)bc.x + 1, (float)bc.y + 1, (float)bc.z + 1);
            SK_CHECK(sk_fit_ortho(pts, n, L, &behind, &P) == SK_OK);
            for (i = 0; i < n; i++) {
                dv3 q = mpoint2(&P, &L, tod(pts[i]));
                SK_CHECK(fabs(q.x) <= 1 + 1e-5 && fabs(q.y) <= 1 + 1e-5 && fabs(q.z) <= 1 + 1e-5);
            }
        }
    }
    /* a single point / a flat set: valid or a documented error, never NaN */
    {
        sk_vec3 one[1];
        sk_result r;
        one[0] = v3(1, 2, 3);
        fill_sentinel(&P, sizeof P);
        r = sk_fit_ortho(one, 1, L, NULL, &P);
        SK_CHECK(r == SK_OK || r == SK_ERR_DEGENERATE);
        if (r == SK_OK) {
            dv3 q = mpoint2(&P, &L, tod(one[0]));
            SK_CHECK(all_finite_mat(&P));
            SK_CHECK(fabs(q.x) <= 1 + 1e-5 && fabs(q.y) <= 1 + 1e-5 && fabs(q.z) <= 1 + 1e-5);
        }
    }
    /* bad input: INVALID_ARG, out untouched */
    {
        sk_vec3 bp[4];
        sk_mat4 BL = L;
        sk_aabb bc = box3(1, 1, 1, 0, 2, 2), nc = box3(0, 0, fnan(), 1, 1, 1);
        for (i = 0; i < 4; i++) bp[i] = pts[i];
        fill_sentinel(&P, sizeof P);
        SK_CHECK(sk_fit_ortho(NULL, 4, L, NULL, &P) == SK_ERR_INVALID_ARG);
        SK_CHECK(sk_fit_ortho(bp, 0, L, NULL, &P) == SK_ERR_INVALID_ARG);
        SK_CHECK(sk_fit_ortho(bp, -3, L, NULL, &P) == SK_ERR_INVALID_ARG);
        SK_CHECK(sk_fit_ortho(bp, 4, L, NULL, NULL) == SK_ERR_INVALID_ARG);
        SK_CHECK(sk_fit_ortho(bp, 4, L, &bc, &P) == SK_ERR_INVALID_ARG);
        SK_CHECK(sk_fit_ortho(bp, 4, L, &nc, &P) == SK_ERR_INVALID_ARG);
        BL.m[5] = fnan();
        SK_CHECK(sk_fit_ortho(bp, 4, BL, NULL, &P) == SK_ERR_INVALID_ARG);
        BL = L; BL.m[13] = finf();
        SK_CHECK(sk_fit_ortho(bp, 4, BL, NULL, &P) == SK_ERR_INVALID_ARG);
        bp[2].y = fnan();
        SK_CHECK(sk_fit_ortho(bp, 4, L, NULL, &P) == SK_ERR_INVALID_ARG);
        bp[2].y = finf();
        SK_CHECK(sk_fit_ortho(bp, 4, L, NULL, &P) == SK_ERR_INVALID_ARG);
        SK_CHECK(is_sentinel(&P, sizeof P));
    }
}

/* ------------------------------------------------------------ stable crop */
/* texel coordinates (u, v) of world point p under light_vp = P * L, res texels */
static inline void texel_uv(const sk_mat4 *P, const sk_mat4 *L, dv3 p, int res, double *u, double *v) {
    dv3 q = mpoint2(P, L, p);
    *u = (q.x + 1.0) * 0.5 * res;
    *v = (q.y + 1.0) * 0.5 * res;
}
/* sphere inside the map: centre +- r along light-view x, y, z within [-1,1] */
static int sphere_inside(const sk_mat4 *P, const sk_mat4 *L, sk_sphere s, double tol) {
    dv3 cl = mpoint(L, tod(s.c));
    int a, sg;
    for (a = 0; a < 3; a++)
        for (sg = -1; sg <= 1; sg += 2) {
            dv3 p = cl, q;
            if (a == 0) p.x += sg * (double)s.r;
            if (a == 1) p.y += sg * (double)s.r;
            if (a == 2) p.z += sg * (double)s.r;
            q = mpoint(P, p);
            if (!(fabs(q.x) <= 1 + tol && fabs(q.y) <= 1 + tol && fabs(q.z) <= 1 + tol)) return 0;
        }
    return 1;
}
/* the world -> texel mapping of two crops differs by whole texels only:
   returns the worst fractional difference over the points */
static double texel_shift_frac(const sk_mat4 *P1, const sk_mat4 *P2, const sk_mat4 *L, const dv3 *pts, int n, int res) {
    double worst = 0;
    int i;
    for (i = 0; i < n; i++) {
        double u1, v1, u2, v2, f;
        texel_uv(P1, L, pts[i], res, &u1, &v1);
        texel_uv(P2, L, pts[i], res, &u2, &v2);
        f = frac_dist(u2 - u1); if (f > worst) worst = f;
        f = frac_dist(v2 - v1); if (f > worst) worst = f;
    }
    return worst;
}

static void test_stable_crop(void) {
    const int res = 1024;
    sk_mat4 L = sk_light_view_directional(v3(0.3f, -1.0f, 0.2f)), P, P2;
    sk_sphere s = sphere(3.2f, 1.1f, -4.7f, 12.5f);
    dv3 xa = dv(L.m[0], L.m[4], L.m[8]), ya = dv(L.m[1], L.m[5], L.m[9]), za = dv(L.m[2], L.m[6], L.m[10]);
    dv3 wp[24];
    double texel = 2.0 * s.r / (res - 1), w;
    int i;
    for (i = 0; i < 24; i++) wp[i] = dadd(tod(s.c), dv(rnd(-8, 8), rnd(-8, 8), rnd(-8, 8)));

    fill_sentinel(&P, sizeof P);
    SK_CHECK(sk_stable_crop(s, L, res, NULL, &P) == SK_OK);
    SK_CHECK(all_finite_mat(&P));
    SK_CHECK(P.m[3] == 0 && P.m[7] == 0 && P.m[11] == 0 && P.m[15] == 1);  /* orthographic */
    /* texel size in world units is the documented 2r/(res-1) on both axes */
    SK_CHECK_NEAR(2.0 / (P.m[0] * res), texel, texel * 1e-5);
    SK_CHECK_NEAR(2.0 / (P.m[5] * res), texel, texel * 1e-5);
    SK_CHECK_MSG(sphere_inside(&P, &L, s, 1e-5), "sphere not inside the stable map");

    /* sub-texel moves of the sphere (= the camera): whole-texel shifts only */
    {
        static const double steps[][3] = { { 0.3, 0, 0 }, { 0, 0.7, 0 }, { 0.45, -0.2, 0 }, { 0, 0, 0.3 },
                                           { 37.3, -12.6, 5 }, { -0.01, 0.99, 0 }, { 0.5, 0.5, 0 } };
        int j;
        for (j = 0; j < (int)(sizeof steps / sizeof steps[0]); j++) {
            dv3 mv = dadd(dadd(dmul(xa, steps[j][0] * texel), dmul(ya, steps[j][1] * texel)), dmul(za, steps[j][2] * texel));
            sk_sphere s2 = s;
            s2.c = tof(dadd(tod(s.c), mv));
            SK_CHECK(sk_stable_crop(s2, L, res, NULL, &P2) == SK_OK);
            /* same texel size (float noise of the ortho bounds aside) */
            SK_CHECK(fabs(P2.m[0] - P.m[0]) <= 1e-6 * fabs(P.m[0]) && fabs(P2.m[5] - P.m[5]) <= 1e-6 * fabs(P.m[5]));
            w = texel_shift_frac(&P, &P2, &L, wp, 24, res);
            SK_CHECK_MSG(w <= 1e-3, "move %d (%g,%g,%g texels): fractional texel shift %g", j, steps[j][0],
                         steps[j][1], steps[j][2], w);
            SK_CHECK_MSG(sphere_inside(&P2, &L, s2, 1e-5), "move %d: sphere not inside", j);
        }
    }
    /* a sphere some 60 units from the origin (a float matrix still holds its
       offset of ~5 radii to 5e-7, i.e. 2.4e-4 texel at res 1024) */
    {
        sk_sphere sf = sphere(41.3f, 6.2f, -37.9f, 12.5f);
        dv3 wq[24];
        sk_mat4 Pf;
        int j;
        for (i = 0; i < 24; i++) wq[i] = dadd(tod(sf.c), dv(rnd(-8, 8), rnd(-8, 8), rnd(-8, 8)));
        SK_CHECK(sk_stable_crop(sf, L, res, NULL, &Pf) == SK_OK);
        for (j = 1; j <= 10; j++) {
            sk_sphere s2 = sf;
            s2.c = tof(dadd(tod(sf.c), dadd(dmul(xa, 0.37 * j * texel), dmul(ya, -0.23 * j * texel))));
            SK_CHECK(sk_stable_crop(s2, L, res, NULL, &P2) == SK_OK);
            w = texel_shift_frac(&Pf, &P2, &L, wq, 24, res);
            SK_CHECK_MSG(w <= 1e-3, "far sphere, step %d: fractional texel shift %g", j, w);
            SK_CHECK(sphere_inside(&P2, &L, s2, 1e-5));
        }
    }
    /* odd and small resolutions obey the same rules */
    {
        static const int rs[4] = { 2, 3, 255, 4096 };
        int j;
        for (j = 0; j < 4; j++) {
            double tx = 2.0 * s.r / (rs[j] - 1);
            sk_sphere s2 = s;
            s2.c = tof(dadd(tod(s.c), dmul(xa, 0.3 * tx)));
            SK_CHECK(sk_stable_crop(s, L, rs[j], NULL, &P) == SK_OK);
            SK_CHECK(sk_stable_crop(s2, L, rs[j], NULL, &P2) == SK_OK);
            SK_CHECK_NEAR(2.0 / (P.m[0] * rs[j]), tx, tx * 1e-5);
            SK_CHECK_MSG(sphere_inside(&P, &L, s, 1e-5) && sphere_inside(&P2, &L, s2, 1e-5), "res %d: sphere outside", rs[j]);
            w = texel_shift_frac(&P, &P2, &L, wp, 24, rs[j]);
            SK_CHECK_MSG(w <= 1e-3, "res %d: fractional texel shift %g", rs[j], w);
        }
    }

    /* the whole cascade pipeline: camera translated by sub-texel steps ->
       from_matrix -> slice -> bounding sphere -> stable crop */
    {
        const dv3 eye0 = dv(2, 4, 9), fwd = dv(-0.2, -0.3, -1);
        sk_mat4 Pb;
        sk_sphere sb;
        int j, bad = 0;
        for (j = 0; j < 12; j++) {
            dv3 e = dadd(eye0, dmul(xa, 0.013 * j));
            e = dadd(e, dmul(ya, -0.021 * j));
            e = dadd(e, dmul(za, 0.05 * j));
            {
                sk_mat4 VP = sk_mat4_mul(sk_mat4_perspective(0.9f, 1.5f, 0.5f, 50.0f),
                                         sk_mat4_look_at(tof(e), tof(dadd(e, fwd)), v3(0, 1, 0)));
                sk_frustum vm = sk_frustum_from_matrix(VP), sl;
                sk_sphere sp;
                SK_CHECK(sk_frustum_slice(&vm, 0.5f, 50.0f, 2.0f, 10.0f, &sl) == SK_OK);
                sp = sk_frustum_bounding_sphere(&sl);
                SK_CHECK(sk_stable_crop(sp, L, res, NULL, &P2) == SK_OK);
                SK_CHECK(sphere_inside(&P2, &L, sp, 1e-5));
                if (j == 0) { Pb = P2; sb = sp; continue; }
                if (sp.r != sb.r) {
                    bad++;
                    printf("    pipeline step %d: radius %.9g != %.9g\n", j, sp.r, sb.r);
                    continue;
                }
                w = texel_shift_frac(&Pb, &P2, &L, wp, 24, res);
                if (w > 1e-3) {
                    bad++;
                    printf("    pipeline step %d: fractional texel shift %g\n", j, w);
                }
            }
        }
        SK_CHECK_MSG(bad == 0, "cascade pipeline shimmered in %d of 11 steps", bad);
    }

    /* casters up-light: depth range pulled back to include them */
    {
        dv3 ldir = dnorm(dv(0.3, -1, 0.2)), cc = dsub(tod(s.c), dmul(ldir, 60));
        sk_aabb cas = box3((float)cc.x - 3, (float)cc.y - 3, (float)cc.z - 3, (float)cc.x + 3, (float)cc.y + 3, (float)cc.z + 3);
        double zmin = 1e9;
        SK_CHECK(sk_stable_crop(s, L, res, &cas, &P2) == SK_OK);
        for (i = 0; i < 8; i++) {
            dv3 q = mpoint2(&P2, &L, dv((i & 1) ? cas.max.x : cas.min.x, (i & 2) ? cas.max.y : cas.min.y,
                                        (i & 4) ? cas.max.z : cas.min.z));
            if (q.z < zmin) zmin = q.z;
        }
        SK_CHECK_MSG(zmin >= -1 - 1e-5, "stable crop clips casters: z_ndc %g", zmin);
        SK_CHECK(sphere_inside(&P2, &L, s, 1e-5));
        /* xy unchanged by casters: the same texel grid */
        SK_CHECK(sk_stable_crop(s, L, res, NULL, &P) == SK_OK);
        SK_CHECK(P2.m[0] == P.m[0] && P2.m[12] == P.m[12] && P2.m[5] == P.m[5] && P2.m[13] == P.m[13]);
    }

    /* bad input: INVALID_ARG, out untouched */
    {
        sk_mat4 BL = L;
        sk_aabb bc = box3(1, 1, 1, 0, 2, 2), nc = box3(0, fnan(), 0, 1, 1, 1);
        fill_sentinel(&P, sizeof P);
        SK_CHECK(sk_stable_crop(s, L, 0, NULL, &P) == SK_ERR_INVALID_ARG);
        SK_CHECK(sk_stable_crop(s, L, 1, NULL, &P) == SK_ERR_INVALID_ARG);
        SK_CHECK(sk_stable_crop(s, L, -5, NULL, &P) == SK_ERR_INVALID_ARG);
        SK_CHECK(sk_stable_crop(sphere(0, 0, 0, 0), L, res, NULL, &P) == SK_ERR_INVALID_ARG);
        SK_CHECK(sk_stable_crop(sphere(0, 0, 0, -1), L, res, NULL, &P) == SK_ERR_INVALID_ARG);
        SK_CHECK(sk_stable_crop(sphere(0, 0, 0, fnan()), L, res, NULL, &P) == SK_ERR_INVALID_ARG);
        SK_CHECK(sk_stable_crop(sphere(0, 0, 0, finf()), L, res, NULL, &P) == SK_ERR_INVALID_ARG);
        SK_CHECK(sk_stable_crop(sphere(fnan(), 0, 0, 1), L, res, NULL, &P) == SK_ERR_INVALID_ARG);
        SK_CHECK(sk_stable_crop(sphere(0, -finf(), 0, 1), L, res, NULL, &P) == SK_ERR_INVALID_ARG);
        SK_CHECK(sk_stable_crop(s, L, res, &bc, &P) == SK_ERR_INVALID_ARG);
        SK_CHECK(sk_stable_crop(s, L, res, &nc, &P) == SK_ERR_INVALID_ARG);
        BL.m[2] = fnan();
        SK_CHECK(sk_stable_crop(s, BL, res, NULL, &P) == SK_ERR_INVALID_ARG);
        SK_CHECK(is_sentinel(&P, sizeof P));
        SK_CHECK(sk_stable_crop(s, L, res, NULL, NULL) == SK_ERR_INVALID_ARG);
        /* a huge resolution: valid and finite, or refused; never NaN */
        {
            sk_result r = sk_stable_crop(s, L, 2147483647, NULL, &P);
            SK_CHECK(r == SK_OK || r == SK_ERR_INVALID_ARG);
            if (r == SK_OK) SK_CHECK(all_finite_mat(&P));
        }
    }
}

/* sk_stable_crop_origin: coordinates relative to a world origin (large
   worlds). The texel grid must be the one sk_stable_crop gives for the same
   points in world coordinates, whatever the origin, so moving the origin
   (a camera crossing into another cell) never shifts the grid; and with
   the origin at 1e5 sub-texel moves of the sphere give whole-texel shifts
   only, as at the world origin. */
static double texel_shift_frac_rel(const sk_mat4 *P1, const double o1[3], const sk_mat4 *P2, const double o2[3],
                                   const sk_mat4 *L, const dv3 *world, int n, int res) {
    double worst = 0;
    int i;
    for (i = 0; i < n; i++) {
        double u1, v1, u2, v2, f;
        texel_uv(P1, L, dsub(world[i], dv(o1[0], o1[1], o1[2])), res, &u1, &v1);
        texel_uv(P2, L, dsub(world[i], dv(o2[0], o2[1], o2[2])), res, &u2, &v2);
        f = frac_dist(u2 - u1); if (f > worst) worst = f;
        f = frac_dist(v2 - v1); if (f > worst) worst = f;
    }
    return worst;
}

static void test_stable_crop_origin(void) {
    const int res = 1024;
    sk_mat4 L = sk_light_view_directional(v3(0.3f, -1.0f, 0.2f)), P, P2;
    dv3 xa = dv(L.m[0], L.m[4], L.m[8]), ya = dv(L.m[1], L.m[5], L.m[9]);
    /* origins: multiples of 256 (exact floats) around a world point 1e5 out */
    static const double origins[3][3] = {{60160.0, 47872.0, -64000.0}, {60416.0, 47872.0, -64000.0},
                                         {60160.0, 48128.0, -63744.0}};
    const dv3 centre = dv(60230.37, 47913.11, -63871.55);
    dv3 world[24];
    double texel, w;
    int i, j;
    sk_sphere s0 = sphere(0, 0, 0, 12.5f);
    texel = 2.0 * s0.r / (res - 1);
    for (i = 0; i < 24; i++) world[i] = dadd(centre, dv(rnd(-8, 8), rnd(-8, 8), rnd(-8, 8)));

    /* NULL origin: exactly sk_stable_crop */
    {
        sk_sphere s = sphere(3.2f, 1.1f, -4.7f, 12.5f);
        SK_CHECK(sk_stable_crop(s, L, res, NULL, &P) == SK_OK);
        SK_CHECK(sk_stable_crop_origin(s, L, res, NULL, NULL, &P2) == SK_OK);
        SK_CHECK(memcmp(&P, &P2, sizeof P) == 0);
    }
    /* the same world sphere relative to three origins: one grid */
    {
        sk_mat4 Ps[3];
        for (j = 0; j < 3; j++) {
            sk_sphere s = s0;
            s.c = tof(dsub(centre, dv(origins[j][0], origins[j][1], origins[j][2])));
            SK_CHECK(sk_stable_crop_origin(s, L, res, NULL, origins[j], &Ps[j]) == SK_OK);
            SK_CHECK(all_finite_mat(&Ps[j]));
            SK_CHECK(sphere_inside(&Ps[j], &L, s, 1e-5));
        }
        for (j = 1; j < 3; j++) {
            w = texel_shift_frac_rel(&Ps[0], origins[0], &Ps[j], origins[j], &L, world, 24, res);
            SK_CHECK_MSG(w <= 1e-3, "origin %d: fractional texel shift %g against origin 0", j, w);
        }
    }
    /* sub-texel moves of the sphere at 1e5, origin fixed: whole-texel shifts */
    {
        sk_sphere s = s0;
        s.c = tof(dsub(centre, dv(origins[0][0], origins[0][1], origins[0][2])));
        SK_CHECK(sk_stable_crop_origin(s, L, res, NULL, origins[0], &P) == SK_OK);
        for (j = 1; j <= 10; j++) {
            sk_sphere s2 = s;
            s2.c = tof(dadd(tod(s.c), dadd(dmul(xa, 0.37 * j * texel), dmul(ya, -0.23 * j * texel))));
            SK_CHECK(sk_stable_crop_origin(s2, L, res, NULL, origins[0], &P2) == SK_OK);
            w = texel_shift_frac_rel(&P, origins[0], &P2, origins[0], &L, world, 24, res);
            SK_CHECK_MSG(w <= 1e-3, "step %d at 1e5: fractional texel shift %g", j, w);
            SK_CHECK(sphere_inside(&P2, &L, s2, 1e-5));
        }
    }
    /* near the world origin, where world floats are still exact enough: the
       grid of sk_stable_crop on world coordinates */
    {
        static const double o[3] = {512.0, 0.0, -256.0};
        sk_sphere sw = sphere(530.25f, 3.5f, -241.75f, 12.5f), sr = sw;
        dv3 near_pts[24];
        for (i = 0; i < 24; i++) near_pts[i] = dadd(tod(sw.c), dv(rnd(-8, 8), rnd(-8, 8), rnd(-8, 8)));
        sr.c = tof(dsub(tod(sw.c), dv(o[0], o[1], o[2])));
        SK_CHECK(sk_stable_crop(sw, L, res, NULL, &P) == SK_OK);
        SK_CHECK(sk_stable_crop_origin(sr, L, res, NULL, o, &P2) == SK_OK);
        {
            static const double zero[3] = {0, 0, 0};
            w = texel_shift_frac_rel(&P, zero, &P2, o, &L, near_pts, 24, res);
        }
        SK_CHECK_MSG(w <= 2e-3, "world-anchored grid: fractional texel shift %g against sk_stable_crop", w);
    }
    /* bad origin */
    {
        const double bad[3] = {0.0, fnan(), 0.0}, inf3[3] = {finf(), 0.0, 0.0};
        fill_sentinel(&P, sizeof P);
        SK_CHECK(sk_stable_crop_origin(s0, L, res, NULL, bad, &P) == SK_ERR_INVALID_ARG);
        SK_CHECK(sk_stable_crop_origin(s0, L, res, NULL, inf3, &P) == SK_ERR_INVALID_ARG);
        SK_CHECK(sk_stable_crop_origin(s0, L, 1, NULL, origins[0], &P) == SK_ERR_INVALID_ARG);
        SK_CHECK(is_sentinel(&P, sizeof P));
    }
}

SK_TEST_MAIN(test_aliasing_error, test_rmsm_lod, test_crop_matrix, test_pssm_splits, test_frustum_slice,
             test_frustum_bounding_sphere, test_light_view_directional, test_fit_ortho, test_stable_crop,
             test_stable_crop_origin)
