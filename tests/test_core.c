/* tests/test_core.c - section 1 of shadowkit.h (core math): result strings,
   mat4 identity / mul / inverse / perspective / ortho / look_at / transforms,
   frusta from a matrix, from corners, from an AABB, point containment, and
   frustum-AABB clipping.

   Expected values come from the textbook definitions (gluPerspective,
   glOrtho, gluLookAt, column-major products) evaluated here in double, or
   from hand-computed numbers; never from the library's output. Tolerances
   are stated next to each check: float arithmetic rounds each operation to
   2^-24 ~ 6e-8 relative, so a handful of operations stays below 1e-6
   relative unless a conditioning argument says otherwise. */
#define SHADOWKIT_IMPLEMENTATION
#include "shadowkit.h"
#include "tests/sk_test.h"
#include "tests/sk_ref.h"
#include <stdlib.h>

/* ------------------------------------------------------------ helpers */
static inline sk_vec4 v4(float x, float y, float z, float w) {
    sk_vec4 r; r.x = x; r.y = y; r.z = z; r.w = w; return r;
}

static inline int is_identity(const sk_mat4 *m) {
    int k;
    for (k = 0; k < 16; k++) if (m->m[k] != ((k % 5 == 0) ? 1.0f : 0.0f)) return 0;
    return 1;
}

/* textbook matrices, in double */
static inline void e_perspective(double fovy, double aspect, double zn, double zf, double e[16]) {
    double f = 1.0 / tan(fovy / 2.0);
    memset(e, 0, 16 * sizeof e[0]);
    e[0] = f / aspect; e[5] = f;
    e[10] = (zf + zn) / (zn - zf); e[11] = -1.0;
    e[14] = 2.0 * zf * zn / (zn - zf);
}
static inline void e_ortho(double l, double r, double b, double t, double n, double f, double e[16]) {
    memset(e, 0, 16 * sizeof e[0]);
    e[0] = 2.0 / (r - l); e[5] = 2.0 / (t - b); e[10] = -2.0 / (f - n);
    e[12] = -(r + l) / (r - l); e[13] = -(t + b) / (t - b); e[14] = -(f + n) / (f - n);
    e[15] = 1.0;
}
static inline void e_look_at(dv3 eye, dv3 target, dv3 up, double e[16]) {
    dv3 f = dnorm(dsub(target, eye));
    dv3 s = dnorm(dcross(f, up));
    dv3 u = dcross(s, f);
    memset(e, 0, 16 * sizeof e[0]);
    e[0] = s.x; e[4] = s.y; e[8] = s.z;
    e[1] = u.x; e[5] = u.y; e[9] = u.z;
    e[2] = -f.x; e[6] = -f.y; e[10] = -f.z;
    e[12] = -ddot(s, eye); e[13] = -ddot(u, eye); e[14] = ddot(f, eye);
    e[15] = 1.0;
}
/* a gluLookAt + gluPerspective camera, evaluated in double */
typedef struct cam_t { dv3 eye, s, u, f; double ty, aspect, zn, zf; } cam_t;
static inline cam_t make_cam(dv3 eye, dv3 target, dv3 up, float fovy, float aspect, float zn, float zf) {
    cam_t c;
    c.eye = eye;
    c.f = dnorm(dsub(target, eye));
    c.s = dnorm(dcross(c.f, up));
    c.u = dcross(c.s, c.f);
    c.ty = tan((double)fovy / 2.0);
    c.aspect = aspect; c.zn = zn; c.zf = zf;
    return c;
}
/* corner i (sk_frustum order) of the part of the view between eye depths d0, d1 */
static inline dv3 cam_corner(const cam_t *c, int i, double d0, double d1) {
    double d = (i & 4) ? d1 : d0;
    double sx = (i & 1) ? 1.0 : -1.0, sy = (i & 2) ? 1.0 : -1.0;
    return dadd(dadd(dadd(c->eye, dmul(c->s, sx * d * c->ty * c->aspect)),
                     dmul(c->u, sy * d * c->ty)), dmul(c->f, d));
}
static inline sk_mat4 cam_view_proj(const cam_t *c, dv3 target, dv3 up) {
    return sk_mat4_mul(sk_mat4_perspective((float)(2.0 * atan(c->ty)), (float)c->aspect,
                                           (float)c->zn, (float)c->zf),
                       sk_mat4_look_at(tof(c->eye), tof(target), tof(up)));
}
/* the four corners lying on plane k (left, right, bottom, top, near, far) */
static inline int face_has_corner(int k, int i) {
    switch (k) {
    case 0: return (i & 1) == 0;
    case 1: return (i & 1) != 0;
    case 2: return (i & 2) == 0;
    case 3: return (i & 2) != 0;
    case 4: return (i & 4) == 0;
    default: return (i & 4) != 0;
    }
}
static inline dv3 centroid(const sk_frustum *f) {
    dv3 c = dv(0, 0, 0);
    int i;
    for (i = 0; i < 8; i++) c = dadd(c, tod(f->corners[i]));
    return dmul(c, 1.0 / 8.0);
}
/* planes normalised, each containing its 4 corners within tol(corner), centroid
   strictly inside every plane. Returns the number of violated conditions. */
static int frustum_plane_violations(const sk_frustum *f, double tol_abs, double tol_rel, int verbose) {
    int k, i, bad = 0;
    dv3 c = centroid(f);
    for (k = 0; k < 6; k++) {
        const sk_plane *pl = &f->planes[k];
        double nl = dlen(tod(pl->n));
        if (!(fabs(nl - 1.0) <= 1e-5)) {
            bad++;
            if (verbose) printf("    plane %d: |n| = %.9g\n", k, nl);
        }
        for (i = 0; i < 8; i++) {
            if (!face_has_corner(k, i)) continue;
            {
                double dd = pdist(pl, tod(f->corners[i]));
                double tol = tol_abs + tol_rel * dlen(tod(f->corners[i]));
                if (!(fabs(dd) <= tol)) {
                    bad++;
                    if (verbose) printf("    plane %d: corner %d at distance %.9g (tol %g)\n", k, i, dd, tol);
                }
            }
        }
        if (!(pdist(pl, c) > 0.0)) {
            bad++;
            if (verbose) printf("    plane %d: centroid at distance %.9g (not inside)\n", k, pdist(pl, c));
        }
    }
    return bad;
}
static inline int frustum_all_zero(const sk_frustum *f) {
    const float *p = (const float *)(const void *)f;
    size_t i, n = sizeof *f / sizeof(float);
    for (i = 0; i < n; i++) if (p[i] != 0.0f) return 0;
    return 1;
}
static unsigned long long rng_state = 0x9E3779B97F4A7C15ull;
static inline double rnd(double a, double b) {  /* deterministic LCG, uniform in [a,b) */
    rng_state = rng_state * 6364136223846793005ull + 1442695040888963407ull;
    return a + (b - a) * (double)(rng_state >> 11) * (1.0 / 9007199254740992.0);
}

/* ------------------------------------------------------------ result strings */
static void test_result_string(void) {
    SK_CHECK(strcmp(sk_result_string(SK_OK), "ok") == 0);
    SK_CHECK(strcmp(sk_result_string(SK_ERR_INVALID_ARG), "invalid argument") == 0);
    SK_CHECK(strcmp(sk_result_string(SK_ERR_DEGENERATE), "degenerate configuration") == 0);
    SK_CHECK(strcmp(sk_result_string(SK_ERR_CAPACITY), "capacity exceeded") == 0);
    SK_CHECK(strcmp(sk_result_string(SK_ERR_GL), "GL error") == 0);
#ifndef __cplusplus
    /* out-of-range enum values are only well defined in C */
    SK_CHECK(strcmp(sk_result_string((sk_result)99), "unknown result") == 0);
    SK_CHECK(strcmp(sk_result_string((sk_result)-1), "unknown result") == 0);
    SK_CHECK(strcmp(sk_result_string((sk_result)5), "unknown result") == 0);
#endif
}

/* ------------------------------------------------------------ identity, mul */
static void test_mat4_identity_mul(void) {
    sk_mat4 I = sk_mat4_identity(), A, B, T, S, P;
    double E[16];
    int k, r, c;
    sk_vec3 p;
    SK_CHECK(is_identity(&I));

    /* entries are small dyadic rationals (quarters times halves, |sum| < 200),
       so every product and sum is exact in float: tolerance 0 */
    for (k = 0; k < 16; k++) {
        A.m[k] = (float)((k * 7) % 11 - 5) + 0.25f * (float)(k % 4);
        B.m[k] = (float)((k * 5) % 13 - 6) - 0.5f * (float)(k % 3);
    }
    for (c = 0; c < 4; c++)
        for (r = 0; r < 4; r++) {
            double s = 0;
            for (k = 0; k < 4; k++) s += (double)A.m[k * 4 + r] * (double)B.m[c * 4 + k];
            E[c * 4 + r] = s;
        }
    CHECK_MAT_NEAR(sk_mat4_mul(A, B), E, 0.0, 0.0);
    for (k = 0; k < 16; k++) E[k] = A.m[k];
    CHECK_MAT_NEAR(sk_mat4_mul(I, A), E, 0.0, 0.0);
    CHECK_MAT_NEAR(sk_mat4_mul(A, I), E, 0.0, 0.0);

    /* column-major, column vectors: translation in m[12..14]; T*S scales first */
    T = I; T.m[12] = 1; T.m[13] = 2; T.m[14] = 3;
    S = I; S.m[0] = 2; S.m[5] = 3; S.m[10] = 4;
    P = sk_mat4_mul(T, S);
    p = sk_mat4_transform_point(P, v3(1, 1, 1));
    SK_CHECK(p.x == 3.0f && p.y == 5.0f && p.z == 7.0f);
    P = sk_mat4_mul(S, T);
    p = sk_mat4_transform_point(P, v3(1, 1, 1));
    SK_CHECK(p.x == 4.0f && p.y == 9.0f && p.z == 16.0f);
}

/* ------------------------------------------------------------ inverse */
static void test_mat4_inverse(void) {
    sk_mat4 I = sk_mat4_identity(), M, inv, G, Z, bad;
    double E[16];
    int k, r, c, q;

    /* M = T(1,2,3) * S(2,4,8): inverse = S(1/2,1/4,1/8) * T(-1,-2,-3), by hand */
    M = I; M.m[0] = 2; M.m[5] = 4; M.m[10] = 8; M.m[12] = 1; M.m[13] = 2; M.m[14] = 3;
    fill_sentinel(&inv, sizeof inv);
    SK_CHECK(sk_mat4_inverse(M, &inv) == 1);
    memset(E, 0, sizeof E);
    E[0] = 0.5; E[5] = 0.25; E[10] = 0.125; E[15] = 1;
    E[12] = -0.5; E[13] = -0.5; E[14] = -0.375;
    CHECK_MAT_NEAR(inv, E, 0.0, 1e-6);

    /* a general matrix with a non-trivial bottom row (rows listed) */
    {
        static const double rows[4][4] = { { 2, 1, 0, 1 }, { 0, 3, 1, 0 }, { 1, 0, 4, 2 }, { 0.5, 1, 0, 3 } };
        double worst1 = 0, worst2 = 0;
        for (r = 0; r < 4; r++) for (c = 0; c < 4; c++) G.m[c * 4 + r] = (float)rows[r][c];
        SK_CHECK(sk_mat4_inverse(G, &inv) == 1);
        /* G*inv and inv*G in double; G has condition number ~10, so float
           entries of the inverse give residuals of order 1e-6 */
        for (r = 0; r < 4; r++)
            for (c = 0; c < 4; c++) {
                double s1 = 0, s2 = 0;
                for (q = 0; q < 4; q++) {
                    s1 += (double)G.m[q * 4 + r] * (double)inv.m[c * 4 + q];
                    s2 += (double)inv.m[q * 4 + r] * (double)G.m[c * 4 + q];
                }
                s1 -= (r == c); s2 -= (r == c);
                if (fabs(s1) > worst1) worst1 = fabs(s1);
                if (fabs(s2) > worst2) worst2 = fabs(s2);
            }
        SK_CHECK_MSG(worst1 <= 1e-5, "G*inv(G) - I = %g", worst1);
        SK_CHECK_MSG(worst2 <= 1e-5, "inv(G)*G - I = %g", worst2);
    }
    /* a camera view-projection */
    {
        sk_mat4 VP = sk_mat4_mul(sk_mat4_perspective(1.0f, 1.5f, 0.5f, 40.0f),
                                 sk_mat4_look_at(v3(1, 2, 3), v3(4, 1, -5), v3(0, 1, 0)));
        double worst = 0;
        SK_CHECK(sk_mat4_inverse(VP, &inv) == 1);
        for (r = 0; r < 4; r++)
            for (c = 0; c < 4; c++) {
                double s = 0;
                for (q = 0; q < 4; q++) s += (double)inv.m[q * 4 + r] * (double)VP.m[c * 4 + q];
                s -= (r == c);
                if (fabs(s) > worst) worst = fabs(s);
            }
        SK_CHECK_MSG(worst <= 1e-5, "inv(VP)*VP - I = %g", worst);
    }

    /* singular: zero matrix, two equal columns; out untouched */
    memset(&Z, 0, sizeof Z);
    fill_sentinel(&inv, sizeof inv);
    SK_CHECK(sk_mat4_inverse(Z, &inv) == 0);
    SK_CHECK(is_sentinel(&inv, sizeof inv));
    bad = G;
    for (r = 0; r < 4; r++) bad.m[4 + r] = bad.m[r];
    SK_CHECK(sk_mat4_inverse(bad, &inv) == 0);
    SK_CHECK(is_sentinel(&inv, sizeof inv));
    /* a rank-3 projection (last row = 0) */
    bad = I; bad.m[15] = 0;
    SK_CHECK(sk_mat4_inverse(bad, &inv) == 0);
    SK_CHECK(is_sentinel(&inv, sizeof inv));
    /* non-finite entries */
    for (k = 0; k < 16; k += 5) {
        bad = G; bad.m[k] = fnan();
        SK_CHECK(sk_mat4_inverse(bad, &inv) == 0);
        bad = G; bad.m[k] = finf();
        SK_CHECK(sk_mat4_inverse(bad, &inv) == 0);
        bad = G; bad.m[k] = -finf();
        SK_CHECK(sk_mat4_inverse(bad, &inv) == 0);
    }
    bad = G; bad.m[7] = fnan();
    SK_CHECK(sk_mat4_inverse(bad, &inv) == 0);
    SK_CHECK(is_sentinel(&inv, sizeof inv));
    SK_CHECK(sk_mat4_inverse(G, NULL) == 0);
}

/* ------------------------------------------------------------ perspective */
static void test_mat4_perspective(void) {
    const float fovy = 1.0f, aspect = 1.6f, zn = 0.25f, zf = 80.0f;
    sk_mat4 P = sk_mat4_perspective(fovy, aspect, zn, zf);
    double E[16], o[4], in[4];
    double ty = tan((double)fovy / 2.0);
    int i;
    e_perspective(fovy, aspect, zn, zf, E);
    /* a few float roundings plus tanf: 1e-6 relative; zeros must be exact */
    CHECK_MAT_NEAR(P, E, 1e-6, 0.0);

    /* near plane -> z_ndc = -1, far -> +1, w = eye depth */
    in[0] = 0; in[1] = 0; in[2] = -zn; in[3] = 1;
    mxv(&P, in, o);
    SK_CHECK_NEAR(o[2] / o[3], -1.0, 1e-6);
    SK_CHECK_NEAR(o[3], zn, 1e-7);
    in[2] = -zf;
    mxv(&P, in, o);
    SK_CHECK_NEAR(o[2] / o[3], 1.0, 1e-5);
    SK_CHECK_NEAR(o[3], zf, 1e-5);
    /* the corner of the near rectangle -> (1,1,-1); far rectangle corner -> (-1,1,1) */
    {
        dv3 q = mpoint(&P, dv(zn * ty * aspect, zn * ty, -zn));
        SK_CHECK_NEAR(q.x, 1.0, 1e-6); SK_CHECK_NEAR(q.y, 1.0, 1e-6); SK_CHECK_NEAR(q.z, -1.0, 1e-6);
        q = mpoint(&P, dv(-zf * ty * aspect, zf * ty, -zf));
        SK_CHECK_NEAR(q.x, -1.0, 1e-6); SK_CHECK_NEAR(q.y, 1.0, 1e-6); SK_CHECK_NEAR(q.z, 1.0, 1e-5);
        /* depth is monotone: a mid point lies strictly between */
        q = mpoint(&P, dv(0, 0, -10.0));
        SK_CHECK(q.z > -1.0 && q.z < 1.0);
    }
    /* the library's own transform_point agrees */
    {
        sk_vec3 q = sk_mat4_transform_point(P, v3(0, 0, -zn));
        SK_CHECK_NEAR(q.z, -1.0, 1e-6);
        q = sk_mat4_transform_point(P, v3(0, 0, -zf));
        SK_CHECK_NEAR(q.z, 1.0, 1e-5);
    }

    /* fallbacks: the identity */
    {
        const float pi_f = 3.14159274f; /* (float)M_PI rounds above pi */
        sk_mat4 F[24];
        int n = 0;
        F[n++] = sk_mat4_perspective(0.0f, aspect, zn, zf);
        F[n++] = sk_mat4_perspective(-1.0f, aspect, zn, zf);
        F[n++] = sk_mat4_perspective(pi_f, aspect, zn, zf);
        F[n++] = sk_mat4_perspective(4.0f, aspect, zn, zf);
        F[n++] = sk_mat4_perspective(fnan(), aspect, zn, zf);
        F[n++] = sk_mat4_perspective(finf(), aspect, zn, zf);
        F[n++] = sk_mat4_perspective(fovy, 0.0f, zn, zf);
        F[n++] = sk_mat4_perspective(fovy, -1.0f, zn, zf);
        F[n++] = sk_mat4_perspective(fovy, fnan(), zn, zf);
        F[n++] = sk_mat4_perspective(fovy, finf(), zn, zf);
        F[n++] = sk_mat4_perspective(fovy, aspect, 0.0f, zf);
        F[n++] = sk_mat4_perspective(fovy, aspect, -1.0f, zf);
        F[n++] = sk_mat4_perspective(fovy, aspect, fnan(), zf);
        F[n++] = sk_mat4_perspective(fovy, aspect, -finf(), zf);
        F[n++] = sk_mat4_perspective(fovy, aspect, zn, zn);
        F[n++] = sk_mat4_perspective(fovy, aspect, zn, 0.1f);
        F[n++] = sk_mat4_perspective(fovy, aspect, zn, fnan());
        F[n++] = sk_mat4_perspective(fovy, aspect, zn, finf());
        F[n++] = sk_mat4_perspective(fovy, aspect, zn, -finf());
        for (i = 0; i < n; i++) SK_CHECK_MSG(is_identity(&F[i]), "perspective fallback case %d", i);
    }
    /* extreme but valid: finite, and not the fallback */
    {
        sk_mat4 X[6];
        int n = 0;
        X[n++] = sk_mat4_perspective(1e-6f, 1.0f, 0.1f, 10.0f);
        X[n++] = sk_mat4_perspective(3.1415f, 1.0f, 0.1f, 10.0f);
        X[n++] = sk_mat4_perspective(1.0f, 1e-6f, 0.1f, 10.0f);
        X[n++] = sk_mat4_perspective(1.0f, 1e6f, 0.1f, 10.0f);
        X[n++] = sk_mat4_perspective(1.0f, 1.0f, 1e-6f, 1e6f);
        X[n++] = sk_mat4_perspective(1.0f, 1.0f, 1.0f, 1.0000001f);
        for (i = 0; i < n; i++) {
            SK_CHECK_MSG(all_finite_mat(&X[i]), "extreme perspective %d not finite", i);
            SK_CHECK_MSG(X[i].m[11] == -1.0f && X[i].m[15] == 0.0f, "extreme perspective %d fell back", i);
        }
        /* zn = 1e-6, zf = 1e6 still maps near to -1 and far to +1 */
        e_perspective(1.0, 1.0, 1e-6, 1e6, E);
        CHECK_MAT_NEAR(X[4], E, 1e-6, 0.0);
    }
}

/* ------------------------------------------------------------ ortho */
static void test_mat4_ortho(void) {
    double E[16];
    sk_mat4 O = sk_mat4_ortho(-2.0f, 6.0f, -1.0f, 3.0f, 0.5f, 20.0f);
    dv3 q;
    int i;
    e_ortho(-2, 6, -1, 3, 0.5, 20, E);
    CHECK_MAT_NEAR(O, E, 1e-6, 0.0);
    q = mpoint(&O, dv(-2, -1, -0.5));
    SK_CHECK_NEAR(q.x, -1, 1e-6); SK_CHECK_NEAR(q.y, -1, 1e-6); SK_CHECK_NEAR(q.z, -1, 1e-6);
    q = mpoint(&O, dv(6, 3, -20));
    SK_CHECK_NEAR(q.x, 1, 1e-6); SK_CHECK_NEAR(q.y, 1, 1e-6); SK_CHECK_NEAR(q.z, 1, 1e-6);
    q = mpoint(&O, dv(2, 1, -10.25));
    SK_CHECK_NEAR(q.x, 0, 1e-6); SK_CHECK_NEAR(q.y, 0, 1e-6); SK_CHECK_NEAR(q.z, 0, 1e-6);

    /* glOrtho allows mirrored ranges and a negative near plane */
    O = sk_mat4_ortho(3.0f, -1.0f, 2.0f, -2.0f, -5.0f, -10.0f);
    e_ortho(3, -1, 2, -2, -5, -10, E);
    CHECK_MAT_NEAR(O, E, 1e-6, 0.0);
    O = sk_mat4_ortho(-1.0f, 1.0f, -1.0f, 1.0f, -10.0f, 10.0f);
    e_ortho(-1, 1, -1, 1, -10, 10, E);
    CHECK_MAT_NEAR(O, E, 1e-6, 0.0);

    /* fallbacks: identity */
    {
        sk_mat4 F[16];
        int n = 0;
        F[n++] = sk_mat4_ortho(1, 1, -1, 1, 0, 1);
        F[n++] = sk_mat4_ortho(-1, 1, 2, 2, 0, 1);
        F[n++] = sk_mat4_ortho(-1, 1, -1, 1, 3, 3);
        F[n++] = sk_mat4_ortho(fnan(), 1, -1, 1, 0, 1);
        F[n++] = sk_mat4_ortho(-1, fnan(), -1, 1, 0, 1);
        F[n++] = sk_mat4_ortho(-1, 1, fnan(), 1, 0, 1);
        F[n++] = sk_mat4_ortho(-1, 1, -1, fnan(), 0, 1);
        F[n++] = sk_mat4_ortho(-1, 1, -1, 1, fnan(), 1);
        F[n++] = sk_mat4_ortho(-1, 1, -1, 1, 0, fnan());
        F[n++] = sk_mat4_ortho(-finf(), 1, -1, 1, 0, 1);
        F[n++] = sk_mat4_ortho(-1, finf(), -1, 1, 0, 1);
        F[n++] = sk_mat4_ortho(-1, 1, -1, 1, 0, finf());
        for (i = 0; i < n; i++) SK_CHECK_MSG(is_identity(&F[i]), "ortho fallback case %d", i);
    }
    /* extreme but valid */
    O = sk_mat4_ortho(-1e-4f, 1e-4f, -1e5f, 1e5f, 1e-6f, 1e6f);
    SK_CHECK(all_finite_mat(&O));
    e_ortho(-1e-4f, 1e-4f, -1e5f, 1e5f, 1e-6f, 1e6f, E);
    CHECK_MAT_NEAR(O, E, 1e-6, 1e-12);
}

/* ------------------------------------------------------------ look_at */
static void test_mat4_look_at(void) {
    double E[16];
    sk_mat4 V;
    dv3 eye = dv(1, 2, 3), target = dv(4, 1, -5), up = dv(0, 1, 0), q;
    int i;

    V = sk_mat4_look_at(tof(eye), tof(target), tof(up));
    e_look_at(eye, target, up, E);
    /* normalisation and cross products in float: ~1e-7 relative per entry;
       translation entries are dot products with |eye| ~ 3.7 */
    CHECK_MAT_NEAR(V, E, 1e-6, 2e-6);
    SK_CHECK_MSG(rigid_error(&V) <= 1e-6, "look_at not rigid: %g", rigid_error(&V));
    q = mpoint(&V, eye);
    SK_CHECK_MSG(dlen(q) <= 1e-5, "eye -> (%g,%g,%g)", q.x, q.y, q.z);
    q = mpoint(&V, target);
    SK_CHECK_NEAR(q.x, 0, 1e-5); SK_CHECK_NEAR(q.y, 0, 1e-5);
    SK_CHECK_NEAR(q.z, -dlen(dsub(target, eye)), 1e-5);
    {   /* the up vector ends up in the upper half of the view's yz plane */
        sk_vec4 w = sk_mat4_transform_vec4(V, v4(0, 1, 0, 0));
        SK_CHECK_NEAR(w.x, 0, 1e-6);
        SK_CHECK(w.y > 0);
    }

    /* up parallel / anti-parallel to the view direction: replaced by the world
       axis least aligned with f = (1,5,0.5)/|.|, i.e. the z axis. Either sign
       of that axis is a valid reading, so check u = +-(z perpendicular to f). */
    {
        dv3 e2 = dv(1, 1, 1), dir = dv(1, 5, 0.5), t2 = dadd(e2, dmul(dir, 2));
        dv3 f = dnorm(dir), zp = dnorm(dsub(dv(0, 0, 1), dmul(f, f.z)));
        dv3 ups[3];
        ups[0] = dmul(dir, 2); ups[1] = dmul(dir, -1); ups[2] = dv(0, 0, 0);
        for (i = 0; i < 3; i++) {
            V = sk_mat4_look_at(tof(e2), tof(t2), tof(ups[i]));
            SK_CHECK_MSG(all_finite_mat(&V), "look_at up case %d not finite", i);
            SK_CHECK_MSG(rigid_error(&V) <= 1e-5, "look_at up case %d not rigid: %g", i, rigid_error(&V));
            q = mpoint(&V, e2);
            SK_CHECK_MSG(dlen(q) <= 1e-5, "up case %d: eye -> (%g,%g,%g)", i, q.x, q.y, q.z);
            q = mpoint(&V, t2);
            SK_CHECK_MSG(fabs(q.x) <= 1e-5 && fabs(q.y) <= 1e-5 && fabs(q.z + dlen(dsub(t2, e2))) <= 1e-5,
                         "up case %d: target -> (%g,%g,%g)", i, q.x, q.y, q.z);
            if (i < 2) {
                double al = ddot(dv(V.m[1], V.m[5], V.m[9]), zp);
                SK_CHECK_MSG(fabs(fabs(al) - 1) <= 1e-5, "up case %d: u . z_perp = %g", i, al);
            }
        }
        /* nearly parallel (float noise only): still a rigid, finite view */
        V = sk_mat4_look_at(tof(e2), tof(t2), v3(2.0f, 10.0f, 1.0000001f));
        SK_CHECK(all_finite_mat(&V));
        SK_CHECK_MSG(rigid_error(&V) <= 1e-4, "nearly parallel up: not rigid (%g)", rigid_error(&V));
        q = mpoint(&V, t2);
        SK_CHECK_MSG(fabs(q.x) <= 1e-4 && fabs(q.y) <= 1e-4, "nearly parallel up: target -> (%g,%g,%g)", q.x, q.y, q.z);
    }

    /* fallbacks: identity */
    {
        sk_mat4 F[10];
        int n = 0;
        F[n++] = sk_mat4_look_at(v3(1, 2, 3), v3(1, 2, 3), v3(0, 1, 0));
        F[n++] = sk_mat4_look_at(v3(fnan(), 2, 3), v3(0, 0, 0), v3(0, 1, 0));
        F[n++] = sk_mat4_look_at(v3(1, 2, 3), v3(0, fnan(), 0), v3(0, 1, 0));
        F[n++] = sk_mat4_look_at(v3(1, 2, 3), v3(0, 0, 0), v3(0, 1, fnan()));
        F[n++] = sk_mat4_look_at(v3(finf(), 2, 3), v3(0, 0, 0), v3(0, 1, 0));
        F[n++] = sk_mat4_look_at(v3(1, 2, 3), v3(0, 0, -finf()), v3(0, 1, 0));
        F[n++] = sk_mat4_look_at(v3(1, 2, 3), v3(0, 0, 0), v3(finf(), 1, 0));
        for (i = 0; i < n; i++) SK_CHECK_MSG(is_identity(&F[i]), "look_at fallback case %d", i);
    }
    /* extreme but valid: tiny and huge distances stay finite and rigid */
    V = sk_mat4_look_at(v3(0, 0, 0), v3(1e-6f, 0, 0), v3(0, 1, 0));
    SK_CHECK(all_finite_mat(&V) && rigid_error(&V) <= 1e-5);
    V = sk_mat4_look_at(v3(1e6f, 0, 0), v3(-1e6f, 1, 0), v3(0, 1, 0));
    SK_CHECK(all_finite_mat(&V) && rigid_error(&V) <= 1e-5);
}

/* ------------------------------------------------------------ transforms */
static void test_mat4_transform(void) {
    sk_mat4 M = sk_mat4_identity(), A;
    sk_vec3 p;
    sk_vec4 w;
    int k;
    /* x += 4, w = 2: (2,4,6) -> (6,4,6,2) -> (3,2,3) */
    M.m[12] = 4; M.m[15] = 2;
    p = sk_mat4_transform_point(M, v3(2, 4, 6));
    SK_CHECK(p.x == 3.0f && p.y == 2.0f && p.z == 3.0f);
    /* negative w divides as well (points behind a camera) */
    M.m[15] = -2;
    p = sk_mat4_transform_point(M, v3(2, 4, 6));
    SK_CHECK(p.x == -3.0f && p.y == -2.0f && p.z == -3.0f);
    /* w == 0: no divide */
    M.m[15] = 0;
    p = sk_mat4_transform_point(M, v3(2, 4, 6));
    SK_CHECK(p.x == 6.0f && p.y == 4.0f && p.z == 6.0f);
    SK_CHECK_FINITE(p.x);

    /* transform_vec4: plain product, no divide (exact small integers) */
    for (k = 0; k < 16; k++) A.m[k] = (float)(k + 1);
    w = sk_mat4_transform_vec4(A, v4(1, 2, 3, 4));
    /* row r: sum_c (c*4 + r + 1) * (c+1) = 4*(1*0+2*1+3*2+4*3) + (r+1)*(1+2+3+4) = 80 + 10(r+1) */
    SK_CHECK(w.x == 90.0f && w.y == 100.0f && w.z == 110.0f && w.w == 120.0f);
    w = sk_mat4_transform_vec4(A, v4(0, 0, 0, 0));
    SK_CHECK(w.x == 0 && w.y == 0 && w.z == 0 && w.w == 0);
    /* a direction (w = 0) ignores translation */
    M = sk_mat4_identity(); M.m[12] = 5; M.m[13] = 6; M.m[14] = 7;
    w = sk_mat4_transform_vec4(M, v4(1, 2, 3, 0));
    SK_CHECK(w.x == 1.0f && w.y == 2.0f && w.z == 3.0f && w.w == 0.0f);
    p = sk_mat4_transform_point(M, v3(1, 2, 3));
    SK_CHECK(p.x == 6.0f && p.y == 8.0f && p.z == 10.0f);
}

/* ------------------------------------------------------------ frustum from matrix */
static void test_frustum_from_matrix(void) {
    sk_frustum f;
    int i, k, bad;

    /* identity: the NDC cube, planes x >= -1 etc. (exactly known) */
    f = sk_frustum_from_matrix(sk_mat4_identity());
    for (i = 0; i < 8; i++) {
        SK_CHECK_NEAR(f.corners[i].x, (i & 1) ? 1 : -1, 1e-6);
        SK_CHECK_NEAR(f.corners[i].y, (i & 2) ? 1 : -1, 1e-6);
        SK_CHECK_NEAR(f.corners[i].z, (i & 4) ? 1 : -1, 1e-6);
    }
    {
        static const float en[6][3] = { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { 0, 0, -1 } };
        for (k = 0; k < 6; k++) {
            SK_CHECK_MSG(fabs(f.planes[k].n.x - en[k][0]) <= 1e-6 && fabs(f.planes[k].n.y - en[k][1]) <= 1e-6 &&
                         fabs(f.planes[k].n.z - en[k][2]) <= 1e-6 && fabs(f.planes[k].d - 1.0) <= 1e-6,
                         "identity plane %d = (%g,%g,%g,%g)", k, f.planes[k].n.x, f.planes[k].n.y,
                         f.planes[k].n.z, f.planes[k].d);
        }
    }

    /* ortho camera: eye (0,0,5) looking down -z, x in [-2,4], y in [-1,3],
       eye depths 1..11 -> world z from 4 (near) to -6 (far) */
    {
        sk_mat4 VP = sk_mat4_mul(sk_mat4_ortho(-2, 4, -1, 3, 1, 11),
                                 sk_mat4_look_at(v3(0, 0, 5), v3(0, 0, 0), v3(0, 1, 0)));
        static const float en[6][4] = { { 1, 0, 0, 2 }, { -1, 0, 0, 4 }, { 0, 1, 0, 1 },
                                        { 0, -1, 0, 3 }, { 0, 0, -1, 4 }, { 0, 0, 1, 6 } };
        f = sk_frustum_from_matrix(VP);
        for (i = 0; i < 8; i++) {
            SK_CHECK_MSG(fabs(f.corners[i].x - ((i & 1) ? 4 : -2)) <= 1e-5 &&
                         fabs(f.corners[i].y - ((i & 2) ? 3 : -1)) <= 1e-5 &&
                         fabs(f.corners[i].z - ((i & 4) ? -6 : 4)) <= 1e-5,
                         "ortho corner %d = (%g,%g,%g)", i, f.corners[i].x, f.corners[i].y, f.corners[i].z);
        }
        for (k = 0; k < 6; k++)
            SK_CHECK_MSG(fabs(f.planes[k].n.x - en[k][0]) <= 1e-6 && fabs(f.planes[k].n.y - en[k][1]) <= 1e-6 &&
                         fabs(f.planes[k].n.z - en[k][2]) <= 1e-6 && fabs(f.planes[k].d - en[k][3]) <= 1e-5,
                         "ortho plane %d = (%g,%g,%g,%g)", k, f.planes[k].n.x, f.planes[k].n.y,
                         f.planes[k].n.z, f.planes[k].d);
    }

    /* perspective camera: corners against the gluPerspective/gluLookAt
       geometry in double. Unprojection is ill-conditioned with depth:
       dz_ndc/dd = 2 zf zn / ((zf-zn) d^2), so a float rounding of ~2e-7 in
       z_ndc moves a corner by ~1e-7 * d^2/zn; tolerance 4e-6 (1 + d^2/zn). */
    {
        dv3 eye = dv(1, 2, 3), target = dv(4, 1, -5), up = dv(0, 1, 0);
        cam_t c = make_cam(eye, target, up, 0.9f, 1.5f, 0.5f, 30.0f);
        sk_mat4 VP = sk_mat4_mul(sk_mat4_perspective(0.9f, 1.5f, 0.5f, 30.0f),
                                 sk_mat4_look_at(tof(eye), tof(target), tof(up)));
        f = sk_frustum_from_matrix(VP);
        for (i = 0; i < 8; i++) {
            dv3 e = cam_corner(&c, i, c.zn, c.zf);
            double d = (i & 4) ? c.zf : c.zn, tol = 4e-6 * (1.0 + d * d / c.zn);
            double err = dlen(dsub(tod(f.corners[i]), e));
            SK_CHECK_MSG(err <= tol, "perspective corner %d off by %g (tol %g)", i, err, tol);
        }
        /* planes: normalised, through their own 4 corners, centroid inside */
        bad = frustum_plane_violations(&f, 1e-5, 2e-4, 1);
        SK_CHECK_MSG(bad == 0, "perspective frustum planes: %d violations", bad);
        /* plane order: near faces forward, far faces backward, left faces +s ... */
        SK_CHECK(ddot(tod(f.planes[4].n), c.f) > 0.999999);
        SK_CHECK(ddot(tod(f.planes[5].n), c.f) < -0.999999);
        SK_CHECK(ddot(tod(f.planes[0].n), c.s) > 0.5);
        SK_CHECK(ddot(tod(f.planes[1].n), c.s) < -0.5);
        SK_CHECK(ddot(tod(f.planes[2].n), c.u) > 0.5);
        SK_CHECK(ddot(tod(f.planes[3].n), c.u) < -0.5);
        /* side planes pass through the eye */
        for (k = 0; k < 4; k++) SK_CHECK_NEAR(pdist(&f.planes[k], eye), 0.0, 1e-5);
        /* near plane at distance zn from the eye */
        SK_CHECK_NEAR(pdist(&f.planes[4], eye), -0.5, 1e-5);
        SK_CHECK_NEAR(pdist(&f.planes[5], eye), 30.0, 1e-3);
    }

    /* stability: far/near = 1e6 still gives finite corners and planes */
    {
        sk_mat4 VP = sk_mat4_mul(sk_mat4_perspective(1.0f, 1.0f, 0.01f, 1e4f),
                                 sk_mat4_look_at(v3(0, 0, 0), v3(0, 0, -1), v3(0, 1, 0)));
        const float *p;
        size_t n;
        f = sk_frustum_from_matrix(VP);
        p = (const float *)(const void *)&f;
        bad = 0;
        for (n = 0; n < sizeof f / sizeof(float); n++) if (!isfinite((double)p[n])) bad++;
        SK_CHECK_MSG(bad == 0, "far/near 1e6 frustum has %d non-finite values", bad);
        SK_CHECK(!frustum_all_zero(&f));
    }

    /* singular and non-finite matrices: an all-zero frustum */
    {
        sk_mat4 Z;
        memset(&Z, 0, sizeof Z);
        f = sk_frustum_from_matrix(Z);
        SK_CHECK(frustum_all_zero(&f));
        Z = sk_mat4_identity(); Z.m[15] = 0;  /* rank 3 */
        f = sk_frustum_from_matrix(Z);
        SK_CHECK(frustum_all_zero(&f));
        Z = sk_mat4_identity(); Z.m[5] = fnan();
        f = sk_frustum_from_matrix(Z);
        SK_CHECK(frustum_all_zero(&f));
        Z = sk_mat4_identity(); Z.m[12] = finf();
        f = sk_frustum_from_matrix(Z);
        SK_CHECK(frustum_all_zero(&f));
    }
}

/* ------------------------------------------------------------ frustum from corners */
static void test_frustum_from_corners(void) {
    sk_vec3 c[8];
    sk_frustum f, g;
    int i, k, bad;

    /* a box [1,3]x[-2,2]x[0,5]: planes are the axis planes */
    for (i = 0; i < 8; i++) c[i] = v3((i & 1) ? 3.0f : 1.0f, (i & 2) ? 2.0f : -2.0f, (i & 4) ? 5.0f : 0.0f);
    fill_sentinel(&f, sizeof f);
    SK_CHECK(sk_frustum_from_corners(c, &f) == SK_OK);
    SK_CHECK(memcmp(f.corners, c, sizeof c) == 0);
    {
        static const float en[6][4] = { { 1, 0, 0, -1 }, { -1, 0, 0, 3 }, { 0, 1, 0, 2 },
                                        { 0, -1, 0, 2 }, { 0, 0, 1, 0 }, { 0, 0, -1, 5 } };
        for (k = 0; k < 6; k++)
            SK_CHECK_MSG(fabs(f.planes[k].n.x - en[k][0]) <= 1e-6 && fabs(f.planes[k].n.y - en[k][1]) <= 1e-6 &&
                         fabs(f.planes[k].n.z - en[k][2]) <= 1e-6 && fabs(f.planes[k].d - en[k][3]) <= 1e-5,
                         "box plane %d = (%g,%g,%g,%g)", k, f.planes[k].n.x, f.planes[k].n.y,
                         f.planes[k].n.z, f.planes[k].d);
    }

    /* perspective corners (exact geometry rounded to float): planes agree with
       sk_frustum_from_matrix of the same camera */
    {
        dv3 eye = dv(-3, 1, 2), target = dv(2, 0, -6), up = dv(0, 1, 0);
        cam_t cam = make_cam(eye, target, up, 1.1f, 1.25f, 1.0f, 40.0f);
        sk_mat4 VP = cam_view_proj(&cam, target, up);
        for (i = 0; i < 8; i++) c[i] = tof(cam_corner(&cam, i, cam.zn, cam.zf));
        SK_CHECK(sk_frustum_from_corners(c, &f) == SK_OK);
        bad = frustum_plane_violations(&f, 1e-5, 1e-5, 1);
        SK_CHECK_MSG(bad == 0, "perspective-from-corners: %d violations", bad);
        g = sk_frustum_from_matrix(VP);
        for (k = 0; k < 6; k++) {
            double dotn = ddot(tod(f.planes[k].n), tod(g.planes[k].n));
            SK_CHECK_MSG(dotn >= 1.0 - 1e-6, "plane %d normals differ (dot %.9g)", k, dotn);
            SK_CHECK_MSG(fabs(f.planes[k].d - g.planes[k].d) <= 2e-3,
                         "plane %d d: %.9g vs %.9g", k, f.planes[k].d, g.planes[k].d);
        }
    }

    /* a sheared, non-axis-aligned hexahedron (parallelepiped) */
    {
        dv3 o = dv(0.5, -1, 2), a = dv(2, 0.5, 0), b = dv(0.3, 1.5, 0.2), e = dv(-0.4, 0.1, 3);
        for (i = 0; i < 8; i++)
            c[i] = tof(dadd(dadd(dadd(o, dmul(a, (i & 1) ? 1 : 0)), dmul(b, (i & 2) ? 1 : 0)), dmul(e, (i & 4) ? 1 : 0)));
        SK_CHECK(sk_frustum_from_corners(c, &f) == SK_OK);
        bad = frustum_plane_violations(&f, 1e-5, 1e-5, 1);
        SK_CHECK_MSG(bad == 0, "parallelepiped: %d violations", bad);
        /* mirrored corner order (bit 0 = x min): still oriented inward */
        for (i = 0; i < 8; i++)
            c[i] = tof(dadd(dadd(dadd(o, dmul(a, (i & 1) ? 0 : 1)), dmul(b, (i & 2) ? 1 : 0)), dmul(e, (i & 4) ? 1 : 0)));
        SK_CHECK(sk_frustum_from_corners(c, &f) == SK_OK);
        bad = frustum_plane_violations(&f, 1e-5, 1e-5, 1);
        SK_CHECK_MSG(bad == 0, "mirrored parallelepiped: %d violations", bad);
    }

    /* stability (DESIGN.md): far/near = 1e6 is a valid frustum, its tiny near
       face has non-zero area (~1e-4 x 1e-4 here, exactly representable
       corners): SK_OK with consistent planes */
    {
        dv3 eye = dv(0, 0, 0), target = dv(0, 0, -1), up = dv(0, 1, 0);
        cam_t cam = make_cam(eye, target, up, 1.0f, 1.0f, 0.01f, 1e4f);
        sk_result r;
        for (i = 0; i < 8; i++) c[i] = tof(cam_corner(&cam, i, cam.zn, cam.zf));
        r = sk_frustum_from_corners(c, &f);
        SK_CHECK_MSG(r == SK_OK, "far/near 1e6 frustum from corners: %s", sk_result_string(r));
        if (r == SK_OK) {
            bad = frustum_plane_violations(&f, 1e-6, 1e-5, 1);
            SK_CHECK_MSG(bad == 0, "far/near 1e6 from corners: %d violations", bad);
        }
        for (i = 0; i < 8; i++) c[i] = tof(cam_corner(&cam, i, cam.zn, 1e3));  /* 1e5: fine either way */
        SK_CHECK(sk_frustum_from_corners(c, &f) == SK_OK);
    }

    /* degenerate faces */
    for (i = 0; i < 8; i++) c[i] = v3(1, 2, 3);
    SK_CHECK(sk_frustum_from_corners(c, &f) == SK_ERR_DEGENERATE);
    for (i = 0; i < 8; i++)   /* near face collapsed to a point (a pyramid) */
        c[i] = (i & 4) ? v3((i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f, -5.0f) : v3(0, 0, 0);
    SK_CHECK(sk_frustum_from_corners(c, &f) == SK_ERR_DEGENERATE);
    for (i = 0; i < 8; i++)   /* flat: near and far faces coincide */
        c[i] = v3((i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f, 0.0f);
    SK_CHECK(sk_frustum_from_corners(c, &f) == SK_ERR_DEGENERATE);

    /* bad input: INVALID_ARG, out untouched */
    for (i = 0; i < 8; i++) c[i] = v3((i & 1) ? 3.0f : 1.0f, (i & 2) ? 2.0f : -2.0f, (i & 4) ? 5.0f : 0.0f);
    fill_sentinel(&f, sizeof f);
    SK_CHECK(sk_frustum_from_corners(NULL, &f) == SK_ERR_INVALID_ARG);
    SK_CHECK(sk_frustum_from_corners(c, NULL) == SK_ERR_INVALID_ARG);
    c[5].y = fnan();
    SK_CHECK(sk_frustum_from_corners(c, &f) == SK_ERR_INVALID_ARG);
    c[5].y = finf();
    SK_CHECK(sk_frustum_from_corners(c, &f) == SK_ERR_INVALID_ARG);
    c[5].y = 2.0f; c[0].x = -finf();
    SK_CHECK(sk_frustum_from_corners(c, &f) == SK_ERR_INVALID_ARG);
    SK_CHECK(is_sentinel(&f, sizeof f));
}

/* ------------------------------------------------------------ frustum from AABB */
static void test_frustum_from_aabb(void) {
    sk_frustum f;
    sk_aabb b = box3(1, -2, 0, 3, 2, 5);
    int i, k, bad;
    static const float en[6][4] = { { 1, 0, 0, -1 }, { -1, 0, 0, 3 }, { 0, 1, 0, 2 },
                                    { 0, -1, 0, 2 }, { 0, 0, 1, 0 }, { 0, 0, -1, 5 } };
    fill_sentinel(&f, sizeof f);
    SK_CHECK(sk_frustum_from_aabb(b, &f) == SK_OK);
    for (i = 0; i < 8; i++)
        SK_CHECK_MSG(f.corners[i].x == ((i & 1) ? 3.0f : 1.0f) && f.corners[i].y == ((i & 2) ? 2.0f : -2.0f) &&
                     f.corners[i].z == ((i & 4) ? 5.0f : 0.0f),
                     "aabb corner %d = (%g,%g,%g)", i, f.corners[i].x, f.corners[i].y, f.corners[i].z);
    for (k = 0; k < 6; k++)
        SK_CHECK_MSG(fabs(f.planes[k].n.x - en[k][0]) <= 1e-6 && fabs(f.planes[k].n.y - en[k][1]) <= 1e-6 &&
                     fabs(f.planes[k].n.z - en[k][2]) <= 1e-6 && fabs(f.planes[k].d - en[k][3]) <= 1e-6,
                     "aabb plane %d = (%g,%g,%g,%g)", k, f.planes[k].n.x, f.planes[k].n.y,
                     f.planes[k].n.z, f.planes[k].d);
    bad = frustum_plane_violations(&f, 1e-6, 0, 1);
    SK_CHECK(bad == 0);
    /* far from the origin: planes still exact (d = -1e5 etc.) */
    SK_CHECK(sk_frustum_from_aabb(box3(1e5f, 1e5f, 1e5f, 1e5f + 1, 1e5f + 2, 1e5f + 3), &f) == SK_OK);
    SK_CHECK_NEAR(f.planes[0].d, -1e5, 0.02);
    SK_CHECK_NEAR(f.planes[5].d, 1e5 + 3, 0.02);

    /* bad input: INVALID_ARG, out untouched */
    fill_sentinel(&f, sizeof f);
    SK_CHECK(sk_frustum_from_aabb(box3(3, -2, 0, 1, 2, 5), &f) == SK_ERR_INVALID_ARG);
    SK_CHECK(sk_frustum_from_aabb(box3(1, 2, 0, 3, -2, 5), &f) == SK_ERR_INVALID_ARG);
    SK_CHECK(sk_frustum_from_aabb(box3(1, -2, 5, 3, 2, 0), &f) == SK_ERR_INVALID_ARG);
    SK_CHECK(sk_frustum_from_aabb(box3(fnan(), -2, 0, 3, 2, 5), &f) == SK_ERR_INVALID_ARG);
    SK_CHECK(sk_frustum_from_aabb(box3(1, -2, 0, 3, fnan(), 5), &f) == SK_ERR_INVALID_ARG);
    SK_CHECK(sk_frustum_from_aabb(box3(1, -2, -finf(), 3, 2, 5), &f) == SK_ERR_INVALID_ARG);
    SK_CHECK(sk_frustum_from_aabb(box3(1, -2, 0, finf(), 2, 5), &f) == SK_ERR_INVALID_ARG);
    SK_CHECK(is_sentinel(&f, sizeof f));
    SK_CHECK(sk_frustum_from_aabb(b, NULL) == SK_ERR_INVALID_ARG);
}

/* ------------------------------------------------------------ contains point */
static void test_frustum_contains_point(void) {
    dv3 eye = dv(0, 2, 10), target = dv(0, 0, 0), up = dv(0, 1, 0);
    cam_t c = make_cam(eye, target, up, 0.8f, 1.5f, 1.0f, 20.0f);
    sk_frustum f = sk_frustum_from_matrix(cam_view_proj(&c, target, up)), z, b;
    int i;
    SK_CHECK(sk_frustum_contains_point(&f, tof(centroid(&f))) == 1);
    for (i = 0; i < 8; i++) SK_CHECK(sk_frustum_contains_point(&f, f.corners[i]) == 1);
    /* face centres (on the boundary) are inside */
    SK_CHECK(sk_frustum_contains_point(&f, tof(dadd(eye, dmul(c.f, 1.0)))) == 1);
    SK_CHECK(sk_frustum_contains_point(&f, tof(dadd(eye, dmul(c.f, 20.0)))) == 1);
    SK_CHECK(sk_frustum_contains_point(&f, tof(dadd(eye, dmul(c.f, 7.0)))) == 1);
    /* outside: before near, past far, the eye, beside each side plane */
    SK_CHECK(sk_frustum_contains_point(&f, tof(dadd(eye, dmul(c.f, 0.9)))) == 0);
    SK_CHECK(sk_frustum_contains_point(&f, tof(dadd(eye, dmul(c.f, 20.5)))) == 0);
    SK_CHECK(sk_frustum_contains_point(&f, tof(eye)) == 0);
    {
        double d = 10.0, hx = d * c.ty * c.aspect, hy = d * c.ty;
        dv3 mid = dadd(eye, dmul(c.f, d));
        SK_CHECK(sk_frustum_contains_point(&f, tof(dadd(mid, dmul(c.s, 0.98 * hx)))) == 1);
        SK_CHECK(sk_frustum_contains_point(&f, tof(dadd(mid, dmul(c.s, 1.02 * hx)))) == 0);
        SK_CHECK(sk_frustum_contains_point(&f, tof(dadd(mid, dmul(c.s, -1.02 * hx)))) == 0);
        SK_CHECK(sk_frustum_contains_point(&f, tof(dadd(mid, dmul(c.u, 0.98 * hy)))) == 1);
        SK_CHECK(sk_frustum_contains_point(&f, tof(dadd(mid, dmul(c.u, 1.02 * hy)))) == 0);
        SK_CHECK(sk_frustum_contains_point(&f, tof(dadd(mid, dmul(c.u, -1.02 * hy)))) == 0);
    }
    /* box frustum: boundary tolerance is relative 1e-5 */
    SK_CHECK(sk_frustum_from_aabb(box3(0, 0, 0, 10, 10, 10), &b) == SK_OK);
    SK_CHECK(sk_frustum_contains_point(&b, v3(10, 10, 10)) == 1);
    SK_CHECK(sk_frustum_contains_point(&b, v3(10.00001f, 5, 5)) == 1);   /* 1e-6 relative */
    SK_CHECK(sk_frustum_contains_point(&b, v3(10.01f, 5, 5)) == 0);      /* 1e-3 relative */
    SK_CHECK(sk_frustum_contains_point(&b, v3(5, -0.01f, 5)) == 0);
    /* the all-zero frustum means "unknown": conservatively inside */
    memset(&z, 0, sizeof z);
    SK_CHECK(sk_frustum_contains_point(&z, v3(123, -4, 5)) == 1);
    /* NaN point and NULL frustum: a defined 0/1 answer, no crash */
    i = sk_frustum_contains_point(&f, v3(fnan(), 0, 0));
    SK_CHECK(i == 0 || i == 1);
    i = sk_frustum_contains_point(NULL, v3(0, 0, 0));
    SK_CHECK(i == 0 || i == 1);
}

/* ------------------------------------------------------------ clipping */
/* inside test with absolute tolerance, in double against the frustum's planes */
static inline int in_frustum_tol(const sk_frustum *f, dv3 p, double tol) {
    int k;
    for (k = 0; k < 6; k++) if (pdist(&f->planes[k], p) < -tol) return 0;
    return 1;
}
static inline int in_box_tol(sk_aabb b, dv3 p, double tol) {
    return p.x >= b.min.x - tol && p.x <= b.max.x + tol && p.y >= b.min.y - tol && p.y <= b.max.y + tol &&
           p.z >= b.min.z - tol && p.z <= b.max.z + tol;
}
static inline int has_point(const sk_vec3 *pts, int n, dv3 p, double tol) {
    int i;
    for (i = 0; i < n; i++) if (dlen(dsub(tod(pts[i]), p)) <= tol) return 1;
    return 0;
}
/* soundness: every output point in both (tol); completeness: for sampled points
   of the intersection, the support function of the output hull is not smaller
   in any of a set of directions. Returns the number of violations. */
static int check_clip(const sk_frustum *f, sk_aabb b, const sk_vec3 *pts, int n, double tol, int nsamples,
                      int verbose) {
    dv3 dirs[64];
    double sup[64];
    int nd = 0, i, j, bad = 0, x, y, z;
    for (i = 0; i < n; i++) {
        dv3 p = tod(pts[i]);
        if (!isfinite(p.x) || !isfinite(p.y) || !isfinite(p.z) || !in_frustum_tol(f, p, tol) || !in_box_tol(b, p, tol)) {
            bad++;
            if (verbose) printf("    clip point %d (%g,%g,%g) outside frustum or box\n", i, p.x, p.y, p.z);
        }
    }
    for (x = -1; x <= 1; x++)
        for (y = -1; y <= 1; y++)
            for (z = -1; z <= 1; z++)
                if (x || y || z) dirs[nd++] = dnorm(dv(x, y, z));
    while (nd < 64) dirs[nd++] = dnorm(dv(rnd(-1, 1), rnd(-1, 1), rnd(-1, 1)));
    for (j = 0; j < nd; j++) {
        sup[j] = -1e300;
        for (i = 0; i < n; i++) {
            double s = ddot(dirs[j], tod(pts[i]));
            if (s > sup[j]) sup[j] = s;
        }
    }
    for (i = 0; i < nsamples; i++) {
        dv3 p;
        if (i & 1) {  /* a point of the frustum (trilinear in its corners) */
            double u = rnd(0, 1), v = rnd(0, 1), w = rnd(0, 1);
            int k;
            p = dv(0, 0, 0);
            for (k = 0; k < 8; k++) {
                double wt = ((k & 1) ? u : 1 - u) * ((k & 2) ? v : 1 - v) * ((k & 4) ? w : 1 - w);
                p = dadd(p, dmul(tod(f->corners[k]), wt));
            }
            if (!in_box_tol(b, p, -1e-9)) continue;
        } else {      /* a point of the box */
            p = dv(rnd(b.min.x, b.max.x), rnd(b.min.y, b.max.y), rnd(b.min.z, b.max.z));
            if (!in_frustum_tol(f, p, -1e-9)) continue;
        }
        for (j = 0; j < nd; j++)
            if (ddot(dirs[j], p) > sup[j] + tol) {
                bad++;
                if (verbose && bad < 5)
                    printf("    intersection point (%g,%g,%g) beyond the clip hull in direction %d by %g\n",
                           p.x, p.y, p.z, j, ddot(dirs[j], p) - sup[j]);
                break;
            }
    }
    return bad;
}

static void test_clip_frustum_aabb(void) {
    dv3 eye = dv(0, 2, 10), target = dv(0, 0, 0), up = dv(0, 1, 0);
    cam_t c = make_cam(eye, target, up, 0.8f, 1.3333f, 1.0f, 20.0f);
    sk_frustum f = sk_frustum_from_matrix(cam_view_proj(&c, target, up));
    sk_vec3 out[SK_CLIP_MAX_POINTS + 8];
    sk_aabb b;
    int n, i, bad;
    const double tol = 1e-4 * 20.0;  /* 1e-4 of the scene size */

    /* a box containing the frustum: the frustum itself, all 8 corners present */
    b = box3(-100, -100, -100, 100, 100, 100);
    n = sk_clip_frustum_aabb(&f, b, out, SK_CLIP_MAX_POINTS);
    SK_CHECK_MSG(n >= 8 && n <= SK_CLIP_MAX_POINTS, "containing box: n = %d", n);
    if (n > 0) {
        for (i = 0; i < 8; i++) SK_CHECK_MSG(has_point(out, n, tod(f.corners[i]), tol), "corner %d missing", i);
        bad = check_clip(&f, b, out, n, tol, 4000, 1);
        SK_CHECK_MSG(bad == 0, "containing box: %d violations", bad);
    }

    /* boxes that miss: far away, behind the eye, and inside the frustum's
       own bounding box but outside its left plane */
    fill_sentinel(out, sizeof out);
    SK_CHECK(sk_clip_frustum_aabb(&f, box3(500, 500, 500, 501, 501, 501), out, SK_CLIP_MAX_POINTS) == 0);
    SK_CHECK(sk_clip_frustum_aabb(&f, box3(-1, 1, 11, 1, 3, 12), out, SK_CLIP_MAX_POINTS) == 0);
    {
        double hx = 20.0 * c.ty * c.aspect;
        dv3 p = dadd(dadd(eye, dmul(c.f, 1.5)), dmul(c.s, -0.9 * hx));
        sk_aabb mb = box3((float)p.x - 0.2f, (float)p.y - 0.2f, (float)p.z - 0.2f,
                          (float)p.x + 0.2f, (float)p.y + 0.2f, (float)p.z + 0.2f);
        double lo[3] = { 1e9, 1e9, 1e9 }, hi[3] = { -1e9, -1e9, -1e9 };
        for (i = 0; i < 8; i++) {
            dv3 q = tod(f.corners[i]);
            if (q.x < lo[0]) lo[0] = q.x;
            if (q.y < lo[1]) lo[1] = q.y;
            if (q.z < lo[2]) lo[2] = q.z;
            if (q.x > hi[0]) hi[0] = q.x;
            if (q.y > hi[1]) hi[1] = q.y;
            if (q.z > hi[2]) hi[2] = q.z;
        }
        /* preconditions of this case */
        SK_CHECK(p.x > lo[0] && p.x < hi[0] && p.y > lo[1] && p.y < hi[1] && p.z > lo[2] && p.z < hi[2]);
        SK_CHECK(pdist(&f.planes[0], p) < -0.5);
        SK_CHECK(sk_clip_frustum_aabb(&f, mb, out, SK_CLIP_MAX_POINTS) == 0);
    }
    SK_CHECK(is_sentinel(out, sizeof out));

    /* a box inside the frustum: its 8 corners */
    b = box3(-0.5f, 0.0f, -1.0f, 0.5f, 1.0f, 1.0f);
    n = sk_clip_frustum_aabb(&f, b, out, SK_CLIP_MAX_POINTS);
    SK_CHECK_MSG(n >= 8, "inner box: n = %d", n);
    if (n > 0) {
        for (i = 0; i < 8; i++) {
            dv3 q = dv((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z);
            SK_CHECK_MSG(in_frustum_tol(&f, q, -1e-3), "precondition: box corner %d inside", i);
            SK_CHECK_MSG(has_point(out, n, q, tol), "inner box corner %d missing", i);
        }
        bad = check_clip(&f, b, out, n, tol, 4000, 1);
        SK_CHECK_MSG(bad == 0, "inner box: %d violations", bad);
    }

    /* partial overlap: points inside both, box corners inside the frustum and
       frustum corners inside the box present, nothing of the body missing */
    b = box3(-3, -1, -2, 2, 1.5f, 9.5f);
    n = sk_clip_frustum_aabb(&f, b, out, SK_CLIP_MAX_POINTS);
    SK_CHECK_MSG(n > 8 && n <= SK_CLIP_MAX_POINTS, "partial: n = %d", n);
    if (n > 0) {
        int inside_box_corners = 0, inside_frustum_corners = 0;
        for (i = 0; i < 8; i++) {
            dv3 q = dv((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z);
            if (in_frustum_tol(&f, q, -1e-3)) {
                inside_box_corners++;
                SK_CHECK_MSG(has_point(out, n, q, tol), "partial: box corner %d missing", i);
            }
            if (in_box_tol(b, tod(f.corners[i]), -1e-3)) {
                inside_frustum_corners++;
                SK_CHECK_MSG(has_point(out, n, tod(f.corners[i]), tol), "partial: frustum corner %d missing", i);
            }
        }
        /* preconditions: the case really is partial on both sides */
        SK_CHECK_MSG(inside_box_corners > 0 && inside_box_corners < 8, "box corners inside: %d", inside_box_corners);
        SK_CHECK_MSG(inside_frustum_corners > 0 && inside_frustum_corners < 8, "frustum corners inside: %d",
                     inside_frustum_corners);
        bad = check_clip(&f, b, out, n, tol, 20000, 1);
        SK_CHECK_MSG(bad == 0, "partial: %d violations", bad);

        /* capacity: fewer slots than points -> -CAPACITY, at most cap written */
        fill_sentinel(out, sizeof out);
        SK_CHECK(sk_clip_frustum_aabb(&f, b, out, 3) == -SK_ERR_CAPACITY);
        SK_CHECK(is_sentinel(out + 3, sizeof out - 3 * sizeof out[0]));
        i = sk_clip_frustum_aabb(&f, b, out, 0);
        SK_CHECK_MSG(i == -SK_ERR_CAPACITY || i == -SK_ERR_INVALID_ARG, "cap 0: %d", i);
        SK_CHECK(is_sentinel(out, sizeof out));
    }

    /* scale: distinct vertices of the intersection must survive whatever the
       size of the other body. (a) a short camera frustum inside huge scene
       bounds (+-1e5, a terrain): all 8 frustum corners; (b) a 4 cm box inside
       a far/near = 1e6 view: all 8 box corners. Tolerance 1e-4 of the
       intersection's own size. */
    {
        sk_frustum sf = sk_frustum_from_matrix(sk_mat4_mul(sk_mat4_perspective(1.0f, 1.5f, 0.1f, 10.0f),
                                                           sk_mat4_look_at(v3(0, 1, 0), v3(0, 1, -1), v3(0, 1, 0))));
        sk_frustum lf = sk_frustum_from_matrix(sk_mat4_mul(sk_mat4_perspective(1.0f, 1.0f, 0.01f, 1e4f),
                                                           sk_mat4_look_at(v3(0, 0, 0), v3(0, 0, -1), v3(0, 1, 0))));
        sk_aabb small = box3(-0.02f, -0.02f, -5.04f, 0.02f, 0.02f, -5.0f);
        int miss = 0;
        n = sk_clip_frustum_aabb(&sf, box3(-1e5f, -1e5f, -1e5f, 1e5f, 1e5f, 1e5f), out, SK_CLIP_MAX_POINTS);
        for (i = 0; i < 8; i++) if (n < 0 || !has_point(out, n, tod(sf.corners[i]), 1e-4 * 10)) miss++;
        SK_CHECK_MSG(miss == 0, "frustum (zn 0.1, zf 10) in a +-1e5 box: %d of 8 corners lost (n = %d)", miss, n);
        miss = 0;
        n = sk_clip_frustum_aabb(&lf, small, out, SK_CLIP_MAX_POINTS);
        for (i = 0; i < 8; i++) {
            dv3 q = dv((i & 1) ? small.max.x : small.min.x, (i & 2) ? small.max.y : small.min.y,
                       (i & 4) ? small.max.z : small.min.z);
            if (n < 0 || !has_point(out, n, q, 1e-4 * 0.04)) miss++;
        }
        SK_CHECK_MSG(miss == 0, "4 cm box in a far/near 1e6 view: %d of 8 corners lost (n = %d)", miss, n);
    }

    /* random configurations: never more than SK_CLIP_MAX_POINTS, sound, complete */
    {
        int trial, worst_n = 0, fails = 0, nonzero = 0;
        for (trial = 0; trial < 300; trial++) {
            dv3 e = dv(rnd(-5, 5), rnd(-5, 5), rnd(-5, 5));
            dv3 t = dadd(e, dv(rnd(-1, 1), rnd(-1, 1), rnd(-1, 1)));
            dv3 ctr = dadd(e, dmul(dsub(t, e), rnd(0, 12)));
            sk_frustum rf;
            sk_aabb rb;
            double h = rnd(0.5, 8);
            if (dlen(dsub(t, e)) < 0.1) continue;
            rf = sk_frustum_from_matrix(sk_mat4_mul(
                sk_mat4_perspective((float)rnd(0.3, 2.5), (float)rnd(0.5, 2), (float)rnd(0.1, 1), (float)rnd(5, 20)),
                sk_mat4_look_at(tof(e), tof(t), v3(0, 1, 0))));
            rb = box3((float)(ctr.x - h * rnd(0.2, 1)), (float)(ctr.y - h * rnd(0.2, 1)), (float)(ctr.z - h * rnd(0.2, 1)),
                      (float)(ctr.x + h * rnd(0.2, 1)), (float)(ctr.y + h * rnd(0.2, 1)), (float)(ctr.z + h * rnd(0.2, 1)));
            n = sk_clip_frustum_aabb(&rf, rb, out, SK_CLIP_MAX_POINTS);
            if (n < 0 || n > SK_CLIP_MAX_POINTS) {
                fails++;
                printf("    random clip %d returned %d\n", trial, n);
                continue;
            }
            if (n > worst_n) worst_n = n;
            if (n > 0) nonzero++;
            if (check_clip(&rf, rb, out, n, 1e-4 * 40.0, 600, fails < 3) != 0) {
                fails++;
                printf("    random clip %d: wrong body (n = %d)\n", trial, n);
            }
        }
        SK_CHECK_MSG(fails == 0, "%d of 300 random clips wrong", fails);
        SK_CHECK_MSG(nonzero > 50, "only %d random clips intersect (test too weak)", nonzero);
    }

    /* bad input: -INVALID_ARG, out untouched */
    fill_sentinel(out, sizeof out);
    b = box3(-3, -1, -2, 2, 1.5f, 9.5f);
    SK_CHECK(sk_clip_frustum_aabb(NULL, b, out, SK_CLIP_MAX_POINTS) == -SK_ERR_INVALID_ARG);
    SK_CHECK(sk_clip_frustum_aabb(&f, b, NULL, SK_CLIP_MAX_POINTS) == -SK_ERR_INVALID_ARG);
    SK_CHECK(sk_clip_frustum_aabb(&f, b, out, -1) == -SK_ERR_INVALID_ARG);
    SK_CHECK(sk_clip_frustum_aabb(&f, box3(2, -1, -2, -3, 1.5f, 9.5f), out, SK_CLIP_MAX_POINTS) == -SK_ERR_INVALID_ARG);
    SK_CHECK(sk_clip_frustum_aabb(&f, box3(-3, -1, -2, 2, fnan(), 9.5f), out, SK_CLIP_MAX_POINTS) == -SK_ERR_INVALID_ARG);
    SK_CHECK(sk_clip_frustum_aabb(&f, box3(-3, -1, -finf(), 2, 1.5f, 9.5f), out, SK_CLIP_MAX_POINTS) == -SK_ERR_INVALID_ARG);
    {
        sk_frustum nf = f;
        nf.corners[3].x = fnan();
        nf.planes[2].d = fnan();
        SK_CHECK(sk_clip_frustum_aabb(&nf, b, out, SK_CLIP_MAX_POINTS) == -SK_ERR_INVALID_ARG);
    }
    SK_CHECK(is_sentinel(out, sizeof out));
    /* the all-zero frustum ("unknown"): any defined answer, finite points */
    {
        sk_frustum z;
        memset(&z, 0, sizeof z);
        n = sk_clip_frustum_aabb(&z, b, out, SK_CLIP_MAX_POINTS);
        SK_CHECK(n == -SK_ERR_INVALID_ARG || n == -SK_ERR_DEGENERATE || (n >= 0 && n <= SK_CLIP_MAX_POINTS));
        for (i = 0; i < n; i++) SK_CHECK(isfinite(out[i].x) && isfinite(out[i].y) && isfinite(out[i].z));
    }
}

SK_TEST_MAIN(test_result_string, test_mat4_identity_mul, test_mat4_inverse, test_mat4_perspective,
             test_mat4_ortho, test_mat4_look_at, test_mat4_transform, test_frustum_from_matrix,
             test_frustum_from_corners, test_frustum_from_aabb, test_frustum_contains_point,
             test_clip_frustum_aabb)
