/* test_gl_es.c - shadowkit_gl.h on OpenGL ES: every technique on Mesa's
   native ES context (EGL with EGL_OPENGL_ES_API, llvmpipe), its mask
   compared pixel for pixel with the desktop path's (OSMesa, GL 3.3 core) for
   the same scene, camera and light (tests/es/es_core.h, the same code the
   browser test runs), and the hard techniques with the exact reference.

   Two ES runs:
   - "es": what the context offers (Mesa: ES 3.2 with geometry shaders,
     float render targets and blending, norm16, depth clamp, timer queries);
   - "es30": only what OpenGL ES 3.0 and WebGL2 guarantee plus the two float
     extensions WebGL2 implementations have (skgl_desc.disable_caps): no
     geometry shader (PVSM's conservative pass falls back), no RG16 (VSDCT's
     indirection in RG32F), no depth clamp, no glGetTexLevelParameteriv
     (skgl_remember_texture), no glGetBufferSubData (glMapBufferRange), no
     in-place mip rendering (PVSM's pyramid through copies of its levels);
     timer queries kept (WebGL2 has them through an extension).
   The technique table (tests/es/es_core.h) ends with a spot light
   (skgl_spot_render), judged by the point light's exact reference cut by
   its cone (esx_spot_reference).
   Skips (0 failed, one pass) when no ES context can be made. */
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "sk_test.h"
#include "gl_test_util.h"
#include "es/es_core.h"

#define ES30_CAPS (SKGL_CAP_GEOMETRY_SHADER | SKGL_CAP_GPU_SHADER5 | SKGL_CAP_NORM16 | SKGL_CAP_DEPTH_CLAMP | \
                   SKGL_CAP_TEXTURE_SIZE | SKGL_CAP_BUFFER_READ | SKGL_CAP_MIP_RENDER_LEVEL | SKGL_CAP_CLIP_CONTROL)

/* Bounds, from Mesa 22.3 llvmpipe (ES 3.2 context; GL 4.5 core through
   OSMesa): every hard mask equals the desktop one but VSDCT's through the
   RG16 indirection (0.0365% of the pixels: ES samples the indirection cube
   seamlessly, desktop GL not), PVSM's differs by a mean 0.0015 with the
   ES 3.0 fallbacks (the fine map dilated for the conservative pass) and 0
   without; the errors against the reference move by at most +0.30 (VSDCT,
   hard, % of the shadow) and +0.0019 (PVSM). */
#define BOUND_HARD_DIFF 0.1      /* % of the pixels */
#define BOUND_SOFT_DIFF 0.006    /* mean |difference| */
#define BOUND_HARD_REF 0.5       /* % of the shadow, over the desktop's */
#define BOUND_SOFT_REF 0.005     /* over the desktop's */
/* The spot (esx_techs "spot": 40 degrees down past box0 from the point
   light's place, 512^2, normal offset), against the point light's exact
   reference cut by the cone (esx_spot_reference; 0.5 degrees about the
   cone's edge left out): 0.0246% of the shadow wrong on the desktop, ES
   and ES 3.0 alike, the masks equal to the pixel. Bound 0.25 (10x). Can
   fail: SK_GL_TEST_ES_SPOT_UNCUT=1 takes the point light's reference
   uncut, as a mask without its cone would read: 366% of the shadow wrong,
   both ES runs fail. */
#define BOUND_SPOT_REF 0.25      /* % of the shadow, absolute */

static esx_run g_desk, g_es;

/* a getproc that counts the two ways a read-back ends */
typedef void *(*map_fn)(unsigned, ptrdiff_t, ptrdiff_t, unsigned);
typedef void (*getsub_fn)(unsigned, ptrdiff_t, ptrdiff_t, void *);
static tb_gl_getproc_fn g_real;
static map_fn g_map;
static getsub_fn g_getsub;
static long g_maps, g_getsubs;
static void *w_map(unsigned t, ptrdiff_t o, ptrdiff_t n, unsigned a) { g_maps++; return g_map(t, o, n, a); }
static void w_getsub(unsigned t, ptrdiff_t o, ptrdiff_t n, void *d) { g_getsubs++; g_getsub(t, o, n, d); }
static void *w_getproc(const char *name)
{
    map_fn m = w_map;
    getsub_fn g = w_getsub;
    void *p = g_real(name);
    if (strcmp(name, "glMapBufferRange") == 0) { memcpy(&g_map, &p, sizeof p); memcpy(&p, &m, sizeof p); }
    if (strcmp(name, "glGetBufferSubData") == 0) { memcpy(&g_getsub, &p, sizeof p); memcpy(&p, &g, sizeof p); }
    return p;
}

/* the whole table (or the technique named by only) on a context made with
   these flags; 0 ok, 1 no context. async: read-backs through the ring. */
static int run_some(esx_run *r, int flags, unsigned disable_caps, const esx_scene *sc, const char *label,
                    const char *only, int async)
{
    char err[512];
    tb_gl_context *c = tb_gl_context_create_flags(TB_GL_AUTO, flags, err, sizeof err);
    int steps = 0, left;
    if (!c) {
        printf("%s: no context (%s)\n", label, err);
        return 1;
    }
    printf("%s: %s\n", label, tb_gl_context_version(c));
    g_real = tb_gl_context_getproc(c);
    if (esx_begin(r, w_getproc, sc, disable_caps) != 0) {
        SK_CHECK_MSG(0, "%s: %s", label, r->log);
        esx_end(r);
        tb_gl_context_destroy(c);
        return 0;
    }
    if (only) SK_CHECK(esx_only(r, only) == 0);
    r->async = async;
    while (!esx_step(r) && steps < 1000) steps++;
    left = esx_end(r);
    SK_CHECK_MSG(left == 0, "%s: %d GL objects left after every light was destroyed", label, left);
    tb_gl_context_destroy(c);
    return 0;
}

static int run_all(esx_run *r, int flags, unsigned disable_caps, const esx_scene *sc, const char *label)
{
    return run_some(r, flags, disable_caps, sc, label, NULL, 0);
}

static esx_scene scene_of(const tb_scene *scene)
{
    esx_scene sc;
    sc.pos = scene->positions;
    sc.nrm = scene->normals;
    sc.idx = scene->indices;
    sc.vertices = (int)scene->vertex_count;
    sc.indices = (int)scene->index_count;
    sc.bounds = scene->bounds;
    return sc;
}

/* PVSM's low-resolution pass without a geometry shader, against the
   conservative rasterisation it stands for, on the desktop: the fence's
   2 cm slats and 4 cm poles are thinner than a low-resolution texel (12 cm
   here) and some thinner than a fine one (3 cm). Measured (mean |difference|
   over the penumbra against the exact reference, Mesa 22.3 llvmpipe):
   conservative 0.0676, fine map dilated 0.0692, the two masks 0.0079 apart
   (without the one-texel dilation 0.0074 apart: the block minimum does the
   work; one fine texel per low-res texel instead of the block: 0.1122 apart,
   0.0884 against the reference). Bound: 0.012 between the two masks. */
static void test_thin_casters(void)
{
    static esx_run cons, fine;
    static float vis[ESX_W * ESX_H], res[ESX_W * ESX_H];
    tb_scene scene;
    esx_scene sc;
    tb_reference *ref;
    skgl_camera cam = esx_camera();
    skgl_area_light a = esx_area_light();
    sk_mat4 vp = sk_mat4_mul(cam.proj, cam.view);
    tb_view view;
    tb_light l;
    tb_penumbra_error pc, pf;
    int t, i;
    double d;
    tb_scene_init(&scene);
    SK_CHECK(tb_scene_build_fence(&scene) == 0);
    sc = scene_of(&scene);
    ref = tb_reference_create(&scene);
    SK_CHECK(ref != NULL);
    memset(&l, 0, sizeof l);
    sk_mat4_inverse(vp, &view.inv_view_proj);
    view.width = ESX_W;
    view.height = ESX_H;
    l.type = TB_LIGHT_RECT;
    l.position = a.position;
    skgl_area_light_axes(&a, &l.half_u, &l.half_v);
    l.strata = 16;
    SK_CHECK(ref && tb_reference_trace_exact(ref, &view, NULL, &l, NULL, vis, NULL) == 0);
    if (run_some(&cons, 0, 0, &sc, "fence, conservative", "PVSM", 0) != 0 ||
        run_some(&fine, 0, SKGL_CAP_GEOMETRY_SHADER, &sc, "fence, fine map dilated", "PVSM", 0) != 0) {
        SK_CHECK(0);
    } else {
        esx_only(&cons, "PVSM");
        t = cons.tech;
        SK_CHECK_MSG(cons.result[t] == SK_OK && fine.result[t] == SK_OK, "%s / %s", cons.why[t], fine.why[t]);
        for (i = 0; i < ESX_W * ESX_H; i++) res[i] = cons.mask[t][i] / 255.0f;
        pc = tb_metric_penumbra(vis, res, ESX_W, ESX_H, 2);
        for (i = 0; i < ESX_W * ESX_H; i++) res[i] = fine.mask[t][i] / 255.0f;
        pf = tb_metric_penumbra(vis, res, ESX_W, ESX_H, 2);
        d = esx_mask_diff(cons.mask[t], fine.mask[t], 1);
        printf("fence PVSM: conservative %.4f, fine map dilated %.4f against the reference; masks %.4f apart; "
               "GPU %.2f ms against %.2f\n", pc.penumbra_mae, pf.penumbra_mae, d, fine.ms[t], cons.ms[t]);
        SK_CHECK_MSG(d <= 0.012, "fence: the fine map's mask is %.4f from the conservative one", d);
    }
    tb_reference_destroy(ref);
    tb_scene_free(&scene);
}

/* what a context lacks fails at create, naming it; the API choice; the
   texture sizes ES cannot be asked */
static void draw_nothing(void *user, const skgl_draw_info *info)
{
    (void)user;
    (void)info;
}

static void test_caps_contracts(void)
{
    void (*gen_textures)(int, unsigned *) = NULL;
    void (*bind_texture)(unsigned, unsigned) = NULL;
    void (*delete_textures)(int, const unsigned *) = NULL;
    unsigned tex[2] = {0, 0};
    char err[256];
    tb_gl_context *c = tb_gl_context_create(TB_GL_AUTO, err, sizeof err);
    skgl_desc desc;
    skgl_context *ctx = NULL;
    skgl_caps caps;
    skgl_shadow_desc sd;
    skgl_soft_desc fd;
    skgl_point_desc pd;
    skgl_shadow *s = NULL;
    skgl_soft *f = NULL;
    skgl_point *p = NULL;
    if (!c) { SK_CHECK_MSG(0, "%s", err); return; }
    memset(&desc, 0, sizeof desc);
    desc.getproc = (skgl_getproc_fn)tb_gl_context_getproc(c);
    desc.api = SKGL_API_GLES3;   /* a desktop context is not ES */
    SK_CHECK(skgl_create(&desc, &ctx) == SK_ERR_GL && ctx == NULL);
    desc.api = (skgl_api)7;
    SK_CHECK(skgl_create(&desc, &ctx) == SK_ERR_INVALID_ARG);
    desc.api = SKGL_API_GL33;
    SK_CHECK(skgl_create(&desc, &ctx) == SK_OK);
    caps = skgl_get_caps(ctx);
    SK_CHECK(caps.api == SKGL_API_GL33 && caps.geometry_shader && caps.float_render && caps.float_blend &&
             caps.norm16 && caps.texture_size && caps.buffer_read && caps.mip_render_level && !caps.webgl &&
             caps.max_texture_size >= 2048);
    skgl_destroy(ctx);
    caps = skgl_get_caps(NULL);
    SK_CHECK(caps.api == SKGL_API_AUTO && caps.major == 0);

    desc.api = SKGL_API_AUTO;
    desc.disable_caps = SKGL_CAP_FLOAT_RENDER | SKGL_CAP_GEOMETRY_SHADER | SKGL_CAP_TEXTURE_SIZE;
    SK_CHECK(skgl_create(&desc, &ctx) == SK_OK);
    caps = skgl_get_caps(ctx);
    SK_CHECK(!caps.float_render && !caps.float_blend && !caps.geometry_shader && !caps.gpu_shader5 &&
             !caps.texture_size && caps.norm16);
    memset(&sd, 0, sizeof sd);
    sd.technique = SKGL_FERKO;
    SK_CHECK(skgl_shadow_create(ctx, &sd, &s) == SK_ERR_GL && s == NULL);
    SK_CHECK_MSG(strstr(skgl_error_log(ctx), "GL_EXT_color_buffer_float") != NULL, "%s", skgl_error_log(ctx));
    sd.technique = SKGL_RMSM;
    SK_CHECK(skgl_shadow_create(ctx, &sd, &s) == SK_ERR_GL);
    SK_CHECK_MSG(strstr(skgl_error_log(ctx), "SKGL_RMSM") != NULL, "%s", skgl_error_log(ctx));
    sd.technique = SKGL_PSSM;
    sd.layered = 1;
    SK_CHECK(skgl_shadow_create(ctx, &sd, &s) == SK_ERR_GL);
    SK_CHECK_MSG(strstr(skgl_error_log(ctx), "geometry shaders") != NULL, "%s", skgl_error_log(ctx));
    memset(&pd, 0, sizeof pd);
    pd.layered = 1;
    SK_CHECK(skgl_point_create(ctx, &pd, &p) == SK_ERR_GL && p == NULL);
    memset(&fd, 0, sizeof fd);
    fd.technique = SKGL_SOFT_PVSM;
    SK_CHECK(skgl_soft_create(ctx, &fd, &f) == SK_ERR_GL && f == NULL);
    SK_CHECK_MSG(strstr(skgl_error_log(ctx), "SKGL_SOFT_PVSM needs float colour targets") != NULL, "%s",
                 skgl_error_log(ctx));
    /* without glGetTexLevelParameteriv: a mask texture never given a size */
    sd.technique = SKGL_STANDARD;
    sd.layered = 0;
    sd.resolution = 256;
    SK_CHECK(skgl_shadow_create(ctx, &sd, &s) == SK_OK);
    /* two textures of the caller's (the masks refuse a name that is none, and
       a light never rendered) */
    {
        void *q;
        tb_gl_getproc_fn gp = tb_gl_context_getproc(c);
        q = gp("glGenTextures"); memcpy(&gen_textures, &q, sizeof q);
        q = gp("glBindTexture"); memcpy(&bind_texture, &q, sizeof q);
        q = gp("glDeleteTextures"); memcpy(&delete_textures, &q, sizeof q);
        gen_textures(2, tex);
        bind_texture(0x0DE1 /* GL_TEXTURE_2D */, tex[0]);
        bind_texture(0x0DE1, tex[1]);
        bind_texture(0x0DE1, 0);
    }
    if (s) {
        skgl_camera cam = esx_camera();
        skgl_scene sc;
        memset(&sc, 0, sizeof sc);
        sc.draw = draw_nothing;
        sc.bounds.min.x = sc.bounds.min.y = sc.bounds.min.z = -5.0f;
        sc.bounds.max.x = sc.bounds.max.y = sc.bounds.max.z = 5.0f;
        SK_CHECK(skgl_shadow_render(ctx, s, &cam, &sc, esx_v3(-0.3f, -1.0f, -0.2f)) == SK_OK);
        SK_CHECK(skgl_shadow_mask(ctx, s, &cam, tex[0], 0, tex[1]) != SK_OK);
        SK_CHECK_MSG(strstr(skgl_error_log(ctx), "skgl_remember_texture") != NULL, "%s", skgl_error_log(ctx));
    }
    SK_CHECK(skgl_remember_texture(ctx, 0, 4, 4) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_remember_texture(ctx, tex[0], 0, 4) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_remember_texture(ctx, tex[0], 4, 70000) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_remember_texture(NULL, tex[0], 4, 4) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_remember_texture(ctx, tex[0], 4, 4) == SK_OK);
    delete_textures(2, tex);
    skgl_shadow_destroy(ctx, s);
    skgl_destroy(ctx);
    tb_gl_context_destroy(c);
}

/* the read-backs a frame late through the ring on ES 3.0 (no
   glGetBufferSubData: mapped): FERKO, RMSM and PVSM over ESX_FRAMES
   frames, each mask within the bounds of the desktop's (sync) one */
static void test_async_readbacks(const esx_scene *sc)
{
    static const char *names[3] = {"FERKO", "RMSM", "PVSM"};
    static esx_run r;
    int k;
    for (k = 0; k < 3; k++) {
        long maps = g_maps, subs = g_getsubs;
        int t, soft;
        double d;
        if (run_some(&r, TB_GL_CONTEXT_ES3, ES30_CAPS, sc, "es30 ring", names[k], 1) != 0) return;
        esx_only(&r, names[k]);
        t = r.tech;
        soft = esx_techs[t].kind == ESX_SOFT;
        SK_CHECK_MSG(r.result[t] == SK_OK, "%s: %s", names[k], r.why[t]);
        d = esx_mask_diff(g_desk.mask[t], r.mask[t], soft);
        printf("es30 ring %-5s vs desktop %.4f%s; %ld maps, %ld glGetBufferSubData\n", names[k], d, soft ? "" : "%",
               g_maps - maps, g_getsubs - subs);
        SK_CHECK_MSG(d <= (soft ? BOUND_SOFT_DIFF : BOUND_HARD_DIFF), "es30 ring %s: %.4f from the desktop", names[k], d);
        SK_CHECK_MSG(g_maps - maps >= 1 && g_getsubs == subs, "es30 ring %s: %ld maps, %ld glGetBufferSubData",
                     names[k], g_maps - maps, g_getsubs - subs);
    }
}

static void test_es(void)
{
    tb_scene scene;
    esx_scene sc;
    tb_reference *ref;
    static float vis[4][ESX_W * ESX_H], res[ESX_W * ESX_H];
    int t, pass;
    tb_scene_init(&scene);
    if (tb_scene_build_ground_boxes(&scene) != 0) { SK_CHECK(0); return; }
    sc = scene_of(&scene);

    /* the exact reference of the three lights */
    ref = tb_reference_create(&scene);
    SK_CHECK(ref != NULL);
    {
        skgl_camera cam = esx_camera();
        sk_mat4 vp = sk_mat4_mul(cam.proj, cam.view);
        tb_view view;
        tb_light l[3];
        skgl_area_light a = esx_area_light();
        memset(l, 0, sizeof l);
        sk_mat4_inverse(vp, &view.inv_view_proj);
        view.width = ESX_W;
        view.height = ESX_H;
        l[0].type = TB_LIGHT_DIRECTIONAL;
        l[0].direction = esx_sun_dir();
        l[1].type = TB_LIGHT_POINT;
        l[1].position = esx_point_pos();
        l[1].range = esx_point_range();
        l[2].type = TB_LIGHT_RECT;
        l[2].position = a.position;
        skgl_area_light_axes(&a, &l[2].half_u, &l[2].half_v);
        l[2].strata = 16;
        for (t = 0; t < 3 && ref; t++)
            SK_CHECK(tb_reference_trace_exact(ref, &view, NULL, &l[t], NULL, vis[t], NULL) == 0);
        if (getenv("SK_GL_TEST_ES_SPOT_UNCUT")) memcpy(vis[3], vis[1], sizeof vis[3]);   /* a broken reference */
        else esx_spot_reference(&sc, vis[1], vis[3]);   /* the spot's: the point light's cut by the cone */
    }

    if (run_all(&g_desk, 0, 0, &sc, "desktop") != 0) { SK_CHECK(0); return; }
    for (t = 0; t < ESX_TECHS; t++)
        SK_CHECK_MSG(g_desk.result[t] == SK_OK, "desktop %s: %s", esx_techs[t].name, g_desk.why[t]);

    for (pass = 0; pass < 2; pass++) {
        const char *label = pass == 0 ? "es" : "es30";
        if (run_all(&g_es, TB_GL_CONTEXT_ES3, pass == 0 ? 0u : ES30_CAPS, &sc, label) != 0) {
            printf("skipped: Mesa offers no OpenGL ES context here\n");
            break;
        }
        for (t = 0; t < ESX_TECHS; t++) {
            const esx_tech *e = &esx_techs[t];
            int soft = e->kind == ESX_SOFT, i;
            double d, err_es = -1.0, err_desk = -1.0;
            if (g_es.result[t] != SK_OK) {
                SK_CHECK_MSG(0, "%s %s: %s", label, e->name, g_es.why[t]);
                continue;
            }
            d = esx_mask_diff(g_desk.mask[t], g_es.mask[t], soft);
            if (!soft) {
                tb_shadow_error se;
                const float *rv = vis[e->kind == ESX_DIR ? 0 : e->kind == ESX_SPOT ? 3 : 1];
                for (i = 0; i < ESX_W * ESX_H; i++) res[i] = g_es.mask[t][i] / 255.0f;
                se = tb_metric_shadow(rv, res, ESX_W, ESX_H);
                err_es = se.area_pct;
                for (i = 0; i < ESX_W * ESX_H; i++) res[i] = g_desk.mask[t][i] / 255.0f;
                se = tb_metric_shadow(rv, res, ESX_W, ESX_H);
                err_desk = se.area_pct;
            } else {
                tb_penumbra_error pe;
                for (i = 0; i < ESX_W * ESX_H; i++) res[i] = g_es.mask[t][i] / 255.0f;
                pe = tb_metric_penumbra(vis[2], res, ESX_W, ESX_H, 2);
                err_es = pe.penumbra_mae;
                for (i = 0; i < ESX_W * ESX_H; i++) res[i] = g_desk.mask[t][i] / 255.0f;
                pe = tb_metric_penumbra(vis[2], res, ESX_W, ESX_H, 2);
                err_desk = pe.penumbra_mae;
            }
            printf("%-5s %-8s %s vs desktop %.4f%s; vs reference %.4f (desktop %.4f); GPU %.2f ms (desktop %.2f)\n",
                   label, e->name, soft ? "mean |diff|" : "pixels differ", d, soft ? "" : "%", err_es, err_desk,
                   g_es.ms[t], g_desk.ms[t]);
            SK_CHECK_MSG(d <= (soft ? BOUND_SOFT_DIFF : BOUND_HARD_DIFF), "%s %s: %.4f from the desktop mask",
                         label, e->name, d);
            SK_CHECK_MSG(err_es <= err_desk + (soft ? BOUND_SOFT_REF : BOUND_HARD_REF),
                         "%s %s: %.4f from the reference, desktop %.4f", label, e->name, err_es, err_desk);
            if (e->kind == ESX_SPOT)
                SK_CHECK_MSG(err_es <= BOUND_SPOT_REF && err_desk <= BOUND_SPOT_REF,
                             "%s spot: %.4f (desktop %.4f) from the reference > %g", label, err_es, err_desk,
                             BOUND_SPOT_REF);
        }
    }
    test_async_readbacks(&sc);
    tb_reference_destroy(ref);
    tb_scene_free(&scene);
}

SK_TEST_MAIN(test_caps_contracts, test_es, test_thin_casters)
