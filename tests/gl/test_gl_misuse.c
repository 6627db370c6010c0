/* test_gl_misuse.c - bad input and misuse of every public entry point of
   shadowkit_gl.h (and the matrix functions of shadowkit.h): after each call
   the result, the message (skgl_error_log, or desc.logger where no context
   is left: non-empty, naming the field or argument) and glGetError() ==
   GL_NO_ERROR are checked. Built plain (build/gl) and under ASan + UBSan
   (build/hygiene, mk/hygiene.mk), both part of `make test`.

   What it covers, by the items of the issue it closes:
    8  a GL error the application left pending (glGetString(GL_EXTENSIONS)
       on a core context, as older GLEW does) is cleared and named as a
       warning by the create calls and the debug checks, never failing
       them; a GL error a pass raises names the error and the pass;
    9  skgl_create's failures reach desc.logger: each desc field, every
       entry point missing in turn (by name), a version too low, a shader
       that does not compile (the driver's own message);
   10  zero, inverted, non-finite and huge scene bounds refused by every
       render and analysis (directional, point, area);
   11  a bind to a program without the snippet, or under another prefix,
       refused with desc.debug;
   12  a render from inside another light's draw callback refused, and the
       outer light's map the same as without the attempt;
   13  a callback that leaves its own program current (desc.debug 0): no
       uniform of shadowkit's lands in it, no GL error;
   15  every error has a message: create calls with NULL desc or out, odd
       projections, +-3e38 bounds, remember_texture clearing the log;
   16  names that are not textures, textures without storage, sizes above
       GL_MAX_TEXTURE_SIZE: refused, no GL error left;
   17  negative resolution and cascades, stable at resolution 1, vsdct
       grey levels 1 and INT_MAX, cull_faces 7, point bounds, masks and
       binds of lights never rendered: refused;
   18  sk_mat4_mul and sk_mat4_transform_point finite for finite input
       near +-3e38 and for w = 1e-45.
   Run time: 1.8 s on llvmpipe (5 s under the sanitizers). */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "sk_test.h"
#include "gl_test_util.h"

#define W 320
#define H 180
#define E_NO_ERROR 0
#define E_EXTENSIONS 0x1F03
#define E_TEXTURE_2D 0x0DE1
#define E_COMPILE_STATUS 0x8B81
#define E_MAJOR_VERSION 0x821B
#define E_MINOR_VERSION 0x821C
#define BOGUS_NAME 987654u   /* never made by glGen* */

static gt_env env;
static tb_gl_getproc_fn real_getproc;

/* ---- the logger: every message, the last kept ---------------------------- */
static char last_msg[1200];
static int last_level = -1, messages;
static void logger(void *user, skgl_log_level level, const char *message) {
    (void)user;
    snprintf(last_msg, sizeof last_msg, "%s", message);
    last_level = (int)level;
    messages++;
}
static void logger_reset(void) { last_msg[0] = 0; last_level = -1; messages = 0; }

static unsigned gl_error(void) { return env.gl.GetError(); }

/* r is want, the log holds needle (and is not empty), no GL error left */
static void expect(skgl_context *sk, sk_result r, sk_result want, const char *what, const char *needle) {
    const char *log = skgl_error_log(sk);
    unsigned e = gl_error();
    SK_CHECK_MSG(r == want, "%s: %s, expected %s (log '%s')", what, sk_result_string(r), sk_result_string(want), log);
    if (want != SK_OK) SK_CHECK_MSG(log[0] != 0, "%s: failed with an empty log", what);
    if (needle) SK_CHECK_MSG(strstr(log, needle) != NULL, "%s: log '%s' lacks '%s'", what, log, needle);
    SK_CHECK_MSG(e == E_NO_ERROR, "%s: GL error 0x%x left behind", what, e);
}

static skgl_desc desc_with(skgl_getproc_fn gp, int debug) {
    skgl_desc d;
    memset(&d, 0, sizeof d);
    d.getproc = gp;
    d.debug = debug;
    d.logger.func = logger;
    return d;
}

static skgl_camera camera(void) { return gt_camera(gt_v3(-9, 7, 12), gt_v3(0, 0, 0), 0.9f, 0.1f, 100.0f, W, H); }
static sk_vec3 sun(void) { return gt_v3(-0.5f, -1.0f, -0.35f); }
static skgl_area_light area(void) {
    skgl_area_light l;
    memset(&l, 0, sizeof l);
    l.position = gt_v3(2, 9, 3);
    l.direction = gt_v3(-0.2f, -1, -0.3f);
    l.half_width = l.half_height = 0.5f;
    return l;
}

/* ---- getprocs that lie ----------------------------------------------------- */
static char missing[64];                       /* the entry point getproc_missing withholds */
static char asked[160][48];                    /* every name getproc_record was asked */
static int nasked;
static void *getproc_missing(const char *name) { return strcmp(name, missing) == 0 ? NULL : real_getproc(name); }
static void *getproc_record(const char *name) {
    int i;
    for (i = 0; i < nasked; i++) if (!strcmp(asked[i], name)) break;
    if (i == nasked && nasked < 160) snprintf(asked[nasked++], sizeof asked[0], "%s", name);
    return real_getproc(name);
}

typedef void (*get_integerv_fn)(unsigned, int *);
static get_integerv_fn real_get_integerv;
static void old_get_integerv(unsigned pname, int *v) {   /* an OpenGL 3.2 context */
    real_get_integerv(pname, v);
    if (pname == E_MAJOR_VERSION) *v = 3;
    if (pname == E_MINOR_VERSION) *v = 2;
}
static void *getproc_old(const char *name) {
    void *p = real_getproc(name);
    if (strcmp(name, "glGetIntegerv") == 0) {
        memcpy(&real_get_integerv, &p, sizeof p);
        p = NULL;
        { get_integerv_fn f = old_get_integerv; memcpy(&p, &f, sizeof p); }
    }
    return p;
}

typedef void (*shader_source_fn)(unsigned, int, const char *const *, const int *);
static shader_source_fn real_shader_source;
static void broken_shader_source(unsigned sh, int n, const char *const *src, const int *len) {
    const char *all[16];
    int i;
    (void)len;
    for (i = 0; i < n && i < 15; i++) all[i] = src[i];
    all[i] = "\n#error skgl misuse test: this driver refuses\n";
    real_shader_source(sh, i + 1, all, NULL);
}
static void *getproc_broken_compiler(const char *name) {
    void *p = real_getproc(name);
    if (strcmp(name, "glShaderSource") == 0) {
        shader_source_fn f = broken_shader_source;
        memcpy(&real_shader_source, &p, sizeof p);
        memcpy(&p, &f, sizeof p);
    }
    return p;
}

/* ---- 8: GL errors the application left pending ------------------------ */
static void leave_gl_error(void) {
    /* GL_EXTENSIONS through glGetString is not in a core profile: GL_INVALID_ENUM */
    (void)env.gl.GetString(E_EXTENSIONS);
}

static void draw_with_error(void *user, const skgl_draw_info *info) {
    (void)user;
    (void)info;
    env.gl.Enable(0xFFFF);                           /* GL_INVALID_ENUM inside the pass */
    tb_gl_mesh_draw(&env.gl, &env.mesh, 0, 0);
}

static void test_pending_errors(void) {
    skgl_desc d = desc_with((skgl_getproc_fn)real_getproc, 1);
    skgl_context *sk = NULL;
    skgl_shadow *s = NULL;
    skgl_shadow_desc sd;
    skgl_camera cam = camera();
    skgl_scene sc = gt_scene(&env), bad = sc;
    sk_result r;
    logger_reset();
    leave_gl_error();
    r = skgl_create(&d, &sk);
    SK_CHECK_MSG(r == SK_OK, "skgl_create with an application's GL error pending: %s (logger '%s')",
                 sk_result_string(r), last_msg);
    SK_CHECK_MSG(last_level == SKGL_LOG_WARNING &&
                     strstr(last_msg, "GL error pending before skgl_create: GL_INVALID_ENUM") != NULL,
                 "skgl_create's warning: level %d '%s'", last_level, last_msg);
    SK_CHECK_MSG(gl_error() == E_NO_ERROR, "the pending error is still there after skgl_create");
    if (r != SK_OK) return;
    memset(&sd, 0, sizeof sd);
    sd.resolution = 256;
    leave_gl_error();
    expect(sk, skgl_shadow_create(sk, &sd, &s), SK_OK, "shadow_create with an error pending",
           "GL error pending before skgl_shadow_create: GL_INVALID_ENUM");
    if (!s) { skgl_destroy(sk); return; }
    expect(sk, skgl_shadow_render(sk, s, &cam, &sc, sun()), SK_OK, "render", NULL);
    SK_CHECK_MSG(skgl_error_log(sk)[0] == 0, "log after a clean render: '%s'", skgl_error_log(sk));
    leave_gl_error();
    expect(sk, skgl_shadow_render(sk, s, &cam, &sc, sun()), SK_OK, "debug render with an error pending",
           "GL error pending before skgl_shadow_render: GL_INVALID_ENUM");
    leave_gl_error();
    expect(sk, skgl_shadow_mask(sk, s, &cam, env.gbuf.depth_tex, env.gbuf.color_tex, env.mask.color_tex), SK_OK,
           "debug mask with an error pending", "GL error pending before skgl_shadow_mask: GL_INVALID_ENUM");
    /* an error raised inside a pass: named, with the pass */
    bad.draw = draw_with_error;
    expect(sk, skgl_shadow_render(sk, s, &cam, &bad, sun()), SK_ERR_GL, "an error in the callback",
           "skgl_shadow_render: GL_INVALID_ENUM raised in the draw callback (scene.draw) of the caster pass of "
           "directional layer 0");
    skgl_shadow_destroy(sk, s);
    skgl_destroy(sk);
}

/* ---- 9: skgl_create says why ------------------------------------------- */
static void expect_create(const skgl_desc *d, skgl_context **out, sk_result want, const char *what,
                          const char *needle) {
    skgl_context *sk = (skgl_context *)&env;   /* must come back NULL */
    sk_result r;
    logger_reset();
    r = skgl_create(d, out ? out : &sk);
    SK_CHECK_MSG(r == want, "%s: %s (logger '%s')", what, sk_result_string(r), last_msg);
    SK_CHECK_MSG(last_level == SKGL_LOG_ERROR && strstr(last_msg, needle) != NULL,
                 "%s: logger level %d '%s' lacks '%s'", what, last_level, last_msg, needle);
    SK_CHECK_MSG(gl_error() == E_NO_ERROR, "%s: GL error left", what);
    if (!out) SK_CHECK_MSG(sk == NULL, "%s: *out not NULL", what);
}

static void test_create_messages(void) {
    skgl_desc d;
    skgl_context *sk = NULL;
    int i, loaded = 0;
    d = desc_with((skgl_getproc_fn)real_getproc, 1); d.timing = 7;
    expect_create(&d, NULL, SK_ERR_INVALID_ARG, "timing 7", "desc.timing = 7");
    d = desc_with((skgl_getproc_fn)real_getproc, 1); d.clip_zero_to_one = -1;
    expect_create(&d, NULL, SK_ERR_INVALID_ARG, "clip_zero_to_one -1", "desc.clip_zero_to_one = -1");
    d = desc_with((skgl_getproc_fn)real_getproc, 1); d.api = (skgl_api)9;
    expect_create(&d, NULL, SK_ERR_INVALID_ARG, "api 9", "desc.api = 9");
    d = desc_with((skgl_getproc_fn)real_getproc, 1); d.debug = 2;
    expect_create(&d, NULL, SK_ERR_INVALID_ARG, "debug 2", "desc.debug = 2");
    d = desc_with((skgl_getproc_fn)real_getproc, 1); d.disable_caps = 0x80000000u;
    expect_create(&d, NULL, SK_ERR_INVALID_ARG, "disable_caps", "desc.disable_caps = 0x80000000");
    d = desc_with(NULL, 1);
    expect_create(&d, NULL, SK_ERR_INVALID_ARG, "no getproc", "desc.getproc is NULL");
    d = desc_with((skgl_getproc_fn)real_getproc, 1);
    logger_reset();
    SK_CHECK(skgl_create(&d, NULL) == SK_ERR_INVALID_ARG && strstr(last_msg, "out is NULL") != NULL);
    SK_CHECK(skgl_create(NULL, &sk) == SK_ERR_INVALID_ARG && sk == NULL);
    /* a version too low */
    d = desc_with((skgl_getproc_fn)getproc_old, 1);
    expect_create(&d, NULL, SK_ERR_GL, "GL 3.2", "OpenGL 3.2");
    SK_CHECK_MSG(strstr(last_msg, "OpenGL 3.3 core or later") != NULL, "version message '%s'", last_msg);
    /* a shader that does not compile: the driver's message */
    d = desc_with((skgl_getproc_fn)getproc_broken_compiler, 1);
    expect_create(&d, NULL, SK_ERR_GL, "broken compiler", "skgl misuse test: this driver refuses");
    SK_CHECK_MSG(strstr(last_msg, "shadowkit's own shaders did not build") != NULL, "compile message '%s'", last_msg);
    /* every entry point shadowkit asks for, missing in turn */
    nasked = 0;
    d = desc_with((skgl_getproc_fn)getproc_record, 1);
    SK_CHECK(skgl_create(&d, &sk) == SK_OK);
    skgl_destroy(sk);
    sk = NULL;
    printf("  skgl_create asked for %d entry points\n", nasked);
    SK_CHECK_MSG(nasked >= 80, "only %d entry points asked for", nasked);
    for (i = 0; i < nasked; i++) {
        SK_CHECK_MSG(strcmp(asked[i], "glClear") && strcmp(asked[i], "glCullFace") && strcmp(asked[i], "glClearColor"),
                     "%s is loaded but never called", asked[i]);
        snprintf(missing, sizeof missing, "%s", asked[i]);
        d = desc_with((skgl_getproc_fn)getproc_missing, 1);
        expect_create(&d, NULL, SK_ERR_GL, asked[i], asked[i]);
        loaded += strstr(last_msg, "returned NULL") != NULL;
    }
    SK_CHECK_MSG(loaded == nasked, "%d of %d missing entry points named as returned NULL", loaded, nasked);
    /* clip control asked only with clip_zero_to_one */
    snprintf(missing, sizeof missing, "glClipControl");
    d = desc_with((skgl_getproc_fn)getproc_missing, 1);
    d.clip_zero_to_one = 1;
    expect_create(&d, NULL, SK_ERR_GL, "no glClipControl", "glClipControl");
}

/* lights with default descs but the resolution: STANDARD (*s) at res,
   FERKO (*f, when f) at res, a point light (*p) at point_res, a soft
   shadow (*a, when a) at res */
static void lights_create(skgl_context *sk, int res, int point_res, skgl_shadow **s, skgl_shadow **f, skgl_point **p,
                          skgl_soft **a) {
    skgl_shadow_desc sd;
    skgl_point_desc pd;
    skgl_soft_desc fd;
    memset(&sd, 0, sizeof sd);
    sd.resolution = res;
    SK_CHECK(skgl_shadow_create(sk, &sd, s) == SK_OK);
    sd.technique = SKGL_FERKO;
    if (f) SK_CHECK(skgl_shadow_create(sk, &sd, f) == SK_OK);
    memset(&pd, 0, sizeof pd);
    pd.resolution = point_res;
    SK_CHECK(skgl_point_create(sk, &pd, p) == SK_OK);
    memset(&fd, 0, sizeof fd);
    fd.resolution = res;
    if (a) SK_CHECK(skgl_soft_create(sk, &fd, a) == SK_OK);
}

static void lights_destroy(skgl_context *sk, skgl_shadow *s, skgl_shadow *f, skgl_point *p, skgl_soft *a) {
    skgl_shadow_destroy(sk, s);
    skgl_shadow_destroy(sk, f);
    skgl_point_destroy(sk, p);
    skgl_soft_destroy(sk, a);
}

/* ---- 10, 15, 17: bounds, cameras and descs ------------------------------ */
static void test_bounds(skgl_context *sk) {
    skgl_shadow *s = NULL, *f = NULL;
    skgl_point *p = NULL;
    skgl_soft *a = NULL;
    skgl_camera cam = camera();
    skgl_scene sc = gt_scene(&env), b = sc;
    skgl_area_light l = area();
    static const float huge = 3e38f;
    sk_aabb boxes[6];
    static const char *const names[6] = {"zero", "point", "inverted", "NaN", "+-3e38", "+inf"};
    int i;
    memset(boxes, 0, sizeof boxes);
    boxes[1] = gt_box(1, 2, 3, 1, 2, 3);
    boxes[2] = gt_box(5, 0, -5, -5, 3, 5);
    boxes[3] = gt_box(-5, 0, -5, 5, NAN, 5);
    boxes[4] = gt_box(-huge, -huge, -huge, huge, huge, huge);
    boxes[5] = gt_box(-5, 0, -5, INFINITY, 3, 5);
    lights_create(sk, 256, 64, &s, &f, &p, &a);
    if (!s || !f || !p || !a) goto done;
    for (i = 0; i < 6; i++) {
        char what[96];
        b.bounds = boxes[i];
        snprintf(what, sizeof what, "shadow render, %s bounds", names[i]);
        expect(sk, skgl_shadow_render(sk, s, &cam, &b, sun()), SK_ERR_INVALID_ARG, what, "scene->bounds");
        snprintf(what, sizeof what, "analyze, %s bounds", names[i]);
        expect(sk, skgl_shadow_analyze(sk, f, &cam, &b, sun(), env.gbuf.depth_tex), SK_ERR_INVALID_ARG, what,
               "scene->bounds");
        snprintf(what, sizeof what, "point render, %s bounds", names[i]);
        expect(sk, skgl_point_render(sk, p, &cam, &b, gt_v3(1, 3, 1)), SK_ERR_INVALID_ARG, what, "scene->bounds");
        snprintf(what, sizeof what, "soft render, %s bounds", names[i]);
        expect(sk, skgl_soft_render(sk, a, &cam, &b, &l, env.gbuf.depth_tex, env.gbuf.color_tex, env.mask.color_tex),
               SK_ERR_INVALID_ARG, what, "scene->bounds");
    }
done:
    lights_destroy(sk, s, f, p, a);
}

/* odd projections: a result, with a message when it is an error */
static void test_cameras(skgl_context *sk) {
    skgl_shadow_desc sd;
    skgl_shadow *s = NULL;
    skgl_scene sc = gt_scene(&env);
    skgl_camera cams[5];
    static const char *const names[5] = {"identity proj", "near > far", "huge ortho", "NaN view", "singular"};
    int i, t;
    for (i = 0; i < 5; i++) cams[i] = camera();
    cams[0].proj = sk_mat4_identity();
    cams[1].proj.m[10] = -cams[1].proj.m[10];
    cams[2].proj = sk_mat4_identity();
    cams[2].proj.m[0] = cams[2].proj.m[5] = cams[2].proj.m[10] = 1e-30f;
    cams[3].view.m[0] = NAN;
    memset(&cams[4].proj, 0, sizeof cams[4].proj);
    for (t = 0; t <= SKGL_RMSM; t++) {
        memset(&sd, 0, sizeof sd);
        sd.technique = (skgl_technique)t;
        sd.resolution = t == SKGL_RMSM ? 2048 : 128;
        if (t == SKGL_LSPSM) sd.lspsm.h_max = 2;
        if (skgl_shadow_create(sk, &sd, &s) != SK_OK) { SK_CHECK_MSG(0, "technique %d: create", t); continue; }
        for (i = 0; i < 5; i++) {
            sk_result r = skgl_shadow_render(sk, s, &cams[i], &sc, sun());
            const char *log = skgl_error_log(sk);
            SK_CHECK_MSG(r == SK_OK || log[0] != 0, "technique %d, %s: %s with an empty log", t, names[i],
                         sk_result_string(r));
            SK_CHECK_MSG(r != SK_OK || i < 3, "technique %d, %s: accepted", t, names[i]);
            SK_CHECK_MSG(gl_error() == E_NO_ERROR, "technique %d, %s: GL error left", t, names[i]);
        }
        skgl_shadow_destroy(sk, s);
        s = NULL;
    }
}

typedef struct desc_case {
    const char *needle;
    int point;                     /* 0 shadow, 1 point */
    int field, value;
} desc_case;
enum { F_RES, F_CASCADES, F_STABLE_RES1, F_STABLE, F_GREY, F_CULL, F_CASTERS, F_SCISSOR, F_SELECT };

static void test_descs(skgl_context *sk) {
    static const desc_case cases[] = {
        {"desc.resolution = -256:", 0, F_RES, -256},
        {"desc.cascades = -2:", 0, F_CASCADES, -2},
        {"desc.resolution = 1: 2 or more with desc.stable", 0, F_STABLE_RES1, 1},
        {"desc.stable = 3:", 0, F_STABLE, 3},
        {"desc.resolution = -1:", 1, F_RES, -1},
        {"desc.vsdct_grey_levels = 1:", 1, F_GREY, 1},
        {"desc.vsdct_grey_levels = 2.14748e+09:", 1, F_GREY, INT_MAX},
        {"desc.cull_faces = 7:", 1, F_CULL, 7},
        {"desc.cull_casters = 2:", 1, F_CASTERS, 2},
        {"desc.scissor = -1:", 1, F_SCISSOR, -1},
        {"desc.select_resolution = 5:", 1, F_SELECT, 5},
    };
    size_t i;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const desc_case *c = &cases[i];
        char what[64];
        snprintf(what, sizeof what, "desc case %d (%s)", (int)i, c->needle);
        if (!c->point) {
            skgl_shadow_desc d;
            skgl_shadow *s = NULL;
            memset(&d, 0, sizeof d);
            d.technique = SKGL_PSSM;
            if (c->field == F_RES) d.resolution = c->value;
            if (c->field == F_CASCADES) d.cascades = c->value;
            if (c->field == F_STABLE_RES1) { d.stable = 1; d.resolution = 1; }
            if (c->field == F_STABLE) d.stable = c->value;
            expect(sk, skgl_shadow_create(sk, &d, &s), SK_ERR_INVALID_ARG, what, c->needle);
            SK_CHECK(s == NULL);
            skgl_shadow_destroy(sk, s);
        } else {
            skgl_point_desc d;
            skgl_point *p = NULL;
            memset(&d, 0, sizeof d);
            d.technique = SKGL_POINT_VSDCT;
            d.resolution = 64;
            if (c->field == F_RES) d.resolution = c->value;
            if (c->field == F_GREY) d.vsdct_grey_levels = c->value;
            if (c->field == F_CULL) d.cull_faces = c->value;
            if (c->field == F_CASTERS) d.cull_casters = c->value;
            if (c->field == F_SCISSOR) d.scissor = c->value;
            if (c->field == F_SELECT) d.select_resolution = c->value;
            expect(sk, skgl_point_create(sk, &d, &p), SK_ERR_INVALID_ARG, what, c->needle);
            SK_CHECK(p == NULL);
            skgl_point_destroy(sk, p);
        }
    }
    /* a stable map at resolution 2 still renders */
    {
        skgl_shadow_desc d;
        skgl_shadow *s = NULL;
        skgl_camera cam = camera();
        skgl_scene sc = gt_scene(&env);
        memset(&d, 0, sizeof d);
        d.stable = 1;
        d.resolution = 2;
        expect(sk, skgl_shadow_create(sk, &d, &s), SK_OK, "stable at 2", NULL);
        if (s) expect(sk, skgl_shadow_render(sk, s, &cam, &sc, sun()), SK_OK, "stable at 2: render", NULL);
        skgl_shadow_destroy(sk, s);
    }
}

/* ---- 15: create calls with NULL desc or out, and the log on entry ------- */
static void fail_first(skgl_context *sk) {
    skgl_camera cam = camera();
    skgl_scene sc = gt_scene(&env);
    SK_CHECK(skgl_shadow_render(sk, NULL, &cam, &sc, sun()) == SK_ERR_INVALID_ARG);
    SK_CHECK(strstr(skgl_error_log(sk), "s is NULL") != NULL);
}

static void test_null_creates(skgl_context *sk) {
    skgl_shadow_desc sd;
    skgl_point_desc pd;
    skgl_soft_desc fd;
    skgl_caster_desc cd;
    skgl_shadow *s = NULL;
    skgl_point *p = NULL;
    skgl_soft *a = NULL;
    skgl_caster *c = NULL;
    memset(&sd, 0, sizeof sd);
    memset(&pd, 0, sizeof pd);
    memset(&fd, 0, sizeof fd);
    memset(&cd, 0, sizeof cd);
    fail_first(sk);
    expect(sk, skgl_shadow_create(sk, NULL, &s), SK_ERR_INVALID_ARG, "shadow_create NULL desc", "desc is NULL");
    fail_first(sk);
    expect(sk, skgl_shadow_create(sk, &sd, NULL), SK_ERR_INVALID_ARG, "shadow_create NULL out", "out is NULL");
    fail_first(sk);
    expect(sk, skgl_point_create(sk, NULL, &p), SK_ERR_INVALID_ARG, "point_create NULL desc", "desc is NULL");
    fail_first(sk);
    expect(sk, skgl_point_create(sk, &pd, NULL), SK_ERR_INVALID_ARG, "point_create NULL out", "out is NULL");
    fail_first(sk);
    expect(sk, skgl_soft_create(sk, NULL, &a), SK_ERR_INVALID_ARG, "soft_create NULL desc", "desc is NULL");
    fail_first(sk);
    expect(sk, skgl_soft_create(sk, &fd, NULL), SK_ERR_INVALID_ARG, "soft_create NULL out", "out is NULL");
    fail_first(sk);
    expect(sk, skgl_point_atlas_create(sk, 256, 256, NULL), SK_ERR_INVALID_ARG, "atlas_create NULL out",
           "out is NULL");
    fail_first(sk);
    expect(sk, skgl_caster_create(sk, NULL, &c), SK_ERR_INVALID_ARG, "caster_create NULL desc", "desc is NULL");
    /* remember_texture clears the log */
    fail_first(sk);
    expect(sk, skgl_remember_texture(sk, env.mask.color_tex, W, H), SK_OK, "remember_texture", NULL);
    SK_CHECK_MSG(skgl_error_log(sk)[0] == 0, "log after a good remember_texture: '%s'", skgl_error_log(sk));
    fail_first(sk);
    skgl_forget_texture(sk, env.mask.color_tex);
    SK_CHECK_MSG(skgl_error_log(sk)[0] == 0, "log after skgl_forget_texture: '%s'", skgl_error_log(sk));
    fail_first(sk);
    skgl_forget_program(sk, 0);
    SK_CHECK_MSG(skgl_error_log(sk)[0] == 0, "log after skgl_forget_program: '%s'", skgl_error_log(sk));
}

/* calls given one bad texture among (depth, normal, target) in turn:
   bogus (not a texture) or bare (no storage), each refused naming it */
enum { BAD_MASK, BAD_POINT_MASK, BAD_SOFT };
static const struct bad_textures {
    int call;
    const char *name;
    unsigned bogus, bare;   /* the slots tried so, a bit each */
    unsigned named;         /* the bogus slots whose message names "<slot>_tex = <name>" */
} bad_textures[3] = {{BAD_MASK, "mask", 7, 3, 3}, {BAD_POINT_MASK, "point mask", 7, 2, 0}, {BAD_SOFT, "soft", 7, 0, 0}};

/* bad_textures[k] through s, p or a; bare: a texture without storage */
static void expect_bad_textures(skgl_context *sk, int k, skgl_shadow *s, skgl_point *p, skgl_soft *a, unsigned bare) {
    static const char *const slot_name[3] = {"depth", "normal", "target"};
    const struct bad_textures *b = &bad_textures[k];
    skgl_camera cam = camera();
    skgl_scene sc = gt_scene(&env);
    skgl_area_light l = area();
    int is_bare, slot;
    for (is_bare = 0; is_bare < 2; is_bare++)
        for (slot = 0; slot < 3; slot++) {
            unsigned t[3];
            char what[64], needle[64];
            sk_result r;
            if (!((is_bare ? b->bare : b->bogus) >> slot & 1)) continue;
            t[0] = env.gbuf.depth_tex;
            t[1] = env.gbuf.color_tex;
            t[2] = env.mask.color_tex;
            t[slot] = is_bare ? bare : BOGUS_NAME;
            if (b->call == BAD_MASK) r = skgl_shadow_mask(sk, s, &cam, t[0], t[1], t[2]);
            else if (b->call == BAD_POINT_MASK) r = skgl_point_mask(sk, p, &cam, t[0], t[1], t[2]);
            else r = skgl_soft_render(sk, a, &cam, &sc, &l, t[0], t[1], t[2]);
            snprintf(what, sizeof what, "%s %s %s", b->name, slot_name[slot], is_bare ? "bare" : "bogus");
            if (is_bare) snprintf(needle, sizeof needle, "no level 0");
            else if (b->named >> slot & 1)
                snprintf(needle, sizeof needle, "%s_tex = %u: not a texture", slot_name[slot], BOGUS_NAME);
            else snprintf(needle, sizeof needle, "not a texture");
            expect(sk, r, SK_ERR_INVALID_ARG, what, needle);
        }
}

/* ---- 16: names that are not textures, textures without storage ------------ */
static void test_textures(skgl_context *sk) {
    skgl_shadow *s = NULL, *f = NULL;
    skgl_point *p = NULL;
    skgl_soft *a = NULL;
    skgl_camera cam = camera();
    skgl_scene sc = gt_scene(&env);
    skgl_caps caps = skgl_get_caps(sk);
    unsigned bare = 0, dt = env.gbuf.depth_tex, nt = env.gbuf.color_tex, mt = env.mask.color_tex;
    lights_create(sk, 256, 64, &s, &f, &p, &a);
    env.gl.GenTextures(1, &bare);
    env.gl.BindTexture(E_TEXTURE_2D, bare);       /* a texture, no storage */
    env.gl.BindTexture(E_TEXTURE_2D, 0);
    if (!s || !f || !p || !a) goto done;
    /* 17: masks and binds of lights never rendered */
    expect(sk, skgl_shadow_mask(sk, s, &cam, dt, nt, mt), SK_ERR_INVALID_ARG, "mask before render",
           "has not been rendered");
    expect(sk, skgl_shadow_bind(sk, s, 1, 0), SK_ERR_INVALID_ARG, "bind before render", "has not been rendered");
    SK_CHECK(skgl_shadow_render(sk, s, &cam, &sc, sun()) == SK_OK);
    SK_CHECK(skgl_point_render(sk, p, &cam, &sc, gt_v3(1, 3, 1)) == SK_OK);
    expect_bad_textures(sk, BAD_MASK, s, p, a, bare);
    expect_bad_textures(sk, BAD_POINT_MASK, s, p, a, bare);
    expect(sk, skgl_shadow_analyze(sk, f, &cam, &sc, sun(), BOGUS_NAME), SK_ERR_INVALID_ARG, "analyze bogus",
           "not a texture");
    expect(sk, skgl_shadow_analyze(sk, f, &cam, &sc, sun(), bare), SK_ERR_INVALID_ARG, "analyze bare", "no level 0");
    expect_bad_textures(sk, BAD_SOFT, s, p, a, bare);
    expect(sk, skgl_remember_texture(sk, BOGUS_NAME, 64, 64), SK_ERR_INVALID_ARG, "remember bogus", "not a texture");
    expect(sk, skgl_remember_texture(sk, mt, caps.max_texture_size + 1, 16), SK_ERR_INVALID_ARG, "remember huge",
           "GL_MAX_TEXTURE_SIZE");
    expect(sk, skgl_remember_texture(sk, mt, -3, 16), SK_ERR_INVALID_ARG, "remember negative", "-3 x 16");
    /* the good calls still work */
    expect(sk, skgl_shadow_mask(sk, s, &cam, dt, nt, mt), SK_OK, "mask", NULL);
    expect(sk, skgl_point_mask(sk, p, &cam, dt, nt, mt), SK_OK, "point mask", NULL);
done:
    env.gl.DeleteTextures(1, &bare);
    lights_destroy(sk, s, f, p, a);
}

/* ---- 11: binds to programs without the snippet ------------------------- */
static unsigned link_program(const char *fs_body) {
    static const char vs[] = "#version 330 core\nlayout(location = 0) in vec3 a;\n"
                             "void main() { gl_Position = vec4(a, 1.0); }\n";
    const char *v[1], *f[2];
    int linked;
    v[0] = vs;
    f[0] = "#version 330 core\n";
    f[1] = fs_body;
    return gt_program(&env.gl, 1, v, 2, f, &linked);
}

static void test_binds(skgl_context *sk) {
    skgl_shadow *s = NULL;
    skgl_point *p = NULL;
    skgl_camera cam = camera();
    skgl_scene sc = gt_scene(&env);
    gt_forward fw;
    unsigned plain = link_program("uniform sampler2D u_albedo;\nout vec4 o;\n"
                                  "void main() { o = texture(u_albedo, vec2(0.5)); }\n");
    lights_create(sk, 256, 64, &s, NULL, &p, NULL);
    SK_CHECK(gt_forward_create(&env, &fw) == 0);
    if (!s || !p || !fw.program) goto done;
    SK_CHECK(skgl_shadow_render(sk, s, &cam, &sc, sun()) == SK_OK);
    SK_CHECK(skgl_point_render(sk, p, &cam, &sc, gt_v3(1, 3, 1)) == SK_OK);
    env.gl.UseProgram(plain);
    expect(sk, skgl_shadow_bind(sk, s, plain, 0), SK_ERR_INVALID_ARG, "bind without the snippet",
           "no active uniform sk_shadow_map");
    expect(sk, skgl_point_bind(sk, p, plain, 2), SK_ERR_INVALID_ARG, "point bind without the snippet",
           "no active uniform sk_point_cube");
    env.gl.UseProgram(fw.program);
    expect(sk, skgl_shadow_bind_named(sk, s, fw.program, 0, "sun0_", NULL), SK_ERR_INVALID_ARG,
           "bind under the wrong prefix", "no active uniform sun0_shadow_map");
    expect(sk, skgl_shadow_bind(sk, s, fw.program, 0), SK_OK, "bind with the snippet", NULL);
    env.gl.UseProgram(0);
    expect(sk, skgl_shadow_bind(sk, s, fw.program, 0), SK_ERR_INVALID_ARG, "bind, program not current",
           "is not current");
    expect(sk, skgl_shadow_bind(sk, s, BOGUS_NAME, 0), SK_ERR_INVALID_ARG, "bind, bogus program",
           "not a linked GL program");
    expect(sk, skgl_unbind(sk, 0), SK_OK, "unbind", NULL);
done:
    env.gl.UseProgram(0);
    env.gl.DeleteProgram(plain);
    gt_forward_destroy(&env, &fw);
    skgl_shadow_destroy(sk, s);
    skgl_point_destroy(sk, p);
}

/* ---- 12: renders and creates nested in a draw callback -------------------- */
typedef struct nest {
    skgl_context *sk;
    skgl_shadow *inner;
    skgl_point *lamp;
    skgl_soft *soft;
    int try_nested;
    sk_result got[3];
    sk_result made[5];   /* the five creates tried in the callback */
    int named[5];        /* 1: the log names the create and the callback */
    int left;            /* objects they handed out (0: every out stays NULL) */
} nest;
static nest nested;

/* every create from inside a draw callback: refused by their shared opening
   (skgl__create_open), the log naming the call, nothing handed out */
static void nested_named(nest *n, int k, const char *fn) {
    char want[96];
    snprintf(want, sizeof want, "%s: called inside a draw callback", fn);
    n->named[k] = strstr(skgl_error_log(n->sk), want) != NULL;
}
static void nested_creates(nest *n) {
    struct {
        skgl_shadow_desc shadow;
        skgl_point_desc point;
        skgl_soft_desc soft;
        skgl_caster_desc caster;
    } d;
    skgl_shadow *s = NULL;
    skgl_point *p = NULL;
    skgl_soft *f = NULL;
    skgl_point_atlas *a = NULL;
    skgl_caster *c = NULL;
    memset(&d, 0, sizeof d);
    d.shadow.resolution = d.point.resolution = 64;
    d.soft.resolution = 128;
    d.caster.vertex = "layout(location = 0) in vec3 a_pos;\nvec4 skgl_caster_position() { return vec4(a_pos, 1.0); }\n";
    n->made[0] = skgl_shadow_create(n->sk, &d.shadow, &s);
    nested_named(n, 0, "skgl_shadow_create");
    n->made[1] = skgl_point_create(n->sk, &d.point, &p);
    nested_named(n, 1, "skgl_point_create");
    n->made[2] = skgl_soft_create(n->sk, &d.soft, &f);
    nested_named(n, 2, "skgl_soft_create");
    n->made[3] = skgl_point_atlas_create(n->sk, 256, 128, &a);
    nested_named(n, 3, "skgl_point_atlas_create");
    n->made[4] = skgl_caster_create(n->sk, &d.caster, &c);
    nested_named(n, 4, "skgl_caster_create");
    n->left += (s != NULL) + (p != NULL) + (f != NULL) + (a != NULL) + (c != NULL);
}

static void draw_nesting(void *user, const skgl_draw_info *info) {
    nest *n = (nest *)user;
    static const float lift[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.3f, 0.5f, -0.2f, 1};
    skgl_camera cam = camera();
    skgl_scene sc = gt_scene(&env);
    skgl_area_light l = area();
    (void)info;
    if (n->try_nested) {
        n->got[0] = skgl_shadow_render(n->sk, n->inner, &cam, &sc, gt_v3(0.3f, -1, 0.2f));
        n->got[1] = skgl_point_render(n->sk, n->lamp, &cam, &sc, gt_v3(1, 3, 1));
        n->got[2] = skgl_soft_render(n->sk, n->soft, &cam, &sc, &l, env.gbuf.depth_tex, env.gbuf.color_tex,
                                     env.mask.color_tex);
        nested_creates(n);
    }
    skgl_set_model(n->sk, lift);     /* lost when a nested render resets the model location */
    tb_gl_mesh_draw(&env.gl, &env.mesh, 0, 0);
}

static void test_nested(skgl_context *sk) {
    skgl_shadow_desc sd;
    skgl_point_desc pd;
    skgl_soft_desc fd;
    skgl_shadow *outer = NULL;
    skgl_camera cam = camera();
    skgl_scene sc = gt_scene(&env);
    float *plain = (float *)malloc(sizeof(float) * W * H), *tried = (float *)malloc(sizeof(float) * W * H);
    size_t i, differ = 0;
    memset(&nested, 0, sizeof nested);
    nested.sk = sk;
    memset(&sd, 0, sizeof sd);
    sd.resolution = 512;
    memset(&pd, 0, sizeof pd);
    pd.resolution = 64;
    memset(&fd, 0, sizeof fd);
    fd.resolution = 128;
    SK_CHECK(skgl_shadow_create(sk, &sd, &outer) == SK_OK);
    SK_CHECK(skgl_shadow_create(sk, &sd, &nested.inner) == SK_OK);
    SK_CHECK(skgl_point_create(sk, &pd, &nested.lamp) == SK_OK);
    SK_CHECK(skgl_soft_create(sk, &fd, &nested.soft) == SK_OK);
    if (!outer || !nested.inner || !nested.lamp || !nested.soft || !plain || !tried) goto done;
    sc.draw = draw_nesting;
    sc.user = &nested;
    gt_gbuffer(&env, &cam);
    nested.try_nested = 0;
    expect(sk, skgl_shadow_render(sk, outer, &cam, &sc, sun()), SK_OK, "outer render", NULL);
    gt_mask_only(&env, outer, &cam, plain);
    nested.try_nested = 1;
    expect(sk, skgl_shadow_render(sk, outer, &cam, &sc, sun()), SK_OK, "outer render with nested tries", NULL);
    SK_CHECK_MSG(nested.got[0] == SK_ERR_INVALID_ARG && nested.got[1] == SK_ERR_INVALID_ARG &&
                     nested.got[2] == SK_ERR_INVALID_ARG,
                 "nested renders: %s, %s, %s", sk_result_string(nested.got[0]), sk_result_string(nested.got[1]),
                 sk_result_string(nested.got[2]));
    for (i = 0; i < 5; i++)
        SK_CHECK_MSG(nested.made[i] == SK_ERR_INVALID_ARG && nested.named[i], "nested create %d: %s, named %d",
                     (int)i, sk_result_string(nested.made[i]), nested.named[i]);
    SK_CHECK_MSG(nested.left == 0, "nested creates handed out %d objects", nested.left);
    gt_mask_only(&env, outer, &cam, tried);
    for (i = 0; i < (size_t)W * H; i++) differ += fabsf(plain[i] - tried[i]) > 1e-3f;
    printf("  nested renders: %zu mask pixels differ from the render without them\n", differ);
    SK_CHECK_MSG(differ == 0, "%zu mask pixels changed by the nested render attempts", differ);
done:
    free(plain);
    free(tried);
    skgl_shadow_destroy(sk, outer);
    skgl_shadow_destroy(sk, nested.inner);
    skgl_point_destroy(sk, nested.lamp);
    skgl_soft_destroy(sk, nested.soft);
}

/* ---- 13: a callback that leaves its own program current, debug off ------- */
static unsigned foreign;
static void draw_leaving_program(void *user, const skgl_draw_info *info) {
    static const float lift[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0.25f, 0, 1};
    skgl_context *sk = (skgl_context *)user;
    (void)info;
    skgl_set_model(sk, lift);
    tb_gl_mesh_draw(&env.gl, &env.mesh, 0, 0);
    env.gl.UseProgram(foreign);                     /* against SCENE ACCESS */
}

/* ... without a model of its own (skgl_set_model would have the pass's
   program bound again after the callback, hiding what comes next) */
static void draw_leaving_program_plain(void *user, const skgl_draw_info *info) {
    (void)user;
    (void)info;
    tb_gl_mesh_draw(&env.gl, &env.mesh, 0, 0);
    env.gl.UseProgram(foreign);                     /* against SCENE ACCESS */
}

static void test_foreign_program(void) {
    skgl_desc d = desc_with((skgl_getproc_fn)real_getproc, 0);
    skgl_context *sk = NULL;
    skgl_shadow_desc sd;
    skgl_shadow *s = NULL;
    skgl_camera cam = camera();
    skgl_scene sc = gt_scene(&env);
    float probe[4] = {0, 0, 0, 0};
    int loc;
    void (*get_uniformfv)(unsigned, int, float *) = NULL;
    void (*uniform4f)(int, float, float, float, float) = NULL;
    void *gp = real_getproc("glGetUniformfv");
    memcpy(&get_uniformfv, &gp, sizeof gp);
    gp = real_getproc("glUniform4f");
    memcpy(&uniform4f, &gp, sizeof gp);
    foreign = link_program("uniform vec4 u_probe[4];\nout vec4 o;\nvoid main() { o = u_probe[0] + u_probe[3]; }\n");
    loc = env.gl.GetUniformLocation(foreign, "u_probe");
    env.gl.UseProgram(foreign);
    uniform4f(loc, 7, 7, 7, 7);
    env.gl.UseProgram(0);
    SK_CHECK(skgl_create(&d, &sk) == SK_OK);
    memset(&sd, 0, sizeof sd);
    sd.technique = SKGL_PSSM;
    sd.cascades = 3;
    sd.resolution = 256;
    if (sk) SK_CHECK(skgl_shadow_create(sk, &sd, &s) == SK_OK);
    if (s) {
        sc.draw = draw_leaving_program;
        sc.user = sk;
        (void)skgl_shadow_render(sk, s, &cam, &sc, sun());
        SK_CHECK_MSG(gl_error() == E_NO_ERROR, "a callback leaving its program current: GL error left (debug off)");
        get_uniformfv(foreign, loc, probe);
        SK_CHECK_MSG(probe[0] == 7 && probe[1] == 7 && probe[2] == 7 && probe[3] == 7,
                     "the foreign program's u_probe[0] became (%g %g %g %g)", probe[0], probe[1], probe[2], probe[3]);
    }
    /* RMSM with desc.layered: a callback per 8 pages, the pass's program
       bound again before each batch's matrices (without it the second
       batch's glUniformMatrix4fv lands in the foreign program) */
    if (sk) {
        skgl_shadow *rm = NULL;
        const skgl_shadow_frame_stats *st;
        memset(&sd, 0, sizeof sd);
        sd.technique = SKGL_RMSM;
        sd.resolution = 16384;
        sd.rmsm_page_size = 128;
        sd.rmsm_pool_pages = 8;
        sd.layered = 1;
        SK_CHECK(skgl_shadow_create(sk, &sd, &rm) == SK_OK);
        if (rm && gt_gbuffer(&env, &cam) == 0) {
            sc.draw = draw_leaving_program_plain;
            sc.user = sk;
            SK_CHECK(skgl_shadow_analyze(sk, rm, &cam, &sc, sun(), env.gbuf.depth_tex) == SK_OK);
            (void)skgl_shadow_render(sk, rm, &cam, &sc, sun());
            st = skgl_shadow_stats(rm);
            SK_CHECK_MSG(st->passes > 1 && st->layered > 0, "RMSM layered: %d passes, layered %d", st->passes,
                         st->layered);
            SK_CHECK_MSG(gl_error() == E_NO_ERROR, "RMSM layered, a callback leaving its program current: GL error "
                         "left (debug off)");
            get_uniformfv(foreign, loc, probe);
            SK_CHECK_MSG(probe[0] == 7 && probe[1] == 7 && probe[2] == 7 && probe[3] == 7,
                         "RMSM layered: the foreign program's u_probe[0] became (%g %g %g %g)", probe[0], probe[1],
                         probe[2], probe[3]);
        }
        skgl_shadow_destroy(sk, rm);
    }
    env.gl.UseProgram(0);
    skgl_shadow_destroy(sk, s);
    skgl_destroy(sk);
    env.gl.DeleteProgram(foreign);
}

/* ---- the campaign: NULL, zero, negative, huge, NaN, Inf -------------------- */
static void test_campaign(skgl_context *sk) {
    skgl_shadow *s = NULL;
    skgl_point *p = NULL;
    skgl_point_atlas *atlas = NULL;
    skgl_camera cam = camera(), nan_cam = cam, inf_cam = cam, zero_cam;
    skgl_scene sc = gt_scene(&env);
    skgl_area_light l = area();
    skgl_dynamic dyn;
    sk_aabb box = gt_box(0, 0, 0, 1, 1, 1), nan_box = gt_box(0, 0, 0, NAN, 1, 1);
    double bad_origin[3] = {1e40, 0, 0};
    float nan_v = NAN;
    memset(&zero_cam, 0, sizeof zero_cam);
    nan_cam.proj.m[0] = NAN;
    inf_cam.view.m[12] = INFINITY;
    lights_create(sk, 128, 32, &s, NULL, &p, NULL);
    if (!s || !p) goto done;
    expect(sk, skgl_shadow_render(sk, s, NULL, &sc, sun()), SK_ERR_INVALID_ARG, "render NULL cam", "cam is NULL");
    expect(sk, skgl_shadow_render(sk, s, &cam, NULL, sun()), SK_ERR_INVALID_ARG, "render NULL scene", "scene");
    expect(sk, skgl_shadow_render(sk, s, &nan_cam, &sc, sun()), SK_ERR_INVALID_ARG, "render NaN proj", "cam->proj");
    expect(sk, skgl_shadow_render(sk, s, &inf_cam, &sc, sun()), SK_ERR_INVALID_ARG, "render inf view", "cam->view");
    expect(sk, skgl_shadow_render(sk, s, &zero_cam, &sc, sun()), SK_ERR_INVALID_ARG, "render zero cam", "cam->");
    expect(sk, skgl_shadow_render(sk, s, &cam, &sc, gt_v3(nan_v, 1, 0)), SK_ERR_INVALID_ARG, "render NaN dir",
           "light_dir");
    expect(sk, skgl_shadow_render(sk, s, &cam, &sc, gt_v3(INFINITY, -1, 0)), SK_ERR_INVALID_ARG, "render inf dir",
           "light_dir");
    expect(sk, skgl_shadow_render(sk, s, &cam, &sc, sun()), SK_OK, "render", NULL);
    expect(sk, skgl_shadow_mask(sk, s, NULL, 1, 0, 1), SK_ERR_INVALID_ARG, "mask NULL cam", "cam is NULL");
    expect(sk, skgl_shadow_mask(sk, NULL, &cam, 1, 0, 1), SK_ERR_INVALID_ARG, "mask NULL s", "s is NULL");
    expect(sk, skgl_shadow_mask(sk, s, &cam, 0, 0, env.mask.color_tex), SK_ERR_INVALID_ARG, "mask depth 0",
           "depth_tex = 0");
    expect(sk, skgl_shadow_bind(sk, s, 1, -1), SK_ERR_INVALID_ARG, "bind unit -1", "unit = -1");
    expect(sk, skgl_shadow_bind(sk, s, 1, INT_MAX), SK_ERR_INVALID_ARG, "bind unit huge", "unit = ");
    expect(sk, skgl_shadow_bind_named(sk, s, 1, 0, "gl_x", NULL), SK_ERR_INVALID_ARG, "bind prefix gl_", "prefix");
    expect(sk, skgl_shadow_bind_origin(sk, s, 1, 0, bad_origin), SK_ERR_INVALID_ARG, "bind origin", "origin");
    expect(sk, skgl_unbind(sk, -1), SK_ERR_INVALID_ARG, "unbind -1", "unit = -1");
    expect(sk, skgl_unbind(sk, 1000), SK_ERR_INVALID_ARG, "unbind 1000", "unit = 1000");
    expect(sk, skgl_shadow_invalidate(sk, s, &nan_box), SK_ERR_INVALID_ARG, "invalidate NaN", "box");
    expect(sk, skgl_shadow_invalidate(sk, NULL, &box), SK_ERR_INVALID_ARG, "invalidate NULL", "s");
    memset(&dyn, 0, sizeof dyn);
    expect(sk, skgl_set_dynamic(sk, &dyn), SK_ERR_INVALID_ARG, "dynamic without draw", "dyn->draw");
    dyn.draw = gt_draw;
    dyn.bounds = nan_box;
    expect(sk, skgl_set_dynamic(sk, &dyn), SK_ERR_INVALID_ARG, "dynamic NaN bounds", "dyn->bounds");
    expect(sk, skgl_set_dynamic(sk, NULL), SK_OK, "dynamic NULL", NULL);
    expect(sk, skgl_point_render(sk, p, &cam, &sc, gt_v3(nan_v, 1, 1)), SK_ERR_INVALID_ARG, "point NaN pos",
           "light_pos");
    expect(sk, skgl_point_render(sk, NULL, &cam, &sc, gt_v3(1, 1, 1)), SK_ERR_INVALID_ARG, "point NULL", "p is NULL");
    expect(sk, skgl_point_mask(sk, p, &cam, env.gbuf.depth_tex, 0, env.mask.color_tex), SK_ERR_INVALID_ARG,
           "point mask before render", "not been rendered");
    expect(sk, skgl_point_bind(sk, p, 1, 0), SK_ERR_INVALID_ARG, "point bind before render", "not been rendered");
    expect(sk, skgl_point_invalidate(sk, p, &nan_box), SK_ERR_INVALID_ARG, "point invalidate NaN", "box");
    expect(sk, skgl_point_atlas_create(sk, -1, 64, &atlas), SK_ERR_INVALID_ARG, "atlas -1", "-1 x 64");
    expect(sk, skgl_point_atlas_create(sk, INT_MAX, 64, &atlas), SK_ERR_INVALID_ARG, "atlas huge", "width = 2147483647");
    expect(sk, skgl_point_atlas_pack(sk, NULL, &p, 1, &cam, &l.position), SK_ERR_INVALID_ARG, "pack NULL atlas",
           "a ");
    expect(sk, skgl_soft_render(sk, NULL, &cam, &sc, &l, 0, 0, env.mask.color_tex), SK_ERR_INVALID_ARG, "soft NULL",
           "s is NULL");
    expect(sk, skgl_remember_texture(sk, 0, 16, 16), SK_ERR_INVALID_ARG, "remember 0", "texture = 0");
    expect(sk, skgl_remember_texture(sk, env.mask.color_tex, 0, 16), SK_ERR_INVALID_ARG, "remember 0 wide", "0 x 16");
done:
    skgl_shadow_destroy(sk, s);
    skgl_point_destroy(sk, p);
}

/* ---- 18: the matrix functions ------------------------------------------ */
static int mat_finite(const sk_mat4 *m) {
    int i;
    for (i = 0; i < 16; i++) if (!isfinite(m->m[i])) return 0;
    return 1;
}

static void test_matrices(void) {
    sk_mat4 a = sk_mat4_identity(), b = sk_mat4_identity(), c;
    sk_vec3 q;
    a.m[0] = 3e38f; a.m[4] = 3e38f;               /* row 0: 3e38 x + 3e38 y */
    b.m[0] = 3e38f; b.m[1] = -3e38f;              /* column 0: (3e38, -3e38, 0, 0) */
    c = sk_mat4_mul(a, b);                        /* 9e76 - 9e76 in float: inf - inf */
    SK_CHECK_MSG(mat_finite(&c), "sk_mat4_mul near 3e38: m[0] = %g", c.m[0]);
    b = sk_mat4_identity();
    b.m[0] = 2.0f; b.m[1] = 2.0f;
    c = sk_mat4_mul(a, b);                        /* 6e38 + 6e38: beyond float */
    SK_CHECK_MSG(mat_finite(&c) && c.m[0] > 3.4e38f, "sk_mat4_mul overflow: m[0] = %g", c.m[0]);
    a = sk_mat4_identity();
    a.m[15] = 1e-45f;
    q = sk_mat4_transform_point(a, gt_v3(1, -2, 3));
    SK_CHECK_MSG(isfinite(q.x) && isfinite(q.y) && isfinite(q.z) && q.x > 3e38f && q.y < -3e38f,
                 "sk_mat4_transform_point, w = 1e-45: (%g %g %g)", q.x, q.y, q.z);
    a = sk_mat4_identity();
    a.m[12] = 3e38f;
    q = sk_mat4_transform_point(a, gt_v3(3e38f, 0, 0));
    SK_CHECK_MSG(isfinite(q.x), "sk_mat4_transform_point, x near 3e38: %g", q.x);
    /* ordinary input: the same bits as before (the double path runs only on overflow) */
    a = camera().proj;
    b = camera().view;
    c = sk_mat4_mul(a, b);
    SK_CHECK(c.m[0] == a.m[0] * b.m[0] + a.m[4] * b.m[1] + a.m[8] * b.m[2] + a.m[12] * b.m[3]);
}

static void test_misuse(void) {
    if (gt_env_init_named(&env, "ground-boxes", W, H) != 0) {
        gt_env_free(&env);
        SK_CHECK_MSG(0, "no GL context");
        return;
    }
    real_getproc = tb_gl_context_getproc(env.ctx);
    (void)gl_error();
    test_pending_errors();
    test_create_messages();
    test_bounds(env.sk);
    test_cameras(env.sk);
    test_descs(env.sk);
    test_null_creates(env.sk);
    test_textures(env.sk);
    test_binds(env.sk);
    test_nested(env.sk);
    test_foreign_program();
    test_campaign(env.sk);
    test_matrices();
    SK_CHECK_MSG(gl_error() == E_NO_ERROR, "GL error at the end");
    gt_env_free(&env);
}

SK_TEST_MAIN(test_misuse)
