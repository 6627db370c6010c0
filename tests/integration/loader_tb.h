/* loader_tb.h - the loader tests' reference path: loader_render.h compiled
   against the testbed's own GL table (tb_gl_funcs, loaded through the
   context's getproc), in loader_tb.c. */
#ifndef LOADER_TB_H
#define LOADER_TB_H

#include "shadowkit_gl.h"
#include "tb_gl_funcs.h"
#include "tb_scene.h"

#ifdef __cplusplus
extern "C" {
#endif

/* lr_render (loader_render.h) with every GL call through gl; 0 ok */
int lr_render_testbed(const tb_gl_funcs *gl, skgl_context *sk, const tb_scene *scene, unsigned char *rgb);

#ifdef __cplusplus
}
#endif
#endif /* LOADER_TB_H */
