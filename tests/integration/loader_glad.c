/* loader_glad.c - an application that loads GL through glad and uses
   shadowkit_gl.h in the same translation unit.

   The loader is glad 2 generated for GL 3.3 core with no extensions by
   Debian's python3-glad at build time (mk/integration.mk: glad --api
   gl:core=3.3 --extensions "" --reproducible, into build/integration/glad;
   the output's licence is in its header: (WTFPL OR CC0-1.0) AND
   Apache-2.0). gladLoadGL takes the same getproc as shadowkit, here
   OSMesaGetProcAddress through the testbed's OSMesa context.

   What it checks: lt_run() in loader_test.h on OSMesa (measured: 0 of
   230400 pixels differ from the testbed-table render), and that glad
   reports GL 3.3. It can fail: with the sun's x negated in this program's
   copy of loader_render.h only, 14.0% of the pixels differ from the
   testbed render (and from GLEW's image in loaders.sh). */
#include <glad/gl.h>

#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"

#define GL(name) gl##name
#include "loader_render.h"
#include "loader_test.h"

static tb_gl_getproc_fn glad_getproc;

/* glad wants a function pointer back; the testbed's getproc gives void * */
static GLADapiproc glad_load(const char *name) {
    void *p = glad_getproc(name);
    GLADapiproc f;
    memcpy(&f, &p, sizeof f);
    return f;
}

static int init_glad(tb_gl_context *ctx, char *msg, size_t n) {
    int v;
    glad_getproc = tb_gl_context_getproc(ctx);
    v = gladLoadGL(glad_load);
    if (!v) {
        snprintf(msg, n, "gladLoadGL failed");
        return -1;
    }
    if (GLAD_VERSION_MAJOR(v) * 10 + GLAD_VERSION_MINOR(v) < 33 || !GLAD_GL_VERSION_3_3) {
        snprintf(msg, n, "glad loaded GL %d.%d", GLAD_VERSION_MAJOR(v), GLAD_VERSION_MINOR(v));
        return -1;
    }
    snprintf(msg, n, "gladLoadGL: GL %d.%d", GLAD_VERSION_MAJOR(v), GLAD_VERSION_MINOR(v));
    return 0;
}

static void test_glad(void) {
    static const lt_loader L = { "glad", TB_GL_OSMESA, init_glad };
    lt_run(&L);
}

SK_TEST_MAIN(test_glad)
