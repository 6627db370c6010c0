/* sk_ref.h - the reference geometry the CPU tests share (tests/test_core.c,
   tests/test_crops.c, tests/test_warp.c, tests/test_lspsm.c): vectors in
   double, the library's float matrices applied in double and compared
   element by element, a perspective camera built from its eye, target and
   field of view with its own corners and planes, and the exact convex clip
   of that frustum against a box. Nothing here calls the library except to
   convert its float types; each test checks shadowkit against these in
   double. CHECK_MAT_NEAR needs sk_test.h.

   Include after shadowkit.h. Everything is static inline, so a test pays
   nothing for what it does not use. */
#ifndef SK_REF_H
#define SK_REF_H

#include <math.h>
#include <string.h>

#define T_PI 3.14159265358979323846

typedef struct dv3 { double x, y, z; } dv3;
static inline dv3 dv(double x, double y, double z) { dv3 r; r.x = x; r.y = y; r.z = z; return r; }
static inline dv3 dadd(dv3 a, dv3 b) { return dv(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline dv3 dsub(dv3 a, dv3 b) { return dv(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline dv3 dmul(dv3 a, double s) { return dv(a.x * s, a.y * s, a.z * s); }
static inline double ddot(dv3 a, dv3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline dv3 dcross(dv3 a, dv3 b) { return dv(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x); }
static inline double dlen(dv3 a) { return sqrt(ddot(a, a)); }
static inline dv3 dnorm(dv3 a) { double l = dlen(a); return dmul(a, 1.0 / l); }
static inline sk_vec3 v3(float x, float y, float z) { sk_vec3 r; r.x = x; r.y = y; r.z = z; return r; }
static inline sk_vec3 tof(dv3 a) { return v3((float)a.x, (float)a.y, (float)a.z); }
static inline dv3 tod(sk_vec3 a) { return dv(a.x, a.y, a.z); }
static inline sk_aabb box3(float x0, float y0, float z0, float x1, float y1, float z1) {
    sk_aabb b; b.min = v3(x0, y0, z0); b.max = v3(x1, y1, z1); return b;
}
static inline int finite_d(double x) { return x == x && x - x == 0.0; }
static inline int all_finite_mat(const sk_mat4 *m) { int i; for (i = 0; i < 16; i++) if (!finite_d(m->m[i])) return 0; return 1; }

static inline float fnan(void) { return (float)NAN; }
static inline float finf(void) { return (float)INFINITY; }

/* M * (x,y,z,w) evaluated in double from the float matrix (column-major) */
static inline void mxv(const sk_mat4 *m, const double p[4], double o[4]) {
    int r;
    for (r = 0; r < 4; r++)
        o[r] = (double)m->m[r] * p[0] + (double)m->m[4 + r] * p[1] +
               (double)m->m[8 + r] * p[2] + (double)m->m[12 + r] * p[3];
}
/* M * p with divide, in double from the float matrix */
static inline dv3 mpoint(const sk_mat4 *m, dv3 p) {
    double in[4], o[4];
    in[0] = p.x; in[1] = p.y; in[2] = p.z; in[3] = 1.0;
    mxv(m, in, o);
    return dv(o[0] / o[3], o[1] / o[3], o[2] / o[3]);
}
static inline double pdist(const sk_plane *pl, dv3 p) {
    return (double)pl->n.x * p.x + (double)pl->n.y * p.y + (double)pl->n.z * p.z + (double)pl->d;
}
/* worst element of |M - E| against abs + rel*|E|; returns its index or -1 */
static inline int mat_worst(const sk_mat4 *m, const double *e, double rel, double abs_tol) {
    int k;
    for (k = 0; k < 16; k++) {
        double g = (double)m->m[k];
        if (!(fabs(g - e[k]) <= abs_tol + rel * fabs(e[k]))) return k;
    }
    return -1;
}
#define CHECK_MAT_NEAR(M, E, REL, ABS) do { const sk_mat4 cm_m_ = (M); \
    int cm_k_ = mat_worst(&cm_m_, (E), (REL), (ABS)); \
    SK_CHECK_MSG(cm_k_ < 0, "%s: m[%d] = %.9g, expected %.9g", #M, cm_k_, \
                 cm_k_ >= 0 ? (double)cm_m_.m[cm_k_] : 0.0, cm_k_ >= 0 ? (E)[cm_k_] : 0.0); } while (0)
/* the rotation part of a view matrix orthonormal with det +1, its last row
   0 0 0 1: the largest deviation */
static inline double rigid_error(const sk_mat4 *V) {
    dv3 r0 = dv(V->m[0], V->m[4], V->m[8]);
    dv3 r1 = dv(V->m[1], V->m[5], V->m[9]);
    dv3 r2 = dv(V->m[2], V->m[6], V->m[10]);
    double e = 0, t;
    t = fabs(ddot(r0, r0) - 1); if (t > e) e = t;
    t = fabs(ddot(r1, r1) - 1); if (t > e) e = t;
    t = fabs(ddot(r2, r2) - 1); if (t > e) e = t;
    t = fabs(ddot(r0, r1)); if (t > e) e = t;
    t = fabs(ddot(r0, r2)); if (t > e) e = t;
    t = fabs(ddot(r1, r2)); if (t > e) e = t;
    t = fabs(ddot(dcross(r0, r1), r2) - 1); if (t > e) e = t;
    t = fabs((double)V->m[3]) + fabs((double)V->m[7]) + fabs((double)V->m[11]) + fabs((double)V->m[15] - 1);
    if (t > e) e = t;
    return e;
}

/* an output struct filled with SENTINEL bytes before a call that must not
   write it */
#define SENTINEL 0xA5
static inline void fill_sentinel(void *p, size_t n) { memset(p, SENTINEL, n); }
static inline int is_sentinel(const void *p, size_t n) {
    const unsigned char *c = (const unsigned char *)p;
    size_t i;
    for (i = 0; i < n; i++) if (c[i] != SENTINEL) return 0;
    return 1;
}

/* M * (p,1) in double with a float matrix; out[4] = clip x, y, z, w */
static inline void xform(const sk_mat4 *m, dv3 p, double out[4]) {
    int r;
    for (r = 0; r < 4; r++)
        out[r] = (double)m->m[r] * p.x + (double)m->m[4 + r] * p.y + (double)m->m[8 + r] * p.z + (double)m->m[12 + r];
}

/* ------------------------------------------------------------------ camera */
typedef struct dplane { dv3 n; double d; } dplane;   /* n.p + d >= 0 inside */
typedef struct cam {
    dv3 eye, fwd, up, right;
    double fovy, aspect, zn, zf;
    dv3 corners[8];    /* this file's own, in double, in sk_frustum corner order */
    dplane planes[6];
    /* the library's view of the same camera, filled by the test that checks it */
    sk_frustum f;      /* test_lspsm: sk_mat4_perspective / look_at / sk_frustum_from_matrix */
    sk_mat4 view;      /* test_warp: sk_mat4_look_at */
} cam;

/* the plane through a, b, c, turned so that `inside` is on its inner side */
static inline dplane plane3(dv3 a, dv3 b, dv3 c, dv3 inside) {
    dplane p;
    p.n = dnorm(dcross(dsub(b, a), dsub(c, a)));
    p.d = -ddot(p.n, a);
    if (ddot(p.n, inside) + p.d < 0) { p.n = dmul(p.n, -1.0); p.d = -p.d; }
    return p;
}

/* The camera's frame, corners and inward planes, in double; f and view are
   left zero for the test to fill. Corner i: near (bit 2 clear) or far, right
   (bit 0) or left, top (bit 1) or bottom, as sk_frustum orders them. */
static inline cam cam_frame(dv3 eye, dv3 target, dv3 up_hint, double fovy, double aspect, double zn, double zf) {
    cam c;
    int i;
    dv3 centre;
    static const int face[6][3] = { {0, 2, 4}, {1, 3, 5}, {0, 1, 4}, {2, 3, 6}, {0, 1, 2}, {4, 5, 6} };
    memset(&c, 0, sizeof c);
    c.eye = eye; c.fovy = fovy; c.aspect = aspect; c.zn = zn; c.zf = zf;
    c.fwd = dnorm(dsub(target, eye));
    c.right = dnorm(dcross(c.fwd, up_hint));
    c.up = dcross(c.right, c.fwd);
    for (i = 0; i < 8; i++) {
        double d = (i & 4) ? zf : zn, h = d * tan(fovy / 2), w = h * aspect;
        c.corners[i] = dadd(dadd(dadd(eye, dmul(c.fwd, d)), dmul(c.right, (i & 1) ? w : -w)),
                            dmul(c.up, (i & 2) ? h : -h));
    }
    centre = dadd(eye, dmul(c.fwd, (zn + zf) / 2));
    for (i = 0; i < 6; i++) c.planes[i] = plane3(c.corners[face[i][0]], c.corners[face[i][1]], c.corners[face[i][2]], centre);
    return c;
}

static inline int box_planes(sk_aabb b, dplane *out) {
    out[0].n = dv(1, 0, 0);  out[0].d = -(double)b.min.x;
    out[1].n = dv(-1, 0, 0); out[1].d = b.max.x;
    out[2].n = dv(0, 1, 0);  out[2].d = -(double)b.min.y;
    out[3].n = dv(0, -1, 0); out[3].d = b.max.y;
    out[4].n = dv(0, 0, 1);  out[4].d = -(double)b.min.z;
    out[5].n = dv(0, 0, -1); out[5].d = b.max.z;
    return 6;
}

/* vertices of (frustum ∩ box), by enumerating plane triples */
static inline int clip_body(const cam *c, sk_aabb b, dv3 *out, int cap) {
    dplane pl[12];
    int np = 6, i, j, k, m, count = 0;
    for (i = 0; i < 6; i++) pl[i] = c->planes[i];
    np += box_planes(b, pl + 6);
    for (i = 0; i < np; i++)
        for (j = i + 1; j < np; j++)
            for (k = j + 1; k < np; k++) {
                dv3 jk = dcross(pl[j].n, pl[k].n), ki = dcross(pl[k].n, pl[i].n), ij = dcross(pl[i].n, pl[j].n);
                double det = ddot(pl[i].n, jk), sc;
                dv3 p;
                int ok = 1;
                if (fabs(det) < 1e-9) continue;
                p = dmul(dadd(dadd(dmul(jk, -pl[i].d), dmul(ki, -pl[j].d)), dmul(ij, -pl[k].d)), 1.0 / det);
                sc = 1.0 + dlen(p);
                for (m = 0; m < np && ok; m++) ok = ddot(pl[m].n, p) + pl[m].d >= -1e-9 * sc;
                if (ok && count < cap) out[count++] = p;
            }
    return count;
}

#endif /* SK_REF_H */
