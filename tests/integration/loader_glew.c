/* loader_glew.c - an application that loads GL through GLEW (Debian's
   libglew-dev) and uses shadowkit_gl.h in the same translation unit.

   GLEW on Debian 12 is built for GLX: glewInit() resolves entry points with
   glXGetProcAddressARB from libGL (libglvnd). On an OSMesa context that
   finds nothing (OSMesa is not a libglvnd vendor): glewInit returns
   GLEW_ERROR_NO_GL_VERSION. On an EGL context (Mesa, through libglvnd) the
   GL part works: libglvnd's dispatch follows whichever context is current,
   EGL or GLX. glewInit then loads every GL entry point and its last step,
   glxewInit, returns GLEW_ERROR_NO_GLX_DISPLAY because no GLX display is
   current; that code means "GL loaded, GLX extensions not", so the program
   accepts it and checks GLEW_VERSION_3_3 and the renderer string instead.
   glewExperimental = GL_TRUE is what GLEW's documentation asks for on
   core profiles (GLEW 2.2 here loads the 3.3 entry points without it too).

   What it checks: lt_run() in loader_test.h on the testbed's EGL context
   (Mesa's software device here; measured: 0 of 230400 pixels differ from
   the testbed-table render of the same frame), plus GLEW's own view of the
   context (GL 3.3 entry points, the same renderer string). It can fail:
   on the OSMesa context instead (TB_GL_OSMESA for TB_GL_EGL below) glewInit returns
   GLEW_ERROR_NO_GL_VERSION, the loader check fails and nothing renders. */
#include <GL/glew.h>

#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"

#define GL(name) gl##name
#include "loader_render.h"
#include "loader_test.h"

static int init_glew(tb_gl_context *ctx, char *msg, size_t n) {
    GLenum e;
    const char *renderer;
    glewExperimental = GL_TRUE;
    e = glewInit();
    if (e != GLEW_OK && e != GLEW_ERROR_NO_GLX_DISPLAY) {
        snprintf(msg, n, "glewInit: %u (%s)", (unsigned)e, (const char *)glewGetErrorString(e));
        return -1;
    }
    if (!GLEW_VERSION_3_3 || !glGenVertexArrays || !glGetStringi) {
        snprintf(msg, n, "GLEW found no GL 3.3 core entry points");
        return -1;
    }
    renderer = (const char *)glGetString(GL_RENDERER);
    if (!renderer || strcmp(renderer, tb_gl_context_renderer(ctx)) != 0) {
        snprintf(msg, n, "GLEW's glGetString(GL_RENDERER) is '%s'", renderer ? renderer : "(null)");
        return -1;
    }
    snprintf(msg, n, "glewInit: %s, GLEW %s", e == GLEW_OK ? "GLEW_OK" : "GLEW_ERROR_NO_GLX_DISPLAY (GL loaded)",
             (const char *)glewGetString(GLEW_VERSION));
    return 0;
}

static void test_glew(void) {
    static const lt_loader L = { "glew", TB_GL_EGL, init_glew };
    lt_run(&L);
}

SK_TEST_MAIN(test_glew)
