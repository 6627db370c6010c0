/* tests/test_fuzz_regress.c - one deterministic test per bug the libFuzzer
   targets (tests/fuzz/) found in shadowkit.h, each on the input that showed
   it, written out here by value; the fuzzer's own input for each is in
   tests/fuzz/regress/<target>/ and is replayed by `make test` (flavour fuzz).
   The last tests cover faults of the same kinds found while fixing those.
   Every test fails on the header before its fix. */
#define SHADOWKIT_IMPLEMENTATION
#include "shadowkit.h"
#include "sk_test.h"
#include <float.h>

static sk_vec3 v3(float x, float y, float z) { sk_vec3 v; v.x = x; v.y = y; v.z = z; return v; }
static sk_vec2 v2(float x, float y) { sk_vec2 v; v.x = x; v.y = y; return v; }
static sk_aabb box3(float x0, float y0, float z0, float x1, float y1, float z1)
{
    sk_aabb b;
    b.min = v3(x0, y0, z0);
    b.max = v3(x1, y1, z1);
    return b;
}
static sk_rect rect4(float x0, float y0, float x1, float y1)
{
    sk_rect r;
    r.x0 = x0; r.y0 = y0; r.x1 = x1; r.y1 = y1;
    return r;
}
static int mat_finite(const sk_mat4 *m)
{
    int i;
    for (i = 0; i < 16; i++) if (!isfinite(m->m[i])) return 0;
    return 1;
}
static int v3_finite(sk_vec3 v) { return isfinite(v.x) && isfinite(v.y) && isfinite(v.z); }
static int all_bytes(const void *p, size_t n, unsigned char b)
{
    const unsigned char *c = (const unsigned char *)p;
    size_t i;
    for (i = 0; i < n; i++) if (c[i] != b) return 0;
    return 1;
}
static sk_frustum camera_frustum(void)
{
    return sk_frustum_from_matrix(sk_mat4_mul(sk_mat4_perspective(1.0f, 1.5f, 0.5f, 60.0f),
                                              sk_mat4_look_at(v3(0, 3, 10), v3(0, 0, 0), v3(0, 1, 0))));
}

/* fuzz_lspsm_region, fuzz_lspsm_crops, fuzz_psm, fuzz_lispsm: normalising a
   denormal vector multiplied it by 1/length, which overflows float: NaN
   axes and matrices. A direction's length must not matter. */
static void test_denormal_directions(void)
{
    sk_frustum view = camera_frustum();
    sk_aabb ground = box3(-30, -1, -30, 30, 0, 30);
    sk_lspsm_region a, b;
    sk_lispsm_desc d;
    sk_lispsm_result la, lb;
    sk_vec3 body[8];
    int i;
    SK_CHECK(sk_lspsm_region_extract(&view, v3(0, -3e-40f, -1e-39f), ground, NULL, v3(2e-40f, -1e-39f, 0), &a) == SK_OK);
    SK_CHECK(sk_lspsm_region_extract(&view, v3(0, -0.3f, -1), ground, NULL, v3(0.2f, -1, 0), &b) == SK_OK);
    SK_CHECK(mat_finite(&a.light_view));
    SK_CHECK_NEAR(a.n, b.n, 1e-3 * b.n);
    SK_CHECK_NEAR(a.L, b.L, 1e-3 * b.L);
    SK_CHECK_NEAR(a.theta, b.theta, 1e-3);
    SK_CHECK_FINITE(a.zmin);
    memset(&d, 0, sizeof d);
    for (i = 0; i < 8; i++) body[i] = v3((i & 1) ? 8.0f : -8.0f, (i & 2) ? 2.0f : 0.0f, (i & 4) ? 9.0f : -40.0f);
    d.eye = v3(0, 3, 10);
    d.view_dir = v3(0, -2e-41f, -1e-40f);
    d.zn = 0.5f;
    d.light_dir = v3(3e-40f, -1e-39f, 2e-40f);
    d.body = body;
    d.body_count = 8;
    SK_CHECK(sk_lispsm_matrices(&d, &la) == SK_OK);
    d.view_dir = v3(0, -0.2f, -1);
    d.light_dir = v3(0.3f, -1, 0.2f);
    SK_CHECK(sk_lispsm_matrices(&d, &lb) == SK_OK);
    SK_CHECK(mat_finite(&la.light_view_proj));
    SK_CHECK_NEAR(la.sin_gamma, lb.sin_gamma, 1e-5);
    for (i = 0; i < 16; i++) SK_CHECK_NEAR(la.light_view_proj.m[i], lb.light_view_proj.m[i], 1e-3);
}

/* fuzz_psm (crash-f901a68c): the light turned perpendicular to the view in
   post-perspective space with a denormal direction there: light_pp was
   +-INFINITY with SK_OK. The camera matrix and projection are the
   fuzzer's. */
static void test_psm_denormal_pp_light(void)
{
    static const float cv[16] = {6.94596e-41f, 2.33624e-41f, 2.29589e-41f, 6.94596e-41f, 6.92802e-41f, 0, 2.9869e-40f, 0,
                                 5.90043e-39f, 5.98079e-39f, 0, 0, 0, 0, 5.83155e-39f, 0};
    sk_psm_desc d;
    sk_psm_result r;
    sk_result res;
    memset(&d, 0, sizeof d);
    memcpy(d.cam_view.m, cv, sizeof cv);
    d.fovy = 5.83155e-39f;
    d.aspect = 5.85451e-39f;
    d.zn = 5.78564e-39f;
    d.zf = 6.10132e-39f;
    d.light_dir = v3(1.34218e+08f, -0.5f, 1.17549e-38f);
    res = sk_psm_matrices(&d, &r);
    SK_CHECK(res == SK_OK || res == SK_ERR_DEGENERATE);
    if (res == SK_OK) {
        SK_CHECK(v3_finite(r.light_pp));
        SK_CHECK(mat_finite(&r.light_view_proj));
    }
}

/* fuzz_frustum (crash-790c10bf): an edge of a box spanning -3.4e38..3.4e38
   clipped by a frustum: the lerp's b - a overflowed, points at INFINITY.
   And the crossing of such an edge with a frustum of size 100 is below
   float's resolution along it: the camera frustum's intersection with
   that slab was missed (0 points). */
static void test_clip_huge_box(void)
{
    sk_frustum view = camera_frustum(), cube;
    sk_vec3 pts[SK_CLIP_MAX_POINTS];
    int n, i;
    SK_CHECK(sk_frustum_from_aabb(box3(-1, -1, -1, 1, 1, 1), &cube) == SK_OK);
    n = sk_clip_frustum_aabb(&cube, box3(-0.5f, -3.4e38f, -0.5f, 0.5f, 3.4e38f, 0.5f), pts, SK_CLIP_MAX_POINTS);
    SK_CHECK_MSG(n == 8, "n = %d", n);
    for (i = 0; i < n; i++)
        SK_CHECK_MSG(v3_finite(pts[i]) && fabsf(pts[i].y) <= 1.0001f && fabsf(pts[i].x) <= 0.5f, "point %d (%g %g %g)",
                     i, pts[i].x, pts[i].y, pts[i].z);
    n = sk_clip_frustum_aabb(&view, box3(-1, -3.4e38f, -20, 1, 3.4e38f, -2), pts, SK_CLIP_MAX_POINTS);
    SK_CHECK_MSG(n > 0, "n = %d", n);
    for (i = 0; i < n; i++) {
        SK_CHECK_MSG(v3_finite(pts[i]), "point %d (%g %g %g)", i, pts[i].x, pts[i].y, pts[i].z);
        SK_CHECK(pts[i].x >= -1.0001f && pts[i].x <= 1.0001f);
        SK_CHECK(sk_frustum_contains_point(&view, pts[i]));
    }
}

/* fuzz_lspsm_partition: rows thinner than float resolves. n = 1e-38 at
   theta just below pi/2 gave rows of height 1e-46, written as y0 == y1 == 0;
   n = 3e38 gave a row ending at +INFINITY. Both are now
   -SK_ERR_DEGENERATE with nothing written. */
static void test_partition_unrepresentable(void)
{
    sk_lspsm_params p = sk_lspsm_default_params();
    sk_rect out[64];
    int c;
    memset(out, 0x5a, sizeof out);
    c = sk_lspsm_partition(1e-38f, 1.0f, 1.57079625f, &p, out, 64);
    SK_CHECK_MSG(c == -(int)SK_ERR_DEGENERATE, "n = 1e-38: %d", c);
    SK_CHECK(all_bytes(out, sizeof out, 0x5a));
    c = sk_lspsm_partition(3e38f, 3.4e38f, 0.0f, &p, out, 64);
    SK_CHECK_MSG(c == -(int)SK_ERR_DEGENERATE, "n = 3e38: %d", c);
    SK_CHECK(all_bytes(out, sizeof out, 0x5a));
    /* the ordinary case is unchanged */
    c = sk_lspsm_partition(1.0f, 20.0f, 0.6f, &p, out, 64);
    SK_CHECK(c == 8);
}

/* fuzz_lspsm_crops (crash-08ef3621, crash-e68d3ae6): a region whose light
   view translates z by -2.2e38 against a depth range of 1e-38, and one
   whose origin pushes a rect past FLT_MAX: non-finite matrices and rects
   with a count. Now -SK_ERR_DEGENERATE, nothing written. */
static void test_crops_unrepresentable(void)
{
    sk_lspsm_params p = sk_lspsm_default_params();
    sk_lspsm_region r;
    sk_mat4 vps[16];
    sk_rect rects[16];
    int c;
    memset(&r, 0, sizeof r);
    r.light_view = sk_mat4_identity();
    r.light_view.m[14] = -2.2e38f;
    r.n = 1.0f; r.L = 1.0f; r.theta = 0.0f;
    r.zmin = 1e-38f; r.zmax = 1e-38f;
    r.fallback = 1;
    memset(vps, 0x5a, sizeof vps);
    memset(rects, 0x5a, sizeof rects);
    c = sk_lspsm_crops(&r, &p, vps, rects, 16);
    SK_CHECK_MSG(c == -(int)SK_ERR_DEGENERATE, "z overflow: %d", c);
    r.fallback = 0;
    c = sk_lspsm_crops(&r, &p, vps, rects, 16);
    SK_CHECK_MSG(c == -(int)SK_ERR_DEGENERATE, "z overflow, partitioned: %d", c);
    r.light_view = sk_mat4_identity();
    r.zmin = -1.0f; r.zmax = 1.0f;
    r.origin = v2(3e38f, 0.0f);
    r.n = 1e38f; r.L = 1.0f; r.theta = 0.3f;
    c = sk_lspsm_crops(&r, &p, vps, rects, 16);
    SK_CHECK_MSG(c == -(int)SK_ERR_DEGENERATE, "rect overflow: %d", c);
    SK_CHECK(all_bytes(vps, sizeof vps, 0x5a) && all_bytes(rects, sizeof rects, 0x5a));
}

/* fuzz_lspsm_region (crash-06af8104): receivers flat along the light-view x
   axis (a plane containing the light direction) gave a trapezoid of width
   n = 0. */
static void test_region_flat_body(void)
{
    sk_frustum view = sk_frustum_from_matrix(sk_mat4_mul(sk_mat4_perspective(1.0f, 1.0f, 0.5f, 60.0f),
                                                         sk_mat4_look_at(v3(0, 2, 5), v3(0, 0, -20), v3(0, 1, 0))));
    sk_lspsm_params p = sk_lspsm_default_params();
    sk_lspsm_region r;
    sk_mat4 vps[16];
    int c;
    SK_CHECK(sk_lspsm_region_extract(&view, v3(0, -0.08f, -1), box3(0, -1, -50, 0, 1, -1), NULL, v3(0, -1, 0), &r) ==
             SK_OK);
    SK_CHECK_MSG(r.n > 0.0f, "n = %g", r.n);
    SK_CHECK(r.L > 0.0f);
    c = sk_lspsm_crops(&r, &p, vps, NULL, 16);
    SK_CHECK_MSG(c > 0, "crops: %d", c);
}

/* fuzz_vsdct (crash-7810462b): a hand-made layout far outside the documented
   sizes. In an atlas 2^30 texels wide, float u cannot place a 1-texel face:
   u * atlas_w landed 3.5 texels left of it. Such layouts are refused now. */
static void test_vsdct_huge_atlas(void)
{
    sk_vsdct_layout l;
    unsigned short ind[6 * 2];
    float u = -1.0f, v = -1.0f;
    int f;
    sk_vsdct_layout_make(1, &l);
    l.atlas_w = 1 << 30;
    for (f = 0; f < 6; f++) l.face_x[f] = (1 << 29) + 3;
    f = sk_vsdct_lookup(&l, v3(1, 0.2f, 0.1f), &u, &v);
    SK_CHECK_MSG(f == -1, "face %d, texel x %.3f in [%d, %d]", f, (double)u * l.atlas_w, l.face_x[0], l.face_x[0] + 1);
    SK_CHECK(u == -1.0f && v == -1.0f);
    SK_CHECK(sk_vsdct_indirection_fill(&l, 1, ind) == SK_ERR_INVALID_ARG);
    /* the largest documented layout still works */
    SK_CHECK(sk_vsdct_layout_make(65536, &l) == SK_OK);
    f = sk_vsdct_lookup(&l, v3(1, 0.2f, 0.1f), &u, &v);
    SK_CHECK(f == 0);
    SK_CHECK((double)u * l.atlas_w >= l.face_x[0] + 0.49 && (double)u * l.atlas_w <= l.face_x[0] + 65535.51);
}

/* fuzz_frustum (crash-a2e1286a): a matrix whose NDC corners unproject
   through infinity (clip w < 0, here the negated camera matrix) gave
   corners lying outside its own planes; now the "unknown" all-zero frustum. */
static void test_frustum_through_infinity(void)
{
    sk_mat4 m = sk_mat4_mul(sk_mat4_perspective(1.0f, 1.5f, 0.5f, 60.0f),
                            sk_mat4_look_at(v3(0, 3, 10), v3(0, 0, 0), v3(0, 1, 0)));
    sk_frustum f, zero;
    int i;
    memset(&zero, 0, sizeof zero);
    f = sk_frustum_from_matrix(m);
    SK_CHECK(memcmp(&f, &zero, sizeof f) != 0);
    for (i = 0; i < 16; i++) m.m[i] = -m.m[i];
    f = sk_frustum_from_matrix(m);
    SK_CHECK(memcmp(&f, &zero, sizeof f) == 0);
}

/* fuzz_frustum (crash-ac11470f): the fuzzer's orthographic view whose
   corners come within 1% of FLT_MAX: a plane offset of +INFINITY. */
static void test_frustum_plane_overflow(void)
{
    static const float m[16] = {0.000129782478f, -6.95503664e-40f, 3.73519141e-36f, 0, -1.20175791f, -5.36417052e-42f, 0,
                                0, 0.00108904287f, -5.83617269e-39f, -4.45127053e-37f, 0, -0.202030703f, 1, -1, 1};
    sk_mat4 mm;
    sk_frustum f, zero;
    sk_vec3 c[8];
    int i;
    memcpy(mm.m, m, sizeof m);
    memset(&zero, 0, sizeof zero);
    f = sk_frustum_from_matrix(mm);
    for (i = 0; i < 6; i++) SK_CHECK(isfinite(f.planes[i].d));
    SK_CHECK(memcmp(&f, &zero, sizeof f) == 0);
    /* corners whose face x + y = 6.6e38 lies 4.7e38 from the origin: that
       plane's offset does not fit a float; an error, nothing written */
    for (i = 0; i < 8; i++) {
        float s = (i & 1) ? 0.05e38f : 0.0f, t = (i & 2) ? 0.1e38f : 0.0f;
        c[i] = v3(3.3e38f + s - t, 3.3e38f + t, (i & 4) ? 1e38f : 0.0f);
    }
    memset(&f, 0x5a, sizeof f);
    SK_CHECK(sk_frustum_from_corners(c, &f) == SK_ERR_DEGENERATE);
    SK_CHECK(all_bytes(&f, sizeof f, 0x5a));
}

/* fuzz_culling (crash-05157055, crash-5f87f503): a caster too small to
   subtend an angle float resolves (a point, or 5e-12 across at 970) got a
   zero-width cone: SK_ERR_DEGENERATE, and sk_caster_visible culled a caster
   inside the view. */
static void test_caster_tiny(void)
{
    sk_frustum view = camera_frustum(), f;
    sk_aabb dot = box3(0, 0, 0, 0, 0, 0), speck = box3(0, 0, 0, 4.89343809e-12f, 4.89343809e-12f, 4.89343809e-12f);
    SK_CHECK(sk_caster_shadow_frustum(v3(-2, -2, 0), 10240.0f, dot, &f) == SK_OK);
    SK_CHECK(sk_frustum_contains_point(&f, v3(0, 0, 0)));
    SK_CHECK(sk_caster_visible(v3(-2, -2, 0), 10240.0f, dot, &view) == 1);
    SK_CHECK(sk_caster_shadow_frustum(v3(-562.21875f, -562.21875f, -562.21875f), 4096.0f, speck, &f) == SK_OK);
    SK_CHECK(sk_frustum_contains_point(&f, v3(0, 0, 0)));
    SK_CHECK(sk_caster_visible(v3(-562.21875f, -562.21875f, -562.21875f), 4096.0f, speck, &view) == 1);
    /* out of reach is still out of reach */
    SK_CHECK(sk_caster_shadow_frustum(v3(-2000, 0, 0), 1000.0f, dot, &f) == SK_ERR_DEGENERATE);
}

/* fuzz_light_scissor (crash-075831ee): clip w of +-1e-50, below float's
   range: both signs rounded to 0, every corner counted behind the eye, the
   light skipped although its box straddles the eye. */
static void test_scissor_underflow(void)
{
    sk_mat4 vp = sk_mat4_identity();
    int rect[4] = {7, 7, 7, 7};
    vp.m[15] = 0.0f;
    vp.m[11] = 1e-30f;     /* w = 1e-30 z */
    SK_CHECK(sk_light_scissor(v3(0, 0, 0), 1e-20f, vp, 640, 480, rect) == 1);
    SK_CHECK(rect[0] == 0 && rect[1] == 0 && rect[2] == 640 && rect[3] == 480);
}

/* fuzz_psm (crash-ebeb778c): a focus body flat in post-perspective space (a
   line of receivers) fitted a frustum 2e-6 wide at an offset of 4 in the
   light's tangent space; its float matrix cancelled the positions away and
   put body points in view at x = 3.97. */
static void test_psm_flat_body(void)
{
    sk_psm_desc d;
    sk_psm_result r;
    sk_aabb caster = box3(-2, 0, -2, 0, 3, 12);
    sk_vec3 body[8];
    int i;
    memset(&d, 0, sizeof d);
    for (i = 2; i < 8; i++) body[i] = v3(0, 0, 0);
    body[0] = v3(-10, 0, 0);
    body[1] = v3(-6617.5f, 254, 0);
    d.cam_view = sk_mat4_look_at(v3(0, 3, 10), v3(0, 0, 0), v3(0, 1, 0));
    d.fovy = 1.0f; d.aspect = 1.5f; d.zn = 0.5f; d.zf = 60.0f;
    d.light_dir = v3(0, -0.5f, -1);
    d.casters = &caster; d.caster_count = 1;
    d.body = body; d.body_count = 8;
    SK_CHECK(sk_psm_matrices(&d, &r) == SK_OK);
    SK_CHECK(r.inverted == 1);
    for (i = 0; i < 8; i++) {   /* all but point 1 lie in the (slid) camera's view */
        sk_vec4 p, c, q;
        if (i == 1) continue;
        p.x = body[i].x; p.y = body[i].y; p.z = body[i].z; p.w = 1.0f;
        c = sk_mat4_transform_vec4(r.virtual_cam_view_proj, p);
        SK_CHECK(c.w > 0.0f && fabsf(c.x) < c.w && fabsf(c.y) < c.w);
        q = sk_mat4_transform_vec4(r.light_view_proj, p);
        SK_CHECK_MSG(fabsf(q.x / q.w) <= 1.0f && fabsf(q.y / q.w) <= 1.0f, "body %d maps to (%g %g)", i, q.x / q.w,
                     q.y / q.w);
    }
}

/* fuzz_lispsm (crash-02b4640b): |v x l| of float unit vectors rounded to
   1.00000012 for perpendicular view and light: sin_gamma above 1. */
static void test_lispsm_sin_gamma(void)
{
    sk_lispsm_desc d;
    sk_lispsm_result r;
    sk_vec3 body[2];
    int i, worse = 0;
    memset(&d, 0, sizeof d);
    body[0] = v3(-5, 0, -5);
    body[1] = v3(5, 1, -30);
    d.eye = v3(0, 3, 10);
    d.zn = 0.5f;
    d.body = body;
    d.body_count = 2;
    for (i = 0; i < 64; i++) {
        double a = 0.1 * i;
        d.view_dir = v3((float)cos(a), 0.0f, (float)sin(a));
        d.light_dir = v3((float)(-sin(a) * (1 + i)), 0.0f, (float)(cos(a) * (1 + i)));
        if (sk_lispsm_matrices(&d, &r) == SK_OK && !(r.sin_gamma <= 1.0f)) worse++;
    }
    d.view_dir = v3(0, -0.2f, 4.25f);
    d.light_dir = v3(-8, 0, 0);
    SK_CHECK(sk_lispsm_matrices(&d, &r) == SK_OK);
    SK_CHECK_MSG(r.sin_gamma <= 1.0f, "sin_gamma %.9g", r.sin_gamma);
    SK_CHECK_MSG(worse == 0, "%d perpendicular pairs with sin_gamma > 1", worse);
}

/* fuzz_crops (crash-d07cb592): one axis too thin for its scale to fit a
   float reset the whole crop to the identity, valid axes included. */
static void test_crop_matrix_thin_axis(void)
{
    sk_mat4 m = sk_crop_matrix(rect4(-5, 0, 0, 1e-40f), -1, 3);
    SK_CHECK_NEAR(m.m[0] * -5.0f + m.m[12], -1.0, 1e-6);
    SK_CHECK_NEAR(m.m[12], 1.0, 1e-6);
    SK_CHECK(m.m[5] == 1.0f && m.m[13] == 0.0f);
    SK_CHECK_NEAR(m.m[10] * 3.0f + m.m[14], 1.0, 1e-6);
    SK_CHECK(mat_finite(&m));
}

/* fuzz_crops (crash-dad9d4b3, crash-820dd6cb): spheres past FLT_MAX: a
   radius or centre of INFINITY from sk_cascade_sphere (aspect 3e38) and
   sk_frustum_bounding_sphere (corners at +-3e38). Now the zero sphere. */
static void test_spheres_overflow(void)
{
    sk_sphere s = sk_cascade_sphere(sk_mat4_identity(), 3.1f, 3e38f, 0.0f, 1.0f);
    sk_frustum f;
    SK_CHECK(isfinite(s.r) && v3_finite(s.c));
    SK_CHECK(s.r == 0.0f);
    s = sk_cascade_sphere(sk_mat4_identity(), 1.0f, 1.5f, 1.0f, 10.0f);
    SK_CHECK(s.r > 0.0f);
    SK_CHECK(sk_frustum_from_aabb(box3(-3e38f, -3e38f, -3e38f, 3e38f, 3e38f, 3e38f), &f) == SK_OK);
    s = sk_frustum_bounding_sphere(&f);
    SK_CHECK(isfinite(s.r) && v3_finite(s.c));
    SK_CHECK(s.r == 0.0f);
}

/* fuzz_pvsm (crash-7a6d4ad1): u_h.x = 3.4e38 gave r0 = +INFINITY, which
   the SMTG reads as "no sample"; the largest size float holds instead. */
static void test_pvsm_huge_footprint(void)
{
    float r0 = 0.0f, r1 = 0.0f;
    /* the warped footprint as large: n0 = n1 = 1, rho(1) = 0.667 */
    sk_pvsm_predict(v2(3.4e38f, 0), v2(0, -1.7e38f), v2(3.4e38f, 0), v2(0, 1.7e38f), 1, &r0, &r1);
    SK_CHECK_MSG(r0 == FLT_MAX, "r0 = %g", r0);
    SK_CHECK_MSG(r1 == FLT_MAX, "r1 = %g", r1);
    sk_pvsm_predict(v2(INFINITY, 0), v2(0, 1), v2(1, 0), v2(0, 1), 1, &r0, &r1);
    SK_CHECK(r0 == INFINITY && r1 == INFINITY);
}

/* lit everywhere */
static int lit_all(void *user, int tx, int ty) { (void)user; (void)tx; (void)ty; return 1; }

/* fuzz_smooth_box (crash-5242506a, crash-4f7df8e1): a box thinner than 1e-19
   texels: each texel's coverage, rounded to float, fell to 0 or to a few
   denormal bits, so an all-lit box read 0 (or 0.877) lit. */
static void test_smooth_box_thin(void)
{
    SK_CHECK_NEAR(sk_smooth_box_visibility(-0.0f, 0.0f, 6.06120721e-39f, 7.00649232e-45f, lit_all, NULL), 1.0, 1e-6);
    SK_CHECK_NEAR(sk_smooth_box_visibility(-0.015625f, -0.0f, -0.0f, 3.06884364e-43f, lit_all, NULL), 1.0, 1e-6);
    SK_CHECK_NEAR(sk_smooth_box_visibility(1.40129846e-45f, 0.0f, 32.0644531f, 4.20389539e-45f, lit_all, NULL), 1.0,
                  1e-6);
}

/* fuzz_estimate_resolution (regress texel-overflow): projections beyond
   double range left every patch extent infinite or past FLT_MAX: a texel
   size of +INFINITY with samples. The fuzzer's matrices: */
static void test_resolution_texel_overflow(void)
{
    static const float inv[16] = {-1.34213133e-06f, 1, 0, 0, 0, 0, 1, 0, 1, 1.34213133e-06f, 0, 0, 21101, 0.0283203125f, 0, 1};
    static const float lvp[16] = {0, 0, 0, 0, 0, 0, 5.90043063e-39f, -1.08635284e-19f, 5.83155401e-39f, -1.03845937e+34f,
                                  1.3329151e-41f, 0, 3.97511894e-31f, 4.66352129e-42f, 0, 0};
    static float depth[64269];
    sk_mat4 a, b;
    sk_res_estimate e;
    memcpy(a.m, inv, sizeof inv);
    memcpy(b.m, lvp, sizeof lvp);
    memset(depth, 0, sizeof depth);
    SK_CHECK(sk_estimate_resolution(depth, 64269, 1, a, b, 67584, &e) == SK_OK);
    SK_CHECK(e.samples > 0);
    SK_CHECK_FINITE(e.texel_w);
    SK_CHECK_FINITE(e.texel_h);
    SK_CHECK(e.width >= 1 && e.width <= 67584 && e.height >= 1 && e.height <= 67584);
}

/* fuzz_psm (regress flat-body-ortho): the light perpendicular to the view,
   a focus body flat in post-perspective space: sk_fit_ortho widened the flat
   sides to 1e-6 of their magnitude, below the float error of the points'
   coordinates, and body points in view landed at x = -1.02. Flat sides are
   now widened to 1e-4. */
static void test_psm_flat_body_ortho(void)
{
    static const float cv[16] = {0, -0.986394f, 0.164399f, 0, 1.40815e-39f, 0.164399f, 0.986394f, 0, -1, 2.31497e-40f,
                                 1.38899e-39f, 0, -2.8026e-45f, -0.0f, -3.04138f, 1};
    sk_aabb casters[4];
    sk_vec3 body[4];
    sk_psm_desc d;
    sk_psm_result r;
    int i;
    casters[0] = box3(-2, 0, -2, 0, 3, 12);
    casters[1] = box3(-1, 0, 0, 1, 10, 0);
    casters[2] = box3(-5.83155e-39f, 0, 1.7311e-38f, 5.83155e-39f, 0, 2.89741e-38f);
    casters[3] = box3(2.28692e-41f, 252, 59, 2.28692e-41f, 252, 61);
    body[0] = v3(0.747058809f, 0, 0.0116577148f);
    body[1] = v3(2.3509887e-38f, 2.3509887e-38f, -2);
    body[2] = v3(0, 0, 2.69049305e-43f);
    body[3] = v3(0, 2.69049305e-43f, 0);
    memset(&d, 0, sizeof d);
    memcpy(d.cam_view.m, cv, sizeof cv);
    d.fovy = 1.0f; d.aspect = 1.5f; d.zn = 0.503784f; d.zf = 44.0f;
    d.light_dir = v3(0, 0, -1);
    d.casters = casters; d.caster_count = 4;
    d.body = body; d.body_count = 4;
    d.extra_slide = 1.0f;
    SK_CHECK(sk_psm_matrices(&d, &r) == SK_OK);
    SK_CHECK(r.orthographic == 1);
    for (i = 0; i < 4; i++) {
        sk_vec4 p, c, q;
        p.x = body[i].x; p.y = body[i].y; p.z = body[i].z; p.w = 1.0f;
        c = sk_mat4_transform_vec4(r.virtual_cam_view_proj, p);
        if (!(c.w > 0.0f && fabsf(c.x) < c.w && fabsf(c.y) < c.w)) continue;
        q = sk_mat4_transform_vec4(r.light_view_proj, p);
        SK_CHECK_MSG(fabsf(q.x / q.w) <= 1.001f && fabsf(q.y / q.w) <= 1.001f, "body %d maps to (%g %g)", i, q.x / q.w,
                     q.y / q.w);
    }
}

/* fuzz_lispsm (regress line-body-uniform, line-along-light,
   flat-body-warped): bodies along one light ray (flat across the map) and
   one 8e-6 deep along the warp axis at light-space coordinates of 2: the
   map missed body points by 6%, 7% and 2%.
   Flat sides are widened by the magnitude the coordinates came from, and a
   body too flat to warp gets the uniform map. */
static void test_lispsm_flat_bodies(void)
{
    sk_lispsm_desc d;
    sk_lispsm_result r;
    sk_vec3 line[3], flat[3];
    int i;
    line[0] = v3(0, 0, 0);
    line[1] = v3(0, 0, -0.002f);
    line[2] = v3(1000, 1000, 1000);
    flat[0] = v3(0, 0, 0);
    flat[1] = v3(1.57079625f, 0, 0);
    flat[2] = v3(2.36937346e-38f, 0, 0);
    memset(&d, 0, sizeof d);
    d.eye = v3(0, 0, 0);
    d.view_dir = v3(0, 0, 1);
    d.zn = 1000.0f;
    d.light_dir = v3(1000, 1000, 1000);
    d.body = line;
    d.body_count = 3;
    SK_CHECK(sk_lispsm_matrices(&d, &r) == SK_OK);
    for (i = 0; i < 3; i++) {
        sk_vec3 q = sk_mat4_transform_point(r.light_view_proj, line[i]);
        SK_CHECK_MSG(fabsf(q.x) <= 1.001f && fabsf(q.y) <= 1.001f && fabsf(q.z) <= 1.001f, "line %d maps to (%g %g %g)",
                     i, q.x, q.y, q.z);
    }
    /* (regress line-along-light) a body along a light ray oblique to the
       view: its depth along the warp axis is float noise of 1e-4 */
    line[1] = v3(0, 0, 0);
    line[2] = v3(1000, 1000, 0);
    d.eye = v3(0, 0, 0);
    d.view_dir = v3(13.8837891f, 0, 0);
    d.zn = 0.99999994f;
    d.light_dir = v3(1000, 1000, 0);
    SK_CHECK(sk_lispsm_matrices(&d, &r) == SK_OK);
    for (i = 0; i < 3; i++) {
        sk_vec3 q = sk_mat4_transform_point(r.light_view_proj, line[i]);
        SK_CHECK_MSG(fabsf(q.x) <= 1.001f && fabsf(q.y) <= 1.001f && fabsf(q.z) <= 1.001f, "line %d maps to (%g %g %g)",
                     i, q.x, q.y, q.z);
    }
    d.eye = v3(1.99999893f, -2, 0);
    d.view_dir = v3(4.8e-6f, 1, 0);
    d.zn = 0.0116577148f;
    d.light_dir = v3(0, 0, 1);
    d.body = flat;
    SK_CHECK(sk_lispsm_matrices(&d, &r) == SK_OK);
    for (i = 0; i < 3; i++) {
        sk_vec3 q = sk_mat4_transform_point(r.light_view_proj, flat[i]);
        SK_CHECK_MSG(fabsf(q.x) <= 1.001f && fabsf(q.y) <= 1.001f && fabsf(q.z) <= 1.001f, "flat %d maps to (%g %g %g)",
                     i, q.x, q.y, q.z);
    }
}

/* Found while fixing the above: sk_mat4_look_at with target - eye beyond
   FLT_MAX normalised an infinite vector (NaN matrix). */
static void test_look_at_overflow(void)
{
    sk_mat4 m = sk_mat4_look_at(v3(-3e38f, 0, 0), v3(3e38f, 0, 0), v3(0, 1, 0));
    sk_vec3 p;
    SK_CHECK(mat_finite(&m));
    p = sk_mat4_transform_point(m, v3(0, 0, 0));
    SK_CHECK_NEAR(p.z, -3e38, 1e32);   /* the origin lies 3e38 ahead */
}

/* Found while fixing the above: sk_fit_ortho and sk_stable_crop returned
   SK_OK with the identity (sk_mat4_ortho's fallback) when the crop's bounds
   went past FLT_MAX. */
static void test_ortho_crops_overflow(void)
{
    sk_vec3 pts[2];
    sk_mat4 out, id = sk_mat4_identity();
    sk_sphere s;
    sk_result r;
    /* points on y = FLT_MAX: the flat side, widened by 1e-6, passes FLT_MAX */
    pts[0] = v3(0, FLT_MAX, 0);
    pts[1] = v3(1, FLT_MAX, 1);
    memset(&out, 0x5a, sizeof out);
    r = sk_fit_ortho(pts, 2, sk_mat4_identity(), NULL, &out);
    SK_CHECK_MSG(r == SK_ERR_DEGENERATE, "fit_ortho: %d", (int)r);
    SK_CHECK(memcmp(&out, &id, sizeof out) != 0);
    SK_CHECK(all_bytes(&out, sizeof out, 0x5a));
    /* far out but representable: still fitted */
    pts[0] = v3(-3.3e38f, 0, 0);
    pts[1] = v3(3.3e38f, 1, 1);
    SK_CHECK(sk_fit_ortho(pts, 2, sk_mat4_identity(), NULL, &out) == SK_OK && mat_finite(&out));
    memset(&out, 0x5a, sizeof out);
    s.c = v3(3e38f, 0, 0);
    s.r = 1e38f;
    r = sk_stable_crop(s, sk_mat4_identity(), 1024, NULL, &out);
    SK_CHECK_MSG(r == SK_ERR_DEGENERATE, "stable_crop: %d", (int)r);
    SK_CHECK(all_bytes(&out, sizeof out, 0x5a));
}

/* fuzz_crops (crash-9cb1d413): a flat frustum of subnormal size. The
   centre was rounded to float after the radius was measured from the exact
   one, and r * (1 + 1e-7) rounds back to the same subnormal: a corner lay
   0.2% outside. Now every corner is inside the sphere as returned, with no
   tolerance, here and on frusta of subnormal to normal size around it. */
static void test_sphere_subnormal(void)
{
    const sk_vec3 c[8] = {v3(0, 0, 0), v3(2.67648007e-43f, 0, 0), v3(0, 8.96831017e-44f, 0),
                          v3(2.67648007e-43f, 8.96831017e-44f, 0), v3(0, 0, 0), v3(2.67648007e-43f, 0, 0),
                          v3(0, 8.96831017e-44f, 0), v3(2.67648007e-43f, 8.96831017e-44f, 0)};
    sk_vec3 d[8];
    sk_frustum f;
    unsigned seed = 12345u;
    int i, k, t, outside = 0, solid = 0;
    for (t = 0; t < 2000; t++) {
        float unit = t == 0 ? 1.0f : ldexpf(1.0f, -149 + (t % 160));
        for (i = 0; i < 8; i++) {
            float *p = &d[i].x;
            for (k = 0; k < 3; k++) {
                seed = seed * 1664525u + 1013904223u;
                p[k] = t == 0 ? (&c[i].x)[k] : (float)(seed >> 24) * unit;
            }
        }
        if (sk_frustum_from_corners(d, &f) != SK_OK) continue;   /* coincident corners */
        solid++;
        {
            sk_sphere s = sk_frustum_bounding_sphere(&f);
            for (i = 0; i < 8; i++) {
                double dx = (double)f.corners[i].x - s.c.x, dy = (double)f.corners[i].y - s.c.y,
                       dz = (double)f.corners[i].z - s.c.z;
                if (sqrt(dx * dx + dy * dy + dz * dz) > s.r) outside++;
            }
        }
    }
    SK_CHECK_MSG(solid > 1900, "%d of 2000 frusta accepted", solid);
    SK_CHECK_MSG(outside == 0, "%d corners outside their sphere", outside);
}

/* fuzz_lspsm_region (crash-166dc055): a body 3 wide and 0.00024 long gives
   a trapezoid of theta = atan(12300), 8e-5 short of pi/2, where one float
   step of theta is 0.07% of tan theta; rounded to nearest, the legs passed
   inside the body's far corners by 0.0009. Now theta is rounded up and
   every clipped point is inside the trapezoid. */
static void test_region_steep_theta(void)
{
    const sk_vec3 c[8] = {v3(-1, -0.414213717f, -5.96046519e-08f), v3(1, -0.414213717f, -5.96046519e-08f),
                          v3(-1, 1, -1.41421366f),                  v3(1, 1, -1.41421366f),
                          v3(-1, 0.999999881f, 1.41421366f),        v3(1, 0.999999881f, 1.41421366f),
                          v3(-1, 2.41421366f, 5.96046412e-08f),     v3(1, 2.41421366f, 5.96046412e-08f)};
    sk_frustum view;
    sk_lspsm_region reg;
    sk_vec3 pts[SK_CLIP_MAX_POINTS];
    sk_aabb rec = box3(-1, -1136.4375f, -15.25f, -1, 2140.4375f, 15.25f);
    double t, worst = -1e30;
    int n, i;
    SK_CHECK(sk_frustum_from_corners(c, &view) == SK_OK);
    SK_CHECK(sk_lspsm_region_extract(&view, v3(-2, 0, 6.88542013e-41f), rec, NULL, v3(-2, 23038, 2048), &reg) == SK_OK);
    SK_CHECK_MSG(!reg.fallback && reg.theta > 1.5706f && (double)reg.theta < 0.5 * 3.14159265358979323846,
                 "theta %.9g fallback %d", reg.theta, reg.fallback);
    n = sk_clip_frustum_aabb(&view, rec, pts, SK_CLIP_MAX_POINTS);
    SK_CHECK(n > 0);
    t = tan((double)reg.theta);
    for (i = 0; i < n; i++) {
        const float *m = reg.light_view.m;
        double x = (double)m[0] * pts[i].x + (double)m[4] * pts[i].y + (double)m[8] * pts[i].z + m[12];
        double y = (double)m[1] * pts[i].x + (double)m[5] * pts[i].y + (double)m[9] * pts[i].z + m[13];
        double out = fabs(x - reg.origin.x) - (0.5 * reg.n + (y - reg.origin.y) * t);
        if (out > worst) worst = out;
    }
    /* within float placement of the points (1e-6 of the region's 3 units),
       not 0.0009 outside */
    SK_CHECK_MSG(worst <= 3e-6, "a point %.3g outside the trapezoid", worst);
}

/* fuzz_lispsm (crash-ade32137): a segment from (0,0,0) to (0.25,0.25,0),
   256 from the eye, seen almost end-on from the warp's projection centre
   (n = 0.6): in the warped space it is 5.5e-4 wide in x at x = 0.68, while
   the light-space coordinates it was warped from carry float errors of
   1e-5 (magnitude 256), 7e-5 once divided by w = n. The crop was fitted as
   if the warped points were exact and (0,0,0) landed at x = -1.035.
   Warped sides are now widened by the magnitude their float error comes
   from, and every body point is in the map. */
static void test_lispsm_warped_sliver(void)
{
    sk_lispsm_desc d;
    sk_lispsm_result r;
    sk_vec3 body[9];
    int i;
    body[0] = v3(0.25f, 0.25f, 0);
    for (i = 1; i < 9; i++) body[i] = v3(0, 0, 0);
    memset(&d, 0, sizeof d);
    d.eye = v3(256, 0, 0.25f);
    d.view_dir = v3(1000, 1.57079637f, 0.25f);
    d.zn = 0.25f;
    d.light_dir = v3(0.25f, 2.64992679e+17f, 2.4810418e+17f);
    d.body = body;
    d.body_count = 9;
    SK_CHECK(sk_lispsm_matrices(&d, &r) == SK_OK);
    SK_CHECK_MSG(r.warped == 1, "warped %d n %g", r.warped, r.n);
    for (i = 0; i < 2; i++) {
        sk_vec4 p, q;
        p.x = body[i].x; p.y = body[i].y; p.z = body[i].z; p.w = 1.0f;
        q = sk_mat4_transform_vec4(r.light_view_proj, p);
        SK_CHECK_MSG(q.w > 0.0f && fabsf(q.x / q.w) <= 1.001f && fabsf(q.y / q.w) <= 1.001f &&
                         fabsf(q.z / q.w) <= 1.001f,
                     "body %d maps to (%g %g %g; w %g)", i, q.x / q.w, q.y / q.w, q.z / q.w, q.w);
    }
}

/* fuzz_psm (crash-5231f331): the light behind the viewer, the virtual
   camera slid back 59 for a caster behind it (near 0.5): the light on
   z = (f+n)/(f-n) lay 0.017 beyond the body in post-perspective space, so
   the body's tangent coordinates, x / depth, carried some 120 times the
   float error of its coordinates. The fit kept a side 0.0147 wide at an
   offset of 21.6 (the floor was 1e-4 of the offset), and the body point in
   view landed at y = -1.0185. The floor now grows with that magnification
   and the point lands inside. */
static void test_psm_light_near_body(void)
{
    static const float cv[16] = {3.62199892e-37f, -0.99999994f, -0.0f, 0, 0.956673861f, 3.46507165e-37f, 0.291161627f, 0,
                                 -0.291161627f, -1.05458707e-37f, 0.956673861f, 0, -0.0f, -0.0f, -4.4157507e-39f, 1};
    sk_aabb casters[4];
    sk_vec3 body[4];
    sk_psm_desc d;
    sk_psm_result r;
    sk_mat4 cvp;
    int i, in_view = 0;
    casters[0] = box3(9.18354962e-41f, 0, -4.02677127e-41f, 9.18354962e-41f, 0, 4.60074312e-41f);
    casters[1] = box3(-144.570312f, -144.570312f, -289.140625f, 144.570312f, 144.570312f, 0);
    casters[2] = box3(0, 0, 3.53127213e-43f, 0.00384521484f, 0, 5.83155401e-39f);
    casters[3] = box3(127.5f, 0.50378418f, 59, 127.5f, 0.50378418f, 61);
    body[0] = v3(2.36472815e-38f, 2.35371507e-38f, -2);
    body[1] = v3(510, 0.0116577148f, 0);
    body[2] = v3(0, 0, 0);
    body[3] = v3(0, 0, 0);
    memset(&d, 0, sizeof d);
    memcpy(d.cam_view.m, cv, sizeof cv);
    d.fovy = 1.0f; d.aspect = 1.5f; d.zn = 0.50378418f; d.zf = 44.0078125f;
    d.light_dir = v3(0, 0, -1);
    d.casters = casters; d.caster_count = 4;
    d.body = body; d.body_count = 4;
    SK_CHECK(sk_psm_matrices(&d, &r) == SK_OK);
    SK_CHECK(r.inverted == 1 && r.orthographic == 0 && r.slide > 59.0f);
    cvp = sk_mat4_mul(sk_mat4_perspective(d.fovy, d.aspect, d.zn, d.zf), d.cam_view);
    for (i = 0; i < 4; i++) {   /* the body points in the camera's own view */
        sk_vec4 p, c, q;
        p.x = body[i].x; p.y = body[i].y; p.z = body[i].z; p.w = 1.0f;
        c = sk_mat4_transform_vec4(cvp, p);
        if (!(c.w > 0.0f && fabsf(c.x) < c.w && fabsf(c.y) < c.w && fabsf(c.z) < c.w)) continue;
        in_view++;
        q = sk_mat4_transform_vec4(r.light_view_proj, p);
        SK_CHECK_MSG(q.w > 0.0f && fabsf(q.x / q.w) <= 1.001f && fabsf(q.y / q.w) <= 1.001f, "body %d maps to (%g %g)",
                     i, q.x / q.w, q.y / q.w);
    }
    SK_CHECK(in_view == 1);
}

SK_TEST_MAIN(test_denormal_directions, test_psm_denormal_pp_light, test_clip_huge_box, test_partition_unrepresentable,
             test_crops_unrepresentable, test_region_flat_body, test_vsdct_huge_atlas, test_frustum_through_infinity,
             test_frustum_plane_overflow, test_caster_tiny, test_scissor_underflow, test_psm_flat_body,
             test_lispsm_sin_gamma, test_crop_matrix_thin_axis, test_spheres_overflow, test_pvsm_huge_footprint,
             test_smooth_box_thin, test_resolution_texel_overflow, test_psm_flat_body_ortho, test_lispsm_flat_bodies,
             test_look_at_overflow, test_ortho_crops_overflow, test_sphere_subnormal,
             test_region_steep_theta, test_lispsm_warped_sliver, test_psm_light_near_body)
