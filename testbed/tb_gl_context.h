/* tb_gl_context.h - a headless OpenGL 3.3 core context, chosen at run time.

   Backends:
   - OSMesa (Mesa's off-screen library, llvmpipe): runs anywhere, CPU only.
     OSMesaCreateContextAttribs with OSMESA_PROFILE = OSMESA_CORE_PROFILE,
     version 3.3; made current on a small private 16x16 RGBA buffer (the
     default framebuffer is that buffer: render into your own FBOs).
   - EGL, device platform (EGL_EXT_platform_device: eglQueryDevicesEXT, then
     eglGetPlatformDisplay(EGL_PLATFORM_DEVICE_EXT)), else Mesa's surfaceless
     platform (EGL_PLATFORM_SURFACELESS_MESA). eglBindAPI(EGL_OPENGL_API), a
     3.3 core context made current with no surface
     (EGL_KHR_surfaceless_context; a 16x16 pbuffer where that is missing).
     There is no default framebuffer: render into your own FBOs.

   Selection (tb_gl_context_create(TB_GL_AUTO, ...)): environment variable
   SK_GL = "osmesa" | "egl"; unset or empty: an EGL device that is a real GPU
   (not Mesa's software device, EGL_MESA_device_software), else OSMesa.
   SK_GL=egl: any EGL device (hardware first), else the surfaceless platform.

   The context is current on the calling thread after creation. Load GL entry
   points with the function returned by tb_gl_context_getproc(), e.g.
       skgl_init(..., tb_gl_context_getproc(ctx))
   (OSMesaGetProcAddress / eglGetProcAddress behind it). */
#ifndef TB_GL_CONTEXT_H
#define TB_GL_CONTEXT_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum tb_gl_backend {
    TB_GL_AUTO = 0,      /* SK_GL, else EGL hardware device, else OSMesa */
    TB_GL_OSMESA = 1,
    TB_GL_EGL = 2        /* device platform, else surfaceless */
} tb_gl_backend;

typedef void *(*tb_gl_getproc_fn)(const char *name);
typedef struct tb_gl_context tb_gl_context;

/* NULL on failure, with a reason in err (may be NULL) */
tb_gl_context *tb_gl_context_create(tb_gl_backend want, char *err, size_t errlen);
/* flags for tb_gl_context_create_flags */
#define TB_GL_CONTEXT_DEBUG 1   /* a debug context (EGL: EGL_CONTEXT_OPENGL_DEBUG). OSMesa has no
                                   attribute for one: its context is made as usual, and
                                   GL_KHR_debug output still works there once GL_DEBUG_OUTPUT is
                                   enabled; tb_gl_context_debug() tells which one you got */
#define TB_GL_CONTEXT_ES3 2     /* OpenGL ES 3.0 or later through EGL (EGL_OPENGL_ES_API; Mesa gives
                                   its highest ES, 3.2 on llvmpipe): AUTO and OSMESA are taken as EGL */
tb_gl_context *tb_gl_context_create_flags(tb_gl_backend want, int flags, char *err, size_t errlen);
void tb_gl_context_destroy(tb_gl_context *ctx);          /* NULL is fine */
int tb_gl_context_make_current(tb_gl_context *ctx);      /* 0 ok, -1 failure */

tb_gl_getproc_fn tb_gl_context_getproc(const tb_gl_context *ctx);
/* "osmesa", "egl-device" or "egl-surfaceless" */
const char *tb_gl_context_backend_name(const tb_gl_context *ctx);
/* glGetString(GL_RENDERER / GL_VERSION), captured at creation */
const char *tb_gl_context_renderer(const tb_gl_context *ctx);
const char *tb_gl_context_version(const tb_gl_context *ctx);
/* GL_MAJOR_VERSION, GL_MINOR_VERSION and whether the context is core profile */
void tb_gl_context_gl_version(const tb_gl_context *ctx, int *major, int *minor, int *core);
/* 1 when GL_CONTEXT_FLAGS has GL_CONTEXT_FLAG_DEBUG_BIT (a debug context) */
int tb_gl_context_debug(const tb_gl_context *ctx);

#ifdef __cplusplus
}
#endif
#endif /* TB_GL_CONTEXT_H */
