/* gl_exercise.h - one workout of every shadowkit_gl.h technique, for the
   hygiene tests (test_gl_census.c: GL objects and host memory created vs
   released; test_gl_debug.c: GL_KHR_debug messages). Include after
   gl_test_util.h.

   A case is one technique with one configuration. gx_run() drives it
   through everything the API offers on a context the caller made (and will
   destroy): create, three frames of analyze (FERKO, RMSM: the second frame
   on a G-buffer of another size, so the analysis targets are made again),
   render, deferred mask, forward draw through skgl_shadow_bind (directional)
   or skgl_point_bind (point lights), then destroy. Point-light cases move
   the light between frames; the shared-atlas case packs three VSDCT lights
   (one wanting more than fits, so the pack halves it) before each frame;
   area-light cases (PCSS, PVSM) move the light too and, in the second
   frame, let skgl_soft_render draw its own G-buffer (depth_tex = 0).
   Every call must return SK_OK; the number of calls checked is returned
   (-1 when the case could not run). */
#ifndef GL_EXERCISE_H
#define GL_EXERCISE_H

#define GX_W 320
#define GX_H 180
#define GX_SMALL_W 200   /* the second G-buffer size */
#define GX_SMALL_H 120
#define GX_FRAMES 3

typedef enum gx_kind { GX_CONTEXT = 0, GX_DIRECTIONAL = 1, GX_POINT = 2, GX_ATLAS = 3, GX_SOFT = 4, GX_ENGINE = 5 } gx_kind;

typedef struct gx_case {
    const char *name;
    gx_kind kind;
    skgl_technique technique;     /* GX_DIRECTIONAL */
    int resolution, cascades, stable, sync_readback;
    float blend_band;
    skgl_point_technique point;   /* GX_POINT */
    int optimized;                /* GX_POINT: face and caster culling, scissor, resolution selection */
    skgl_soft_technique soft;     /* GX_SOFT */
} gx_case;

static const gx_case gx_cases[] = {
    {"context", GX_CONTEXT, SKGL_STANDARD, 0, 0, 0, 0, 0.0f, SKGL_POINT_CUBE, 0, SKGL_SOFT_PCSS},
    {"standard", GX_DIRECTIONAL, SKGL_STANDARD, 512, 0, 0, 0, 0.0f, SKGL_POINT_CUBE, 0, SKGL_SOFT_PCSS},
    {"standard-stable", GX_DIRECTIONAL, SKGL_STANDARD, 512, 0, 1, 0, 0.0f, SKGL_POINT_CUBE, 0, SKGL_SOFT_PCSS},
    {"pssm", GX_DIRECTIONAL, SKGL_PSSM, 512, 4, 0, 0, 0.1f, SKGL_POINT_CUBE, 0, SKGL_SOFT_PCSS},
    {"pssm-stable", GX_DIRECTIONAL, SKGL_PSSM, 512, 3, 1, 0, 0.0f, SKGL_POINT_CUBE, 0, SKGL_SOFT_PCSS},
    {"psm", GX_DIRECTIONAL, SKGL_PSM, 512, 0, 0, 0, 0.0f, SKGL_POINT_CUBE, 0, SKGL_SOFT_PCSS},
    {"lispsm", GX_DIRECTIONAL, SKGL_LISPSM, 512, 0, 0, 0, 0.0f, SKGL_POINT_CUBE, 0, SKGL_SOFT_PCSS},
    {"lispsm-pssm", GX_DIRECTIONAL, SKGL_LISPSM, 512, 3, 0, 0, 0.1f, SKGL_POINT_CUBE, 0, SKGL_SOFT_PCSS},
    {"lspsm", GX_DIRECTIONAL, SKGL_LSPSM, 512, 0, 0, 0, 0.0f, SKGL_POINT_CUBE, 0, SKGL_SOFT_PCSS},
    {"ferko", GX_DIRECTIONAL, SKGL_FERKO, 1024, 0, 0, 1, 0.0f, SKGL_POINT_CUBE, 0, SKGL_SOFT_PCSS},
    {"ferko-late", GX_DIRECTIONAL, SKGL_FERKO, 1024, 0, 0, 1, 0.0f, SKGL_POINT_CUBE, 0, SKGL_SOFT_PCSS},
    {"rmsm", GX_DIRECTIONAL, SKGL_RMSM, 4096, 0, 0, 0, 0.0f, SKGL_POINT_CUBE, 0, SKGL_SOFT_PCSS},
    {"point-cube", GX_POINT, SKGL_STANDARD, 256, 0, 0, 0, 0.0f, SKGL_POINT_CUBE, 0, SKGL_SOFT_PCSS},
    {"point-cube-all", GX_POINT, SKGL_STANDARD, 256, 0, 0, 0, 0.0f, SKGL_POINT_CUBE, 1, SKGL_SOFT_PCSS},
    {"point-vsdct", GX_POINT, SKGL_STANDARD, 256, 0, 0, 0, 0.0f, SKGL_POINT_VSDCT, 0, SKGL_SOFT_PCSS},
    {"point-vsdct-all", GX_POINT, SKGL_STANDARD, 256, 0, 0, 0, 0.0f, SKGL_POINT_VSDCT, 1, SKGL_SOFT_PCSS},
    {"point-atlas", GX_ATLAS, SKGL_STANDARD, 256, 0, 0, 0, 0.0f, SKGL_POINT_VSDCT, 1, SKGL_SOFT_PCSS},
    {"soft-pcss", GX_SOFT, SKGL_STANDARD, 1024, 0, 0, 0, 0.0f, SKGL_POINT_CUBE, 0, SKGL_SOFT_PCSS},
    {"soft-pvsm", GX_SOFT, SKGL_STANDARD, 1024, 0, 0, 0, 0.0f, SKGL_POINT_CUBE, 0, SKGL_SOFT_PVSM},
    /* a caster program (varyings, a fragment hook) through layered PSSM, a
       layered cube and PVSM with its own G-buffer: every kind of program
       the hook is linked into */
    {"engine", GX_ENGINE, SKGL_PSSM, 512, 3, 0, 0, 0.0f, SKGL_POINT_CUBE, 0, SKGL_SOFT_PVSM},
};
#define GX_NCASES ((int)(sizeof gx_cases / sizeof gx_cases[0]))

/* the scene, its G-buffers at two sizes, a mask target for the small one,
   a forward program with skgl_glsl_snippet(); all made with the testbed's
   own GL table (never through a getproc a test wraps) */
typedef struct gx_env {
    gt_env e;
    tb_gl_fbo small_gbuf, small_mask;
    gt_forward fw;
    unsigned point_prog[2];   /* the point snippet, cube and VSDCT (gx_point_bind; made on first use) */
    float *vis, *depth;
    skgl_camera cam, small_cam;
    sk_vec3 light;
} gx_env;

static inline void gx_env_free(gx_env *x) {
    if (x->e.ctx) {
        gt_forward_destroy(&x->e, &x->fw);
        if (x->point_prog[0]) x->e.gl.DeleteProgram(x->point_prog[0]);
        if (x->point_prog[1]) x->e.gl.DeleteProgram(x->point_prog[1]);
        tb_gl_fbo_destroy(&x->e.gl, &x->small_gbuf);
        tb_gl_fbo_destroy(&x->e.gl, &x->small_mask);
    }
    free(x->vis);
    free(x->depth);
    gt_env_free(&x->e);
    memset(x, 0, sizeof *x);
}

/* 0 ok; the env's own skgl context is destroyed (each case makes its own).
   gx_env_init_on: on a context of that backend and tb_gl_context_create_flags
   flags; gx_env_init: OSMesa, no flags. */
static inline int gx_env_init_on(gx_env *x, tb_gl_backend backend, int flags) {
    sk_mat4 vp;
    tb_scene scene;
    memset(x, 0, sizeof *x);
    tb_scene_init(&scene);
    if (tb_scene_build(&scene, "ground-boxes") != 0) { tb_scene_free(&scene); SK_CHECK(0); return -1; }
    if (gt_env_init_context(&x->e, &scene, GX_W, GX_H, backend, flags) != 0) return -1;
    skgl_destroy(x->e.sk);
    x->e.sk = NULL;
    x->light = gt_v3(-0.5f, -1, -0.35f);
    x->cam = gt_camera(gt_v3(-9, 7, 12), gt_v3(0, 1, 0), 0.9f, 0.5f, 100, GX_W, GX_H);
    x->small_cam = gt_camera(gt_v3(-9, 7, 12), gt_v3(0, 1, 0), 0.9f, 0.5f, 100, GX_SMALL_W, GX_SMALL_H);
    x->vis = gt_alloc(&x->e);
    x->depth = gt_alloc(&x->e);
    vp = sk_mat4_mul(x->small_cam.proj, x->small_cam.view);
    if (!x->vis || !x->depth || gt_gbuffer(&x->e, &x->cam) != 0 || gt_forward_create(&x->e, &x->fw) != 0 ||
        tb_gl_fbo_create(&x->e.gl, &x->small_gbuf, GX_SMALL_W, GX_SMALL_H, TB_GL_COLOR_RGBA16F) != 0 ||
        tb_gl_fbo_create(&x->e.gl, &x->small_mask, GX_SMALL_W, GX_SMALL_H, TB_GL_COLOR_R16F) != 0 ||
        tb_gl_gbuffer_render(&x->e.gl, &x->e.gb, &x->e.mesh, &x->small_gbuf, &vp) != 0) {
        SK_CHECK_MSG(0, "gl_exercise: environment");
        return -1;
    }
    return 0;
}
static inline int gx_env_init(gx_env *x) { return gx_env_init_on(x, TB_GL_OSMESA, 0); }

/* set by a test that makes calls fail on purpose: failed calls are counted
   in gx_failed_calls instead of being reported as failed checks */
static int gx_expect_failures, gx_failed_calls;

/* counts the call, reports a failure with the case and call named */
static inline int gx_ok_(const char *cname, const char *call, int frame, sk_result r, const skgl_context *sk) {
    if (gx_expect_failures) {
        gx_failed_calls += r != SK_OK;
        return 1;
    }
    SK_CHECK_MSG(r == SK_OK, "%s frame %d: %s: %s (%s)", cname, frame, call, sk_result_string(r),
                 sk ? skgl_error_log(sk) : "");
    return 1;
}
#define GX_OK(call, r) (calls += gx_ok_(c->name, call, f, (r), sk))

static inline void gx_point_desc(const gx_case *c, skgl_point_desc *d) {
    memset(d, 0, sizeof *d);
    d->technique = c->point;
    d->resolution = c->resolution;
    d->range = 14.0f;
    d->cull_faces = d->cull_casters = d->scissor = d->select_resolution = c->optimized;
}

/* a program with the point snippet current, a point light bound to units
   6 and 7 (a bind to a program without the snippet is refused with
   desc.debug) */
static inline sk_result gx_point_bind(gx_env *x, skgl_context *sk, const skgl_point *p) {
    sk_result r;
    int vsdct = skgl_point_get_desc(p).technique == SKGL_POINT_VSDCT;
    if (!x->point_prog[vsdct]) x->point_prog[vsdct] = gt_point_program(&x->e.gl, vsdct);
    x->e.gl.UseProgram(x->point_prog[vsdct]);
    r = skgl_point_bind(sk, p, x->point_prog[vsdct], 6);
    x->e.gl.UseProgram(0);
    return r;
}

/* GX_ENGINE's callback: the mesh through the caster program */
typedef struct gx_engine {
    gt_env *e;
    skgl_context *sk;
    skgl_caster *hook;
} gx_engine;

static inline void gx_engine_draw(void *user, const skgl_draw_info *info) {
    gx_engine *g = (gx_engine *)user;
    (void)info;
    if (!skgl_use_caster(g->sk, g->hook)) return;   /* the render reports it */
    tb_gl_mesh_draw(&g->e->gl, &g->e->mesh, 0, 0);
}

static inline int gx_run_engine(gx_env *x, skgl_context *sk, const gx_case *c);

static inline int gx_run(gx_env *x, skgl_context *sk, const gx_case *c) {
    gt_env *e = &x->e;
    skgl_scene sc = gt_scene(e), psc = sc;
    int f = 0, calls = 0, i;
    psc.draw = gt_point_draw;
    if (c->kind == GX_CONTEXT) return 0;
    if (c->kind == GX_ENGINE) return gx_run_engine(x, sk, c);
    if (c->kind == GX_DIRECTIONAL) {
        skgl_shadow_desc d;
        skgl_shadow *s = NULL;
        memset(&d, 0, sizeof d);
        d.technique = c->technique;
        d.resolution = c->resolution;
        d.cascades = c->cascades;
        d.stable = c->stable;
        d.sync_readback = c->sync_readback;
        d.blend_band = c->blend_band;
        if (c->stable) d.max_distance = 45.0f;
        GX_OK("skgl_shadow_create", skgl_shadow_create(sk, &d, &s));
        if (!s) return -1;
        for (f = 0; f < GX_FRAMES; f++) {
            int small = f == 1;
            const skgl_camera *cam = small ? &x->small_cam : &x->cam;
            if (c->technique == SKGL_FERKO || c->technique == SKGL_RMSM)
                GX_OK("skgl_shadow_analyze", skgl_shadow_analyze(sk, s, cam, &sc, x->light,
                                                                 small ? x->small_gbuf.depth_tex : e->gbuf.depth_tex));
            GX_OK("skgl_shadow_render", skgl_shadow_render(sk, s, cam, &sc, x->light));
            if (small)
                GX_OK("skgl_shadow_mask", skgl_shadow_mask(sk, s, cam, x->small_gbuf.depth_tex,
                                                           x->small_gbuf.color_tex, x->small_mask.color_tex));
            else
                GX_OK("skgl_shadow_mask", skgl_shadow_mask(sk, s, cam, e->gbuf.depth_tex, e->gbuf.color_tex,
                                                           e->mask.color_tex));
            if (!small) {
                /* the forward path: gt_forward_render calls skgl_shadow_bind
                   with the env's context, this case's while it runs */
                int fr;
                e->sk = sk;
                fr = gt_forward_render(e, &x->fw, s, cam, 6, x->vis, x->depth);
                e->sk = NULL;
                if (gx_expect_failures) gx_failed_calls += fr != 0;
                else SK_CHECK_MSG(fr == 0, "%s: forward", c->name);
                calls++;
            }
        }
        skgl_shadow_destroy(sk, s);
        return calls;
    }
    if (c->kind == GX_SOFT) {
        skgl_soft_desc d;
        skgl_soft *so = NULL;
        memset(&d, 0, sizeof d);
        d.technique = c->soft;
        d.resolution = c->resolution;
        if (c->soft == SKGL_SOFT_PVSM) { d.lowres = 256; d.grid = 16; d.max_tiles = 16; }
        GX_OK("skgl_soft_create", skgl_soft_create(sk, &d, &so));
        if (!so) return -1;
        for (f = 0; f < GX_FRAMES; f++) {
            skgl_area_light l;
            memset(&l, 0, sizeof l);
            l.position = gt_v3(2.0f - (float)f, 9.0f, -2.5f + 0.5f * (float)f);
            l.direction = gt_v3(-0.3f, -1.0f, 0.4f);
            l.up = gt_v3(0, 0, 1);
            l.half_width = l.half_height = 0.3f;
            if (f == 1)   /* its own G-buffer, drawn through the callback */
                GX_OK("skgl_soft_render", skgl_soft_render(sk, so, &x->cam, &sc, &l, 0, 0, e->mask.color_tex));
            else
                GX_OK("skgl_soft_render", skgl_soft_render(sk, so, &x->cam, &sc, &l, e->gbuf.depth_tex,
                                                           e->gbuf.color_tex, e->mask.color_tex));
        }
        skgl_soft_destroy(sk, so);
        return calls;
    }
    if (c->kind == GX_POINT) {
        skgl_point_desc d;
        skgl_point *p = NULL;
        gx_point_desc(c, &d);
        GX_OK("skgl_point_create", skgl_point_create(sk, &d, &p));
        if (!p) return -1;
        for (f = 0; f < GX_FRAMES; f++) {
            sk_vec3 lp = gt_v3(0.5f + 1.5f * (float)f, 2.5f, 0.5f - (float)f);
            GX_OK("skgl_point_render", skgl_point_render(sk, p, &x->cam, &psc, lp));
            GX_OK("skgl_point_mask", skgl_point_mask(sk, p, &x->cam, e->gbuf.depth_tex, e->gbuf.color_tex,
                                                     e->mask.color_tex));
            GX_OK("skgl_point_bind", gx_point_bind(x, sk, p));
        }
        skgl_point_destroy(sk, p);
        return calls;
    }
    {
        /* GX_ATLAS: three lights in a 512 x 512 atlas; the first wants 256
           a face: 6 x 256^2 + 6 x 128^2 + 6 x 64^2 does not fit, so the
           pack halves it */
        skgl_point_atlas *a = NULL;
        skgl_point *lights[3] = {NULL, NULL, NULL};
        sk_vec3 lp[3];
        GX_OK("skgl_point_atlas_create", skgl_point_atlas_create(sk, 512, 512, &a));
        if (!a) return -1;
        for (i = 0; i < 3; i++) {
            skgl_point_desc d;
            gx_point_desc(c, &d);
            d.resolution = c->resolution >> i;
            d.select_resolution = i == 2;   /* one light chooses its side */
            d.atlas = a;
            GX_OK("skgl_point_create", skgl_point_create(sk, &d, &lights[i]));
        }
        for (f = 0; f < GX_FRAMES && lights[0] && lights[1] && lights[2]; f++) {
            for (i = 0; i < 3; i++) lp[i] = gt_v3(-3.0f + 3.0f * (float)i, 2.0f + 0.5f * (float)f, 1.0f - (float)f);
            GX_OK("skgl_point_atlas_pack", skgl_point_atlas_pack(sk, a, lights, 3, &x->cam, lp));
            for (i = 0; i < 3; i++) GX_OK("skgl_point_render", skgl_point_render(sk, lights[i], &x->cam, &psc, lp[i]));
            for (i = 0; i < 3; i++) {
                GX_OK("skgl_point_mask", skgl_point_mask(sk, lights[i], &x->cam, e->gbuf.depth_tex,
                                                         e->gbuf.color_tex, e->mask.color_tex));
                GX_OK("skgl_point_bind", gx_point_bind(x, sk, lights[i]));
            }
        }
        for (i = 0; i < 3; i++) skgl_point_destroy(sk, lights[i]);
        skgl_point_atlas_destroy(sk, a);
        return calls;
    }
}

static inline int gx_run_engine(gx_env *x, skgl_context *sk, const gx_case *c) {
    gt_env *e = &x->e;
    gx_engine g;
    skgl_scene sc = gt_scene(e);
    skgl_caster_desc cd;
    skgl_shadow_desc sd;
    skgl_point_desc pd;
    skgl_soft_desc so_d;
    skgl_caster *hook = NULL;
    skgl_shadow *s = NULL;
    skgl_point *p = NULL;
    skgl_soft *so = NULL;
    int f = 0, calls = 0;
    memset(&cd, 0, sizeof cd);
    cd.label = "engine";
    cd.vertex = "layout(location = 0) in vec3 a_pos;\n"
                "vec4 skgl_caster_position() { v_uv = a_pos.xz; return vec4(a_pos, 1.0); }\n";
    cd.fragment = "void skgl_caster_fragment() { if (v_uv.x > 1e6) discard; }\n";
    cd.varyings = "vec2 v_uv;";
    GX_OK("skgl_caster_create", skgl_caster_create(sk, &cd, &hook));
    if (!hook) return -1;
    g.e = e;
    g.sk = sk;
    g.hook = hook;
    sc.draw = gx_engine_draw;
    sc.user = &g;
    memset(&sd, 0, sizeof sd);
    sd.technique = c->technique;
    sd.resolution = c->resolution;
    sd.cascades = c->cascades;
    sd.layered = 1;
    memset(&pd, 0, sizeof pd);
    pd.resolution = 256;
    pd.range = 20.0f;
    pd.layered = 1;
    memset(&so_d, 0, sizeof so_d);
    so_d.technique = c->soft;
    so_d.resolution = 1024;
    so_d.lowres = 256; so_d.grid = 16; so_d.max_tiles = 16;
    GX_OK("skgl_shadow_create", skgl_shadow_create(sk, &sd, &s));
    GX_OK("skgl_point_create", skgl_point_create(sk, &pd, &p));
    GX_OK("skgl_soft_create", skgl_soft_create(sk, &so_d, &so));
    for (f = 0; f < GX_FRAMES && s && p && so; f++) {
        skgl_area_light l;
        memset(&l, 0, sizeof l);
        l.position = gt_v3(2.0f, 9.0f, -2.5f);
        l.direction = gt_v3(-0.3f, -1.0f, 0.4f);
        l.half_width = l.half_height = 0.3f;
        GX_OK("skgl_shadow_render", skgl_shadow_render(sk, s, &x->cam, &sc, x->light));
        GX_OK("skgl_shadow_mask", skgl_shadow_mask(sk, s, &x->cam, e->gbuf.depth_tex, e->gbuf.color_tex,
                                                   e->mask.color_tex));
        GX_OK("skgl_point_render", skgl_point_render(sk, p, &x->cam, &sc, gt_v3(0.5f, 2.5f, 0.5f)));
        GX_OK("skgl_point_mask", skgl_point_mask(sk, p, &x->cam, e->gbuf.depth_tex, e->gbuf.color_tex,
                                                 e->mask.color_tex));
        GX_OK("skgl_soft_render", skgl_soft_render(sk, so, &x->cam, &sc, &l, 0, 0, e->mask.color_tex));
    }
    skgl_soft_destroy(sk, so);
    skgl_point_destroy(sk, p);
    skgl_shadow_destroy(sk, s);
    skgl_caster_destroy(sk, hook);
    return calls;
}
#undef GX_OK

#endif /* GL_EXERCISE_H */
