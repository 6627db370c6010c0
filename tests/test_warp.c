/* test_warp.c - perspective warping: PSM (Stamminger & Drettakis 2002)
   and LiSPSM (Wimmer, Scherzer & Purgathofer 2004).

   Tests sk_psm_matrices and sk_lispsm_matrices. The oracle is geometric and
   computed here in double from this file's own camera model:
   - every point the map must cover (view-frustum samples, caster corners, the
     LiSPSM body from this file's own frustum/box clip) lands in the light clip
     volume (w > 0, |x|,|y|,|z| <= w);
   - two points on one light ray land on the same texel, and their depth order
     matches the reported compare (PSM) or the standard LESS test (LiSPSM);
   - the PSM cases of Romanick's VGP353 slides: light in front, light behind the
     viewer (inverted, GREATER), perpendicular light (orthographic), casters
     behind the camera (virtual camera slid back);
   - LiSPSM's n_opt = (zn + sqrt(zn*zf'))/sin(gamma), zf' = zn + d*sin(gamma),
     its growth towards the uniform map as the light becomes parallel to the
     view, and the resolution it gains near the eye. */
#define SHADOWKIT_IMPLEMENTATION
#include "shadowkit.h"
#include "tests/sk_test.h"
#include "tests/sk_ref.h"
#include <float.h>

/* ---------------------------------------------------------------- helpers */
static dv3 dlerp(dv3 a, dv3 b, double t) { return dadd(a, dmul(dsub(b, a), t)); }
static double deg(double d) { return d * T_PI / 180.0; }

static dv3 box_corner(sk_aabb b, int k) {
    return dv((k & 1) ? b.max.x : b.min.x, (k & 2) ? b.max.y : b.min.y, (k & 4) ? b.max.z : b.min.z);
}

/* ------------------------------------------------------------------ camera */
static cam make_cam(dv3 eye, dv3 target, dv3 up_hint, double fovy, double aspect, double zn, double zf) {
    cam c = cam_frame(eye, target, up_hint, fovy, aspect, zn, zf);
    c.view = sk_mat4_look_at(tof(eye), tof(target), tof(up_hint));
    {   /* core-math sanity: the view matrix maps the eye to 0 and fwd to -z */
        double q[4], r[4];
        xform(&c.view, eye, q);
        xform(&c.view, dadd(eye, c.fwd), r);
        SK_CHECK_MSG(fabs(q[0]) + fabs(q[1]) + fabs(q[2]) < 1e-4 * (1 + dlen(eye)) &&
                     fabs(r[0]) + fabs(r[1]) + fabs(r[2] + 1) < 1e-4 * (1 + dlen(eye)),
                     "sk_mat4_look_at disagrees with the test's camera (core math)");
    }
    return c;
}

static int in_frustum(const cam *c, dv3 p, double margin) {
    int i;
    for (i = 0; i < 6; i++) if (ddot(c->planes[i].n, p) + c->planes[i].d < margin) return 0;
    return 1;
}

/* trilinear samples of the frustum (corners included): k^3 points */
static int frustum_samples(const cam *c, int k, dv3 *out) {
    int i, j, l, n = 0;
    for (i = 0; i < k; i++)
        for (j = 0; j < k; j++)
            for (l = 0; l < k; l++) {
                double u = (double)i / (k - 1), v = (double)j / (k - 1), w = (double)l / (k - 1);
                dv3 a = dlerp(c->corners[0], c->corners[1], u), b = dlerp(c->corners[2], c->corners[3], u);
                dv3 e = dlerp(c->corners[4], c->corners[5], u), f = dlerp(c->corners[6], c->corners[7], u);
                out[n++] = dlerp(dlerp(a, b, v), dlerp(e, f, v), w);
            }
    return n;
}



/* how many of pts fall outside the clip volume of m (w > 0, |xyz| <= w(1+tol)) */
static int count_outside(const sk_mat4 *m, const dv3 *pts, int n, double tol, int *worst_i, double *worst) {
    int i, out = 0;
    *worst_i = -1; *worst = 0;
    for (i = 0; i < n; i++) {
        double q[4], e;
        xform(m, pts[i], q);
        if (!(q[3] > 0)) { out++; *worst_i = i; *worst = 1e30; continue; }
        e = fabs(q[0]);
        if (fabs(q[1]) > e) e = fabs(q[1]);
        if (fabs(q[2]) > e) e = fabs(q[2]);
        e = e / q[3] - 1.0;
        if (e > tol) { out++; if (e > *worst) { *worst = e; *worst_i = i; } }
    }
    return out;
}

/* Light-ray consistency: p and p + s*dir (p nearer the light) on one texel,
   depth order as 'greater' says. Returns the number of pairs tested. */
static int in_box(const sk_aabb *b, dv3 p) {
    return !b || (p.x >= b->min.x && p.x <= b->max.x && p.y >= b->min.y && p.y <= b->max.y &&
                  p.z >= b->min.z && p.z <= b->max.z);
}
/* pairs: p (inside the view frustum and 'within' when given) and p + s*dir,
   s = step, 2 step, 3 step, when that is inside as well */
static int check_ray_order(const char *name, const sk_mat4 *m, const dv3 *pts, int n, dv3 dir, const cam *c,
                           int greater, double step, const sk_aabb *within) {
    int i, k, tested = 0, bad_order = 0, bad_texel = 0;
    double span = c->zf - c->zn;
    dir = dnorm(dir);
    for (i = 0; i < n; i++) {
        if (!in_frustum(c, pts[i], 1e-6 * span) || !in_box(within, pts[i])) continue;
        for (k = 1; k <= 3; k++) {
            double s = step * k, a[4], b[4], za, zb;
            dv3 q = dadd(pts[i], dmul(dir, s));
            if (!in_frustum(c, q, 1e-6 * span) || !in_box(within, q)) continue;
            xform(m, pts[i], a);
            xform(m, q, b);
            if (!(a[3] > 0 && b[3] > 0)) { bad_order++; continue; }
            za = a[2] / a[3]; zb = b[2] / b[3];
            if (greater ? !(za > zb) : !(za < zb)) bad_order++;
            if (fabs(a[0] / a[3] - b[0] / b[3]) > 2e-3 || fabs(a[1] / a[3] - b[1] / b[3]) > 2e-3) bad_texel++;
            tested++;
        }
    }
    SK_CHECK_MSG(bad_order == 0, "%s: %d of %d pairs along a light ray in the wrong depth order for %s",
                 name, bad_order, tested, greater ? "GREATER" : "LESS");
    SK_CHECK_MSG(bad_texel == 0, "%s: %d of %d pairs along a light ray on different texels", name, bad_texel, tested);
    return tested;
}

/* ===================================================================== PSM */
static sk_psm_desc psm_desc(const cam *c, dv3 light) {
    sk_psm_desc d;
    memset(&d, 0, sizeof d);
    d.cam_view = c->view;
    d.fovy = (float)c->fovy; d.aspect = (float)c->aspect; d.zn = (float)c->zn; d.zf = (float)c->zf;
    d.light_dir = tof(light);
    d.casters = NULL; d.caster_count = 0;
    return d;
}

/* expect_inverted / expect_ortho / expect_reach (some caster sample shadows the
   view): 0 or 1, or -1 for "not asserted" */
static void psm_case_r(const char *name, const cam *c, dv3 light, int expect_inverted, int expect_ortho,
                       const sk_aabb *casters, int ncasters, int expect_reach) {
    sk_psm_desc d = psm_desc(c, light);
    sk_psm_result r;
    sk_result res;
    dv3 pts[125 + 64];
    int n = frustum_samples(c, 5, pts), wi, k, j, out;
    double worst;
    d.casters = casters; d.caster_count = ncasters;
    memset(&r, 0, sizeof r);
    res = sk_psm_matrices(&d, &r);
    SK_CHECK_MSG(res == SK_OK, "%s: %s", name, sk_result_string(res));
    if (res != SK_OK) return;
    SK_CHECK_MSG(all_finite_mat(&r.light_view_proj) && all_finite_mat(&r.virtual_cam_view_proj) && finite_d(r.light_pp.x) &&
                 finite_d(r.light_pp.y) && finite_d(r.light_pp.z) && finite_d(r.slide),
                 "%s: non-finite result", name);
    SK_CHECK_MSG(r.slide >= 0, "%s: slide %g < 0", name, r.slide);
    {   /* the virtual camera sits 'slide' behind the eye, looking the same way:
           its clip w is the depth from the virtual eye */
        double q0[4], q1[4];
        xform(&r.virtual_cam_view_proj, c->eye, q0);
        xform(&r.virtual_cam_view_proj, dadd(c->eye, dmul(c->fwd, 10.0)), q1);
        SK_CHECK_MSG(fabs(q0[3] - r.slide) <= 1e-4 * (1 + r.slide) && fabs(q1[3] - q0[3] - 10.0) <= 1e-3,
                     "%s: virtual camera w at the eye %g (slide %g), 10 units ahead %g", name, q0[3], r.slide, q1[3]);
    }
    SK_CHECK_MSG(r.inverted == 0 || r.inverted == 1, "%s: inverted = %d", name, r.inverted);
    SK_CHECK_MSG(r.orthographic == 0 || r.orthographic == 1, "%s: orthographic = %d", name, r.orthographic);
    SK_CHECK_MSG((r.compare == SK_DEPTH_GREATER) == (r.inverted == 1),
                 "%s: compare %d inconsistent with inverted %d", name, (int)r.compare, r.inverted);
    if (expect_inverted >= 0) {
        SK_CHECK_MSG(r.inverted == expect_inverted, "%s: inverted %d, expected %d", name, r.inverted, expect_inverted);
        SK_CHECK_MSG(r.compare == (expect_inverted ? SK_DEPTH_GREATER : SK_DEPTH_LESS), "%s: compare %d", name,
                     (int)r.compare);
    }
    if (expect_ortho >= 0)
        SK_CHECK_MSG(r.orthographic == expect_ortho, "%s: orthographic %d, expected %d", name, r.orthographic, expect_ortho);
    /* light_pp: the post-perspective light. Rays of the directional light become
       lines through it (or, orthographic, parallel to it); without a slide it lies
       on the plane z = (f+n)/(f-n) (Stamminger and Drettakis 2002) */
    {
        int i2, bad = 0, tested = 0;
        dv3 lp = tod(r.light_pp), dir = dnorm(light);
        if (!r.orthographic && r.slide == 0)
            SK_CHECK_MSG(fabs(lp.z - (c->zf + c->zn) / (c->zf - c->zn)) <= 1e-4 * (c->zf + c->zn) / (c->zf - c->zn),
                         "%s: light_pp.z %g, expected (f+n)/(f-n) = %g", name, lp.z, (c->zf + c->zn) / (c->zf - c->zn));
        for (i2 = 0; i2 < n; i2 += 7) {
            dv3 p = dlerp(pts[i2], dadd(c->eye, dmul(c->fwd, 0.3 * (c->zn + c->zf))), 0.5);
            dv3 q = dadd(p, dmul(dir, 0.5));
            double a[4], b[4];
            dv3 pa, pb, u, w;
            xform(&r.virtual_cam_view_proj, p, a);
            xform(&r.virtual_cam_view_proj, q, b);
            if (!(a[3] > 0 && b[3] > 0)) continue;
            pa = dv(a[0] / a[3], a[1] / a[3], a[2] / a[3]);
            pb = dv(b[0] / b[3], b[1] / b[3], b[2] / b[3]);
            u = dsub(pb, pa);
            w = r.orthographic ? lp : dsub(lp, pa);
            if (dlen(u) < 1e-5) continue;
            tested++;
            if (dlen(dcross(dnorm(u), dnorm(w))) > 2e-3) bad++;
        }
        SK_CHECK_MSG(bad == 0 && tested > 0, "%s: %d of %d light rays do not pass through light_pp (%g, %g, %g)", name,
                     bad, tested, lp.x, lp.y, lp.z);
    }
    /* the whole view frustum is in the light clip volume */
    out = count_outside(&r.light_view_proj, pts, n, 2e-3, &wi, &worst);
    SK_CHECK_MSG(out == 0, "%s: %d of %d view-frustum samples outside the light clip volume (worst #%d by %g)",
                 name, out, n, wi, worst);
    /* casters: in front of the virtual camera and of the light (w > 0), inside the
       map's depth range; and in the map (x, y too) wherever their shadow can reach
       the view: every caster sample whose light ray enters the view frustum.
       (A caster part whose light ray misses the view frustum shadows nothing
       visible; its x, y may lie outside the map.) */
    for (j = 0; j < ncasters; j++) {
        dv3 cc[8], samp[125];
        int ns = 0, a, b2, e, reach = 0, miss = 0;
        double span = c->zf - c->zn;
        for (k = 0; k < 8; k++) cc[k] = box_corner(casters[j], k);
        for (k = 0; k < 8; k++) {
            double q[4];
            xform(&r.light_view_proj, cc[k], q);
            SK_CHECK_MSG(q[3] > 0 && fabs(q[2]) <= q[3] * (1 + 2e-3),
                         "%s: caster %d corner %d outside the map's depth range (z/w %g, w %g)", name, j, k,
                         q[2] / q[3], q[3]);
            xform(&r.virtual_cam_view_proj, cc[k], q);
            SK_CHECK_MSG(q[3] > 0, "%s: caster corner %d behind the virtual camera (w = %g)", name, k, q[3]);
        }
        for (a = 0; a < 5; a++)
            for (b2 = 0; b2 < 5; b2++)
                for (e = 0; e < 5; e++)
                    samp[ns++] = dv(casters[j].min.x + (casters[j].max.x - casters[j].min.x) * a / 4.0,
                                    casters[j].min.y + (casters[j].max.y - casters[j].min.y) * b2 / 4.0,
                                    casters[j].min.z + (casters[j].max.z - casters[j].min.z) * e / 4.0);
        for (k = 0; k < ns; k++) {
            double s;
            int hits = 0;
            dv3 dir = dnorm(light);
            for (s = 0; s <= 2 * span && !hits; s += span / 400) hits = in_frustum(c, dadd(samp[k], dmul(dir, s)), 0);
            if (!hits) continue;
            reach++;
            out = count_outside(&r.light_view_proj, &samp[k], 1, 2e-3, &wi, &worst);
            if (out) miss++;
        }
        SK_CHECK_MSG(miss == 0, "%s: %d of %d caster %d samples that shadow the view are outside the map",
                     name, miss, reach, j);
        if (expect_reach >= 0)
            SK_CHECK_MSG((reach > 0) == (expect_reach > 0), "%s: test set-up: %d caster samples reach the view",
                         name, reach);
    }
    /* a light ray is one texel; depth order as reported */
    {
        dv3 inner[125];
        int ni = 0, i;
        for (i = 0; i < n; i++) if (in_frustum(c, pts[i], 1e-6)) inner[ni++] = pts[i];
        /* add interior samples: pull the samples towards the frustum's centre */
        {
            dv3 centre = dadd(c->eye, dmul(c->fwd, 0.3 * (c->zn + c->zf)));
            for (i = 0; i < n && ni < 125; i++) inner[ni++] = dlerp(pts[i], centre, 0.3);
        }
        k = check_ray_order(name, &r.light_view_proj, inner, ni, light, c, r.compare == SK_DEPTH_GREATER,
                            0.04 * (c->zf - c->zn), NULL);
        SK_CHECK_MSG(k >= 10, "%s: only %d light-ray pairs tested", name, k);
    }
}

static void psm_case(const char *name, const cam *c, dv3 light, int expect_inverted, int expect_ortho,
                     const sk_aabb *casters, int ncasters) {
    psm_case_r(name, c, light, expect_inverted, expect_ortho, casters, ncasters, -1);
}

static cam cam_a(void) {
    return make_cam(dv(0, 2, 0), dv(0, 2, -1), dv(0, 1, 0), deg(60), 1.33, 0.5, 50.0);
}
static cam cam_b(void) {
    return make_cam(dv(3, 5, 8), dv(0, 0, -10), dv(0, 1, 0), deg(45), 1.78, 0.1, 100.0);
}

static void test_psm_cases(void) {
    cam a = cam_a(), b = cam_b();
    /* light travelling towards the camera: in front of the viewer, normal depth test */
    psm_case("A front", &a, dv(0.3, -0.5, 1), 0, 0, NULL, 0);
    psm_case("A front low", &a, dv(-0.8, -0.1, 1), 0, 0, NULL, 0);
    /* light travelling along the view direction: behind the viewer, inverted */
    psm_case("A behind", &a, dv(0.3, -0.5, -1), 1, 0, NULL, 0);
    psm_case("A behind steep", &a, dv(0.1, -3, -1), 1, 0, NULL, 0);
    /* perpendicular: the light stays directional in post-perspective space */
    psm_case("A perpendicular down", &a, dv(0, -1, 0), 0, 1, NULL, 0);
    psm_case("A perpendicular side", &a, dv(1, 0, 0), 0, 1, NULL, 0);
    psm_case("A perpendicular oblique", &a, dv(0.6, -0.8, 0), 0, 1, NULL, 0);
    /* exactly parallel / anti-parallel to the view direction */
    psm_case("A parallel", &a, dv(0, 0, -1), 1, 0, NULL, 0);
    psm_case("A anti-parallel", &a, dv(0, 0, 1), 0, 0, NULL, 0);
    /* nearly perpendicular, either side */
    psm_case("A near-perpendicular +", &a, dv(0, -1, 1e-6), -1, -1, NULL, 0);
    psm_case("A near-perpendicular -", &a, dv(0, -1, -1e-6), -1, -1, NULL, 0);
    psm_case("A near-perpendicular 1e-3", &a, dv(0.2, -1, -1e-3), 1, 0, NULL, 0);
    /* a tilted camera */
    {
        dv3 v = b.fwd, side = dnorm(dcross(b.fwd, dv(0, 1, 0)));
        psm_case("B front", &b, dv(0.4, -1, 0.9), 0, 0, NULL, 0);
        psm_case("B behind", &b, dv(-0.2, -1, -0.7), 1, 0, NULL, 0);
        psm_case("B perpendicular", &b, dcross(v, side), 0, 1, NULL, 0);
        psm_case("B parallel", &b, v, 1, 0, NULL, 0);
        psm_case("B anti-parallel", &b, dmul(v, -1), 0, 0, NULL, 0);
    }
}

static void test_psm_casters_behind(void) {
    cam a = cam_a();
    sk_aabb behind = box3(-0.5f, 2.2f, 0.5f, 0.5f, 2.8f, 1.5f);          /* z > 0: behind the eye at z = 0 */
    sk_aabb two[2];
    dv3 light = dv(0, -0.4, -1);    /* shallow enough for the caster's shadow to enter the view */
    sk_psm_desc d;
    sk_psm_result r;
    sk_aabb many[200];
    int i;
    two[0] = behind;
    two[1] = box3(-2, 0, -10, 2, 1, -8);                                /* one in view as well */
    psm_case_r("casters behind, light behind", &a, light, 1, 0, &behind, 1, 1);
    psm_case_r("casters behind, steep light behind", &a, dv(0, -0.6, -1), 1, 0, &behind, 1, -1);
    psm_case_r("casters behind, light in front", &a, dv(0.2, -0.6, 1), 0, 0, &behind, 1, 0);
    psm_case_r("casters behind, light perpendicular", &a, dv(0, -1, 0), 0, 1, &behind, 1, -1);
    psm_case_r("two casters", &a, light, 1, 0, two, 2, -1);
    /* a realistic caster list: 200 boxes, some behind the camera */
    for (i = 0; i < 200; i++) {
        float x = (float)(i % 20) - 10.0f, z = -(float)(i / 20) * 4.0f + 6.0f;
        many[i] = box3(x, 0.0f, z, x + 0.5f, 1.0f + (float)(i % 3), z + 0.5f);
    }
    psm_case_r("200 casters", &a, light, 1, 0, many, 200, -1);
    /* slide > 0, and the caster shadows the receiver on its light ray */
    d = psm_desc(&a, light);
    d.casters = &behind; d.caster_count = 1;
    memset(&r, 0, sizeof r);
    if (sk_psm_matrices(&d, &r) == SK_OK) {
        dv3 cc = dv(0, 2.5, 1.0), dir = dnorm(light), rec;
        double s, qa[4], qb[4];
        SK_CHECK_MSG(r.slide > 0, "caster behind the camera but slide = %g", r.slide);
        /* walk along the light ray from the caster centre until inside the view frustum, well inside */
        for (s = 0.5; s < 60; s += 0.25)
            if (in_frustum(&a, dadd(cc, dmul(dir, s)), 0.5)) break;
        rec = dadd(cc, dmul(dir, s + 1.0));
        SK_CHECK(in_frustum(&a, rec, 0.0));
        xform(&r.light_view_proj, cc, qa);
        xform(&r.light_view_proj, rec, qb);
        SK_CHECK_MSG(qa[3] > 0 && qb[3] > 0, "w %g, %g", qa[3], qb[3]);
        if (qa[3] > 0 && qb[3] > 0) {
            double za = qa[2] / qa[3], zb = qb[2] / qb[3];
            SK_CHECK_MSG(r.compare == SK_DEPTH_GREATER ? za > zb : za < zb,
                         "caster behind the camera does not shadow its receiver: caster z %g, receiver z %g, compare %d",
                         za, zb, (int)r.compare);
            SK_CHECK_NEAR(qa[0] / qa[3], qb[0] / qb[3], 2e-3);
            SK_CHECK_NEAR(qa[1] / qa[3], qb[1] / qb[3], 2e-3);
        }
    } else {
        SK_CHECK_MSG(0, "sk_psm_matrices failed with a caster behind the camera");
    }
    /* a caster only in front of the camera (inside the view): nothing to slide for */
    {
        sk_aabb front = box3(-1, 0, -12, 1, 2, -10);
        psm_case("caster in view", &a, light, 1, 0, &front, 1);
    }
}

/* The focus body: the light frustum is fitted to the receivers in
   post-perspective space (tight: they touch the map's edges) instead of to
   the whole view frustum. extra_slide: the virtual camera and its near plane
   move back by exactly that much; the view frustum stays inside the map and
   depth order along light rays holds. */
static void test_psm_body_and_slide(void) {
    cam a = cam_a();
    sk_aabb recv = box3(-3, 0, -20, 3, 1, -4);
    dv3 bodyd[256], pts[125 + 64];
    sk_vec3 body[256];
    static const double lights[3][3] = {{0.3, -0.5, 1}, {0.3, -0.5, -1}, {0, -1, 0}};
    int nb = clip_body(&a, recv, bodyd, 256), n = frustum_samples(&a, 5, pts), i, k, wi;
    double worst;
    SK_CHECK(nb >= 8 && nb <= SK_CLIP_MAX_POINTS);
    for (i = 0; i < nb; i++) body[i] = tof(bodyd[i]);
    for (k = 0; k < 3; k++) {
        dv3 l = dv(lights[k][0], lights[k][1], lights[k][2]);
        sk_psm_desc d = psm_desc(&a, l);
        sk_psm_result full, fit, slid;
        double lo[2][2] = {{1e30, 1e30}, {1e30, 1e30}}, hi[2][2] = {{-1e30, -1e30}, {-1e30, -1e30}};
        int j, c, q;
        SK_CHECK(sk_psm_matrices(&d, &full) == SK_OK);
        d.body = body; d.body_count = nb;
        SK_CHECK(sk_psm_matrices(&d, &fit) == SK_OK);
        SK_CHECK_MSG(count_outside(&fit.light_view_proj, bodyd, nb, 2e-3, &wi, &worst) == 0,
                     "light %d: body point %d outside the fitted map by %g", k, wi, worst);
        for (q = 0; q < 2; q++)
            for (j = 0; j < nb; j++) {
                double h[4];
                xform(q ? &fit.light_view_proj : &full.light_view_proj, bodyd[j], h);
                for (c = 0; c < 2; c++) {
                    if (h[c] / h[3] < lo[q][c]) lo[q][c] = h[c] / h[3];
                    if (h[c] / h[3] > hi[q][c]) hi[q][c] = h[c] / h[3];
                }
            }
        /* tight on both axes, and more of the map spent on the receivers */
        for (c = 0; c < 2; c++)
            SK_CHECK_MSG(lo[1][c] < -0.99 && hi[1][c] > 0.99, "light %d axis %d: body spans [%g, %g] of the map", k,
                         c, lo[1][c], hi[1][c]);
        SK_CHECK_MSG((hi[1][0] - lo[1][0]) * (hi[1][1] - lo[1][1]) > 1.05 * (hi[0][0] - lo[0][0]) * (hi[0][1] - lo[0][1]),
                     "light %d: fitted area %g not above the whole-frustum fit's %g", k,
                     (hi[1][0] - lo[1][0]) * (hi[1][1] - lo[1][1]), (hi[0][0] - lo[0][0]) * (hi[0][1] - lo[0][1]));
        d.body = NULL; d.body_count = 0;
        d.extra_slide = 4.0f;
        SK_CHECK(sk_psm_matrices(&d, &slid) == SK_OK);
        SK_CHECK_NEAR(slid.slide, 4.0, 1e-5);
        SK_CHECK_MSG(count_outside(&slid.light_view_proj, pts, n, 2e-3, &wi, &worst) == 0,
                     "light %d, slid: view sample %d outside the map by %g", k, wi, worst);
        check_ray_order("extra slide", &slid.light_view_proj, pts, n, dnorm(l), &a, slid.compare == SK_DEPTH_GREATER,
                        0.5, NULL);
    }
}

static void test_psm_bad_input(void) {
    cam a = cam_a();
    sk_psm_desc good = psm_desc(&a, dv(0.3, -0.5, 1)), d;
    sk_psm_result r, sentinel;
    sk_aabb cb[1];
    sk_result res;
    int i;
    memset(&sentinel, 0x5a, sizeof sentinel);
    sk_vec3 pts[SK_CLIP_MAX_POINTS + 1];
    for (i = 0; i <= SK_CLIP_MAX_POINTS; i++) pts[i] = v3(0, 1, -5);
    for (i = 0; i < 35; i++) {
        const sk_psm_desc *dp = &d;
        sk_psm_result *op = &r;
        d = good;
        cb[0] = box3(-1, 0, -12, 1, 2, -10);
        switch (i) {
        case 0: dp = NULL; break;
        case 1: op = NULL; break;
        case 2: d.light_dir = v3(0, 0, 0); break;
        case 3: d.light_dir.x = NAN; break;
        case 4: d.light_dir.y = INFINITY; break;
        case 5: d.light_dir.z = -INFINITY; break;
        case 6: d.fovy = 0.0f; break;
        case 7: d.fovy = -1.0f; break;
        case 8: d.fovy = (float)T_PI; break;
        case 9: d.fovy = NAN; break;
        case 10: d.aspect = 0.0f; break;
        case 11: d.aspect = -1.33f; break;
        case 12: d.aspect = INFINITY; break;
        case 13: d.zn = 0.0f; break;
        case 14: d.zn = -0.5f; break;
        case 15: d.zf = d.zn; break;
        case 16: d.zf = 0.1f; break;
        case 17: d.zf = INFINITY; break;
        case 18: d.zn = NAN; break;
        case 19: d.cam_view.m[13] = NAN; break;
        case 20: d.cam_view.m[0] = INFINITY; break;
        case 21: d.caster_count = -1; d.casters = cb; break;
        case 22: d.caster_count = 1; d.casters = NULL; break;
        case 23: cb[0].min.x = NAN; d.casters = cb; d.caster_count = 1; break;
        case 24: cb[0].max.z = INFINITY; d.casters = cb; d.caster_count = 1; break;
        case 25: d.light_dir = v3(1e-30f, 0, 0); d.light_dir.x = 0; d.light_dir.y = -0.0f; break;
        case 26: d.aspect = NAN; break;
        case 27: d.zf = NAN; break;
        case 28: d.body = pts; d.body_count = -1; break;
        case 29: d.body = pts; d.body_count = SK_CLIP_MAX_POINTS + 1; break;
        case 30: d.body = NULL; d.body_count = 3; break;
        case 31: pts[2].y = NAN; d.body = pts; d.body_count = 4; break;
        case 32: d.extra_slide = -1.0f; break;
        case 33: d.extra_slide = NAN; break;
        case 34: d.extra_slide = INFINITY; break;
        }
        memcpy(&r, &sentinel, sizeof r);
        res = sk_psm_matrices(dp, op);
        SK_CHECK_MSG(res == SK_ERR_INVALID_ARG, "bad input %d: %s", i, sk_result_string(res));
        SK_CHECK_MSG(memcmp(&r, &sentinel, sizeof r) == 0, "bad input %d: out was written", i);
    }
}

/* ================================================================== LiSPSM */
#define MAXB 256
typedef struct lcase {
    cam c;
    sk_aabb receivers;
    dv3 body[MAXB];
    sk_vec3 bodyf[MAXB];
    int nb;
} lcase;

static void lcase_init(lcase *L, cam c, sk_aabb receivers) {
    int i;
    L->c = c;
    L->receivers = receivers;
    L->nb = clip_body(&c, receivers, L->body, MAXB);
    for (i = 0; i < L->nb; i++) { L->bodyf[i] = tof(L->body[i]); L->body[i] = tod(L->bodyf[i]); }
    SK_CHECK_MSG(L->nb >= 4, "LiSPSM oracle body has %d points", L->nb);
}

static sk_lispsm_desc lispsm_desc(const lcase *L, dv3 light) {
    sk_lispsm_desc d;
    memset(&d, 0, sizeof d);
    d.eye = tof(L->c.eye);
    d.view_dir = tof(L->c.fwd);
    d.zn = (float)L->c.zn;
    d.light_dir = tof(light);
    d.body = L->bodyf;
    d.body_count = L->nb;
    d.casters = NULL;
    d.n_override = 0.0f;
    return d;
}

/* n_opt and sin(gamma) as documented, in double, from the float inputs */
static double n_opt_ref(const lcase *L, const sk_lispsm_desc *d, double *sin_gamma, double *depth) {
    dv3 v = dnorm(tod(d->view_dir)), l = dnorm(tod(d->light_dir));
    double sg = dlen(dcross(v, l)), lo = 1e300, hi = -1e300, zn = d->zn, zfp;
    int i;
    *sin_gamma = sg;
    if (sg == 0) { *depth = 0; return INFINITY; }
    {
        dv3 axis = dnorm(dsub(v, dmul(l, ddot(v, l))));
        for (i = 0; i < L->nb; i++) {
            double s = ddot(axis, L->body[i]);
            if (s < lo) lo = s;
            if (s > hi) hi = s;
        }
    }
    *depth = hi - lo;
    zfp = zn + *depth * sg;
    return (zn + sqrt(zn * zfp)) / sg;
}

/* The warp's projection centre: light clip w is affine in the world point and
   vanishes on the plane through the centre perpendicular to the warp axis, so
   w / |grad w| is the distance to that plane; at the body's near side it must
   be n (Wimmer et al.: the centre lies n before the body along the axis). A
   uniform map has constant w. */
static void check_warp_centre(const char *name, const lcase *L, const sk_lispsm_desc *d, const sk_lispsm_result *r) {
    const sk_mat4 *m = &r->light_view_proj;
    dv3 g = dv(m->m[3], m->m[7], m->m[11]);
    dv3 v = dnorm(tod(d->view_dir)), l = dnorm(tod(d->light_dir));
    double gl = dlen(g);
    int i;
    if (!r->warped) {
        double w0[4];
        xform(m, L->body[0], w0);
        SK_CHECK_MSG(gl <= 1e-6 * fabs(w0[3]), "%s: uniform map but w varies (|grad w| %g, w %g)", name, gl, w0[3]);
        return;
    }
    {
        dv3 axis = dnorm(dsub(v, dmul(l, ddot(v, l))));
        double lo = 1e300, bad = 0;
        SK_CHECK_MSG(gl > 0 && ddot(g, axis) / gl > 1 - 1e-4, "%s: w does not grow along the warp axis (cos %g)", name,
                     gl > 0 ? ddot(g, axis) / gl : 0.0);
        if (!(gl > 0)) return;
        for (i = 0; i < L->nb; i++) if (ddot(axis, L->body[i]) < lo) lo = ddot(axis, L->body[i]);
        for (i = 0; i < L->nb; i++) {
            double q[4], e;
            xform(m, L->body[i], q);
            e = fabs(q[3] / gl - (r->n + ddot(axis, L->body[i]) - lo));
            if (e > bad) bad = e;
        }
        SK_CHECK_MSG(bad <= 1e-3 * r->n, "%s: projection centre not at n = %g before the body (off by %g)", name, r->n, bad);
    }
}

static void check_lispsm_cover(const char *name, const lcase *L, const sk_lispsm_result *r, dv3 light) {
    int wi, out;
    double worst;
    out = count_outside(&r->light_view_proj, L->body, L->nb, 2e-3, &wi, &worst);
    SK_CHECK_MSG(out == 0, "%s: %d of %d body points outside the light clip volume (worst #%d by %g)",
                 name, out, L->nb, wi, worst);
    {   /* standard depth test: nearer the light = smaller depth; a light ray is one texel */
        dv3 inner[MAXB];
        int i, ni = 0;
        dv3 centre = dv(0, 0, 0);
        for (i = 0; i < L->nb; i++) centre = dadd(centre, dmul(L->body[i], 1.0 / L->nb));
        for (i = 0; i < L->nb && ni < MAXB; i++) inner[ni++] = dlerp(L->body[i], centre, 0.5);
        /* pairs along a light ray inside the body (frustum and receiver box) */
        i = check_ray_order(name, &r->light_view_proj, inner, ni, light, &L->c, 0, 0.2, &L->receivers);
        SK_CHECK_MSG(i >= 3, "%s: only %d light-ray pairs tested", name, i);
    }
}

static lcase g_lc;   /* big; static storage */

static void lispsm_setup_horizontal(void) {
    lcase_init(&g_lc, make_cam(dv(0, 2, 0), dv(0, 2, -1), dv(0, 1, 0), deg(60), 1.33, 0.5, 60.0),
               box3(-100, -1, -100, 100, 0, 100));
}

static void sweep(const char *family, double zsign) {
    static const double gammas[] = { 90, 75, 60, 45, 30, 20, 10, 5, 2, 1, 0.5, 0.1, 0.05, 0.01, 1e-3, 1e-4 };
    int i, ng = (int)(sizeof gammas / sizeof gammas[0]);
    double prev_n = 0;
    char name[96];
    for (i = 0; i < ng; i++) {
        double g = deg(gammas[i]);
        /* light travel direction at angle gamma from the view direction (0,0,-1) (zsign = 1)
           or from its opposite (zsign = -1), in the vertical plane */
        dv3 light = dv(0, -sin(g), -zsign * cos(g));
        sk_lispsm_desc d = lispsm_desc(&g_lc, light);
        sk_lispsm_result r;
        sk_result res;
        double sg, depth, nref;
        sprintf(name, "LiSPSM %s gamma %g deg", family, gammas[i]);
        memset(&r, 0, sizeof r);
        res = sk_lispsm_matrices(&d, &r);
        SK_CHECK_MSG(res == SK_OK, "%s: %s", name, sk_result_string(res));
        if (res != SK_OK) continue;
        nref = n_opt_ref(&g_lc, &d, &sg, &depth);
        SK_CHECK_MSG(all_finite_mat(&r.light_view_proj), "%s: matrix not finite", name);
        SK_CHECK_MSG(fabs(r.sin_gamma - sg) <= 1e-3 * sg + 2e-6, "%s: sin_gamma %.9g, expected %.9g", name, r.sin_gamma, sg);
        SK_CHECK_MSG(r.warped == 0 || r.warped == 1, "%s: warped %d", name, r.warped);
        SK_CHECK_MSG(r.warped ? finite_d(r.n) && r.n > 0 : r.n == INFINITY,
                     "%s: warped %d with n = %g", name, r.warped, r.n);
        if (nref < 0.5e4 * depth) {
            SK_CHECK_MSG(r.warped == 1, "%s: n_opt %g < 1e4*d = %g but warped = 0", name, nref, 1e4 * depth);
            SK_CHECK_MSG(fabs(r.n - nref) <= 1e-3 * nref, "%s: n = %.9g, n_opt = %.9g (d = %g, sin %g)", name, r.n,
                         nref, depth, sg);
        } else if (nref > 2e4 * depth) {
            SK_CHECK_MSG(r.warped == 0, "%s: n_opt %g > 1e4*d = %g but warped = 1", name, nref, 1e4 * depth);
        }
        SK_CHECK_MSG(r.n >= prev_n * (1 - 1e-4), "%s: n %g decreased from %g as the light became more parallel",
                     name, r.n, prev_n);
        prev_n = r.n;
        check_lispsm_cover(name, &g_lc, &r, light);
        check_warp_centre(name, &g_lc, &d, &r);
    }
    /* exactly parallel: uniform */
    {
        dv3 light = dv(0, 0, -zsign);
        sk_lispsm_desc d = lispsm_desc(&g_lc, light);
        sk_lispsm_result r;
        sk_result res;
        sprintf(name, "LiSPSM %s gamma 0", family);
        memset(&r, 0, sizeof r);
        res = sk_lispsm_matrices(&d, &r);
        SK_CHECK_MSG(res == SK_OK, "%s: %s", name, sk_result_string(res));
        if (res == SK_OK) {
            SK_CHECK_MSG(r.warped == 0, "%s: warped %d", name, r.warped);
            SK_CHECK_MSG(r.n == INFINITY, "%s: n %g", name, r.n);
            SK_CHECK_MSG(fabs(r.sin_gamma) <= 1e-6, "%s: sin_gamma %g", name, r.sin_gamma);
            SK_CHECK_MSG(all_finite_mat(&r.light_view_proj), "%s: matrix not finite", name);
            check_lispsm_cover(name, &g_lc, &r, light);
            check_warp_centre(name, &g_lc, &d, &r);
        }
    }
}

static void test_lispsm_sweep(void) {
    lispsm_setup_horizontal();
    sweep("light behind", 1.0);
    sweep("light in front", -1.0);
}

static void test_lispsm_oblique_and_override(void) {
    lcase *L = &g_lc;
    sk_lispsm_desc d;
    sk_lispsm_result r;
    sk_result res;
    static const double lights[5][3] = { {0.3, -1, -0.2}, {1, -0.4, 0.3}, {-0.2, -1, 0.8}, {0, -1, 0}, {0.7, -0.1, -0.7} };
    int i;
    /* a tilted camera */
    lcase_init(L, make_cam(dv(3, 6, 8), dv(0, 0, -15), dv(0, 1, 0), deg(50), 1.5, 0.3, 80.0),
               box3(-60, -2, -80, 60, 0.5, 40));
    for (i = 0; i < 5; i++) {
        dv3 light = dv(lights[i][0], lights[i][1], lights[i][2]);
        double sg, depth, nref;
        char name[64];
        sprintf(name, "LiSPSM tilted, light %d", i);
        d = lispsm_desc(L, light);
        memset(&r, 0, sizeof r);
        res = sk_lispsm_matrices(&d, &r);
        SK_CHECK_MSG(res == SK_OK, "%s: %s", name, sk_result_string(res));
        if (res != SK_OK) continue;
        nref = n_opt_ref(L, &d, &sg, &depth);
        SK_CHECK_MSG(all_finite_mat(&r.light_view_proj), "%s: not finite", name);
        SK_CHECK_MSG(r.warped == 1 && fabs(r.n - nref) <= 1e-3 * nref, "%s: warped %d n %.9g, n_opt %.9g", name,
                     r.warped, r.n, nref);
        SK_CHECK_MSG(fabs(r.sin_gamma - sg) <= 1e-4, "%s: sin_gamma %g, expected %g", name, r.sin_gamma, sg);
        check_lispsm_cover(name, L, &r, light);
        check_warp_centre(name, L, &d, &r);
        /* n_override */
        d.n_override = 3.0f;
        memset(&r, 0, sizeof r);
        res = sk_lispsm_matrices(&d, &r);
        SK_CHECK_MSG(res == SK_OK && r.n == 3.0f && r.warped == 1, "%s override 3: %s n %g warped %d", name,
                     sk_result_string(res), r.n, r.warped);
        if (res == SK_OK) { check_lispsm_cover(name, L, &r, light); check_warp_centre(name, L, &d, &r); }
        d.n_override = 250.0f;
        memset(&r, 0, sizeof r);
        res = sk_lispsm_matrices(&d, &r);
        SK_CHECK_MSG(res == SK_OK && r.n == 250.0f && r.warped == 1, "%s override 250: %s n %g warped %d", name,
                     sk_result_string(res), r.n, r.warped);
        if (res == SK_OK) { check_lispsm_cover(name, L, &r, light); check_warp_centre(name, L, &d, &r); }
    }
}

static double ndc_quad_area(const sk_mat4 *m, const dv3 q[4]) {
    double x[4], y[4], a = 0;
    int i;
    for (i = 0; i < 4; i++) {
        double c[4];
        xform(m, q[i], c);
        x[i] = c[0] / c[3]; y[i] = c[1] / c[3];
    }
    for (i = 0; i < 4; i++) a += x[i] * y[(i + 1) % 4] - x[(i + 1) % 4] * y[i];
    return fabs(a) / 2;
}

static void test_lispsm_resolution_near_eye(void) {
    lcase *L = &g_lc;
    dv3 light = dv(0, -1, 0), nearq[4], farq[4];
    sk_lispsm_desc d;
    sk_lispsm_result r;
    double a_near, a_far, a_uniform, xlo = 1e300, xhi = -1e300, zlo = 1e300, zhi = -1e300;
    int i;
    lispsm_setup_horizontal();
    d = lispsm_desc(L, light);
    memset(&r, 0, sizeof r);
    if (sk_lispsm_matrices(&d, &r) != SK_OK) { SK_CHECK_MSG(0, "LiSPSM perpendicular light failed"); return; }
    SK_CHECK(r.warped == 1);
    /* unit squares on the ground y = 0, near (z in [-5,-4]) and far (z in [-40,-39]) */
    nearq[0] = dv(-0.5, 0, -4); nearq[1] = dv(0.5, 0, -4); nearq[2] = dv(0.5, 0, -5); nearq[3] = dv(-0.5, 0, -5);
    for (i = 0; i < 4; i++) farq[i] = dv(nearq[i].x, 0, nearq[i].z - 35);
    a_near = ndc_quad_area(&r.light_view_proj, nearq);
    a_far = ndc_quad_area(&r.light_view_proj, farq);
    /* the uniform (focused, orthographic) map of the same body: NDC area 4 over the
       body's extent across and along the warp axis (x and z here) */
    for (i = 0; i < L->nb; i++) {
        if (L->body[i].x < xlo) xlo = L->body[i].x;
        if (L->body[i].x > xhi) xhi = L->body[i].x;
        if (L->body[i].z < zlo) zlo = L->body[i].z;
        if (L->body[i].z > zhi) zhi = L->body[i].z;
    }
    a_uniform = 4.0 / ((xhi - xlo) * (zhi - zlo));
    SK_CHECK_MSG(a_near > 2.0 * a_far, "near square %g, far square %g: no more resolution near the eye", a_near, a_far);
    SK_CHECK_MSG(a_near > a_uniform, "near square %g <= uniform map's %g", a_near, a_uniform);
    /* with n_override -> large the warp tends to the uniform map */
    d.n_override = 1e3f;
    memset(&r, 0, sizeof r);
    if (sk_lispsm_matrices(&d, &r) == SK_OK) {
        double b_near = ndc_quad_area(&r.light_view_proj, nearq), b_far = ndc_quad_area(&r.light_view_proj, farq);
        SK_CHECK_MSG(b_near < a_near && b_far > a_far, "n = 1000: near %g far %g vs n_opt near %g far %g",
                     b_near, b_far, a_near, a_far);
        SK_CHECK_MSG(fabs(b_near / b_far - 1) < 0.2, "n = 1000 should be nearly uniform: near %g far %g", b_near, b_far);
    }
}

static void test_lispsm_casters(void) {
    lcase *L = &g_lc;
    sk_aabb caster = box3(-0.5f, 3.0f, -15.0f, 0.5f, 4.0f, -14.0f);
    static const double lights[2][3] = { {0, -1, 0}, {0.3, -1, -0.2} };
    int i, k;
    lispsm_setup_horizontal();
    for (i = 0; i < 2; i++) {
        dv3 light = dv(lights[i][0], lights[i][1], lights[i][2]), cc[8];
        sk_lispsm_desc d = lispsm_desc(L, light);
        sk_lispsm_result r;
        int wi, out;
        double worst;
        d.casters = &caster;
        memset(&r, 0, sizeof r);
        if (sk_lispsm_matrices(&d, &r) != SK_OK) { SK_CHECK_MSG(0, "LiSPSM with casters failed"); continue; }
        for (k = 0; k < 8; k++) cc[k] = box_corner(caster, k);
        out = count_outside(&r.light_view_proj, cc, 8, 2e-3, &wi, &worst);
        SK_CHECK_MSG(out == 0, "light %d: %d caster corners above the body outside the map (worst #%d by %g)",
                     i, out, wi, worst);
        check_lispsm_cover("LiSPSM with casters", L, &r, light);
        /* the caster is nearer the light than the ground below it */
        {
            double a[4], b[4];
            dv3 top = dv(0, 3.5, -14.5), ground = dadd(top, dmul(dnorm(light), 3.5 / dnorm(light).y * -1.0));
            xform(&r.light_view_proj, top, a);
            xform(&r.light_view_proj, ground, b);
            SK_CHECK_MSG(a[3] > 0 && b[3] > 0 && a[2] / a[3] < b[2] / b[3], "light %d: caster not in front of the ground", i);
        }
    }
}

static void test_lispsm_bad_input(void) {
    lcase *L = &g_lc;
    sk_lispsm_desc good, d;
    sk_lispsm_result r, sentinel;
    sk_vec3 badbody[MAXB];
    sk_aabb cb;
    sk_result res;
    int i;
    lispsm_setup_horizontal();
    good = lispsm_desc(L, dv(0.3, -1, -0.2));
    memset(&sentinel, 0x5a, sizeof sentinel);
    for (i = 0; i < 25; i++) {
        const sk_lispsm_desc *dp = &d;
        sk_lispsm_result *op = &r;
        d = good;
        memcpy(badbody, L->bodyf, sizeof(sk_vec3) * (size_t)L->nb);
        cb = box3(-1, 3, -10, 1, 4, -9);
        switch (i) {
        case 0: dp = NULL; break;
        case 1: op = NULL; break;
        case 2: d.eye.x = NAN; break;
        case 3: d.eye.z = INFINITY; break;
        case 4: d.view_dir = v3(0, 0, 0); break;
        case 5: d.view_dir.y = NAN; break;
        case 6: d.view_dir.z = -INFINITY; break;
        case 7: d.light_dir = v3(0, 0, 0); break;
        case 8: d.light_dir.x = NAN; break;
        case 9: d.light_dir.y = -INFINITY; break;
        case 10: d.zn = 0.0f; break;
        case 11: d.zn = -0.5f; break;
        case 12: d.zn = NAN; break;
        case 13: d.zn = INFINITY; break;
        case 14: d.body = NULL; break;
        case 15: d.body_count = 0; break;
        case 16: d.body_count = -3; break;
        case 17: badbody[2].y = NAN; d.body = badbody; break;
        case 18: badbody[0].x = INFINITY; d.body = badbody; break;
        case 19: badbody[L->nb - 1].z = -INFINITY; d.body = badbody; break;
        case 20: cb.min.y = NAN; d.casters = &cb; break;
        case 21: cb.max.x = INFINITY; d.casters = &cb; break;
        case 22: d.n_override = NAN; break;
        case 23: d.n_override = INFINITY; break;
        case 24: d.body = NULL; d.body_count = 0; break;
        }
        memcpy(&r, &sentinel, sizeof r);
        res = sk_lispsm_matrices(dp, op);
        SK_CHECK_MSG(res == SK_ERR_INVALID_ARG, "bad input %d: %s", i, sk_result_string(res));
        SK_CHECK_MSG(memcmp(&r, &sentinel, sizeof r) == 0, "bad input %d: out was written", i);
    }
}

SK_TEST_MAIN(test_psm_cases, test_psm_casters_behind, test_psm_body_and_slide, test_psm_bad_input, test_lispsm_sweep,
             test_lispsm_oblique_and_override, test_lispsm_resolution_near_eye, test_lispsm_casters,
             test_lispsm_bad_input)
