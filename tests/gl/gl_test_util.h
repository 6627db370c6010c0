/* gl_test_util.h - what the GL tests share: an OSMesa context, a scene on
   the GPU, the camera G-buffer (window depth + world normals), the exact
   Embree reference (tb_reference_trace_exact: primary rays through the
   pixel centres, pixels whose rasterised surface differs from the traced
   one left out as TB_VIS_SILHOUETTE, back-facing receivers left out as
   TB_VIS_BACKFACING), and shadowkit_gl.h's deferred mask read back. Include after shadowkit_gl.h (with its
   implementation) and sk_test.h. All functions are static inline.

   One frame of a test:
       gt_env e;  gt_env_init(&e, scene, W, H)      (takes the scene)
       skgl_camera cam = gt_camera(eye, target, fovy, zn, zf, W, H);
       gt_gbuffer(&e, &cam);                       depth + normals of this view
       gt_reference(&e, light_dir, ref);           exact visibility per pixel
       gt_mask(&e, shadow, &cam, light_dir, res);  skgl_shadow_render + skgl_shadow_mask
       tb_hard_error err = tb_metric_hard(ref, res, W * H);
   Images go under out/tests/ (error image: red false lit, blue false shadow). */
#ifndef GL_TEST_UTIL_H
#define GL_TEST_UTIL_H

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "tb_closed_form.h"
#include "tb_gl_context.h"
#include "tb_gl_fbo.h"
#include "tb_gl_funcs.h"
#include "tb_gl_scene.h"
#include "tb_image.h"
#include "tb_metrics.h"
#include "tb_reference.h"
#include "tb_scene.h"

#include "gl_forward_vs.h"

typedef struct gt_env {
    tb_gl_context *ctx;
    tb_gl_funcs gl;
    skgl_context *sk;
    tb_scene scene;
    tb_gl_mesh mesh;
    tb_gl_gbuffer gb;
    tb_gl_fbo gbuf;        /* RGBA16F world normals + DEPTH_COMPONENT32F */
    tb_gl_fbo mask;        /* R16F visibility (skgl_shadow_mask target) */
    tb_reference *ref;
    int w, h;
    size_t n;              /* w * h */
    float *depth;          /* window depth of the last gt_gbuffer, row 0 at the bottom */
    float *normals;        /* 3 per pixel, world space, facing the camera; 0 on background */
    float *rgba;           /* scratch */
    sk_mat4 inv_vp;        /* of the last gt_gbuffer */
    sk_mat4 view;          /* of the last gt_gbuffer */
    tb_ref_stats ref_stats;/* pixel counts of the last gt_reference */
} gt_env;

static inline sk_vec3 gt_v3(float x, float y, float z) { sk_vec3 r; r.x = x; r.y = y; r.z = z; return r; }

static inline sk_aabb gt_box(float x0, float y0, float z0, float x1, float y1, float z1) {
    sk_aabb b;
    b.min = gt_v3(x0, y0, z0);
    b.max = gt_v3(x1, y1, z1);
    return b;
}

/* a directional light's desc: the technique and its map layout, every
   other field its default */
static inline skgl_shadow_desc gt_shadow_desc(skgl_technique technique, int resolution, int cascades, int stable) {
    skgl_shadow_desc d;
    memset(&d, 0, sizeof d);
    d.technique = technique;
    d.resolution = resolution;
    d.cascades = cascades;
    d.stable = stable;
    return d;
}

/* FERKO's analysis programs and RMSM's are made with the first light that
   needs them and kept with the context until skgl_destroy: a light of each
   made and destroyed here, so that an object count taken afterwards comes
   back to itself once the lights a test makes are destroyed */
static inline void gt_warm_programs(skgl_context *sk) {
    skgl_shadow_desc d = gt_shadow_desc(SKGL_FERKO, 1024, 1, 0);
    skgl_shadow *s = NULL;
    if (skgl_shadow_create(sk, &d, &s) == SK_OK) skgl_shadow_destroy(sk, s);
#ifndef SKGL_NO_RMSM
    d.technique = SKGL_RMSM;
    s = NULL;
    if (skgl_shadow_create(sk, &d, &s) == SK_OK) skgl_shadow_destroy(sk, s);
#endif
}

/* one row of a printed table: a label, then n names or n values */
static inline void gt_print_names(const char *label, const char *const *names, int n) {
    int i;
    printf("%-14s", label);
    for (i = 0; i < n; i++) printf(" %9s", names[i]);
    printf("\n");
}
static inline void gt_print_values(const char *label, const double *v, int n) {
    int i;
    printf("%-14s", label);
    for (i = 0; i < n; i++) printf(" %9.4f", v[i]);
    printf("\n");
}

/* a perspective camera for a w x h image; up = +y */
static inline skgl_camera gt_camera(sk_vec3 eye, sk_vec3 target, float fovy, float zn, float zf, int w, int h) {
    skgl_camera c;
    c.view = sk_mat4_look_at(eye, target, gt_v3(0, 1, 0));
    c.proj = sk_mat4_perspective(fovy, (float)w / (float)h, zn, zf);
    return c;
}

/* the draw callback: the whole mesh with shadowkit's depth program */
static inline void gt_draw(void *user, const skgl_draw_info *info) {
    gt_env *e = (gt_env *)user;
    (void)info;
    tb_gl_mesh_draw(&e->gl, &e->mesh, 0, 0);
}

static inline skgl_scene gt_scene(gt_env *e) {
    skgl_scene sc;
    sc.draw = gt_draw;
    sc.user = e;
    sc.bounds = e->scene.bounds;
    return sc;
}

static inline void gt_env_free(gt_env *e) {
    if (e->sk) skgl_destroy(e->sk);
    if (e->ctx) {
        tb_gl_gbuffer_destroy(&e->gl, &e->gb);
        tb_gl_mesh_destroy(&e->gl, &e->mesh);
        tb_gl_fbo_destroy(&e->gl, &e->gbuf);
        tb_gl_fbo_destroy(&e->gl, &e->mask);
        tb_gl_context_destroy(e->ctx);
    }
    tb_reference_destroy(e->ref);
    tb_scene_free(&e->scene);
    free(e->depth); free(e->normals); free(e->rgba);
    memset(e, 0, sizeof *e);
}

/* gt_env_init on a context of the given backend and tb_gl_context_create_flags
   flags (TB_GL_CONTEXT_DEBUG) */
static inline int gt_env_init_context(gt_env *e, tb_scene *scene, int w, int h, tb_gl_backend backend, int flags);

/* Takes ownership of *scene (left empty). OSMesa forced: what CI runs.
   0 ok; -1 with the reason printed (and counted as a failed check). */
static inline int gt_env_init(gt_env *e, tb_scene *scene, int w, int h) {
    return gt_env_init_context(e, scene, w, h, TB_GL_OSMESA, 0);
}

static inline int gt_env_init_context(gt_env *e, tb_scene *scene, int w, int h, tb_gl_backend backend, int flags) {
    char err[1024] = "";
    skgl_desc d;
    sk_result r;
    memset(e, 0, sizeof *e);
    e->scene = *scene;
    tb_scene_init(scene);
    e->w = w;
    e->h = h;
    e->n = (size_t)w * (size_t)h;
    e->depth = (float *)malloc(sizeof(float) * e->n);
    e->normals = (float *)malloc(sizeof(float) * 3 * e->n);
    e->rgba = (float *)malloc(sizeof(float) * 4 * e->n);
    if (!e->depth || !e->normals || !e->rgba) { SK_CHECK_MSG(0, "out of memory"); return -1; }
    e->ctx = tb_gl_context_create_flags(backend, flags, err, sizeof err);
    if (!e->ctx) { SK_CHECK_MSG(0, "GL context: %s", err); return -1; }
    if (tb_gl_funcs_load(&e->gl, tb_gl_context_getproc(e->ctx)) != 0 ||
        tb_gl_fbo_create(&e->gl, &e->gbuf, w, h, TB_GL_COLOR_RGBA16F) != 0 ||
        tb_gl_fbo_create(&e->gl, &e->mask, w, h, TB_GL_COLOR_R16F) != 0 ||
        tb_gl_mesh_create(&e->gl, &e->mesh, &e->scene) != 0 ||
        tb_gl_gbuffer_create(&e->gl, &e->gb, err, sizeof err) != 0) {
        SK_CHECK_MSG(0, "testbed GL setup failed: %s", err);
        return -1;
    }
    e->ref = tb_reference_create(&e->scene);
    if (!e->ref) { SK_CHECK_MSG(0, "Embree scene"); return -1; }
    memset(&d, 0, sizeof d);
    d.getproc = (skgl_getproc_fn)tb_gl_context_getproc(e->ctx);
    d.debug = 1;
    r = skgl_create(&d, &e->sk);
    if (r != SK_OK) {
        SK_CHECK_MSG(0, "skgl_create: %s (%s)", sk_result_string(r), e->sk ? skgl_error_log(e->sk) : "");
        return -1;
    }
    return 0;
}

static inline int gt_env_init_named(gt_env *e, const char *name, int w, int h) {
    tb_scene s;
    tb_scene_init(&s);
    if (tb_scene_build(&s, name) != 0) { SK_CHECK_MSG(0, "scene %s", name); tb_scene_free(&s); return -1; }
    return gt_env_init(e, &s, w, h);
}

/* G-buffer of this camera: e->depth, e->normals (and the textures in e->gbuf) */
static inline int gt_gbuffer(gt_env *e, const skgl_camera *cam) {
    sk_mat4 vp = sk_mat4_mul(cam->proj, cam->view);
    if (!sk_mat4_inverse(vp, &e->inv_vp)) return -1;
    e->view = cam->view;
    if (tb_gl_gbuffer_render(&e->gl, &e->gb, &e->mesh, &e->gbuf, &vp) != 0) return -1;
    if (tb_gl_read_depth(&e->gl, e->gbuf.fbo, e->w, e->h, e->depth) != 0) return -1;
    if (tb_gl_read_normals(&e->gl, e->gbuf.fbo, e->w, e->h, e->rgba, e->normals) != 0) return -1;
    return 0;
}

static inline tb_light gt_sun(sk_vec3 dir) {
    tb_light l;
    memset(&l, 0, sizeof l);
    l.type = TB_LIGHT_DIRECTIONAL;
    l.direction = dir;
    return l;
}

/* the reference's options over the last G-buffer: its normals go to the
   same-face test (tb_ref_options.raster_normals) */
static inline tb_ref_options gt_ref_options(const gt_env *e) {
    tb_ref_options opt;
    memset(&opt, 0, sizeof opt);
    opt.raster_normals = e->normals;
    return opt;
}

/* The exact reference of a sun over the last G-buffer (its raster depth
   and normals decide the silhouettes): 1 lit, 0 shadowed, < 0 not counted
   (TB_VIS_BACKGROUND, TB_VIS_BACKFACING, TB_VIS_SILHOUETTE). The counts go
   to e->ref_stats; SK_GL_TEST_REF_STATS=1 prints them. */
static inline int gt_reference(gt_env *e, sk_vec3 light_dir, float *vis) {
    tb_view v;
    tb_light l = gt_sun(light_dir);
    tb_ref_options opt = gt_ref_options(e);
    const char *pr = getenv("SK_GL_TEST_REF_STATS");
    int r;
    v.inv_view_proj = e->inv_vp;
    v.width = e->w;
    v.height = e->h;
    r = tb_reference_trace_exact(e->ref, &v, e->depth, &l, &opt, vis, &e->ref_stats);
    if (pr && *pr && *pr != '0')
        printf("gt_reference: %llu pixels, %llu covered, %llu background, %llu back-facing, %llu silhouette "
               "(%.4f%%)\n",
               (unsigned long long)e->ref_stats.pixels, (unsigned long long)e->ref_stats.covered,
               (unsigned long long)e->ref_stats.background, (unsigned long long)e->ref_stats.backfacing,
               (unsigned long long)e->ref_stats.silhouette,
               e->ref_stats.pixels ? 100.0 * (double)e->ref_stats.silhouette / (double)e->ref_stats.pixels : 0.0);
    return r;
}

/* e->mask read back into vis, the last G-buffer's background pixels -1
   (like the reference); 0 ok */
static inline int gt_read_mask(gt_env *e, float *vis) {
    size_t i;
    if (tb_gl_read_texture_red(&e->gl, e->mask.color_tex, e->w, e->h, vis) != 0) return -1;
    for (i = 0; i < e->n; i++) if (!(e->depth[i] < 1.0f)) vis[i] = -1.0f;
    return 0;
}

/* skgl_shadow_render for cam, then skgl_shadow_mask over the last G-buffer
   (which must be of the same camera unless the test wants otherwise), read
   back into vis. Background pixels get -1 (like the reference). */
static inline int gt_mask_only(gt_env *e, skgl_shadow *s, const skgl_camera *cam, float *vis) {
    sk_result r = skgl_shadow_mask(e->sk, s, cam, e->gbuf.depth_tex, e->gbuf.color_tex, e->mask.color_tex);
    if (r != SK_OK) {
        printf("skgl_shadow_mask: %s (%s)\n", sk_result_string(r), skgl_error_log(e->sk));
        return -1;
    }
    return gt_read_mask(e, vis);
}

static inline int gt_mask(gt_env *e, skgl_shadow *s, const skgl_camera *cam, sk_vec3 light_dir, float *vis) {
    skgl_scene sc = gt_scene(e);
    sk_result r = skgl_shadow_render(e->sk, s, cam, &sc, light_dir);
    if (r != SK_OK) {
        printf("skgl_shadow_render: %s (%s)\n", sk_result_string(r), skgl_error_log(e->sk));
        return -1;
    }
    return gt_mask_only(e, s, cam, vis);
}

/* the draw callback of a point light or a spot: the objects
   skgl_point_caster_visible passes (user: the gt_env) */
static inline void gt_point_draw(void *user, const skgl_draw_info *info) {
    gt_env *e = (gt_env *)user;
    uint32_t i;
    for (i = 0; i < e->scene.object_count; i++) {
        const tb_object *o = &e->scene.objects[i];
        if (skgl_point_caster_visible(info, o->bounds))
            tb_gl_mesh_draw(&e->gl, &e->mesh, o->first_index, o->index_count);
    }
}

/* skgl_point_mask of p, already rendered for cam, over the last G-buffer
   into e->mask cleared to `clear` first (the mask pass's scissor leaves
   the rest as it is), read back as gt_read_mask does. 0 ok. */
static inline int gt_point_mask(gt_env *e, skgl_point *p, const skgl_camera *cam, float clear, float *vis) {
    sk_result r;
    tb_gl_fbo_bind(&e->gl, &e->mask);
    e->gl.ClearColor(clear, 0, 0, 0);
    e->gl.Clear(0x00004000u);   /* GL_COLOR_BUFFER_BIT */
    tb_gl_fbo_bind(&e->gl, NULL);
    r = skgl_point_mask(e->sk, p, cam, e->gbuf.depth_tex, e->gbuf.color_tex, e->mask.color_tex);
    if (r != SK_OK) {
        printf("skgl_point_mask: %s (%s)\n", sk_result_string(r), skgl_error_log(e->sk));
        return -1;
    }
    return gt_read_mask(e, vis);
}

/* the can-fail experiments' bias knob, applied to every shadow gt_shadow
   creates (and every point light a test creates through gt_point_bias),
   whatever the test asked for; the tests' comments give the figures:
     SK_GL_TEST_BIAS=normal-offset  the normal-offset bias
                                    (SKGL_BIAS_NORMAL_OFFSET, its defaults)
     SK_GL_TEST_BIAS=none           no bias at all: the plain depth
                                    comparison (normal-offset mode with no
                                    offset, no polygon offset)
   Unset: the desc as given. Returns 1 (normal-offset), 2 (none) or 0. */
static inline int gt_bias_knob(void) {
    const char *s = getenv("SK_GL_TEST_BIAS");
    if (!s) return 0;
    return strcmp(s, "normal-offset") == 0 ? 1 : strcmp(s, "none") == 0 ? 2 : 0;
}

static inline void gt_point_bias(skgl_point_desc *d) {
    int k = gt_bias_knob();
    if (k == 1) d->bias = SKGL_BIAS_NORMAL_OFFSET;
    if (k == 2) {
        d->bias = SKGL_BIAS_NONE;
        d->disable_polygon_offset = 1;
    }
}

static inline skgl_shadow *gt_shadow(gt_env *e, const skgl_shadow_desc *desc) {
    skgl_shadow *s = NULL;
    skgl_shadow_desc dd = *desc;
    const skgl_shadow_desc *d = &dd;
    sk_result r;
    int k = gt_bias_knob();
    if (k == 1) dd.bias = SKGL_BIAS_NORMAL_OFFSET;
    if (k == 2) {
        dd.bias = SKGL_BIAS_NONE;
        dd.disable_polygon_offset = 1;
    }
    r = skgl_shadow_create(e->sk, d, &s);
    if (r != SK_OK) {
        SK_CHECK_MSG(0, "skgl_shadow_create: %s (%s)", sk_result_string(r), skgl_error_log(e->sk));
        return NULL;
    }
    return s;
}

/* world position of pixel i of the last G-buffer; 0 ok, -1 background */
static inline int gt_world(const gt_env *e, size_t i, double out[3]) {
    if (!(e->depth[i] < 1.0f)) return -1;
    return tb_unproject_pixel(&e->inv_vp, e->w, e->h, (int)(i % (size_t)e->w), (int)(i / (size_t)e->w),
                              e->depth[i], out);
}

/* view depth (distance along the view axis) of pixel i; -1 on background */
static inline double gt_view_depth(const gt_env *e, size_t i) {
    double p[3];
    const float *m = e->view.m;
    if (gt_world(e, i, p)) return -1.0;
    return -(m[2] * p[0] + m[6] * p[1] + m[10] * p[2] + m[14]);
}

/* writes out/tests/<name>.png (visibility) and out/tests/<name>-error.png */
static inline void gt_images(const gt_env *e, const char *name, const float *ref, const float *res) {
    char path[256];
    snprintf(path, sizeof path, "out/tests/%s.png", name);
    tb_image_write_visibility(path, e->w, e->h, res);
    snprintf(path, sizeof path, "out/tests/%s-error.png", name);
    tb_image_write_error(path, e->w, e->h, ref, res);
}

/* 1 when pixel i's reference class differs from a pixel within r pixels
   (Chebyshev): near a shadow boundary, where aliasing, not bias, decides */
static inline int gt_near_boundary(const gt_env *e, const float *ref, size_t i, int r) {
    int x0 = (int)(i % (size_t)e->w), y0 = (int)(i / (size_t)e->w), x, y;
    int c = tb_visibility_class(ref[i]);
    for (y = y0 - r; y <= y0 + r; y++)
        for (x = x0 - r; x <= x0 + r; x++) {
            int k;
            if (x < 0 || y < 0 || x >= e->w || y >= e->h) continue;
            k = tb_visibility_class(ref[(size_t)y * (size_t)e->w + (size_t)x]);
            if (k >= 0 && k != c) return 1;
        }
    return 0;
}

/* ---- the forward path: a tiny shader containing skgl_glsl_snippet() ---- */
typedef struct gt_forward {
    unsigned program;
    int u_view_proj, u_view;
    tb_gl_fbo fbo;         /* R16F visibility + depth, the env's size */
} gt_forward;

static const char gt_forward_vs[] = GT_FORWARD_VS;   /* gl_forward_vs.h */
/* the snippet goes between the #version line and this */
static const char gt_forward_fs[] =
    "in vec3 v_world;\n"
    "in vec3 v_normal;\n"
    "in float v_view_depth;\n"
    "out float o_visibility;\n"
    "void main() {\n"
    "    vec3 n = normalize(v_normal);\n"
    "    o_visibility = sk_shadow(v_world, gl_FrontFacing ? n : -n, v_view_depth);\n"
    "}\n";

static inline unsigned gt_compile(const tb_gl_funcs *gl, unsigned type, int count, const char *const *src) {
    unsigned sh = gl->CreateShader(type);
    int ok = 0;
    gl->ShaderSource(sh, count, src, NULL);
    gl->CompileShader(sh);
    gl->GetShaderiv(sh, 0x8B81 /* COMPILE_STATUS */, &ok);
    if (!ok) {
        char log[2048] = "";
        gl->GetShaderInfoLog(sh, (int)sizeof log, NULL, log);
        SK_CHECK_MSG(0, "forward shader: %s", log);
        gl->DeleteShader(sh);
        return 0;
    }
    return sh;
}

/* 0 ok */
static inline int gt_forward_create(gt_env *e, gt_forward *f) {
    const tb_gl_funcs *gl = &e->gl;
    const char *vs[1], *fs[3];
    unsigned v, g;
    int ok = 0;
    memset(f, 0, sizeof *f);
    vs[0] = gt_forward_vs;
    fs[0] = "#version 330 core\n";
    fs[1] = skgl_glsl_snippet();
    fs[2] = gt_forward_fs;
    v = gt_compile(gl, 0x8B31 /* VERTEX_SHADER */, 1, vs);
    g = gt_compile(gl, 0x8B30 /* FRAGMENT_SHADER */, 3, fs);
    if (!v || !g) { if (v) gl->DeleteShader(v); if (g) gl->DeleteShader(g); return -1; }
    f->program = gl->CreateProgram();
    gl->AttachShader(f->program, v);
    gl->AttachShader(f->program, g);
    gl->LinkProgram(f->program);
    gl->DeleteShader(v);
    gl->DeleteShader(g);
    gl->GetProgramiv(f->program, 0x8B82 /* LINK_STATUS */, &ok);
    if (!ok) {
        char log[2048] = "";
        gl->GetProgramInfoLog(f->program, (int)sizeof log, NULL, log);
        SK_CHECK_MSG(0, "forward program: %s", log);
        gl->DeleteProgram(f->program);
        f->program = 0;
        return -1;
    }
    f->u_view_proj = gl->GetUniformLocation(f->program, "u_view_proj");
    f->u_view = gl->GetUniformLocation(f->program, "u_view");
    if (tb_gl_fbo_create(gl, &f->fbo, e->w, e->h, TB_GL_COLOR_R16F) != 0) {
        gl->DeleteProgram(f->program);
        f->program = 0;
        return -1;
    }
    return 0;
}

/* the program of vertex sources vs[0, nv) and fragment sources fs[0, nf),
   its shaders deleted, *linked its LINK_STATUS; 0 when a shader did not
   compile (gt_compile's failed check) */
static inline unsigned gt_program(const tb_gl_funcs *gl, int nv, const char *const *vs, int nf,
                                  const char *const *fs, int *linked) {
    unsigned sh[2], prog = 0;
    int i;
    sh[0] = gt_compile(gl, 0x8B31 /* VERTEX_SHADER */, nv, vs);
    sh[1] = gt_compile(gl, 0x8B30 /* FRAGMENT_SHADER */, nf, fs);
    *linked = 0;
    if (sh[0] && sh[1]) {
        prog = gl->CreateProgram();
        for (i = 0; i < 2; i++) gl->AttachShader(prog, sh[i]);
        gl->LinkProgram(prog);
        gl->GetProgramiv(prog, 0x8B82 /* LINK_STATUS */, linked);
    }
    for (i = 0; i < 2; i++) if (sh[i]) gl->DeleteShader(sh[i]);
    return prog;
}

/* the program of vertex shader vs and fragment body `body` under the point
   snippet (VSDCT's with vsdct), *linked its LINK_STATUS; 0 when a shader
   did not compile */
static inline unsigned gt_point_program_of(const tb_gl_funcs *gl, int vsdct, const char *vs, const char *body,
                                           int *linked) {
    const char *v[1], *f[4];
    v[0] = vs;
    f[0] = "#version 330 core\n";
    f[1] = vsdct ? "#define SK_POINT_VSDCT 1\n" : "";
    f[2] = skgl_point_glsl_snippet();
    f[3] = body;
    return gt_program(gl, 1, v, 4, f, linked);
}

/* a program holding the point snippet (VSDCT's with vsdct), for
   skgl_point_bind; 0 on failure (a failed check) */
static inline unsigned gt_point_program(const tb_gl_funcs *gl, int vsdct) {
    static const char vs[] = "#version 330 core\nlayout(location = 0) in vec3 a_position;\nout vec3 v_world;\n"
                             "void main() { v_world = a_position; gl_Position = vec4(a_position, 1.0); }\n";
    static const char body[] = "in vec3 v_world;\nout float o_visibility;\n"
                               "void main() { o_visibility = sk_point_shadow(v_world, vec3(0.0, 1.0, 0.0)); }\n";
    int ok = 0;
    unsigned prog = gt_point_program_of(gl, vsdct, vs, body, &ok);
    if (!prog) return 0;
    SK_CHECK_MSG(ok, "point program did not link");
    if (!ok) { gl->DeleteProgram(prog); return 0; }
    return prog;
}

static inline void gt_forward_destroy(gt_env *e, gt_forward *f) {
    if (f->program) e->gl.DeleteProgram(f->program);
    tb_gl_fbo_destroy(&e->gl, &f->fbo);
    memset(f, 0, sizeof *f);
}

/* The start of a forward pass for cam: f's target bound and cleared
   (visibility -1, depth 1), the depth test on, f's program in use with
   cam's matrices. The caller binds a light and draws, then
   gt_forward_unbind and gt_forward_read. */
static inline void gt_forward_begin(gt_env *e, gt_forward *f, const skgl_camera *cam) {
    const tb_gl_funcs *gl = &e->gl;
    sk_mat4 vp = sk_mat4_mul(cam->proj, cam->view);
    tb_gl_fbo_bind(gl, &f->fbo);
    gl->ClearColor(-1.0f, 0, 0, 0);
    gl->ClearDepth(1.0);
    gl->Clear(0x00004000u | 0x00000100u);
    gl->Enable(0x0B71 /* DEPTH_TEST */);
    gl->DepthFunc(0x0201 /* LESS */);
    gl->UseProgram(f->program);
    gl->UniformMatrix4fv(f->u_view_proj, 1, 0, vp.m);
    gl->UniformMatrix4fv(f->u_view, 1, 0, cam->view.m);
}

static inline void gt_forward_unbind(gt_env *e) {
    e->gl.UseProgram(0);
    tb_gl_fbo_bind(&e->gl, NULL);
}

/* the pass's visibility into vis (-1 where it drew nothing) and its depth
   into depth; 0 ok */
static inline int gt_forward_read(gt_env *e, gt_forward *f, float *vis, float *depth) {
    size_t i;
    if (tb_gl_read_red(&e->gl, f->fbo.fbo, e->w, e->h, vis) != 0) return -1;
    if (tb_gl_read_depth(&e->gl, f->fbo.fbo, e->w, e->h, depth) != 0) return -1;
    for (i = 0; i < e->n; i++) if (!(depth[i] < 1.0f)) vis[i] = -1.0f;
    return 0;
}

/* Draws the scene with the forward shader for cam, the map of s (already
   rendered for cam) bound to texture unit `unit`; reads visibility back
   (-1 where the forward pass drew nothing). 0 ok. */
static inline int gt_forward_render(gt_env *e, gt_forward *f, const skgl_shadow *s, const skgl_camera *cam,
                                    int unit, float *vis, float *depth) {
    sk_result r;
    gt_forward_begin(e, f, cam);
    r = skgl_shadow_bind(e->sk, s, f->program, unit);
    if (r != SK_OK) {
        SK_CHECK_MSG(0, "skgl_shadow_bind: %s (%s)", sk_result_string(r), skgl_error_log(e->sk));
        gt_forward_unbind(e);
        return -1;
    }
    tb_gl_mesh_draw(&e->gl, &e->mesh, 0, 0);
    gt_forward_unbind(e);
    return gt_forward_read(e, f, vis, depth);
}

/* a scale for the can-fail experiments: SK_GL_TEST_RES_SCALE=0.25 runs the
   accuracy tests at a quarter of their shadow-map resolution (they must then
   fail; the figures are in the tests' comments). Unset: 1. */
static inline double gt_res_scale(void) {
    const char *s = getenv("SK_GL_TEST_RES_SCALE");
    double v = s && *s ? atof(s) : 1.0;
    return v > 0.0 && v <= 4.0 ? v : 1.0;
}

static inline float *gt_alloc(const gt_env *e) { return (float *)malloc(sizeof(float) * e->n); }

/* The hard-shadow scores of one result against the exact reference: the
   shadow-area error (tb_metric_shadow: misclassified pixels over the
   reference's shadowed ones, false shadow and false light apart, edge
   displacement) and the covered % (tb_metric_hard's pct, the same wrong
   pixels over every covered one). ok = 0 when it could not be computed. */
static inline tb_shadow_error gt_shadow_error(const gt_env *e, const float *ref, const float *res) {
    return tb_metric_shadow(ref, res, e->w, e->h);
}

/* "area 0.1234% (covered 0.0123%; false shadow 0.05%, false light 0.07%,
   edge mean 0.62 p95 1.21 px; 12 wrong of 9731 shadow px)" into buf */
static inline const char *gt_shadow_error_str(const tb_shadow_error *se, char *buf, size_t size) {
    snprintf(buf, size,
             "area %.4f%% (covered %.4f%%; false shadow %.4f%%, false light %.4f%%, edge mean %.2f p95 %.2f px; "
             "%llu wrong of %llu shadow px)",
             se->area_pct, se->covered_pct, se->false_shadow_pct, se->false_light_pct, se->edge_mean_px,
             se->edge_p95_px, (unsigned long long)se->wrong, (unsigned long long)se->shadow);
    return buf;
}

/* One frame of a directional technique (render + mask of the last G-buffer)
   scored against ref: the error (covered % and the shadow-area error), the
   stats, whether every layer matrix is finite, and the share of the
   reference's shadowed pixels the mask calls lit. pct < 0 when the frame
   failed. image: out/tests/<image>*.png or NULL. */
typedef struct gt_run_result {
    double pct;
    tb_shadow_error se;
    skgl_shadow_frame_stats st;
    int finite;
    size_t shadowed;
    double false_lit_pct;
} gt_run_result;

static inline gt_run_result gt_run(gt_env *e, const skgl_camera *cam, sk_vec3 light, const float *ref,
                                   const skgl_shadow_desc *d, const char *image) {
    gt_run_result w;
    skgl_shadow *s = gt_shadow(e, d);
    float *mask = gt_alloc(e);
    int i, k;
    memset(&w, 0, sizeof w);
    w.pct = -1;
    if (s && mask && gt_mask(e, s, cam, light, mask) == 0) {
        tb_hard_error he = tb_metric_hard(ref, mask, e->n);
        size_t j;
        for (j = 0; j < e->n; j++) w.shadowed += ref[j] >= 0 && tb_visibility_class(ref[j]) == 0;
        w.pct = he.pct;
        w.se = gt_shadow_error(e, ref, mask);
        w.false_lit_pct = w.shadowed ? 100.0 * (double)he.false_lit / (double)w.shadowed : 0.0;
        w.st = *skgl_shadow_stats(s);
        w.finite = 1;
        for (i = 0; i < w.st.maps; i++) {
            sk_mat4 m = skgl_shadow_matrix(s, i);
            for (k = 0; k < 16; k++) if (!isfinite(m.m[k])) w.finite = 0;
        }
        if (image) gt_images(e, image, ref, mask);
    }
    SK_CHECK_MSG(e->gl.GetError() == 0, "GL error");
    free(mask);
    skgl_shadow_destroy(e->sk, s);
    return w;
}

/* ---- area lights (skgl_soft_*) ----------------------------------------- */
/* the reference for an area light: strata^2 stratified samples (>= 256) */
static inline int gt_area_reference(gt_env *e, const skgl_area_light *light, int strata, float *vis) {
    tb_view v;
    tb_ref_options opt;
    tb_light l;
    memset(&l, 0, sizeof l);
    l.type = TB_LIGHT_RECT;
    l.position = light->position;
    skgl_area_light_axes(light, &l.half_u, &l.half_v);
    l.strata = strata;
    l.seed = 7;
    v.inv_view_proj = e->inv_vp;
    v.width = e->w;
    v.height = e->h;
    opt = gt_ref_options(e);
    return tb_reference_trace_exact(e->ref, &v, e->depth, &l, &opt, vis, NULL);
}

/* ---- closed-form cases (tb_closed_form.h) ------------------------------- */
/* An env on one of the closed-form scenes ("plate", "pole", "box"); cf gets
   the analytic description. 0 ok; -1 counted as a failed check. */
static inline int gt_env_init_cf(gt_env *e, tb_cf_scene *cf, const char *name, int w, int h) {
    tb_scene s;
    tb_scene_init(&s);
    if (tb_cf_build(&s, cf, name) != 0) {
        SK_CHECK_MSG(0, "closed-form scene %s", name);
        tb_scene_free(&s);
        memset(e, 0, sizeof *e);
        return -1;
    }
    return gt_env_init(e, &s, w, h);
}

/* the tb_view of the last G-buffer */
static inline tb_view gt_view(const gt_env *e) {
    tb_view v;
    v.inv_view_proj = e->inv_vp;
    v.width = e->w;
    v.height = e->h;
    return v;
}

/* travel direction of a sun at this elevation above the horizon and
   azimuth (degrees; azimuth 0 = the sun in +x, 90 = in +z) */
static inline sk_vec3 gt_sun_dir(double elevation_deg, double azimuth_deg) {
    double e = elevation_deg * 3.14159265358979323846 / 180.0, a = azimuth_deg * 3.14159265358979323846 / 180.0;
    return gt_v3((float)(-cos(e) * cos(a)), (float)(-sin(e)), (float)(-cos(e) * sin(a)));
}

/* A camera w x h for a sun over a closed-form caster whose top is `height`
   above the ground: it looks at the middle of the caster and its shadow
   (the shadow of the top lies height / tan(elevation) away), from the same
   side for every light, far enough back to hold both. */
static inline skgl_camera gt_cf_sun_camera(float height, sk_vec3 dir, int w, int h) {
    double k = height / -dir.y, sx = dir.x * k, sz = dir.z * k;
    double len = sqrt(sx * sx + sz * sz), dist = 7.0 + 0.9 * len;
    sk_vec3 target = gt_v3((float)(0.5 * sx), 0.3f, (float)(0.5 * sz));
    sk_vec3 eye = gt_v3((float)(target.x + 0.55 * dist), (float)(0.45 * dist), (float)(target.z + 0.70 * dist));
    return gt_camera(eye, target, 0.9f, 0.1f, 120, w, h);
}

/* the exact reference (tb_reference_trace_exact) of any light over the last
   G-buffer, with its raster depth; stats may be NULL */
static inline int gt_reference_exact(gt_env *e, const tb_light *l, float *vis, tb_ref_stats *stats) {
    tb_view v = gt_view(e);
    tb_ref_options opt = gt_ref_options(e);
    return tb_reference_trace_exact(e->ref, &v, e->depth, l, &opt, vis, stats);
}

/* Into truth the closed form (tb_cf_visibility) of light l over the last
   G-buffer, with the pixels its exact reference (traced into ref) leaves
   out as silhouettes left out too: there the raster saw another surface
   than the ray, and the mask has no receiver to judge. 0 ok. */
static inline int gt_cf_truth(gt_env *e, const tb_cf_scene *cf, const tb_light *l, float *ref, float *truth) {
    tb_view v = gt_view(e);
    size_t i;
    if (gt_reference_exact(e, l, ref, NULL) != 0 || tb_cf_visibility(cf, &v, l, truth) != 0) return -1;
    for (i = 0; i < e->n; i++)
        if (ref[i] == TB_VIS_SILHOUETTE) truth[i] = TB_VIS_SILHOUETTE;
    return 0;
}

/* One sun frame over a closed-form caster whose top is `height` above the
   ground: the sun's travel direction at this elevation and azimuth into
   *dir, gt_cf_sun_camera's camera (e->w x e->h) into *cam, its G-buffer,
   and gt_cf_truth's truth and reference. 0 ok; -1 counted as a failed
   check naming the sun. */
static inline int gt_cf_sun_frame(gt_env *e, const tb_cf_scene *cf, float height, double elevation_deg,
                                  double azimuth_deg, float *ref, float *truth, sk_vec3 *dir, skgl_camera *cam) {
    tb_light l;
    *dir = gt_sun_dir(elevation_deg, azimuth_deg);
    l = gt_sun(*dir);
    *cam = gt_cf_sun_camera(height, *dir, e->w, e->h);
    if (gt_gbuffer(e, cam) != 0 || gt_cf_truth(e, cf, &l, ref, truth) != 0) {
        SK_CHECK_MSG(0, "sun %g/%g: G-buffer or truth", elevation_deg, azimuth_deg);
        return -1;
    }
    return 0;
}

/* 1 when pixel i is "open" false shadow: lit in the truth, shadowed in
   res, and no truth pixel of the other class in its 5 x 5 (acne, not
   aliasing). The exact edge lies between pixel centres of different
   classes, but a shadow thinner than a pixel (a pole's, seen far away) may
   hold no shadow pixel centre at all, and a pixel a little over 1 px from
   its edge can then be 2 px from the nearest shadow centre: the
   neighbourhood is 2 px, which holds every false shadow within 1 px of an
   edge. */
static inline int gt_open_false_shadow(const gt_env *e, const float *truth, const float *res, size_t i) {
    return tb_visibility_class(truth[i]) == 1 && res[i] < 0.5f && !gt_near_boundary(e, truth, i, 2);
}

/* Hard-shadow agreement of two visibility images over the pixels both
   cover (both >= 0): how many, and how many differ in class. */
typedef struct gt_agreement {
    size_t both, differ;
} gt_agreement;

static inline gt_agreement gt_agree(const float *a, const float *b, size_t n) {
    gt_agreement g;
    size_t i;
    g.both = g.differ = 0;
    for (i = 0; i < n; i++) {
        if (!(a[i] >= 0) || !(b[i] >= 0)) continue;
        g.both++;
        g.differ += tb_visibility_class(a[i]) != tb_visibility_class(b[i]);
    }
    return g;
}

/* skgl_soft_render over the last G-buffer, read back (-1 on background);
   the stats into *st when not NULL. 0 ok. */
static inline int gt_soft_mask(gt_env *e, skgl_soft *s, const skgl_camera *cam, const skgl_area_light *light,
                               float *vis, skgl_soft_frame_stats *st) {
    skgl_scene sc = gt_scene(e);
    sk_result r = skgl_soft_render(e->sk, s, cam, &sc, light, e->gbuf.depth_tex, e->gbuf.color_tex,
                                   e->mask.color_tex);
    if (r != SK_OK) {
        printf("skgl_soft_render: %s (%s)\n", sk_result_string(r), skgl_error_log(e->sk));
        return -1;
    }
    if (gt_read_mask(e, vis) != 0) return -1;
    if (st) *st = *skgl_soft_stats(s);
    return 0;
}

/* a soft-shadow object of this technique and resolution, other fields default */
static inline skgl_soft *gt_soft(gt_env *e, skgl_soft_technique t, int resolution) {
    skgl_soft_desc d;
    skgl_soft *s = NULL;
    sk_result r;
    memset(&d, 0, sizeof d);
    d.technique = t;
    d.resolution = resolution;
    r = skgl_soft_create(e->sk, &d, &s);
    if (r != SK_OK) {
        SK_CHECK_MSG(0, "skgl_soft_create: %s (%s)", sk_result_string(r), skgl_error_log(e->sk));
        return NULL;
    }
    return s;
}

/* ---- the off-screen caster (test_gl_offscreen.c, test_gl_optout.c, ------
   test_gl_warp.c): a 40 x 40 m ground, a 10 m tower [-1,0,12]..[1,10,14]
   behind the camera (eye (0,2,8) looking toward -z) and a small box in
   view; the light travels (0.1,-0.6,-1), so the tower's shadow runs 16 m
   into the view. */
typedef struct gt_offscreen {
    gt_env e;
    skgl_camera cam;
    sk_vec3 light;
    skgl_scene scene;      /* gt_scene(&e) */
    float *ref;            /* the light's exact reference over cam's G-buffer */
    float *res;            /* scratch for a mask */
} gt_offscreen;

static inline void gt_offscreen_free(gt_offscreen *o) {
    free(o->ref);
    free(o->res);
    o->ref = o->res = NULL;
    gt_env_free(&o->e);
}

/* The scene at w x h, the camera's G-buffer and the reference. 0 ok
   (gt_offscreen_free frees it); -1 counted as a failed check, nothing
   held. */
static inline int gt_offscreen_init(gt_offscreen *o, int w, int h) {
    tb_scene sc;
    o->ref = o->res = NULL;
    o->light = gt_v3(0.1f, -0.6f, -1);
    o->cam = gt_camera(gt_v3(0, 2, 8), gt_v3(0, 0, -2), 0.9f, 0.3f, 60, w, h);
    tb_scene_init(&sc);
    tb_scene_add_ground(&sc, "ground", 0, 0, 20, 20, 0, 4, 4);
    tb_scene_add_box(&sc, "tower", gt_v3(-1, 0, 12), gt_v3(1, 10, 14));
    tb_scene_add_box(&sc, "box", gt_v3(3, 0, -3), gt_v3(4, 1, -2));
    if (gt_env_init(&o->e, &sc, w, h) != 0) { gt_offscreen_free(o); return -1; }
    o->scene = gt_scene(&o->e);
    o->ref = gt_alloc(&o->e);
    o->res = gt_alloc(&o->e);
    if (!o->ref || !o->res || gt_gbuffer(&o->e, &o->cam) != 0 || gt_reference(&o->e, o->light, o->ref) != 0) {
        SK_CHECK_MSG(0, "off-screen caster: G-buffer or reference");
        gt_offscreen_free(o);
        return -1;
    }
    return 0;
}

/* The cache tests' world (test_gl_cache*.c): "ground-boxes" plus a 0.8 m
   "mover" box. gt_movers_draw_static (scene.draw) draws every object but
   the mover, box0 shifted by box0_shift and box3 left out while
   box3_hidden; gt_movers_draw_dynamic (the dynamic casters) draws the
   mover at mover_at. */
typedef struct gt_movers {
    gt_env e;
    int mover, box0, box3;            /* object indices */
    sk_vec3 mover_at, box0_shift;
    int box3_hidden;
} gt_movers;

static inline void gt_translation(float m[16], sk_vec3 t) {
    memset(m, 0, sizeof(float) * 16);
    m[0] = m[5] = m[10] = m[15] = 1;
    m[12] = t.x; m[13] = t.y; m[14] = t.z;
}

static inline sk_aabb gt_moved(sk_aabb b, sk_vec3 t) {
    b.min.x += t.x; b.min.y += t.y; b.min.z += t.z;
    b.max.x += t.x; b.max.y += t.y; b.max.z += t.z;
    return b;
}

static inline void gt_movers_draw_object(gt_movers *w, int obj) {
    const tb_object *o = &w->e.scene.objects[obj];
    tb_gl_mesh_draw(&w->e.gl, &w->e.mesh, o->first_index, o->index_count);
}

static inline void gt_movers_draw_static(void *user, const skgl_draw_info *info) {
    gt_movers *w = (gt_movers *)user;
    uint32_t i;
    float m[16];
    (void)info;
    for (i = 0; i < w->e.scene.object_count; i++) {
        if ((int)i == w->mover || ((int)i == w->box3 && w->box3_hidden)) continue;
        if ((int)i == w->box0) {
            gt_translation(m, w->box0_shift);
            skgl_set_model(w->e.sk, m);
            gt_movers_draw_object(w, (int)i);
            gt_translation(m, gt_v3(0, 0, 0));
            skgl_set_model(w->e.sk, m);
            continue;
        }
        gt_movers_draw_object(w, (int)i);
    }
}

static inline void gt_movers_draw_dynamic(void *user, const skgl_draw_info *info) {
    gt_movers *w = (gt_movers *)user;
    float m[16];
    (void)info;
    gt_translation(m, w->mover_at);
    skgl_set_model(w->e.sk, m);
    gt_movers_draw_object(w, w->mover);
}

/* the static scene (gt_movers_draw_static, the scene's bounds), the
   dynamic casters cleared */
static inline skgl_scene gt_movers_scene(gt_movers *w) {
    skgl_scene sc;
    sc.draw = gt_movers_draw_static;
    sc.user = w;
    sc.bounds = w->e.scene.bounds;
    SK_CHECK(skgl_set_dynamic(w->e.sk, NULL) == SK_OK);
    return sc;
}

/* clears *w and builds its scene and GL environment at w x h; 0, or -1
   (a failed check) */
static inline int gt_movers_init(gt_movers *w, int width, int height) {
    tb_scene s;
    memset(w, 0, sizeof *w);
    tb_scene_init(&s);
    if (tb_scene_build(&s, "ground-boxes") != 0 ||
        tb_scene_add_box(&s, "mover", gt_v3(-0.4f, 0, -0.4f), gt_v3(0.4f, 1.6f, 0.4f)) < 0) {
        SK_CHECK_MSG(0, "scene");
        tb_scene_free(&s);
        return -1;
    }
    if (gt_env_init(&w->e, &s, width, height) != 0) { gt_env_free(&w->e); return -1; }
    w->mover = tb_scene_find_object(&w->e.scene, "mover");
    w->box0 = tb_scene_find_object(&w->e.scene, "box0");
    w->box3 = tb_scene_find_object(&w->e.scene, "box3");
    SK_CHECK(w->mover >= 0 && w->box0 >= 0 && w->box3 >= 0);
    return 0;
}

/* The caster tests' lights (test_gl_casters.c, test_gl_caster_varyings.c):
   a sun, a point light of range 40 at GT_CASTER_LAMP, and a 0.6 m square
   area light there facing down. */
#define GT_CASTER_SUN gt_v3(-0.45f, -1.0f, -0.3f)
#define GT_CASTER_LAMP gt_v3(2.0f, 9.0f, 3.0f)

static inline skgl_area_light gt_caster_area(void) {
    skgl_area_light l;
    memset(&l, 0, sizeof l);
    l.position = GT_CASTER_LAMP;
    l.direction = gt_v3(0, -1, 0);
    l.up = gt_v3(0, 0, 1);
    l.half_width = l.half_height = 0.3f;
    return l;
}

/* the three lights' references over e's G-buffer (the area light with 16
   strata), each a check */
static inline void gt_caster_references(gt_env *e, float *sun, float *point, float *area) {
    tb_light pl;
    skgl_area_light al = gt_caster_area();
    SK_CHECK(gt_reference(e, GT_CASTER_SUN, sun) == 0);
    memset(&pl, 0, sizeof pl);
    pl.type = TB_LIGHT_POINT;
    pl.position = GT_CASTER_LAMP;
    pl.range = 40.0f;
    SK_CHECK(gt_reference_exact(e, &pl, point, NULL) == 0);
    SK_CHECK(gt_area_reference(e, &al, 16, area) == 0);
}

/* A caster program whose vertices move by the uniform u_offset (label
   "moved"): a layered or batched pass must draw it with each callback's
   offset. NULL where its create fails (the check names the log). */
static inline skgl_caster *gt_offset_caster(gt_env *e) {
    skgl_caster_desc cd;
    skgl_caster *hook = NULL;
    memset(&cd, 0, sizeof cd);
    cd.label = "moved";
    cd.vertex = "layout(location = 0) in vec3 a_pos;\n"
                "uniform vec3 u_offset;\n"
                "vec4 skgl_caster_position() { return vec4(a_pos + u_offset, 1.0); }\n";
    cd.uniforms[0] = "u_offset";
    SK_CHECK_MSG(skgl_caster_create(e->sk, &cd, &hook) == SK_OK, "%s", skgl_error_log(e->sk));
    return hook;
}

#endif /* GL_TEST_UTIL_H */
