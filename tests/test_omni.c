/* tests/test_omni.c - section 6 of shadowkit.h, omnidirectional lights
   (King & Newhall 2004, "Efficient Omnidirectional Shadow Maps"):
   cube faces, frustum-frustum culling (HalfIntersection), caster culling,
   scissor, cube resolution N*M^2 >= c*S, and the Virtual Shadow Depth Cube
   Texture (Eqs. 5.4.6 and 5.4.7, indirection cube map).

   Every expected value comes from an oracle written here in double precision,
   never from the implementation:
     - the OpenGL spec's cube-map face selection table (major axis, sc, tc,
       s = (sc/|ma| + 1)/2, t = (tc/|ma| + 1)/2) and its inverse;
     - Eq. 5.4.6 z = zf/(zf-zn) - zf*zn/((zf-zn)*MA) and Eq. 5.4.7 by hand
       and in integer arithmetic;
     - frustum intersection: exact convex clipping of one frustum's faces by
       the other's planes, and random points sampled inside both;
     - caster culling: points of the view frustum whose segment to the light
       crosses the caster box, and points of the shadow volume itself;
     - scissor: the 8 range-box corners projected here;
     - cube resolution and indirection size: brute force over integers.
   Frusta given to the library are built here (corners and planes), so these
   tests do not depend on the core-math section. */
#define SHADOWKIT_IMPLEMENTATION
#include "shadowkit.h"
#include "tests/sk_test.h"
#include <stdlib.h>
#include <float.h>
#include <limits.h>

/* ================================================================ helpers */
typedef struct dv3 { double x, y, z; } dv3;
static dv3 d3(double x, double y, double z) { dv3 r; r.x = x; r.y = y; r.z = z; return r; }
static dv3 dadd(dv3 a, dv3 b) { return d3(a.x + b.x, a.y + b.y, a.z + b.z); }
static dv3 dsub(dv3 a, dv3 b) { return d3(a.x - b.x, a.y - b.y, a.z - b.z); }
static dv3 dmul(dv3 a, double s) { return d3(a.x * s, a.y * s, a.z * s); }
static double ddot(dv3 a, dv3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static dv3 dcross(dv3 a, dv3 b) {
    return d3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static double dlen(dv3 a) { return sqrt(ddot(a, a)); }
static dv3 dnorm(dv3 a) { double l = dlen(a); return l > 0 ? dmul(a, 1.0 / l) : a; }
static dv3 dlerp(dv3 a, dv3 b, double t) { return dadd(a, dmul(dsub(b, a), t)); }
static double dmax(double a, double b) { return a > b ? a : b; }
static double dmin(double a, double b) { return a < b ? a : b; }
static double dclamp(double x, double a, double b) { return x < a ? a : (x > b ? b : x); }
static sk_vec3 v3(double x, double y, double z) {
    sk_vec3 r; r.x = (float)x; r.y = (float)y; r.z = (float)z; return r;
}
static sk_vec3 tof(dv3 a) { return v3(a.x, a.y, a.z); }
static dv3 tod(sk_vec3 a) { return d3(a.x, a.y, a.z); }
static sk_aabb mkbox(dv3 mn, dv3 mx) { sk_aabb b; b.min = tof(mn); b.max = tof(mx); return b; }
static int mat_finite(const sk_mat4 *m) {
    int i;
    for (i = 0; i < 16; i++) if (!isfinite(m->m[i])) return 0;
    return 1;
}
static int mat_same(const sk_mat4 *a, const sk_mat4 *b) {
    int i;
    for (i = 0; i < 16; i++) if (a->m[i] != b->m[i]) return 0;
    return 1;
}
static int mat_is_identity(const sk_mat4 *a) {
    int i;
    for (i = 0; i < 16; i++) if (a->m[i] != ((i % 5 == 0) ? 1.0f : 0.0f)) return 0;
    return 1;
}

/* fixed-seed 64-bit LCG: runs are reproducible */
static unsigned long long rng_state = 88172645463325252ULL;
static void rng_seed(unsigned long long s) { rng_state = s * 2862933555777941757ULL + 3037000493ULL; }
static double rnd(void) {
    rng_state = rng_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(rng_state >> 11) * (1.0 / 9007199254740992.0);    /* [0,1) */
}
static double rndr(double a, double b) { return a + (b - a) * rnd(); }
static dv3 rnd_unit(void) {
    for (;;) {
        dv3 p = d3(rndr(-1, 1), rndr(-1, 1), rndr(-1, 1));
        double l = dlen(p);
        if (l > 1e-3 && l <= 1) return dmul(p, 1.0 / l);
    }
}
static dv3 rnd_in_box(double h) { return d3(rndr(-h, h), rndr(-h, h), rndr(-h, h)); }

/* column-major sk_mat4 applied to a 4-vector, in double */
static void mat_apply(const sk_mat4 *m, const double in[4], double out[4]) {
    int r;
    for (r = 0; r < 4; r++)
        out[r] = (double)m->m[r] * in[0] + (double)m->m[4 + r] * in[1] +
                 (double)m->m[8 + r] * in[2] + (double)m->m[12 + r] * in[3];
}
static void mat_point(const sk_mat4 *m, dv3 p, double out[4]) {
    double in[4];
    in[0] = p.x; in[1] = p.y; in[2] = p.z; in[3] = 1.0;
    mat_apply(m, in, out);
}

/* ---------------------------------------------- OpenGL cube-map face table
   OpenGL 3.3 core spec, Table 3.21 (section 3.8.10): major axis direction,
   target, sc, tc, ma:
     +rx  POSITIVE_X  -rz  -ry  rx        -rx  NEGATIVE_X  +rz  -ry  rx
     +ry  POSITIVE_Y  +rx  +rz  ry        -ry  NEGATIVE_Y  +rx  -rz  ry
     +rz  POSITIVE_Z  +rx  -ry  rz        -rz  NEGATIVE_Z  -rx  -ry  rz
   s = (sc/|ma| + 1)/2, t = (tc/|ma| + 1)/2. */
static void face_st(int f, dv3 r, double *s, double *t, double *ma) {
    double m, sc, tc;
    switch (f) {
    case 0:  m = r.x;  sc = -r.z; tc = -r.y; break;
    case 1:  m = -r.x; sc = r.z;  tc = -r.y; break;
    case 2:  m = r.y;  sc = r.x;  tc = r.z;  break;
    case 3:  m = -r.y; sc = r.x;  tc = -r.z; break;
    case 4:  m = r.z;  sc = r.x;  tc = -r.y; break;
    default: m = -r.z; sc = -r.x; tc = -r.y; break;
    }
    m = fabs(m);
    *ma = m;
    *s = (sc / m + 1.0) * 0.5;
    *t = (tc / m + 1.0) * 0.5;
}
/* the faces the table may select: the major axis; on a tie (cube edges and
   corners) the spec leaves the choice open, so every tied axis is allowed */
static unsigned table_faces(dv3 r) {
    double ax = fabs(r.x), ay = fabs(r.y), az = fabs(r.z);
    double m = dmax(ax, dmax(ay, az));
    unsigned mask = 0;
    if (!(m > 0)) return 0;
    if (ax == m) mask |= 1u << (r.x < 0 ? 1 : 0);
    if (ay == m) mask |= 1u << (r.y < 0 ? 3 : 2);
    if (az == m) mask |= 1u << (r.z < 0 ? 5 : 4);
    return mask;
}
static int table_face(dv3 r) {
    unsigned mask = table_faces(r);
    int f;
    for (f = 0; f < 6; f++) if (mask & (1u << f)) return f;
    return -1;
}
/* inverse of the table: the direction (|ma| = 1) through (sc, tc) of face f */
static dv3 face_dir(int f, double sc, double tc) {
    switch (f) {
    case 0:  return d3(1, -tc, -sc);
    case 1:  return d3(-1, -tc, sc);
    case 2:  return d3(sc, 1, tc);
    case 3:  return d3(sc, -1, -tc);
    case 4:  return d3(sc, -tc, 1);
    default: return d3(-sc, -tc, -1);
    }
}
static dv3 face_axis(int f) {
    double s = (f & 1) ? -1.0 : 1.0;
    return f < 2 ? d3(s, 0, 0) : (f < 4 ? d3(0, s, 0) : d3(0, 0, s));
}

/* ------------------------------------------------- convex hexahedra (poly)
   Corner order of sk_frustum: bit 0 x (right), bit 1 y (up), bit 2 z (far).
   Faces in the order left, right, bottom, top, near, far; each quad listed
   cyclically. Planes are recomputed here (Newell normal, oriented towards
   the centroid), in double, from the float corners the library sees. */
static const int face_quads[6][4] = {
    { 0, 2, 6, 4 }, { 1, 3, 7, 5 }, { 0, 1, 5, 4 }, { 2, 3, 7, 6 }, { 0, 1, 3, 2 }, { 4, 5, 7, 6 }
};
typedef struct poly { dv3 c[8]; dv3 n[6]; double d[6]; dv3 g; double radius; } poly;

static void poly_from_corners(poly *P, const dv3 c[8]) {
    int i, k;
    P->g = d3(0, 0, 0);
    for (i = 0; i < 8; i++) { P->c[i] = c[i]; P->g = dadd(P->g, dmul(c[i], 0.125)); }
    P->radius = 0;
    for (i = 0; i < 8; i++) P->radius = dmax(P->radius, dlen(dsub(c[i], P->g)));
    for (k = 0; k < 6; k++) {
        dv3 n = d3(0, 0, 0), fc = d3(0, 0, 0);
        for (i = 0; i < 4; i++) {
            dv3 a = c[face_quads[k][i]], b = c[face_quads[k][(i + 1) & 3]];
            n.x += (a.y - b.y) * (a.z + b.z);
            n.y += (a.z - b.z) * (a.x + b.x);
            n.z += (a.x - b.x) * (a.y + b.y);
            fc = dadd(fc, dmul(a, 0.25));
        }
        n = dnorm(n);
        P->n[k] = n;
        P->d[k] = -ddot(n, fc);
        if (ddot(n, P->g) + P->d[k] < 0) { P->n[k] = dmul(n, -1); P->d[k] = -P->d[k]; }
    }
}
static void poly_from_sk(poly *P, const sk_frustum *f) {
    dv3 c[8];
    int i;
    for (i = 0; i < 8; i++) c[i] = tod(f->corners[i]);
    poly_from_corners(P, c);
}
/* builds the library's frustum from corners (rounded to float), and the
   oracle's polytope from exactly those float corners */
static void make_frustum(const dv3 c[8], sk_frustum *f, poly *P) {
    int i;
    for (i = 0; i < 8; i++) f->corners[i] = tof(c[i]);
    poly_from_sk(P, f);
    for (i = 0; i < 6; i++) {
        f->planes[i].n = tof(P->n[i]);
        f->planes[i].d = (float)P->d[i];
    }
}
static void box_corners(dv3 mn, dv3 mx, dv3 c[8]) {
    int i;
    for (i = 0; i < 8; i++)
        c[i] = d3((i & 1) ? mx.x : mn.x, (i & 2) ? mx.y : mn.y, (i & 4) ? mx.z : mn.z);
}
static void make_box_frustum(dv3 mn, dv3 mx, sk_frustum *f, poly *P) {
    dv3 c[8];
    box_corners(mn, mx, c);
    make_frustum(c, f, P);
}
static int poly_contains(const poly *P, dv3 p, double margin) {
    int k;
    for (k = 0; k < 6; k++) if (ddot(P->n[k], p) + P->d[k] < margin) return 0;
    return 1;
}
/* trilinear point of the hexahedron (inside it for a,b,c in [0,1]) */
static dv3 poly_sample(const poly *P, double a, double b, double c) {
    dv3 x00 = dlerp(P->c[0], P->c[1], a), x10 = dlerp(P->c[2], P->c[3], a);
    dv3 x01 = dlerp(P->c[4], P->c[5], a), x11 = dlerp(P->c[6], P->c[7], a);
    return dlerp(dlerp(x00, x10, b), dlerp(x01, x11, b), c);
}
static dv3 poly_sample_rnd(const poly *P) {
    return poly_sample(P, rndr(0.001, 0.999), rndr(0.001, 0.999), rndr(0.001, 0.999));
}
/* Sutherland-Hodgman: keeps dot(n,p) + d >= margin */
static int clip_polygon(const dv3 *in, int n, dv3 nrm, double d, double margin, dv3 *out) {
    int i, m = 0;
    for (i = 0; i < n; i++) {
        dv3 a = in[i], b = in[(i + 1) % n];
        double da = ddot(nrm, a) + d - margin, db = ddot(nrm, b) + d - margin;
        if (da >= 0) out[m++] = a;
        if ((da >= 0) != (db >= 0)) out[m++] = dlerp(a, b, da / (da - db));
    }
    return m;
}
/* 1 if some point of a face of A lies inside B by at least margin */
static int poly_faces_in(const poly *A, const poly *B, double margin) {
    int k, j, i;
    for (k = 0; k < 6; k++) {
        dv3 buf[2][32];
        int n = 4, cur = 0;
        for (i = 0; i < 4; i++) buf[0][i] = A->c[face_quads[k][i]];
        for (j = 0; j < 6 && n > 0; j++) {
            n = clip_polygon(buf[cur], n, B->n[j], B->d[j], margin, buf[cur ^ 1]);
            cur ^= 1;
        }
        if (n > 0) return 1;
    }
    return 0;
}
/* exact test (up to margin) that two convex hexahedra share a point: if they
   do, a face of one meets the other (or one contains the other, whose faces
   then lie inside) */
static int poly_intersect_oracle(const poly *A, const poly *B, double margin) {
    return poly_faces_in(A, B, margin) || poly_faces_in(B, A, margin);
}
/* random points inside A that are inside B (both by margin) */
static int poly_sample_oracle(const poly *A, const poly *B, int samples, double margin) {
    int i;
    for (i = 0; i < samples; i++) {
        dv3 p = poly_sample_rnd(A);
        if (poly_contains(A, p, margin) && poly_contains(B, p, margin)) return 1;
        p = poly_sample_rnd(B);
        if (poly_contains(A, p, margin) && poly_contains(B, p, margin)) return 1;
    }
    return 0;
}
/* bounding spheres apart with a gap: no corner of one can be inside the
   other and no edge of one can cross the other (HalfIntersection says no) */
static int sphere_separated(const poly *A, const poly *B, double gap) {
    return dlen(dsub(A->g, B->g)) > (A->radius + B->radius) * (1.0 + gap);
}

/* perspective frustum from parameters: apex eye, orthonormal f (forward),
   r (right), u (up); lateral extent tx*d, ty*d at depth d in [zn, zf] */
typedef struct pfr { dv3 eye, f, r, u; double tx, ty, zn, zf; } pfr;
static void basis_from_forward(dv3 f, dv3 *r, dv3 *u) {
    dv3 helper = fabs(f.y) < 0.9 ? d3(0, 1, 0) : d3(1, 0, 0);
    *r = dnorm(dcross(f, helper));
    *u = dcross(*r, f);
}
static void pfr_corners(const pfr *p, dv3 c[8]) {
    int i;
    for (i = 0; i < 8; i++) {
        double sx = (i & 1) ? 1.0 : -1.0, sy = (i & 2) ? 1.0 : -1.0;
        double d = (i & 4) ? p->zf : p->zn;
        c[i] = dadd(p->eye, dadd(dmul(p->f, d), dadd(dmul(p->r, sx * p->tx * d), dmul(p->u, sy * p->ty * d))));
    }
}
static void make_pfr_frustum(const pfr *p, sk_frustum *f, poly *P) {
    dv3 c[8];
    pfr_corners(p, c);
    make_frustum(c, f, P);
}
static void pfr_random(pfr *p, double pos_extent) {
    p->eye = rnd_in_box(pos_extent);
    p->f = rnd_unit();
    basis_from_forward(p->f, &p->r, &p->u);
    p->tx = rndr(0.2, 1.5);
    p->ty = rndr(0.2, 1.5);
    p->zn = rndr(0.05, 2.0);
    p->zf = p->zn + rndr(1.0, 25.0);
}
/* the volume rendered into cube face f: apex at the light, 90 degrees */
static void face_pfr(int f, dv3 light, double zn, double zf, pfr *p) {
    p->eye = light;
    p->f = face_axis(f);
    basis_from_forward(p->f, &p->r, &p->u);
    p->tx = p->ty = 1.0;
    p->zn = zn;
    p->zf = zf;
}

/* ============================================ cube face view / projection */
static void test_cube_face_proj_matrix(void) {
    static const float zz[][2] = { { 0.1f, 100.0f }, { 0.5f, 50.0f }, { 1e-3f, 1e6f },
                                   { 2.0f, 2.5f }, { 1.0f, 3.0f } };
    static const float bad[][2] = { { 0.0f, 1.0f }, { -1.0f, 1.0f }, { 1.0f, 1.0f }, { 2.0f, 1.0f },
                                    { -2.0f, -1.0f } };
    float nan = NAN, inf = INFINITY;
    sk_mat4 m;
    int i, k;
    for (i = 0; i < (int)(sizeof zz / sizeof zz[0]); i++) {
        double zn = zz[i][0], zf = zz[i][1], e[16];
        m = sk_cube_face_proj(zz[i][0], zz[i][1]);
        /* gluPerspective(90 deg, 1, zn, zf): cot(45 deg) = 1 */
        for (k = 0; k < 16; k++) e[k] = 0;
        e[0] = 1; e[5] = 1; e[10] = -(zf + zn) / (zf - zn); e[11] = -1;
        e[14] = -2.0 * zf * zn / (zf - zn);
        for (k = 0; k < 16; k++)
            SK_CHECK_NEAR(m.m[k], e[k], 2e-6 * dmax(1.0, fabs(e[k])));
        /* w = eye depth: a point at eye depth 7 (z_eye = -7) has clip w = 7 */
        SK_CHECK_NEAR(-(double)m.m[11] * 1.0, 1.0, 0);
        /* window depth at MA = zn is 0 and at MA = zf is 1 */
        SK_CHECK_NEAR(0.5 * (m.m[10] * -zn + m.m[14]) / zn + 0.5, 0.0, 1e-5);
        SK_CHECK_NEAR(0.5 * (m.m[10] * -zf + m.m[14]) / zf + 0.5, 1.0, 1e-5);
    }
    /* bad input: the identity */
    for (i = 0; i < (int)(sizeof bad / sizeof bad[0]); i++) {
        m = sk_cube_face_proj(bad[i][0], bad[i][1]);
        SK_CHECK_MSG(mat_is_identity(&m), "sk_cube_face_proj(%g, %g) is not the identity",
                     bad[i][0], bad[i][1]);
    }
    m = sk_cube_face_proj(nan, 10.0f); SK_CHECK(mat_is_identity(&m));
    m = sk_cube_face_proj(0.1f, nan);  SK_CHECK(mat_is_identity(&m));
    m = sk_cube_face_proj(nan, nan);   SK_CHECK(mat_is_identity(&m));
    m = sk_cube_face_proj(-inf, 10.0f); SK_CHECK(mat_is_identity(&m));
    m = sk_cube_face_proj(inf, inf);   SK_CHECK(mat_is_identity(&m));
    m = sk_cube_face_proj(0.1f, -inf); SK_CHECK(mat_is_identity(&m));
    /* zf = +Inf: non-finite, so the identity under the library's conventions;
       the infinite-far projection (m10 = -1, m14 = -2 zn) would also be a
       sensible answer. Either way: finite. */
    m = sk_cube_face_proj(0.1f, inf);
    SK_CHECK(mat_finite(&m));
    SK_CHECK_MSG(mat_is_identity(&m) || (m.m[10] == -1.0f && fabs(m.m[14] + 0.2) < 1e-6),
                 "sk_cube_face_proj(0.1, inf): m10 = %g, m14 = %g", m.m[10], m.m[14]);
}

static void test_cube_face_view_rigid(void) {
    static const double lights[][3] = { { 0, 0, 0 }, { 3, -2, 5 }, { -100, 50, 20.5 } };
    int li, f, i, j;
    for (li = 0; li < 3; li++) {
        dv3 L = d3(lights[li][0], lights[li][1], lights[li][2]);
        for (f = 0; f < 6; f++) {
            sk_mat4 v = sk_cube_face_view(f, tof(L));
            double o[4], det;
            int orth = 1;
            SK_CHECK(mat_finite(&v));
            /* light at the eye */
            mat_point(&v, L, o);
            SK_CHECK_NEAR(o[0], 0, 2e-5 * (1 + dlen(L)));
            SK_CHECK_NEAR(o[1], 0, 2e-5 * (1 + dlen(L)));
            SK_CHECK_NEAR(o[2], 0, 2e-5 * (1 + dlen(L)));
            SK_CHECK_NEAR(o[3], 1, 0);
            /* bottom row (0,0,0,1), rotation orthonormal with det +1 */
            SK_CHECK(v.m[3] == 0 && v.m[7] == 0 && v.m[11] == 0 && v.m[15] == 1);
            for (i = 0; i < 3; i++)
                for (j = 0; j < 3; j++) {
                    double dot = v.m[i * 4 + 0] * v.m[j * 4 + 0] + v.m[i * 4 + 1] * v.m[j * 4 + 1] +
                                 v.m[i * 4 + 2] * v.m[j * 4 + 2];
                    if (fabs(dot - (i == j ? 1.0 : 0.0)) > 1e-6) orth = 0;
                }
            SK_CHECK_MSG(orth, "face %d view rotation not orthonormal", f);
            det = v.m[0] * (v.m[5] * v.m[10] - v.m[9] * v.m[6]) - v.m[4] * (v.m[1] * v.m[10] - v.m[9] * v.m[2]) +
                  v.m[8] * (v.m[1] * v.m[6] - v.m[5] * v.m[2]);
            SK_CHECK_NEAR(det, 1.0, 1e-5);
            /* the face's axis is the view direction (eye -z) */
            {
                dv3 a = face_axis(f);
                double e[4];
                mat_point(&v, dadd(L, a), e);
                SK_CHECK_NEAR(e[2], -1.0, 1e-4);
                SK_CHECK_NEAR(e[0], 0.0, 1e-4);
                SK_CHECK_NEAR(e[1], 0.0, 1e-4);
            }
        }
        /* face outside [0,5]: the +X face */
        {
            static const int badf[] = { -1, 6, 7, 100, INT_MIN, INT_MAX };
            sk_mat4 v0 = sk_cube_face_view(0, tof(L));
            for (i = 0; i < (int)(sizeof badf / sizeof badf[0]); i++) {
                sk_mat4 vb = sk_cube_face_view(badf[i], tof(L));
                SK_CHECK_MSG(mat_same(&vb, &v0), "sk_cube_face_view(%d) is not the +X face", badf[i]);
            }
        }
    }
    /* non-finite light position: no documented fallback, but the library
       promises no function returns NaN */
    {
        float nan = NAN, inf = INFINITY;
        for (f = 0; f < 6; f++) {
            sk_mat4 v = sk_cube_face_view(f, v3(nan, 0, 0));
            SK_CHECK_MSG(mat_finite(&v), "sk_cube_face_view(%d, (NaN,0,0)) has non-finite entries", f);
            v = sk_cube_face_view(f, v3(0, inf, -inf));
            SK_CHECK_MSG(mat_finite(&v), "sk_cube_face_view(%d, (0,Inf,-Inf)) has non-finite entries", f);
        }
    }
}

/* proj * view of the face the GL table selects maps light_pos + d to NDC
   (2s-1, 2t-1), in front, w = MA, window depth = Eq. 5.4.6 */
static void test_cube_face_table(void) {
    static const double lights[][3] = { { 0, 0, 0 }, { 3, -2, 5 }, { -100, 50, 20.5 } };
    static const float zz[][2] = { { 0.25f, 40.0f }, { 0.05f, 1000.0f } };
    int li, zi, it;
    rng_seed(1);
    for (zi = 0; zi < 2; zi++) {
        float znf = zz[zi][0], zff = zz[zi][1];
        double zn = znf, zf = zff;
        sk_mat4 P = sk_cube_face_proj(znf, zff);
        float sc = 0, bi = 0;
        sk_vsdct_depth_coeffs(znf, zff, &sc, &bi);
        for (li = 0; li < 3; li++) {
            dv3 L0 = d3(lights[li][0], lights[li][1], lights[li][2]);
            sk_vec3 Lf = tof(L0);
            dv3 L = tod(Lf);
            int bad_ndc = 0, bad_w = 0, bad_z = 0, bad_coeff = 0, n = 0;
            for (it = 0; it < 3000; it++) {
                dv3 d = rnd_unit(), r;
                double target = exp(rndr(log(zn * 1.02), log(zf * 0.98)));
                double ma0 = dmax(fabs(d.x), dmax(fabs(d.y), fabs(d.z)));
                sk_vec3 pf;
                double s, t, ma, e[4], c[4], ndcx, ndcy, zwin, zexp, tol;
                int f;
                sk_mat4 V;
                d = dmul(d, target / ma0);
                pf = tof(dadd(L, d));
                r = dsub(tod(pf), L);               /* the exact light-to-point vector */
                f = table_face(r);
                face_st(f, r, &s, &t, &ma);
                V = sk_cube_face_view(f, Lf);
                mat_point(&V, tod(pf), e);
                mat_apply(&P, e, c);
                n++;
                tol = 1e-5 + 5e-7 * (dlen(L) + ma) / ma;
                if (!(c[3] > 0)) { bad_w++; continue; }
                ndcx = c[0] / c[3];
                ndcy = c[1] / c[3];
                if (fabs(ndcx - (2 * s - 1)) > tol || fabs(ndcy - (2 * t - 1)) > tol) {
                    if (!bad_ndc)
                        printf("  face %d dir (%g,%g,%g): ndc (%.7f,%.7f), table (%.7f,%.7f)\n", f, r.x,
                               r.y, r.z, ndcx, ndcy, 2 * s - 1, 2 * t - 1);
                    bad_ndc++;
                }
                if (fabs(c[3] - ma) > tol * ma) bad_w++;
                zwin = 0.5 * c[2] / c[3] + 0.5;
                zexp = zf / (zf - zn) - zf * zn / ((zf - zn) * ma);     /* Eq. 5.4.6 */
                if (fabs(zwin - zexp) > tol * 4 + 2e-6 * zf / zn * tol) {
                    if (!bad_z) printf("  face %d MA %g: window depth %.9f, Eq. 5.4.6 %.9f\n", f, ma, zwin, zexp);
                    bad_z++;
                }
                if (fabs((double)sc / ma + (double)bi - zexp) > 1e-5) bad_coeff++;
            }
            SK_CHECK_MSG(bad_ndc == 0, "light %d z %d: %d of %d points off the GL face table", li, zi, bad_ndc, n);
            SK_CHECK_MSG(bad_w == 0, "light %d z %d: %d of %d points with clip w != MA", li, zi, bad_w, n);
            SK_CHECK_MSG(bad_z == 0, "light %d z %d: %d of %d window depths != Eq. 5.4.6", li, zi, bad_z, n);
            SK_CHECK_MSG(bad_coeff == 0, "light %d z %d: %d of %d scale/MA+bias != Eq. 5.4.6", li, zi,
                         bad_coeff, n);
        }
    }
}

static void test_vsdct_depth_coeffs(void) {
    static const float zz[][2] = { { 0.1f, 100.0f }, { 1.0f, 2.0f }, { 0.5f, 50.0f },
                                   { 1e-3f, 1e6f }, { 3.0f, 3.0001f } };
    float nan = NAN, inf = INFINITY;
    int i;
    for (i = 0; i < (int)(sizeof zz / sizeof zz[0]); i++) {
        double zn = zz[i][0], zf = zz[i][1];
        double es = -zf * zn / (zf - zn), eb = zf / (zf - zn);      /* Eq. 5.4.6 */
        float s = 7, b = 7;
        sk_vsdct_depth_coeffs(zz[i][0], zz[i][1], &s, &b);
        SK_CHECK_NEAR(s, es, 2e-6 * fabs(es) + 1e-7);
        SK_CHECK_NEAR(b, eb, 2e-6 * fabs(eb) + 1e-7);
        if (zf / zn < 1e4) {
            SK_CHECK_NEAR((double)s / zn + b, 0.0, 1e-4 * eb);
            SK_CHECK_NEAR((double)s / zf + b, 1.0, 1e-4 * eb);
        }
    }
    /* hand example: zn 1, zf 3 -> scale -1.5, bias 1.5; MA 2 -> 0.75 */
    {
        float s = 0, b = 0;
        sk_vsdct_depth_coeffs(1.0f, 3.0f, &s, &b);
        SK_CHECK_NEAR(s, -1.5, 1e-6);
        SK_CHECK_NEAR(b, 1.5, 1e-6);
        SK_CHECK_NEAR(s / 2.0f + b, 0.75, 1e-6);
    }
    /* bad input: scale 0, bias 1 */
    {
        static const float bad[][2] = { { 0.0f, 1.0f }, { -1.0f, 10.0f }, { 1.0f, 1.0f }, { 2.0f, 1.0f } };
        for (i = 0; i < (int)(sizeof bad / sizeof bad[0]); i++) {
            float s = 7, b = 7;
            sk_vsdct_depth_coeffs(bad[i][0], bad[i][1], &s, &b);
            SK_CHECK_MSG(s == 0.0f && b == 1.0f, "depth_coeffs(%g,%g) -> %g, %g; expected 0, 1",
                         bad[i][0], bad[i][1], s, b);
        }
        {
            float s = 7, b = 7;
            sk_vsdct_depth_coeffs(nan, 10.0f, &s, &b); SK_CHECK(s == 0.0f && b == 1.0f);
            s = 7; b = 7;
            sk_vsdct_depth_coeffs(0.1f, nan, &s, &b); SK_CHECK(s == 0.0f && b == 1.0f);
            s = 7; b = 7;
            sk_vsdct_depth_coeffs(inf, inf, &s, &b); SK_CHECK(s == 0.0f && b == 1.0f);
            s = 7; b = 7;
            sk_vsdct_depth_coeffs(-inf, 1.0f, &s, &b); SK_CHECK(s == 0.0f && b == 1.0f);
            /* zf = +Inf: bad (non-finite) -> (0, 1), or the limit (-zn, 1) */
            s = 7; b = 7;
            sk_vsdct_depth_coeffs(0.5f, inf, &s, &b);
            SK_CHECK_MSG((s == 0.0f && b == 1.0f) || (fabs(s + 0.5) < 1e-6 && b == 1.0f),
                         "depth_coeffs(0.5, inf) -> %g, %g", s, b);
        }
        /* NULL outputs: no crash */
        {
            float s = 7, b = 7;
            sk_vsdct_depth_coeffs(0.1f, 10.0f, NULL, &b);
            sk_vsdct_depth_coeffs(0.1f, 10.0f, &s, NULL);
            sk_vsdct_depth_coeffs(0.1f, 10.0f, NULL, NULL);
            SK_CHECK(isfinite(s) && isfinite(b));
        }
    }
}

/* ================================================== frustum intersection */
static void test_frustum_intersects_cases(void) {
    sk_frustum A, B, Z;
    poly PA, PB;
    int r1, r2;
    make_box_frustum(d3(0, 0, 0), d3(1, 1, 1), &A, &PA);

#define BOTH(expect, msg) do { r1 = sk_frustum_intersects(&A, &B); r2 = sk_frustum_intersects(&B, &A); \
        SK_CHECK_MSG(r1 == (expect) && r2 == (expect), "%s: got %d,%d expected %d", msg, r1, r2, expect); } while (0)
    make_box_frustum(d3(5, 0, 0), d3(6, 1, 1), &B, &PB);      BOTH(1 - 1, "far apart boxes");
    make_box_frustum(d3(0, 0, 30), d3(1, 1, 31), &B, &PB);    BOTH(0, "far apart boxes (z)");
    make_box_frustum(d3(1, 0, 0), d3(2, 1, 1), &B, &PB);      BOTH(1, "boxes sharing a face");
    make_box_frustum(d3(1, 1, 0), d3(2, 2, 1), &B, &PB);      BOTH(1, "boxes sharing an edge");
    make_box_frustum(d3(1, 1, 1), d3(2, 2, 2), &B, &PB);      BOTH(1, "boxes sharing a corner");
    make_box_frustum(d3(0.5, 0.5, 0.5), d3(1.5, 1.5, 1.5), &B, &PB); BOTH(1, "overlapping boxes");
    make_box_frustum(d3(0.25, 0.25, 0.25), d3(0.75, 0.75, 0.75), &B, &PB); BOTH(1, "box inside box");
    make_box_frustum(d3(0, 0, 0), d3(1, 1, 1), &B, &PB);      BOTH(1, "identical boxes");
    make_box_frustum(d3(-10, -10, -10), d3(10, 10, 10), &B, &PB); BOTH(1, "box around box");
    /* a one-ulp gap (float rounding) counts as touching */
    make_box_frustum(d3(nextafterf(1.0f, 2.0f), 0, 0), d3(2, 1, 1), &B, &PB); BOTH(1, "boxes 1 ulp apart");
    /* plus sign: no corner of either is inside the other, only edges cross */
    make_box_frustum(d3(-10, -1, -1), d3(10, 1, 1), &A, &PA);
    make_box_frustum(d3(-1, -10, -0.5), d3(1, 10, 0.5), &B, &PB); BOTH(1, "crossing bars");
    /* frustum pierced by a bar: no corner inside either, edges of the bar cross */
    {
        pfr p;
        p.eye = d3(0, 0, 0); p.f = d3(0, 0, 1); p.r = d3(1, 0, 0); p.u = d3(0, 1, 0);
        p.tx = p.ty = 1; p.zn = 0.1; p.zf = 10;
        make_pfr_frustum(&p, &A, &PA);
        make_box_frustum(d3(-20, -0.1, 4), d3(20, 0.1, 5), &B, &PB); BOTH(1, "frustum pierced by a bar");
        /* bar behind the apex, far away */
        make_box_frustum(d3(-3, -0.1, -40), d3(3, 0.1, -39), &B, &PB); BOTH(0, "bar far behind the apex");
        /* a second frustum whose apex region overlaps */
        {
            pfr q = p;
            q.eye = d3(0, 0, 9); q.f = d3(0, 0, -1); q.r = d3(-1, 0, 0);
            make_pfr_frustum(&q, &B, &PB); BOTH(1, "opposed frusta");
        }
    }
    /* invalid frusta intersect everything (conservative), both orders */
    memset(&Z, 0, sizeof Z);
    make_box_frustum(d3(0, 0, 0), d3(1, 1, 1), &A, &PA);
    SK_CHECK(sk_frustum_intersects(&A, &Z) == 1);
    SK_CHECK(sk_frustum_intersects(&Z, &A) == 1);
    SK_CHECK(sk_frustum_intersects(&Z, &Z) == 1);
    {
        sk_frustum N = A;
        float nan = NAN;
        make_box_frustum(d3(50, 50, 50), d3(51, 51, 51), &B, &PB);
        N.corners[3].x = nan;
        N.planes[1].d = nan;
        SK_CHECK_MSG(sk_frustum_intersects(&N, &B) == 1, "frustum with NaN: not conservative");
        SK_CHECK_MSG(sk_frustum_intersects(&B, &N) == 1, "frustum with NaN: not conservative");
    }
    /* NULL: nothing to judge -> conservative 1, no crash */
    SK_CHECK(sk_frustum_intersects(NULL, &A) == 1);
    SK_CHECK(sk_frustum_intersects(&A, NULL) == 1);
    SK_CHECK(sk_frustum_intersects(NULL, NULL) == 1);
#undef BOTH
}

static void test_frustum_intersects_random(void) {
    int it, n = 600, n_pos = 0, n_sep = 0, miss = 0, asym = 0, sep_bad = 0;
    rng_seed(2);
    for (it = 0; it < n; it++) {
        sk_frustum A, B;
        poly PA, PB;
        pfr pa, pb;
        int r1, r2, pos, sep;
        double margin;
        pfr_random(&pa, 12.0);
        if (it % 4 == 3) {            /* some boxes too */
            dv3 c = rnd_in_box(12.0), h = d3(rndr(0.1, 6), rndr(0.1, 6), rndr(0.1, 6));
            make_box_frustum(dsub(c, h), dadd(c, h), &B, &PB);
        } else {
            pfr_random(&pb, 12.0);
            if (it % 3 == 1) { pb.tx *= 0.1; pb.zf = pb.zn + 40; }   /* long thin ones */
            make_pfr_frustum(&pb, &B, &PB);
        }
        make_pfr_frustum(&pa, &A, &PA);
        r1 = sk_frustum_intersects(&A, &B);
        r2 = sk_frustum_intersects(&B, &A);
        margin = 1e-6 * dmax(PA.radius, PB.radius);
        pos = poly_intersect_oracle(&PA, &PB, margin) || poly_sample_oracle(&PA, &PB, 300, margin);
        sep = sphere_separated(&PA, &PB, 0.01);
        n_pos += pos;
        n_sep += sep;
        if (r1 != r2) asym++;
        if (pos && !(r1 && r2)) {
            if (!miss) printf("  missed intersection at pair %d (got %d,%d)\n", it, r1, r2);
            miss++;
        }
        if (sep && (r1 || r2)) {
            if (!sep_bad) printf("  pair %d: bounding spheres apart but reported intersecting\n", it);
            sep_bad++;
        }
    }
    SK_CHECK_MSG(miss == 0, "%d of %d intersecting pairs missed (must be conservative)", miss, n_pos);
    SK_CHECK_MSG(asym == 0, "%d of %d pairs: result depends on argument order", asym, n);
    SK_CHECK_MSG(sep_bad == 0, "%d of %d clearly separated pairs reported intersecting", sep_bad, n_sep);
    /* the generator produced both kinds (the test can fail either way) */
    SK_CHECK(n_pos > 50);
    SK_CHECK(n_sep > 50);
}

/* ==================================================== cube face culling */
static unsigned visible_faces_oracle_check(dv3 L, double zn, double zf, const sk_frustum *view,
                                           const poly *PV, unsigned mask, int *bad_need, int *bad_sep) {
    int f;
    unsigned need = 0;
    for (f = 0; f < 6; f++) {
        pfr p;
        sk_frustum F;
        poly PF;
        double margin;
        face_pfr(f, L, zn, zf, &p);
        make_pfr_frustum(&p, &F, &PF);
        margin = 1e-6 * dmax(PF.radius, PV->radius);
        if (poly_intersect_oracle(&PF, PV, margin) || poly_sample_oracle(&PF, PV, 100, margin)) {
            need |= 1u << f;
            if (!(mask & (1u << f))) (*bad_need)++;
        }
        if (sphere_separated(&PF, PV, 0.01) && (mask & (1u << f))) (*bad_sep)++;
    }
    (void)view;
    return need;
}

static void test_cube_visible_faces(void) {
    int it, bad_need = 0, bad_sep = 0, bad_bits = 0, culled = 0, n = 300;
    float nan = NAN, inf = INFINITY;
    rng_seed(3);
    /* light inside the view frustum: every face is visible */
    for (it = 0; it < 50; it++) {
        pfr p;
        sk_frustum V;
        poly PV;
        dv3 L;
        unsigned m;
        pfr_random(&p, 20.0);
        make_pfr_frustum(&p, &V, &PV);
        L = dadd(p.eye, dadd(dmul(p.f, 0.5 * (p.zn + p.zf)),
                             dadd(dmul(p.r, rndr(-0.5, 0.5) * p.tx * p.zn), dmul(p.u, rndr(-0.5, 0.5) * p.ty * p.zn))));
        m = sk_cube_visible_faces(tof(L), 0.05f, (float)rndr(1, 50), &V);
        SK_CHECK_MSG(m == 0x3fu, "light inside the view frustum: faces 0x%x, expected 0x3f", m);
    }
    /* light far behind the camera, which looks away: at least one face culled,
       the face looking at the view frustum (-Z) kept */
    {
        pfr p;
        sk_frustum V;
        poly PV;
        unsigned m;
        int bn = 0, bs = 0;
        p.eye = d3(0, 0, 0); p.f = d3(0, 0, -1); p.r = d3(1, 0, 0); p.u = d3(0, 1, 0);
        p.tx = p.ty = 1; p.zn = 0.1; p.zf = 50;
        make_pfr_frustum(&p, &V, &PV);
        m = sk_cube_visible_faces(v3(0, 0, 100), 0.1f, 200.0f, &V);
        SK_CHECK_MSG(m != 0x3fu, "light far behind the camera: no face culled (0x%x)", m);
        SK_CHECK_MSG(m & (1u << 5), "light far behind the camera: the -Z face is culled (0x%x)", m);
        visible_faces_oracle_check(d3(0, 0, 100), 0.1, 200.0, &V, &PV, m, &bn, &bs);
        SK_CHECK(bn == 0);
        /* the same, the light off to one side and above */
        m = sk_cube_visible_faces(v3(30, 40, 120), 0.1f, 300.0f, &V);
        SK_CHECK_MSG(m != 0x3fu, "light behind (offset): no face culled (0x%x)", m);
        visible_faces_oracle_check(d3(30, 40, 120), 0.1, 300.0, &V, &PV, m, &bn, &bs);
        SK_CHECK(bn == 0);
        /* light range too short to reach the view frustum at all */
        m = sk_cube_visible_faces(v3(0, 0, 100), 0.1f, 20.0f, &V);
        SK_CHECK_MSG(m == 0u, "light range 20 at distance 100: faces 0x%x, expected none", m);
    }
    /* random configurations: every face the oracle needs is set; a face whose
       frustum is clearly apart from the view frustum is clear */
    for (it = 0; it < n; it++) {
        pfr p;
        sk_frustum V;
        poly PV;
        dv3 L = rnd_in_box(25.0);
        float zn = (float)rndr(0.05, 1.0), zf = (float)rndr(3.0, 30.0);
        unsigned m;
        pfr_random(&p, 25.0);
        if (it % 5 == 0) p.eye = dadd(L, dmul(rnd_unit(), rndr(0, zf)));  /* camera inside the light range */
        make_pfr_frustum(&p, &V, &PV);
        m = sk_cube_visible_faces(tof(L), zn, zf, &V);
        if (m & ~0x3fu) bad_bits++;
        if (m != 0x3fu) culled++;
        visible_faces_oracle_check(tod(tof(L)), zn, zf, &V, &PV, m, &bad_need, &bad_sep);
    }
    SK_CHECK_MSG(bad_need == 0, "%d faces that intersect the view frustum were culled", bad_need);
    SK_CHECK_MSG(bad_sep == 0, "%d faces clearly apart from the view frustum were kept", bad_sep);
    SK_CHECK_MSG(bad_bits == 0, "%d masks with bits above 0x3f", bad_bits);
    SK_CHECK(culled > 20);
    /* camera exactly at the light (stability) */
    {
        pfr p;
        sk_frustum V;
        poly PV;
        unsigned m;
        int bn = 0, bs = 0;
        p.eye = d3(1, 2, 3); p.f = dnorm(d3(1, -0.3, 0.2));
        basis_from_forward(p.f, &p.r, &p.u);
        p.tx = 1.2; p.ty = 0.8; p.zn = 0.1; p.zf = 100;
        make_pfr_frustum(&p, &V, &PV);
        m = sk_cube_visible_faces(tof(p.eye), 0.1f, 25.0f, &V);
        SK_CHECK(m <= 0x3fu && (m & 1u));
        visible_faces_oracle_check(tod(tof(p.eye)), 0.1, 25.0, &V, &PV, m, &bn, &bs);
        SK_CHECK(bn == 0);
    }
    /* bad input: all six faces */
    {
        sk_frustum V, Z;
        poly PV;
        make_box_frustum(d3(-1, -1, -1), d3(1, 1, 1), &V, &PV);
        memset(&Z, 0, sizeof Z);
        SK_CHECK(sk_cube_visible_faces(v3(0, 0, 50), 0.0f, 10.0f, &V) == 0x3fu);
        SK_CHECK(sk_cube_visible_faces(v3(0, 0, 50), -1.0f, 10.0f, &V) == 0x3fu);
        SK_CHECK(sk_cube_visible_faces(v3(0, 0, 50), 10.0f, 10.0f, &V) == 0x3fu);
        SK_CHECK(sk_cube_visible_faces(v3(0, 0, 50), 10.0f, 1.0f, &V) == 0x3fu);
        SK_CHECK(sk_cube_visible_faces(v3(0, 0, 50), nan, 10.0f, &V) == 0x3fu);
        SK_CHECK(sk_cube_visible_faces(v3(0, 0, 50), 0.1f, nan, &V) == 0x3fu);
        SK_CHECK(sk_cube_visible_faces(v3(0, 0, 50), 0.1f, inf, &V) == 0x3fu);
        SK_CHECK(sk_cube_visible_faces(v3(0, 0, 50), -inf, 10.0f, &V) == 0x3fu);
        SK_CHECK(sk_cube_visible_faces(v3(0, 0, 50), 0.1f, 10.0f, NULL) == 0x3fu);
        SK_CHECK(sk_cube_visible_faces(v3(nan, 0, 50), 0.1f, 10.0f, &V) == 0x3fu);
        SK_CHECK(sk_cube_visible_faces(v3(0, inf, 50), 0.1f, 10.0f, &V) == 0x3fu);
        SK_CHECK(sk_cube_visible_faces(v3(0, 0, 50), 0.1f, 10.0f, &Z) == 0x3fu);
    }
}

/* ======================================================== caster culling */
static int seg_hits_box(dv3 a, dv3 b, dv3 mn, dv3 mx) {
    double t0 = 0, t1 = 1, pa[3], pd[3], lo[3], hi[3];
    int k;
    pa[0] = a.x; pa[1] = a.y; pa[2] = a.z;
    pd[0] = b.x - a.x; pd[1] = b.y - a.y; pd[2] = b.z - a.z;
    lo[0] = mn.x; lo[1] = mn.y; lo[2] = mn.z;
    hi[0] = mx.x; hi[1] = mx.y; hi[2] = mx.z;
    for (k = 0; k < 3; k++) {
        if (fabs(pd[k]) < 1e-300) {
            if (pa[k] < lo[k] || pa[k] > hi[k]) return 0;
        } else {
            double ta = (lo[k] - pa[k]) / pd[k], tb = (hi[k] - pa[k]) / pd[k];
            if (ta > tb) { double tmp = ta; ta = tb; tb = tmp; }
            t0 = dmax(t0, ta);
            t1 = dmin(t1, tb);
            if (t0 > t1) return 0;
        }
    }
    return 1;
}
static double box_dist(dv3 p, dv3 mn, dv3 mx) {
    dv3 q = d3(dclamp(p.x, mn.x, mx.x), dclamp(p.y, mn.y, mx.y), dclamp(p.z, mn.z, mx.z));
    return dlen(dsub(p, q));
}
static int in_box(dv3 p, dv3 mn, dv3 mx) {
    return p.x >= mn.x && p.x <= mx.x && p.y >= mn.y && p.y <= mx.y && p.z >= mn.z && p.z <= mx.z;
}
/* does the shadow of [mn,mx] (cast by L, up to range) reach a point of the
   view polytope? Points of the view whose segment to the light crosses the
   (slightly shrunk) box, and points of the shadow volume inside the view. */
static int shadow_reaches(dv3 L, double range, dv3 mn, dv3 mx, const poly *PV, int samples) {
    dv3 smn, smx;
    double e = 1e-4, margin = 1e-6 * PV->radius;
    int i;
    smn = d3(mn.x + dmin(e, 0.5 * (mx.x - mn.x)), mn.y + dmin(e, 0.5 * (mx.y - mn.y)), mn.z + dmin(e, 0.5 * (mx.z - mn.z)));
    smx = d3(mx.x - dmin(e, 0.5 * (mx.x - mn.x)), mx.y - dmin(e, 0.5 * (mx.y - mn.y)), mx.z - dmin(e, 0.5 * (mx.z - mn.z)));
    for (i = 0; i < samples; i++) {
        dv3 q = poly_sample_rnd(PV);
        if (dlen(dsub(q, L)) <= range * (1 - 1e-6) && poly_contains(PV, q, margin) && seg_hits_box(L, q, smn, smx))
            return 1;
    }
    for (i = 0; i < samples; i++) {
        dv3 b = d3(rndr(smn.x, smx.x), rndr(smn.y, smx.y), rndr(smn.z, smx.z)), q;
        double dist = dlen(dsub(b, L));
        if (dist >= range * (1 - 1e-6)) continue;
        q = dadd(L, dmul(dsub(b, L), dist > 0 ? rndr(1.0, range * (1 - 1e-6) / dist) : 1.0));
        if (poly_contains(PV, q, margin)) return 1;
    }
    return 0;
}

static void check_range_box(const sk_frustum *f, dv3 L, double range, const char *what) {
    int i, bad = 0;
    for (i = 0; i < 8; i++) {
        dv3 e = d3(L.x + ((i & 1) ? range : -range), L.y + ((i & 2) ? range : -range), L.z + ((i & 4) ? range : -range));
        if (dlen(dsub(tod(f->corners[i]), e)) > 1e-5 * (range + dlen(L))) bad++;
    }
    SK_CHECK_MSG(bad == 0, "%s: %d corners differ from the light-range box", what, bad);
}
/* shadow points of the box must satisfy the frustum's planes and lie in the
   hexahedron of its corners */
static int shadow_contained(const sk_frustum *f, dv3 L, double range, dv3 mn, dv3 mx, int samples) {
    poly P;
    int i, k, bad = 0;
    double tol = 1e-4 * (range + dlen(dsub(mx, mn)));
    poly_from_sk(&P, f);
    for (i = 0; i < samples; i++) {
        dv3 b, q;
        double dist;
        if (i < 8) b = d3((i & 1) ? mx.x : mn.x, (i & 2) ? mx.y : mn.y, (i & 4) ? mx.z : mn.z);
        else b = d3(rndr(mn.x, mx.x), rndr(mn.y, mx.y), rndr(mn.z, mx.z));
        dist = dlen(dsub(b, L));
        if (dist > range) continue;
        q = dist > 0 ? dadd(L, dmul(dsub(b, L), rndr(1.0, range / dist))) : b;
        if (i % 3 == 0) q = b;
        for (k = 0; k < 6; k++) {
            double nl = dlen(tod(f->planes[k].n));
            if (ddot(tod(f->planes[k].n), q) + f->planes[k].d < -tol * dmax(nl, 1e-30)) { bad++; break; }
        }
        if (k == 6 && !poly_contains(&P, q, -tol)) bad++;
    }
    return bad;
}

static void test_caster_shadow_frustum(void) {
    float nan = NAN, inf = INFINITY;
    sk_frustum out, sentinel;
    sk_result r;
    int it;
    rng_seed(4);
    memset(&sentinel, 0x5a, sizeof sentinel);

    /* light inside the box: the light-range box (stability) */
    out = sentinel;
    r = sk_caster_shadow_frustum(v3(0.5, 0.5, 0.5), 10.0f, mkbox(d3(0, 0, 0), d3(1, 1, 1)), &out);
    SK_CHECK(r == SK_OK);
    if (r == SK_OK) check_range_box(&out, d3(0.5, 0.5, 0.5), 10.0, "light inside the box");
    /* light on the box surface */
    out = sentinel;
    r = sk_caster_shadow_frustum(v3(1, 0.5, 0.25), 4.0f, mkbox(d3(0, 0, 0), d3(1, 1, 1)), &out);
    SK_CHECK(r == SK_OK);
    if (r == SK_OK) check_range_box(&out, d3(1, 0.5, 0.25), 4.0, "light on the box surface");
    /* light just outside a face: the cone is wider than 170 degrees */
    out = sentinel;
    r = sk_caster_shadow_frustum(v3(0.5, 0.5, -1e-3), 6.0f, mkbox(d3(0, 0, 0), d3(1, 1, 1)), &out);
    SK_CHECK(r == SK_OK);
    if (r == SK_OK) check_range_box(&out, tod(v3(0.5, 0.5, -1e-3)), 6.0, "cone wider than 170 degrees");
    /* box beyond the light range: casts nothing */
    SK_CHECK(sk_caster_shadow_frustum(v3(0, 0, 0), 10.0f, mkbox(d3(20, -1, -1), d3(22, 1, 1)), &out) == SK_ERR_DEGENERATE);
    SK_CHECK(sk_caster_shadow_frustum(v3(0, 0, 0), 10.0f, mkbox(d3(8, 8, -1), d3(9, 9, 1)), &out) == SK_ERR_DEGENERATE);
    /* just within range: a frustum */
    out = sentinel;
    r = sk_caster_shadow_frustum(v3(0, 0, 0), 10.0f, mkbox(d3(9, -1, -1), d3(11, 1, 1)), &out);
    SK_CHECK(r == SK_OK);
    if (r == SK_OK) SK_CHECK(shadow_contained(&out, d3(0, 0, 0), 10.0, d3(9, -1, -1), d3(11, 1, 1), 2000) == 0);

    /* a narrow cone along +X: contains the shadow, not the light, bounded */
    out = sentinel;
    r = sk_caster_shadow_frustum(v3(0, 0, 0), 20.0f, mkbox(d3(5, -0.5, -0.5), d3(6, 0.5, 0.5)), &out);
    SK_CHECK(r == SK_OK);
    if (r == SK_OK) {
        poly P;
        int i, far_ok = 1;
        SK_CHECK(shadow_contained(&out, d3(0, 0, 0), 20.0, d3(5, -0.5, -0.5), d3(6, 0.5, 0.5), 3000) == 0);
        poly_from_sk(&P, &out);
        SK_CHECK_MSG(!poly_contains(&P, d3(0, 0, 0), 0.0), "narrow cone: frustum contains the light");
        SK_CHECK_MSG(!poly_contains(&P, d3(4.4, 0, 0), 0.0), "narrow cone: near plane before the box");
        SK_CHECK_MSG(!poly_contains(&P, d3(0, 10, 0), 0.0), "narrow cone: frustum far too wide");
        SK_CHECK_MSG(!poly_contains(&P, d3(-10, 0, 0), 0.0), "narrow cone: frustum behind the light");
        for (i = 0; i < 8; i++) if (dlen(tod(out.corners[i])) > 1.2 * 20.0) far_ok = 0;
        SK_CHECK_MSG(far_ok, "narrow cone: corners beyond 1.2 * light_range");
        for (i = 0; i < 8; i++) SK_CHECK_FINITE(out.corners[i].x + out.corners[i].y + out.corners[i].z);
        for (i = 0; i < 6; i++) SK_CHECK_FINITE(out.planes[i].n.x + out.planes[i].n.y + out.planes[i].n.z + out.planes[i].d);
    }

    /* random boxes and lights */
    {
        int n = 400, bad_cont = 0, bad_res = 0, bad_light = 0, bad_far = 0, bad_inside = 0, n_ok = 0, n_inside = 0;
        for (it = 0; it < n; it++) {
            dv3 L = tod(tof(rnd_in_box(10.0)));
            double range = (float)rndr(3, 30);
            dv3 c = dadd(L, dmul(rnd_unit(), rndr(0, 25)));
            dv3 h = d3(rndr(0.05, 3), rndr(0.05, 3), rndr(0.05, 3));
            sk_aabb box = mkbox(dsub(c, h), dadd(c, h));
            dv3 mn = tod(box.min), mx = tod(box.max);
            double dist = box_dist(L, mn, mx);
            out = sentinel;
            r = sk_caster_shadow_frustum(tof(L), (float)range, box, &out);
            if (dist > range * (1 + 1e-5)) { if (r != SK_ERR_DEGENERATE) bad_res++; continue; }
            if (dist < range * (1 - 1e-5) && r != SK_OK) { bad_res++; continue; }
            if (r != SK_OK) continue;
            n_ok++;
            if (shadow_contained(&out, L, range, mn, mx, 600)) {
                if (!bad_cont) printf("  random caster %d: shadow escapes its frustum\n", it);
                bad_cont++;
            }
            if (in_box(L, mn, mx)) {
                int i, ok = 1;
                n_inside++;
                for (i = 0; i < 8; i++) {
                    dv3 e = d3(L.x + ((i & 1) ? range : -range), L.y + ((i & 2) ? range : -range), L.z + ((i & 4) ? range : -range));
                    if (dlen(dsub(tod(out.corners[i]), e)) > 1e-5 * (range + dlen(L))) ok = 0;
                }
                if (!ok) bad_inside++;
            } else {
                /* narrow cone: box bounding sphere well inside the distance */
                dv3 bc = dmul(dadd(mn, mx), 0.5);
                double br = 0.5 * dlen(dsub(mx, mn)), bd = dlen(dsub(bc, L));
                if (br < 0.3 * bd) {
                    poly P;
                    int i;
                    poly_from_sk(&P, &out);
                    if (poly_contains(&P, L, 1e-6 * range)) bad_light++;
                    for (i = 0; i < 8; i++)
                        if (dlen(dsub(tod(out.corners[i]), L)) > 1.2 * range) { bad_far++; break; }
                }
            }
        }
        SK_CHECK_MSG(bad_res == 0, "%d boxes with the wrong result (DEGENERATE iff beyond range)", bad_res);
        SK_CHECK_MSG(bad_cont == 0, "%d of %d shadow frusta do not contain their shadow", bad_cont, n_ok);
        SK_CHECK_MSG(bad_inside == 0, "%d of %d lights inside their box: not the light-range box", bad_inside, n_inside);
        SK_CHECK_MSG(bad_light == 0, "%d narrow-cone frusta contain the light itself", bad_light);
        SK_CHECK_MSG(bad_far == 0, "%d narrow-cone frusta reach beyond 1.2 * light_range", bad_far);
        SK_CHECK(n_ok > 100);
    }
    /* flat box (a quad) with the light in its plane, and a point box: if a
       frustum is returned it holds the (degenerate) shadow */
    out = sentinel;
    r = sk_caster_shadow_frustum(v3(0, 0, 0), 10.0f, mkbox(d3(2, 0, -0.5), d3(3, 0, 0.5)), &out);
    SK_CHECK(r == SK_OK || r == SK_ERR_DEGENERATE);
    if (r == SK_OK) SK_CHECK(shadow_contained(&out, d3(0, 0, 0), 10.0, d3(2, 0, -0.5), d3(3, 0, 0.5), 500) == 0);
    out = sentinel;
    r = sk_caster_shadow_frustum(v3(0, 0, 0), 10.0f, mkbox(d3(3, 1, 0), d3(3, 1, 0)), &out);
    SK_CHECK(r == SK_OK || r == SK_ERR_DEGENERATE);
    if (r == SK_OK) SK_CHECK(shadow_contained(&out, d3(0, 0, 0), 10.0, d3(3, 1, 0), d3(3, 1, 0), 100) == 0);

    /* bad input: SK_ERR_INVALID_ARG, out untouched */
    {
        sk_aabb ok = mkbox(d3(2, 2, 2), d3(3, 3, 3)), inv = mkbox(d3(3, 2, 2), d3(2, 3, 3)), nb = ok;
        nb.max.y = nan;
#define BAD_SF(expr, what) do { out = sentinel; r = (expr); \
        SK_CHECK_MSG(r == SK_ERR_INVALID_ARG, "%s: result %d", what, (int)r); \
        SK_CHECK_MSG(memcmp(&out, &sentinel, sizeof out) == 0, "%s: output written", what); } while (0)
        BAD_SF(sk_caster_shadow_frustum(v3(nan, 0, 0), 10.0f, ok, &out), "NaN light");
        BAD_SF(sk_caster_shadow_frustum(v3(0, inf, 0), 10.0f, ok, &out), "Inf light");
        BAD_SF(sk_caster_shadow_frustum(v3(0, 0, 0), nan, ok, &out), "NaN range");
        BAD_SF(sk_caster_shadow_frustum(v3(0, 0, 0), inf, ok, &out), "Inf range");
        BAD_SF(sk_caster_shadow_frustum(v3(0, 0, 0), 0.0f, ok, &out), "zero range");
        BAD_SF(sk_caster_shadow_frustum(v3(0, 0, 0), -5.0f, ok, &out), "negative range");
        BAD_SF(sk_caster_shadow_frustum(v3(0, 0, 0), 10.0f, inv, &out), "box min > max");
        BAD_SF(sk_caster_shadow_frustum(v3(0, 0, 0), 10.0f, nb, &out), "NaN box");
        nb = ok; nb.min.x = -inf;
        BAD_SF(sk_caster_shadow_frustum(v3(0, 0, 0), 10.0f, nb, &out), "Inf box");
#undef BAD_SF
        SK_CHECK(sk_caster_shadow_frustum(v3(0, 0, 0), 10.0f, ok, NULL) == SK_ERR_INVALID_ARG);
    }
}

static void test_caster_visible(void) {
    float nan = NAN, inf = INFINITY;
    sk_frustum V;
    poly PV;
    int it;
    rng_seed(5);
    /* (a) view frustum beyond the light range entirely */
    make_box_frustum(d3(-5, -5, 50), d3(5, 5, 100), &V, &PV);
    SK_CHECK_MSG(sk_caster_visible(v3(0, 0, 0), 20.0f, mkbox(d3(-5.5, -0.5, -0.5), d3(-4.5, 0.5, 0.5)), &V) == 0,
                 "view beyond the light range: caster kept");
    /* (b) view inside the light range, shadow thrown the other way */
    make_box_frustum(d3(5, -3, -3), d3(15, 3, 3), &V, &PV);
    SK_CHECK_MSG(sk_caster_visible(v3(0, 0, 0), 20.0f, mkbox(d3(-5.5, -0.5, -0.5), d3(-4.5, 0.5, 0.5)), &V) == 0,
                 "shadow thrown away from the view: caster kept");
    /* (c) light inside the caster box, view beyond the range box */
    make_box_frustum(d3(-5, -5, 50), d3(5, 5, 100), &V, &PV);
    SK_CHECK_MSG(sk_caster_visible(v3(0, 0, 0), 20.0f, mkbox(d3(-1, -1, -1), d3(1, 1, 1)), &V) == 0,
                 "light inside the box, view beyond range: caster kept");
    /* (d) light inside the caster box, view within range, any direction */
    make_box_frustum(d3(5, -3, -3), d3(15, 3, 3), &V, &PV);
    SK_CHECK_MSG(sk_caster_visible(v3(0, 0, 0), 20.0f, mkbox(d3(-1, -1, -1), d3(1, 1, 1)), &V) == 1,
                 "light inside the box, view within range: caster culled");
    /* (e) caster between the light and the view */
    make_box_frustum(d3(8, -2, -2), d3(12, 2, 2), &V, &PV);
    SK_CHECK(sk_caster_visible(v3(0, 0, 0), 20.0f, mkbox(d3(4.5, -0.5, -0.5), d3(5.5, 0.5, 0.5)), &V) == 1);
    /* (f) off-screen caster shadowing the visible ground (Figure 5.4.3) */
    make_box_frustum(d3(-2, -1, -2), d3(2, 0.5, 2), &V, &PV);
    SK_CHECK_MSG(sk_caster_visible(v3(0, 10, 0), 30.0f, mkbox(d3(-0.5, 4.5, -0.5), d3(0.5, 5.5, 0.5)), &V) == 1,
                 "off-screen caster shadowing the view: culled");
    /* (g) shadow just reaching the view before the range ends */
    make_box_frustum(d3(9.5, -2, -2), d3(12, 2, 2), &V, &PV);
    SK_CHECK(sk_caster_visible(v3(0, 0, 0), 10.0f, mkbox(d3(4.5, -0.5, -0.5), d3(5.5, 0.5, 0.5)), &V) == 1);
    /* (h) flat caster, light in its plane: the shadow is a planar wedge */
    make_box_frustum(d3(5, -0.01, -0.5), d3(8, 0.01, 0.5), &V, &PV);
    SK_CHECK_MSG(sk_caster_visible(v3(0, 0, 0), 10.0f, mkbox(d3(2, 0, -0.5), d3(3, 0, 0.5)), &V) == 1,
                 "flat caster, coplanar light: culled");
    /* (i) point caster */
    make_box_frustum(d3(5, 1.5, -0.5), d3(8, 2.5, 0.5), &V, &PV);
    SK_CHECK_MSG(sk_caster_visible(v3(0, 0, 0), 10.0f, mkbox(d3(3, 1, 0), d3(3, 1, 0)), &V) == 1,
                 "point caster: culled");
    /* (j) light just outside a box face (cone wider than 170 degrees) */
    make_box_frustum(d3(0, -3, -3), d3(1, 3, -2), &V, &PV);
    SK_CHECK(sk_caster_visible(v3(0.5, 0.5, 1.001f), 10.0f, mkbox(d3(0, 0, 0), d3(1, 1, 1)), &V) == 1);

    /* random: whenever the shadow reaches the view, the caster is kept */
    {
        int n = 500, n_pos = 0, n_zero = 0, miss = 0, bad_sep = 0;
        for (it = 0; it < n; it++) {
            pfr p;
            dv3 L = tod(tof(rnd_in_box(10.0)));
            double range = (float)rndr(4, 30);
            dv3 c = dadd(L, dmul(rnd_unit(), rndr(0, 20)));
            dv3 h = d3(rndr(0.1, 3), rndr(0.1, 3), rndr(0.1, 3));
            sk_aabb box = mkbox(dsub(c, h), dadd(c, h));
            dv3 mn = tod(box.min), mx = tod(box.max);
            int res, pos;
            pfr_random(&p, 1.0);
            p.eye = dadd(L, dmul(rnd_unit(), rndr(0, 30)));
            if (it % 5 == 0) p.eye = dadd(L, dmul(rnd_unit(), rndr(0, 0.5 * range)));  /* camera in range */
            make_pfr_frustum(&p, &V, &PV);
            res = sk_caster_visible(tof(L), (float)range, box, &V);
            pos = shadow_reaches(L, range, mn, mx, &PV, 1500);
            n_pos += pos;
            if (!res) n_zero++;
            if (pos && res != 1) {
                if (!miss) printf("  random caster %d: shadow reaches the view, culled (res %d)\n", it, res);
                miss++;
            }
            /* light inside the box: the light-range box decides */
            if (in_box(L, mn, mx)) {
                sk_frustum RB;
                poly PR;
                make_box_frustum(dsub(L, d3(range, range, range)), dadd(L, d3(range, range, range)), &RB, &PR);
                if (sphere_separated(&PR, &PV, 0.01) && res != 0) bad_sep++;
            }
        }
        SK_CHECK_MSG(miss == 0, "%d of %d visible shadows culled (must be conservative)", miss, n_pos);
        SK_CHECK_MSG(bad_sep == 0, "%d light-inside-box casters kept though the range box is far away", bad_sep);
        SK_CHECK(n_pos > 50);
        SK_CHECK(n_zero > 20);
    }
    /* light inside the caster box, camera inside the light range (stability) */
    for (it = 0; it < 50; it++) {
        pfr p;
        dv3 L = rnd_in_box(5.0);
        int res;
        pfr_random(&p, 1.0);
        p.eye = dadd(L, dmul(rnd_unit(), rndr(0, 3)));
        make_pfr_frustum(&p, &V, &PV);
        res = sk_caster_visible(tof(L), 10.0f, mkbox(dsub(L, d3(1, 2, 1)), dadd(L, d3(2, 1, 1))), &V);
        SK_CHECK_MSG(res == 1, "light inside the caster, camera within range: culled");
    }
    /* bad input: 1 (never culls what it cannot judge) */
    {
        sk_aabb ok = mkbox(d3(-5.5, -0.5, -0.5), d3(-4.5, 0.5, 0.5)), inv = ok, nb = ok;
        sk_frustum Z;
        inv.min.x = -4.0f;
        nb.min.z = nan;
        memset(&Z, 0, sizeof Z);
        make_box_frustum(d3(5, -3, -3), d3(15, 3, 3), &V, &PV);   /* case (b): culled when valid */
        SK_CHECK(sk_caster_visible(v3(0, 0, 0), 20.0f, ok, &V) == 0);
        SK_CHECK(sk_caster_visible(v3(nan, 0, 0), 20.0f, ok, &V) == 1);
        SK_CHECK(sk_caster_visible(v3(0, -inf, 0), 20.0f, ok, &V) == 1);
        SK_CHECK(sk_caster_visible(v3(0, 0, 0), nan, ok, &V) == 1);
        SK_CHECK(sk_caster_visible(v3(0, 0, 0), inf, ok, &V) == 1);
        SK_CHECK(sk_caster_visible(v3(0, 0, 0), 0.0f, ok, &V) == 1);
        SK_CHECK(sk_caster_visible(v3(0, 0, 0), -3.0f, ok, &V) == 1);
        SK_CHECK(sk_caster_visible(v3(0, 0, 0), 20.0f, inv, &V) == 1);
        SK_CHECK(sk_caster_visible(v3(0, 0, 0), 20.0f, nb, &V) == 1);
        SK_CHECK(sk_caster_visible(v3(0, 0, 0), 20.0f, ok, NULL) == 1);
        SK_CHECK(sk_caster_visible(v3(0, 0, 0), 20.0f, ok, &Z) == 1);
    }
}

/* ================================================================ scissor */
static sk_mat4 my_view_proj(dv3 eye, dv3 f, dv3 r, dv3 u, double fovy, double aspect, double zn, double zf) {
    double V[16], P[16], M[16];
    int i, j, k;
    sk_mat4 out;
    double c = 1.0 / tan(0.5 * fovy);
    for (i = 0; i < 16; i++) V[i] = P[i] = 0;
    V[0] = r.x; V[4] = r.y; V[8] = r.z; V[12] = -ddot(r, eye);
    V[1] = u.x; V[5] = u.y; V[9] = u.z; V[13] = -ddot(u, eye);
    V[2] = -f.x; V[6] = -f.y; V[10] = -f.z; V[14] = ddot(f, eye);
    V[15] = 1;
    P[0] = c / aspect; P[5] = c; P[10] = (zf + zn) / (zn - zf); P[11] = -1; P[14] = 2 * zf * zn / (zn - zf);
    for (i = 0; i < 4; i++)          /* column */
        for (j = 0; j < 4; j++) {    /* row */
            double s = 0;
            for (k = 0; k < 4; k++) s += P[k * 4 + j] * V[i * 4 + k];
            M[i * 4 + j] = s;
        }
    for (i = 0; i < 16; i++) out.m[i] = (float)M[i];
    return out;
}
/* returns the expected result; *ambiguous when float rounding could decide
   it: a corner with w ~ 0, or a rect edge within the float error bound of an
   integer (the library may compute corners and clip coordinates in float) */
static int scissor_oracle(dv3 L, double rad, const sk_mat4 *m, int W, int H, int rect[4], int *ambiguous) {
    int i, j, front = 0;
    double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300, wscale = 0, tolx = 0, toly = 0;
    double x0, x1, y0, y1;
    *ambiguous = 0;
    rect[0] = rect[1] = rect[2] = rect[3] = 0;
    for (i = 0; i < 16; i++) wscale = dmax(wscale, fabs(m->m[i]));
    wscale *= (dlen(L) + rad + 1);
    for (i = 0; i < 8; i++) {
        dv3 p = d3(L.x + ((i & 1) ? rad : -rad), L.y + ((i & 2) ? rad : -rad), L.z + ((i & 4) ? rad : -rad));
        double c[4], sa[4], pp[4];
        mat_point(m, p, c);
        pp[0] = p.x; pp[1] = p.y; pp[2] = p.z; pp[3] = 1;
        for (j = 0; j < 4; j++)     /* sum of |terms| of each clip coordinate: its float error scale */
            sa[j] = fabs(m->m[j] * pp[0]) + fabs(m->m[4 + j] * pp[1]) + fabs(m->m[8 + j] * pp[2]) + fabs(m->m[12 + j]);
        if (fabs(c[3]) < 1e-5 * wscale) *ambiguous = 1;
        if (c[3] > 0) {
            double x = (c[0] / c[3] * 0.5 + 0.5) * W, y = (c[1] / c[3] * 0.5 + 0.5) * H;
            front++;
            xmin = dmin(xmin, x); xmax = dmax(xmax, x);
            ymin = dmin(ymin, y); ymax = dmax(ymax, y);
            tolx = dmax(tolx, 1e-6 * (sa[0] + fabs(c[0] / c[3]) * sa[3]) / c[3] * W);
            toly = dmax(toly, 1e-6 * (sa[1] + fabs(c[1] / c[3]) * sa[3]) / c[3] * H);
        }
    }
    if (front == 0) return 0;
    if (front < 8) { rect[2] = W; rect[3] = H; return 1; }
    {
        double v[4], tv[4];
        v[0] = xmin; v[1] = xmax; v[2] = ymin; v[3] = ymax;
        tv[0] = tv[1] = tolx + 1e-3; tv[2] = tv[3] = toly + 1e-3;
        for (i = 0; i < 4; i++)
            if (fabs(v[i]) < 1e7 && fabs(v[i] - floor(v[i] + 0.5)) < tv[i]) *ambiguous = 1;
    }
    x0 = dclamp(floor(xmin), 0, W); x1 = dclamp(ceil(xmax), 0, W);
    y0 = dclamp(floor(ymin), 0, H); y1 = dclamp(ceil(ymax), 0, H);
    if (x1 <= x0 || y1 <= y0) return 0;
    rect[0] = (int)x0; rect[1] = (int)y0; rect[2] = (int)(x1 - x0); rect[3] = (int)(y1 - y0);
    return 1;
}

static void test_light_scissor(void) {
    float nan = NAN, inf = INFINITY;
    int rect[4], exp_rect[4], amb, er, r, it;
    dv3 eye = d3(0, 0, 10), f = d3(0, 0, -1), rr = d3(1, 0, 0), u = d3(0, 1, 0);
    sk_mat4 vp = my_view_proj(eye, f, rr, u, 1.0, 800.0 / 600.0, 0.1, 100.0);
    rng_seed(6);

#define SC(L, rad, m, W, H) (rect[0] = rect[1] = rect[2] = rect[3] = 777, \
                             sk_light_scissor(tof(L), (float)(rad), m, W, H, rect))
#define ZEROED (rect[0] == 0 && rect[1] == 0 && rect[2] == 0 && rect[3] == 0)
    /* centred light: symmetric rect, by hand: corner (1,1,1) at eye depth 9,
       cot(0.5)/aspect * 1/9 ... computed by the oracle */
    r = SC(d3(0, 0, 0), 1.0, vp, 800, 600);
    er = scissor_oracle(d3(0, 0, 0), 1.0, &vp, 800, 600, exp_rect, &amb);
    SK_CHECK(r == 1 && er == 1);
    SK_CHECK(rect[0] == exp_rect[0] && rect[1] == exp_rect[1] && rect[2] == exp_rect[2] && rect[3] == exp_rect[3]);
    SK_CHECK_MSG(rect[0] + rect[2] == 800 - rect[0] && rect[1] + rect[3] == 600 - rect[1],
                 "centred light: rect {%d,%d,%d,%d} not symmetric", rect[0], rect[1], rect[2], rect[3]);
    /* hand check: nearest face z = 1 at eye depth 9, far face at 11; the widest
       extent is the near face: x_ndc = cot(0.5)/(4/3) * 1/9 */
    {
        double xn = (1.0 / tan(0.5)) / (800.0 / 600.0) / 9.0, yn = (1.0 / tan(0.5)) / 9.0;
        int ex0 = (int)floor((-xn * 0.5 + 0.5) * 800), ex1 = (int)ceil((xn * 0.5 + 0.5) * 800);
        int ey0 = (int)floor((-yn * 0.5 + 0.5) * 600), ey1 = (int)ceil((yn * 0.5 + 0.5) * 600);
        SK_CHECK(rect[0] == ex0 && rect[2] == ex1 - ex0 && rect[1] == ey0 && rect[3] == ey1 - ey0);
    }
    /* light off to the upper right: origin bottom-left, so x and y grow */
    r = SC(d3(2, 1.5, 0), 0.5, vp, 800, 600);
    SK_CHECK(r == 1 && rect[0] > 400 && rect[1] > 300);
    /* partially off-screen: clipped at the right edge */
    r = SC(d3(4, 0, 0), 2.0, vp, 800, 600);
    er = scissor_oracle(d3(4, 0, 0), 2.0, &vp, 800, 600, exp_rect, &amb);
    SK_CHECK(r == 1 && rect[0] + rect[2] == 800 && rect[0] == exp_rect[0] && rect[1] == exp_rect[1] &&
             rect[3] == exp_rect[3]);
    /* eye inside the range box (camera inside the light range): full viewport */
    r = SC(d3(0.2, -0.3, 10.5), 1.0, vp, 800, 600);
    SK_CHECK_MSG(r == 1 && rect[0] == 0 && rect[1] == 0 && rect[2] == 800 && rect[3] == 600,
                 "eye inside the range box: {%d,%d,%d,%d} r %d", rect[0], rect[1], rect[2], rect[3], r);
    r = SC(eye, 5.0, vp, 640, 480);                       /* light at the eye */
    SK_CHECK(r == 1 && rect[0] == 0 && rect[1] == 0 && rect[2] == 640 && rect[3] == 480);
    /* box entirely behind the eye */
    r = SC(d3(0, 0, 20), 1.0, vp, 800, 600);
    SK_CHECK_MSG(r == 0 && ZEROED, "box behind the eye: r %d {%d,%d,%d,%d}", r, rect[0], rect[1], rect[2], rect[3]);
    /* in front but off-screen: empty rect */
    r = SC(d3(100, 0, 0), 1.0, vp, 800, 600);
    SK_CHECK_MSG(r == 0 && ZEROED, "off-screen box: r %d {%d,%d,%d,%d}", r, rect[0], rect[1], rect[2], rect[3]);
    r = SC(d3(0, -60, -5), 1.0, vp, 800, 600);
    SK_CHECK(r == 0 && ZEROED);
    /* orthographic view-projection (w = 1): x in [-10,10], y in [-5,5] */
    {
        sk_mat4 o;
        memset(&o, 0, sizeof o);
        /* binary fractions only, so every value below is exact in float */
        o.m[0] = 0.125f; o.m[5] = 0.25f; o.m[10] = -0.0078125f; o.m[15] = 1.0f;
        r = SC(d3(0, 0, 0), 1.0, o, 200, 100);
        /* x: [-1,1] -> ndc [-0.125,0.125] -> window [87.5,112.5] -> [87,113];
           y: [-1,1] -> ndc [-0.25,0.25] -> window [37.5,62.5] -> [37,63] */
        SK_CHECK_MSG(r == 1 && rect[0] == 87 && rect[1] == 37 && rect[2] == 26 && rect[3] == 26,
                     "ortho: r %d {%d,%d,%d,%d}", r, rect[0], rect[1], rect[2], rect[3]);
        r = SC(d3(-7.5, 3.5, 0), 1.0, o, 200, 100);       /* clipped at left and top */
        /* x: [-8.5,-6.5] -> ndc [-1.0625,-0.8125] -> [-6.25,18.75] -> [0,19];
           y: [2.5,4.5] -> ndc [0.625,1.125] -> [81.25,106.25] -> [81,100] */
        SK_CHECK_MSG(r == 1 && rect[0] == 0 && rect[1] == 81 && rect[2] == 19 && rect[3] == 19,
                     "ortho clipped: r %d {%d,%d,%d,%d}", r, rect[0], rect[1], rect[2], rect[3]);
        /* exactly on integers: [87.5 - 0.5 ...]: radius 1.2 -> x ndc +-0.15 is not
           exact; use the light at x = 0.5: x in [-0.5,1.5] -> ndc [-0.0625,0.1875]
           -> window [93.75,118.75] -> [93,119] */
        r = SC(d3(0.5, 0, 0), 1.0, o, 200, 100);
        SK_CHECK_MSG(r == 1 && rect[0] == 93 && rect[2] == 26, "ortho shifted: r %d {%d,%d,%d,%d}", r, rect[0],
                     rect[1], rect[2], rect[3]);
        /* a rect edge exactly on a pixel boundary stays there (floor/ceil of
           an integer): light x = 4, radius 4 -> x in [0,8] -> ndc [0,1] -> [100,200] */
        r = SC(d3(4, 0, 0), 4.0, o, 200, 100);
        SK_CHECK_MSG(r == 1 && rect[0] == 100 && rect[2] == 100 && rect[1] == 0 && rect[3] == 100,
                     "ortho on pixel edges: r %d {%d,%d,%d,%d}", r, rect[0], rect[1], rect[2], rect[3]);
    }
    /* random against the oracle */
    {
        int n = 3000, bad = 0, checked = 0, n_full = 0, n_zero = 0, n_part = 0;
        for (it = 0; it < n; it++) {
            dv3 e = rnd_in_box(20.0), fw = rnd_unit(), rt, up, L;
            double rad = rndr(0.2, 8.0);
            int W = 1 + (int)rndr(0, 2000), H = 1 + (int)rndr(0, 1500);
            sk_mat4 m;
            basis_from_forward(fw, &rt, &up);
            m = my_view_proj(e, fw, rt, up, rndr(0.4, 2.0), (double)W / H, 0.1, 100.0);
            L = dadd(e, dadd(dmul(fw, rndr(-10, 40)), dadd(dmul(rt, rndr(-15, 15)), dmul(up, rndr(-15, 15)))));
            L = tod(tof(L));
            rad = (float)rad;
            er = scissor_oracle(L, rad, &m, W, H, exp_rect, &amb);
            if (amb) continue;
            checked++;
            r = SC(L, rad, m, W, H);
            if (er == 0) n_zero++;
            else if (exp_rect[2] == W && exp_rect[3] == H) n_full++;
            else n_part++;
            if (r != er || (er == 1 && (rect[0] != exp_rect[0] || rect[1] != exp_rect[1] ||
                                        rect[2] != exp_rect[2] || rect[3] != exp_rect[3])) ||
                (er == 0 && !ZEROED)) {
                if (!bad)
                    printf("  scissor case %d: got %d {%d,%d,%d,%d}, expected %d {%d,%d,%d,%d}\n", it, r, rect[0],
                           rect[1], rect[2], rect[3], er, exp_rect[0], exp_rect[1], exp_rect[2], exp_rect[3]);
                bad++;
            }
        }
        SK_CHECK_MSG(bad == 0, "%d of %d scissor rects differ from the projected range box", bad, checked);
        SK_CHECK(checked > 2000 && n_zero > 100 && n_full > 100 && n_part > 100);
    }
    /* bad input: 0, rect zeroed */
    {
        sk_mat4 nm = vp, im = vp, zm;
        nm.m[5] = nan;
        im.m[12] = inf;
        memset(&zm, 0, sizeof zm);
        r = SC(d3(0, 0, 0), 0.0, vp, 800, 600);    SK_CHECK(r == 0 && ZEROED);
        r = SC(d3(0, 0, 0), -1.0, vp, 800, 600);   SK_CHECK(r == 0 && ZEROED);
        r = SC(d3(0, 0, 0), nan, vp, 800, 600);    SK_CHECK(r == 0 && ZEROED);
        r = SC(d3(0, 0, 0), inf, vp, 800, 600);    SK_CHECK(r == 0 && ZEROED);
        r = SC(d3(nan, 0, 0), 1.0, vp, 800, 600);  SK_CHECK(r == 0 && ZEROED);
        r = SC(d3(0, -inf, 0), 1.0, vp, 800, 600); SK_CHECK(r == 0 && ZEROED);
        r = SC(d3(0, 0, 0), 1.0, vp, 0, 600);      SK_CHECK(r == 0 && ZEROED);
        r = SC(d3(0, 0, 0), 1.0, vp, 800, 0);      SK_CHECK(r == 0 && ZEROED);
        r = SC(d3(0, 0, 0), 1.0, vp, -800, 600);   SK_CHECK(r == 0 && ZEROED);
        r = SC(d3(0, 0, 0), 1.0, vp, 800, INT_MIN); SK_CHECK(r == 0 && ZEROED);
        r = SC(d3(0, 0, 0), 1.0, nm, 800, 600);    SK_CHECK(r == 0 && ZEROED);
        r = SC(d3(0, 0, 0), 1.0, im, 800, 600);    SK_CHECK(r == 0 && ZEROED);
        r = SC(d3(0, 0, 0), 1.0, zm, 800, 600);    SK_CHECK(r == 0 && ZEROED);   /* every w = 0 */
        SK_CHECK(sk_light_scissor(v3(0, 0, 0), 1.0f, vp, 800, 600, NULL) == 0);
        /* a tiny box just in front of the eye plane, far to the right (left,
           above, below): every corner in front (w in [1e-6, 3e-6]) but its
           window coords are ~1e10, beyond int: empty rect, never an int
           overflow */
        {
            sk_mat4 pm = my_view_proj(d3(0, 0, 0), d3(0, 0, -1), d3(1, 0, 0), d3(0, 1, 0), 1.0, 4.0 / 3.0, 0.1, 100.0);
            double c4[4];
            mat_point(&pm, d3(50, 0, -1e-6), c4);
            SK_CHECK(c4[3] > 0);
            r = SC(d3(50, 0, -2e-6), 1e-6, pm, 800, 600);
            SK_CHECK_MSG(r == 0 && ZEROED, "box far right of the window: r %d {%d,%d,%d,%d}", r, rect[0], rect[1],
                         rect[2], rect[3]);
            r = SC(d3(-50, 0, -2e-6), 1e-6, pm, 800, 600);
            SK_CHECK_MSG(r == 0 && ZEROED, "box far left of the window: r %d {%d,%d,%d,%d}", r, rect[0], rect[1],
                         rect[2], rect[3]);
            r = SC(d3(0, 50, -2e-6), 1e-6, pm, 800, 600);
            SK_CHECK_MSG(r == 0 && ZEROED, "box far above the window: r %d {%d,%d,%d,%d}", r, rect[0], rect[1],
                         rect[2], rect[3]);
            r = SC(d3(0, -50, -2e-6), 1e-6, pm, 800, 600);
            SK_CHECK_MSG(r == 0 && ZEROED, "box far below the window: r %d {%d,%d,%d,%d}", r, rect[0], rect[1],
                         rect[2], rect[3]);
        }
        /* huge viewport: the full-viewport case must not overflow */
        r = SC(d3(0, 0, 10.5), 1.0, vp, INT_MAX, INT_MAX);
        SK_CHECK(r == 1 && rect[0] == 0 && rect[1] == 0 && rect[2] == INT_MAX && rect[3] == INT_MAX);
    }
#undef SC
#undef ZEROED
}

/* ======================================================= cube resolution */
static int cube_res_oracle(int faces, double pixels, double c, int max_res) {
    long long cap = 1, M = 1;
    if (faces == 0) return 0;
    while (cap * 2 <= max_res) cap *= 2;
    while (M < cap && (double)faces * (double)M * (double)M < c * pixels) M *= 2;
    return (int)M;
}
static void test_cube_resolution(void) {
    float nan = NAN, inf = INFINITY;
    int it, bad = 0, n = 0;
    /* by hand */
    SK_CHECK(sk_cube_resolution(6, 24576.0f, 1.0f, 4096) == 64);      /* 6*64^2 = 24576 exactly */
    SK_CHECK(sk_cube_resolution(6, 24577.0f, 1.0f, 4096) == 128);
    SK_CHECK(sk_cube_resolution(6, 12288.0f, 2.0f, 4096) == 64);      /* c = 2 (the seed's) */
    SK_CHECK(sk_cube_resolution(1, 1.0f, 1.0f, 10) == 1);
    SK_CHECK(sk_cube_resolution(1, 2.0f, 1.0f, 10) == 2);
    SK_CHECK(sk_cube_resolution(1, 5.0f, 1.0f, 10) == 4);
    SK_CHECK(sk_cube_resolution(1, 17.0f, 1.0f, 10) == 8);            /* 8 is the cap: 16 > 10 */
    SK_CHECK(sk_cube_resolution(1, 17.0f, 1.0f, 16) == 8);            /* 8*8 = 64 >= 17 */
    SK_CHECK(sk_cube_resolution(3, 20000.0f, 2.0f, 4096) == 128);     /* 3*128^2 = 49152 >= 40000 > 3*64^2 */
    SK_CHECK(sk_cube_resolution(6, 1e6f, 2.0f, 256) == 256);          /* would be 1024: clamped */
    SK_CHECK(sk_cube_resolution(6, 1e6f, 2.0f, 1000) == 512);         /* largest power of two <= 1000 */
    SK_CHECK(sk_cube_resolution(6, 1e6f, 2.0f, 1) == 1);
    SK_CHECK(sk_cube_resolution(6, 0.0f, 2.0f, 512) == 1);
    SK_CHECK(sk_cube_resolution(2, 0.5f, 0.1f, 512) == 1);
    SK_CHECK(sk_cube_resolution(0, 100.0f, 2.0f, 512) == 0);
    SK_CHECK(sk_cube_resolution(0, 0.0f, 2.0f, 512) == 0);
    /* no int overflow: 6*M*M passes 2^31 from M = 2^15 */
    SK_CHECK_MSG(sk_cube_resolution(6, 1e18f, 1.0f, INT_MAX) == (1 << 29), "6 M^2 >= 1e18: got %d",
                 sk_cube_resolution(6, 1e18f, 1.0f, INT_MAX));
    SK_CHECK(sk_cube_resolution(6, 1e20f, 1.0f, INT_MAX) == (1 << 30));
    SK_CHECK(sk_cube_resolution(6, 3e38f, 10.0f, INT_MAX) == (1 << 30));   /* c*pixels overflows float */
    SK_CHECK(sk_cube_resolution(1, 1e9f, 1.0f, 65536) == 32768);       /* 32768^2 = 1.07e9 >= 1e9 */
    /* brute force */
    rng_seed(7);
    for (it = 0; it < 20000; it++) {
        int faces = (int)rndr(1, 7), max_res = (it % 3) ? (int)exp(rndr(0, log(70000.0))) : (1 << (int)rndr(0, 17));
        float pixels = (float)((it % 7 == 0) ? floor(rndr(0, 5000)) : exp(rndr(-2, 35)));
        float c = (float)((it % 4 == 0) ? 2.0 : rndr(0.05, 10));
        double cp = (double)c * (double)pixels;
        int e, got, amb = 0;
        long long M;
        if (max_res < 1) max_res = 1;
        e = cube_res_oracle(faces, pixels, c, max_res);
        /* skip products within float rounding of a boundary faces*M^2 */
        for (M = 1; M <= (1LL << 20); M *= 2)
            if (fabs((double)faces * M * M - cp) <= 1e-5 * cp) amb = 1;
        if (amb) continue;
        n++;
        got = sk_cube_resolution(faces, pixels, c, max_res);
        if (got != e) {
            if (!bad) printf("  sk_cube_resolution(%d, %.9g, %.9g, %d) = %d, expected %d\n", faces, pixels, c, max_res, got, e);
            bad++;
        }
    }
    SK_CHECK_MSG(bad == 0, "%d of %d cube resolutions differ from the brute force", bad, n);
    /* bad input: 0 */
    SK_CHECK(sk_cube_resolution(7, 100.0f, 2.0f, 512) == 0);
    SK_CHECK(sk_cube_resolution(-1, 100.0f, 2.0f, 512) == 0);
    SK_CHECK(sk_cube_resolution(INT_MAX, 100.0f, 2.0f, 512) == 0);
    SK_CHECK(sk_cube_resolution(6, -1.0f, 2.0f, 512) == 0);
    SK_CHECK(sk_cube_resolution(6, nan, 2.0f, 512) == 0);
    SK_CHECK(sk_cube_resolution(6, 100.0f, 0.0f, 512) == 0);
    SK_CHECK(sk_cube_resolution(6, 100.0f, -2.0f, 512) == 0);
    SK_CHECK(sk_cube_resolution(6, 100.0f, nan, 512) == 0);
    SK_CHECK(sk_cube_resolution(6, 100.0f, 2.0f, 0) == 0);
    SK_CHECK(sk_cube_resolution(6, 100.0f, 2.0f, -512) == 0);
    SK_CHECK(sk_cube_resolution(6, 100.0f, 2.0f, INT_MIN) == 0);
    SK_CHECK(sk_cube_resolution(6, -inf, 2.0f, 512) == 0);
    /* +Inf pixels or c: bad (non-finite) -> 0, or the cap; never a hang */
    {
        int a = sk_cube_resolution(6, inf, 2.0f, 512), b = sk_cube_resolution(6, 100.0f, inf, 512);
        SK_CHECK_MSG(a == 0 || a == 512, "sk_cube_resolution(6, inf, 2, 512) = %d", a);
        SK_CHECK_MSG(b == 0 || b == 512, "sk_cube_resolution(6, 100, inf, 512) = %d", b);
    }
}

/* ================================================================= VSDCT */
static void test_vsdct_layout_make(void) {
    static const int sizes[] = { 1, 2, 7, 256, 1000, 4096, SK_VSDCT_MAX_FACE_RES };
    sk_vsdct_layout l, sentinel;
    int i, f, g;
    memset(&sentinel, 0x5a, sizeof sentinel);
    for (i = 0; i < (int)(sizeof sizes / sizeof sizes[0]); i++) {
        int N = sizes[i], inside = 1, overlap = 0;
        l = sentinel;
        SK_CHECK(sk_vsdct_layout_make(N, &l) == SK_OK);
        SK_CHECK(l.face_res == N);
        SK_CHECK(l.atlas_w >= 3 * N && l.atlas_h >= 2 * N);
        for (f = 0; f < 6; f++) {
            /* face f at column f%3, row f/3, row 0 at the bottom */
            SK_CHECK_MSG(l.face_x[f] == (f % 3) * N && l.face_y[f] == (f / 3) * N,
                         "face_res %d face %d at (%d,%d), expected (%d,%d)", N, f, l.face_x[f], l.face_y[f],
                         (f % 3) * N, (f / 3) * N);
            if (l.face_x[f] < 0 || l.face_y[f] < 0 || l.face_x[f] + N > l.atlas_w || l.face_y[f] + N > l.atlas_h)
                inside = 0;
            for (g = 0; g < f; g++)
                if (l.face_x[f] < l.face_x[g] + N && l.face_x[g] < l.face_x[f] + N &&
                    l.face_y[f] < l.face_y[g] + N && l.face_y[g] < l.face_y[f] + N) overlap = 1;
        }
        SK_CHECK(inside);
        SK_CHECK(!overlap);
    }
    /* bad input: SK_ERR_INVALID_ARG, out untouched */
    {
        static const int bad[] = { 0, -1, -256, SK_VSDCT_MAX_FACE_RES + 1, INT_MAX, INT_MIN };
        for (i = 0; i < (int)(sizeof bad / sizeof bad[0]); i++) {
            l = sentinel;
            SK_CHECK_MSG(sk_vsdct_layout_make(bad[i], &l) == SK_ERR_INVALID_ARG, "layout_make(%d)", bad[i]);
            SK_CHECK(memcmp(&l, &sentinel, sizeof l) == 0);
        }
        SK_CHECK(sk_vsdct_layout_make(64, NULL) == SK_ERR_INVALID_ARG);
    }
}

static int ceil_log2_ll(long long x) { int k = 0; while ((1LL << k) < x) k++; return k; }
static long long isize_oracle(long long ns, long long g, int D) {     /* Eq. 5.4.7 in integers */
    int lg = ceil_log2_ll(g);
    int e = ceil_log2_ll(ns) + (lg < D ? lg : D) - D;
    return e < 0 ? 1 : (1LL << e);
}
static void test_vsdct_indirection_size(void) {
    int ns, g, D, bad = 0, n = 0;
    /* the seed's example: 256x256 faces, 16 grey levels, D = 8 -> 16 */
    SK_CHECK(sk_vsdct_indirection_size(256, 16, 8) == 16);
    /* by hand */
    SK_CHECK(sk_vsdct_indirection_size(1024, 256, 8) == 1024);   /* 2^(10+8-8) */
    SK_CHECK(sk_vsdct_indirection_size(1000, 17, 8) == 128);     /* 2^(10+5-8) */
    SK_CHECK(sk_vsdct_indirection_size(257, 16, 8) == 32);       /* 2^(9+4-8) */
    SK_CHECK(sk_vsdct_indirection_size(255, 16, 8) == 16);       /* 2^(8+4-8) */
    SK_CHECK(sk_vsdct_indirection_size(16, 16, 8) == 1);         /* 2^0 */
    SK_CHECK(sk_vsdct_indirection_size(8, 2, 8) == 1);           /* 2^-4 -> at least 1 */
    SK_CHECK(sk_vsdct_indirection_size(1, 1, 8) == 1);
    SK_CHECK(sk_vsdct_indirection_size(256, 1, 8) == 1);         /* one grey level: 2^(8+0-8) */
    SK_CHECK(sk_vsdct_indirection_size(300, 5, 0) == 512);       /* D = 0: next power of two of Ns */
    SK_CHECK(sk_vsdct_indirection_size(512, 1000, 4) == 512);    /* min(10, 4) - 4 = 0 */
    SK_CHECK(sk_vsdct_indirection_size(65536, 1 << 20, 30) == 64);  /* 2^(16+20-30) */
    /* D is any number of bits >= 0 (documented bad input: D < 0 only); a large
       D makes the exponent negative -> 1 */
    SK_CHECK_MSG(sk_vsdct_indirection_size(256, 16, 100) == 1, "(256, 16, D=100): got %d, expected 2^(8+4-100) -> 1",
                 sk_vsdct_indirection_size(256, 16, 100));
    SK_CHECK_MSG(sk_vsdct_indirection_size(256, 16, 31) == 1, "(256, 16, D=31): got %d, expected 1",
                 sk_vsdct_indirection_size(256, 16, 31));
    /* exact ceil(log2): 2^24 + 1 is not a float; a float log2 gets 24, not 25 */
    SK_CHECK_MSG(sk_vsdct_indirection_size(32, (1 << 24) + 1, 25) == 32, "G = 2^24+1: got %d, expected 32",
                 sk_vsdct_indirection_size(32, (1 << 24) + 1, 25));
    /* Ns above SK_VSDCT_MAX_FACE_RES: no VSDCT face can be that large; the
       formula's value or 0 (bad input) are both accepted */
    {
        int a = sk_vsdct_indirection_size((1 << 24) + 1, 1, 8), b = sk_vsdct_indirection_size(INT_MAX, 1, 8);
        SK_CHECK_MSG(a == 0 || a == (1 << 17), "Ns = 2^24+1: got %d, expected 2^17 (or 0)", a);
        SK_CHECK_MSG(b == 0 || b == (1 << 23), "Ns = INT_MAX: got %d, expected 2^23 (or 0)", b);
    }
    /* brute force */
    for (ns = 1; ns <= 5000; ns += (ns < 300 ? 1 : 37))
        for (g = 1; g <= 3000; g += (g < 70 ? 1 : 53))
            for (D = 0; D <= 12; D += 3) {
                long long e = isize_oracle(ns, g, D);
                int got = sk_vsdct_indirection_size(ns, g, D);
                n++;
                if (got != e) {
                    if (!bad) printf("  indirection_size(%d, %d, %d) = %d, expected %lld\n", ns, g, D, got, e);
                    bad++;
                }
            }
    SK_CHECK_MSG(bad == 0, "%d of %d indirection sizes differ from Eq. 5.4.7", bad, n);
    /* bad input: 0 */
    SK_CHECK(sk_vsdct_indirection_size(0, 16, 8) == 0);
    SK_CHECK(sk_vsdct_indirection_size(-256, 16, 8) == 0);
    SK_CHECK(sk_vsdct_indirection_size(256, 0, 8) == 0);
    SK_CHECK(sk_vsdct_indirection_size(256, -16, 8) == 0);
    SK_CHECK(sk_vsdct_indirection_size(256, 16, -1) == 0);
    SK_CHECK(sk_vsdct_indirection_size(INT_MIN, INT_MIN, INT_MIN) == 0);
}

/* Run last: an integer ceil(log2) that overflows (1 << 31) for G > 2^30 is
   UB and, optimised, may loop forever; the other tests report first. */
static void test_vsdct_indirection_size_extremes(void) {
    /* G above 2^30: ceil(log2 G) = 31 */
    SK_CHECK_MSG(sk_vsdct_indirection_size(256, (1 << 30) + 1, 30) == 256, "(256, 2^30+1, 30): got %d, expected 256",
                 sk_vsdct_indirection_size(256, (1 << 30) + 1, 30));
    SK_CHECK_MSG(sk_vsdct_indirection_size(256, INT_MAX, 8) == 256, "(256, INT_MAX, 8): got %d, expected 2^(8+8-8)",
                 sk_vsdct_indirection_size(256, INT_MAX, 8));
    SK_CHECK_MSG(sk_vsdct_indirection_size(1, INT_MAX, INT_MAX) == 1, "(1, INT_MAX, INT_MAX): got %d, expected 1",
                 sk_vsdct_indirection_size(1, INT_MAX, INT_MAX));
    /* never negative */
    SK_CHECK(sk_vsdct_indirection_size(INT_MAX, INT_MAX, INT_MAX) >= 0);
    SK_CHECK(sk_vsdct_indirection_size(INT_MAX, INT_MAX, 30) >= 0);
}

/* expected atlas texel coordinates of direction r on face f of layout l */
static void lookup_expect(const sk_vsdct_layout *l, int f, dv3 r, double *ex, double *ey) {
    double s, t, ma, N = l->face_res;
    face_st(f, r, &s, &t, &ma);
    *ex = l->face_x[f] + dclamp(s * N, 0.5, N - 0.5);
    *ey = l->face_y[f] + dclamp(t * N, 0.5, N - 0.5);
}
/* one lookup against the table; returns 1 if it agrees */
static int check_lookup(const sk_vsdct_layout *l, sk_vec3 dir, int verbose) {
    dv3 r = tod(dir);
    unsigned allowed = table_faces(r);
    float u = -7, v = -7;
    int f = sk_vsdct_lookup(l, dir, &u, &v);
    double ex, ey, gx, gy, tol = 2e-3 + 3e-7 * dmax(l->atlas_w, l->atlas_h);
    if (f < 0 || f > 5 || !(allowed & (1u << f))) {
        if (verbose) printf("  lookup (%.9g,%.9g,%.9g): face %d, table allows mask 0x%x\n", dir.x, dir.y, dir.z, f, allowed);
        return 0;
    }
    lookup_expect(l, f, r, &ex, &ey);
    gx = (double)u * l->atlas_w;
    gy = (double)v * l->atlas_h;
    if (!(fabs(gx - ex) <= tol && fabs(gy - ey) <= tol)) {
        if (verbose)
            printf("  lookup (%.9g,%.9g,%.9g) face %d: texel (%.5f,%.5f), expected (%.5f,%.5f)\n", dir.x, dir.y,
                   dir.z, f, gx, gy, ex, ey);
        return 0;
    }
    return 1;
}
static void custom_layout(sk_vsdct_layout *l) {
    static const int fx[6] = { 20, 0, 10, 26, 3, 14 }, fy[6] = { 10, 0, 2, 0, 14, 12 };
    int f;
    l->face_res = 5; l->atlas_w = 32; l->atlas_h = 20;
    for (f = 0; f < 6; f++) { l->face_x[f] = fx[f]; l->face_y[f] = fy[f]; }
}

static void test_vsdct_lookup(void) {
    static const int sizes[] = { 1, 2, 4, 64, 1000 };
    sk_vsdct_layout layouts[6];
    float nan = NAN, inf = INFINITY;
    int li, it, nl = 0;
    rng_seed(8);
    for (li = 0; li < (int)(sizeof sizes / sizeof sizes[0]); li++)
        if (sk_vsdct_layout_make(sizes[li], &layouts[nl]) == SK_OK) nl++;
    custom_layout(&layouts[nl++]);
    SK_CHECK(nl == 6);
    for (li = 0; li < nl; li++) {
        const sk_vsdct_layout *l = &layouts[li];
        int bad = 0, n = 0, a, b, c;
        /* random directions, random magnitudes */
        for (it = 0; it < 4000; it++) {
            dv3 d = dmul(rnd_unit(), exp(rndr(-20, 20)));
            n++;
            if (!check_lookup(l, tof(d), !bad)) bad++;
        }
        /* axes, cube edges and corners exactly: (1,1,0), (1,1,1), ... */
        for (a = -1; a <= 1; a++)
            for (b = -1; b <= 1; b++)
                for (c = -1; c <= 1; c++) {
                    double k;
                    if (!a && !b && !c) continue;
                    for (k = 1; k < 1e4; k *= 37.5) {
                        n++;
                        if (!check_lookup(l, v3(a * k, b * k, c * k), !bad)) bad++;
                    }
                }
        /* near face edges: a second component within 10^-k of the major one */
        for (it = 0; it < 600; it++) {
            dv3 d = rnd_unit();
            double comp[3];
            int i = it % 3, j = (it / 3) % 3, k = 1 + (it / 9) % 7;
            float fc[3];
            if (j == i) j = (i + 1) % 3;
            comp[0] = d.x; comp[1] = d.y; comp[2] = d.z;
            comp[i] = (comp[i] < 0 ? -1.0 : 1.0) * dmax(fabs(comp[i]), 0.8);
            comp[j] = (comp[j] < 0 ? -1.0 : 1.0) * fabs(comp[i]) * (1.0 - pow(10.0, -k) * ((it & 1) ? 1 : -1));
            fc[0] = (float)comp[0]; fc[1] = (float)comp[1]; fc[2] = (float)comp[2];
            n++;
            if (!check_lookup(l, v3(fc[0], fc[1], fc[2]), !bad)) bad++;
            fc[j] = (fc[j] < 0 ? -1.0f : 1.0f) * fabsf(fc[i]);        /* an exact tie */
            n++;
            if (!check_lookup(l, v3(fc[0], fc[1], fc[2]), !bad)) bad++;
        }
        /* extreme but valid magnitudes: FLT_MAX corners, denormals */
        {
            static const float ext[][3] = { { FLT_MAX, FLT_MAX, FLT_MAX }, { -FLT_MAX, FLT_MAX, 0 },
                                            { FLT_MAX, -1, 0.5f }, { 1e-40f, 0, 0 }, { 0, -1e-45f, 0 },
                                            { 1e-38f, 2e-39f, -5e-39f }, { 0, 0, -FLT_MIN },
                                            { 3e38f, -2e38f, 1e38f } };
            int e;
            for (e = 0; e < (int)(sizeof ext / sizeof ext[0]); e++) {
                n++;
                if (!check_lookup(l, v3(ext[e][0], ext[e][1], ext[e][2]), 1)) bad++;
            }
        }
        SK_CHECK_MSG(bad == 0, "layout %d (face_res %d): %d of %d lookups disagree with the GL face table", li,
                     l->face_res, bad, n);
        /* scale invariance (powers of two) */
        {
            int sbad = 0;
            for (it = 0; it < 500; it++) {
                dv3 d = rnd_unit();
                sk_vec3 d0 = tof(d), d1 = tof(dmul(tod(d0), ldexp(1.0, 60))), d2 = tof(dmul(tod(d0), ldexp(1.0, -60)));
                float u0 = 0, v0 = 0, u1 = 0, v1 = 0, u2 = 0, v2 = 0;
                int f0 = sk_vsdct_lookup(l, d0, &u0, &v0), f1 = sk_vsdct_lookup(l, d1, &u1, &v1),
                    f2 = sk_vsdct_lookup(l, d2, &u2, &v2);
                if (f0 != f1 || f0 != f2 || fabsf(u0 - u1) > 1e-6f || fabsf(u0 - u2) > 1e-6f ||
                    fabsf(v0 - v1) > 1e-6f || fabsf(v0 - v2) > 1e-6f) sbad++;
            }
            SK_CHECK_MSG(sbad == 0, "layout %d: %d lookups change when the direction is scaled", li, sbad);
        }
    }
    /* a worked example by hand: face_res 4 layout (atlas 12x8), direction
       (1, 0.5, -0.25): +X, sc = 0.25, tc = -0.5 -> s = 0.625, t = 0.25 ->
       texel (2.5, 1.0) -> u = 2.5/12, v = 1/8 */
    {
        float u = 0, v = 0;
        int f = sk_vsdct_lookup(&layouts[2], v3(1, 0.5, -0.25), &u, &v);
        SK_CHECK(layouts[2].face_res == 4);
        SK_CHECK(f == 0);
        SK_CHECK_NEAR(u * layouts[2].atlas_w, 2.5, 1e-5);
        SK_CHECK_NEAR(v * layouts[2].atlas_h, 1.0, 1e-5);
        /* -Z face (column 2, row 1): (0.5, 0.5, -1): sc = -0.5, tc = -0.5 ->
           s = t = 0.25 -> texel (8 + 1, 4 + 1) */
        f = sk_vsdct_lookup(&layouts[2], v3(0.5, 0.5, -1), &u, &v);
        SK_CHECK(f == 5);
        SK_CHECK_NEAR(u * layouts[2].atlas_w, 9.0, 1e-5);
        SK_CHECK_NEAR(v * layouts[2].atlas_h, 5.0, 1e-5);
        /* the corner (1,1,1) of the face_res 1 layout: the texel centre */
        f = sk_vsdct_lookup(&layouts[0], v3(1, 1, 1), &u, &v);
        SK_CHECK(f == 0 || f == 2 || f == 4);
        if (f >= 0) {
            SK_CHECK_NEAR(u * layouts[0].atlas_w, layouts[0].face_x[f] + 0.5, 1e-5);
            SK_CHECK_NEAR(v * layouts[0].atlas_h, layouts[0].face_y[f] + 0.5, 1e-5);
        }
    }
    /* bad input: -1, u and v untouched */
    {
        const sk_vsdct_layout *l = &layouts[3];
        float u, v;
        int f;
#define BAD_LU(dir, what) do { u = 123.0f; v = 456.0f; f = sk_vsdct_lookup(l, dir, &u, &v); \
        SK_CHECK_MSG(f == -1 && u == 123.0f && v == 456.0f, "%s: face %d u %g v %g", what, f, u, v); } while (0)
        BAD_LU(v3(0, 0, 0), "zero direction");
        BAD_LU(v3(-0.0, 0.0, -0.0), "negative zero direction");
        BAD_LU(v3(nan, 1, 0), "NaN x");
        BAD_LU(v3(0, nan, 0), "NaN y");
        BAD_LU(v3(1, 0, nan), "NaN z");
        BAD_LU(v3(inf, 0, 0), "+Inf x");
        BAD_LU(v3(0, -inf, 0), "-Inf y");
        BAD_LU(v3(inf, inf, inf), "Inf corner");
        BAD_LU(v3(1, 2, -inf), "-Inf z");
#undef BAD_LU
        u = 123.0f; v = 456.0f;
        SK_CHECK(sk_vsdct_lookup(NULL, v3(1, 0, 0), &u, &v) == -1 && u == 123.0f && v == 456.0f);
        SK_CHECK(sk_vsdct_lookup(l, v3(1, 0, 0), NULL, &v) == -1 && v == 456.0f);
        SK_CHECK(sk_vsdct_lookup(l, v3(1, 0, 0), &u, NULL) == -1 && u == 123.0f);
        /* an invalid layout: no documented result, but no garbage */
        {
            sk_vsdct_layout z;
            memset(&z, 0, sizeof z);
            u = 123.0f; v = 456.0f;
            f = sk_vsdct_lookup(&z, v3(1, 0, 0), &u, &v);
            SK_CHECK_MSG(f == -1 || (f == 0 && isfinite(u) && isfinite(v)), "zero layout: face %d u %g v %g", f, u, v);
        }
    }
}

static void test_vsdct_indirection_fill(void) {
    static const int nis[] = { 1, 2, 4, 16 };
    static const int sizes[] = { 1, 8, 100 };
    sk_vsdct_layout layouts[4];
    int nl = 0, li, ii;
    for (li = 0; li < 3; li++)
        if (sk_vsdct_layout_make(sizes[li], &layouts[nl]) == SK_OK) nl++;
    custom_layout(&layouts[nl++]);
    SK_CHECK(nl == 4);
    for (li = 0; li < nl; li++)
        for (ii = 0; ii < (int)(sizeof nis / sizeof nis[0]); ii++) {
            const sk_vsdct_layout *l = &layouts[li];
            int ni = nis[ii], f, s, t, bad = 0, bad_lu = 0, bad_inv = 0;
            size_t count = (size_t)6 * ni * ni * 2;
            unsigned short *buf = (unsigned short *)malloc(count * sizeof *buf);
            sk_result r;
            if (!buf) { SK_CHECK(buf != NULL); return; }
            memset(buf, 0xee, count * sizeof *buf);
            r = sk_vsdct_indirection_fill(l, ni, buf);
            SK_CHECK_MSG(r == SK_OK, "fill layout %d ni %d: result %d", li, ni, (int)r);
            if (r == SK_OK)
                for (f = 0; f < 6; f++)
                    for (t = 0; t < ni; t++)
                        for (s = 0; s < ni; s++) {
                            /* the texel centre's direction, from the inverse table */
                            double sc = 2.0 * (s + 0.5) / ni - 1.0, tc = 2.0 * (t + 0.5) / ni - 1.0;
                            dv3 dir = face_dir(f, sc, tc);
                            double ex, ey, es, et, ema, eu, ev;
                            size_t idx = (((size_t)f * ni + t) * ni + s) * 2;
                            float lu = 0, lv = 0;
                            int lf;
                            /* the inverse really is the table's inverse */
                            face_st(f, dir, &es, &et, &ema);
                            if (table_face(dir) != f || fabs(es - (s + 0.5) / ni) > 1e-12 || fabs(et - (t + 0.5) / ni) > 1e-12)
                                bad_inv++;
                            lookup_expect(l, f, dir, &ex, &ey);
                            eu = floor(ex / l->atlas_w * 65535.0 + 0.5);
                            ev = floor(ey / l->atlas_h * 65535.0 + 0.5);
                            if (fabs(buf[idx] - eu) > 1 || fabs(buf[idx + 1] - ev) > 1) {
                                if (!bad)
                                    printf("  fill layout %d ni %d face %d s %d t %d: (%u,%u), expected (%.0f,%.0f)\n",
                                           li, ni, f, s, t, buf[idx], buf[idx + 1], eu, ev);
                                bad++;
                            }
                            lf = sk_vsdct_lookup(l, tof(dir), &lu, &lv);
                            if (lf != f || fabs(buf[idx] - lu * 65535.0) > 1 || fabs(buf[idx + 1] - lv * 65535.0) > 1)
                                bad_lu++;
                        }
            SK_CHECK(bad_inv == 0);
            SK_CHECK_MSG(bad == 0, "fill layout %d ni %d: %d of %d texels differ from the table", li, ni, bad, 6 * ni * ni);
            SK_CHECK_MSG(bad_lu == 0, "fill layout %d ni %d: %d texels differ from sk_vsdct_lookup", li, ni, bad_lu);
            free(buf);
        }
    /* the seed's configuration: 256 faces, N_i = 16 from Eq. 5.4.7 */
    {
        sk_vsdct_layout l;
        int ni = sk_vsdct_indirection_size(256, 16, 8);
        unsigned short *buf;
        SK_CHECK(ni == 16);
        if (ni == 16 && sk_vsdct_layout_make(256, &l) == SK_OK) {
            buf = (unsigned short *)malloc((size_t)6 * ni * ni * 2 * sizeof *buf);
            if (buf) {
                SK_CHECK(sk_vsdct_indirection_fill(&l, ni, buf) == SK_OK);
                /* +X face, texel (0,0): centre s = t = 1/32 -> atlas texel 8 of 768 */
                SK_CHECK_NEAR(buf[0], floor(8.0 / 768.0 * 65535.0 + 0.5), 1);
                SK_CHECK_NEAR(buf[1], floor(8.0 / 512.0 * 65535.0 + 0.5), 1);
                free(buf);
            }
        }
    }
    /* bad input: SK_ERR_INVALID_ARG, out untouched */
    {
        unsigned short buf[6 * 4 * 4 * 2], ref[6 * 4 * 4 * 2];
        sk_vsdct_layout good, bl;
        sk_result r;
        int k;
        SK_CHECK(sk_vsdct_layout_make(8, &good) == SK_OK);
        for (k = 0; k < (int)(sizeof buf / sizeof buf[0]); k++) ref[k] = (unsigned short)(0x1234 + k);
#define BAD_FILL(lp, ni, what) do { memcpy(buf, ref, sizeof buf); r = sk_vsdct_indirection_fill(lp, ni, buf); \
        SK_CHECK_MSG(r == SK_ERR_INVALID_ARG, "%s: result %d", what, (int)r); \
        SK_CHECK_MSG(memcmp(buf, ref, sizeof buf) == 0, "%s: output written", what); } while (0)
        BAD_FILL(&good, 0, "ni 0");
        BAD_FILL(&good, -4, "ni -4");
        BAD_FILL(&good, 65537, "ni 65537");
        BAD_FILL(&good, INT_MAX, "ni INT_MAX");
        BAD_FILL(&good, INT_MIN, "ni INT_MIN");
        BAD_FILL(NULL, 4, "NULL layout");
        bl = good; bl.face_res = 0;                 BAD_FILL(&bl, 4, "face_res 0");
        bl = good; bl.face_res = -8;                BAD_FILL(&bl, 4, "face_res -8");
        bl = good; bl.atlas_w = 0;                  BAD_FILL(&bl, 4, "atlas_w 0");
        bl = good; bl.atlas_h = -16;                BAD_FILL(&bl, 4, "atlas_h -16");
        bl = good; bl.face_x[2] = bl.atlas_w - bl.face_res + 1; BAD_FILL(&bl, 4, "face 2 past the atlas's right edge");
        bl = good; bl.face_y[5] = -1;               BAD_FILL(&bl, 4, "face 5 below the atlas");
        bl = good; bl.face_y[4] = bl.atlas_h;       BAD_FILL(&bl, 4, "face 4 above the atlas");
        bl = good; bl.face_x[0] = INT_MAX;          BAD_FILL(&bl, 4, "face 0 at INT_MAX");
#undef BAD_FILL
        SK_CHECK(sk_vsdct_indirection_fill(&good, 4, NULL) == SK_ERR_INVALID_ARG);
    }
}

SK_TEST_MAIN(test_cube_face_proj_matrix, test_cube_face_view_rigid, test_cube_face_table,
             test_vsdct_depth_coeffs, test_frustum_intersects_cases, test_frustum_intersects_random,
             test_cube_visible_faces, test_caster_shadow_frustum, test_caster_visible, test_light_scissor,
             test_cube_resolution, test_vsdct_layout_make, test_vsdct_indirection_size, test_vsdct_lookup,
             test_vsdct_indirection_fill, test_vsdct_indirection_size_extremes)
