/* tests/test_edges.c - edge cases across shadowkit.h that the per-section
   tests leave out: results that overflow float although every input is
   finite (inverse, projections, crops, convolution, PSM), matrices whose
   frustum corners lie at infinity, a box clipped by its own frustum, every
   argument of the bad-input contracts of sk_cascade_sphere, sk_lspsm_crops,
   sk_smooth_box_visibility and sk_pvsm_merge, PSM and LiSPSM invariances
   (a camera turned half a turn, body points behind the camera, more caster
   boxes than PSM keeps in post-perspective space, more body points than
   LiSPSM keeps in light space), and the degenerate inputs of the
   resolution estimate, the SMTG pyramid, the kd-tree tiles and the RMSM
   page requests.

   Expected values are derived in each test from the contract in the
   header (quoted next to the checks) or from an exact argument (a sign
   flip, a duplicate input), never copied from the library's output. */
#define SHADOWKIT_IMPLEMENTATION
#include "shadowkit.h"
#include "tests/sk_test.h"

/* ------------------------------------------------------------ helpers */
static inline sk_vec3 v3(float x, float y, float z) { sk_vec3 r; r.x = x; r.y = y; r.z = z; return r; }
static inline sk_vec2 v2(float x, float y) { sk_vec2 r; r.x = x; r.y = y; return r; }
static inline sk_aabb box3(float x0, float y0, float z0, float x1, float y1, float z1) {
    sk_aabb b; b.min = v3(x0, y0, z0); b.max = v3(x1, y1, z1); return b;
}
static inline sk_rect rect4(float x0, float y0, float x1, float y1) {
    sk_rect r; r.x0 = x0; r.y0 = y0; r.x1 = x1; r.y1 = y1; return r;
}
static inline float fnan(void) { return (float)NAN; }
static inline float finf(void) { return (float)INFINITY; }
static inline int mat_eq(const sk_mat4 *a, const sk_mat4 *b) {
    int k;
    for (k = 0; k < 16; k++) if (!(a->m[k] == b->m[k])) return 0;
    return 1;
}
static inline int is_identity(const sk_mat4 *m) {
    sk_mat4 id = sk_mat4_identity();
    return mat_eq(m, &id);
}
static inline int mat_finite(const sk_mat4 *m) {
    int k;
    for (k = 0; k < 16; k++) if (!isfinite((double)m->m[k])) return 0;
    return 1;
}
static inline int frustum_all_zero(const sk_frustum *f) {
    const float *p = &f->corners[0].x;
    int k;
    for (k = 0; k < 24; k++) if (p[k] != 0.0f) return 0;
    for (k = 0; k < 6; k++)
        if (f->planes[k].n.x != 0.0f || f->planes[k].n.y != 0.0f || f->planes[k].n.z != 0.0f ||
            f->planes[k].d != 0.0f)
            return 0;
    return 1;
}
/* light-clip position of p under m, in double (w-divided) */
static inline void clip_of(const sk_mat4 *m, sk_vec3 p, double out[3]) {
    double c[4];
    int r;
    for (r = 0; r < 4; r++)
        c[r] = (double)m->m[r] * p.x + (double)m->m[4 + r] * p.y + (double)m->m[8 + r] * p.z + m->m[12 + r];
    for (r = 0; r < 3; r++) out[r] = c[r] / c[3];
}

/* ------------------------------------------------- 1. core math */

/* "1 and *out = inverse; 0 (out untouched) if singular, non-finite or out
   NULL": an invertible matrix whose inverse does not fit in float is a
   non-finite inverse. diag(1e-39) (subnormal, finite) inverts to 1e39 > FLT_MAX. */
static void test_inverse_overflow(void) {
    sk_mat4 m, out, sentinel;
    int k;
    memset(&m, 0, sizeof m);
    m.m[0] = m.m[5] = m.m[10] = 1e-39f;
    m.m[15] = 1.0f;
    for (k = 0; k < 16; k++) sentinel.m[k] = 7.0f;
    out = sentinel;
    SK_CHECK(sk_mat4_inverse(m, &out) == 0);
    SK_CHECK(mat_eq(&out, &sentinel));
    /* control: diag(1e-19) inverts to diag(1e19), within float */
    m.m[0] = m.m[5] = m.m[10] = 1e-19f;
    SK_CHECK(sk_mat4_inverse(m, &out) == 1);
    SK_CHECK_NEAR(out.m[0] / 1e19, 1.0 / (1e-19f * 1e19), 1e-6);
    SK_CHECK_NEAR(out.m[15], 1.0, 0.0);
    SK_CHECK(out.m[1] == 0.0f && out.m[4] == 0.0f && out.m[12] == 0.0f);
}

/* Projections whose finite arguments give entries beyond float: the
   identity, as for the documented bad inputs (no function returns NaN or
   infinity in a matrix). */
static void test_projection_overflow(void) {
    sk_mat4 m;
    /* gluPerspective f = 1/tan(fovy/2) = 2e30, f/aspect = 2e50 */
    m = sk_mat4_perspective(1e-30f, 1e-20f, 1.0f, 2.0f);
    SK_CHECK(is_identity(&m));
    /* control: a narrow but representable one, m[5] = 1/tan(5e-4) */
    m = sk_mat4_perspective(1e-3f, 1.0f, 1.0f, 2.0f);
    SK_CHECK_NEAR(m.m[5], 1.0 / tan(5e-4), 1e-6 * 2000.0);
    SK_CHECK(m.m[11] == -1.0f);
    /* glOrtho 2/(r-l) = 2e39 */
    m = sk_mat4_ortho(0.0f, 1e-39f, 0.0f, 1.0f, 0.0f, 1.0f);
    SK_CHECK(is_identity(&m));
    m = sk_mat4_ortho(0.0f, 1.0f, 0.0f, 1.0f, 0.0f, 1e-39f);
    SK_CHECK(is_identity(&m));
}

/* "A singular or non-finite matrix gives an all-zero frustum, which every
   test below treats as unknown (conservatively intersecting)". An infinite
   far plane (m[10] = m[11] = -1) puts the far corners at infinity: their
   unprojected w is 0. */
static void test_frustum_corners_at_infinity(void) {
    sk_mat4 p = sk_mat4_perspective(1.0f, 1.0f, 0.1f, 10.0f), vp;
    sk_frustum f, g;
    sk_aabb far_box = box3(1000.0f, 1000.0f, 1000.0f, 1001.0f, 1001.0f, 1001.0f);
    sk_vec3 pts[SK_CLIP_MAX_POINTS];
    p.m[10] = -1.0f;
    p.m[14] = -0.2f;   /* -2 zn */
    f = sk_frustum_from_matrix(p);
    SK_CHECK(frustum_all_zero(&f));
    /* an unknown frustum intersects everything, culls no cube face */
    SK_CHECK(sk_frustum_from_aabb(far_box, &g) == SK_OK);
    SK_CHECK(sk_frustum_intersects(&f, &g) == 1);
    SK_CHECK(sk_frustum_intersects(&g, &f) == 1);
    SK_CHECK(sk_cube_visible_faces(v3(0, 0, 0), 0.1f, 10.0f, &f) == 0x3fu);
    SK_CHECK(sk_caster_visible(v3(0, 0, 0), 100.0f, box3(1, 1, 1, 2, 2, 2), &f) == 1);
    /* and is refused where a real one is required */
    SK_CHECK(sk_clip_frustum_aabb(&f, far_box, pts, SK_CLIP_MAX_POINTS) == -(int)SK_ERR_INVALID_ARG);
    SK_CHECK(sk_frustum_slice(&f, 0.1f, 10.0f, 1.0f, 2.0f, &g) == SK_ERR_INVALID_ARG);
    /* far corners beyond float: fovy near pi, far 1e30 (the far corners'
       x = 1e30 * tan(1.55) ~ 5e31 fits, the far plane's w rounds to 0) */
    vp = sk_mat4_perspective(3.1f, 1.0f, 1e-3f, 1e30f);
    SK_CHECK(mat_finite(&vp));
    f = sk_frustum_from_matrix(vp);
    SK_CHECK(frustum_all_zero(&f));
    /* far 1e38, near 1e31: w stays non-zero (m[10] = -(1 + 2e-7)), but the
       far corners' x = 1e38 tan(1.55) ~ 5e39 overflow float */
    vp = sk_mat4_perspective(3.1f, 1.0f, 1e31f, 1e38f);
    SK_CHECK(mat_finite(&vp) && vp.m[10] != -1.0f);
    f = sk_frustum_from_matrix(vp);
    SK_CHECK(frustum_all_zero(&f));
}

/* A box clipped by the frustum of the same box: every corner of each is
   on the other, so the 16 candidates collapse to the 8 corners, each once.
   The same box grown by less than the containment tolerance (1e-5 relative)
   gives 8 points too. */
static void test_clip_box_by_itself(void) {
    sk_aabb b = box3(-1.0f, 2.0f, -3.0f, 4.0f, 5.0f, 6.0f);
    sk_frustum f;
    sk_vec3 pts[SK_CLIP_MAX_POINTS];
    int n, i, j;
    SK_CHECK(sk_frustum_from_aabb(b, &f) == SK_OK);
    n = sk_clip_frustum_aabb(&f, b, pts, SK_CLIP_MAX_POINTS);
    SK_CHECK_MSG(n == 8, "n = %d", n);
    for (i = 0; i < 8; i++) {
        sk_vec3 c = v3((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z);
        int found = 0;
        for (j = 0; j < n && j < SK_CLIP_MAX_POINTS; j++)
            found += pts[j].x == c.x && pts[j].y == c.y && pts[j].z == c.z;
        SK_CHECK_MSG(found == 1, "corner %d found %d times", i, found);
    }
    /* 8 points do not fit in 7: an error, nothing dropped silently */
    SK_CHECK(sk_clip_frustum_aabb(&f, b, pts, 7) == -(int)SK_ERR_CAPACITY);
    {
        sk_aabb g = box3(-1.0f - 1e-6f, 2.0f - 1e-6f, -3.0f - 1e-6f, 4.0f + 1e-6f, 5.0f + 1e-6f, 6.0f + 1e-6f);
        n = sk_clip_frustum_aabb(&f, g, pts, SK_CLIP_MAX_POINTS);
        SK_CHECK_MSG(n == 8, "grown by 1e-6: n = %d", n);
    }
}

/* "Planes the whole edge is within tolerance of do not cut it, so faces that
   touch or coincide keep their vertices": a box [0,1]^3 and a frustum (a box)
   whose face lies 1e-6 outside the box's face x = 1 (within the 1e-5
   tolerance), then one whose face lies 1e-6 outside x = 0. The frustum's
   edges across that face start (or end) within tolerance of it, so their
   crossing parameter falls just outside [0,1] and is clamped to the end:
   the intersection is the touching face, its 4 corners, each once. */
static void test_clip_touching_faces(void) {
    sk_aabb unit = box3(0, 0, 0, 1, 1, 1);
    sk_vec3 pts[SK_CLIP_MAX_POINTS];
    int side, n, i;
    for (side = 0; side < 2; side++) {
        float x = side ? -1e-6f : 1.0f + 1e-6f;
        sk_aabb b = side ? box3(-2.0f, 0.2f, 0.2f, x, 0.8f, 0.8f) : box3(x, 0.2f, 0.2f, 3.0f, 0.8f, 0.8f);
        sk_frustum f;
        SK_CHECK(sk_frustum_from_aabb(b, &f) == SK_OK);
        n = sk_clip_frustum_aabb(&f, unit, pts, SK_CLIP_MAX_POINTS);
        SK_CHECK_MSG(n == 4, "side %d: n = %d", side, n);
        for (i = 0; i < n && i < SK_CLIP_MAX_POINTS; i++) {
            SK_CHECK_MSG(pts[i].x == x, "side %d: x = %.9g", side, pts[i].x);
            SK_CHECK((pts[i].y == 0.2f || pts[i].y == 0.8f) && (pts[i].z == 0.2f || pts[i].z == 0.8f));
        }
    }
}

/* ---------------------------------------------- 2. aliasing analysis */

/* d = ds (rs/ri) (n.v / n.l) is a ratio of lengths: a negative ds or rs
   measures nothing, and is reported as unbounded aliasing (+INFINITY), as
   ri <= 0 is. */
static void test_aliasing_negative_lengths(void) {
    SK_CHECK(sk_aliasing_error(-1.0f, 1.0f, 1.0f, 1.0f, 1.0f) == finf());
    SK_CHECK(sk_aliasing_error(1.0f, -1.0f, 1.0f, 1.0f, 1.0f) == finf());
    SK_CHECK(sk_aliasing_error(1.0f, 1.0f, -1.0f, 1.0f, 1.0f) == finf());
    /* control: 2 * (3/4) * (0.5/0.25) = 3 */
    SK_CHECK_NEAR(sk_aliasing_error(2.0f, 3.0f, 4.0f, 0.5f, 0.25f), 3.0, 1e-6);
}

/* ---------------------------------------------- 3. crops and splits */

/* "An axis with an empty or non-finite range is left as the identity",
   axis by axis; a range so small that 2/extent overflows leaves the whole
   matrix the identity (never an infinite entry). */
static void test_crop_matrix_axes(void) {
    sk_mat4 m;
    m = sk_crop_matrix(rect4(0.0f, -1.0f, finf(), 3.0f), 0.0f, 2.0f);
    SK_CHECK(m.m[0] == 1.0f && m.m[12] == 0.0f);        /* x: infinite range */
    SK_CHECK_NEAR(m.m[5], 0.5, 0.0);                     /* y: [-1,3] -> 2/4 */
    SK_CHECK_NEAR(m.m[13], -0.5, 0.0);                   /* -(3 + -1)/4 */
    SK_CHECK_NEAR(m.m[10], 1.0, 0.0);                    /* z: [0,2] */
    SK_CHECK_NEAR(m.m[14], -1.0, 0.0);
    m = sk_crop_matrix(rect4(fnan(), 0.0f, 1.0f, 1.0f), fnan(), 1.0f);
    SK_CHECK(m.m[0] == 1.0f && m.m[12] == 0.0f && m.m[10] == 1.0f && m.m[14] == 0.0f);
    SK_CHECK_NEAR(m.m[5], 2.0, 0.0);
    m = sk_crop_matrix(rect4(0.0f, 0.0f, 1.0f, 1.0f), 0.0f, finf());
    SK_CHECK(m.m[10] == 1.0f && m.m[14] == 0.0f);
    m = sk_crop_matrix(rect4(0.0f, 0.0f, 1.0f, 1.0f), 2.0f, 1.0f);   /* empty z range */
    SK_CHECK(m.m[10] == 1.0f && m.m[14] == 0.0f);
    SK_CHECK_NEAR(m.m[0], 2.0, 0.0);
    /* an x range too thin for float: x left alone, y and z still cropped */
    m = sk_crop_matrix(rect4(0.0f, 0.0f, 1e-39f, 1.0f), -1.0f, 1.0f);
    SK_CHECK(m.m[0] == 1.0f && m.m[12] == 0.0f);
    SK_CHECK_NEAR(m.m[5], 2.0, 0.0);
    SK_CHECK_NEAR(m.m[13], -1.0, 0.0);
    SK_CHECK(m.m[10] == 1.0f && m.m[14] == 0.0f);
}

/* sk_frustum_bounding_sphere of a hexahedron whose near face is far larger
   than its far face: the point on the axis where the farthest near and far
   corners are equidistant lies before the near face, so the centre stays
   on the near face's centre; the radius is then the near half-diagonal,
   rounded up by at most 2^-9 of itself, and every corner is inside. */
static void test_bounding_sphere_wide_near_face(void) {
    sk_vec3 c[8];
    sk_frustum f;
    sk_sphere s;
    int i;
    double r = 10.0 * sqrt(2.0);
    for (i = 0; i < 8; i++) {
        float h = (i & 4) ? 1.0f : 10.0f, z = (i & 4) ? -2.0f : -1.0f;
        c[i] = v3((i & 1) ? h : -h, (i & 2) ? h : -h, z);
    }
    SK_CHECK(sk_frustum_from_corners(c, &f) == SK_OK);
    s = sk_frustum_bounding_sphere(&f);
    SK_CHECK_NEAR(s.c.x, 0.0, 0.0);
    SK_CHECK_NEAR(s.c.y, 0.0, 0.0);
    SK_CHECK_NEAR(s.c.z, -1.0, 0.0);
    SK_CHECK_MSG(s.r >= r && s.r <= r * (1.0 + 1.0 / 512.0), "r = %.9g, half-diagonal %.9g", s.r, r);
    for (i = 0; i < 8; i++) {
        double dx = c[i].x - s.c.x, dy = c[i].y - s.c.y, dz = c[i].z - s.c.z;
        SK_CHECK(sqrt(dx * dx + dy * dy + dz * dz) <= s.r);
    }
}

/* "Bad input: a zero sphere (r = 0)", for each argument in turn. */
static void test_cascade_sphere_bad_input(void) {
    sk_mat4 v = sk_mat4_identity(), bad = sk_mat4_identity();
    const float PI_F = 3.14159274f;   /* float(pi) > pi */
    struct { sk_mat4 v; float fovy, aspect, d0, d1; const char *what; } cases[12];
    int i, n = 0;
    sk_sphere s;
    bad.m[13] = fnan();
#define CASE(V, F, A, D0, D1, W) do { cases[n].v = (V); cases[n].fovy = (F); cases[n].aspect = (A); \
    cases[n].d0 = (D0); cases[n].d1 = (D1); cases[n].what = (W); n++; } while (0)
    CASE(bad, 1.0f, 1.0f, 1.0f, 2.0f, "NaN view");
    CASE(v, fnan(), 1.0f, 1.0f, 2.0f, "NaN fovy");
    CASE(v, 1.0f, finf(), 1.0f, 2.0f, "infinite aspect");
    CASE(v, 1.0f, 1.0f, fnan(), 2.0f, "NaN d0");
    CASE(v, 1.0f, 1.0f, 1.0f, finf(), "infinite d1");
    CASE(v, 0.0f, 1.0f, 1.0f, 2.0f, "fovy 0");
    CASE(v, PI_F, 1.0f, 1.0f, 2.0f, "fovy pi");
    CASE(v, 1.0f, 0.0f, 1.0f, 2.0f, "aspect 0");
    CASE(v, 1.0f, 1.0f, -1.0f, 2.0f, "d0 < 0");
    CASE(v, 1.0f, 1.0f, 2.0f, 2.0f, "d1 == d0");
    CASE(v, 1.0f, 1.0f, 3.0f, 2.0f, "d1 < d0");
#undef CASE
    for (i = 0; i < n; i++) {
        s = sk_cascade_sphere(cases[i].v, cases[i].fovy, cases[i].aspect, cases[i].d0, cases[i].d1);
        SK_CHECK_MSG(s.r == 0.0f && s.c.x == 0.0f && s.c.y == 0.0f && s.c.z == 0.0f, "%s: r = %g",
                     cases[i].what, s.r);
    }
    /* control: d0 = 0 is allowed; fovy pi/2, aspect 1, [0, 1]: the far
       half-diagonal sqrt(2) is the radius, the centre at the far face */
    s = sk_cascade_sphere(v, 1.5707964f, 1.0f, 0.0f, 1.0f);
    SK_CHECK_NEAR(s.r, sqrt(2.0) * (1.0 + 1e-4), 1e-6);
    SK_CHECK_NEAR(s.c.z, -1.0, 1e-6);
}

/* ---------------------------------------------- 4. PSM and LiSPSM */

static sk_psm_desc psm_base(void) {
    sk_psm_desc d;
    memset(&d, 0, sizeof d);
    d.cam_view = sk_mat4_look_at(v3(0, 0, 0), v3(0, 0, -1), v3(0, 1, 0));
    d.fovy = 1.0f;
    d.aspect = 1.25f;
    d.zn = 0.5f;
    d.zf = 50.0f;
    d.light_dir = v3(0.3f, -1.0f, -0.4f);
    return d;
}

/* The scene turned half a turn about y (x -> -x, z -> -z), the camera with
   it: eye space is the same to the bit (every change is a sign flip), so the
   slide is the same, and the light matrix is the first one times that turn:
   columns 0 and 2 negated, 1 and 3 equal. The camera looking down +z makes
   the caster's nearest corner its min z, where looking down -z it is its
   max z. */
static void test_psm_half_turn(void) {
    sk_psm_desc a = psm_base(), b;
    sk_psm_result ra, rb;
    sk_aabb ca[2], cb[2];
    int i, k;
    ca[0] = box3(-1.0f, -2.0f, 1.0f, 1.0f, 0.0f, 3.0f);      /* behind the camera */
    ca[1] = box3(2.0f, -1.0f, -10.0f, 3.0f, 1.0f, -8.0f);
    for (i = 0; i < 2; i++) cb[i] = box3(-ca[i].max.x, ca[i].min.y, -ca[i].max.z, -ca[i].min.x, ca[i].max.y, -ca[i].min.z);
    a.casters = ca;
    a.caster_count = 2;
    b = a;
    b.cam_view = sk_mat4_look_at(v3(0, 0, 0), v3(0, 0, 1), v3(0, 1, 0));
    b.light_dir = v3(-a.light_dir.x, a.light_dir.y, -a.light_dir.z);
    b.casters = cb;
    SK_CHECK(sk_psm_matrices(&a, &ra) == SK_OK);
    SK_CHECK(sk_psm_matrices(&b, &rb) == SK_OK);
    SK_CHECK(ra.slide > 0.0f);
    SK_CHECK(ra.slide == rb.slide);
    SK_CHECK(ra.inverted == rb.inverted && ra.orthographic == rb.orthographic);
    for (k = 0; k < 16; k++) {
        float sgn = (k / 4 == 0 || k / 4 == 2) ? -1.0f : 1.0f;
        SK_CHECK_MSG(rb.light_view_proj.m[k] == sgn * ra.light_view_proj.m[k], "m[%d]: %.9g vs %.9g", k,
                     rb.light_view_proj.m[k], sgn * ra.light_view_proj.m[k]);
    }
}

/* Body points behind the camera have no post-perspective image and are
   left out of the fit: adding one changes nothing. Body points beyond the
   view frustum are clamped to its unit cube: a box around the whole view
   frustum (seen from inside, with its near corners behind the near plane)
   fits the cube, as no body at all does. */
static void test_psm_body_outside_view(void) {
    sk_psm_desc d = psm_base();
    sk_psm_result r0, r1, r2;
    sk_vec3 body[9];
    int i;
    for (i = 0; i < 8; i++)
        body[i] = v3((i & 1) ? 2.0f : -2.0f, (i & 2) ? 1.0f : -1.0f, (i & 4) ? -20.0f : -5.0f);
    d.body = body;
    d.body_count = 8;
    SK_CHECK(sk_psm_matrices(&d, &r0) == SK_OK);
    body[8] = v3(0.5f, 0.5f, 4.0f);   /* behind the eye (looking down -z) */
    d.body_count = 9;
    SK_CHECK(sk_psm_matrices(&d, &r1) == SK_OK);
    SK_CHECK(mat_eq(&r0.light_view_proj, &r1.light_view_proj));
    /* the surrounding box: x, y far beyond the frustum, z from just in
       front of the eye (inside the near plane) to beyond the far plane */
    for (i = 0; i < 8; i++)
        body[i] = v3((i & 1) ? 1e3f : -1e3f, (i & 2) ? 1e3f : -1e3f, (i & 4) ? -0.1f : -1e3f);
    d.body_count = 8;
    SK_CHECK(sk_psm_matrices(&d, &r1) == SK_OK);
    d.body = NULL;
    d.body_count = 0;
    SK_CHECK(sk_psm_matrices(&d, &r2) == SK_OK);
    SK_CHECK(mat_eq(&r1.light_view_proj, &r2.light_view_proj));
}

/* More caster boxes than PSM keeps transformed (32): the corners are then
   transformed as they are needed, with the same sums of the same products,
   so 40 copies of one box give the result of that one box, to the bit; with
   the light perpendicular to the view (orthographic in post-perspective
   space) and oblique to it. */
static void test_psm_many_casters(void) {
    sk_aabb many[40];
    int i, pass;
    for (i = 0; i < 40; i++) many[i] = box3(-1.0f, 3.0f, 2.0f, 1.0f, 4.0f, 3.0f);   /* behind, above */
    for (pass = 0; pass < 2; pass++) {
        sk_psm_desc d = psm_base();
        sk_psm_result r1, r40;
        if (pass == 0) d.light_dir = v3(1.0f, -0.5f, 0.0f);   /* perpendicular to -z */
        d.casters = many;
        d.caster_count = 1;
        SK_CHECK(sk_psm_matrices(&d, &r1) == SK_OK);
        d.caster_count = 40;
        SK_CHECK(sk_psm_matrices(&d, &r40) == SK_OK);
        SK_CHECK_MSG(r1.orthographic == (pass == 0), "pass %d: orthographic %d", pass, r1.orthographic);
        SK_CHECK(r1.slide > 0.0f && r1.slide == r40.slide);
        SK_CHECK_MSG(mat_eq(&r1.light_view_proj, &r40.light_view_proj), "pass %d", pass);
        SK_CHECK(mat_finite(&r40.light_view_proj));
    }
}

/* With the light perpendicular to the view the map is orthographic in
   post-perspective space, fitted to the unit cube, and a caster box only
   widens its depth range: a caster inside the view frustum (inside the
   cube) leaves the map as it is, to rounding (the depth scale is recomputed
   from the range), and its corners have depths inside [-1,1]. */
static void test_psm_ortho_caster_inside(void) {
    sk_psm_desc d = psm_base();
    sk_psm_result r0, r1;
    sk_aabb c = box3(2.0f, -1.0f, -10.0f, 3.0f, 1.0f, -8.0f);
    double scale = 0.0;
    int k;
    d.light_dir = v3(1.0f, -0.5f, 0.0f);
    SK_CHECK(sk_psm_matrices(&d, &r0) == SK_OK);
    d.casters = &c;
    d.caster_count = 1;
    SK_CHECK(sk_psm_matrices(&d, &r1) == SK_OK);
    SK_CHECK(r0.orthographic == 1 && r1.orthographic == 1 && r1.slide == 0.0f);
    for (k = 0; k < 16; k++) if (fabs(r0.light_view_proj.m[k]) > scale) scale = fabs(r0.light_view_proj.m[k]);
    for (k = 0; k < 16; k++)
        SK_CHECK_NEAR(r1.light_view_proj.m[k], r0.light_view_proj.m[k], 1e-5 * scale);
    for (k = 0; k < 8; k++) {
        double q[3];
        clip_of(&r1.light_view_proj, v3((k & 1) ? c.max.x : c.min.x, (k & 2) ? c.max.y : c.min.y,
                                        (k & 4) ? c.max.z : c.min.z), q);
        SK_CHECK_MSG(fabs(q[2]) <= 1.0, "corner %d depth %g", k, q[2]);
    }
    /* a caster downstream of the view along the light (x = 30 and beyond,
       the light travelling +x): the depth range is widened to take it */
    c = box3(30.0f, -1.0f, -10.0f, 31.0f, 1.0f, -8.0f);
    SK_CHECK(sk_psm_matrices(&d, &r1) == SK_OK);
    SK_CHECK(r1.orthographic == 1);
    for (k = 0; k < 8; k++) {
        double q[3];
        clip_of(&r1.light_view_proj, v3((k & 1) ? c.max.x : c.min.x, (k & 2) ? c.max.y : c.min.y,
                                        (k & 4) ? c.max.z : c.min.z), q);
        SK_CHECK_MSG(fabs(q[2]) <= 1.0 + 1e-6, "downstream corner %d depth %g", k, q[2]);
    }
}

/* PSM where no light frustum exists or the chain overflows: an error, never
   a matrix with NaN. (a) far/near = 1e9: the post-perspective light lies on
   z = (f+n)/(f-n), which rounds to 1 in float, on the face of the unit cube
   the map must cover. (b) a finite camera matrix scaled by 3e38: its
   product with the projection overflows. */
static void test_psm_degenerate(void) {
    sk_psm_desc d = psm_base();
    sk_psm_result r;
    d.zn = 0.01f;
    d.zf = 1e7f;
    d.light_dir = v3(0.3f, 0.3f, 1.0f);
    SK_CHECK(sk_psm_matrices(&d, &r) == SK_ERR_DEGENERATE);
    /* control: far/near 1e3 */
    d.zf = 10.0f;
    SK_CHECK(sk_psm_matrices(&d, &r) == SK_OK);
    SK_CHECK(mat_finite(&r.light_view_proj));
    d = psm_base();
    d.cam_view.m[0] = d.cam_view.m[5] = d.cam_view.m[10] = 3e38f;
    SK_CHECK(sk_psm_matrices(&d, &r) == SK_ERR_DEGENERATE);
}

/* LiSPSM keeps the light-space image of the first SK_CLIP_MAX_POINTS body
   points and transforms the rest again when it needs them: a body of the 8
   corners of a box plus 292 points strictly inside it gives the matrix of
   the 8 corners alone (the extremes are the corners', and the warp maps the
   inside of the box into the inside of its image). */
static void test_lispsm_large_body(void) {
    sk_vec3 body[300];
    sk_lispsm_desc d;
    sk_lispsm_result r8, r300;
    int i;
    for (i = 0; i < 8; i++)
        body[i] = v3((i & 1) ? 10.0f : -10.0f, (i & 2) ? 2.0f : 0.0f, (i & 4) ? -1.0f : -30.0f);
    for (i = 8; i < 300; i++) {
        /* points of the box shrunk by 0.8 about its centre (0, 1, -15.5) */
        double a = (i % 17) / 16.0, b = (i % 7) / 6.0, c = (i % 13) / 12.0;
        body[i] = v3((float)(0.8 * (-10.0 + 20.0 * a)), (float)(1.0 + 0.8 * (-1.0 + 2.0 * b)),
                     (float)(-15.5 + 0.8 * (-14.5 + 29.0 * c)));
    }
    memset(&d, 0, sizeof d);
    d.eye = v3(0.0f, 1.0f, 0.0f);
    d.view_dir = v3(0.0f, 0.0f, -1.0f);
    d.zn = 0.5f;
    d.light_dir = v3(0.2f, -1.0f, 0.3f);
    d.body = body;
    d.body_count = 8;
    SK_CHECK(sk_lispsm_matrices(&d, &r8) == SK_OK);
    d.body_count = 300;
    SK_CHECK(sk_lispsm_matrices(&d, &r300) == SK_OK);
    SK_CHECK(r8.warped == 1 && r300.warped == 1);
    SK_CHECK(r8.n == r300.n);
    SK_CHECK(mat_eq(&r8.light_view_proj, &r300.light_view_proj));
    /* every body point lands in the map */
    for (i = 0; i < 300; i++) {
        double c[3];
        clip_of(&r300.light_view_proj, body[i], c);
        SK_CHECK_MSG(fabs(c[0]) <= 1.0 + 1e-5 && fabs(c[1]) <= 1.0 + 1e-5 && fabs(c[2]) <= 1.0 + 1e-5,
                     "point %d at %g %g %g", i, c[0], c[1], c[2]);
    }
}

/* A body with no depth along the warp axis (d = 0): "beyond n > 1e4 * d the
   uniform map is used directly", so a flat body gets the uniform focused
   map (warped 0, n +INFINITY) covering it. The view looks down -z, the light
   down -y: the warp axis is -z, and the body is the square z = -10. */
static void test_lispsm_flat_body(void) {
    sk_vec3 body[4];
    sk_lispsm_desc d;
    sk_lispsm_result r;
    int i;
    for (i = 0; i < 4; i++) body[i] = v3((i & 1) ? 5.0f : -5.0f, (i & 2) ? 2.0f : 0.0f, -10.0f);
    memset(&d, 0, sizeof d);
    d.eye = v3(0.0f, 1.0f, 0.0f);
    d.view_dir = v3(0.0f, 0.0f, -1.0f);
    d.zn = 0.5f;
    d.light_dir = v3(0.0f, -1.0f, 0.0f);
    d.body = body;
    d.body_count = 4;
    SK_CHECK(sk_lispsm_matrices(&d, &r) == SK_OK);
    SK_CHECK(r.warped == 0);
    SK_CHECK(r.n == finf());
    SK_CHECK_NEAR(r.sin_gamma, 1.0, 1e-6);
    SK_CHECK(mat_finite(&r.light_view_proj));
    for (i = 0; i < 4; i++) {
        double c[3];
        clip_of(&r.light_view_proj, body[i], c);
        SK_CHECK_MSG(fabs(c[0]) <= 1.0 + 1e-5 && fabs(c[1]) <= 1.0 + 1e-5 && fabs(c[2]) <= 1.0 + 1e-5,
                     "point %d at %g %g %g", i, c[0], c[1], c[2]);
    }
}

/* ----------------------------------------------------------- 5. LSPSM */

static sk_lspsm_region lspsm_region(void) {
    sk_lspsm_region r;
    memset(&r, 0, sizeof r);
    r.light_view = sk_mat4_identity();
    r.n = 2.0f;
    r.L = 10.0f;
    r.theta = 0.3f;
    r.zmin = -5.0f;
    r.zmax = 5.0f;
    return r;
}

/* "Returns the count, or -sk_result as sk_lspsm_partition": every field of
   the region is checked, each bad one alone gives -SK_ERR_INVALID_ARG and
   writes nothing. */
static void test_lspsm_crops_bad_region(void) {
    sk_lspsm_params p = sk_lspsm_default_params(), bp = p;
    sk_mat4 vps[16], sentinel = sk_mat4_identity();
    sk_rect rects[16];
    sk_lspsm_region r;
    int i, k, got;
    sentinel.m[1] = 42.0f;
    for (k = 0; k < 17; k++) {
        const char *what = "";
        r = lspsm_region();
        switch (k) {
        case 0: r.light_view.m[3] = fnan(); what = "NaN light_view"; break;
        case 1: r.n = fnan(); what = "NaN n"; break;
        case 2: r.L = finf(); what = "infinite L"; break;
        case 3: r.theta = fnan(); what = "NaN theta"; break;
        case 4: r.n = 0.0f; what = "n = 0"; break;
        case 5: r.L = -1.0f; what = "L < 0"; break;
        case 6: r.theta = -0.1f; what = "theta < 0"; break;
        case 7: r.theta = 1.5707964f; what = "theta = pi/2"; break;
        case 8: r.zmin = fnan(); what = "NaN zmin"; break;
        case 9: r.zmax = finf(); what = "infinite zmax"; break;
        case 10: r.origin.x = fnan(); what = "NaN origin.x"; break;
        case 11: r.origin.y = finf(); what = "infinite origin.y"; break;
        default: break;
        }
        for (i = 0; i < 16; i++) vps[i] = sentinel;
        switch (k) {
        case 12: got = sk_lspsm_crops(NULL, &p, vps, rects, 16); what = "NULL region"; break;
        case 13: got = sk_lspsm_crops(&r, &p, NULL, rects, 16); what = "NULL matrices"; break;
        case 14: got = sk_lspsm_crops(&r, &p, vps, rects, -1); what = "cap < 0"; break;
        case 15: got = sk_lspsm_crops(&r, NULL, vps, rects, 16); what = "NULL params"; break;
        case 16: bp.h_max = 0; got = sk_lspsm_crops(&r, &bp, vps, rects, 16); what = "h_max 0"; break;
        default: got = sk_lspsm_crops(&r, &p, vps, rects, 16); break;
        }
        SK_CHECK_MSG(got == -(int)SK_ERR_INVALID_ARG, "%s: %d", what, got);
        SK_CHECK_MSG(mat_eq(&vps[0], &sentinel), "%s: wrote a matrix", what);
    }
    /* a fallback region is one crop: cap 0 cannot take it */
    r = lspsm_region();
    r.fallback = 1;
    SK_CHECK(sk_lspsm_crops(&r, &p, vps, rects, 0) == -(int)SK_ERR_CAPACITY);
    SK_CHECK(sk_lspsm_crops(&r, &p, vps, NULL, 1) == 1);
    SK_CHECK(mat_finite(&vps[0]));
}

/* Receivers that are one point of the view: the region has no extent, it
   falls back to one focused map of a small positive size around that point,
   which lands inside it. */
static void test_lspsm_point_region(void) {
    sk_mat4 vp = sk_mat4_mul(sk_mat4_perspective(1.0f, 1.0f, 0.5f, 50.0f),
                             sk_mat4_look_at(v3(0, 5, 10), v3(0, 0, 0), v3(0, 1, 0)));
    sk_frustum view = sk_frustum_from_matrix(vp);
    sk_aabb pt = box3(0.5f, 0.25f, -1.0f, 0.5f, 0.25f, -1.0f);
    sk_lspsm_region r;
    sk_lspsm_params p = sk_lspsm_default_params();
    sk_mat4 vps[4];
    double c[3];
    int n;
    SK_CHECK(sk_lspsm_region_extract(&view, v3(0, -5, -10), pt, NULL, v3(0.5f, -1.0f, 0.2f), &r) == SK_OK);
    SK_CHECK(r.fallback == 1);
    SK_CHECK(r.n > 0.0f && r.L > 0.0f && isfinite(r.n) && isfinite(r.L));
    SK_CHECK(r.n < 1e-4f && r.L < 1e-4f);
    n = sk_lspsm_crops(&r, &p, vps, NULL, 4);
    SK_CHECK(n == 1);
    clip_of(&vps[0], pt.min, c);
    SK_CHECK_MSG(fabs(c[0]) <= 1.0 && fabs(c[1]) <= 1.0 && fabs(c[2]) <= 1.0, "at %g %g %g", c[0], c[1], c[2]);
}

/* Receivers that project onto the trapezoid's axis (a segment along the
   view direction, light from above): the region has a length but no width,
   so the trapezoid's bases would be 0 (n = 0, which sk_lspsm_crops refuses).
   It falls back to one focused map, as a region of no length does, and that
   map covers the segment. The same for a box 1e-7 wide. */
static void test_lspsm_zero_width_region(void) {
    sk_mat4 vp = sk_mat4_mul(sk_mat4_perspective(1.0f, 1.0f, 0.5f, 50.0f),
                             sk_mat4_look_at(v3(0, 5, 10), v3(0, 0, 0), v3(0, 1, 0)));
    sk_frustum view = sk_frustum_from_matrix(vp);
    sk_lspsm_params p = sk_lspsm_default_params();
    int pass;
    for (pass = 0; pass < 2; pass++) {
        float w = pass ? 1e-7f : 0.0f;
        sk_aabb seg = box3(0.0f, 0.0f, -5.0f, w, 0.0f, 3.0f);
        sk_lspsm_region r;
        sk_mat4 vps[16];
        int n, k;
        SK_CHECK(sk_lspsm_region_extract(&view, v3(0, -5, -10), seg, NULL, v3(0, -1, 0), &r) == SK_OK);
        SK_CHECK_MSG(r.fallback == 1, "width %g: fallback %d", w, r.fallback);
        SK_CHECK_MSG(r.n > 0.0f && r.L > 7.9f && r.L < 8.1f, "width %g: n %g L %g", w, r.n, r.L);
        n = sk_lspsm_crops(&r, &p, vps, NULL, 16);
        SK_CHECK_MSG(n == 1, "width %g: %d crops", w, n);
        for (k = 0; k < 8 && n == 1; k++) {
            double c[3];
            clip_of(&vps[0], v3((k & 1) ? seg.max.x : seg.min.x, 0.0f, (k & 4) ? seg.max.z : seg.min.z), c);
            SK_CHECK_MSG(fabs(c[0]) <= 1.0 + 1e-5 && fabs(c[1]) <= 1.0 + 1e-5 && fabs(c[2]) <= 1.0 + 1e-5,
                         "width %g: corner %d at %g %g %g", w, k, c[0], c[1], c[2]);
        }
    }
}

/* "all are tried, the smallest t winning ties": receivers that are a
   segment at 45 degrees to the trapezoid's axis in the light plane (a
   segment along world z, the light straight down, the view's projection
   on the ground along (1, 0, -1)). The rectangle around it (t = 0, n = W)
   and the triangle along it (t = W / L, n = 0) have the same area L W;
   the rectangle is chosen. Here W = L = 6 / sqrt(2). */
static void test_lspsm_area_tie(void) {
    sk_mat4 vp = sk_mat4_mul(sk_mat4_perspective(1.0f, 1.0f, 0.5f, 50.0f),
                             sk_mat4_look_at(v3(-8, 6, 8), v3(0, 0, 0), v3(0, 1, 0)));
    sk_frustum view = sk_frustum_from_matrix(vp);
    sk_aabb seg = box3(0.0f, 0.0f, -4.0f, 0.0f, 0.0f, 2.0f);
    sk_lspsm_region r;
    sk_lspsm_params p = sk_lspsm_default_params();
    sk_mat4 vps[16];
    double w = 6.0 / sqrt(2.0);
    int n, e, k;
    SK_CHECK(sk_lspsm_region_extract(&view, v3(8, -6, -8), seg, NULL, v3(0, -1, 0), &r) == SK_OK);
    SK_CHECK(r.fallback == 0);
    SK_CHECK(r.theta == 0.0f);
    SK_CHECK_NEAR(r.n, w, 1e-5);
    SK_CHECK_NEAR(r.L, w, 1e-5);
    n = sk_lspsm_crops(&r, &p, vps, NULL, 16);
    SK_CHECK(n >= 1);
    /* each end of the segment lies in some crop */
    for (e = 0; e < 2; e++) {
        sk_vec3 q = e ? seg.max : seg.min;
        int inside = 0;
        for (k = 0; k < n && k < 16; k++) {
            double c[3];
            clip_of(&vps[k], q, c);
            inside |= fabs(c[0]) <= 1.0 + 1e-5 && fabs(c[1]) <= 1.0 + 1e-5 && fabs(c[2]) <= 1.0 + 1e-5;
        }
        SK_CHECK_MSG(inside, "end %d in no crop", e);
    }
}

/* -------------------------------------------- 6. omnidirectional lights */

/* sk_vsdct_lookup and sk_vsdct_indirection_fill refuse a layout whose face
   does not lie inside the atlas, on either axis and at either end. */
static void test_vsdct_bad_layout(void) {
    sk_vsdct_layout good, l;
    unsigned short buf[6 * 2 * 2 * 2];
    float u = 5.0f, v = 5.0f;
    int k;
    SK_CHECK(sk_vsdct_layout_make(8, &good) == SK_OK);
    for (k = 0; k < 6; k++) {
        l = good;
        switch (k) {
        case 0: l.face_x[2] = -1; break;
        case 1: l.face_y[4] = -1; break;
        case 2: l.face_x[5] = l.atlas_w - l.face_res + 1; break;
        case 3: l.face_y[3] = l.atlas_h - l.face_res + 1; break;
        case 4: l.atlas_h = l.face_res - 1; break;
        default: l.face_res = 0; break;
        }
        SK_CHECK_MSG(sk_vsdct_lookup(&l, v3(1, 0.2f, 0.1f), &u, &v) == -1, "case %d", k);
        SK_CHECK_MSG(sk_vsdct_indirection_fill(&l, 2, buf) == SK_ERR_INVALID_ARG, "case %d", k);
    }
    SK_CHECK(u == 5.0f && v == 5.0f);
    /* control: the largest valid offsets */
    l = good;
    l.face_x[5] = l.atlas_w - l.face_res;
    l.face_y[3] = l.atlas_h - l.face_res;
    SK_CHECK(sk_vsdct_lookup(&l, v3(1, 0.2f, 0.1f), &u, &v) == 0);
}

/* ------------------------------------------ 7. resolution estimation */

/* A camera's inverse view-projection and its negation are the same
   projective map (every homogeneous point flips sign, w included); the
   estimate makes each point's w positive first, so both give the same
   result, to the bit. */
static void test_resest_negated_inverse(void) {
    enum { W = 24, H = 16 };
    float depth[W * H];
    sk_mat4 cam = sk_mat4_mul(sk_mat4_perspective(1.0f, 1.5f, 0.5f, 40.0f),
                              sk_mat4_look_at(v3(0, 6, 8), v3(0, 0, 0), v3(0, 1, 0)));
    sk_mat4 inv, neg, light;
    sk_res_estimate a, b;
    int i;
    SK_CHECK(sk_mat4_inverse(cam, &inv) == 1);
    for (i = 0; i < 16; i++) neg.m[i] = -inv.m[i];
    light = sk_mat4_mul(sk_mat4_ortho(-10, 10, -10, 10, -30, 30),
                        sk_light_view_directional(v3(0.3f, -1.0f, 0.2f)));
    for (i = 0; i < W * H; i++) depth[i] = (i % 5 == 0) ? 1.0f : 0.9f + 0.004f * (float)(i % 17);
    SK_CHECK(sk_estimate_resolution(depth, W, H, inv, light, 2048, &a) == SK_OK);
    SK_CHECK(sk_estimate_resolution(depth, W, H, neg, light, 2048, &b) == SK_OK);
    SK_CHECK(a.samples > 0);
    SK_CHECK(a.samples == b.samples && a.width == b.width && a.height == b.height);
    SK_CHECK(a.texel_w == b.texel_w && a.texel_h == b.texel_h);
    SK_CHECK(a.bounds.x0 == b.bounds.x0 && a.bounds.x1 == b.bounds.x1 && a.bounds.y0 == b.bounds.y0 &&
             a.bounds.y1 == b.bounds.y1);
}

/* "If no patch has all four corners in front of the light, the texel size
   is the bounds over max_res (so the map is max_res wide)": one pixel of an
   orthographic camera over the ground square [-1,1]^2 (y = 0), seen by a
   wide perspective light at (-0.5, 0.5, 0) looking along +x: the pixel's
   centre (the origin) is 0.5 in front of the light, its corners at x = -1
   are 0.5 behind it. */
static void test_resest_no_patch(void) {
    float depth[1];
    sk_mat4 cam = sk_mat4_mul(sk_mat4_ortho(-1, 1, -1, 1, 1, 3),
                              sk_mat4_look_at(v3(0, 2, 0), v3(0, 0, 0), v3(0, 0, -1)));
    sk_mat4 light = sk_mat4_mul(sk_mat4_perspective(3.0f, 1.0f, 0.1f, 10.0f),
                                sk_mat4_look_at(v3(-0.5f, 0.5f, 0.0f), v3(1.0f, 0.5f, 0.0f), v3(0, 1, 0)));
    sk_mat4 inv;
    sk_res_estimate e;
    SK_CHECK(sk_mat4_inverse(cam, &inv) == 1);
    depth[0] = 0.5f;   /* window depth of y = 0: halfway between y = 1 and y = -1 */
    SK_CHECK(sk_estimate_resolution(depth, 1, 1, inv, light, 512, &e) == SK_OK);
    SK_CHECK(e.samples == 1);
    SK_CHECK(e.width == 512 && e.height == 512);
    SK_CHECK(e.texel_w == 0.0f && e.texel_h == 0.0f);   /* one sample: bounds of zero extent */
    SK_CHECK(e.bounds.x0 == e.bounds.x1 && e.bounds.y0 == e.bounds.y1);
}

/* --------------------------------------------------------------- 8. PVSM */

/* Finite half-axes whose variance overflows float: "non-finite input gives
   zero axes" applies to the non-finite result as well; never infinity. */
static void test_convolve_overflow(void) {
    sk_vec2 u, v;
    sk_convolve_parallelograms(v2(3e38f, 0.0f), v2(0.0f, 1.0f), v2(3e38f, 0.0f), v2(0.0f, 1.0f), &u, &v);
    SK_CHECK(u.x == 0.0f && u.y == 0.0f && v.x == 0.0f && v.y == 0.0f);
    sk_convolve_parallelograms(v2(1.0f, 0.0f), v2(0.0f, 3e38f), v2(1.0f, 0.0f), v2(0.0f, 3e38f), &u, &v);
    SK_CHECK(u.x == 0.0f && u.y == 0.0f && v.x == 0.0f && v.y == 0.0f);
    /* u_out.y = m10 / u_out.x: a tiny x against a huge y */
    sk_convolve_parallelograms(v2(1e-20f, 3e38f), v2(1e-20f, 3e38f), v2(0, 0), v2(0, 0), &u, &v);
    SK_CHECK(u.x == 0.0f && u.y == 0.0f && v.x == 0.0f && v.y == 0.0f);
    /* control: axes (3,0),(0,4) twice: sqrt(18), sqrt(32) */
    sk_convolve_parallelograms(v2(3, 0), v2(0, 4), v2(3, 0), v2(0, 4), &u, &v);
    SK_CHECK_NEAR(u.x, sqrt(18.0), 1e-6);
    SK_CHECK_NEAR(v.y, sqrt(32.0), 1e-6);
}

static int lit_left(void *user, int tx, int ty) { (void)user; (void)ty; return tx < 0; }

/* "a larger box returns -1", as does every non-finite coordinate, one of
   magnitude beyond 1e9 (texel indices past int) and a NULL callback; an
   empty box on either axis is the lit value of the texel at its centre. */
static void test_smooth_visibility_bad_input(void) {
    SK_CHECK(sk_smooth_box_visibility(0, 0, 1, 1, NULL, NULL) == -1.0f);
    SK_CHECK(sk_smooth_box_visibility(fnan(), 0, 1, 1, lit_left, NULL) == -1.0f);
    SK_CHECK(sk_smooth_box_visibility(0, fnan(), 1, 1, lit_left, NULL) == -1.0f);
    SK_CHECK(sk_smooth_box_visibility(0, 0, finf(), 1, lit_left, NULL) == -1.0f);
    SK_CHECK(sk_smooth_box_visibility(0, 0, 1, -finf(), lit_left, NULL) == -1.0f);
    SK_CHECK(sk_smooth_box_visibility(-2e9f, 0, 1, 1, lit_left, NULL) == -1.0f);
    SK_CHECK(sk_smooth_box_visibility(0, 0, 2e9f, 1, lit_left, NULL) == -1.0f);
    SK_CHECK(sk_smooth_box_visibility(0, -2e9f, 1, 1, lit_left, NULL) == -1.0f);
    SK_CHECK(sk_smooth_box_visibility(0, 0, 1, 2e9f, lit_left, NULL) == -1.0f);
    /* 65 texels across x or y */
    SK_CHECK(sk_smooth_box_visibility(0, 0, 64.5f, 1, lit_left, NULL) == -1.0f);
    SK_CHECK(sk_smooth_box_visibility(0, 0, 1, 64.5f, lit_left, NULL) == -1.0f);
    /* empty in y only: centre (-0.5, 3) is in texel (-1, 3), lit; (0.5, 3) is not */
    SK_CHECK(sk_smooth_box_visibility(-1.0f, 3.0f, 0.0f, 3.0f, lit_left, NULL) == 1.0f);
    SK_CHECK(sk_smooth_box_visibility(0.0f, 3.0f, 1.0f, 3.0f, lit_left, NULL) == 0.0f);
    /* control: [-1, 1] x [0, 1] is half lit */
    SK_CHECK_NEAR(sk_smooth_box_visibility(-1.0f, 0.0f, 1.0f, 1.0f, lit_left, NULL), 0.5, 1e-7);
}

/* sk_pvsm_predict writes only the outputs it is given. */
static void test_pvsm_predict_null_outputs(void) {
    float r0 = 1.0f, r1 = 1.0f;
    sk_pvsm_predict(v2(fnan(), 0), v2(0, 1), v2(1, 0), v2(0, 1), 1, NULL, &r1);
    SK_CHECK(r1 == finf());
    sk_pvsm_predict(v2(1, 0), v2(0, 1), v2(finf(), 0), v2(0, 1), 0, &r0, NULL);
    SK_CHECK(r0 == finf());
    r0 = r1 = 1.0f;
    sk_pvsm_predict(v2(1, 0), v2(0, 1), v2(1, 0), v2(0, 1), 1, NULL, NULL);   /* nothing to write */
    sk_pvsm_predict(v2(1, 0), v2(0, 1), v2(1, 0), v2(0, 1), 1, NULL, &r1);
    SK_CHECK_NEAR(r1, 2.0 / sk_rho_dynamic(1.0f), 1e-6);
    SK_CHECK(r0 == 1.0f);
}

/* sk_pvsm_merge ignores a merge it cannot make (either pointer NULL, a
   non-finite or non-positive source area, a non-finite source value, a
   non-finite or negative destination): the destination is unchanged. */
static void test_pvsm_merge_bad_input(void) {
    float v = 0.25f, a = 2.0f, bv, ba;
    sk_pvsm_merge(NULL, &a, 1.0f, 1.0f);
    SK_CHECK(a == 2.0f);
    sk_pvsm_merge(&v, NULL, 1.0f, 1.0f);
    SK_CHECK(v == 0.25f);
    sk_pvsm_merge(&v, &a, fnan(), 1.0f);
    sk_pvsm_merge(&v, &a, 1.0f, finf());
    sk_pvsm_merge(&v, &a, 1.0f, 0.0f);
    sk_pvsm_merge(&v, &a, 1.0f, -1.0f);
    SK_CHECK(v == 0.25f && a == 2.0f);
    bv = fnan(); ba = 2.0f;
    sk_pvsm_merge(&bv, &ba, 1.0f, 1.0f);
    SK_CHECK(bv != bv && ba == 2.0f);
    bv = 0.25f; ba = finf();
    sk_pvsm_merge(&bv, &ba, 1.0f, 1.0f);
    SK_CHECK(bv == 0.25f && ba == finf());
    bv = 0.25f; ba = -1.0f;
    sk_pvsm_merge(&bv, &ba, 1.0f, 1.0f);
    SK_CHECK(bv == 0.25f && ba == -1.0f);
    /* control: (0.25*2 + 1*2) / 4 */
    sk_pvsm_merge(&v, &a, 1.0f, 2.0f);
    SK_CHECK_NEAR(v, 0.625, 0.0);
    SK_CHECK_NEAR(a, 4.0, 0.0);
}

/* "0 on bad input (gw, gh outside [1, 4096])", each bound on each axis. */
static void test_smtg_size_bounds(void) {
    SK_CHECK(sk_smtg_pyramid_size(0, 4) == 0);
    SK_CHECK(sk_smtg_pyramid_size(4, 0) == 0);
    SK_CHECK(sk_smtg_pyramid_size(4097, 4) == 0);
    SK_CHECK(sk_smtg_pyramid_size(4, 4097) == 0);
    /* 4096 x 1: levels 4096, 2048, ..., 1 cells, 2 floats each */
    SK_CHECK(sk_smtg_pyramid_size(4096, 1) == 2 * (2 * 4096 - 1));
    SK_CHECK(sk_smtg_pyramid_size(1, 4096) == 2 * (2 * 4096 - 1));
}

/* "+INFINITY or NaN = no sample": level 0 of the pyramid holds +INFINITY
   for NaN, and the minima above ignore it. */
static void test_smtg_pyramid_nan(void) {
    float grid[2 * 2 * 2], out[2 * (4 + 1)];
    int levels;
    grid[0] = fnan();  grid[1] = 0.5f;     /* (0,0) */
    grid[2] = 0.25f;   grid[3] = fnan();   /* (1,0) */
    grid[4] = finf();  grid[5] = 0.75f;    /* (0,1) */
    grid[6] = fnan();  grid[7] = fnan();   /* (1,1) */
    levels = sk_smtg_pyramid(grid, 2, 2, out, 10);
    SK_CHECK(levels == 2);
    SK_CHECK(out[0] == finf() && out[1] == 0.5f && out[2] == 0.25f && out[3] == finf());
    SK_CHECK(out[6] == finf() && out[7] == finf());
    SK_CHECK(out[8] == 0.25f && out[9] == 0.5f);
}

/* A cell sampled along one axis only (the other +INFINITY or NaN) is still
   a sampled cell: it is covered, its unsampled axis needs no more than one
   texel, the sampled one span / min texel. */
static void test_fvsm_one_axis_sampled(void) {
    enum { G = 4 };
    float grid[G * G * 2];
    sk_tile t[8];
    int i, n;
    for (i = 0; i < G * G * 2; i++) grid[i] = finf();
    /* cell (1,2): x unsampled (NaN), y needs 1/64 -> res_y = (2*1/4) / (1/64) = 32 */
    grid[(2 * G + 1) * 2] = fnan();
    grid[(2 * G + 1) * 2 + 1] = 1.0f / 64.0f;
    n = sk_fvsm_tiles(grid, G, G, 1024, t, 8);
    SK_CHECK(n == 1);
    if (n == 1) {
        SK_CHECK(t[0].x0 == 1 && t[0].x1 == 2 && t[0].y0 == 2 && t[0].y1 == 3);
        SK_CHECK(t[0].res_x == 1);
        SK_CHECK(t[0].res_y == 32);
    }
    /* cell (3,0): y unsampled (+INFINITY), x needs 1/16 -> res_x = 0.5 / (1/16) = 8 */
    grid[(2 * G + 1) * 2 + 1] = finf();
    grid[(0 * G + 3) * 2] = 1.0f / 16.0f;
    grid[(0 * G + 3) * 2 + 1] = fnan();
    n = sk_fvsm_tiles(grid, G, G, 1024, t, 8);
    SK_CHECK(n == 1);
    if (n == 1) {
        SK_CHECK(t[0].x0 == 3 && t[0].x1 == 4 && t[0].y0 == 0 && t[0].y1 == 1);
        SK_CHECK(t[0].res_x == 8 && t[0].res_y == 1);
    }
}

/* "<= 0 is an unbounded demand (that cell ends in a 1x1 tile at max_res)",
   on the x axis as on y; the other axis keeps its own need. */
static void test_fvsm_unbounded_x(void) {
    enum { G = 4 };
    float grid[G * G * 2];
    sk_tile t[4];
    int i, n;
    for (i = 0; i < G * G * 2; i++) grid[i] = finf();
    grid[(1 * G + 2) * 2] = -1.0f;          /* cell (2,1): x unbounded */
    grid[(1 * G + 2) * 2 + 1] = 0.25f;      /* y: span 0.5 / 0.25 = 2 */
    n = sk_fvsm_tiles(grid, G, G, 256, t, 4);
    SK_CHECK(n == 1);
    if (n == 1) {
        SK_CHECK(t[0].x0 == 2 && t[0].x1 == 3 && t[0].y0 == 1 && t[0].y1 == 2);
        SK_CHECK(t[0].res_x == 256 && t[0].res_y == 2);
    }
}

/* ---------------------------------------------------------- 9. RMSM pages */

/* "a sample needs level clamp(floor(lod), 0, log2(virtual_res/page_size))":
   NaN and negative lods are level 0, an infinite one the coarsest level. */
static void test_rmsm_lod_clamp(void) {
    sk_vec3 s[4];
    sk_page p[4];
    int n;
    s[0] = v3(0.9f, 0.1f, fnan());
    s[1] = v3(0.9f, 0.1f, -finf());
    s[2] = v3(0.1f, 0.1f, finf());
    s[3] = v3(0.6f, 0.6f, 1.5f);
    n = sk_rmsm_page_requests(s, 4, 1024, 128, p, 4);   /* levels 0..3 */
    SK_CHECK(n == 3);
    if (n == 3) {
        /* sorted by level: (0: page (7,0)), (1: 1024/2/128 = 4 pages, (2,2)), (3: one page) */
        SK_CHECK(p[0].level == 0 && p[0].px == 7 && p[0].py == 0);
        SK_CHECK(p[1].level == 1 && p[1].px == 2 && p[1].py == 2);
        SK_CHECK(p[2].level == 3 && p[2].px == 0 && p[2].py == 0);
    }
}

SK_TEST_MAIN(test_inverse_overflow, test_projection_overflow, test_frustum_corners_at_infinity,
             test_clip_box_by_itself, test_clip_touching_faces, test_aliasing_negative_lengths, test_crop_matrix_axes,
             test_bounding_sphere_wide_near_face, test_cascade_sphere_bad_input, test_psm_half_turn,
             test_psm_body_outside_view, test_psm_many_casters, test_psm_ortho_caster_inside, test_psm_degenerate,
             test_lispsm_large_body, test_lispsm_flat_body, test_lspsm_crops_bad_region, test_lspsm_point_region,
             test_lspsm_zero_width_region, test_lspsm_area_tie, test_vsdct_bad_layout,
             test_resest_negated_inverse, test_resest_no_patch, test_convolve_overflow,
             test_smooth_visibility_bad_input, test_pvsm_predict_null_outputs, test_pvsm_merge_bad_input,
             test_smtg_size_bounds, test_smtg_pyramid_nan, test_fvsm_one_axis_sampled, test_fvsm_unbounded_x,
             test_rmsm_lod_clamp)
