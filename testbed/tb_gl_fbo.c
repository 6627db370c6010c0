/* tb_gl_fbo.c - see tb_gl_fbo.h */
#include "tb_gl_fbo.h"

#include <string.h>

/* the GL 3.3 enums used here */
#define TB_GL_NO_ERROR 0
#define TB_GL_NONE 0
#define TB_GL_TEXTURE_2D 0x0DE1
#define TB_GL_TEXTURE_MAG_FILTER 0x2800
#define TB_GL_TEXTURE_MIN_FILTER 0x2801
#define TB_GL_TEXTURE_WRAP_S 0x2802
#define TB_GL_TEXTURE_WRAP_T 0x2803
#define TB_GL_NEAREST 0x2600
#define TB_GL_CLAMP_TO_EDGE 0x812F
#define TB_GL_UNSIGNED_BYTE 0x1401
#define TB_GL_FLOAT 0x1406
#define TB_GL_RED 0x1903
#define TB_GL_RGB 0x1907
#define TB_GL_RGBA 0x1908
#define TB_GL_RGBA8 0x8058
#define TB_GL_R16F 0x822D
#define TB_GL_RGBA16F 0x881A
#define TB_GL_DEPTH_COMPONENT 0x1902
#define TB_GL_DEPTH_COMPONENT32F 0x8CAC
#define TB_GL_FRAMEBUFFER 0x8D40
#define TB_GL_READ_FRAMEBUFFER 0x8CA8
#define TB_GL_DRAW_FRAMEBUFFER 0x8CA9
#define TB_GL_READ_FRAMEBUFFER_BINDING 0x8CAA
#define TB_GL_DRAW_FRAMEBUFFER_BINDING 0x8CA6
#define TB_GL_COLOR_ATTACHMENT0 0x8CE0
#define TB_GL_DEPTH_ATTACHMENT 0x8D00
#define TB_GL_FRAMEBUFFER_COMPLETE 0x8CD5
#define TB_GL_PACK_ALIGNMENT 0x0D05
#define TB_GL_READ_BUFFER 0x0C02
#define TB_GL_TEXTURE_BINDING_2D 0x8069

static unsigned tb_make_tex_(const tb_gl_funcs *gl, int internal, int w, int h, unsigned fmt,
                             unsigned type) {
    unsigned tex = 0;
    gl->GenTextures(1, &tex);
    gl->BindTexture(TB_GL_TEXTURE_2D, tex);
    gl->TexImage2D(TB_GL_TEXTURE_2D, 0, internal, w, h, 0, fmt, type, NULL);
    gl->TexParameteri(TB_GL_TEXTURE_2D, TB_GL_TEXTURE_MIN_FILTER, TB_GL_NEAREST);
    gl->TexParameteri(TB_GL_TEXTURE_2D, TB_GL_TEXTURE_MAG_FILTER, TB_GL_NEAREST);
    gl->TexParameteri(TB_GL_TEXTURE_2D, TB_GL_TEXTURE_WRAP_S, TB_GL_CLAMP_TO_EDGE);
    gl->TexParameteri(TB_GL_TEXTURE_2D, TB_GL_TEXTURE_WRAP_T, TB_GL_CLAMP_TO_EDGE);
    return tex;
}

int tb_gl_fbo_create(const tb_gl_funcs *gl, tb_gl_fbo *f, int width, int height,
                     tb_gl_color_format color) {
    int prev_tex = 0, prev_draw = 0, prev_read = 0;
    unsigned status;
    memset(f, 0, sizeof *f);
    if (width <= 0 || height <= 0) return -1;
    while (gl->GetError() != TB_GL_NO_ERROR) {}
    gl->GetIntegerv(TB_GL_TEXTURE_BINDING_2D, &prev_tex);
    gl->GetIntegerv(TB_GL_DRAW_FRAMEBUFFER_BINDING, &prev_draw);
    gl->GetIntegerv(TB_GL_READ_FRAMEBUFFER_BINDING, &prev_read);
    f->width = width;
    f->height = height;
    gl->GenFramebuffers(1, &f->fbo);
    gl->BindFramebuffer(TB_GL_FRAMEBUFFER, f->fbo);
    if (color == TB_GL_COLOR_RGBA8)
        f->color_tex = tb_make_tex_(gl, TB_GL_RGBA8, width, height, TB_GL_RGBA, TB_GL_UNSIGNED_BYTE);
    else if (color == TB_GL_COLOR_R16F)
        f->color_tex = tb_make_tex_(gl, TB_GL_R16F, width, height, TB_GL_RED, TB_GL_FLOAT);
    else if (color == TB_GL_COLOR_RGBA16F)
        f->color_tex = tb_make_tex_(gl, TB_GL_RGBA16F, width, height, TB_GL_RGBA, TB_GL_FLOAT);
    if (f->color_tex) {
        unsigned buf = TB_GL_COLOR_ATTACHMENT0;
        gl->FramebufferTexture2D(TB_GL_FRAMEBUFFER, TB_GL_COLOR_ATTACHMENT0, TB_GL_TEXTURE_2D,
                                 f->color_tex, 0);
        gl->DrawBuffers(1, &buf);
        gl->ReadBuffer(TB_GL_COLOR_ATTACHMENT0);
    } else {
        unsigned buf = TB_GL_NONE;
        gl->DrawBuffers(1, &buf);
        gl->ReadBuffer(TB_GL_NONE);
    }
    f->depth_tex = tb_make_tex_(gl, TB_GL_DEPTH_COMPONENT32F, width, height, TB_GL_DEPTH_COMPONENT,
                                TB_GL_FLOAT);
    gl->FramebufferTexture2D(TB_GL_FRAMEBUFFER, TB_GL_DEPTH_ATTACHMENT, TB_GL_TEXTURE_2D,
                             f->depth_tex, 0);
    status = gl->CheckFramebufferStatus(TB_GL_FRAMEBUFFER);
    gl->BindTexture(TB_GL_TEXTURE_2D, (unsigned)prev_tex);
    gl->BindFramebuffer(TB_GL_DRAW_FRAMEBUFFER, (unsigned)prev_draw);
    gl->BindFramebuffer(TB_GL_READ_FRAMEBUFFER, (unsigned)prev_read);
    if (status != TB_GL_FRAMEBUFFER_COMPLETE || gl->GetError() != TB_GL_NO_ERROR) {
        tb_gl_fbo_destroy(gl, f);
        return -1;
    }
    return 0;
}

void tb_gl_fbo_destroy(const tb_gl_funcs *gl, tb_gl_fbo *f) {
    if (f->fbo) gl->DeleteFramebuffers(1, &f->fbo);
    if (f->color_tex) gl->DeleteTextures(1, &f->color_tex);
    if (f->depth_tex) gl->DeleteTextures(1, &f->depth_tex);
    memset(f, 0, sizeof *f);
}

void tb_gl_fbo_bind(const tb_gl_funcs *gl, const tb_gl_fbo *f) {
    gl->BindFramebuffer(TB_GL_FRAMEBUFFER, f ? f->fbo : 0);
    if (f) gl->Viewport(0, 0, f->width, f->height);
}

/* glReadPixels from `fbo`; color: read attachment 0 (else depth) */
static int tb_read_(const tb_gl_funcs *gl, unsigned fbo, int color, int w, int h, unsigned fmt,
                    unsigned type, void *out) {
    int prev_read = 0, prev_pack = 4, prev_buf = 0, prev_pbo = 0;
    int ok;
    if (w <= 0 || h <= 0 || !out) return -1;
    while (gl->GetError() != TB_GL_NO_ERROR) {}
    gl->GetIntegerv(TB_GL_READ_FRAMEBUFFER_BINDING, &prev_read);
    gl->GetIntegerv(TB_GL_PACK_ALIGNMENT, &prev_pack);
    /* a bound pixel-pack buffer would take the pixels: read to client memory */
    gl->GetIntegerv(0x88ED /* GL_PIXEL_PACK_BUFFER_BINDING */, &prev_pbo);
    gl->BindBuffer(0x88EB /* GL_PIXEL_PACK_BUFFER */, 0);
    gl->BindFramebuffer(TB_GL_READ_FRAMEBUFFER, fbo);
    gl->GetIntegerv(TB_GL_READ_BUFFER, &prev_buf);
    if (color && fbo) gl->ReadBuffer(TB_GL_COLOR_ATTACHMENT0);
    gl->PixelStorei(TB_GL_PACK_ALIGNMENT, 1);
    gl->ReadPixels(0, 0, w, h, fmt, type, out);
    ok = gl->GetError() == TB_GL_NO_ERROR;
    if (color && fbo) gl->ReadBuffer((unsigned)prev_buf);
    gl->PixelStorei(TB_GL_PACK_ALIGNMENT, prev_pack);
    gl->BindBuffer(0x88EB, (unsigned)prev_pbo);
    gl->BindFramebuffer(TB_GL_READ_FRAMEBUFFER, (unsigned)prev_read);
    return ok ? 0 : -1;
}

int tb_gl_read_depth(const tb_gl_funcs *gl, unsigned fbo, int w, int h, float *out) {
    return tb_read_(gl, fbo, 0, w, h, TB_GL_DEPTH_COMPONENT, TB_GL_FLOAT, out);
}
int tb_gl_read_rgba8(const tb_gl_funcs *gl, unsigned fbo, int w, int h, unsigned char *out) {
    return tb_read_(gl, fbo, 1, w, h, TB_GL_RGBA, TB_GL_UNSIGNED_BYTE, out);
}
int tb_gl_read_rgb8(const tb_gl_funcs *gl, unsigned fbo, int w, int h, unsigned char *out) {
    return tb_read_(gl, fbo, 1, w, h, TB_GL_RGB, TB_GL_UNSIGNED_BYTE, out);
}
int tb_gl_read_red(const tb_gl_funcs *gl, unsigned fbo, int w, int h, float *out) {
    return tb_read_(gl, fbo, 1, w, h, TB_GL_RED, TB_GL_FLOAT, out);
}
int tb_gl_read_rgba_float(const tb_gl_funcs *gl, unsigned fbo, int w, int h, float *out) {
    return tb_read_(gl, fbo, 1, w, h, TB_GL_RGBA, TB_GL_FLOAT, out);
}
int tb_gl_read_normals(const tb_gl_funcs *gl, unsigned fbo, int w, int h, float *rgba, float *out) {
    size_t i, n = (size_t)w * (size_t)h;
    if (tb_gl_read_rgba_float(gl, fbo, w, h, rgba) != 0) return -1;
    for (i = 0; i < n; i++) {
        out[3 * i] = rgba[4 * i];
        out[3 * i + 1] = rgba[4 * i + 1];
        out[3 * i + 2] = rgba[4 * i + 2];
    }
    return 0;
}

static int tb_read_texture_(const tb_gl_funcs *gl, unsigned tex, int depth, int w, int h,
                            float *out, unsigned color_fmt) {
    unsigned fbo = 0, none = TB_GL_NONE, att0 = TB_GL_COLOR_ATTACHMENT0;
    int prev_read = 0, r;
    gl->GetIntegerv(TB_GL_READ_FRAMEBUFFER_BINDING, &prev_read);
    gl->GenFramebuffers(1, &fbo);
    gl->BindFramebuffer(TB_GL_READ_FRAMEBUFFER, fbo);
    gl->FramebufferTexture2D(TB_GL_READ_FRAMEBUFFER,
                             depth ? TB_GL_DEPTH_ATTACHMENT : TB_GL_COLOR_ATTACHMENT0,
                             TB_GL_TEXTURE_2D, tex, 0);
    gl->ReadBuffer(depth ? none : att0);
    r = gl->CheckFramebufferStatus(TB_GL_READ_FRAMEBUFFER) == TB_GL_FRAMEBUFFER_COMPLETE ? 0 : -1;
    gl->BindFramebuffer(TB_GL_READ_FRAMEBUFFER, (unsigned)prev_read);
    if (r == 0)
        r = depth ? tb_read_(gl, fbo, 0, w, h, TB_GL_DEPTH_COMPONENT, TB_GL_FLOAT, out)
                  : tb_read_(gl, fbo, 1, w, h, color_fmt, TB_GL_FLOAT, out);
    gl->DeleteFramebuffers(1, &fbo);
    return r;
}

int tb_gl_read_texture_red(const tb_gl_funcs *gl, unsigned tex, int w, int h, float *out) {
    return tb_read_texture_(gl, tex, 0, w, h, out, TB_GL_RED);
}
int tb_gl_read_texture_rgba_float(const tb_gl_funcs *gl, unsigned tex, int w, int h, float *out) {
    return tb_read_texture_(gl, tex, 0, w, h, out, TB_GL_RGBA);
}
int tb_gl_read_texture_depth(const tb_gl_funcs *gl, unsigned tex, int w, int h, float *out) {
    return tb_read_texture_(gl, tex, 1, w, h, out, TB_GL_RED);
}
