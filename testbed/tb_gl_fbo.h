/* tb_gl_fbo.h - an off-screen render target and pixel readback for the
   testbed, on any current GL 3.3 core context (GL calls through tb_gl_funcs).
   All readbacks return rows bottom-up (row 0 = bottom), as glReadPixels
   does and as tb_reference / tb_image expect, tightly packed. Each helper
   saves and restores the framebuffer bindings and pack alignment it changes. */
#ifndef TB_GL_FBO_H
#define TB_GL_FBO_H

#include "tb_gl_funcs.h"

#ifdef __cplusplus
extern "C" {
#endif

/* colour formats for tb_gl_fbo_create */
typedef enum tb_gl_color_format {
    TB_GL_COLOR_NONE = 0,    /* depth only */
    TB_GL_COLOR_RGBA8 = 1,
    TB_GL_COLOR_R16F = 2,    /* e.g. a visibility mask */
    TB_GL_COLOR_RGBA16F = 3  /* e.g. world-space normals (tb_gl_scene.h) */
} tb_gl_color_format;

typedef struct tb_gl_fbo {
    unsigned fbo;
    unsigned color_tex;      /* 0 with TB_GL_COLOR_NONE */
    unsigned depth_tex;      /* GL_DEPTH_COMPONENT32F, NEAREST, CLAMP_TO_EDGE */
    int width, height;
} tb_gl_fbo;

/* complete FBO with a colour texture on attachment 0 and a 32F depth texture;
   0 ok, -1 (nothing left allocated) */
int tb_gl_fbo_create(const tb_gl_funcs *gl, tb_gl_fbo *f, int width, int height,
                     tb_gl_color_format color);
void tb_gl_fbo_destroy(const tb_gl_funcs *gl, tb_gl_fbo *f);
/* binds f (or the default framebuffer for NULL) for drawing and sets the viewport */
void tb_gl_fbo_bind(const tb_gl_funcs *gl, const tb_gl_fbo *f);

/* readbacks of the w x h rectangle at the origin of framebuffer `fbo`
   (0 = default); 0 ok, -1 on a GL error */
int tb_gl_read_depth(const tb_gl_funcs *gl, unsigned fbo, int w, int h, float *out);  /* window depth [0,1] */
int tb_gl_read_rgba8(const tb_gl_funcs *gl, unsigned fbo, int w, int h, unsigned char *out);
int tb_gl_read_rgb8(const tb_gl_funcs *gl, unsigned fbo, int w, int h, unsigned char *out);
int tb_gl_read_red(const tb_gl_funcs *gl, unsigned fbo, int w, int h, float *out);    /* R of attachment 0 */
int tb_gl_read_rgba_float(const tb_gl_funcs *gl, unsigned fbo, int w, int h, float *out);
/* the G-buffer's normals: RGB of attachment 0, 3 floats a pixel into out,
   read through rgba (4 floats a pixel, the caller's scratch) */
int tb_gl_read_normals(const tb_gl_funcs *gl, unsigned fbo, int w, int h, float *rgba, float *out);
/* red channel / depth of any 2D texture (through a temporary FBO) */
int tb_gl_read_texture_red(const tb_gl_funcs *gl, unsigned tex, int w, int h, float *out);
int tb_gl_read_texture_rgba_float(const tb_gl_funcs *gl, unsigned tex, int w, int h, float *out);  /* 4 per texel */
int tb_gl_read_texture_depth(const tb_gl_funcs *gl, unsigned tex, int w, int h, float *out);

#ifdef __cplusplus
}
#endif
#endif /* TB_GL_FBO_H */
