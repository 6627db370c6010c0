/* test_gl_paths.c - the error paths and the less travelled branches of
   shadowkit_gl.h: the context, directional lights of every technique,
   point lights, the shared point atlas, area lights (test_soft_paths,
   described there), and what shadowkit keeps between
   calls (read-back rings, timer rings, the uniform-location cache per
   program, the texture-size cache per texture name, framebuffer checks).

   GL failures that Mesa's llvmpipe never produces on its own are injected
   by a getproc of this test (fault_getproc) that wraps the testbed
   context's and lies on demand: every entry point NULL, or one; the GL
   version; a shader's compile status or a program's link status; a
   framebuffer incomplete (the (n+1)-th glCheckFramebufferStatus from
   now); glGetError reporting GL_OUT_OF_MEMORY once; glClientWaitSync
   answering GL_CONDITION_SATISFIED for GL_ALREADY_SIGNALED; glFenceSync
   giving no fence; glGetTexLevelParameteriv answering a given width or
   height. Everything else goes to the real function.

   Every case asserts on values: the sk_result; that skgl_error_log names
   the offending field or argument (only the field name is looked for:
   the messages are being reworded) and, where the call clears the log
   (skgl_shadow_create: "the error log is cleared per call"), that the log
   is empty again after a later successful call; that the context's GL
   object count (skgl_gl_object_count) is back at its value before the
   failed call (nothing leaked, nothing counted twice); the stats fields a
   branch sets; mask pixels where the branch decides them.

   test_context: skgl_create with NULL desc / getproc / out, timing -1 and
     3 (SK_ERR_INVALID_ARG); a getproc that finds nothing, or lacks one
     entry point (SK_ERR_GL, *out NULL); GL 2.1 and 3.2 reported (SK_ERR_GL);
     a compile failure, a link failure, a GL error while making the
     context's objects (SK_ERR_GL); the NULL-context accessors; a context
     made and destroyed leaves a fresh context's count where it was.
   test_shadow_rules: every rule of skgl_shadow_desc broken once (26
     cases, both sides of each range): SK_ERR_INVALID_ARG, *out NULL, the
     field named, no object made; a valid create clears the log. The
     defaults (skgl_shadow_get_desc) of the negative "none" values.
   test_shadow_args: NULL and bad arguments of render, analyze, mask,
     bind, bind_origin (unit, program, origin), a camera whose projection
     is neither perspective nor orthographic, a singular one; the NULL
     accessors; skgl_shadow_matrix out of range is the identity.
   test_shadow_techniques: STANDARD, PSSM (blend band, stable), PSM,
     LiSPSM, LSPSM, FERKO, RMSM rendered and masked on a 128 x 128 view of
     "ground-boxes" (256 maps), in the default mode and caller-owns mode,
     with debug and timing = 1 / SKGL_TIMING_SYNC: SK_OK, lit and
     shadowed pixels in the mask, stats as the mode says (SYNC: times of
     this frame, >= 0, after one frame; timing 1: -1 after one frame).
   test_faults: framebuffer incomplete at the creation of each technique's
     objects (STANDARD, PSSM's third layer, FERKO's estimate target,
     RMSM's request atlas), at FERKO's and RMSM's analysis targets, at the
     mask's target, at a point light's cube faces, VSDCT atlas and shared
     atlas: SK_ERR_GL, the log says which, the count unchanged; the same
     call again without the fault succeeds. A GL error (desc.debug) after
     render, mask, analyze, bind, point render / mask / bind: SK_ERR_GL and
     the log names the function; at skgl_shadow_create, skgl_point_create,
     skgl_point_atlas_create: SK_ERR_GL, nothing leaked.
   test_textures: a mask texture with no level 0 (SK_ERR_INVALID_ARG, log
     "level 0"), a depth texture as the mask (not colour-renderable:
     SK_ERR_GL), each again after skgl_forget_texture once fixed; a size
     past 65536 or a zero height reported; desc.debug refusing a height
     that changed under the same name; without debug the size is
     remembered (a mask texture grown under its name is written only in
     its old size: pixels beyond keep the clear value) until
     skgl_forget_texture (then all of it).
   test_rings: FERKO and RMSM through the read-back ring with
     glClientWaitSync answering GL_CONDITION_SATISFIED (a landed fence:
     the estimate / pages of the second frame are read) and with no fence
     made (nothing lands: the first frame's result stays, no fence
     counted as an object).
   test_program_cache: a forward program that declares the snippet but
     never calls sk_shadow (every location -1: no uniform is sent, no
     sentinel read); relinked with one more active uniform (the default
     mode's count check looks its locations up again); under desc.debug,
     relinked so that its locations change; skgl_forget_program with 0 and
     a NULL context; a point program bound twice.
   test_point_paths: every rule of skgl_point_desc (17 cases) names its
     field; caster_visible outside a point pass (NULL info, a directional
     pass, no light) and without cull_casters is 1; CUBE and VSDCT with
     cull_faces, cull_casters, scissor, select_resolution (screen given,
     and from the viewport) in both modes; a light whose range box is off
     screen with the scissor (stats.scissor all 0, no pixel written);
     point bind and mask arguments.
   test_atlas: create arguments (0, past GL_MAX_TEXTURE_SIZE: the field
     named); pack arguments (NULL lights, n 0, a NULL light, a light of no
     or another atlas, a NaN position); an atlas too small for six faces
     of one texel (SK_ERR_CAPACITY, the log says so, every light keeps
     its placement); a shared-atlas light rendered before any pack
     (SK_ERR_INVALID_ARG, log names skgl_point_atlas_pack); a CUBE light
     given an atlas ("atlas" named).
   test_callback_program: desc.debug, a draw callback that returns with a
     program of its own current in an RMSM render (the pages' loop) and a
     point render (the faces' loop): SK_ERR_INVALID_ARG, the log names the
     program; the plain callback then gives SK_OK.
   test_set_model: skgl_set_model with NULL context or matrix; outside a
     callback (no program current; the caller's program current; a
     caller's program with a mat4 at the location u_model has in the depth
     program, found through info->program).
   test_log_cleared: after a failed mask, each successful call of render,
     mask, analyze, bind, point create / render, atlas create.

   Two gaps this test found, fixed since (10 checks that failed on the
   header before the fix):
   - the log was cleared at the start of skgl_shadow_create only, not of
     every call that takes the context: the 7 successful calls above left
     the failed mask's message in place;
   - skgl_set_model outside a draw callback called glUniformMatrix4fv on
     whatever program was current: GL_INVALID_OPERATION with none or with
     one that has no mat4 there, and a caller's program that has a mat4 at
     u_model's location (1 here) had its value overwritten silently. It
     does nothing outside a caster pass now.
   Also found: the LSPSM rule "lspsm.h_max * lspsm.nw_max" can never fire
   (the defaults set cascades = h_max * nw_max first, so the cascades rule
   refuses the product and names "cascades", a field the caller left 0);
   the case asserts what the header does.

   Measured (Mesa llvmpipe, OSMesa, 2 cores): 971 checks pass in about 1 s
   (-O2; 1.3 s in the --coverage build). make coverage, all tests, on
   shadowkit_gl.h: branches 75.7% (1750 of 2312) before this test, 90.4%
   (2089) with it; lines 96.5% (2730 of 2828) before, 98.6% (2789) after;
   this test alone: branches 70.6%, lines 69.6%. Outside skgl_soft_* (which
   this test leaves alone, 422 branches): 76.1% -> 94.0% of 1890.
   Can fail (each shown once on a local copy of shadowkit_gl.h):
   - a failed framebuffer that is deleted without ctx->objects--: "ferko
     analysis fault: 35 objects (34)" and 10 more count checks;
   - the texture size asked every time without debug: the grown texture's
     mask refused (its size changed under the name) and "remembered size:
     0 written inside the old size";
   - the ring poll taking only GL_ALREADY_SIGNALED as landed:
     "CONDITION_SATISFIED: 46 pages, B's 50" (and FERKO's estimate);
   - SKGL_TIMING_SYNC not reading the query at once: "standard: SYNC after
     one frame: -1 / -1 / -1 ms" for every technique;
   - the default mode's active-uniform count check ignored: "relinked, one
     more uniform: radius 0, unit 0";
   - debug's location check ignored: the bind after the relink fails;
   - the mask's framebuffer checked at every call: "2 framebuffer checks in
     two masks after the failure";
   - skgl__log_clear emptied: "shadow rules: log ... after a successful
     create" (3 checks);
   - a rule renaming its field ("sigma" for "lspsm.sigma"): 2 checks. */
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "sk_test.h"
#include "gl_test_util.h"

#define W 128
#define H 128
#define RES 256

/* ---- the fault-injecting getproc ---- */
static struct {
    int null_all;             /* every entry point NULL */
    const char *null_name;    /* this one NULL */
    int major, minor;         /* reported version (0: the real one) */
    int compile_fail;         /* the next compile status reads 0 */
    int link_fail;            /* the next link status reads 0 */
    int fb_skip, fb_fail;     /* after fb_skip more checks, fb_fail of them answer incomplete */
    int gl_error;             /* glGetError answers GL_OUT_OF_MEMORY this many times, from the
                                 second call on (the first is the call's entry check for errors
                                 the application left pending, which are not shadowkit's) */
    int gl_error_entry;       /* 1: that first call has been answered */
    int wait_satisfied;       /* ALREADY_SIGNALED reported as CONDITION_SATISFIED */
    int no_fence;             /* glFenceSync gives NULL */
    int tex_w, tex_h;         /* glGetTexLevelParameteriv answers these when > 0 or < 0 (-1: 0) */
    long fb_checks, fences;
} F;

typedef void (*getintegerv_fn)(unsigned, int *);
typedef void (*getshaderiv_fn)(unsigned, unsigned, int *);
typedef unsigned (*checkfb_fn)(unsigned);
typedef unsigned (*geterror_fn)(void);
typedef unsigned (*clientwait_fn)(void *, unsigned, unsigned long long);
typedef void *(*fencesync_fn)(unsigned, unsigned);
typedef void (*texlevel_fn)(unsigned, int, unsigned, int *);
static tb_gl_getproc_fn real_getproc;
static getintegerv_fn real_get_integerv;
static getshaderiv_fn real_get_shaderiv, real_get_programiv;
static checkfb_fn real_check_fb;
static geterror_fn real_get_error;
static clientwait_fn real_client_wait;
static fencesync_fn real_fence_sync;
static texlevel_fn real_tex_level;

static void w_get_integerv(unsigned pname, int *v) {
    real_get_integerv(pname, v);
    if (pname == 0x821B /* MAJOR_VERSION */ && F.major) *v = F.major;
    if (pname == 0x821C /* MINOR_VERSION */ && F.major) *v = F.minor;
}
static void w_get_shaderiv(unsigned sh, unsigned pname, int *v) {
    real_get_shaderiv(sh, pname, v);
    if (pname == 0x8B81 /* COMPILE_STATUS */ && F.compile_fail) { F.compile_fail = 0; *v = 0; }
}
static void w_get_programiv(unsigned p, unsigned pname, int *v) {
    real_get_programiv(p, pname, v);
    if (pname == 0x8B82 /* LINK_STATUS */ && F.link_fail) { F.link_fail = 0; *v = 0; }
}
static unsigned w_check_fb(unsigned target) {
    unsigned r = real_check_fb(target);
    F.fb_checks++;
    if (F.fb_fail > 0) {
        if (F.fb_skip > 0) F.fb_skip--;
        else { F.fb_fail--; return 0x8CD6; /* INCOMPLETE_ATTACHMENT */ }
    }
    return r;
}
static unsigned w_get_error(void) {
    unsigned r = real_get_error();
    if (r == 0 && F.gl_error > 0) {
        if (!F.gl_error_entry) { F.gl_error_entry = 1; return 0; }
        if (--F.gl_error == 0) F.gl_error_entry = 0;
        return 0x0505; /* OUT_OF_MEMORY */
    }
    return r;
}
static unsigned w_client_wait(void *sync, unsigned flags, unsigned long long timeout) {
    unsigned r = real_client_wait(sync, flags, timeout);
    return F.wait_satisfied && r == 0x911A /* ALREADY_SIGNALED */ ? 0x911C /* CONDITION_SATISFIED */ : r;
}
static void *w_fence_sync(unsigned cond, unsigned flags) {
    F.fences++;
    return F.no_fence ? NULL : real_fence_sync(cond, flags);
}
static void w_tex_level(unsigned target, int level, unsigned pname, int *v) {
    real_tex_level(target, level, pname, v);
    if (pname == 0x1000 /* TEXTURE_WIDTH */ && F.tex_w) *v = F.tex_w < 0 ? 0 : F.tex_w;
    if (pname == 0x1001 /* TEXTURE_HEIGHT */ && F.tex_h) *v = F.tex_h < 0 ? 0 : F.tex_h;
}

#define FN_TO_PTR(f, p) memcpy(&(p), &(f), sizeof(p))
#define PTR_TO_FN(p, f) memcpy(&(f), &(p), sizeof(f))
static void *fault_getproc(const char *name) {
    void *p = NULL;
    getintegerv_fn gi = w_get_integerv;
    getshaderiv_fn gs = w_get_shaderiv, gp = w_get_programiv;
    checkfb_fn cf = w_check_fb;
    geterror_fn ge = w_get_error;
    clientwait_fn cw = w_client_wait;
    fencesync_fn fs = w_fence_sync;
    texlevel_fn tl = w_tex_level;
    if (F.null_all || (F.null_name && !strcmp(name, F.null_name))) return NULL;
    if (!strcmp(name, "glGetIntegerv")) FN_TO_PTR(gi, p);
    else if (!strcmp(name, "glGetShaderiv")) FN_TO_PTR(gs, p);
    else if (!strcmp(name, "glGetProgramiv")) FN_TO_PTR(gp, p);
    else if (!strcmp(name, "glCheckFramebufferStatus")) FN_TO_PTR(cf, p);
    else if (!strcmp(name, "glGetError")) FN_TO_PTR(ge, p);
    else if (!strcmp(name, "glClientWaitSync")) FN_TO_PTR(cw, p);
    else if (!strcmp(name, "glFenceSync")) FN_TO_PTR(fs, p);
    else if (!strcmp(name, "glGetTexLevelParameteriv")) FN_TO_PTR(tl, p);
    else return real_getproc(name);
    return p;
}
static void fault_install(tb_gl_getproc_fn gp) {
    void *p;
    real_getproc = gp;
    p = gp("glGetIntegerv"); PTR_TO_FN(p, real_get_integerv);
    p = gp("glGetShaderiv"); PTR_TO_FN(p, real_get_shaderiv);
    p = gp("glGetProgramiv"); PTR_TO_FN(p, real_get_programiv);
    p = gp("glCheckFramebufferStatus"); PTR_TO_FN(p, real_check_fb);
    p = gp("glGetError"); PTR_TO_FN(p, real_get_error);
    p = gp("glClientWaitSync"); PTR_TO_FN(p, real_client_wait);
    p = gp("glFenceSync"); PTR_TO_FN(p, real_fence_sync);
    p = gp("glGetTexLevelParameteriv"); PTR_TO_FN(p, real_tex_level);
}
static void faults_off(void) { memset(&F, 0, sizeof F); }

static skgl_context *fault_context(int debug, int timing, int owns) {
    skgl_desc d;
    skgl_context *sk = NULL;
    sk_result r;
    memset(&d, 0, sizeof d);
    d.getproc = fault_getproc;
    d.debug = debug;
    d.timing = timing;
    d.caller_owns_state = owns;
    r = skgl_create(&d, &sk);
    SK_CHECK_MSG(r == SK_OK && sk, "skgl_create: %s", sk_result_string(r));
    return sk;
}

/* the log names `what` (non-empty) */
#define CHECK_LOG(sk, what) SK_CHECK_MSG(skgl_error_log(sk)[0] && strstr(skgl_error_log(sk), (what)) != NULL, \
                                         "log \"%s\" does not name %s", skgl_error_log(sk), (what))
/* a later successful skgl_shadow_create leaves the log empty */
static void check_log_cleared(skgl_context *sk, const char *where) {
    skgl_shadow_desc d;
    skgl_shadow *s = NULL;
    int before = skgl_gl_object_count(sk);
    memset(&d, 0, sizeof d);
    d.resolution = 64;
    SK_CHECK_MSG(skgl_shadow_create(sk, &d, &s) == SK_OK && s, "%s: create after the failure", where);
    SK_CHECK_MSG(skgl_error_log(sk)[0] == 0, "%s: log \"%s\" after a successful create", where, skgl_error_log(sk));
    skgl_shadow_destroy(sk, s);
    SK_CHECK_MSG(skgl_gl_object_count(sk) == before, "%s: %d objects, %d before", where, skgl_gl_object_count(sk),
                 before);
}

static sk_vec3 light_dir(void) { return gt_v3(-0.5f, -1, -0.35f); }
static skgl_camera view_a(void) { return gt_camera(gt_v3(-9, 7, 12), gt_v3(0, 1, 0), 1.0f, 0.1f, 250, W, H); }
static skgl_camera view_b(void) { return gt_camera(gt_v3(-3, 2.5f, 4), gt_v3(0, 0.5f, 0), 1.0f, 0.1f, 250, W, H); }

static int env_init(gt_env *e) {
    if (gt_env_init_named(e, "ground-boxes", W, H) != 0) { gt_env_free(e); return -1; }
    fault_install(tb_gl_context_getproc(e->ctx));
    faults_off();
    return 0;
}

/* lit (> 0.9) and shadowed (< 0.1) covered pixels of a mask */
static void count_mask(const gt_env *e, const float *m, int *lit, int *dark) {
    size_t i;
    *lit = *dark = 0;
    for (i = 0; i < e->n; i++) {
        if (m[i] < 0) continue;
        if (m[i] > 0.9f) (*lit)++;
        else if (m[i] < 0.1f) (*dark)++;
    }
}

/* render (+ analysis where the technique has one) and mask with sk; 0 ok */
static int frame(gt_env *e, skgl_context *sk, skgl_shadow *s, const skgl_camera *cam, float *mask) {
    skgl_scene sc = gt_scene(e);
    sk_result r;
    size_t i;
    skgl_technique t = skgl_shadow_get_desc(s).technique;
    if (t == SKGL_FERKO || t == SKGL_RMSM) {
        r = skgl_shadow_analyze(sk, s, cam, &sc, light_dir(), e->gbuf.depth_tex);
        if (r != SK_OK) { printf("analyze: %s (%s)\n", sk_result_string(r), skgl_error_log(sk)); return -1; }
    }
    r = skgl_shadow_render(sk, s, cam, &sc, light_dir());
    if (r != SK_OK) { printf("render: %s (%s)\n", sk_result_string(r), skgl_error_log(sk)); return -1; }
    r = skgl_shadow_mask(sk, s, cam, e->gbuf.depth_tex, e->gbuf.color_tex, e->mask.color_tex);
    if (r != SK_OK) { printf("mask: %s (%s)\n", sk_result_string(r), skgl_error_log(sk)); return -1; }
    if (!mask) return 0;
    if (tb_gl_read_texture_red(&e->gl, e->mask.color_tex, e->w, e->h, mask) != 0) return -1;
    for (i = 0; i < e->n; i++) if (!(e->depth[i] < 1.0f)) mask[i] = -1.0f;
    return 0;
}

/* ======================================================================= */
static void test_context(void) {
    gt_env e;
    skgl_desc d;
    skgl_context *sk = (skgl_context *)&d;
    int base;
    float m[16];
    if (env_init(&e) != 0) return;
    memset(&d, 0, sizeof d);
    SK_CHECK(skgl_create(NULL, &sk) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_create(&d, &sk) == SK_ERR_INVALID_ARG);         /* no getproc */
    d.getproc = fault_getproc;
    SK_CHECK(skgl_create(&d, NULL) == SK_ERR_INVALID_ARG);
    d.timing = -1;
    SK_CHECK(skgl_create(&d, &sk) == SK_ERR_INVALID_ARG);
    d.timing = SKGL_TIMING_SYNC + 1;
    SK_CHECK(skgl_create(&d, &sk) == SK_ERR_INVALID_ARG);
    d.timing = 0;
    /* nothing found, one entry point missing */
    F.null_all = 1;
    sk = (skgl_context *)&d;
    SK_CHECK(skgl_create(&d, &sk) == SK_ERR_GL && sk == NULL);
    faults_off();
    F.null_name = "glFenceSync";
    sk = (skgl_context *)&d;
    SK_CHECK(skgl_create(&d, &sk) == SK_ERR_GL && sk == NULL);
    /* too old a GL */
    faults_off();
    F.major = 2; F.minor = 1;
    SK_CHECK(skgl_create(&d, &sk) == SK_ERR_GL && sk == NULL);
    F.major = 3; F.minor = 2;
    SK_CHECK(skgl_create(&d, &sk) == SK_ERR_GL && sk == NULL);
    F.major = 3; F.minor = 3;
    SK_CHECK(skgl_create(&d, &sk) == SK_OK && sk != NULL);
    base = skgl_gl_object_count(sk);
    skgl_destroy(sk);
    sk = NULL;
    faults_off();
    /* shaders: a compile and a link that fail; a GL error at the end */
    F.compile_fail = 1;
    SK_CHECK(skgl_create(&d, &sk) == SK_ERR_GL && sk == NULL);
    SK_CHECK(F.compile_fail == 0);
    F.link_fail = 1;
    SK_CHECK(skgl_create(&d, &sk) == SK_ERR_GL && sk == NULL);
    SK_CHECK(F.link_fail == 0);
    F.gl_error = 1;
    SK_CHECK(skgl_create(&d, &sk) == SK_ERR_GL && sk == NULL);
    SK_CHECK(F.gl_error == 0);
    faults_off();
    SK_CHECK(e.gl.GetError() == 0);
    /* after all that, a context counts what the first one did */
    SK_CHECK(skgl_create(&d, &sk) == SK_OK && sk != NULL);
    SK_CHECK_MSG(skgl_gl_object_count(sk) == base && base > 0, "%d objects, first context %d",
                 skgl_gl_object_count(sk), base);
    SK_CHECK(skgl_error_log(sk)[0] == 0);
    /* the NULL context */
    SK_CHECK(skgl_gl_object_count(NULL) == 0);
    SK_CHECK(skgl_error_log(NULL) != NULL && skgl_error_log(NULL)[0] == 0);
    skgl_destroy(NULL);
    memset(m, 0, sizeof m);
    m[0] = m[5] = m[10] = m[15] = 1;
    skgl_set_model(NULL, m);
    skgl_set_model(sk, NULL);
    skgl_forget_program(NULL, 5);
    skgl_forget_program(sk, 0);
    skgl_forget_texture(NULL, 5);
    skgl_forget_texture(sk, 0);
    SK_CHECK(skgl_gl_object_count(sk) == base);
    SK_CHECK(e.gl.GetError() == 0);
    skgl_destroy(sk);
    gt_env_free(&e);
}

/* ======================================================================= */
typedef struct rule_case {
    const char *field;
    skgl_technique technique;
    int which;
} rule_case;

static void rule_apply(skgl_shadow_desc *d, int which) {
    switch (which) {
    case 0: d->technique = (skgl_technique)(SKGL_AUTO + 1); break;
    case 1: d->technique = (skgl_technique)-1; break;
    case 2: d->resolution = 16385; break;
    case 3: d->cascades = SKGL_MAX_CASCADES + 1; break;
    case 4: d->lambda = 1.5f; break;
    case 5: d->blend_band = -0.1f; break;
    case 6: d->blend_band = 1.0f; break;
    case 7: d->pcf_radius = 9; break;
    case 8: d->max_distance = -1.0f; break;
    case 9: d->psm_slide = 2000.0f; break;
    case 10: d->bias = (skgl_bias)3; break;
    case 11: d->bias = (skgl_bias)-1; break;
    case 12: d->plane_bias = 65.0f; break;
    case 13: d->lspsm.zeta = 0.6f; break;
    case 14: d->lspsm.zeta = -0.1f; break;
    case 15: d->lspsm.sigma = -1.0f; break;
    case 16: d->lspsm.sigma = 2000.0f; break;
    case 17: d->lspsm.h_max = -1; break;
    case 18: d->lspsm.h_max = 9; break;
    case 19: d->lspsm.nw_max = -1; break;
    case 20: d->lspsm.nw_max = 9; break;
    case 21: d->lspsm.h_max = 3; d->lspsm.nw_max = 3; break;
    case 22: d->sync_readback = 2; break;
    case 23: d->sync_readback = -2; break;
    case 24: d->normal_bias = -1.0f; break;
    case 25: d->slope_bias = -1.0f; break;
    case 26: d->rmsm_page_size = 8; break;
    case 27: d->rmsm_page_size = 2048; break;
    case 28: d->rmsm_page_size = 100; break;
    case 29: d->resolution = 3000; break;
    case 30: d->resolution = 64; d->rmsm_page_size = 128; break;
    case 31: d->resolution = 65536; d->rmsm_page_size = 16; break;
    case 32: d->rmsm_pool_pages = 1; break;
    case 33: d->rmsm_pool_pages = 65; break;
    case 34: d->rmsm_pool_pages = 64; d->rmsm_page_size = 512; break;
    default: break;
    }
}

static void test_shadow_rules(void) {
    static const rule_case cases[] = {
        {"technique", SKGL_STANDARD, 0}, {"technique", SKGL_STANDARD, 1}, {"resolution", SKGL_STANDARD, 2},
        {"cascades", SKGL_PSSM, 3}, {"lambda", SKGL_PSSM, 4}, {"blend_band", SKGL_PSSM, 5},
        {"blend_band", SKGL_PSSM, 6}, {"pcf_radius", SKGL_STANDARD, 7}, {"max_distance", SKGL_STANDARD, 8},
        {"psm_slide", SKGL_PSM, 9}, {"bias", SKGL_STANDARD, 10}, {"bias", SKGL_STANDARD, 11},
        {"plane_bias", SKGL_STANDARD, 12}, {"lspsm.zeta", SKGL_LSPSM, 13}, {"lspsm.zeta", SKGL_LSPSM, 14},
        {"lspsm.sigma", SKGL_LSPSM, 15}, {"lspsm.sigma", SKGL_LSPSM, 16}, {"lspsm.h_max", SKGL_LSPSM, 17},
        {"lspsm.h_max", SKGL_LSPSM, 18}, {"lspsm.nw_max", SKGL_LSPSM, 19}, {"lspsm.nw_max", SKGL_LSPSM, 20},
        /* the product rule is checked before .cascades, which the defaults
           set to h_max * nw_max: the log names the fields the caller set */
        {"lspsm.h_max * lspsm.nw_max", SKGL_LSPSM, 21}, {"sync_readback", SKGL_FERKO, 22},
        {"sync_readback", SKGL_RMSM, 23}, {"normal_bias", SKGL_STANDARD, 24}, {"slope_bias", SKGL_RMSM, 25},
        {"rmsm_page_size", SKGL_RMSM, 26}, {"rmsm_page_size", SKGL_RMSM, 27}, {"rmsm_page_size", SKGL_RMSM, 28},
        {"resolution", SKGL_RMSM, 29}, {"resolution", SKGL_RMSM, 30}, {"resolution", SKGL_RMSM, 31},
        {"rmsm_pool_pages", SKGL_RMSM, 32}, {"rmsm_pool_pages", SKGL_RMSM, 33},
        {"rmsm_pool_pages", SKGL_RMSM, 34}};
    gt_env e;
    skgl_context *sk;
    skgl_shadow_desc d, g;
    skgl_shadow *s;
    size_t k;
    int base;
    if (env_init(&e) != 0) return;
    sk = fault_context(0, 0, 0);
    if (!sk) { gt_env_free(&e); return; }
    base = skgl_gl_object_count(sk);
    for (k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        sk_result r;
        memset(&d, 0, sizeof d);
        d.technique = cases[k].technique;
        rule_apply(&d, cases[k].which);
        s = (skgl_shadow *)&d;
        r = skgl_shadow_create(sk, &d, &s);
        SK_CHECK_MSG(r == SK_ERR_INVALID_ARG && s == NULL, "rule %d (%s): %s", cases[k].which, cases[k].field,
                     sk_result_string(r));
        CHECK_LOG(sk, cases[k].field);
        SK_CHECK_MSG(skgl_gl_object_count(sk) == base, "rule %d: %d objects (%d)", cases[k].which,
                     skgl_gl_object_count(sk), base);
        if (s) skgl_shadow_destroy(sk, s);
    }
    check_log_cleared(sk, "shadow rules");
    /* NULL arguments */
    memset(&d, 0, sizeof d);
    s = (skgl_shadow *)&d;
    SK_CHECK(skgl_shadow_create(NULL, &d, &s) == SK_ERR_INVALID_ARG && s == NULL);
    SK_CHECK(skgl_shadow_create(sk, NULL, &s) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_shadow_create(sk, &d, NULL) == SK_ERR_INVALID_ARG);
    /* the "none" values and explicit ones kept by the defaults */
    memset(&d, 0, sizeof d);
    d.technique = SKGL_PSM;
    d.resolution = 128;
    d.uniform_splits = 1;
    d.disable_polygon_offset = 1; d.normal_bias = 0.7f; d.disable_plane_bias = 1;
    d.disable_psm_slide = 1; d.disable_pcf_kernel = 1; d.sync_readback = 1;
    d.lspsm.sigma = 0.8f;
    s = NULL;
    SK_CHECK(skgl_shadow_create(sk, &d, &s) == SK_OK && s);
    g = skgl_shadow_get_desc(s);
    SK_CHECK(g.lambda == 0.0f && g.slope_bias == 0.0f && g.depth_bias == 0.0f && g.normal_bias == 0.7f);
    SK_CHECK(g.plane_bias == 0.0f && g.psm_slide == 0.0f && g.pcf_radius == 0 && g.sync_readback == 1);
    SK_CHECK(g.lspsm.sigma == 0.8f && g.cascades == 1);
    skgl_shadow_destroy(sk, s);
    d.psm_slide = 2.0f; d.lambda = 0.5f;
    d.disable_psm_slide = d.uniform_splits = 0;
    s = NULL;
    SK_CHECK(skgl_shadow_create(sk, &d, &s) == SK_OK && s);
    g = skgl_shadow_get_desc(s);
    SK_CHECK(g.psm_slide == 2.0f && g.lambda == 0.5f);
    skgl_shadow_destroy(sk, s);
    g = skgl_shadow_get_desc(NULL);
    SK_CHECK(g.resolution == 0 && g.technique == SKGL_STANDARD);
    SK_CHECK(skgl_gl_object_count(sk) == base);
    skgl_destroy(sk);
    gt_env_free(&e);
}

/* ======================================================================= */
static int mat_is_identity(sk_mat4 m) {
    int k;
    for (k = 0; k < 16; k++) if (m.m[k] != ((k % 5) == 0 ? 1.0f : 0.0f)) return 0;
    return 1;
}

static void test_shadow_args(void) {
    gt_env e;
    skgl_context *sk;
    skgl_shadow_desc d;
    skgl_shadow *s = NULL, *f = NULL;
    skgl_scene sc, bad_sc;
    skgl_camera cam = view_a(), bad = view_a(), ortho = view_a(), sing = view_a();
    sk_vec3 zero = gt_v3(0, 0, 0), nan3 = gt_v3(NAN, 0, -1);
    double far_origin[3] = {1e31, 0, 0};
    int base;
    if (env_init(&e) != 0) return;
    sk = fault_context(1, 0, 0);
    if (!sk) { gt_env_free(&e); return; }
    sc = gt_scene(&e);
    SK_CHECK(gt_gbuffer(&e, &cam) == 0);
    gt_warm_programs(sk);
    base = skgl_gl_object_count(sk);
    memset(&d, 0, sizeof d);
    d.resolution = RES;
    SK_CHECK(skgl_shadow_create(sk, &d, &s) == SK_OK);
    d.technique = SKGL_FERKO;
    SK_CHECK(skgl_shadow_create(sk, &d, &f) == SK_OK);
    if (!s || !f) { skgl_destroy(sk); gt_env_free(&e); return; }
    bad.view.m[3] = NAN;
    /* a projection that is neither perspective nor orthographic */
    ortho.proj = sk_mat4_identity();
    ortho.proj.m[11] = 0.5f;
    /* singular view-projection */
    memset(&sing.proj, 0, sizeof sing.proj);
    sing.proj.m[11] = -1.0f;
    /* render */
    SK_CHECK(skgl_shadow_render(NULL, s, &cam, &sc, light_dir()) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_shadow_render(sk, NULL, &cam, &sc, light_dir()) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_shadow_render(sk, s, NULL, &sc, light_dir()) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_shadow_render(sk, s, &cam, NULL, light_dir()) == SK_ERR_INVALID_ARG);
    bad_sc = sc; bad_sc.draw = NULL;
    SK_CHECK(skgl_shadow_render(sk, s, &cam, &bad_sc, light_dir()) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_shadow_render(sk, s, &cam, &sc, zero) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_shadow_render(sk, s, &cam, &sc, nan3) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_shadow_render(sk, s, &bad, &sc, light_dir()) == SK_ERR_INVALID_ARG);
    bad.view.m[3] = 0; bad.proj.m[3] = NAN;
    SK_CHECK(skgl_shadow_render(sk, s, &bad, &sc, light_dir()) == SK_ERR_INVALID_ARG);
    bad.view.m[3] = NAN; bad.proj.m[3] = 0;
    bad_sc = sc; bad_sc.bounds.min.x = bad_sc.bounds.max.x + 1;
    SK_CHECK(skgl_shadow_render(sk, s, &cam, &bad_sc, light_dir()) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_shadow_render(sk, s, &ortho, &sc, light_dir()) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_shadow_stats(s)->passes == 0);
    /* analyze */
    SK_CHECK(skgl_shadow_analyze(NULL, f, &cam, &sc, light_dir(), e.gbuf.depth_tex) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_shadow_analyze(sk, NULL, &cam, &sc, light_dir(), e.gbuf.depth_tex) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_shadow_analyze(sk, f, NULL, &sc, light_dir(), e.gbuf.depth_tex) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_shadow_analyze(sk, f, &cam, NULL, light_dir(), e.gbuf.depth_tex) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_shadow_analyze(sk, f, &cam, &sc, light_dir(), 0) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_shadow_analyze(sk, s, &cam, &sc, light_dir(), e.gbuf.depth_tex) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_shadow_analyze(sk, f, &cam, &sc, zero, e.gbuf.depth_tex) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_shadow_analyze(sk, f, &cam, &sc, nan3, e.gbuf.depth_tex) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_shadow_analyze(sk, f, &bad, &sc, light_dir(), e.gbuf.depth_tex) == SK_ERR_INVALID_ARG);
    bad.view.m[3] = 0; bad.proj.m[3] = NAN;
    SK_CHECK(skgl_shadow_analyze(sk, f, &bad, &sc, light_dir(), e.gbuf.depth_tex) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_shadow_analyze(sk, f, &cam, &bad_sc, light_dir(), e.gbuf.depth_tex) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_shadow_analyze(sk, f, &sing, &sc, light_dir(), e.gbuf.depth_tex) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_shadow_stats(f)->estimate.samples == 0);
    /* mask */
    SK_CHECK(skgl_shadow_mask(NULL, s, &cam, e.gbuf.depth_tex, 0, e.mask.color_tex) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_shadow_mask(sk, NULL, &cam, e.gbuf.depth_tex, 0, e.mask.color_tex) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_shadow_mask(sk, s, NULL, e.gbuf.depth_tex, 0, e.mask.color_tex) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_shadow_mask(sk, s, &cam, 0, 0, e.mask.color_tex) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_shadow_mask(sk, s, &cam, e.gbuf.depth_tex, 0, 0) == SK_ERR_INVALID_ARG);
    bad = view_a(); bad.view.m[0] = INFINITY;
    SK_CHECK(skgl_shadow_mask(sk, s, &bad, e.gbuf.depth_tex, 0, e.mask.color_tex) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_shadow_mask(sk, s, &sing, e.gbuf.depth_tex, 0, e.mask.color_tex) == SK_ERR_INVALID_ARG);
    /* bind (program 0 refused before anything is looked at) */
    SK_CHECK(skgl_shadow_bind(NULL, s, 1, 0) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_shadow_bind(sk, NULL, 1, 0) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_shadow_bind(sk, s, 0, 0) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_shadow_bind(sk, s, 1, -1) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_shadow_bind(sk, s, 1, 32) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_shadow_bind_origin(sk, s, 1, 0, far_origin) == SK_ERR_INVALID_ARG);
    far_origin[0] = 0; far_origin[1] = NAN;
    SK_CHECK(skgl_shadow_bind_origin(sk, s, 1, 0, far_origin) == SK_ERR_INVALID_ARG);
    far_origin[1] = 0; far_origin[2] = -INFINITY;
    SK_CHECK(skgl_shadow_bind_origin(sk, s, 1, 0, far_origin) == SK_ERR_INVALID_ARG);
    /* accessors */
    SK_CHECK(skgl_shadow_stats(NULL) == NULL);
    SK_CHECK(skgl_shadow_texture(NULL) == 0 && skgl_shadow_texture(s) != 0);
    SK_CHECK(skgl_shadow_analysis_texture(NULL) == 0 && skgl_shadow_analysis_texture(s) == 0);
    SK_CHECK(skgl_shadow_pages(NULL, NULL, 4) == 0);
    SK_CHECK(skgl_shadow_pages(s, NULL, 4) == 0);
    SK_CHECK(mat_is_identity(skgl_shadow_matrix(NULL, 0)));
    SK_CHECK(mat_is_identity(skgl_shadow_matrix(s, -1)));
    SK_CHECK(mat_is_identity(skgl_shadow_matrix(s, 1)));
    /* the valid calls still work after all that, and clear nothing they should not */
    SK_CHECK(frame(&e, sk, s, &cam, NULL) == 0);
    SK_CHECK(!mat_is_identity(skgl_shadow_matrix(s, 0)) && skgl_shadow_stats(s)->passes == 1);
    SK_CHECK(e.gl.GetError() == 0);
    skgl_shadow_destroy(sk, s);
    skgl_shadow_destroy(sk, f);
    skgl_shadow_destroy(NULL, NULL);
    SK_CHECK(skgl_gl_object_count(sk) == base);
    skgl_destroy(sk);
    gt_env_free(&e);
}

/* ======================================================================= */
typedef struct tech_case {
    const char *name;
    skgl_technique t;
    int cascades, stable;
    float blend;
} tech_case;

static void test_shadow_techniques(void) {
    static const tech_case cases[] = {
        {"standard", SKGL_STANDARD, 0, 0, 0}, {"pssm blend", SKGL_PSSM, 3, 0, 0.2f},
        {"pssm stable", SKGL_PSSM, 2, 1, 0}, {"psm", SKGL_PSM, 0, 0, 0}, {"lispsm", SKGL_LISPSM, 2, 0, 0},
        {"lspsm", SKGL_LSPSM, 0, 0, 0}, {"ferko", SKGL_FERKO, 0, 0, 0}, {"rmsm", SKGL_RMSM, 0, 0, 0}};
    static const int modes[][3] = {/* debug, timing, owns */ {1, 1, 0}, {0, SKGL_TIMING_SYNC, 1}, {1, 0, 1}};
    gt_env e;
    skgl_camera cam = view_a();
    float *mask;
    size_t k, m;
    if (env_init(&e) != 0) return;
    mask = gt_alloc(&e);
    SK_CHECK(gt_gbuffer(&e, &cam) == 0);
    for (m = 0; m < sizeof modes / sizeof modes[0]; m++) {
        skgl_context *sk = fault_context(modes[m][0], modes[m][1], modes[m][2]);
        int base;
        if (!sk) continue;
        gt_warm_programs(sk);
        base = skgl_gl_object_count(sk);
        for (k = 0; k < sizeof cases / sizeof cases[0]; k++) {
            skgl_shadow_desc d;
            skgl_shadow *s = NULL;
            const skgl_shadow_frame_stats *st;
            int lit, dark;
            memset(&d, 0, sizeof d);
            d.technique = cases[k].t;
            d.resolution = cases[k].t == SKGL_RMSM ? 2048 : RES;
            d.cascades = cases[k].cascades;
            d.stable = cases[k].stable;
            d.blend_band = cases[k].blend;
            d.rmsm_page_size = 64;
            d.rmsm_pool_pages = 8;
            d.disable_plane_bias = 1;   /* none: the plane's own tolerance only */
            d.disable_polygon_offset = m == 2;   /* no polygon offset at all in the third mode */
            if (skgl_shadow_create(sk, &d, &s) != SK_OK) {
                SK_CHECK_MSG(0, "%s: create: %s", cases[k].name, skgl_error_log(sk));
                continue;
            }
            SK_CHECK_MSG(frame(&e, sk, s, &cam, mask) == 0, "%s, mode %d: frame", cases[k].name, (int)m);
            st = skgl_shadow_stats(s);
            count_mask(&e, mask, &lit, &dark);
            SK_CHECK_MSG(lit > 1000 && dark > 200, "%s, mode %d: %d lit, %d shadowed", cases[k].name, (int)m, lit,
                         dark);
            if (modes[m][1] == SKGL_TIMING_SYNC)
                SK_CHECK_MSG(st->shadow_ms >= 0 && st->mask_ms >= 0 &&
                                 (cases[k].t != SKGL_FERKO && cases[k].t != SKGL_RMSM ? 1 : st->analysis_ms >= 0),
                             "%s: SYNC after one frame: %g / %g / %g ms", cases[k].name, st->shadow_ms, st->mask_ms,
                             st->analysis_ms);
            else if (modes[m][1] == 1)
                SK_CHECK_MSG(st->shadow_ms == -1.0f && st->mask_ms == -1.0f,
                             "%s: timing 1 after one frame: %g / %g ms", cases[k].name, st->shadow_ms, st->mask_ms);
            else SK_CHECK(st->shadow_ms == -1.0f && st->mask_ms == -1.0f && st->analysis_ms == -1.0f);
            SK_CHECK_MSG(skgl_error_log(sk)[0] == 0 || cases[k].t == SKGL_STANDARD, "%s: log \"%s\"",
                         cases[k].name, skgl_error_log(sk));
            skgl_shadow_destroy(sk, s);
        }
        SK_CHECK_MSG(skgl_gl_object_count(sk) == base, "mode %d: %d objects (%d)", (int)m, skgl_gl_object_count(sk),
                     base);
        SK_CHECK(e.gl.GetError() == 0);
        skgl_destroy(sk);
    }
    free(mask);
    gt_env_free(&e);
}

/* ======================================================================= */
static void test_faults(void) {
    gt_env e;
    skgl_context *sk;
    skgl_shadow_desc d;
    skgl_shadow *s = NULL, *f = NULL, *rm = NULL;
    skgl_point_desc pd;
    skgl_point *p = NULL;
    skgl_point_atlas *a = NULL;
    skgl_scene sc;
    skgl_camera cam = view_a();
    unsigned prog = 0, pprog = 0;
    gt_forward fw;
    int base, n;
    if (env_init(&e) != 0) return;
    sk = fault_context(1, 0, 0);
    if (!sk) { gt_env_free(&e); return; }
    sc = gt_scene(&e);
    SK_CHECK(gt_gbuffer(&e, &cam) == 0);
    gt_warm_programs(sk);
    base = skgl_gl_object_count(sk);
    memset(&d, 0, sizeof d);
    d.resolution = RES;
    /* framebuffer incomplete while creating: STANDARD's layer, PSSM's
       third, FERKO's estimate target, RMSM's request atlas */
    F.fb_fail = 1;
    SK_CHECK(skgl_shadow_create(sk, &d, &s) == SK_ERR_GL && s == NULL);
    CHECK_LOG(sk, "framebuffer");
    SK_CHECK(skgl_gl_object_count(sk) == base);
    d.technique = SKGL_PSSM; d.cascades = 4;
    F.fb_skip = 2; F.fb_fail = 1;
    SK_CHECK(skgl_shadow_create(sk, &d, &s) == SK_ERR_GL && s == NULL);
    CHECK_LOG(sk, "framebuffer");
    SK_CHECK(skgl_gl_object_count(sk) == base);
    d.technique = SKGL_FERKO; d.cascades = 0;
    F.fb_skip = 1; F.fb_fail = 1;
    SK_CHECK(skgl_shadow_create(sk, &d, &s) == SK_ERR_GL && s == NULL);
    CHECK_LOG(sk, "RGBA32F");
    SK_CHECK(skgl_gl_object_count(sk) == base);
    d.technique = SKGL_RMSM; d.resolution = 2048; d.rmsm_page_size = 64; d.rmsm_pool_pages = 8;
    F.fb_skip = 1; F.fb_fail = 1;
    SK_CHECK(skgl_shadow_create(sk, &d, &s) == SK_ERR_GL && s == NULL);
    CHECK_LOG(sk, "request atlas");
    SK_CHECK(skgl_gl_object_count(sk) == base);
    /* a GL error at the end of a create */
    faults_off();
    F.gl_error = 1;
    d.technique = SKGL_STANDARD; d.resolution = RES;
    SK_CHECK(skgl_shadow_create(sk, &d, &s) == SK_ERR_GL && s == NULL);
    CHECK_LOG(sk, "GL_OUT_OF_MEMORY");
    SK_CHECK(skgl_gl_object_count(sk) == base);
    faults_off();
    check_log_cleared(sk, "create faults");
    /* the analysis targets: FERKO's reduction chain, RMSM's samples */
    d.technique = SKGL_FERKO;
    SK_CHECK(skgl_shadow_create(sk, &d, &f) == SK_OK);
    d.technique = SKGL_RMSM; d.resolution = 2048;
    SK_CHECK(skgl_shadow_create(sk, &d, &rm) == SK_OK);
    d.technique = SKGL_STANDARD; d.resolution = RES;
    SK_CHECK(skgl_shadow_create(sk, &d, &s) == SK_OK);
    if (!f || !rm || !s) goto done;
    n = skgl_gl_object_count(sk);
    F.fb_fail = 1;
    SK_CHECK(skgl_shadow_analyze(sk, f, &cam, &sc, light_dir(), e.gbuf.depth_tex) == SK_ERR_GL);
    CHECK_LOG(sk, "RGBA32F");
    SK_CHECK_MSG(skgl_gl_object_count(sk) == n, "ferko analysis fault: %d objects (%d)", skgl_gl_object_count(sk), n);
    F.fb_fail = 1;
    SK_CHECK(skgl_shadow_analyze(sk, rm, &cam, &sc, light_dir(), e.gbuf.depth_tex) == SK_ERR_GL);
    CHECK_LOG(sk, "RGBA32F");
    SK_CHECK(skgl_shadow_analysis_texture(rm) != 0);    /* the texture stays, the framebuffer does not */
    faults_off();
    SK_CHECK(frame(&e, sk, f, &cam, NULL) == 0 && skgl_shadow_stats(f)->estimate.samples == 1);
    SK_CHECK(frame(&e, sk, rm, &cam, NULL) == 0 && skgl_shadow_stats(rm)->pages_rendered > 1);
    /* the mask's target: checked once per texture name */
    SK_CHECK(skgl_shadow_render(sk, s, &cam, &sc, light_dir()) == SK_OK);
    skgl_forget_texture(sk, e.mask.color_tex);
    F.fb_fail = 1;
    SK_CHECK(skgl_shadow_mask(sk, s, &cam, e.gbuf.depth_tex, e.gbuf.color_tex, e.mask.color_tex) == SK_ERR_GL);
    CHECK_LOG(sk, "colour-renderable");
    F.fb_checks = 0;
    SK_CHECK(skgl_shadow_mask(sk, s, &cam, e.gbuf.depth_tex, e.gbuf.color_tex, e.mask.color_tex) == SK_OK);
    SK_CHECK(skgl_shadow_mask(sk, s, &cam, e.gbuf.depth_tex, e.gbuf.color_tex, e.mask.color_tex) == SK_OK);
    SK_CHECK_MSG(F.fb_checks == 1, "%ld framebuffer checks in two masks after the failure", F.fb_checks);
    /* GL errors under desc.debug: each call names itself */
    F.gl_error = 1;
    SK_CHECK(skgl_shadow_render(sk, s, &cam, &sc, light_dir()) == SK_ERR_GL);
    CHECK_LOG(sk, "skgl_shadow_render");
    F.gl_error = 1;
    SK_CHECK(skgl_shadow_render(sk, rm, &cam, &sc, light_dir()) == SK_ERR_GL);
    CHECK_LOG(sk, "skgl_shadow_render");
    F.gl_error = 1;
    SK_CHECK(skgl_shadow_mask(sk, s, &cam, e.gbuf.depth_tex, 0, e.mask.color_tex) == SK_ERR_GL);
    CHECK_LOG(sk, "skgl_shadow_mask");
    F.gl_error = 1;
    SK_CHECK(skgl_shadow_analyze(sk, f, &cam, &sc, light_dir(), e.gbuf.depth_tex) == SK_ERR_GL);
    CHECK_LOG(sk, "skgl_shadow_analyze");
    /* programs that hold the snippets: desc.debug refuses a bind to one that
       does not (ERRORS AND MISUSE) */
    SK_CHECK(gt_forward_create(&e, &fw) == 0);
    prog = fw.program;
    pprog = gt_point_program(&e.gl, 0);
    e.gl.UseProgram(prog);
    F.gl_error = 1;
    SK_CHECK(skgl_shadow_bind(sk, s, prog, 0) == SK_ERR_GL);
    CHECK_LOG(sk, "skgl_shadow_bind");
    e.gl.UseProgram(0);
    faults_off();
    /* point lights: a cube face, the VSDCT atlas, a GL error */
    memset(&pd, 0, sizeof pd);
    pd.resolution = 64;
    pd.range = 30;
    n = skgl_gl_object_count(sk);
    F.fb_skip = 3; F.fb_fail = 1;
    SK_CHECK(skgl_point_create(sk, &pd, &p) == SK_ERR_GL && p == NULL);
    CHECK_LOG(sk, "framebuffer");
    SK_CHECK_MSG(skgl_gl_object_count(sk) == n, "cube fault: %d objects (%d)", skgl_gl_object_count(sk), n);
    pd.technique = SKGL_POINT_VSDCT;
    F.fb_fail = 1;
    SK_CHECK(skgl_point_create(sk, &pd, &p) == SK_ERR_GL && p == NULL);
    CHECK_LOG(sk, "framebuffer");
    SK_CHECK(skgl_gl_object_count(sk) == n);
    faults_off();
    F.gl_error = 1;
    SK_CHECK(skgl_point_create(sk, &pd, &p) == SK_ERR_GL && p == NULL);
    CHECK_LOG(sk, "skgl_point_create");
    SK_CHECK(skgl_gl_object_count(sk) == n);
    /* the shared atlas */
    F.fb_fail = 1;
    SK_CHECK(skgl_point_atlas_create(sk, 256, 128, &a) == SK_ERR_GL && a == NULL);
    CHECK_LOG(sk, "skgl_point_atlas_create");
    SK_CHECK(skgl_gl_object_count(sk) == n);
    F.gl_error = 1;
    SK_CHECK(skgl_point_atlas_create(sk, 256, 128, &a) == SK_ERR_GL && a == NULL);
    SK_CHECK(skgl_gl_object_count(sk) == n);
    faults_off();
    /* a point light working, then GL errors in its calls */
    pd.technique = SKGL_POINT_CUBE;
    SK_CHECK(skgl_point_create(sk, &pd, &p) == SK_OK && p);
    if (p) {
        F.gl_error = 1;
        SK_CHECK(skgl_point_render(sk, p, &cam, &sc, gt_v3(0, 4, 0)) == SK_ERR_GL);
        CHECK_LOG(sk, "skgl_point_render");
        F.gl_error = 1;
        SK_CHECK(skgl_point_mask(sk, p, &cam, e.gbuf.depth_tex, 0, e.mask.color_tex) == SK_ERR_GL);
        CHECK_LOG(sk, "skgl_point_mask");
        e.gl.UseProgram(pprog);
        F.gl_error = 1;
        SK_CHECK(skgl_point_bind(sk, p, pprog, 0) == SK_ERR_GL);
        CHECK_LOG(sk, "skgl_point_bind");
        e.gl.UseProgram(0);
        faults_off();
        skgl_point_destroy(sk, p);
    }
done:
    faults_off();
    if (prog) gt_forward_destroy(&e, &fw);
    if (pprog) e.gl.DeleteProgram(pprog);
    skgl_shadow_destroy(sk, s);
    skgl_shadow_destroy(sk, f);
    skgl_shadow_destroy(sk, rm);
    SK_CHECK_MSG(skgl_gl_object_count(sk) == base, "faults: %d objects at the end (%d)", skgl_gl_object_count(sk),
                 base);
    SK_CHECK(e.gl.GetError() == 0);
    skgl_destroy(sk);
    gt_env_free(&e);
}

/* ======================================================================= */
/* the entry points the test needs beyond the testbed's table */
typedef struct ext_funcs {
    void (*GetUniformiv)(unsigned, int, int *);
    void (*GetUniformfv)(unsigned, int, float *);
    void (*DetachShader)(unsigned, unsigned);
    void (*GetAttachedShaders)(unsigned, int, int *, unsigned *);
    void (*FramebufferTexture2D)(unsigned, unsigned, unsigned, unsigned, int);
} ext_funcs;
static ext_funcs X;
static void ext_load(tb_gl_getproc_fn gp) {
    void *p;
    p = gp("glGetUniformiv"); PTR_TO_FN(p, X.GetUniformiv);
    p = gp("glGetUniformfv"); PTR_TO_FN(p, X.GetUniformfv);
    p = gp("glDetachShader"); PTR_TO_FN(p, X.DetachShader);
    p = gp("glGetAttachedShaders"); PTR_TO_FN(p, X.GetAttachedShaders);
    p = gp("glFramebufferTexture2D"); PTR_TO_FN(p, X.FramebufferTexture2D);
    SK_CHECK(X.GetUniformiv && X.GetUniformfv && X.DetachShader && X.GetAttachedShaders && X.FramebufferTexture2D);
}

/* a 2D texture of this format (R16F: 0x822D/RED/FLOAT; depth: 0x8CAC/DEPTH_COMPONENT/FLOAT) */
static unsigned make_tex(const tb_gl_funcs *gl, unsigned tex, int ifmt, unsigned fmt, int w, int h) {
    if (!tex) gl->GenTextures(1, &tex);
    gl->BindTexture(0x0DE1, tex);
    gl->TexImage2D(0x0DE1, 0, ifmt, w, h, 0, fmt, 0x1406, NULL);
    gl->TexParameteri(0x0DE1, 0x2801, 0x2600);   /* MIN_FILTER NEAREST */
    gl->TexParameteri(0x0DE1, 0x2800, 0x2600);
    gl->BindTexture(0x0DE1, 0);
    return tex;
}
#define R16F 0x822D
#define RED 0x1903

/* every texel of a colour texture set to v */
static void clear_tex(const tb_gl_funcs *gl, unsigned tex, float v) {
    unsigned fb = 0;
    gl->GenFramebuffers(1, &fb);
    gl->BindFramebuffer(0x8D40, fb);
    X.FramebufferTexture2D(0x8D40, 0x8CE0, 0x0DE1, tex, 0);
    gl->ClearColor(v, v, v, v);
    gl->Clear(0x4000);
    gl->BindFramebuffer(0x8D40, 0);
    gl->DeleteFramebuffers(1, &fb);
}

/* pixels of a w x h red texture inside [0, 1] (written by a mask) and equal to 5 (not written),
   in the rectangle x < rw, y < rh and outside it */
typedef struct split_count { int in_written, in_kept, out_written, out_kept; } split_count;
static split_count split(const gt_env *e, unsigned tex, int w, int h, int rw, int rh) {
    split_count c;
    float *v = (float *)malloc(sizeof(float) * (size_t)w * (size_t)h);
    int x, y;
    memset(&c, 0, sizeof c);
    if (!v || tb_gl_read_texture_red(&e->gl, tex, w, h, v) != 0) { free(v); return c; }
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            float t = v[y * w + x];
            int in = x < rw && y < rh, written = t >= 0.0f && t <= 1.0f, kept = t == 5.0f;
            if (in) { c.in_written += written; c.in_kept += kept; }
            else { c.out_written += written; c.out_kept += kept; }
        }
    free(v);
    return c;
}

static void test_textures(void) {
    gt_env e;
    skgl_context *sk, *dbg;
    skgl_shadow_desc d;
    skgl_shadow *s = NULL, *sd = NULL, *f = NULL;
    skgl_point_desc pd;
    skgl_point *p = NULL;
    skgl_scene sc;
    skgl_camera cam = view_a();
    unsigned t = 0, t2 = 0;
    split_count c;
    int base;
    if (env_init(&e) != 0) return;
    ext_load(tb_gl_context_getproc(e.ctx));
    sk = fault_context(0, 0, 0);
    dbg = fault_context(1, 0, 0);
    if (!sk || !dbg) { skgl_destroy(sk); skgl_destroy(dbg); gt_env_free(&e); return; }
    sc = gt_scene(&e);
    SK_CHECK(gt_gbuffer(&e, &cam) == 0);
    gt_warm_programs(sk);
    base = skgl_gl_object_count(sk);
    memset(&d, 0, sizeof d);
    d.resolution = RES;
    SK_CHECK(skgl_shadow_create(sk, &d, &s) == SK_OK);
    SK_CHECK(skgl_shadow_create(dbg, &d, &sd) == SK_OK);
    d.technique = SKGL_FERKO;
    SK_CHECK(skgl_shadow_create(sk, &d, &f) == SK_OK);
    memset(&pd, 0, sizeof pd);
    pd.resolution = 64;
    pd.range = 30;
    SK_CHECK(skgl_point_create(sk, &pd, &p) == SK_OK);
    if (!s || !sd || !f || !p) goto done;
    SK_CHECK(skgl_shadow_render(sk, s, &cam, &sc, light_dir()) == SK_OK);
    SK_CHECK(skgl_shadow_render(dbg, sd, &cam, &sc, light_dir()) == SK_OK);
    SK_CHECK(skgl_point_render(sk, p, &cam, &sc, gt_v3(0, 4, 0)) == SK_OK);
    /* a name with no level 0: refused (mask, point mask, analysis), then given storage */
    e.gl.GenTextures(1, &t);
    SK_CHECK(skgl_shadow_mask(sk, s, &cam, e.gbuf.depth_tex, 0, t) == SK_ERR_INVALID_ARG);
    CHECK_LOG(sk, "not a texture");   /* never bound: glIsTexture says no */
    CHECK_LOG(sk, "mask_tex");
    SK_CHECK(skgl_point_mask(sk, p, &cam, e.gbuf.depth_tex, 0, t) == SK_ERR_INVALID_ARG);
    CHECK_LOG(sk, "mask_tex");
    SK_CHECK(skgl_shadow_analyze(sk, f, &cam, &sc, light_dir(), t) == SK_ERR_INVALID_ARG);
    CHECK_LOG(sk, "depth_tex");
    make_tex(&e.gl, t, R16F, RED, W, H);
    clear_tex(&e.gl, t, 5.0f);
    SK_CHECK(skgl_shadow_mask(sk, s, &cam, e.gbuf.depth_tex, 0, t) == SK_OK);
    c = split(&e, t, W, H, W, H);
    SK_CHECK_MSG(c.in_written == W * H, "storage given: %d of %d pixels written", c.in_written, W * H);
    /* a depth texture as the mask: not colour-renderable; the same name as R16F then passes */
    t2 = make_tex(&e.gl, 0, 0x8CAC, 0x1902, W, H);
    SK_CHECK(skgl_shadow_mask(sk, s, &cam, e.gbuf.depth_tex, 0, t2) == SK_ERR_GL);
    CHECK_LOG(sk, "colour-renderable");
    SK_CHECK(skgl_point_mask(sk, p, &cam, e.gbuf.depth_tex, 0, t2) == SK_ERR_GL);
    CHECK_LOG(sk, "colour-renderable");
    make_tex(&e.gl, t2, R16F, RED, W, H);
    SK_CHECK(skgl_shadow_mask(sk, s, &cam, e.gbuf.depth_tex, 0, t2) == SK_OK);
    check_log_cleared(sk, "mask texture");
    /* sizes GL could not have: past 65536, a zero height (a name not seen before) */
    skgl_forget_texture(sk, t2);
    F.tex_w = 70000;
    SK_CHECK(skgl_shadow_mask(sk, s, &cam, e.gbuf.depth_tex, 0, t2) == SK_ERR_INVALID_ARG);
    CHECK_LOG(sk, "level 0");
    F.tex_w = 0; F.tex_h = 70000;
    SK_CHECK(skgl_shadow_mask(sk, s, &cam, e.gbuf.depth_tex, 0, t2) == SK_ERR_INVALID_ARG);
    F.tex_h = -1;
    SK_CHECK(skgl_shadow_mask(sk, s, &cam, e.gbuf.depth_tex, 0, t2) == SK_ERR_INVALID_ARG);
    CHECK_LOG(sk, "level 0");
    faults_off();
    SK_CHECK(skgl_shadow_mask(sk, s, &cam, e.gbuf.depth_tex, 0, t2) == SK_OK);
    /* without debug the size is remembered: the texture grown under its name
       is written in its old size only, until skgl_forget_texture */
    make_tex(&e.gl, t, R16F, RED, W / 2, H / 2);
    skgl_forget_texture(sk, t);
    SK_CHECK(skgl_shadow_mask(sk, s, &cam, e.gbuf.depth_tex, 0, t) == SK_OK);
    make_tex(&e.gl, t, R16F, RED, W, H);
    clear_tex(&e.gl, t, 5.0f);
    SK_CHECK(skgl_shadow_mask(sk, s, &cam, e.gbuf.depth_tex, 0, t) == SK_OK);
    c = split(&e, t, W, H, W / 2, H / 2);
    SK_CHECK_MSG(c.in_written == W * H / 4 && c.out_kept == W * H * 3 / 4,
                 "remembered size: %d written inside the old size, %d kept outside (%d, %d)", c.in_written,
                 c.out_kept, W * H / 4, W * H * 3 / 4);
    skgl_forget_texture(sk, t);
    clear_tex(&e.gl, t, 5.0f);
    SK_CHECK(skgl_shadow_mask(sk, s, &cam, e.gbuf.depth_tex, 0, t) == SK_OK);
    c = split(&e, t, W, H, W / 2, H / 2);
    SK_CHECK_MSG(c.in_written == W * H / 4 && c.out_written == W * H * 3 / 4,
                 "forgotten: %d written inside, %d outside", c.in_written, c.out_written);
    /* desc.debug refuses a height that changed under the same name */
    make_tex(&e.gl, t, R16F, RED, W, H / 2);
    SK_CHECK(skgl_shadow_mask(dbg, sd, &cam, e.gbuf.depth_tex, 0, t) == SK_OK);
    make_tex(&e.gl, t, R16F, RED, W, H);
    SK_CHECK(skgl_shadow_mask(dbg, sd, &cam, e.gbuf.depth_tex, 0, t) == SK_ERR_INVALID_ARG);
    CHECK_LOG(dbg, "skgl_forget_texture");
    skgl_forget_texture(dbg, t);
    SK_CHECK(skgl_shadow_mask(dbg, sd, &cam, e.gbuf.depth_tex, 0, t) == SK_OK);
    check_log_cleared(dbg, "debug size");
done:
    faults_off();
    skgl_shadow_destroy(sk, s);
    skgl_shadow_destroy(sk, f);
    skgl_point_destroy(sk, p);
    skgl_shadow_destroy(dbg, sd);
    SK_CHECK_MSG(skgl_gl_object_count(sk) == base, "textures: %d objects (%d)", skgl_gl_object_count(sk), base);
    skgl_forget_texture(sk, t);
    skgl_forget_texture(sk, t2);
    skgl_forget_texture(dbg, t);
    if (t) e.gl.DeleteTextures(1, &t);
    if (t2) e.gl.DeleteTextures(1, &t2);
    SK_CHECK(e.gl.GetError() == 0);
    skgl_destroy(sk);
    skgl_destroy(dbg);
    gt_env_free(&e);
}

/* ======================================================================= */
static int same_estimate(const sk_res_estimate *a, const sk_res_estimate *b) {
    return a->width == b->width && a->height == b->height && a->samples == b->samples &&
           a->bounds.x0 == b->bounds.x0 && a->bounds.x1 == b->bounds.x1 && a->bounds.y0 == b->bounds.y0 &&
           a->bounds.y1 == b->bounds.y1;
}
#define MAX_PAGES 4096
static int same_pages(const sk_page *a, int na, const sk_page *b, int nb) {
    int i;
    if (na != nb) return 0;
    for (i = 0; i < na; i++)
        if (a[i].level != b[i].level || a[i].px != b[i].px || a[i].py != b[i].py) return 0;
    return 1;
}

static unsigned make_tex(const tb_gl_funcs *gl, unsigned tex, int ifmt, unsigned fmt, int w, int h);
static void test_rings(void) {
    static sk_page pa[MAX_PAGES], pb[MAX_PAGES], got[MAX_PAGES];
    gt_env e;
    skgl_context *sk;
    skgl_shadow_desc d;
    skgl_shadow *ref = NULL, *s = NULL, *rref = NULL, *r = NULL;
    skgl_camera ca = view_a(), cb = view_b();
    sk_res_estimate est_a, est_b;
    int na, nb, n, k, objs;
    if (env_init(&e) != 0) return;
    sk = fault_context(0, 0, 0);
    if (!sk) { gt_env_free(&e); return; }
        memset(&d, 0, sizeof d);
    d.technique = SKGL_FERKO;
    d.resolution = 1024;
    d.sync_readback = 1;
    SK_CHECK(skgl_shadow_create(sk, &d, &ref) == SK_OK);
    d.technique = SKGL_RMSM;
    d.resolution = 4096;
    d.rmsm_page_size = 64;
    d.rmsm_pool_pages = 16;
    SK_CHECK(skgl_shadow_create(sk, &d, &rref) == SK_OK);
    if (!ref || !rref) goto done;
    /* the references: this frame's results of views B and A */
    SK_CHECK(gt_gbuffer(&e, &cb) == 0);
    SK_CHECK(frame(&e, sk, ref, &cb, NULL) == 0 && frame(&e, sk, rref, &cb, NULL) == 0);
    est_b = skgl_shadow_stats(ref)->estimate;
    nb = skgl_shadow_pages(rref, pb, MAX_PAGES);
    SK_CHECK(gt_gbuffer(&e, &ca) == 0);
    SK_CHECK(frame(&e, sk, ref, &ca, NULL) == 0 && frame(&e, sk, rref, &ca, NULL) == 0);
    est_a = skgl_shadow_stats(ref)->estimate;
    na = skgl_shadow_pages(rref, pa, MAX_PAGES);
    SK_CHECK_MSG(!same_estimate(&est_a, &est_b) && !same_pages(pa, na, pb, nb) && na > 1 && nb > 1,
                 "views A and B: %dx%d / %dx%d, %d / %d pages", est_a.width, est_a.height, est_b.width,
                 est_b.height, na, nb);
    /* glClientWaitSync answering CONDITION_SATISFIED: a landed fence all the same */
    F.wait_satisfied = 1;
    d.sync_readback = 0;
    d.technique = SKGL_FERKO; d.resolution = 1024;
    SK_CHECK(skgl_shadow_create(sk, &d, &s) == SK_OK);
    d.technique = SKGL_RMSM; d.resolution = 4096;
    SK_CHECK(skgl_shadow_create(sk, &d, &r) == SK_OK);
    if (!s || !r) goto done;
    SK_CHECK(frame(&e, sk, s, &ca, NULL) == 0 && frame(&e, sk, r, &ca, NULL) == 0);   /* frame 1: at once */
    SK_CHECK(same_estimate(&skgl_shadow_stats(s)->estimate, &est_a));
    SK_CHECK(gt_gbuffer(&e, &cb) == 0);
    for (k = 0; k < 2; k++) {
        e.gl.Finish();
        SK_CHECK(frame(&e, sk, s, &cb, NULL) == 0 && frame(&e, sk, r, &cb, NULL) == 0);
    }
    n = skgl_shadow_pages(r, got, MAX_PAGES);
    SK_CHECK_MSG(same_estimate(&skgl_shadow_stats(s)->estimate, &est_b), "CONDITION_SATISFIED: %dx%d, B's %dx%d",
                 skgl_shadow_stats(s)->estimate.width, skgl_shadow_stats(s)->estimate.height, est_b.width,
                 est_b.height);
    SK_CHECK_MSG(same_pages(got, n, pb, nb), "CONDITION_SATISFIED: %d pages, B's %d", n, nb);
    /* a smaller buffer: the count all the same, two written */
    got[2].level = -5;
    SK_CHECK(skgl_shadow_pages(r, got, 2) == nb && same_pages(got, 2, pb, 2) && got[2].level == -5);
    /* the analysis of a depth texture of another height: its targets made again */
    {
        unsigned half = make_tex(&e.gl, 0, 0x8CAC, 0x1902, W, H / 2);
        skgl_scene sc = gt_scene(&e);
        SK_CHECK(skgl_shadow_analyze(sk, r, &cb, &sc, light_dir(), half) == SK_OK);
        SK_CHECK(skgl_shadow_analyze(sk, s, &cb, &sc, light_dir(), half) == SK_OK);
        SK_CHECK(skgl_shadow_render(sk, r, &cb, &sc, light_dir()) == SK_OK && skgl_shadow_stats(r)->pages_rendered >= 1);
        skgl_forget_texture(sk, half);
        e.gl.DeleteTextures(1, &half);
    }
    skgl_shadow_destroy(sk, s);
    skgl_shadow_destroy(sk, r);
    s = r = NULL;
    /* no fence made: nothing ever lands, the first frame's result stays */
    faults_off();
    F.no_fence = 1;
    d.technique = SKGL_FERKO; d.resolution = 1024;
    SK_CHECK(skgl_shadow_create(sk, &d, &s) == SK_OK);
    d.technique = SKGL_RMSM; d.resolution = 4096;
    SK_CHECK(skgl_shadow_create(sk, &d, &r) == SK_OK);
    if (!s || !r) goto done;
    SK_CHECK(gt_gbuffer(&e, &ca) == 0);
    SK_CHECK(frame(&e, sk, s, &ca, NULL) == 0 && frame(&e, sk, r, &ca, NULL) == 0);
    objs = skgl_gl_object_count(sk);
    SK_CHECK(gt_gbuffer(&e, &cb) == 0);
    F.fences = 0;
    for (k = 0; k < 4; k++) {
        e.gl.Finish();
        SK_CHECK(frame(&e, sk, s, &cb, NULL) == 0 && frame(&e, sk, r, &cb, NULL) == 0);
    }
    n = skgl_shadow_pages(r, got, MAX_PAGES);
    SK_CHECK_MSG(F.fences == 8 && skgl_gl_object_count(sk) == objs, "no fences: %ld asked for, %d objects (%d)",
                 F.fences, skgl_gl_object_count(sk), objs);
    SK_CHECK(same_estimate(&skgl_shadow_stats(s)->estimate, &est_a));
    SK_CHECK_MSG(same_pages(got, n, pa, na), "no fences: %d pages, A's %d", n, na);
done:
    faults_off();
    skgl_shadow_destroy(sk, s);
    skgl_shadow_destroy(sk, r);
    skgl_shadow_destroy(sk, ref);
    skgl_shadow_destroy(sk, rref);
    SK_CHECK(e.gl.GetError() == 0);
    skgl_destroy(sk);
    gt_env_free(&e);
}

/* ======================================================================= */
static const char dead_fs[] = "out float o_visibility;\nvoid main() { o_visibility = 1.0; }\n";
static const char extra_fs[] =
    "in vec3 v_world;\nin vec3 v_normal;\nin float v_view_depth;\nout float o_visibility;\n"
    "uniform float u_extra;\n"
    "void main() { o_visibility = sk_shadow(v_world, normalize(v_normal), v_view_depth) * u_extra; }\n";
static const char point_fs[] =
    "in vec3 v_world;\nin vec3 v_normal;\nout float o_visibility;\n"
    "void main() { o_visibility = sk_point_shadow(v_world, normalize(v_normal)); }\n";

/* (re)links program prog (0: a new one) from the forward vertex shader and
   "#version", a snippet, body; the program's name is kept */
static unsigned link_program(gt_env *e, unsigned prog, const char *snippet, const char *body) {
    const tb_gl_funcs *gl = &e->gl;
    const char *vs[1], *fs[3];
    unsigned v, g, att[4];
    int ok = 0, na = 0, i;
    vs[0] = gt_forward_vs;
    fs[0] = "#version 330 core\n";
    fs[1] = snippet;
    fs[2] = body;
    v = gt_compile(gl, 0x8B31, 1, vs);
    g = gt_compile(gl, 0x8B30, 3, fs);
    if (!v || !g) return 0;
    if (!prog) prog = gl->CreateProgram();
    X.GetAttachedShaders(prog, 4, &na, att);
    for (i = 0; i < na; i++) X.DetachShader(prog, att[i]);
    gl->AttachShader(prog, v);
    gl->AttachShader(prog, g);
    gl->LinkProgram(prog);
    gl->DeleteShader(v);
    gl->DeleteShader(g);
    gl->GetProgramiv(prog, 0x8B82, &ok);
    SK_CHECK_MSG(ok, "link");
    return prog;
}

static int uniform_i(gt_env *e, unsigned prog, const char *name) {
    int v = -7, loc = e->gl.GetUniformLocation(prog, name);
    if (loc >= 0) X.GetUniformiv(prog, loc, &v);
    return v;
}
static float uniform_f(gt_env *e, unsigned prog, const char *name) {
    float v = -7.0f;
    int loc = e->gl.GetUniformLocation(prog, name);
    if (loc >= 0) X.GetUniformfv(prog, loc, &v);
    return v;
}

static void test_program_cache(void) {
    gt_env e;
    skgl_context *sk, *dbg;
    skgl_shadow_desc d;
    skgl_shadow *s = NULL, *sd = NULL;
    skgl_point_desc pd;
    skgl_point *p = NULL;
    skgl_scene sc;
    skgl_camera cam = view_a();
    unsigned dead = 0, prog = 0, pprog = 0;
    int nu = -1, active = 0;
    char point_snippet[16384];
    if (env_init(&e) != 0) return;
    ext_load(tb_gl_context_getproc(e.ctx));
    sk = fault_context(0, 0, 0);
    dbg = fault_context(1, 0, 0);
    if (!sk || !dbg) { skgl_destroy(sk); skgl_destroy(dbg); gt_env_free(&e); return; }
    sc = gt_scene(&e);
    memset(&d, 0, sizeof d);
    d.resolution = RES;
    d.pcf_radius = 3;
    SK_CHECK(skgl_shadow_create(sk, &d, &s) == SK_OK);
    SK_CHECK(skgl_shadow_create(dbg, &d, &sd) == SK_OK);
    memset(&pd, 0, sizeof pd);
    pd.resolution = 64;
    pd.range = 30;
    SK_CHECK(skgl_point_create(sk, &pd, &p) == SK_OK);
    if (!s || !sd || !p) goto done;
    SK_CHECK(skgl_shadow_render(sk, s, &cam, &sc, light_dir()) == SK_OK);
    SK_CHECK(skgl_shadow_render(dbg, sd, &cam, &sc, light_dir()) == SK_OK);
    SK_CHECK(skgl_point_render(sk, p, &cam, &sc, gt_v3(0, 4, 0)) == SK_OK);
    /* the snippet declared, never called: no active uniform, nothing sent */
    dead = link_program(&e, 0, skgl_glsl_snippet(), dead_fs);
    e.gl.GetProgramiv(dead, 0x8B86 /* ACTIVE_UNIFORMS */, &nu);
    SK_CHECK_MSG(nu == 1 && e.gl.GetUniformLocation(dead, "sk_shadow_map") < 0 &&
                     e.gl.GetUniformLocation(dead, "sk_rmsm_page") < 0,
                 "dead program: %d active uniforms (u_view_proj only)", nu);
    e.gl.UseProgram(dead);
    SK_CHECK(skgl_shadow_bind(sk, s, dead, 0) == SK_OK);
    SK_CHECK(skgl_shadow_bind(sk, s, dead, 0) == SK_OK);
    /* desc.debug refuses it: its map sampler is not active, as in a program
       without the snippet (ERRORS AND MISUSE) */
    SK_CHECK(skgl_shadow_bind(dbg, sd, dead, 0) == SK_ERR_INVALID_ARG);
    CHECK_LOG(dbg, "no active uniform sk_shadow_map");
    SK_CHECK(e.gl.GetError() == 0);
    /* relinked with one more active uniform, same name: the default mode's count check */
    prog = link_program(&e, 0, skgl_glsl_snippet(), gt_forward_fs);
    e.gl.UseProgram(prog);
    SK_CHECK(skgl_shadow_bind(sk, s, prog, 2) == SK_OK);
    SK_CHECK(uniform_i(&e, prog, "sk_pcf_radius") == 3 && uniform_i(&e, prog, "sk_shadow_map") == 2);
    SK_CHECK(link_program(&e, prog, skgl_glsl_snippet(), extra_fs) == prog);
    e.gl.UseProgram(prog);
    SK_CHECK(uniform_i(&e, prog, "sk_pcf_radius") == 0);
    SK_CHECK(skgl_shadow_bind(sk, s, prog, 2) == SK_OK);
    SK_CHECK_MSG(uniform_i(&e, prog, "sk_pcf_radius") == 3 && uniform_i(&e, prog, "sk_shadow_map") == 2,
                 "relinked, one more uniform: radius %d, unit %d", uniform_i(&e, prog, "sk_pcf_radius"),
                 uniform_i(&e, prog, "sk_shadow_map"));
    /* the same light on another unit: the units sent again */
    SK_CHECK(skgl_shadow_bind(sk, s, prog, 5) == SK_OK && uniform_i(&e, prog, "sk_shadow_map") == 5);
    /* desc.debug: relinked without the call (every location gone), then back */
    SK_CHECK(skgl_shadow_bind(dbg, sd, prog, 1) == SK_OK && uniform_i(&e, prog, "sk_shadow_map") == 1);
    SK_CHECK(link_program(&e, prog, skgl_glsl_snippet(), dead_fs) == prog);
    e.gl.UseProgram(prog);
    SK_CHECK(skgl_shadow_bind(dbg, sd, prog, 1) == SK_ERR_INVALID_ARG);   /* no active sk_shadow_map */
    SK_CHECK(link_program(&e, prog, skgl_glsl_snippet(), gt_forward_fs) == prog);
    e.gl.UseProgram(prog);
    SK_CHECK(skgl_shadow_bind(dbg, sd, prog, 1) == SK_OK);
    SK_CHECK_MSG(uniform_i(&e, prog, "sk_pcf_radius") == 3 && uniform_i(&e, prog, "sk_shadow_map") == 1,
                 "debug, relinked twice: radius %d, unit %d", uniform_i(&e, prog, "sk_pcf_radius"),
                 uniform_i(&e, prog, "sk_shadow_map"));
    /* a point program bound twice (the sentinel read), relinked (range back at 0) */
    snprintf(point_snippet, sizeof point_snippet, "#define SK_POINT_VSDCT 0\n%s", skgl_point_glsl_snippet());
    pprog = link_program(&e, 0, point_snippet, point_fs);
    e.gl.UseProgram(pprog);
    e.gl.ActiveTexture(0x84C0 + 4);
    SK_CHECK(skgl_point_bind(sk, p, pprog, 4) == SK_OK);
    e.gl.GetIntegerv(0x84E0 /* ACTIVE_TEXTURE */, &active);
    SK_CHECK_MSG(active == 0x84C0 + 4, "point bind on the active unit: 0x%x active after", (unsigned)active);
    SK_CHECK(skgl_point_bind(sk, p, pprog, 4) == SK_OK && uniform_f(&e, pprog, "sk_point_range") == 30.0f);
    SK_CHECK(link_program(&e, pprog, point_snippet, point_fs) == pprog);
    e.gl.UseProgram(pprog);
    SK_CHECK(uniform_f(&e, pprog, "sk_point_range") == 0.0f);
    SK_CHECK(skgl_point_bind(sk, p, pprog, 4) == SK_OK);
    SK_CHECK_MSG(uniform_f(&e, pprog, "sk_point_range") == 30.0f && uniform_i(&e, pprog, "sk_point_cube") == 4,
                 "point program relinked: range %g, unit %d", uniform_f(&e, pprog, "sk_point_range"),
                 uniform_i(&e, pprog, "sk_point_cube"));
    SK_CHECK(skgl_point_bind(sk, p, pprog, 6) == SK_OK && uniform_i(&e, pprog, "sk_point_cube") == 6);
    e.gl.ActiveTexture(0x84C0);
    e.gl.UseProgram(0);
    skgl_forget_program(sk, pprog);
    skgl_forget_program(sk, prog);
    skgl_forget_program(dbg, prog);
    SK_CHECK(e.gl.GetError() == 0);
done:
    if (dead) e.gl.DeleteProgram(dead);
    if (prog) e.gl.DeleteProgram(prog);
    if (pprog) e.gl.DeleteProgram(pprog);
    skgl_shadow_destroy(sk, s);
    skgl_point_destroy(sk, p);
    skgl_shadow_destroy(dbg, sd);
    skgl_destroy(sk);
    skgl_destroy(dbg);
    gt_env_free(&e);
}

/* ======================================================================= */
static void point_rule(skgl_point_desc *d, int which) {
    switch (which) {
    case 0: d->technique = (skgl_point_technique)2; break;
    case 1: d->resolution = -1; break;
    case 2: d->near_plane = -1; break;
    case 3: d->near_plane = NAN; break;
    case 4: d->range = 0.01f; break;
    case 5: d->slope_bias = NAN; break;
    case 6: d->depth_bias = INFINITY; break;
    case 7: d->normal_bias = NAN; break;
    case 8: d->bias = (skgl_bias)3; break;
    case 9: d->bias = (skgl_bias)-1; break;
    case 10: d->plane_bias = 65; break;
    case 11: d->pcf_radius = 9; break;
    case 12: d->pcf_radius = -1; break;
    case 13: d->resolution_c = -1; break;
    case 14: d->resolution_c = NAN; break;
    case 15: d->screen_w = -1; break;
    case 16: d->screen_h = -1; break;
    case 17: d->vsdct_grey_levels = -1; break;
    case 18: d->select_resolution = 1; d->resolution = 300; break;
    case 19: d->resolution = 1 << 20; break;
    case 20: d->technique = SKGL_POINT_VSDCT; d->resolution = 1 << 20; break;
    default: break;
    }
}

/* the point pass callback: the mesh, and caster_visible asked for a box in
   view, one far away and an empty one */
static struct { int calls, far_visible, empty_visible, near_visible; } PC;
static void point_draw(void *user, const skgl_draw_info *info) {
    gt_env *e = (gt_env *)user;
    PC.calls++;
    PC.near_visible += skgl_point_caster_visible(info, gt_box(-1, 0, -1, 1, 2, 1));
    PC.far_visible += skgl_point_caster_visible(info, gt_box(500, 500, 500, 501, 501, 501));
    PC.empty_visible += skgl_point_caster_visible(info, gt_box(1, 1, 1, -1, -1, -1));
    tb_gl_mesh_draw(&e->gl, &e->mesh, 0, 0);
}

static void test_point_paths(void) {
    static const char *const fields[] = {
        "technique", "resolution", "near_plane", "near_plane", "range", "slope_bias", "depth_bias", "normal_bias",
        "bias", "bias", "plane_bias", "pcf_radius", "pcf_radius", "resolution_c", "resolution_c", "screen_w",
        "screen_h", "vsdct_grey_levels", "resolution", "resolution", "resolution"};
    gt_env e;
    skgl_context *sk;
    skgl_point_desc pd, g;
    skgl_point *p;
    skgl_scene sc;
    skgl_camera cam = view_a(), bad = view_a(), sing = view_a(), badp = view_a();
    skgl_draw_info info;
    float *mask;
    int k, base, mode;
    if (env_init(&e) != 0) return;
    mask = gt_alloc(&e);
    SK_CHECK(gt_gbuffer(&e, &cam) == 0);
    sk = fault_context(0, 0, 0);
    if (!sk || !mask) { skgl_destroy(sk); free(mask); gt_env_free(&e); return; }
    sc = gt_scene(&e);
    sc.draw = point_draw;
    base = skgl_gl_object_count(sk);
    for (k = 0; k < (int)(sizeof fields / sizeof fields[0]); k++) {
        sk_result r;
        memset(&pd, 0, sizeof pd);
        point_rule(&pd, k);
        p = (skgl_point *)&pd;
        r = skgl_point_create(sk, &pd, &p);
        SK_CHECK_MSG(r == SK_ERR_INVALID_ARG && p == NULL, "point rule %d (%s): %s", k, fields[k],
                     sk_result_string(r));
        CHECK_LOG(sk, fields[k]);
        SK_CHECK(skgl_gl_object_count(sk) == base);
        if (r == SK_OK) skgl_point_destroy(sk, p);
    }
    check_log_cleared(sk, "point rules");
    memset(&pd, 0, sizeof pd);
    p = (skgl_point *)&pd;
    SK_CHECK(skgl_point_create(NULL, &pd, &p) == SK_ERR_INVALID_ARG && p == NULL);
    SK_CHECK(skgl_point_create(sk, NULL, &p) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_point_create(sk, &pd, NULL) == SK_ERR_INVALID_ARG);
    /* caster_visible outside a point pass */
    memset(&info, 0, sizeof info);
    SK_CHECK(skgl_point_caster_visible(NULL, gt_box(0, 0, 0, 1, 1, 1)) == 1);
    info.kind = SKGL_PASS_DIRECTIONAL;
    SK_CHECK(skgl_point_caster_visible(&info, gt_box(500, 500, 500, 501, 501, 501)) == 1);
    info.kind = SKGL_PASS_CUBE_FACE;
    SK_CHECK(skgl_point_caster_visible(&info, gt_box(500, 500, 500, 501, 501, 501)) == 1);
    /* the NULL accessors */
    g = skgl_point_get_desc(NULL);
    SK_CHECK(g.resolution == 0 && skgl_point_stats(NULL) == NULL && skgl_point_texture(NULL) == 0);
    SK_CHECK(skgl_point_layout(NULL).face_res == 0);
    skgl_point_destroy(sk, NULL);
    skgl_point_destroy(NULL, NULL);
    /* every switch, CUBE and VSDCT, both modes; the resolution selection from
       the screen given and from the viewport */
    bad.view.m[5] = NAN;
    badp.proj.m[5] = NAN;
    memset(&sing.proj, 0, sizeof sing.proj);
    sing.proj.m[11] = -1.0f;
    for (mode = 0; mode < 4; mode++) {
        skgl_context *c = mode < 2 ? sk : fault_context(0, 1, 1);
        int tech;
        if (!c) continue;
        for (tech = 0; tech < 2; tech++) {
            const skgl_point_frame_stats *st;
            int lit, dark, cb = skgl_gl_object_count(c);
            p = NULL;
            memset(&pd, 0, sizeof pd);
            pd.technique = tech ? SKGL_POINT_VSDCT : SKGL_POINT_CUBE;
            pd.resolution = 128;
            pd.range = 30;
            pd.cull_faces = pd.cull_casters = pd.scissor = pd.select_resolution = 1;
            pd.disable_plane_bias = 1; pd.slope_bias = 1e-6f; pd.depth_bias = 3;
            if (mode & 1) { pd.screen_w = W; pd.screen_h = H; }
            SK_CHECK(skgl_point_create(c, &pd, &p) == SK_OK);
            if (!p) continue;
            /* before any render: bind and mask refused */
            SK_CHECK(skgl_point_bind(c, p, e.gb.program, 0) == SK_ERR_INVALID_ARG);
            SK_CHECK(skgl_point_mask(c, p, &cam, e.gbuf.depth_tex, 0, e.mask.color_tex) == SK_ERR_INVALID_ARG);
            e.gl.Viewport(0, 0, W, H);
            memset(&PC, 0, sizeof PC);
            SK_CHECK(skgl_point_render(c, p, &cam, &sc, gt_v3(0, 4, 0)) == SK_OK);
            st = skgl_point_stats(p);
            SK_CHECK_MSG(PC.calls == st->faces_rendered && st->faces_rendered + st->faces_culled == 6 &&
                             st->faces_rendered >= 1 && PC.far_visible == 0 && PC.near_visible >= 1 &&
                             st->casters_culled >= PC.calls && st->resolution <= 128 && st->resolution >= 1,
                         "tech %d mode %d: %d calls, %d faces (+%d culled), near %d far %d empty %d, drawn %d culled %d, "
                         "side %d", tech, mode, PC.calls, st->faces_rendered, st->faces_culled, PC.near_visible,
                         PC.far_visible, PC.empty_visible, st->casters_drawn, st->casters_culled, st->resolution);
            SK_CHECK(skgl_point_mask(c, p, &cam, e.gbuf.depth_tex, e.gbuf.color_tex, e.mask.color_tex) == SK_OK);
            SK_CHECK(tb_gl_read_texture_red(&e.gl, e.mask.color_tex, W, H, mask) == 0);
            {
                size_t i;
                for (i = 0; i < e.n; i++) if (!(e.depth[i] < 1.0f)) mask[i] = -1.0f;
            }
            count_mask(&e, mask, &lit, &dark);
            SK_CHECK_MSG(lit > 1000 && dark > 50 && st->scissor[2] > 0 && st->scissor[3] > 0,
                         "tech %d mode %d: %d lit, %d shadowed, scissor %d x %d", tech, mode, lit, dark,
                         st->scissor[2], st->scissor[3]);
            /* bad arguments of the calls */
            SK_CHECK(skgl_point_render(NULL, p, &cam, &sc, gt_v3(0, 4, 0)) == SK_ERR_INVALID_ARG);
            SK_CHECK(skgl_point_render(c, NULL, &cam, &sc, gt_v3(0, 4, 0)) == SK_ERR_INVALID_ARG);
            SK_CHECK(skgl_point_render(c, p, NULL, &sc, gt_v3(0, 4, 0)) == SK_ERR_INVALID_ARG);
            SK_CHECK(skgl_point_render(c, p, &cam, NULL, gt_v3(0, 4, 0)) == SK_ERR_INVALID_ARG);
            SK_CHECK(skgl_point_render(c, p, &cam, &sc, gt_v3(0, NAN, 0)) == SK_ERR_INVALID_ARG);
            SK_CHECK(skgl_point_render(c, p, &bad, &sc, gt_v3(0, 4, 0)) == SK_ERR_INVALID_ARG);
            SK_CHECK(skgl_point_render(c, p, &badp, &sc, gt_v3(0, 4, 0)) == SK_ERR_INVALID_ARG);
            SK_CHECK(skgl_point_mask(c, p, &badp, e.gbuf.depth_tex, 0, e.mask.color_tex) == SK_ERR_INVALID_ARG);
            SK_CHECK(skgl_point_mask(NULL, p, &cam, e.gbuf.depth_tex, 0, e.mask.color_tex) == SK_ERR_INVALID_ARG);
            SK_CHECK(skgl_point_mask(c, NULL, &cam, e.gbuf.depth_tex, 0, e.mask.color_tex) == SK_ERR_INVALID_ARG);
            SK_CHECK(skgl_point_mask(c, p, NULL, e.gbuf.depth_tex, 0, e.mask.color_tex) == SK_ERR_INVALID_ARG);
            SK_CHECK(skgl_point_mask(c, p, &cam, 0, 0, e.mask.color_tex) == SK_ERR_INVALID_ARG);
            SK_CHECK(skgl_point_mask(c, p, &cam, e.gbuf.depth_tex, 0, 0) == SK_ERR_INVALID_ARG);
            SK_CHECK(skgl_point_mask(c, p, &bad, e.gbuf.depth_tex, 0, e.mask.color_tex) == SK_ERR_INVALID_ARG);
            SK_CHECK(skgl_point_mask(c, p, &sing, e.gbuf.depth_tex, 0, e.mask.color_tex) == SK_ERR_INVALID_ARG);
            SK_CHECK(skgl_point_bind(NULL, p, e.gb.program, 0) == SK_ERR_INVALID_ARG);
            SK_CHECK(skgl_point_bind(c, NULL, e.gb.program, 0) == SK_ERR_INVALID_ARG);
            SK_CHECK(skgl_point_bind(c, p, 0, 0) == SK_ERR_INVALID_ARG);
            SK_CHECK(skgl_point_bind(c, p, e.gb.program, -1) == SK_ERR_INVALID_ARG);
            SK_CHECK(skgl_point_bind(c, p, e.gb.program, 31) == SK_ERR_INVALID_ARG);
            /* the light's range box off screen: the scissored mask draws nothing */
            clear_tex(&e.gl, e.mask.color_tex, 5.0f);
            SK_CHECK(skgl_point_render(c, p, &cam, &sc, gt_v3(-300, 4, 300)) == SK_OK);
            SK_CHECK(skgl_point_mask(c, p, &cam, e.gbuf.depth_tex, 0, e.mask.color_tex) == SK_OK);
            {
                split_count sp = split(&e, e.mask.color_tex, W, H, W, H);
                SK_CHECK_MSG(sp.in_kept == W * H && st->scissor[0] == 0 && st->scissor[2] == 0 &&
                                 st->mask_ms == (mode >= 2 ? 0.0f : -1.0f),
                             "off screen: %d of %d pixels kept, scissor %d %d %d %d, mask %g ms", sp.in_kept, W * H,
                             st->scissor[0], st->scissor[1], st->scissor[2], st->scissor[3], st->mask_ms);
            }
            SK_CHECK(skgl_point_texture(p) != 0 && skgl_point_get_desc(p).resolution == 128);
            skgl_point_destroy(c, p);
            SK_CHECK_MSG(skgl_gl_object_count(c) == cb, "tech %d mode %d: %d objects (%d)", tech, mode,
                         skgl_gl_object_count(c), cb);
        }
        SK_CHECK(e.gl.GetError() == 0);
        if (c != sk) skgl_destroy(c);
    }
    /* the screen half given (the viewport then), a viewport of no height, the
       light behind the camera: no pixels, the smallest side; polygon offset
       units only */
    memset(&pd, 0, sizeof pd);
    pd.resolution = 128;
    pd.range = 10;
    pd.select_resolution = 1;
    pd.screen_w = W;
    pd.disable_polygon_offset = 1;
    p = NULL;
    SK_CHECK(skgl_point_create(sk, &pd, &p) == SK_OK);
    if (p) {
        int full;
        e.gl.Viewport(0, 0, W, H);
        SK_CHECK(skgl_point_render(sk, p, &cam, &sc, gt_v3(0, 4, 0)) == SK_OK);
        full = skgl_point_stats(p)->resolution;
        e.gl.Viewport(0, 0, W, 0);
        SK_CHECK(skgl_point_render(sk, p, &cam, &sc, gt_v3(0, 4, 0)) == SK_OK);
        SK_CHECK_MSG(skgl_point_stats(p)->resolution < full, "no viewport height: side %d (%d)",
                     skgl_point_stats(p)->resolution, full);
        e.gl.Viewport(0, 0, W, H);
        SK_CHECK(skgl_point_render(sk, p, &cam, &sc, gt_v3(-40, 20, 50)) == SK_OK);
        SK_CHECK_MSG(skgl_point_stats(p)->resolution < full, "light behind the camera: side %d (%d)",
                     skgl_point_stats(p)->resolution, full);
        skgl_point_destroy(sk, p);
    }
    /* selection from an empty viewport (no pixels: the smallest side) and a cube
       level change whose framebuffers fail */
    memset(&pd, 0, sizeof pd);
    pd.resolution = 128;
    pd.range = 30;
    pd.select_resolution = 1;
    p = NULL;
    SK_CHECK(skgl_point_create(sk, &pd, &p) == SK_OK);
    if (p) {
        e.gl.Viewport(0, 0, 0, 0);
        SK_CHECK(skgl_point_render(sk, p, &cam, &sc, gt_v3(0, 4, 0)) == SK_OK);
        SK_CHECK_MSG(skgl_point_stats(p)->resolution < 128, "empty viewport: side %d",
                     skgl_point_stats(p)->resolution);
        e.gl.Viewport(0, 0, W, H);
        SK_CHECK(skgl_point_render(sk, p, &cam, &sc, gt_v3(0, 4, 0)) == SK_OK);
        SK_CHECK(skgl_point_stats(p)->resolution == 128);
        e.gl.Viewport(0, 0, 0, 0);
        F.fb_fail = 1;
        SK_CHECK(skgl_point_render(sk, p, &cam, &sc, gt_v3(0, 4, 0)) == SK_ERR_GL);
        CHECK_LOG(sk, "framebuffer");
        faults_off();
        SK_CHECK(skgl_point_render(sk, p, &cam, &sc, gt_v3(0, 4, 0)) == SK_OK);
        e.gl.Viewport(0, 0, W, H);
        skgl_point_destroy(sk, p);
    }
    SK_CHECK(skgl_gl_object_count(sk) == base);
    SK_CHECK(e.gl.GetError() == 0);
    free(mask);
    skgl_destroy(sk);
    gt_env_free(&e);
}

/* ======================================================================= */
static void test_atlas(void) {
    gt_env e;
    skgl_context *sk;
    skgl_point_atlas *a = NULL, *tiny = NULL, *other = NULL;
    skgl_point_desc pd;
    skgl_point *l[3] = {NULL, NULL, NULL}, *own = NULL, *t = NULL;
    skgl_scene sc;
    skgl_camera cam = view_a(), bad = view_a();
    sk_vec3 pos[3];
    int base, w = -1, h = -1, k;
    if (env_init(&e) != 0) return;
    SK_CHECK(gt_gbuffer(&e, &cam) == 0);
    sk = fault_context(0, 0, 0);
    if (!sk) { gt_env_free(&e); return; }
    sc = gt_scene(&e);
    base = skgl_gl_object_count(sk);
    pos[0] = gt_v3(0, 4, 0); pos[1] = gt_v3(3, 3, 3); pos[2] = gt_v3(-3, 3, 2);
    /* create: arguments */
    a = (skgl_point_atlas *)&pd;
    SK_CHECK(skgl_point_atlas_create(NULL, 64, 64, &a) == SK_ERR_INVALID_ARG && a == NULL);
    SK_CHECK(skgl_point_atlas_create(sk, 64, 64, NULL) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_point_atlas_create(sk, 0, 64, &a) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_point_atlas_create(sk, 64, 0, &a) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_point_atlas_create(sk, 1 << 20, 64, &a) == SK_ERR_INVALID_ARG);
    CHECK_LOG(sk, "width");
    SK_CHECK(skgl_point_atlas_create(sk, 64, 1 << 20, &a) == SK_ERR_INVALID_ARG);
    CHECK_LOG(sk, "height");
    SK_CHECK(skgl_gl_object_count(sk) == base);
    check_log_cleared(sk, "atlas create");
    skgl_point_atlas_size(NULL, &w, &h);
    SK_CHECK(w == 0 && h == 0 && skgl_point_atlas_texture(NULL) == 0);
    skgl_point_atlas_size(NULL, NULL, NULL);
    skgl_point_atlas_destroy(sk, NULL);
    skgl_point_atlas_destroy(NULL, NULL);
    SK_CHECK(skgl_point_atlas_create(sk, 384, 256, &a) == SK_OK && a);
    SK_CHECK(skgl_point_atlas_create(sk, 5, 1, &tiny) == SK_OK && tiny);
    SK_CHECK(skgl_point_atlas_create(sk, 64, 64, &other) == SK_OK && other);
    if (!a || !tiny || !other) goto done;
    skgl_point_atlas_size(a, &w, &h);
    SK_CHECK(w == 384 && h == 256 && skgl_point_atlas_texture(a) != 0);
    skgl_point_atlas_size(a, NULL, NULL);
    /* a CUBE light given an atlas */
    memset(&pd, 0, sizeof pd);
    pd.resolution = 64;
    pd.range = 30;
    pd.atlas = a;
    SK_CHECK(skgl_point_create(sk, &pd, &t) == SK_ERR_INVALID_ARG && t == NULL);
    CHECK_LOG(sk, "atlas");
    /* three lights in the atlas (the third selects its side from the viewport) */
    pd.technique = SKGL_POINT_VSDCT;
    for (k = 0; k < 3; k++) {
        /* 0 and 2 select their side for the viewport (read once), 1 for the screen given */
        pd.select_resolution = 1;
        pd.screen_w = k == 1 ? W : 0;
        pd.screen_h = k == 1 ? H : 0;
        SK_CHECK(skgl_point_create(sk, &pd, &l[k]) == SK_OK);
    }
    pd.select_resolution = 0;
    pd.screen_w = pd.screen_h = 0;
    pd.atlas = NULL;
    SK_CHECK(skgl_point_create(sk, &pd, &own) == SK_OK);
    pd.atlas = tiny;
    SK_CHECK(skgl_point_create(sk, &pd, &t) == SK_OK);
    if (!l[0] || !l[1] || !l[2] || !own || !t) goto done;
    /* rendered before any pack */
    SK_CHECK(skgl_point_render(sk, l[0], &cam, &sc, pos[0]) == SK_ERR_INVALID_ARG);
    CHECK_LOG(sk, "skgl_point_atlas_pack");
    /* pack: arguments */
    bad.proj.m[0] = NAN;
    SK_CHECK(skgl_point_atlas_pack(NULL, a, l, 3, &cam, pos) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_point_atlas_pack(sk, NULL, l, 3, &cam, pos) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_point_atlas_pack(sk, a, NULL, 3, &cam, pos) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_point_atlas_pack(sk, a, l, 0, &cam, pos) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_point_atlas_pack(sk, a, l, 3, NULL, pos) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_point_atlas_pack(sk, a, l, 3, &cam, NULL) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_point_atlas_pack(sk, a, l, 3, &bad, pos) == SK_ERR_INVALID_ARG);
    bad.proj.m[0] = 1; bad.view.m[0] = NAN;
    SK_CHECK(skgl_point_atlas_pack(sk, a, l, 3, &bad, pos) == SK_ERR_INVALID_ARG);
    {
        skgl_point *mixed[3];
        sk_vec3 npos[3];
        mixed[0] = l[0]; mixed[1] = NULL; mixed[2] = l[2];
        SK_CHECK(skgl_point_atlas_pack(sk, a, mixed, 3, &cam, pos) == SK_ERR_INVALID_ARG);
        mixed[1] = own;
        SK_CHECK(skgl_point_atlas_pack(sk, a, mixed, 3, &cam, pos) == SK_ERR_INVALID_ARG);
        mixed[1] = l[1];
        SK_CHECK(skgl_point_atlas_pack(sk, other, mixed, 3, &cam, pos) == SK_ERR_INVALID_ARG);
        npos[0] = pos[0]; npos[1] = gt_v3(INFINITY, 0, 0); npos[2] = pos[2];
        SK_CHECK(skgl_point_atlas_pack(sk, a, mixed, 3, &cam, npos) == SK_ERR_INVALID_ARG);
    }
    SK_CHECK(skgl_point_render(sk, l[1], &cam, &sc, pos[1]) == SK_ERR_INVALID_ARG);
    /* packed: 18 faces of 64 do not fit in 384 x 256 (6 x 4 = 24 do: they fit) */
    e.gl.Viewport(0, 0, W, H);
    SK_CHECK(skgl_point_atlas_pack(sk, a, l, 3, &cam, pos) == SK_OK);
    for (k = 0; k < 3; k++) {
        sk_vsdct_layout lay = skgl_point_layout(l[k]);
        SK_CHECK_MSG(lay.face_res >= 1 && lay.face_res <= 64 && skgl_point_stats(l[k])->atlas_wanted >= lay.face_res,
                     "light %d: side %d, wanted %d", k, lay.face_res, skgl_point_stats(l[k])->atlas_wanted);
        SK_CHECK(skgl_point_render(sk, l[k], &cam, &sc, pos[k]) == SK_OK);
        SK_CHECK(skgl_point_mask(sk, l[k], &cam, e.gbuf.depth_tex, e.gbuf.color_tex, e.mask.color_tex) == SK_OK);
        SK_CHECK(skgl_point_texture(l[k]) == skgl_point_atlas_texture(a));
    }
    /* the tiny atlas: six faces of one texel need 6 x 1 */
    {
        sk_vsdct_layout before = skgl_point_layout(t);
        SK_CHECK(skgl_point_atlas_pack(sk, tiny, &t, 1, &cam, pos) == SK_ERR_CAPACITY);
        CHECK_LOG(sk, "fit");
        SK_CHECK(skgl_point_layout(t).face_res == before.face_res);
        SK_CHECK(skgl_point_render(sk, t, &cam, &sc, pos[0]) == SK_ERR_INVALID_ARG);
    }
    check_log_cleared(sk, "atlas pack");
    SK_CHECK(e.gl.GetError() == 0);
done:
    for (k = 0; k < 3; k++) skgl_point_destroy(sk, l[k]);
    skgl_point_destroy(sk, own);
    skgl_point_destroy(sk, t);
    skgl_point_atlas_destroy(sk, a);
    skgl_point_atlas_destroy(sk, tiny);
    skgl_point_atlas_destroy(sk, other);
    SK_CHECK_MSG(skgl_gl_object_count(sk) == base, "atlas: %d objects (%d)", skgl_gl_object_count(sk), base);
    skgl_destroy(sk);
    gt_env_free(&e);
}

/* ======================================================================= */
/* skgl_set_model outside a draw callback: the model is a uniform of
   shadowkit's depth program, which is not current then. Also: a caller's
   program with a mat4 at the location u_model has in the depth program
   (taken from info->program in a callback) keeps its value. */
static unsigned depth_program;
static void grab_program(void *user, const skgl_draw_info *info) {
    gt_env *e = (gt_env *)user;
    depth_program = info->program;
    tb_gl_mesh_draw(&e->gl, &e->mesh, 0, 0);
}
static const char two_mats_vs[] =
    "#version 330 core\nlayout(location = 0) in vec3 a_position;\nuniform mat4 u_a;\nuniform mat4 u_b;\n"
    "uniform mat4 u_c;\nvoid main() { gl_Position = u_a * u_b * u_c * vec4(a_position, 1.0); }\n";
static const char two_mats_fs[] = "#version 330 core\nout vec4 o;\nvoid main() { o = vec4(1.0); }\n";

static void test_set_model(void) {
    gt_env e;
    skgl_context *sk;
    skgl_shadow_desc d;
    skgl_shadow *s = NULL;
    skgl_scene sc;
    skgl_camera cam = view_a();
    float m[16], got[16];
    unsigned err, caller = 0;
    int prog = -1, model_loc = -1, k, i;
    if (env_init(&e) != 0) return;
    ext_load(tb_gl_context_getproc(e.ctx));
    sk = fault_context(0, 0, 0);
    if (!sk) { gt_env_free(&e); return; }
    /* the depth program's u_model location */
    memset(&d, 0, sizeof d);
    d.resolution = 64;
    sc = gt_scene(&e);
    sc.draw = grab_program;
    SK_CHECK(skgl_shadow_create(sk, &d, &s) == SK_OK);
    if (s) SK_CHECK(skgl_shadow_render(sk, s, &cam, &sc, light_dir()) == SK_OK);
    skgl_shadow_destroy(sk, s);
    model_loc = depth_program ? e.gl.GetUniformLocation(depth_program, "skgl_model") : -1;
    SK_CHECK_MSG(model_loc >= 0, "u_model at %d", model_loc);
    {
        const char *vs[1], *fs[1];
        unsigned v, f;
        vs[0] = two_mats_vs;
        fs[0] = two_mats_fs;
        v = gt_compile(&e.gl, 0x8B31, 1, vs);
        f = gt_compile(&e.gl, 0x8B30, 1, fs);
        caller = e.gl.CreateProgram();
        e.gl.AttachShader(caller, v);
        e.gl.AttachShader(caller, f);
        e.gl.LinkProgram(caller);
        e.gl.DeleteShader(v);
        e.gl.DeleteShader(f);
    }
    memset(m, 0, sizeof m);
    m[0] = m[5] = m[10] = m[15] = 1;
    m[12] = 3;
    e.gl.UseProgram(0);
    skgl_set_model(sk, m);
    err = e.gl.GetError();
    SK_CHECK_MSG(err == 0, "skgl_set_model outside a callback, no program current: GL error 0x%x", err);
    e.gl.UseProgram(e.gb.program);
    skgl_set_model(sk, m);
    err = e.gl.GetError();
    e.gl.GetIntegerv(0x8B8D /* CURRENT_PROGRAM */, &prog);
    SK_CHECK(prog == (int)e.gb.program);
    SK_CHECK_MSG(err == 0, "skgl_set_model outside a callback, the caller's program current: GL error 0x%x", err);
    SK_CHECK(e.gl.GetError() == 0);
    /* a caller's program whose mat4 sits at u_model's location */
    e.gl.UseProgram(caller);
    for (k = 0; k < 16; k++) got[k] = (float)(k + 1);
    if (model_loc >= 0) e.gl.UniformMatrix4fv(model_loc, 1, 0, got);
    skgl_set_model(sk, m);
    err = e.gl.GetError();
    memset(got, 0, sizeof got);
    if (model_loc >= 0) X.GetUniformfv(caller, model_loc, got);
    for (k = 0, i = 0; k < 16; k++) i += got[k] != (float)(k + 1);
    SK_CHECK_MSG(i == 0 && err == 0, "the caller's mat4 at %d: %d of 16 values changed", model_loc, i);
    e.gl.UseProgram(0);
    e.gl.DeleteProgram(caller);
    e.gl.UseProgram(0);
    skgl_destroy(sk);
    gt_env_free(&e);
}

/* ======================================================================= */
/* desc.debug: a draw callback that returns with its own program current, in
   an RMSM render (the pages' loop) and a point render (the faces' loop) */
static unsigned other_program;
static void rogue_draw(void *user, const skgl_draw_info *info) {
    gt_env *e = (gt_env *)user;
    tb_gl_mesh_draw(&e->gl, &e->mesh, 0, 0);
    if (info->index == 0) e->gl.UseProgram(other_program);
}

static void test_callback_program(void) {
    gt_env e;
    skgl_context *sk;
    skgl_shadow_desc d;
    skgl_shadow *r = NULL;
    skgl_point_desc pd;
    skgl_point *p = NULL;
    skgl_scene sc;
    skgl_camera cam = view_a();
    if (env_init(&e) != 0) return;
    sk = fault_context(1, 0, 0);
    if (!sk) { gt_env_free(&e); return; }
    SK_CHECK(gt_gbuffer(&e, &cam) == 0);
    sc = gt_scene(&e);
    other_program = e.gb.program;
    memset(&d, 0, sizeof d);
    d.technique = SKGL_RMSM;
    d.resolution = 2048;
    d.rmsm_page_size = 64;
    d.rmsm_pool_pages = 8;
    memset(&pd, 0, sizeof pd);
    pd.resolution = 64;
    pd.range = 30;
    SK_CHECK(skgl_shadow_create(sk, &d, &r) == SK_OK);
    SK_CHECK(skgl_point_create(sk, &pd, &p) == SK_OK);
    if (r && p) {
        SK_CHECK(skgl_shadow_analyze(sk, r, &cam, &sc, light_dir(), e.gbuf.depth_tex) == SK_OK);
        sc.draw = rogue_draw;
        SK_CHECK(skgl_shadow_render(sk, r, &cam, &sc, light_dir()) == SK_ERR_INVALID_ARG);
        CHECK_LOG(sk, "program");
        SK_CHECK(skgl_point_render(sk, p, &cam, &sc, gt_v3(0, 4, 0)) == SK_ERR_INVALID_ARG);
        CHECK_LOG(sk, "program");
        sc.draw = gt_draw;
        SK_CHECK(skgl_shadow_render(sk, r, &cam, &sc, light_dir()) == SK_OK);
        SK_CHECK(skgl_point_render(sk, p, &cam, &sc, gt_v3(0, 4, 0)) == SK_OK);
    }
    e.gl.UseProgram(0);
    SK_CHECK(e.gl.GetError() == 0);
    skgl_shadow_destroy(sk, r);
    skgl_point_destroy(sk, p);
    skgl_destroy(sk);
    gt_env_free(&e);
}

/* ======================================================================= */
/* The header's promise ("every public call that takes the context clears
   it first"): after a failed mask, each successful call below leaves the
   log empty. */
static void test_log_cleared(void) {
    gt_env e;
    skgl_context *sk;
    skgl_shadow_desc d;
    skgl_shadow *s = NULL, *f = NULL;
    skgl_point_desc pd;
    skgl_point *p = NULL;
    skgl_point_atlas *a = NULL;
    skgl_scene sc;
    skgl_camera cam = view_a();
    unsigned bare = 0;
    int k;
    const char *names[7] = {"skgl_shadow_render", "skgl_shadow_mask", "skgl_shadow_analyze", "skgl_shadow_bind",
                            "skgl_point_create", "skgl_point_render", "skgl_point_atlas_create"};
    if (env_init(&e) != 0) return;
    sk = fault_context(0, 0, 0);
    if (!sk) { gt_env_free(&e); return; }
    SK_CHECK(gt_gbuffer(&e, &cam) == 0);
    sc = gt_scene(&e);
    memset(&d, 0, sizeof d);
    d.resolution = RES;
    SK_CHECK(skgl_shadow_create(sk, &d, &s) == SK_OK);
    d.technique = SKGL_FERKO;
    SK_CHECK(skgl_shadow_create(sk, &d, &f) == SK_OK);
    e.gl.GenTextures(1, &bare);
    memset(&pd, 0, sizeof pd);
    pd.resolution = 64;
    pd.range = 30;
    if (s && f) {
        for (k = 0; k < 7; k++) {
            sk_result r = SK_OK;
            SK_CHECK(skgl_shadow_mask(sk, s, &cam, e.gbuf.depth_tex, 0, bare) == SK_ERR_INVALID_ARG);
            CHECK_LOG(sk, "skgl_shadow_mask");   /* never rendered (k 0), then mask_tex: not a texture */
            switch (k) {
            case 0: r = skgl_shadow_render(sk, s, &cam, &sc, light_dir()); break;
            case 1: r = skgl_shadow_mask(sk, s, &cam, e.gbuf.depth_tex, 0, e.mask.color_tex); break;
            case 2: r = skgl_shadow_analyze(sk, f, &cam, &sc, light_dir(), e.gbuf.depth_tex); break;
            case 3:
                e.gl.UseProgram(e.gb.program);
                r = skgl_shadow_bind(sk, s, e.gb.program, 0);
                e.gl.UseProgram(0);
                break;
            case 4: r = skgl_point_create(sk, &pd, &p); break;
            case 5: r = skgl_point_render(sk, p, &cam, &sc, gt_v3(0, 4, 0)); break;
            case 6: r = skgl_point_atlas_create(sk, 64, 64, &a); break;
            default: break;
            }
            SK_CHECK_MSG(r == SK_OK, "%s: %s", names[k], sk_result_string(r));
            SK_CHECK_MSG(skgl_error_log(sk)[0] == 0, "%s succeeded and left the log \"%s\"", names[k],
                         skgl_error_log(sk));
        }
    }
    skgl_forget_texture(sk, bare);
    e.gl.DeleteTextures(1, &bare);
    skgl_point_atlas_destroy(sk, a);
    skgl_point_destroy(sk, p);
    skgl_shadow_destroy(sk, s);
    skgl_shadow_destroy(sk, f);
    SK_CHECK(e.gl.GetError() == 0);
    skgl_destroy(sk);
    gt_env_free(&e);
}

/* ======================================================================= */
/* ---- area lights (skgl_soft_*) ---- */
typedef struct soft_rule {
    const char *field;
    double value;
} soft_rule;

/* a PCSS (or, for PVSM-only fields, PVSM) desc with one field broken */
static skgl_soft_desc soft_rule_desc(const soft_rule *r) {
    skgl_soft_desc d;
    const char *f = r->field;
    float v = (float)r->value;
    int i = (int)r->value;
    memset(&d, 0, sizeof d);
    d.resolution = RES;
    if (!strcmp(f, "technique")) d.technique = (skgl_soft_technique)i;
    else if (!strcmp(f, "resolution")) d.resolution = i;
    else if (!strcmp(f, "lowres")) d.lowres = i;
    else if (!strcmp(f, "grid")) d.grid = i;
    else if (!strcmp(f, "max_tiles")) d.max_tiles = i;
    else if (!strcmp(f, "disable_conservative")) d.disable_conservative = i;
    else if (!strcmp(f, "static_scene")) d.static_scene = i;
    else if (!strcmp(f, "blocker_cells")) d.blocker_cells = i;
    else if (!strcmp(f, "pcf_taps")) d.pcf_taps = i;
    else if (!strcmp(f, "slope_bias")) d.slope_bias = v;
    else if (!strcmp(f, "depth_bias")) d.depth_bias = v;
    else if (!strcmp(f, "disable_polygon_offset")) d.disable_polygon_offset = i;
    else if (!strcmp(f, "rel_bias")) d.rel_bias = v;
    else if (!strcmp(f, "disable_antialias")) d.disable_antialias = i;
    else if (!strcmp(f, "resolution_scale")) d.resolution_scale = v;
    else if (!strcmp(f, "sync_readback")) d.sync_readback = i;
    return d;
}

static int soft_mask(gt_env *e, skgl_context *sk, skgl_soft *s, const skgl_camera *cam, const skgl_area_light *l,
                     unsigned depth_tex, float *mask) {
    skgl_scene sc = gt_scene(e);
    size_t i;
    sk_result r = skgl_soft_render(sk, s, cam, &sc, l, depth_tex, depth_tex ? e->gbuf.color_tex : 0,
                                   e->mask.color_tex);
    if (r != SK_OK) { printf("soft render: %s (%s)\n", sk_result_string(r), skgl_error_log(sk)); return -1; }
    if (!mask) return 0;
    if (tb_gl_read_texture_red(&e->gl, e->mask.color_tex, e->w, e->h, mask) != 0) return -1;
    for (i = 0; i < e->n; i++) if (!(e->depth[i] < 1.0f)) mask[i] = -1.0f;
    return 0;
}

static skgl_area_light soft_light(void) {
    skgl_area_light l;
    memset(&l, 0, sizeof l);
    l.position = gt_v3(2.0f, 9.0f, -2.5f);
    l.direction = gt_v3(-0.3f, -1.0f, 0.4f);
    l.up = gt_v3(0, 0, 1);
    l.half_width = l.half_height = 0.3f;
    return l;
}

/* test_soft_paths: every rule of skgl_soft_desc broken once (28 cases, the
   field named, nothing made); the defaults; the NULL accessors; render's
   arguments, each named; a scene wholly behind the light
   (SK_ERR_DEGENERATE); a mask texture without level 0 and one that is not
   colour-renderable; a framebuffer incomplete at each target made at
   create (PCSS's map; PVSM's low-res map, a pyramid level, the SMTG) and at
   render (PVSM's screen targets, the own G-buffer), a compile and a link
   failure, a GL error at create and (desc.debug) at render: SK_ERR_GL, the
   log says which, the object count unchanged, the next call good; both
   techniques in caller-owns mode, with and without a G-buffer given,
   mask for mask equal to the default mode's. It found a framebuffer
   leaked when a pyramid level's was incomplete ("PVSM fb 2: 12 objects,
   11 before"), fixed since. */
static void test_soft_paths(void) {
    static const soft_rule rules[] = {
        {"technique", 2}, {"technique", -1}, {"resolution", 8}, {"resolution", 1 << 20}, {"lowres", 24},
        {"lowres", 8}, {"lowres", 16384}, {"grid", 2}, {"grid", 12}, {"grid", 512}, {"max_tiles", -1},
        {"max_tiles", 5000}, {"disable_conservative", 2}, {"static_scene", -1}, {"blocker_cells", 1},
        {"blocker_cells", 17}, {"pcf_taps", -1}, {"pcf_taps", 17}, {"slope_bias", -1}, {"slope_bias", 1e5},
        {"depth_bias", -1}, {"disable_polygon_offset", 2}, {"rel_bias", -0.1}, {"rel_bias", 0.6},
        {"disable_antialias", -1}, {"resolution_scale", 0.1}, {"resolution_scale", 9}, {"sync_readback", 2}};
    gt_env e;
    skgl_context *sk, *own;
    skgl_soft_desc d, g;
    skgl_soft *s = NULL;
    skgl_scene sc, nodraw;
    skgl_camera cam = view_a(), badcam;
    skgl_area_light l = soft_light(), bad;
    sk_vec3 hu, hv;
    float *m0, *m1;
    size_t i;
    int base, k, t, differ;
    if (env_init(&e) != 0) return;
    sk = fault_context(1, 0, 0);
    if (!sk) { gt_env_free(&e); return; }
    sc = gt_scene(&e);
    m0 = gt_alloc(&e);
    m1 = gt_alloc(&e);
    SK_CHECK(gt_gbuffer(&e, &cam) == 0);
    base = skgl_gl_object_count(sk);
    for (k = 0; k < (int)(sizeof rules / sizeof rules[0]); k++) {
        d = soft_rule_desc(&rules[k]);
        s = (skgl_soft *)&d;   /* must come back NULL */
        SK_CHECK_MSG(skgl_soft_create(sk, &d, &s) == SK_ERR_INVALID_ARG && s == NULL, "soft rule %s = %g accepted",
                     rules[k].field, rules[k].value);
        CHECK_LOG(sk, rules[k].field);
        SK_CHECK(skgl_gl_object_count(sk) == base);
    }
    /* NaN biases */
    memset(&d, 0, sizeof d);
    d.slope_bias = NAN;
    SK_CHECK(skgl_soft_create(sk, &d, &s) == SK_ERR_INVALID_ARG);
    CHECK_LOG(sk, "slope_bias");
    SK_CHECK(skgl_soft_create(NULL, &d, &s) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_soft_create(sk, NULL, &s) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_soft_create(sk, &d, NULL) == SK_ERR_INVALID_ARG);
    /* the defaults, and the NULL accessors */
    memset(&d, 0, sizeof d);
    d.technique = SKGL_SOFT_PVSM;
    SK_CHECK(skgl_soft_create(sk, &d, &s) == SK_OK && s);
    SK_CHECK(skgl_error_log(sk)[0] == 0);
    g = skgl_soft_get_desc(s);
    SK_CHECK_MSG(g.resolution == 4096 && g.lowres == 1024 && g.grid == 64 && g.max_tiles == 64 &&
                     g.blocker_cells == 8 && g.pcf_taps == 12 && g.slope_bias == 1.5f && g.depth_bias == 1.0f &&
                     g.rel_bias == 0.002f && g.resolution_scale == 1.0f && g.sync_readback == 0 &&
                     g.disable_conservative == 0 && g.disable_antialias == 0,
                 "PVSM defaults: %d %d %d %d", g.resolution, g.lowres, g.grid, g.max_tiles);
    SK_CHECK(skgl_soft_pyramid(s, NULL, 0) == 0 && skgl_soft_tiles(s, NULL, 0) == 0);
    SK_CHECK(skgl_soft_stats(s)->lit_fraction == 1.0f && skgl_soft_stats(s)->shadow_ms == -1.0f);
    skgl_soft_destroy(sk, s);
    s = NULL;
    g = skgl_soft_get_desc(NULL);
    SK_CHECK(g.resolution == 0 && g.technique == SKGL_SOFT_PCSS);
    SK_CHECK(skgl_soft_stats(NULL) == NULL && skgl_soft_tiles(NULL, NULL, 0) == 0 &&
             skgl_soft_tile_rects(NULL, NULL, 0) == 0 && skgl_soft_pyramid(NULL, NULL, 0) == 0);
    SK_CHECK(memcmp(skgl_soft_matrix(NULL).m, sk_mat4_identity().m, sizeof(float) * 16) == 0);
    skgl_soft_destroy(sk, NULL);
    skgl_soft_destroy(NULL, NULL);
    skgl_area_light_axes(NULL, &hu, &hv);
    SK_CHECK(hu.x == 0.0f && hv.y == 0.0f);
    skgl_area_light_axes(&l, NULL, &hv);
    bad = l;
    bad.up = gt_v3(-0.3f, -1.0f, 0.4f);   /* along the direction: another axis is taken */
    skgl_area_light_axes(&bad, &hu, &hv);
    SK_CHECK(fabs(sqrt((double)hu.x * hu.x + (double)hu.y * hu.y + (double)hu.z * hu.z) - 0.3) < 1e-5 &&
             fabs(sqrt((double)hv.x * hv.x + (double)hv.y * hv.y + (double)hv.z * hv.z) - 0.3) < 1e-5);
    SK_CHECK(skgl_gl_object_count(sk) == base);

    /* render's arguments */
    memset(&d, 0, sizeof d);
    d.resolution = RES;
    SK_CHECK(skgl_soft_create(sk, &d, &s) == SK_OK && s);
    if (!s) goto done;
    SK_CHECK(skgl_soft_render(NULL, s, &cam, &sc, &l, 0, 0, e.mask.color_tex) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_soft_render(sk, NULL, &cam, &sc, &l, 0, 0, e.mask.color_tex) == SK_ERR_INVALID_ARG);
    CHECK_LOG(sk, "s is NULL");
    badcam = cam;
    badcam.view.m[5] = NAN;
    SK_CHECK(skgl_soft_render(sk, s, &badcam, &sc, &l, 0, 0, e.mask.color_tex) == SK_ERR_INVALID_ARG);
    CHECK_LOG(sk, "cam");
    nodraw = sc;
    nodraw.draw = NULL;
    SK_CHECK(skgl_soft_render(sk, s, &cam, &nodraw, &l, 0, 0, e.mask.color_tex) == SK_ERR_INVALID_ARG);
    CHECK_LOG(sk, "draw");
    SK_CHECK(skgl_soft_render(sk, s, &cam, &sc, NULL, 0, 0, e.mask.color_tex) == SK_ERR_INVALID_ARG);
    CHECK_LOG(sk, "light");
    bad = l;
    bad.direction = gt_v3(0, 0, 0);
    SK_CHECK(skgl_soft_render(sk, s, &cam, &sc, &bad, 0, 0, e.mask.color_tex) == SK_ERR_INVALID_ARG);
    CHECK_LOG(sk, "direction");
    bad = l;
    bad.position.y = INFINITY;
    SK_CHECK(skgl_soft_render(sk, s, &cam, &sc, &bad, 0, 0, e.mask.color_tex) == SK_ERR_INVALID_ARG);
    CHECK_LOG(sk, "position");
    bad = l;
    bad.up.x = NAN;
    SK_CHECK(skgl_soft_render(sk, s, &cam, &sc, &bad, 0, 0, e.mask.color_tex) == SK_ERR_INVALID_ARG);
    CHECK_LOG(sk, "up");
    bad = l;
    bad.half_height = -1.0f;
    SK_CHECK(skgl_soft_render(sk, s, &cam, &sc, &bad, 0, 0, e.mask.color_tex) == SK_ERR_INVALID_ARG);
    CHECK_LOG(sk, "half_width");
    SK_CHECK(skgl_soft_render(sk, s, &cam, &sc, &l, 0, 0, 0) == SK_ERR_INVALID_ARG);
    CHECK_LOG(sk, "mask_tex");
    /* the whole scene behind the light's plane */
    bad = l;
    bad.position = gt_v3(0, -50, 0);
    bad.direction = gt_v3(0, -1, 0);
    SK_CHECK(skgl_soft_render(sk, s, &cam, &sc, &bad, 0, 0, e.mask.color_tex) == SK_ERR_DEGENERATE);
    CHECK_LOG(sk, "behind");
    /* a mask texture with no level 0, one that is not colour-renderable */
    F.tex_w = -1;
    SK_CHECK(skgl_soft_render(sk, s, &cam, &sc, &l, e.gbuf.depth_tex, e.gbuf.color_tex, e.mask.color_tex) ==
             SK_ERR_INVALID_ARG);
    CHECK_LOG(sk, "level 0");
    faults_off();
    SK_CHECK(skgl_soft_render(sk, s, &cam, &sc, &l, e.gbuf.depth_tex, e.gbuf.color_tex, e.gbuf.depth_tex) ==
             SK_ERR_GL);
    CHECK_LOG(sk, "colour-renderable");
    SK_CHECK(soft_mask(&e, sk, s, &cam, &l, e.gbuf.depth_tex, NULL) == 0);
    SK_CHECK(skgl_error_log(sk)[0] == 0);
    skgl_soft_destroy(sk, s);
    s = NULL;
    SK_CHECK(skgl_gl_object_count(sk) == base);

    /* framebuffers incomplete at create: PCSS's map; PVSM's low-res map, its
       pyramid's first level, the SMTG (after the map, the low-res map and
       its 5 levels at lowres 64) */
    memset(&d, 0, sizeof d);
    d.resolution = RES;
    F.fb_fail = 1;
    SK_CHECK(skgl_soft_create(sk, &d, &s) == SK_ERR_GL && !s);
    CHECK_LOG(sk, "DEPTH32F");
    SK_CHECK(skgl_gl_object_count(sk) == base);
    d.technique = SKGL_SOFT_PVSM;
    d.lowres = 64;
    for (k = 0; k < 3; k++) {
        static const int skip[3] = {1, 2, 8};
        static const char *const what[3] = {"R32F", "R32F", "RGBA32F"};
        faults_off();
        F.fb_skip = skip[k];
        F.fb_fail = 1;
        SK_CHECK_MSG(skgl_soft_create(sk, &d, &s) == SK_ERR_GL && !s, "PVSM framebuffer %d made", skip[k]);
        CHECK_LOG(sk, what[k]);
        SK_CHECK_MSG(skgl_gl_object_count(sk) == base, "PVSM fb %d: %d objects, %d before", skip[k], skgl_gl_object_count(sk), base);
    }
    /* a compile and a link failure, a GL error at the end of create */
    faults_off();
    F.compile_fail = 1;
    SK_CHECK(skgl_soft_create(sk, &d, &s) == SK_ERR_GL && !s);
    SK_CHECK(skgl_gl_object_count(sk) == base);
    F.link_fail = 1;
    SK_CHECK(skgl_soft_create(sk, &d, &s) == SK_ERR_GL && !s);
    SK_CHECK(skgl_gl_object_count(sk) == base);
    F.gl_error = 1;
    SK_CHECK(skgl_soft_create(sk, &d, &s) == SK_ERR_GL && !s);
    CHECK_LOG(sk, "GL_OUT_OF_MEMORY");
    SK_CHECK(skgl_gl_object_count(sk) == base);
    faults_off();
    /* at render: PVSM's screen targets, the own G-buffer; desc.debug's GL error */
    SK_CHECK(skgl_soft_create(sk, &d, &s) == SK_OK && s);
    if (!s) goto done;
    F.fb_fail = 1;
    SK_CHECK(skgl_soft_render(sk, s, &cam, &sc, &l, e.gbuf.depth_tex, e.gbuf.color_tex, e.mask.color_tex) ==
             SK_ERR_GL);
    CHECK_LOG(sk, "screen targets");
    F.fb_fail = 1;
    SK_CHECK(skgl_soft_render(sk, s, &cam, &sc, &l, 0, 0, e.mask.color_tex) == SK_ERR_GL);
    CHECK_LOG(sk, "G-buffer");
    faults_off();
    F.gl_error = 1;
    SK_CHECK(skgl_soft_render(sk, s, &cam, &sc, &l, e.gbuf.depth_tex, e.gbuf.color_tex, e.mask.color_tex) ==
             SK_ERR_GL);
    CHECK_LOG(sk, "skgl_soft_render");
    faults_off();
    SK_CHECK(soft_mask(&e, sk, s, &cam, &l, 0, NULL) == 0);
    SK_CHECK(skgl_error_log(sk)[0] == 0);
    skgl_soft_destroy(sk, s);
    s = NULL;
    SK_CHECK(skgl_gl_object_count(sk) == base);

    /* more tiles than max_tiles: every predicted resolution halved until
       they fit (256-texel tiles make 7 here; at most 2 allowed) */
    memset(&d, 0, sizeof d);
    d.technique = SKGL_SOFT_PVSM;
    d.resolution = 256;
    d.sync_readback = 1;
    SK_CHECK(skgl_soft_create(sk, &d, &s) == SK_OK && s);
    if (s) {
        int many, few;
        SK_CHECK(soft_mask(&e, sk, s, &cam, &l, e.gbuf.depth_tex, NULL) == 0);
        many = skgl_soft_stats(s)->tiles;
        skgl_soft_destroy(sk, s);
        d.max_tiles = 2;
        s = NULL;
        SK_CHECK(skgl_soft_create(sk, &d, &s) == SK_OK && s);
        SK_CHECK(s && soft_mask(&e, sk, s, &cam, &l, e.gbuf.depth_tex, NULL) == 0);
        few = s ? skgl_soft_stats(s)->tiles : -1;
        SK_CHECK_MSG(many > 2 && few >= 1 && few <= 2, "max_tiles 2: %d tiles (%d without the cap)", few, many);
        skgl_soft_destroy(sk, s);
        s = NULL;
    }
    /* caller-owns mode: the same masks, with and without a G-buffer given */
    own = fault_context(0, 0, 1);
    for (t = 0; own && t < 4; t++) {
        skgl_soft *a = NULL, *b = NULL;
        memset(&d, 0, sizeof d);
        d.technique = t & 1 ? SKGL_SOFT_PVSM : SKGL_SOFT_PCSS;
        d.resolution = RES;
        d.sync_readback = 1;
        SK_CHECK(skgl_soft_create(sk, &d, &a) == SK_OK && skgl_soft_create(own, &d, &b) == SK_OK);
        if (a && b) {
            unsigned depth = t & 2 ? 0 : e.gbuf.depth_tex;
            SK_CHECK(soft_mask(&e, sk, a, &cam, &l, depth, m0) == 0);
            SK_CHECK(soft_mask(&e, own, b, &cam, &l, depth, m1) == 0);
            for (i = 0, differ = 0; i < e.n; i++) differ += m0[i] != m1[i];
            SK_CHECK_MSG(differ == 0, "%s%s, caller owns the state: %d mask values differ",
                         t & 1 ? "PVSM" : "PCSS", t & 2 ? " (own G-buffer)" : "", differ);
        }
        skgl_soft_destroy(sk, a);
        skgl_soft_destroy(own, b);
    }
    skgl_destroy(own);
done:
    faults_off();
    if (s) skgl_soft_destroy(sk, s);
    SK_CHECK(skgl_gl_object_count(sk) == base);
    SK_CHECK(e.gl.GetError() == 0);
    skgl_destroy(sk);
    free(m0);
    free(m1);
    gt_env_free(&e);
}

/* test_callback_state: desc.debug, draw callbacks that break SCENE ACCESS
   after drawing (the viewport, the depth function, the polygon offset, in
   a STANDARD render; the blend equation, in PVSM's low-res pass):
   SK_ERR_INVALID_ARG, the log names what changed; and the changes it
   allows: culling switched on (SK_OK, the caller's culling off again
   after the call), a pixel pack buffer of its own bound in PVSM's low-res
   pass (SK_OK, the mask value for value the plain callback's, no GL
   error: the read-back does not land in the callback's buffer). Can fail:
   the kept state not compared ("callback changing viewport: ok", and the
   depth function, polygon offset, blend equation); culling taken as still
   known after a callback ("culling left on after the call"). */
static int cb_mode;
static unsigned cb_buffer;
static void (*cb_polygon_offset)(float, float);
static void (*cb_blend_equation)(unsigned);
static void state_draw(void *user, const skgl_draw_info *info) {
    gt_env *e = (gt_env *)user;
    tb_gl_mesh_draw(&e->gl, &e->mesh, 0, 0);
    if (info->index != 0) return;
    switch (cb_mode) {
    case 1: e->gl.Viewport(0, 0, 7, 7); break;
    case 2: e->gl.DepthFunc(0x0207 /* ALWAYS */); break;
    case 3: cb_polygon_offset(0.0f, 0.0f); break;
    case 4: cb_blend_equation(0x8006 /* FUNC_ADD */); break;
    case 5: e->gl.Enable(0x0B44 /* CULL_FACE */); break;
    case 6: e->gl.BindBuffer(0x88EB /* PIXEL_PACK_BUFFER */, cb_buffer); break;
    default: break;
    }
}

static void test_callback_state(void) {
    static const char *const what[5] = {"", "viewport", "depth function", "polygon offset", "blend equation"};
    gt_env e;
    skgl_context *sk;
    skgl_shadow_desc d;
    skgl_shadow *s = NULL;
    skgl_soft_desc sd;
    skgl_soft *so = NULL;
    skgl_scene sc;
    skgl_camera cam = view_a();
    skgl_area_light l = soft_light();
    float *m0, *m1;
    void *p;
    size_t i;
    int k, differ;
    if (env_init(&e) != 0) return;
    sk = fault_context(1, 0, 0);
    if (!sk) { gt_env_free(&e); return; }
    p = real_getproc("glPolygonOffset"); memcpy(&cb_polygon_offset, &p, sizeof p);
    p = real_getproc("glBlendEquation"); memcpy(&cb_blend_equation, &p, sizeof p);
    SK_CHECK(gt_gbuffer(&e, &cam) == 0);
    sc = gt_scene(&e);
    sc.draw = state_draw;
    m0 = gt_alloc(&e);
    m1 = gt_alloc(&e);
    memset(&d, 0, sizeof d);
    d.resolution = RES;
    memset(&sd, 0, sizeof sd);
    sd.technique = SKGL_SOFT_PVSM;
    sd.resolution = RES;
    sd.lowres = 64;
    sd.sync_readback = 1;
    SK_CHECK(skgl_shadow_create(sk, &d, &s) == SK_OK && skgl_soft_create(sk, &sd, &so) == SK_OK);
    if (!s || !so) goto done;
    for (k = 1; k <= 4; k++) {
        sk_result r;
        cb_mode = k;
        if (k < 4) r = skgl_shadow_render(sk, s, &cam, &sc, light_dir());
        else r = skgl_soft_render(sk, so, &cam, &sc, &l, e.gbuf.depth_tex, e.gbuf.color_tex, e.mask.color_tex);
        SK_CHECK_MSG(r == SK_ERR_INVALID_ARG, "callback changing %s: %s", what[k], sk_result_string(r));
        CHECK_LOG(sk, what[k]);
        SK_CHECK(e.gl.GetError() == 0);
    }
    /* allowed: culling (put back), a pixel pack buffer of its own */
    cb_mode = 5;
    SK_CHECK(skgl_shadow_render(sk, s, &cam, &sc, light_dir()) == SK_OK);
    SK_CHECK_MSG(!e.gl.IsEnabled(0x0B44), "culling left on after the call");
    cb_mode = 0;
    SK_CHECK(soft_mask(&e, sk, so, &cam, &l, e.gbuf.depth_tex, m0) == 0);
    e.gl.GenBuffers(1, &cb_buffer);
    e.gl.BindBuffer(0x88EB, cb_buffer);
    e.gl.BufferData(0x88EB, 64, NULL, 0x88E1 /* STREAM_DRAW */);
    e.gl.BindBuffer(0x88EB, 0);
    cb_mode = 6;
    SK_CHECK(soft_mask(&e, sk, so, &cam, &l, e.gbuf.depth_tex, m1) == 0);
    for (i = 0, differ = 0; i < e.n; i++) differ += m0[i] != m1[i];
    SK_CHECK_MSG(differ == 0, "a pack buffer bound by the callback: %d mask values differ", differ);
    SK_CHECK(e.gl.GetError() == 0);
    e.gl.DeleteBuffers(1, &cb_buffer);
done:
    cb_mode = 0;
    skgl_shadow_destroy(sk, s);
    skgl_soft_destroy(sk, so);
    skgl_destroy(sk);
    free(m0);
    free(m1);
    gt_env_free(&e);
}

SK_TEST_MAIN(test_context, test_shadow_rules, test_shadow_args, test_shadow_techniques, test_faults, test_textures,
             test_rings, test_program_cache, test_point_paths, test_atlas, test_callback_program, test_set_model,
             test_log_cleared, test_soft_paths, test_callback_state)
