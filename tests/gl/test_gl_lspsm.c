/* test_gl_lspsm.c - Light Space Partitioned Shadow Maps (LSPSM)
   through shadowkit_gl.h, against the exact Embree reference, next to
   PSSM, and at the configurations where the trapezoid degenerates. 400 x
   225, default bias (receiver plane) and PCF, the paper's parameters
   (zeta 0.25, sigma 0.5, h_max 4, nw_max 2). Errors: covered % (pixels
   misclassified over the covered ones, tb_metric_hard) and the
   shadow-area error (the same pixels over the reference's shadowed ones,
   tb_metric_shadow).

   Measured (Mesa 22.3 llvmpipe, OSMesa); "old": the previous reference
   and the normal-offset bias; "n-o": this reference with the normal-offset
   bias (SK_GL_TEST_BIAS=normal-offset); "1/4": a quarter of the
   resolution (SK_GL_TEST_RES_SCALE=0.25); "none": no bias at all
   (SK_GL_TEST_BIAS=none). Bounds about 1.4x the measurement.

   test_against_pssm - maps of 512^2 each, covered % / area %:
       view          lspsm (partitions)    pssm-8         pssm-4         bound        old     n-o / 1/4
       terrace-low   0.0418 / 1.58 (4)     0.0579 / 2.18  0.0708 / 2.67  0.06 / 2.2   0.0646  0.116 / 0.261
       terrace-side  0.0839 / 1.39 (4)     0.0460 / 0.76  0.0812 / 1.34  0.12 / 2.0   0.1265  0.200 / 0.360
       boxes         0.0810 / 3.79 (2)     0.0738 / 3.45  0.0846 / 3.96  0.115 / 5.4  0.2816  0.308 / 0.488
       fence         2.2494 / 27.5 (8)     0.6479 / 7.92  0.8859 / 10.8  3.2 / 39     3.4099  4.502 / 4.091
     (reference shadow: 824, 2237, 1188, 4708 pixels; n-o areas 4.37,
     3.31, 14.4, 55.1%, 1/4 areas 9.83, 5.95, 22.8, 50.0%: every bound
     fails both ways; previous bounds 0.11, 0.21, 0.45, 5.0% covered.)
     LSPSM uses 2 to 8 partitions where PSSM-8 always renders 8. With the
     normal-offset bias its error lay between PSSM-4's and PSSM-8's; with
     the receiver plane it does on the terrace-low view and the boxes, is
     level with PSSM-4 on terrace-side, and on the fence it is 3.5x
     PSSM-8's (false light on 22% of the shadow, all within a pixel of its
     edges: the slats' shadows thinner than LSPSM's texels there).

   test_failure_cases - 1024^2 per partition, covered % (pixels):
       parallel (view along the light: no axis)   0.0683% (42), fallback, 1 map
       near-parallel-2 (2 degrees off)            0.1202% (74), 1 partition
       wide-150 (150 degree lens: theta 72 deg)   0.0023% (1), 4 partitions
       zero-length (region 10 m x 0.19 m)         0.0117% (2), 1 partition;
                                                  the ledge's 2520-pixel
                                                  shadow all there but 2
     (old 0.0681, 0.1200, 0.0000, 0.0000%.) Looking along the light the
     only shadow in view is a strip a few centimetres wide under the slab's
     near edge, seen past it in perspective (42 and 74 pixels), which no
     map here resolves (the same figure at 1/16 of the resolution): the
     bounds there catch false shadow. The standard map's figures are the
     same (parallel, near-parallel), 2 pixels (wide-150) and 0 (zero-length).
     Asserted: finite matrices, the documented fallback exactly when the
     view is along the light, covered % under 0.10 / 0.17 / 0.006 /
     0.02% (previously 0.15 / 0.20 / 0.05 / 0.05%), at most NO_WORSE_PX (3)
     misclassified pixels more than the standard map (previously 0.01
     percentage point: zero-length's 2 pixels are 0.0117 point of its
     17100 covered pixels, an edge pixel rounding apart between two
     different maps), theta > 69 deg (wide-150), L < 0.05 n (zero-length),
     and where the view holds a real shadow (zero-length) false light and
     shadow-area error <= 0.12% of it (measured 0.079%, 2 pixels;
     previously false light <= 2%).
     Can fail: with no bias (none) parallel 0.387%, near-parallel 1.067%
     (acne); at 1/4 wide-150 0.0069% (3 pixels), zero-length 0.0819% with
     14 pixels more than the standard map and 0.556% of the shadow lit:
     each of these bounds fails. At 1/16 of the resolution zero-length
     gives 6.02% and 40.9% of its shadow wrong.
   Pictures: out/tests/lspsm-*.png and -error.png. */
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "sk_test.h"
#include "gl_test_util.h"

#include <math.h>

#define W 400
#define H 225

typedef gt_run_result lrun;

static lrun run(gt_env *e, const skgl_camera *cam, sk_vec3 light, const float *ref, skgl_technique t, int res,
                int cascades, const char *image) {
    skgl_shadow_desc d;
    memset(&d, 0, sizeof d);
    d.technique = t;
    d.resolution = (int)(res * gt_res_scale());
    d.cascades = cascades;
    return gt_run(e, cam, light, ref, &d, image);
}

typedef struct view_case {
    const char *label, *scene;
    float eye[3], target[3], light[3];
    double max_pct, max_area_pct;   /* covered %, shadow-area error % */
} view_case;

static void test_against_pssm(void) {
    static const view_case cases[] = {
        /* measured 0.0418% / 1.58% (old 0.0646%) */
        {"terrace-low", "terrace", {0, 2, 1}, {0, 0.5f, -30}, {0.7f, -1, 0.4f}, 0.06, 2.2},
        /* measured 0.0839% / 1.39% (old 0.1265%) */
        {"terrace-side", "terrace", {0, 2, 1}, {0, 0.5f, -30}, {0.8f, -0.75f, -0.6f}, 0.12, 2.0},
        /* measured 0.0810% / 3.79% (old 0.2816%) */
        {"boxes", "ground-boxes", {-9, 7, 12}, {0, 1, 0}, {-0.5f, -1, -0.35f}, 0.115, 5.4},
        /* measured 2.2494% / 27.5% (old 3.4099%) */
        {"fence", "fence", {1, 1.6f, 3.5f}, {0, 0.5f, 0}, {0.3f, -1, 0.6f}, 3.2, 39},
    };
    size_t c;
    for (c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        const view_case *k = &cases[c];
        gt_env e;
        skgl_camera cam = gt_camera(gt_v3(k->eye[0], k->eye[1], k->eye[2]),
                                    gt_v3(k->target[0], k->target[1], k->target[2]), 1.0f, 0.1f, 250, W, H);
        sk_vec3 l = gt_v3(k->light[0], k->light[1], k->light[2]);
        float *ref;
        lrun rl, r8, r4;
        char img[64], buf[256];
        if (gt_env_init_named(&e, k->scene, W, H) != 0) { gt_env_free(&e); continue; }
        ref = gt_alloc(&e);
        if (!ref || gt_gbuffer(&e, &cam) != 0 || gt_reference(&e, l, ref) != 0) { SK_CHECK(0); free(ref); gt_env_free(&e); continue; }
        snprintf(img, sizeof img, "lspsm-%s", k->label);
        rl = run(&e, &cam, l, ref, SKGL_LSPSM, 512, 0, img);
        r8 = run(&e, &cam, l, ref, SKGL_PSSM, 512, 8, NULL);
        r4 = run(&e, &cam, l, ref, SKGL_PSSM, 512, 4, NULL);
        printf("%-13s lspsm %.4f%% area %.4f%% (%d partitions, fallback %d)  pssm-8 %.4f%% area %.4f%%  pssm-4 %.4f%% "
               "area %.4f%%; lspsm %s\n", k->label, rl.pct, rl.se.area_pct, rl.st.maps, rl.st.lspsm_fallback, r8.pct,
               r8.se.area_pct, r4.pct, r4.se.area_pct, gt_shadow_error_str(&rl.se, buf, sizeof buf));
        SK_CHECK(rl.finite && rl.st.maps >= 1 && rl.st.maps <= 8 && rl.st.passes == rl.st.maps);
        SK_CHECK_MSG(rl.pct >= 0 && rl.pct < k->max_pct, "%s: lspsm %.4f%% >= %.3f%%", k->label, rl.pct, k->max_pct);
        SK_CHECK_MSG(rl.se.ok && rl.se.area_pct < k->max_area_pct, "%s: lspsm shadow-area error %.4f%% >= %.1f%%",
                     k->label, rl.se.area_pct, k->max_area_pct);
        free(ref);
        gt_env_free(&e);
    }
}

/* the region the GL pass extracts, recomputed here to report theta */
static sk_lspsm_region region_of(const gt_env *e, const skgl_camera *cam, sk_vec3 l) {
    sk_lspsm_region reg;
    sk_frustum f = sk_frustum_from_matrix(sk_mat4_mul(cam->proj, cam->view));
    sk_vec3 vd = gt_v3(-cam->view.m[2], -cam->view.m[6], -cam->view.m[10]);
    memset(&reg, 0, sizeof reg);
    if (sk_lspsm_region_extract(&f, vd, e->scene.bounds, &e->scene.bounds, l, &reg) != SK_OK) reg.fallback = -1;
    return reg;
}

typedef struct fail_case {
    const char *label, *scene;
    float eye[3], target[3], light[3];
    float fovy, zf;
    double max_pct;
    int expect_fallback;
} fail_case;

/* "open": a 400 m ground with a few boxes near the origin, so the view is
   clipped by its far plane, not by the scene's bounds; else a testbed scene */
static int env_for(gt_env *e, const char *name) {
    tb_scene sc;
    int i;
    char nm[16];
    if (strcmp(name, "wall") == 0) {
        /* a 1 cm wall and a 10 cm ledge: seen along -z under a near-vertical
           light, the region on the light plane is 10 m wide and ~0.1 m long */
        tb_scene_init(&sc);
        tb_scene_add_box(&sc, "wall", gt_v3(-5, 0, -10.01f), gt_v3(5, 4, -10));
        tb_scene_add_box(&sc, "ledge", gt_v3(-1, 2.9f, -10), gt_v3(1, 3, -9.9f));
        return gt_env_init(e, &sc, W, H);
    }
    if (strcmp(name, "open") != 0) return gt_env_init_named(e, name, W, H);
    tb_scene_init(&sc);
    tb_scene_add_ground(&sc, "ground", 0, 0, 200, 200, 0, 8, 8);
    for (i = 0; i < 9; i++) {
        float x = -8.0f + 2.0f * (float)i, z = -2.0f - 2.5f * (float)(i % 3);
        snprintf(nm, sizeof nm, "box%d", i);
        tb_scene_add_box(&sc, nm, gt_v3(x - 0.4f, 0, z - 0.4f), gt_v3(x + 0.4f, 1.2f + 0.3f * (float)(i % 4), z + 0.4f));
    }
    return gt_env_init(e, &sc, W, H);
}

/* LSPSM against the standard map, in misclassified pixels: measured at
   most 2 more (zero-length: an edge pixel rounding apart between two
   different maps) */
#define NO_WORSE_PX 3
/* false light and shadow-area error over a real shadow region, %:
   measured 0.079% (2 of zero-length's 2520 pixels) */
#define REAL_SHADOW_MAX_PCT 0.12

static void test_failure_cases(void) {
    static const fail_case cases[] = {
        /* straight down on the boxes, the light straight down: no axis */
        /* measured 0.0683% (42 pixels, old 0.0681%) */
        {"parallel", "ground-boxes", {0.5f, 30, 0.3f}, {0.5f, 0, 0.3f}, {0, -1, 0}, 1.0f, 250, 0.10, 1},
        /* measured 0.1202% (74 pixels, old 0.1200%) */
        {"near-parallel-2", "ground-boxes", {0.5f, 30, 0.3f}, {0.5f, 0, 0.3f}, {0.035f, -1, 0}, 1.0f, 250, 0.17, 0},
        /* a 150 degree lens held level: the trapezoid opens toward pi/2;
           measured 0.0023% (1 pixel, old 0): at most 2 */
        {"wide-150", "open", {0, 2.5f, 4}, {0, 1.0f, -10}, {0.4f, -1, -0.3f}, 2.6f, 12, 0.006, 0},
        /* measured 0.0117% (2 pixels, old 0): at most 3 */
        {"zero-length", "wall", {0, 2, 0}, {0, 2, -10}, {0, -1, -0.02f}, 1.0f, 30, 0.02, 0},
    };
    size_t c;
    for (c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        const fail_case *k = &cases[c];
        gt_env e;
        skgl_camera cam = gt_camera(gt_v3(k->eye[0], k->eye[1], k->eye[2]),
                                    gt_v3(k->target[0], k->target[1], k->target[2]), k->fovy, 0.1f, k->zf, W, H);
        sk_vec3 l = gt_v3(k->light[0], k->light[1], k->light[2]);
        float *ref;
        lrun rl, rs;
        sk_lspsm_region reg;
        char img[64], buf[256];
        if (env_for(&e, k->scene) != 0) { gt_env_free(&e); continue; }
        ref = gt_alloc(&e);
        if (!ref || gt_gbuffer(&e, &cam) != 0 || gt_reference(&e, l, ref) != 0) { SK_CHECK(0); free(ref); gt_env_free(&e); continue; }
        snprintf(img, sizeof img, "lspsm-%s", k->label);
        rl = run(&e, &cam, l, ref, SKGL_LSPSM, 1024, 0, img);
        rs = run(&e, &cam, l, ref, SKGL_STANDARD, 1024, 0, NULL);
        reg = region_of(&e, &cam, l);
        printf("%-16s lspsm %.4f%% area %.4f%% (%d partitions, fallback %d; theta %.1f deg, n %.3g, L %.3g)  standard "
               "%.4f%% area %.4f%% (%llu wrong); lspsm %s\n", k->label, rl.pct, rl.se.area_pct, rl.st.maps,
               rl.st.lspsm_fallback, reg.theta * 57.29578, reg.n, reg.L, rs.pct, rs.se.area_pct,
               (unsigned long long)rs.se.wrong, gt_shadow_error_str(&rl.se, buf, sizeof buf));
        SK_CHECK(rl.finite && rl.st.maps >= 1);
        SK_CHECK_MSG(rl.st.lspsm_fallback == k->expect_fallback, "%s: fallback %d", k->label, rl.st.lspsm_fallback);
        SK_CHECK_MSG(rl.pct >= 0 && rl.pct < k->max_pct, "%s: %.4f%% >= %.3f%%", k->label, rl.pct, k->max_pct);
        SK_CHECK_MSG(rl.se.wrong <= rs.se.wrong + NO_WORSE_PX, "%s: lspsm %llu pixels wrong (%.4f%%), standard %llu (%.4f%%)",
                     k->label, (unsigned long long)rl.se.wrong, rl.pct, (unsigned long long)rs.se.wrong, rs.pct);
        /* where the view holds a real shadow region (not just edges): it is there */
        if (rl.shadowed > 1000) {
            SK_CHECK_MSG(rl.false_lit_pct <= REAL_SHADOW_MAX_PCT, "%s: false light on %.4f%% of %zu shadowed pixels",
                         k->label, rl.false_lit_pct, rl.shadowed);
            SK_CHECK_MSG(rl.se.area_pct <= REAL_SHADOW_MAX_PCT, "%s: shadow-area error %.4f%%", k->label,
                         rl.se.area_pct);
        }
        if (strcmp(k->label, "wide-150") == 0)
            SK_CHECK_MSG(reg.theta > 1.2f, "wide-150: theta %.1f deg", reg.theta * 57.29578);
        if (strcmp(k->label, "zero-length") == 0)
            SK_CHECK_MSG(reg.L < 0.05f * reg.n, "zero-length: L %g, n %g", reg.L, reg.n);
        free(ref);
        gt_env_free(&e);
    }
}

/* partition limits past the texture array's layers are refused at create;
   b == 4: h_max * nw_max = 2^32 overflows an int (the UBSan build of this
   test, build/hygiene, aborted there before the rule computed it in
   double) */
static void test_bad_params(void) {
    gt_env e;
    int b;
    if (gt_env_init_named(&e, "ground-boxes", 64, 64) != 0) { gt_env_free(&e); return; }
    for (b = 0; b < 5; b++) {
        skgl_shadow_desc d;
        skgl_shadow *s = NULL;
        memset(&d, 0, sizeof d);
        d.technique = SKGL_LSPSM;
        if (b == 0) d.lspsm.h_max = 100;
        if (b == 1) d.lspsm.nw_max = 9;
        if (b == 2) { d.lspsm.h_max = 3; d.lspsm.nw_max = 3; }    /* 9 > 8 layers */
        if (b == 3) d.lspsm.zeta = 0.5f;
        if (b == 4) d.lspsm.h_max = d.lspsm.nw_max = 65536;
        SK_CHECK_MSG(skgl_shadow_create(e.sk, &d, &s) == SK_ERR_INVALID_ARG, "bad params %d accepted", b);
        if (b == 4)
            SK_CHECK_MSG(strstr(skgl_error_log(e.sk), "lspsm.h_max * lspsm.nw_max") != NULL, "log: %s",
                         skgl_error_log(e.sk));
        skgl_shadow_destroy(e.sk, s);
    }
    gt_env_free(&e);
}

SK_TEST_MAIN(test_against_pssm, test_failure_cases, test_bad_params)
