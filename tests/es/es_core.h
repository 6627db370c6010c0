/* es_core.h - one scene, one camera, every technique, drawn the same way on
   desktop OpenGL 3.3, OpenGL ES 3.0 and WebGL2; each technique's mask read
   back. Shared by the native ES test (tests/gl/test_gl_es.c), the dump of
   the desktop masks the browser test compares with (tests/es/es_dump.c) and
   the browser test page itself (tests/es/es_web_test.c, built with emcc).

   Portable C99 with shadowkit.h and shadowkit_gl.h only: the GL entry points
   come from the same getproc skgl_create gets (eglGetProcAddress,
   OSMesaGetProcAddress, emscripten_webgl_get_proc_address), the shaders
   take the dialect's first lines from skgl_get_caps. Include it once, after
   the shadowkit implementations.

   A run walks the technique table one frame at a time (esx_step), so that a
   browser can yield between frames. Masks are R8 (colour-renderable on ES
   3.0 without extensions), read back as RGBA bytes, row 0 at the bottom. */
#ifndef ES_CORE_H
#define ES_CORE_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <stdarg.h>

#define ESX_W 320
#define ESX_H 180

/* ---- techniques ---------------------------------------------------------- */
enum { ESX_DIR, ESX_POINT, ESX_SOFT, ESX_SPOT };
typedef struct esx_tech {
    const char *name;
    int kind;          /* ESX_DIR, ESX_POINT, ESX_SOFT, ESX_SPOT (a skgl_point with a cone) */
    int technique;     /* skgl_technique, skgl_point_technique or skgl_soft_technique */
} esx_tech;
static const esx_tech esx_techs[] = {
    {"STANDARD", ESX_DIR, SKGL_STANDARD}, {"PSSM", ESX_DIR, SKGL_PSSM},     {"PSM", ESX_DIR, SKGL_PSM},
    {"LiSPSM", ESX_DIR, SKGL_LISPSM},     {"LSPSM", ESX_DIR, SKGL_LSPSM},   {"FERKO", ESX_DIR, SKGL_FERKO},
    {"RMSM", ESX_DIR, SKGL_RMSM},         {"cube", ESX_POINT, SKGL_POINT_CUBE},
    {"VSDCT", ESX_POINT, SKGL_POINT_VSDCT}, {"PCSS", ESX_SOFT, SKGL_SOFT_PCSS},
    {"PVSM", ESX_SOFT, SKGL_SOFT_PVSM},   {"spot", ESX_SPOT, SKGL_POINT_VSDCT}};
#define ESX_TECHS ((int)(sizeof esx_techs / sizeof esx_techs[0]))
#define ESX_FRAMES 3   /* frames rendered per technique; the mask of the last is kept */

/* ---- the scene's lights and camera (the native test traces the same) ---- */
static inline sk_vec3 esx_v3(float x, float y, float z)
{
    sk_vec3 v;
    v.x = x; v.y = y; v.z = z;
    return v;
}
static inline sk_vec3 esx_sun_dir(void)
{
    float n = sqrtf(0.45f * 0.45f + 1.0f + 0.35f * 0.35f);
    return esx_v3(-0.45f / n, -1.0f / n, -0.35f / n);
}
static inline sk_vec3 esx_point_pos(void) { return esx_v3(1.5f, 5.0f, 2.5f); }
static inline float esx_point_range(void) { return 30.0f; }
/* the spot: at the point light's place, its range, aimed past box0 */
static inline sk_vec3 esx_spot_dir(void) { return esx_v3(-0.3f, -1.0f, -0.5f); }
static inline float esx_spot_angle(void) { return 40.0f; }
static inline skgl_area_light esx_area_light(void)
{
    skgl_area_light a;
    memset(&a, 0, sizeof a);
    a.position = esx_v3(2.0f, 9.0f, 3.0f);
    a.direction = esx_v3(-0.2f, -1.0f, -0.3f);
    a.half_width = a.half_height = 0.4f;
    return a;
}
static inline skgl_camera esx_camera(void)
{
    skgl_camera c;
    c.view = sk_mat4_look_at(esx_v3(-11.0f, 7.0f, 13.0f), esx_v3(0.0f, 0.5f, 0.0f), esx_v3(0.0f, 1.0f, 0.0f));
    c.proj = sk_mat4_perspective(0.9f, (float)ESX_W / (float)ESX_H, 0.3f, 60.0f);
    return c;
}

/* ---- GL ------------------------------------------------------------------ */
typedef void *(*esx_getproc)(const char *name);
#if defined(_WIN32)
#define ESX_APIENTRY __stdcall
#else
#define ESX_APIENTRY
#endif
#define ESX_FUNCS(X) \
    X(unsigned, GetError, (void)) \
    X(unsigned, CreateShader, (unsigned t)) \
    X(void, ShaderSource, (unsigned s, int n, const char *const *src, const int *len)) \
    X(void, CompileShader, (unsigned s)) \
    X(void, GetShaderiv, (unsigned s, unsigned p, int *v)) \
    X(void, GetShaderInfoLog, (unsigned s, int n, int *len, char *log)) \
    X(void, DeleteShader, (unsigned s)) \
    X(unsigned, CreateProgram, (void)) \
    X(void, AttachShader, (unsigned p, unsigned s)) \
    X(void, LinkProgram, (unsigned p)) \
    X(void, GetProgramiv, (unsigned p, unsigned n, int *v)) \
    X(void, DeleteProgram, (unsigned p)) \
    X(void, UseProgram, (unsigned p)) \
    X(int, GetUniformLocation, (unsigned p, const char *n)) \
    X(void, UniformMatrix4fv, (int l, int n, unsigned char t, const float *v)) \
    X(void, GenBuffers, (int n, unsigned *b)) \
    X(void, BindBuffer, (unsigned t, unsigned b)) \
    X(void, BufferData, (unsigned t, ptrdiff_t n, const void *d, unsigned u)) \
    X(void, DeleteBuffers, (int n, const unsigned *b)) \
    X(void, GenVertexArrays, (int n, unsigned *v)) \
    X(void, BindVertexArray, (unsigned v)) \
    X(void, DeleteVertexArrays, (int n, const unsigned *v)) \
    X(void, VertexAttribPointer, (unsigned i, int n, unsigned t, unsigned char nm, int st, const void *p)) \
    X(void, EnableVertexAttribArray, (unsigned i)) \
    X(void, DrawElements, (unsigned m, int n, unsigned t, const void *p)) \
    X(void, GenTextures, (int n, unsigned *t)) \
    X(void, BindTexture, (unsigned t, unsigned x)) \
    X(void, ActiveTexture, (unsigned u)) \
    X(void, TexImage2D, (unsigned t, int l, int f, int w, int h, int b, unsigned fm, unsigned ty, const void *d)) \
    X(void, TexParameteri, (unsigned t, unsigned p, int v)) \
    X(void, DeleteTextures, (int n, const unsigned *t)) \
    X(void, GenFramebuffers, (int n, unsigned *f)) \
    X(void, BindFramebuffer, (unsigned t, unsigned f)) \
    X(void, FramebufferTexture2D, (unsigned t, unsigned a, unsigned tt, unsigned x, int l)) \
    X(unsigned, CheckFramebufferStatus, (unsigned t)) \
    X(void, DeleteFramebuffers, (int n, const unsigned *f)) \
    X(void, DrawBuffers, (int n, const unsigned *b)) \
    X(void, Viewport, (int x, int y, int w, int h)) \
    X(void, Enable, (unsigned c)) \
    X(void, Disable, (unsigned c)) \
    X(void, DepthFunc, (unsigned f)) \
    X(void, DepthMask, (unsigned char m)) \
    X(void, ClearBufferfv, (unsigned b, int i, const float *v)) \
    X(void, ReadPixels, (int x, int y, int w, int h, unsigned f, unsigned t, void *d)) \
    X(void, Finish, (void))
typedef struct esx_gl {
#define ESX_X(ret, name, args) ret (ESX_APIENTRY *name) args;
    ESX_FUNCS(ESX_X)
#undef ESX_X
} esx_gl;

/* ---- one run ------------------------------------------------------------- */
typedef struct esx_scene {
    const float *pos, *nrm;         /* 3 floats per vertex */
    const unsigned *idx;
    int vertices, indices;
    sk_aabb bounds;
} esx_scene;

typedef struct esx_run {
    esx_gl gl;
    skgl_context *sk;
    skgl_desc desc;
    esx_scene scene;
    unsigned vao, vbo[3], prog, depth_tex, normal_tex, gbuf_fbo, mask_tex, mask_fbo;
    int u_vp, u_model;
    int tech, frame;                /* where the run is */
    int last;                       /* the run ends before this technique [ESX_TECHS] */
    sk_vec3 sun;                    /* the directional light's travel direction [esx_sun_dir()] */
    int async;                      /* 1: FERKO, RMSM and PVSM read back through the ring, a frame
                                       or two late [0: at once, .sync_readback] */
    void *light;                    /* the technique's skgl_shadow / skgl_point / skgl_soft */
    int objects;                    /* shadowkit's GL objects before the first light */
    unsigned char mask[ESX_TECHS][ESX_W * ESX_H];
    sk_result result[ESX_TECHS];    /* SK_OK, or why the technique did not run */
    char why[ESX_TECHS][256];
    float ms[ESX_TECHS];            /* the technique's GPU ms (shadow + mask), -1 without timers */
    char log[600];
} esx_run;

static inline int esx_fail(esx_run *r, const char *what, const char *detail)
{
    snprintf(r->log, sizeof r->log, "%s%s%s", what, detail ? ": " : "", detail ? detail : "");
    return -1;
}

static inline unsigned esx_shader(esx_run *r, unsigned type, const char *body)
{
    const char *src[2];
    unsigned sh = r->gl.CreateShader(type);
    int ok = 0;
    skgl_caps c = skgl_get_caps(r->sk);
    src[0] = c.api == SKGL_API_GLES3 ? "#version 300 es\nprecision highp float;\n" : "#version 330 core\n";
    src[1] = body;
    r->gl.ShaderSource(sh, 2, src, NULL);
    r->gl.CompileShader(sh);
    r->gl.GetShaderiv(sh, 0x8B81 /* COMPILE_STATUS */, &ok);
    if (!ok) {
        char log[400] = "";
        r->gl.GetShaderInfoLog(sh, (int)sizeof log, NULL, log);
        esx_fail(r, "scene shader", log);
        r->gl.DeleteShader(sh);
        return 0;
    }
    return sh;
}

/* the scene's depth-only program: the G-buffer pass and the casters */
static const char esx_vs[] =
    "layout(location = 0) in vec3 a_position;\n"
    "layout(location = 1) in vec3 a_normal;\n"
    "uniform mat4 u_view_proj;\n"
    "uniform mat4 u_model;\n"
    "out vec3 v_normal;\n"
    "void main() {\n"
    "    v_normal = a_normal;\n"
    "    gl_Position = u_view_proj * (u_model * vec4(a_position, 1.0));\n"
    "}\n";
/* world normals, toward the camera (the G-buffer's second target; a depth
   pass has no colour target, and its output goes nowhere) */
static const char esx_fs[] =
    "in vec3 v_normal;\n"
    "out vec4 o_normal;\n"
    "void main() { vec3 n = normalize(v_normal); o_normal = vec4(gl_FrontFacing ? n : -n, 1.0); }\n";

/* the draw callback: shadowkit's program is bound, its matrices set */
static inline void esx_draw(void *user, const skgl_draw_info *info)
{
    esx_run *r = (esx_run *)user;
    (void)info;
    r->gl.BindVertexArray(r->vao);
    r->gl.DrawElements(0x0004 /* TRIANGLES */, r->scene.indices, 0x1405 /* UNSIGNED_INT */, NULL);
    r->gl.BindVertexArray(0);
}

/* FERKO's analysis programs and RMSM's are made with the first light of
   each and kept with the context: a light of each made and destroyed before
   the objects are counted, so that every light of the table must give back
   all it makes (a technique the context refuses makes nothing) */
static inline void esx_warm_up(esx_run *r)
{
    static const int techs[2] = {SKGL_FERKO, SKGL_RMSM};
    int i;
    for (i = 0; i < 2; i++) {
        skgl_shadow_desc d;
        skgl_shadow *s = NULL;
        memset(&d, 0, sizeof d);
        d.technique = (skgl_technique)techs[i];
        d.resolution = 1024;
        if (skgl_shadow_create(r->sk, &d, &s) == SK_OK) skgl_shadow_destroy(r->sk, s);
    }
}

/* 0 ok; the GL context current, getproc its loader */
static inline int esx_begin(esx_run *r, esx_getproc getproc, const esx_scene *scene, unsigned disable_caps)
{
    esx_gl *gl = &r->gl;
    unsigned vs, fs;
    int ok = 0, missing = 0;
    static const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    memset(r, 0, sizeof *r);
#define ESX_X(ret, name, args) { void *p_ = getproc("gl" #name); memcpy(&gl->name, &p_, sizeof p_); missing |= !p_; }
    ESX_FUNCS(ESX_X)
#undef ESX_X
    if (missing) return esx_fail(r, "a GL entry point is missing", NULL);
    r->scene = *scene;
    r->desc.getproc = getproc;
    r->desc.disable_caps = disable_caps;
    r->desc.timing = 1;
    if (skgl_create(&r->desc, &r->sk) != SK_OK) return esx_fail(r, "skgl_create failed", NULL);
    /* the scene's buffers */
    gl->GenVertexArrays(1, &r->vao);
    gl->BindVertexArray(r->vao);
    gl->GenBuffers(3, r->vbo);
    gl->BindBuffer(0x8892 /* ARRAY_BUFFER */, r->vbo[0]);
    gl->BufferData(0x8892, (ptrdiff_t)scene->vertices * 12, scene->pos, 0x88E4 /* STATIC_DRAW */);
    gl->VertexAttribPointer(0, 3, 0x1406 /* FLOAT */, 0, 12, NULL);
    gl->EnableVertexAttribArray(0);
    gl->BindBuffer(0x8892, r->vbo[1]);
    gl->BufferData(0x8892, (ptrdiff_t)scene->vertices * 12, scene->nrm, 0x88E4);
    gl->VertexAttribPointer(1, 3, 0x1406, 0, 12, NULL);
    gl->EnableVertexAttribArray(1);
    gl->BindBuffer(0x8893 /* ELEMENT_ARRAY_BUFFER */, r->vbo[2]);
    gl->BufferData(0x8893, (ptrdiff_t)scene->indices * 4, scene->idx, 0x88E4);
    gl->BindVertexArray(0);
    gl->BindBuffer(0x8892, 0);
    /* its program */
    vs = esx_shader(r, 0x8B31, esx_vs);
    fs = vs ? esx_shader(r, 0x8B30, esx_fs) : 0;
    if (!fs) return -1;
    r->prog = gl->CreateProgram();
    gl->AttachShader(r->prog, vs);
    gl->AttachShader(r->prog, fs);
    gl->LinkProgram(r->prog);
    gl->DeleteShader(vs);
    gl->DeleteShader(fs);
    gl->GetProgramiv(r->prog, 0x8B82 /* LINK_STATUS */, &ok);
    if (!ok) return esx_fail(r, "scene program did not link", NULL);
    r->u_vp = gl->GetUniformLocation(r->prog, "u_view_proj");
    r->u_model = gl->GetUniformLocation(r->prog, "u_model");
    gl->UseProgram(r->prog);
    gl->UniformMatrix4fv(r->u_model, 1, 0, identity);
    gl->UseProgram(0);
    /* the G-buffer: window depth in a DEPTH_COMPONENT32F texture */
    gl->GenTextures(1, &r->depth_tex);
    gl->BindTexture(0x0DE1, r->depth_tex);
    gl->TexImage2D(0x0DE1, 0, 0x8CAC /* DEPTH_COMPONENT32F */, ESX_W, ESX_H, 0, 0x1902 /* DEPTH_COMPONENT */,
                   0x1406, NULL);
    gl->TexParameteri(0x0DE1, 0x2801, 0x2600);   /* NEAREST: float depth is not filterable on ES */
    gl->TexParameteri(0x0DE1, 0x2800, 0x2600);
    gl->GenTextures(1, &r->normal_tex);   /* RGBA16F: renderable with EXT_color_buffer_float */
    gl->BindTexture(0x0DE1, r->normal_tex);
    gl->TexImage2D(0x0DE1, 0, 0x881A /* RGBA16F */, ESX_W, ESX_H, 0, 0x1908, 0x140B /* HALF_FLOAT */, NULL);
    gl->TexParameteri(0x0DE1, 0x2801, 0x2600);
    gl->TexParameteri(0x0DE1, 0x2800, 0x2600);
    gl->GenTextures(1, &r->mask_tex);
    gl->BindTexture(0x0DE1, r->mask_tex);
    gl->TexImage2D(0x0DE1, 0, 0x8229 /* R8 */, ESX_W, ESX_H, 0, 0x1903 /* RED */, 0x1401, NULL);
    gl->TexParameteri(0x0DE1, 0x2801, 0x2600);
    gl->TexParameteri(0x0DE1, 0x2800, 0x2600);
    gl->BindTexture(0x0DE1, 0);
    gl->GenFramebuffers(1, &r->gbuf_fbo);
    gl->BindFramebuffer(0x8D40, r->gbuf_fbo);
    gl->FramebufferTexture2D(0x8D40, 0x8D00 /* DEPTH_ATTACHMENT */, 0x0DE1, r->depth_tex, 0);
    gl->FramebufferTexture2D(0x8D40, 0x8CE0 /* COLOR_ATTACHMENT0 */, 0x0DE1, r->normal_tex, 0);
    if (gl->CheckFramebufferStatus(0x8D40) != 0x8CD5) return esx_fail(r, "G-buffer framebuffer incomplete", NULL);
    gl->GenFramebuffers(1, &r->mask_fbo);
    gl->BindFramebuffer(0x8D40, r->mask_fbo);
    gl->FramebufferTexture2D(0x8D40, 0x8CE0 /* COLOR_ATTACHMENT0 */, 0x0DE1, r->mask_tex, 0);
    if (gl->CheckFramebufferStatus(0x8D40) != 0x8CD5) return esx_fail(r, "mask framebuffer incomplete", NULL);
    gl->BindFramebuffer(0x8D40, 0);
    /* OpenGL ES 3.0 and WebGL2 cannot be asked a texture's size */
    skgl_remember_texture(r->sk, r->depth_tex, ESX_W, ESX_H);
    skgl_remember_texture(r->sk, r->normal_tex, ESX_W, ESX_H);
    skgl_remember_texture(r->sk, r->mask_tex, ESX_W, ESX_H);
    if (gl->GetError() != 0) return esx_fail(r, "GL error while making the scene", NULL);
    esx_warm_up(r);
    r->objects = skgl_gl_object_count(r->sk);
    r->last = ESX_TECHS;
    r->sun = esx_sun_dir();
    return 0;
}

static inline void esx_gbuffer(esx_run *r, const skgl_camera *cam)
{
    esx_gl *gl = &r->gl;
    sk_mat4 vp = sk_mat4_mul(cam->proj, cam->view);
    float one = 1.0f, zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    gl->BindFramebuffer(0x8D40, r->gbuf_fbo);
    gl->Viewport(0, 0, ESX_W, ESX_H);
    gl->Enable(0x0B71 /* DEPTH_TEST */);
    gl->DepthFunc(0x0201 /* LESS */);
    gl->DepthMask(1);
    gl->ClearBufferfv(0x1801 /* DEPTH */, 0, &one);
    gl->ClearBufferfv(0x1800 /* COLOR */, 0, zero);
    gl->UseProgram(r->prog);
    gl->UniformMatrix4fv(r->u_vp, 1, 0, vp.m);
    esx_draw(r, NULL);
    gl->UseProgram(0);
    gl->Disable(0x0B71);
    gl->BindFramebuffer(0x8D40, 0);
    /* the mask left bound on units 2 and 3, as the caller's lighting pass
       would leave it: WebGL2 refuses a draw into a texture any sampler of
       the program names, used or not */
    gl->ActiveTexture(0x84C2);
    gl->BindTexture(0x0DE1, r->mask_tex);
    gl->ActiveTexture(0x84C3);
    gl->BindTexture(0x0DE1, r->mask_tex);
    gl->ActiveTexture(0x84C0);
}

static inline void esx_free_light(esx_run *r)
{
    if (!r->light) return;
    switch (esx_techs[r->tech].kind) {
    case ESX_DIR: skgl_shadow_destroy(r->sk, (skgl_shadow *)r->light); break;
    case ESX_POINT:
    case ESX_SPOT: skgl_point_destroy(r->sk, (skgl_point *)r->light); break;
    default: skgl_soft_destroy(r->sk, (skgl_soft *)r->light); break;
    }
    r->light = NULL;
}

/* the light of the current technique; SK_OK or what create said */
static inline sk_result esx_make_light(esx_run *r)
{
    const esx_tech *t = &esx_techs[r->tech];
    sk_result res;
    if (t->kind == ESX_DIR) {
        skgl_shadow_desc d;
        memset(&d, 0, sizeof d);
        d.technique = (skgl_technique)t->technique;
        d.resolution = 1024;
        d.sync_readback = !r->async;
        if (t->technique == SKGL_LISPSM) d.cascades = 1;
        res = skgl_shadow_create(r->sk, &d, (skgl_shadow **)&r->light);
    } else if (t->kind == ESX_POINT || t->kind == ESX_SPOT) {
        skgl_point_desc d;
        memset(&d, 0, sizeof d);
        d.technique = (skgl_point_technique)t->technique;
        d.resolution = 512;
        d.range = esx_point_range();
        if (t->kind == ESX_SPOT) d.spot_angle = esx_spot_angle();
        /* normal offset: with the receiver-plane bias, Chromium's SwiftShader
           puts false shadow on 2% of the pixels (17% against the exact
           reference, 0.58% on the desktop) where Mesa, desktop or ES, matches
           the desktop to the pixel. Its polygon offset is far smaller than
           llvmpipe's: 64 units of depth_bias bring it to 0.77%. Normal
           offset moves the receiver, not the depth, and agrees on both */
        d.bias = SKGL_BIAS_NORMAL_OFFSET;
        res = skgl_point_create(r->sk, &d, (skgl_point **)&r->light);
    } else {
        skgl_soft_desc d;
        memset(&d, 0, sizeof d);
        d.technique = (skgl_soft_technique)t->technique;
        d.resolution = t->technique == SKGL_SOFT_PCSS ? 1024 : 2048;
        d.sync_readback = !r->async;
        res = skgl_soft_create(r->sk, &d, (skgl_soft **)&r->light);
    }
    return res;
}

/* one frame of the current technique into the mask texture */
static inline sk_result esx_frame(esx_run *r, const skgl_camera *cam)
{
    const esx_tech *t = &esx_techs[r->tech];
    skgl_scene sc;
    sk_result res;
    sc.draw = esx_draw;
    sc.user = r;
    sc.bounds = r->scene.bounds;
    esx_gbuffer(r, cam);
    if (t->kind == ESX_DIR) {
        skgl_shadow *s = (skgl_shadow *)r->light;
        sk_vec3 dir = r->sun;
        res = SK_OK;
        if (t->technique == SKGL_FERKO || t->technique == SKGL_RMSM)
            res = skgl_shadow_analyze(r->sk, s, cam, &sc, dir, r->depth_tex);
        if (res == SK_OK) res = skgl_shadow_render(r->sk, s, cam, &sc, dir);
        if (res == SK_OK) res = skgl_shadow_mask(r->sk, s, cam, r->depth_tex, r->normal_tex, r->mask_tex);
        if (res == SK_OK) {
            const skgl_shadow_frame_stats *st = skgl_shadow_stats(s);
            r->ms[r->tech] = st->shadow_ms >= 0 && st->mask_ms >= 0 ? st->shadow_ms + st->mask_ms : -1.0f;
        }
    } else if (t->kind == ESX_POINT || t->kind == ESX_SPOT) {
        skgl_point *p = (skgl_point *)r->light;
        res = t->kind == ESX_SPOT ? skgl_spot_render(r->sk, p, cam, &sc, esx_point_pos(), esx_spot_dir())
                                  : skgl_point_render(r->sk, p, cam, &sc, esx_point_pos());
        if (res == SK_OK) res = skgl_point_mask(r->sk, p, cam, r->depth_tex, r->normal_tex, r->mask_tex);
        if (res == SK_OK) {
            const skgl_point_frame_stats *st = skgl_point_stats(p);
            r->ms[r->tech] = st->shadow_ms >= 0 && st->mask_ms >= 0 ? st->shadow_ms + st->mask_ms : -1.0f;
        }
    } else {
        skgl_area_light a = esx_area_light();
        skgl_soft *s = (skgl_soft *)r->light;
        res = skgl_soft_render(r->sk, s, cam, &sc, &a, r->depth_tex, r->normal_tex, r->mask_tex);
        if (res == SK_OK) {
            const skgl_soft_frame_stats *st = skgl_soft_stats(s);
            r->ms[r->tech] = st->shadow_ms >= 0 && st->mask_ms >= 0 ? st->shadow_ms + st->mask_ms : -1.0f;
        }
    }
    return res;
}

static inline void esx_read_mask(esx_run *r, unsigned char *out)
{
    static unsigned char rgba[ESX_W * ESX_H * 4];
    int i;
    r->gl.BindFramebuffer(0x8CA8 /* READ_FRAMEBUFFER */, r->mask_fbo);
    r->gl.ReadPixels(0, 0, ESX_W, ESX_H, 0x1908 /* RGBA */, 0x1401 /* UNSIGNED_BYTE */, rgba);
    r->gl.BindFramebuffer(0x8CA8, 0);
    for (i = 0; i < ESX_W * ESX_H; i++) out[i] = rgba[4 * i];
}

/* the run does only the technique of this name (after esx_begin); 0 ok */
static inline int esx_only(esx_run *r, const char *name)
{
    int t;
    for (t = 0; t < ESX_TECHS; t++)
        if (strcmp(esx_techs[t].name, name) == 0) {
            r->tech = t;
            r->last = t + 1;
            return 0;
        }
    return -1;
}

/* One frame of the run; 1 when every technique is done. A technique that
   cannot be made or rendered keeps its result and message and gets an
   all-zero mask. */
static inline int esx_step(esx_run *r)
{
    skgl_camera cam = esx_camera();
    sk_result res;
    if (r->tech >= r->last) return 1;
    if (r->frame == 0) {
        r->ms[r->tech] = -1.0f;
        res = esx_make_light(r);
        if (res != SK_OK) {
            r->result[r->tech] = res;
            snprintf(r->why[r->tech], sizeof r->why[r->tech], "%.199s", skgl_error_log(r->sk));
            r->tech++;
            return r->tech >= r->last;
        }
    }
    res = esx_frame(r, &cam);
    if (res != SK_OK || ++r->frame == ESX_FRAMES) {
        r->result[r->tech] = res;
        if (res != SK_OK) snprintf(r->why[r->tech], sizeof r->why[r->tech], "%.199s", skgl_error_log(r->sk));
        else esx_read_mask(r, r->mask[r->tech]);
        esx_free_light(r);
        r->frame = 0;
        r->tech++;
    }
    return r->tech >= r->last;
}

/* frees everything esx_begin made; returns the GL objects the lights left */
static inline int esx_end(esx_run *r)
{
    esx_gl *gl = &r->gl;
    int left;
    esx_free_light(r);
    if (r->sk) {
        skgl_forget_texture(r->sk, r->mask_tex);
        left = skgl_gl_object_count(r->sk) - r->objects;
    } else {
        left = 0;
    }
    skgl_destroy(r->sk);
    r->sk = NULL;
    if (r->vao) gl->DeleteVertexArrays(1, &r->vao);
    if (r->vbo[0]) gl->DeleteBuffers(3, r->vbo);
    if (r->prog) gl->DeleteProgram(r->prog);
    if (r->depth_tex) gl->DeleteTextures(1, &r->depth_tex);
    if (r->mask_tex) gl->DeleteTextures(1, &r->mask_tex);
    if (r->normal_tex) gl->DeleteTextures(1, &r->normal_tex);
    if (r->gbuf_fbo) gl->DeleteFramebuffers(1, &r->gbuf_fbo);
    if (r->mask_fbo) gl->DeleteFramebuffers(1, &r->mask_fbo);
    return left;
}

/* ---- comparing masks ----------------------------------------------------- */
/* hard techniques: the share of pixels whose class (lit >= 128) differs, in
   %; soft: the mean |difference| over pixels either mask has in penumbra or
   umbra (value < 250), in units of full visibility */
static inline double esx_mask_diff(const unsigned char *a, const unsigned char *b, int soft)
{
    int i, n = ESX_W * ESX_H, count = 0;
    double sum = 0.0;
    for (i = 0; i < n; i++) {
        if (!soft) {
            count += (a[i] >= 128) != (b[i] >= 128);
        } else if (a[i] < 250 || b[i] < 250) {
            sum += fabs((double)a[i] - (double)b[i]) / 255.0;
            count++;
        }
    }
    if (!soft) return 100.0 * (double)count / (double)n;
    return count ? sum / (double)count : 0.0;
}

/* against the exact reference (vis: -1 and below where no receiver counts):
   hard, the wrong pixels per reference shadow pixel in % (the lit majority
   cannot dilute it); soft, the mean |difference| over the pixels where the
   reference or the mask is not fully lit */
static inline double esx_ref_error(const float *vis, const unsigned char *m, int soft)
{
    int i, n = ESX_W * ESX_H, shadow = 0, wrong = 0, count = 0;
    double sum = 0.0;
    for (i = 0; i < n; i++) {
        float v = vis[i], x = (float)m[i] / 255.0f;
        if (!(v >= 0.0f)) continue;
        if (!soft) {
            shadow += v < 0.5f;
            wrong += (v < 0.5f) != (x < 0.5f);
        } else if (v < 0.999f || x < 0.98f) {
            sum += fabs((double)v - (double)x);
            count++;
        }
    }
    if (!soft) return shadow ? 100.0 * (double)wrong / (double)shadow : 0.0;
    return count ? sum / (double)count : 0.0;
}

/* ---- the spot's reference ----------------------------------------------- */
/* The nearest triangle of sc along the ray o + t d (Moller-Trumbore), t > 0;
   1 and the point, 0 none */
static inline int esx_cast(const esx_scene *sc, const double o[3], const double d[3], double hit[3])
{
    double best = 1e300;
    int k, found = 0;
    for (k = 0; k + 2 < sc->indices; k += 3) {
        const float *a = sc->pos + 3 * sc->idx[k], *b = sc->pos + 3 * sc->idx[k + 1], *c = sc->pos + 3 * sc->idx[k + 2];
        double e1[3], e2[3], pv[3], tv[3], qv[3], det, u, v, t;
        int i;
        for (i = 0; i < 3; i++) { e1[i] = (double)b[i] - a[i]; e2[i] = (double)c[i] - a[i]; tv[i] = o[i] - a[i]; }
        pv[0] = d[1] * e2[2] - d[2] * e2[1]; pv[1] = d[2] * e2[0] - d[0] * e2[2]; pv[2] = d[0] * e2[1] - d[1] * e2[0];
        det = e1[0] * pv[0] + e1[1] * pv[1] + e1[2] * pv[2];
        if (fabs(det) < 1e-12) continue;
        u = (tv[0] * pv[0] + tv[1] * pv[1] + tv[2] * pv[2]) / det;
        if (u < 0 || u > 1) continue;
        qv[0] = tv[1] * e1[2] - tv[2] * e1[1]; qv[1] = tv[2] * e1[0] - tv[0] * e1[2]; qv[2] = tv[0] * e1[1] - tv[1] * e1[0];
        v = (d[0] * qv[0] + d[1] * qv[1] + d[2] * qv[2]) / det;
        if (v < 0 || u + v > 1) continue;
        t = (e2[0] * qv[0] + e2[1] * qv[1] + e2[2] * qv[2]) / det;
        if (t > 0 && t < best) { best = t; found = 1; }
    }
    if (found) for (k = 0; k < 3; k++) hit[k] = o[k] + best * d[k];
    return found;
}

/* The spot's exact visibility from the point light's (point_vis, the same
   position and range): each pixel's receiver (the camera ray's nearest
   triangle) outside the cone gets 0, within 0.5 degrees of its edge -1 (left
   out: the cone's edge is not what the comparison is about); inside it
   keeps the point light's value. */
static inline void esx_spot_reference(const esx_scene *sc, const float *point_vis, float *out)
{
    skgl_camera cam = esx_camera();
    sk_mat4 inv;
    sk_vec3 lp = esx_point_pos(), ax = esx_spot_dir();
    double axl = sqrt((double)ax.x * ax.x + (double)ax.y * ax.y + (double)ax.z * ax.z);
    int x, y, k;
    sk_mat4_inverse(sk_mat4_mul(cam.proj, cam.view), &inv);
    for (y = 0; y < ESX_H; y++)
        for (x = 0; x < ESX_W; x++) {
            int i = y * ESX_W + x;
            double ends[2][3], d[3], hit[3], v[3], vl, ang;
            out[i] = point_vis[i];
            if (!(point_vis[i] >= 0.0f)) continue;
            for (k = 0; k < 2; k++) {
                double nx = 2.0 * (x + 0.5) / ESX_W - 1.0, ny = 2.0 * (y + 0.5) / ESX_H - 1.0, nz = k ? 1.0 : -1.0;
                const float *m = inv.m;
                double w = m[3] * nx + m[7] * ny + m[11] * nz + m[15];
                ends[k][0] = (m[0] * nx + m[4] * ny + m[8] * nz + m[12]) / w;
                ends[k][1] = (m[1] * nx + m[5] * ny + m[9] * nz + m[13]) / w;
                ends[k][2] = (m[2] * nx + m[6] * ny + m[10] * nz + m[14]) / w;
            }
            for (k = 0; k < 3; k++) d[k] = ends[1][k] - ends[0][k];
            if (!esx_cast(sc, ends[0], d, hit)) continue;
            v[0] = hit[0] - lp.x; v[1] = hit[1] - lp.y; v[2] = hit[2] - lp.z;
            vl = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            ang = acos(fmax(-1.0, fmin(1.0, (v[0] * ax.x + v[1] * ax.y + v[2] * ax.z) / (vl * axl)))) * 57.29577951308232;
            if (fabs(ang - esx_spot_angle()) < 0.5) out[i] = -1.0f;
            else if (ang > esx_spot_angle()) out[i] = 0.0f;
        }
}

/* ---- the data the browser test compares with (tests/es/es_dump.c) -------- */
#define ESX_MAGIC 0x31585345u   /* "ESX1" */
typedef struct esx_data_header {
    unsigned magic, vertices, indices, techs, w, h;
    float bounds[6];
} esx_data_header;
/* file: header, positions (3 floats a vertex), normals, indices, the
   desktop masks (techs x w x h bytes), the reference of the sun, the point
   light and the area light (3 x w x h floats) */

#endif
