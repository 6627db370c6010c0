/* tb_gl_scene.h - a tb_scene on the GPU, and a camera G-buffer pass.

   tb_gl_mesh: the scene's positions (vertex attribute 0, vec3) and normals
   (attribute 1, vec3) in two VBOs, uint32 indices in an IBO, one VAO. Draw
   all of it or one object's index range, with whatever program is bound:
   this is what a shadowkit_gl.h draw callback needs.

   tb_gl_gbuffer: the camera pass the reference needs: window depth (the
   FBO's DEPTH_COMPONENT32F texture) and world-space unit normals turned
   toward the camera (gl_FrontFacing) in an RGBA16F colour texture, alpha 1
   on covered pixels, cleared to depth 1 and normal 0. Depth test LESS,
   no face culling (the room and ground are single-sided).
   Read back with tb_gl_read_depth / tb_gl_read_rgba_float (tb_gl_fbo.h).

   State: tb_gl_gbuffer_render saves and restores the draw framebuffer,
   viewport, program, VAO, depth test/func/mask and cull-face enable; it
   changes the clear colour and clear depth values. */
#ifndef TB_GL_SCENE_H
#define TB_GL_SCENE_H

#include <stddef.h>
#include <stdint.h>
#include "tb_gl_fbo.h"
#include "tb_scene.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct tb_gl_mesh {
    unsigned vao, vbo_pos, vbo_nrm, ibo;
    uint32_t index_count;
} tb_gl_mesh;

/* 0 ok, -1 (nothing allocated) on a GL error or an empty scene */
int tb_gl_mesh_create(const tb_gl_funcs *gl, tb_gl_mesh *m, const tb_scene *s);
void tb_gl_mesh_destroy(const tb_gl_funcs *gl, tb_gl_mesh *m);
/* draws index_count indices from first_index (index_count 0: to the end) as
   GL_TRIANGLES with the bound program; restores the VAO binding */
void tb_gl_mesh_draw(const tb_gl_funcs *gl, const tb_gl_mesh *m, uint32_t first_index,
                     uint32_t index_count);

typedef struct tb_gl_gbuffer {
    unsigned program;
    int u_view_proj;
} tb_gl_gbuffer;

/* 0 ok; -1 with the compile/link log in err (may be NULL) */
int tb_gl_gbuffer_create(const tb_gl_funcs *gl, tb_gl_gbuffer *g, char *err, size_t errlen);
void tb_gl_gbuffer_destroy(const tb_gl_funcs *gl, tb_gl_gbuffer *g);
/* f: created with TB_GL_COLOR_RGBA16F (normals) or TB_GL_COLOR_NONE (depth
   only); view_proj: world -> clip, column-major. 0 ok, -1 on a GL error. */
int tb_gl_gbuffer_render(const tb_gl_funcs *gl, const tb_gl_gbuffer *g, const tb_gl_mesh *m,
                         const tb_gl_fbo *f, const sk_mat4 *view_proj);

#ifdef __cplusplus
}
#endif
#endif /* TB_GL_SCENE_H */
