/* loader_tb.c - loader_render.h through the testbed's GL table: the path
   the GLEW and glad renders are compared with (see loader_tb.h). */
#include "loader_tb.h"

static const tb_gl_funcs *lr_gl;
#define GL(name) (lr_gl->name)
#include "loader_render.h"

int lr_render_testbed(const tb_gl_funcs *gl, skgl_context *sk, const tb_scene *scene, unsigned char *rgb) {
    lr_gl = gl;
    return lr_render(sk, scene, rgb);
}
