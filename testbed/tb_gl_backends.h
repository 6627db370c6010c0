/* tb_gl_backends.h - private to tb_gl_context.c, tb_gl_osmesa.c, tb_gl_egl.c.
   Each backend creates a 3.3 core context, makes it current and fills the
   handle; destroy releases it. They share no GL header. */
#ifndef TB_GL_BACKENDS_H
#define TB_GL_BACKENDS_H

#include <stddef.h>
#include "tb_gl_context.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct tb_gl_backend_handle {
    void *a, *b, *c, *d;     /* backend-private (context, display, surface, buffer) */
    const char *name;        /* "osmesa", "egl-device", "egl-surfaceless" */
    int es;                  /* EGL: an OpenGL ES context (eglBindAPI(EGL_OPENGL_ES_API)) */
} tb_gl_backend_handle;

/* 0 on success (context current); -1 with a message in err */
int tb_gl_osmesa_create(tb_gl_backend_handle *h, char *err, size_t errlen);
void tb_gl_osmesa_destroy(tb_gl_backend_handle *h);
int tb_gl_osmesa_make_current(tb_gl_backend_handle *h);
void *tb_gl_osmesa_getproc(const char *name);

/* hardware_only: skip Mesa's software device and the surfaceless platform;
   flags: TB_GL_CONTEXT_DEBUG asks for a debug context (EGL_CONTEXT_OPENGL_DEBUG),
   TB_GL_CONTEXT_ES3 for OpenGL ES 3.0 or later instead of 3.3 core */
int tb_gl_egl_create(tb_gl_backend_handle *h, int hardware_only, int flags, char *err, size_t errlen);
void tb_gl_egl_destroy(tb_gl_backend_handle *h);
int tb_gl_egl_make_current(tb_gl_backend_handle *h);
void *tb_gl_egl_getproc(const char *name);

#ifdef __cplusplus
}
#endif
#endif
