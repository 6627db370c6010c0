/* test_gl_optout.c - shadowkit_gl.h with its optional features compiled
   out (CONFIGURATION: SKGL_NO_SOFT, SKGL_NO_RMSM, SKGL_NO_CACHE,
   SKGL_NO_CASTERS, SKGL_NO_FERKO; test_gl_optout_cache.c builds it with
   the cache and the casters alone, mk/testbed.mk's test_gl_optout_no_<x>
   with each switch alone): the directional techniques that stay still
   shadow, and a removed feature's entry points refuse with a message
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
   checks of test_soft_refused fail; built without SKGL_NO_RMSM, an SKGL_RMSM
   shadow is created and four checks fail; built without SKGL_NO_CACHE,
   desc.cache 1 is accepted for a directional and a point light and eight
   checks of test_cache_refused fail; built without SKGL_NO_CASTERS, the
   caster is created, skgl_use_caster answers in the callback, the render
   succeeds and eight checks of test_casters_refused fail.
   Where the depth analysis stays (every build but SKGL_NO_FERKO's), FERKO
   (its estimate read back at once) 0.1704% and PSSM with .fit_to_depth
   0.0577% (0.0467% before a fitted range took log splits), as without the
   switches; bounds about 1.4x: 0.24% / 0.08%.
   At a quarter of the resolution 0.6403% / 0.2418%, both fail. */
#define SK_TEST_OWN_IMPLEMENTATION 1
#ifndef SK_OPTOUT_ONE   /* mk/testbed.mk's test_gl_optout_<switch>: that -DSKGL_NO_* alone */
#ifndef SK_OPTOUT_SOME   /* test_gl_optout_cache.c: the cache and the casters alone */
#define SKGL_NO_SOFT
#define SKGL_NO_RMSM
#define SKGL_NO_FERKO
#endif
#define SKGL_NO_CACHE
#define SKGL_NO_CASTERS
#endif
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "sk_test.h"
#include "gl_test_util.h"

#define W 320
#define H 180

/* one frame of tech (fit: .fit_to_depth) against the exact reference, the
   analysis first where the light has one */
static void smoke(skgl_technique tech, int fit, double max_err_pct)
{
    gt_offscreen o;
    skgl_shadow_desc d;
    skgl_shadow *s;
    const char *tn = tech == SKGL_PSSM ? (fit ? "pssm fit_to_depth" : "pssm") : tech == SKGL_RMSM ? "rmsm"
                     : tech == SKGL_FERKO ? "ferko" : "standard";
    int analyse = tech == SKGL_RMSM || tech == SKGL_FERKO || fit;
    tb_hard_error he;
    if (gt_offscreen_init(&o, W, H) != 0) return;
    memset(&d, 0, sizeof d);
    d.technique = tech;
    d.fit_to_depth = fit;
    d.sync_readback = fit || tech == SKGL_FERKO;   /* this frame's estimate or depth range */
    d.resolution = (int)(1024 * gt_res_scale());
    if (tech == SKGL_RMSM) {   /* a virtual 8192^2 in pages of 128, a pool of 16^2 (2080^2 texels) */
        d.resolution = (int)(8192 * gt_res_scale());
        d.rmsm_page_size = 128;
        d.rmsm_pool_pages = 16;
    }
    s = gt_shadow(&o.e, &d);
    if (!s || (analyse && skgl_shadow_analyze(o.e.sk, s, &o.cam, &o.scene, o.light, o.e.gbuf.depth_tex) != SK_OK) ||
        gt_mask(&o.e, s, &o.cam, o.light, o.res) != 0) {
        SK_CHECK_MSG(0, "%s: frame failed", tn);
        goto done;
    }
    he = tb_metric_hard(o.ref, o.res, o.e.n);
    printf("%s (opt-outs): error %.4f%%\n", tn, he.pct);
    SK_CHECK_MSG(he.pct < max_err_pct, "%s: error %.4f%% >= %.3f%%", tn, he.pct, max_err_pct);
done:
    SK_CHECK(o.e.gl.GetError() == 0);
    skgl_shadow_destroy(o.e.sk, s);
    gt_offscreen_free(&o);
}

static void test_standard(void) { smoke(SKGL_STANDARD, 0, 0.18); }
static void test_pssm(void) { smoke(SKGL_PSSM, 0, 0.07); }

#ifndef SKGL_NO_RMSM
/* RMSM stays with the cache compiled out: its pages drawn uncached */
#ifndef RMSM_MAX_ERR
#define RMSM_MAX_ERR 0.055
#endif
static void test_rmsm(void) { smoke(SKGL_RMSM, 0, RMSM_MAX_ERR); }
#define SK_T_RMSM test_rmsm,
#endif

#ifndef SKGL_NO_FERKO
/* the depth analysis stays: FERKO's map, and PSSM's splits fitted to the
   depth range */
#define FERKO_MAX_ERR 0.24
#define PSSM_FIT_MAX_ERR 0.08
static void test_ferko(void) { smoke(SKGL_FERKO, 0, FERKO_MAX_ERR); }
static void test_pssm_fit(void) { smoke(SKGL_PSSM, 1, PSSM_FIT_MAX_ERR); }
#define SK_T_FERKO test_ferko, test_pssm_fit,
#endif

/* a compiled-out feature's create refuses, names the macro, makes nothing */
#if defined(SKGL_NO_SOFT) || defined(SKGL_NO_RMSM) || defined(SKGL_NO_FERKO) || defined(SKGL_NO_CACHE)
/* the refusal tests' context: a ground plane, and the GL objects it holds
   before the refused create */
static int refusal_env(gt_env *e, int *objects)
{
    tb_scene sc;
    tb_scene_init(&sc);
    tb_scene_add_ground(&sc, "ground", 0, 0, 20, 20, 0, 4, 4);
    if (gt_env_init(e, &sc, W, H) != 0) { gt_env_free(e); return -1; }
    *objects = skgl_gl_object_count(e->sk);
    return 0;
}
#endif

#ifdef SKGL_NO_SOFT
static void test_soft_refused(void)
{
    gt_env e;
    skgl_soft_desc sd;
    skgl_soft *soft = (skgl_soft *)&sd;   /* must be reset to NULL */
    int objects;
    if (refusal_env(&e, &objects) != 0) return;
    memset(&sd, 0, sizeof sd);
    SK_CHECK(skgl_soft_create(e.sk, &sd, &soft) == SK_ERR_INVALID_ARG);
    SK_CHECK(soft == NULL);
    SK_CHECK_MSG(strcmp(skgl_error_log(e.sk), "skgl_soft_create: compiled out (SKGL_NO_SOFT)") == 0, "log: %s",
                 skgl_error_log(e.sk));
    SK_CHECK(skgl_soft_render(e.sk, NULL, NULL, NULL, NULL, 0, 0, 0) == SK_ERR_INVALID_ARG);
    SK_CHECK(strstr(skgl_error_log(e.sk), "SKGL_NO_SOFT") != NULL);
    SK_CHECK(skgl_soft_stats(NULL) == NULL && skgl_soft_tiles(NULL, NULL, 0) == 0);
    SK_CHECK(skgl_gl_object_count(e.sk) == objects);
    SK_CHECK(e.gl.GetError() == 0);
    gt_env_free(&e);
}
#define SK_T_SOFT test_soft_refused,
#endif

#ifdef SKGL_NO_RMSM
static void test_rmsm_refused(void)
{
    gt_env e;
    skgl_shadow_desc d;
    skgl_shadow *s = (skgl_shadow *)&d;   /* must be reset to NULL */
    int objects;
    if (refusal_env(&e, &objects) != 0) return;
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
#define SK_T_RMSM test_rmsm_refused,
#endif

#ifdef SKGL_NO_FERKO
/* SKGL_NO_FERKO: FERKO, AUTO and .fit_to_depth refused, each naming the
   field and the macro, nothing made; a PSSM light without them is made
   and analyses nothing (test_pssm draws its frame) */
static void refused_log(gt_env *e, skgl_shadow_desc *d, const char *want)
{
    skgl_shadow *s = (skgl_shadow *)d;   /* must be reset to NULL */
    SK_CHECK(skgl_shadow_create(e->sk, d, &s) == SK_ERR_INVALID_ARG);
    SK_CHECK(s == NULL);
    SK_CHECK_MSG(strcmp(skgl_error_log(e->sk), want) == 0, "log: %s\nwant: %s", skgl_error_log(e->sk), want);
}

static void test_ferko_refused(void)
{
    gt_env e;
    skgl_shadow_desc d;
    skgl_shadow *s = NULL;
    skgl_scene scene;
    skgl_camera cam = gt_camera(gt_v3(0, 2, 8), gt_v3(0, 0, -2), 0.9f, 0.3f, 60, W, H);
    int objects;
    if (refusal_env(&e, &objects) != 0) return;
    memset(&d, 0, sizeof d);
    d.technique = SKGL_FERKO;
    refused_log(&e, &d, "skgl_shadow_create: desc.technique = 5: FERKO's resolution estimation is compiled out "
                        "(SKGL_NO_FERKO)");
    d.technique = SKGL_AUTO;
    refused_log(&e, &d, "skgl_shadow_create: desc.technique = 7: AUTO splits the depth range of the depth analysis, "
                        "which is compiled out (SKGL_NO_FERKO)");
    d.technique = SKGL_PSSM;
    d.fit_to_depth = 1;
    refused_log(&e, &d, "skgl_shadow_create: desc.fit_to_depth = 1: the depth analysis is compiled out "
                        "(SKGL_NO_FERKO)");
    SK_CHECK(skgl_gl_object_count(e.sk) == objects);
    d.fit_to_depth = 0;
    SK_CHECK(skgl_shadow_create(e.sk, &d, &s) == SK_OK && s != NULL);
    scene = gt_scene(&e);
    SK_CHECK(gt_gbuffer(&e, &cam) == 0);
    SK_CHECK(skgl_shadow_analyze(e.sk, s, &cam, &scene, gt_v3(0.1f, -0.6f, -1), e.gbuf.depth_tex) ==
             SK_ERR_INVALID_ARG);
    SK_CHECK_MSG(strstr(skgl_error_log(e.sk), "skgl_shadow_analyze: s->desc.technique = 1: only") != NULL, "log: %s",
                 skgl_error_log(e.sk));
    skgl_shadow_destroy(e.sk, s);
    SK_CHECK(skgl_gl_object_count(e.sk) == objects);
    SK_CHECK(e.gl.GetError() == 0);
    gt_env_free(&e);
}
#define SK_T_FERKO test_ferko_refused,
#endif

#ifdef SKGL_NO_CACHE
/* SKGL_NO_CACHE: desc.cache refused naming the field and the macro; the
   invalidate calls check their arguments and answer SK_OK (no cache) */
static void test_cache_refused(void)
{
    gt_env e;
    skgl_shadow_desc d;
    skgl_point_desc pd;
    skgl_shadow *s = (skgl_shadow *)&d;
    skgl_point *p = (skgl_point *)&pd;
    sk_aabb bad = gt_box(1, 0, 0, 0, 1, 1);   /* min.x > max.x */
    sk_aabb box = gt_box(0, 0, 0, 1, 1, 1);
    int objects;
    if (refusal_env(&e, &objects) != 0) return;
    memset(&d, 0, sizeof d);
    d.technique = SKGL_PSSM;
    d.cache = 1;
    SK_CHECK(skgl_shadow_create(e.sk, &d, &s) == SK_ERR_INVALID_ARG);
    SK_CHECK(s == NULL);
    SK_CHECK_MSG(strcmp(skgl_error_log(e.sk), "skgl_shadow_create: desc.cache = 1: cached maps are compiled out "
                                              "(SKGL_NO_CACHE)") == 0, "log: %s", skgl_error_log(e.sk));
    memset(&pd, 0, sizeof pd);
    pd.technique = SKGL_POINT_CUBE;
    pd.resolution = 256;
    pd.range = 16;
    pd.cache = 1;
    SK_CHECK(skgl_point_create(e.sk, &pd, &p) == SK_ERR_INVALID_ARG);
    SK_CHECK(p == NULL);
    SK_CHECK_MSG(strcmp(skgl_error_log(e.sk), "skgl_point_create: desc.cache = 1: cached maps are compiled out "
                                              "(SKGL_NO_CACHE)") == 0, "log: %s", skgl_error_log(e.sk));
    SK_CHECK(skgl_gl_object_count(e.sk) == objects);
    d.cache = 0;
    pd.cache = 0;
    SK_CHECK(skgl_shadow_create(e.sk, &d, &s) == SK_OK && s != NULL);
    SK_CHECK(skgl_point_create(e.sk, &pd, &p) == SK_OK && p != NULL);
    SK_CHECK(skgl_shadow_invalidate(e.sk, s, NULL) == SK_OK);
    SK_CHECK(skgl_shadow_invalidate(e.sk, s, &box) == SK_OK);
    SK_CHECK(skgl_point_invalidate(e.sk, p, &box) == SK_OK);
    SK_CHECK(skgl_shadow_invalidate(e.sk, s, &bad) == SK_ERR_INVALID_ARG);
    SK_CHECK_MSG(strstr(skgl_error_log(e.sk), "skgl_shadow_invalidate: box: finite") != NULL, "log: %s",
                 skgl_error_log(e.sk));
    SK_CHECK(skgl_point_invalidate(e.sk, NULL, NULL) == SK_ERR_INVALID_ARG);
    skgl_shadow_destroy(e.sk, s);
    skgl_point_destroy(e.sk, p);
    SK_CHECK(skgl_gl_object_count(e.sk) == objects);
    SK_CHECK(e.gl.GetError() == 0);
    gt_env_free(&e);
}
#define SK_T_CACHE test_cache_refused,
#endif

#ifdef SKGL_NO_CASTERS
/* SKGL_NO_CASTERS: skgl_caster_create refuses, and skgl_use_caster in a
   draw callback fails the render, both naming the macro */
typedef struct caster_world {
    gt_env *e;
    int calls, got;          /* callbacks; skgl_use_caster returned non-NULL */
} caster_world;

static void draw_with_caster(void *user, const skgl_draw_info *info)
{
    caster_world *w = (caster_world *)user;
    (void)info;
    w->calls++;
    if (skgl_use_caster(w->e->sk, NULL)) w->got++;
    gt_draw(w->e, info);
}

static void test_casters_refused(void)
{
    gt_env e;
    tb_scene sc;
    skgl_caster_desc cd;
    skgl_caster *c = (skgl_caster *)&cd;
    skgl_shadow_desc d;
    skgl_shadow *s;
    skgl_scene scene;
    caster_world w;
    sk_result r;
    int objects;
    skgl_camera cam = gt_camera(gt_v3(0, 2, 8), gt_v3(0, 0, -2), 0.9f, 0.3f, 60, W, H);
    tb_scene_init(&sc);
    tb_scene_add_ground(&sc, "ground", 0, 0, 20, 20, 0, 4, 4);
    tb_scene_add_box(&sc, "box", gt_v3(3, 0, -3), gt_v3(4, 1, -2));
    if (gt_env_init(&e, &sc, W, H) != 0) { gt_env_free(&e); return; }
    objects = skgl_gl_object_count(e.sk);
    memset(&cd, 0, sizeof cd);
    cd.vertex = "layout(location = 0) in vec3 a_pos;\n"
                "vec4 skgl_caster_position() { return vec4(a_pos, 1.0); }\n";
    SK_CHECK(skgl_caster_create(e.sk, &cd, &c) == SK_ERR_INVALID_ARG);
    SK_CHECK(c == NULL);
    SK_CHECK_MSG(strcmp(skgl_error_log(e.sk), "skgl_caster_create: compiled out (SKGL_NO_CASTERS)") == 0, "log: %s",
                 skgl_error_log(e.sk));
    SK_CHECK(skgl_gl_object_count(e.sk) == objects);
    skgl_caster_destroy(e.sk, NULL);
    SK_CHECK(skgl_use_caster(e.sk, NULL) == NULL);   /* outside a callback */
    memset(&d, 0, sizeof d);
    d.technique = SKGL_STANDARD;
    d.resolution = 512;
    s = gt_shadow(&e, &d);
    memset(&w, 0, sizeof w);
    w.e = &e;
    scene = gt_scene(&e);
    scene.draw = draw_with_caster;
    scene.user = &w;
    r = s ? skgl_shadow_render(e.sk, s, &cam, &scene, gt_v3(0.1f, -0.6f, -1)) : SK_ERR_INVALID_ARG;
    SK_CHECK_MSG(r == SK_ERR_INVALID_ARG, "render: %s", sk_result_string(r));
    SK_CHECK_MSG(w.calls > 0 && w.got == 0, "callbacks %d, locations %d", w.calls, w.got);
    SK_CHECK_MSG(strstr(skgl_error_log(e.sk), "skgl_use_caster: compiled out (SKGL_NO_CASTERS)") != NULL, "log: %s",
                 skgl_error_log(e.sk));
    skgl_shadow_destroy(e.sk, s);
    SK_CHECK(skgl_gl_object_count(e.sk) == objects);
    SK_CHECK(e.gl.GetError() == 0);
    gt_env_free(&e);
}

#define SK_T_CASTERS test_casters_refused,
#endif

/* each SK_T_* is its part's tests followed by a comma, or nothing */
#ifndef SK_T_SOFT
#define SK_T_SOFT
#endif
#ifndef SK_T_CACHE
#define SK_T_CACHE
#endif
#ifndef SK_T_CASTERS
#define SK_T_CASTERS
#endif
SK_TEST_MAIN(SK_T_SOFT SK_T_RMSM SK_T_FERKO SK_T_CACHE SK_T_CASTERS test_standard, test_pssm)
