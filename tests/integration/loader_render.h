/* loader_render.h - one small application renderer, written once and
   compiled against different GL loaders: the loader tests include it after
   defining GL(name) as the way their translation unit calls glName
       GLEW or glad:      #define GL(name) gl##name
       the testbed table: #define GL(name) (lr_gl->name)   (tb_gl_funcs)
   so the GLEW, glad and testbed renders issue the same calls in the same
   order. Include after shadowkit_gl.h; every function is static.

   lr_render draws the testbed's ground-boxes scene at LR_W x LR_H from a
   fixed camera, lit by a fixed sun with shadowkit's PSSM (4 cascades of
   1024^2, PCF 1) through the forward path: the application uploads the
   mesh, builds its own program around skgl_glsl_snippet(), draws the
   casters in shadowkit's callback through a caster program of its own
   (skgl_caster_create: its vertex layout's position, as an engine hands
   over its vertex code) in one layered pass for the four cascades
   (desc.layered), calls skgl_shadow_bind and draws the lambert-lit scene
   into its own RGBA8 framebuffer, read back as RGB.
   Only the GL enums below are used (no GL header needed here). */
#ifndef LOADER_RENDER_H
#define LOADER_RENDER_H

#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "tb_scene.h"
#include "gl_forward_vs.h"

#define LR_W 640
#define LR_H 360

#define LR_GL_TRIANGLES 0x0004
#define LR_GL_UNSIGNED_INT 0x1405
#define LR_GL_UNSIGNED_BYTE 0x1401
#define LR_GL_FLOAT 0x1406
#define LR_GL_DEPTH_TEST 0x0B71
#define LR_GL_LESS 0x0201
#define LR_GL_COLOR_BUFFER_BIT 0x4000
#define LR_GL_DEPTH_BUFFER_BIT 0x0100
#define LR_GL_ARRAY_BUFFER 0x8892
#define LR_GL_ELEMENT_ARRAY_BUFFER 0x8893
#define LR_GL_STATIC_DRAW 0x88E4
#define LR_GL_TEXTURE_2D 0x0DE1
#define LR_GL_TEXTURE_MIN_FILTER 0x2801
#define LR_GL_TEXTURE_MAG_FILTER 0x2800
#define LR_GL_NEAREST 0x2600
#define LR_GL_RGBA8 0x8058
#define LR_GL_RGBA 0x1908
#define LR_GL_RGB 0x1907
#define LR_GL_DEPTH_COMPONENT24 0x81A6
#define LR_GL_DEPTH_COMPONENT 0x1902
#define LR_GL_FRAMEBUFFER 0x8D40
#define LR_GL_COLOR_ATTACHMENT0 0x8CE0
#define LR_GL_DEPTH_ATTACHMENT 0x8D00
#define LR_GL_FRAMEBUFFER_COMPLETE 0x8CD5
#define LR_GL_VERTEX_SHADER 0x8B31
#define LR_GL_FRAGMENT_SHADER 0x8B30
#define LR_GL_COMPILE_STATUS 0x8B81
#define LR_GL_LINK_STATUS 0x8B82
#define LR_GL_PACK_ALIGNMENT 0x0D05

static const char lr_vs[] = GT_FORWARD_VS;   /* tests/gl/gl_forward_vs.h */
/* after "#version 330 core" and skgl_glsl_snippet() */
static const char lr_fs[] =
    "in vec3 v_world;\n"
    "in vec3 v_normal;\n"
    "in float v_view_depth;\n"
    "uniform vec3 u_light_dir;\n"
    "out vec4 o_color;\n"
    "void main() {\n"
    "    vec3 n = normalize(v_normal);\n"
    "    if (!gl_FrontFacing) n = -n;\n"
    "    float lambert = max(dot(n, -u_light_dir), 0.0);\n"
    "    float vis = sk_shadow(v_world, n, v_view_depth);\n"
    "    vec3 c = vec3(0.8, 0.75, 0.6) * (0.25 + 0.75 * lambert * vis);\n"
    "    o_color = vec4(c, 1.0);\n"
    "}\n";

typedef struct lr_gpu {
    unsigned vao, vbo[2], ibo;
    int index_count;
    skgl_context *sk;
    skgl_caster *caster;     /* the casters' vertex code */
    int callbacks, failed;
} lr_gpu;

/* the application's caster vertex code: its own layout's position */
static const char lr_caster_vs[] =
    "layout(location = 0) in vec3 a_position;\n"
    "vec4 skgl_caster_position() { return vec4(a_position, 1.0); }\n";

/* shadowkit's draw callback: the whole mesh through our caster program */
static void lr_draw_casters(void *user, const skgl_draw_info *info) {
    lr_gpu *g = (lr_gpu *)user;
    (void)info;
    g->callbacks++;
    if (!skgl_use_caster(g->sk, g->caster)) { g->failed = 1; return; }
    GL(BindVertexArray)(g->vao);
    GL(DrawElements)(LR_GL_TRIANGLES, g->index_count, LR_GL_UNSIGNED_INT, (const void *)0);
    GL(BindVertexArray)(0);
}

static unsigned lr_shader(unsigned type, int count, const char *const *src) {
    unsigned sh = GL(CreateShader)(type);
    int ok = 0;
    GL(ShaderSource)(sh, count, src, NULL);
    GL(CompileShader)(sh);
    GL(GetShaderiv)(sh, LR_GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[2048] = "";
        GL(GetShaderInfoLog)(sh, (int)sizeof log, NULL, log);
        printf("loader_render: shader: %s\n", log);
        GL(DeleteShader)(sh);
        return 0;
    }
    return sh;
}

static void lr_v3(sk_vec3 *v, float x, float y, float z) { v->x = x; v->y = y; v->z = z; }

/* The camera and sun of every loader render. */
static void lr_view(skgl_camera *cam, sk_vec3 *light) {
    sk_vec3 eye, target, up;
    lr_v3(&eye, 9.0f, 6.5f, 11.0f);
    lr_v3(&target, 0.0f, 1.0f, 0.0f);
    lr_v3(&up, 0.0f, 1.0f, 0.0f);
    cam->view = sk_mat4_look_at(eye, target, up);
    cam->proj = sk_mat4_perspective(0.9f, (float)LR_W / (float)LR_H, 0.1f, 80.0f);
    lr_v3(light, -0.9f, -0.8f, 0.5f);   /* low, from the right of the view: long shadows */
}

/* One frame, read back into rgb (3 * LR_W * LR_H bytes, row 0 at the
   bottom). Creates and deletes all its GL objects and its skgl_shadow.
   0 ok, -1 with the reason printed. */
static int lr_render(skgl_context *sk, const tb_scene *scene, unsigned char *rgb) {
    const char *fs_src[3];
    const char *vs_src = lr_vs;
    unsigned vs, fs, prog, color_tex = 0, depth_tex = 0, fbo = 0;
    int ok = 0, status = -1, u_vp, u_view, u_light;
    lr_gpu g;
    skgl_shadow_desc sd;
    skgl_shadow *sun = NULL;
    skgl_camera cam;
    skgl_scene sc;
    sk_vec3 light;
    sk_mat4 vp;
    sk_result r;

    /* the program: our shader around shadowkit's snippet */
    fs_src[0] = "#version 330 core\n";
    fs_src[1] = skgl_glsl_snippet();
    fs_src[2] = lr_fs;
    vs = lr_shader(LR_GL_VERTEX_SHADER, 1, &vs_src);
    fs = lr_shader(LR_GL_FRAGMENT_SHADER, 3, fs_src);
    prog = GL(CreateProgram)();
    if (vs) GL(AttachShader)(prog, vs);
    if (fs) GL(AttachShader)(prog, fs);
    GL(LinkProgram)(prog);
    if (vs) GL(DeleteShader)(vs);
    if (fs) GL(DeleteShader)(fs);
    GL(GetProgramiv)(prog, LR_GL_LINK_STATUS, &ok);
    if (!vs || !fs || !ok) {
        printf("loader_render: the forward program does not link\n");
        GL(DeleteProgram)(prog);
        return -1;
    }
    u_vp = GL(GetUniformLocation)(prog, "u_view_proj");
    u_view = GL(GetUniformLocation)(prog, "u_view");
    u_light = GL(GetUniformLocation)(prog, "u_light_dir");

    /* the mesh: positions (attribute 0), normals (1), indices */
    memset(&g, 0, sizeof g);
    g.index_count = (int)scene->index_count;
    GL(GenVertexArrays)(1, &g.vao);
    GL(BindVertexArray)(g.vao);
    GL(GenBuffers)(2, g.vbo);
    GL(BindBuffer)(LR_GL_ARRAY_BUFFER, g.vbo[0]);
    GL(BufferData)(LR_GL_ARRAY_BUFFER, (ptrdiff_t)(sizeof(float) * 3 * scene->vertex_count), scene->positions,
                   LR_GL_STATIC_DRAW);
    GL(VertexAttribPointer)(0, 3, LR_GL_FLOAT, 0, 0, (const void *)0);
    GL(EnableVertexAttribArray)(0);
    GL(BindBuffer)(LR_GL_ARRAY_BUFFER, g.vbo[1]);
    GL(BufferData)(LR_GL_ARRAY_BUFFER, (ptrdiff_t)(sizeof(float) * 3 * scene->vertex_count), scene->normals,
                   LR_GL_STATIC_DRAW);
    GL(VertexAttribPointer)(1, 3, LR_GL_FLOAT, 0, 0, (const void *)0);
    GL(EnableVertexAttribArray)(1);
    GL(GenBuffers)(1, &g.ibo);
    GL(BindBuffer)(LR_GL_ELEMENT_ARRAY_BUFFER, g.ibo);
    GL(BufferData)(LR_GL_ELEMENT_ARRAY_BUFFER, (ptrdiff_t)(sizeof(uint32_t) * scene->index_count), scene->indices,
                   LR_GL_STATIC_DRAW);
    GL(BindVertexArray)(0);
    GL(BindBuffer)(LR_GL_ARRAY_BUFFER, 0);

    /* our render target: RGBA8 colour, 24-bit depth */
    GL(GenTextures)(1, &color_tex);
    GL(BindTexture)(LR_GL_TEXTURE_2D, color_tex);
    GL(TexImage2D)(LR_GL_TEXTURE_2D, 0, LR_GL_RGBA8, LR_W, LR_H, 0, LR_GL_RGBA, LR_GL_UNSIGNED_BYTE, NULL);
    GL(TexParameteri)(LR_GL_TEXTURE_2D, LR_GL_TEXTURE_MIN_FILTER, LR_GL_NEAREST);
    GL(TexParameteri)(LR_GL_TEXTURE_2D, LR_GL_TEXTURE_MAG_FILTER, LR_GL_NEAREST);
    GL(GenTextures)(1, &depth_tex);
    GL(BindTexture)(LR_GL_TEXTURE_2D, depth_tex);
    GL(TexImage2D)(LR_GL_TEXTURE_2D, 0, LR_GL_DEPTH_COMPONENT24, LR_W, LR_H, 0, LR_GL_DEPTH_COMPONENT,
                   LR_GL_UNSIGNED_INT, NULL);
    GL(TexParameteri)(LR_GL_TEXTURE_2D, LR_GL_TEXTURE_MIN_FILTER, LR_GL_NEAREST);
    GL(TexParameteri)(LR_GL_TEXTURE_2D, LR_GL_TEXTURE_MAG_FILTER, LR_GL_NEAREST);
    GL(BindTexture)(LR_GL_TEXTURE_2D, 0);
    GL(GenFramebuffers)(1, &fbo);
    GL(BindFramebuffer)(LR_GL_FRAMEBUFFER, fbo);
    GL(FramebufferTexture2D)(LR_GL_FRAMEBUFFER, LR_GL_COLOR_ATTACHMENT0, LR_GL_TEXTURE_2D, color_tex, 0);
    GL(FramebufferTexture2D)(LR_GL_FRAMEBUFFER, LR_GL_DEPTH_ATTACHMENT, LR_GL_TEXTURE_2D, depth_tex, 0);
    if (GL(CheckFramebufferStatus)(LR_GL_FRAMEBUFFER) != LR_GL_FRAMEBUFFER_COMPLETE) {
        printf("loader_render: framebuffer incomplete\n");
        goto done;
    }

    /* the shadow: PSSM, 4 cascades of 1024^2 */
    memset(&sd, 0, sizeof sd);
    sd.technique = SKGL_PSSM;
    sd.cascades = 4;
    sd.resolution = 1024;
    sd.pcf_radius = 1;
    sd.layered = 1;
    if ((r = skgl_shadow_create(sk, &sd, &sun)) != SK_OK) {
        printf("loader_render: skgl_shadow_create: %s (%s)\n", sk_result_string(r), skgl_error_log(sk));
        goto done;
    }
    {
        skgl_caster_desc cd;
        memset(&cd, 0, sizeof cd);
        cd.label = "loader_render";
        cd.vertex = lr_caster_vs;
        g.sk = sk;
        if ((r = skgl_caster_create(sk, &cd, &g.caster)) != SK_OK) {
            printf("loader_render: skgl_caster_create: %s (%s)\n", sk_result_string(r), skgl_error_log(sk));
            goto done;
        }
    }
    lr_view(&cam, &light);
    sc.draw = lr_draw_casters;
    sc.user = &g;
    sc.bounds = scene->bounds;

    /* the frame: shadow map, then our forward pass into our framebuffer */
    GL(Viewport)(0, 0, LR_W, LR_H);
    if ((r = skgl_shadow_render(sk, sun, &cam, &sc, light)) != SK_OK) {
        printf("loader_render: skgl_shadow_render: %s (%s)\n", sk_result_string(r), skgl_error_log(sk));
        goto done;
    }
    if (g.failed || g.callbacks != 1 || skgl_shadow_stats(sun)->layered == 0) {
        printf("loader_render: the casters' pass: %d callbacks (1 expected), caster program %s, layered %d\n",
               g.callbacks, g.failed ? "refused" : "used", skgl_shadow_stats(sun)->layered);
        goto done;
    }
    GL(ClearColor)(0.3f, 0.4f, 0.6f, 1.0f);
    GL(ClearDepth)(1.0);
    GL(Clear)(LR_GL_COLOR_BUFFER_BIT | LR_GL_DEPTH_BUFFER_BIT);
    GL(Enable)(LR_GL_DEPTH_TEST);
    GL(DepthFunc)(LR_GL_LESS);
    GL(UseProgram)(prog);
    vp = sk_mat4_mul(cam.proj, cam.view);
    GL(UniformMatrix4fv)(u_vp, 1, 0, vp.m);
    GL(UniformMatrix4fv)(u_view, 1, 0, cam.view.m);
    GL(Uniform3f)(u_light, light.x, light.y, light.z);
    if ((r = skgl_shadow_bind(sk, sun, prog, 0)) != SK_OK) {
        printf("loader_render: skgl_shadow_bind: %s (%s)\n", sk_result_string(r), skgl_error_log(sk));
        goto done;
    }
    GL(BindVertexArray)(g.vao);
    GL(DrawElements)(LR_GL_TRIANGLES, g.index_count, LR_GL_UNSIGNED_INT, (const void *)0);
    GL(BindVertexArray)(0);
    GL(UseProgram)(0);
    GL(PixelStorei)(LR_GL_PACK_ALIGNMENT, 1);
    GL(ReadPixels)(0, 0, LR_W, LR_H, LR_GL_RGB, LR_GL_UNSIGNED_BYTE, rgb);
    GL(PixelStorei)(LR_GL_PACK_ALIGNMENT, 4);
    if (GL(GetError)() != 0) {
        printf("loader_render: a GL error in the frame\n");
        goto done;
    }
    status = 0;

done:
    if (g.caster) skgl_caster_destroy(sk, g.caster);
    if (sun) skgl_shadow_destroy(sk, sun);
    GL(BindFramebuffer)(LR_GL_FRAMEBUFFER, 0);
    GL(DeleteFramebuffers)(1, &fbo);
    GL(DeleteTextures)(1, &color_tex);
    GL(DeleteTextures)(1, &depth_tex);
    GL(DeleteBuffers)(2, g.vbo);
    GL(DeleteBuffers)(1, &g.ibo);
    GL(DeleteVertexArrays)(1, &g.vao);
    GL(DeleteProgram)(prog);
    return status;
}

#endif /* LOADER_RENDER_H */
