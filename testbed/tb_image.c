/* tb_image.c - see tb_image.h */
#if !defined(_POSIX_C_SOURCE) || _POSIX_C_SOURCE < 200809L
#undef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L
#endif
#include "tb_image.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>

#ifdef TB_STB_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#endif
#include <stb/stb_image_write.h>

int tb_image_make_parent_dirs(const char *path) {
    char buf[4096];
    size_t n = strlen(path), i;
    if (n >= sizeof buf) return -1;
    memcpy(buf, path, n + 1);
    for (i = 1; i < n; i++) {
        if (buf[i] != '/') continue;
        buf[i] = 0;
        if (mkdir(buf, 0777) != 0 && errno != EEXIST) return -1;
        buf[i] = '/';
    }
    return 0;
}

/* write comp-channel 8-bit pixels given bottom-up */
static int tb_write_(const char *path, int w, int h, int comp, const unsigned char *px) {
    size_t stride = (size_t)w * (size_t)comp;
    unsigned char *flipped;
    int y, ok;
    if (!path || !px || w <= 0 || h <= 0) return -1;
    if (tb_image_make_parent_dirs(path)) return -1;
    flipped = (unsigned char *)malloc(stride * (size_t)h);
    if (!flipped) return -1;
    for (y = 0; y < h; y++)
        memcpy(flipped + (size_t)y * stride, px + (size_t)(h - 1 - y) * stride, stride);
    ok = stbi_write_png(path, w, h, comp, flipped, (int)stride);
    free(flipped);
    return ok ? 0 : -1;
}

int tb_image_write_rgb8(const char *path, int w, int h, const unsigned char *rgb) {
    return tb_write_(path, w, h, 3, rgb);
}

int tb_image_write_rgba8(const char *path, int w, int h, const unsigned char *rgba) {
    return tb_write_(path, w, h, 4, rgba);
}

static void tb_set_(unsigned char *p, int r, int g, int b) {
    p[0] = (unsigned char)r;
    p[1] = (unsigned char)g;
    p[2] = (unsigned char)b;
}

static unsigned char tb_unit_to_byte_(double t) {
    if (!(t > 0)) return 0;
    if (t >= 1) return 255;
    return (unsigned char)(t * 255.0 + 0.5);
}

/* map each pixel through fn into an RGB buffer, then write */
typedef void (*tb_pixel_fn_)(unsigned char *rgb, size_t i, const void *ctx);

static int tb_write_mapped_(const char *path, int w, int h, tb_pixel_fn_ fn, const void *ctx) {
    size_t n, i;
    unsigned char *rgb;
    int r;
    if (w <= 0 || h <= 0) return -1;
    n = (size_t)w * (size_t)h;
    rgb = (unsigned char *)malloc(n * 3);
    if (!rgb) return -1;
    for (i = 0; i < n; i++) fn(rgb + 3 * i, i, ctx);
    r = tb_write_(path, w, h, 3, rgb);
    free(rgb);
    return r;
}

static void tb_vis_px_(unsigned char *p, size_t i, const void *ctx) {
    float v = ((const float *)ctx)[i];
    unsigned char g;
    if (!isfinite(v)) { tb_set_(p, 255, 0, 255); return; }
    if (v < 0) { tb_set_(p, 24, 32, 64); return; }
    g = tb_unit_to_byte_(v);
    tb_set_(p, g, g, g);
}

int tb_image_write_visibility(const char *path, int w, int h, const float *vis) {
    if (!vis) return -1;
    return tb_write_mapped_(path, w, h, tb_vis_px_, vis);
}

typedef struct tb_gray_ctx_ { const float *v; double lo, hi; } tb_gray_ctx_;

static void tb_gray_px_(unsigned char *p, size_t i, const void *ctx) {
    const tb_gray_ctx_ *c = (const tb_gray_ctx_ *)ctx;
    float v = c->v[i];
    unsigned char g;
    if (!isfinite(v)) { tb_set_(p, 255, 0, 255); return; }
    g = tb_unit_to_byte_(c->hi != c->lo ? (v - c->lo) / (c->hi - c->lo) : 0.0);
    tb_set_(p, g, g, g);
}

int tb_image_write_gray(const char *path, int w, int h, const float *v, float lo, float hi) {
    tb_gray_ctx_ c;
    if (!v) return -1;
    c.v = v;
    c.lo = lo;
    c.hi = hi;
    return tb_write_mapped_(path, w, h, tb_gray_px_, &c);
}

typedef struct tb_err_ctx_ { const float *ref, *res; } tb_err_ctx_;

static void tb_err_px_(unsigned char *p, size_t i, const void *ctx) {
    const tb_err_ctx_ *c = (const tb_err_ctx_ *)ctx;
    float r = c->ref[i], v = c->res[i];
    int rl, vl;
    if (!(r >= 0) || !isfinite(r)) { tb_set_(p, 0, 0, 0); return; }
    if (!isfinite(v)) { tb_set_(p, 255, 0, 255); return; }
    rl = r >= 0.5f;
    vl = v >= 0.5f;
    if (rl && vl) tb_set_(p, 200, 200, 200);
    else if (!rl && !vl) tb_set_(p, 64, 64, 64);
    else if (vl) tb_set_(p, 230, 40, 40);      /* false lit */
    else tb_set_(p, 40, 90, 230);              /* false shadow */
}

int tb_image_write_error(const char *path, int w, int h, const float *ref, const float *result) {
    tb_err_ctx_ c;
    if (!ref || !result) return -1;
    c.ref = ref;
    c.res = result;
    return tb_write_mapped_(path, w, h, tb_err_px_, &c);
}
