/* test_gl_optout.c - shadowkit_gl.h with its optional features compiled
   out (CONFIGURATION: SKGL_NO_SOFT, SKGL_NO_RMSM): the directional techniques that stay
   still shadow, and a removed feature's entry points refuse with a message
   naming the macro.

   Scene: test_gl_offscreen.c's (ground, a 10 m tower behind the camera
   casting 16 m into the view, a small box), 320 x 180, maps 1024^2.
   Measured (Mesa 22.3 llvmpipe) against the exact reference, default bias:
   covered error (tb_metric_hard) 0.1237% standard, 0.0495% pssm, the same
   to the fourth digit as this program built without the opt-outs (the
   code that remains is unchanged). Bounds about 1.4x: 0.18% / 0.07%.
   Can fail: at a quarter of the map resolution (SK_GL_TEST_RES_SCALE=0.25)
   0.6540% / 0.2638%, both fail; built without SKGL_NO_SOFT,
   skgl_soft_create succeeds on the zeroed desc (its defaults) and five
   checks of test_refusals fail; built without SKGL_NO_RMSM, an SKGL_RMSM
   shadow is created and four checks fail. */
#define SK_TEST_OWN_IMPLEMENTATION 1
#define SKGL_NO_SOFT
#define SKGL_NO_RMSM
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "sk_test.h"
#include "gl_test_util.h"

#define W 320
#define H 180

static void smoke(skgl_technique tech, double max_err_pct)
{
    gt_env e;
    skgl_shadow_desc d;
    skgl_shadow *s;
    tb_scene sc;
    sk_vec3 light = gt_v3(0.1f, -0.6f, -1);
    skgl_camera cam = gt_camera(gt_v3(0, 2, 8), gt_v3(0, 0, -2), 0.9f, 0.3f, 60, W, H);
    float *ref, *res;
    const char *tn = tech == SKGL_PSSM ? "pssm" : "standard";
    tb_hard_error he;
    tb_scene_init(&sc);
    tb_scene_add_ground(&sc, "ground", 0, 0, 20, 20, 0, 4, 4);
    tb_scene_add_box(&sc, "tower", gt_v3(-1, 0, 12), gt_v3(1, 10, 14));
    tb_scene_add_box(&sc, "box", gt_v3(3, 0, -3), gt_v3(4, 1, -2));
    if (gt_env_init(&e, &sc, W, H) != 0) { gt_env_free(&e); return; }
    memset(&d, 0, sizeof d);
    d.technique = tech;
    d.resolution = (int)(1024 * gt_res_scale());
    s = gt_shadow(&e, &d);
    ref = gt_alloc(&e); res = gt_alloc(&e);
    if (!s || !ref || !res || gt_gbuffer(&e, &cam) != 0 || gt_reference(&e, light, ref) != 0 ||
        gt_mask(&e, s, &cam, light, res) != 0) {
        SK_CHECK_MSG(0, "%s: frame failed", tn);
        goto done;
    }
    he = tb_metric_hard(ref, res, e.n);
    printf("%s (opt-outs): error %.4f%%\n", tn, he.pct);
    SK_CHECK_MSG(he.pct < max_err_pct, "%s: error %.4f%% >= %.3f%%", tn, he.pct, max_err_pct);
done:
    SK_CHECK(e.gl.GetError() == 0);
    free(ref); free(res);
    skgl_shadow_destroy(e.sk, s);
    gt_env_free(&e);
}

static void test_standard(void) { smoke(SKGL_STANDARD, 0.18); }
static void test_pssm(void) { smoke(SKGL_PSSM, 0.07); }

/* a compiled-out feature's create refuses, names the macro, makes nothing */
static void test_refusals(void)
{
    gt_env e;
    tb_scene sc;
    skgl_soft_desc sd;
    skgl_soft *soft = (skgl_soft *)&sd;   /* must be reset to NULL */
    skgl_shadow_desc d;
    skgl_shadow *s = (skgl_shadow *)&d;
    int objects;
    tb_scene_init(&sc);
    tb_scene_add_ground(&sc, "ground", 0, 0, 20, 20, 0, 4, 4);
    if (gt_env_init(&e, &sc, W, H) != 0) { gt_env_free(&e); return; }
    objects = skgl_gl_object_count(e.sk);
    memset(&sd, 0, sizeof sd);
    SK_CHECK(skgl_soft_create(e.sk, &sd, &soft) == SK_ERR_INVALID_ARG);
    SK_CHECK(soft == NULL);
    SK_CHECK_MSG(strcmp(skgl_error_log(e.sk), "skgl_soft_create: compiled out (SKGL_NO_SOFT)") == 0, "log: %s",
                 skgl_error_log(e.sk));
    SK_CHECK(skgl_soft_render(e.sk, NULL, NULL, NULL, NULL, 0, 0, 0) == SK_ERR_INVALID_ARG);
    SK_CHECK(strstr(skgl_error_log(e.sk), "SKGL_NO_SOFT") != NULL);
    SK_CHECK(skgl_soft_stats(NULL) == NULL && skgl_soft_tiles(NULL, NULL, 0) == 0);
    memset(&d, 0, sizeof d);
    d.technique = SKGL_RMSM;
    SK_CHECK(skgl_shadow_create(e.sk, &d, &s) == SK_ERR_INVALID_ARG);
    SK_CHECK(s == NULL);
    SK_CHECK_MSG(strstr(skgl_error_log(e.sk), "skgl_shadow_create: desc.technique") != NULL &&
                     strstr(skgl_error_log(e.sk), "compiled out (SKGL_NO_RMSM)") != NULL,
                 "log: %s", skgl_error_log(e.sk));
    SK_CHECK(skgl_gl_object_count(e.sk) == objects);
    SK_CHECK(e.gl.GetError() == 0);
    gt_env_free(&e);
}

SK_TEST_MAIN(test_standard, test_pssm, test_refusals)
