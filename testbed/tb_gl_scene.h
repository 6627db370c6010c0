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

   tb_gl_instanced (below): one mesh drawn many times with per-instance
   offsets, and an alpha-tested G-buffer for it (the forest's trees).

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
    int u_alpha;              /* tb_gl_gbuffer_create_instanced's alpha sampler; -1 otherwise */
} tb_gl_gbuffer;

/* 0 ok; -1 with the compile/link log in err (may be NULL) */
int tb_gl_gbuffer_create(const tb_gl_funcs *gl, tb_gl_gbuffer *g, char *err, size_t errlen);
void tb_gl_gbuffer_destroy(const tb_gl_funcs *gl, tb_gl_gbuffer *g);
/* f: created with TB_GL_COLOR_RGBA16F (normals) or TB_GL_COLOR_NONE (depth
   only); view_proj: world -> clip, column-major. 0 ok, -1 on a GL error. */
int tb_gl_gbuffer_render(const tb_gl_funcs *gl, const tb_gl_gbuffer *g, const tb_gl_mesh *m,
                         const tb_gl_fbo *f, const sk_mat4 *view_proj);

/* ---- instanced, alpha-tested meshes (the forest's trees) ----------------
   tb_gl_instanced: one mesh (positions attribute 0, normals 1, uv 2, vec2)
   drawn instance_count times; per instance (divisor 1) attribute 3, vec4
   (offset x, y, z, scale s) and attribute 4, vec2 (s cos yaw, s sin yaw):
   TB_FOREST_INSTANCE_FLOATS floats an instance, tb_forest_instances'
   layout and tb_forest_instance_point's transform. alpha_tex: an R8
   texture, nearest, GL_REPEAT (0 when none was given). */
typedef struct tb_gl_instanced {
    unsigned vao, vbo_pos, vbo_nrm, vbo_uv, vbo_inst, ibo, alpha_tex;
    uint32_t index_count, instance_count;
} tb_gl_instanced;

/* mesh: its positions, normals and indices (every object); uv: 2 floats a
   vertex; instances: 6 floats each; alpha: alpha_w x alpha_h bytes, row 0
   first, or NULL. 0 ok, -1 (nothing allocated) on bad arguments or a GL
   error. Restores the VAO, array buffer and texture bindings it changes. */
int tb_gl_instanced_create(const tb_gl_funcs *gl, tb_gl_instanced *m, const tb_scene *mesh, const float *uv,
                           const float *instances, uint32_t instance_count, const unsigned char *alpha, int alpha_w,
                           int alpha_h);
void tb_gl_instanced_destroy(const tb_gl_funcs *gl, tb_gl_instanced *m);
/* every instance (glDrawElementsInstanced) with the bound program; restores
   the VAO binding */
void tb_gl_instanced_draw(const tb_gl_funcs *gl, const tb_gl_instanced *m);

/* Those instances' GLSL in shadowkit's caster-hook form (shadowkit_gl.h,
   skgl_caster_desc: .vertex, .fragment, .varyings, uniform "u_alpha"):
   the vertex hook reads attributes 0, 2, 3 and 4 and returns the instance
   transform of the vertex (writing v_uv); the fragment hook discards where
   the alpha texture (sampler u_alpha, its red channel) is below 0.5. The
   G-buffer program of tb_gl_gbuffer_create_instanced is built from the
   same strings, so the camera sees what casts. */
extern const char tb_gl_instanced_vertex_hook[];
extern const char tb_gl_instanced_fragment_hook[];
#define TB_GL_INSTANCED_VARYINGS "vec2 v_uv;"

/* A G-buffer program for tb_gl_instanced: the vertex hook, and with
   alpha_test the fragment hook; the normal is the triangle's own (from the
   screen derivatives of the world position), toward the camera. 0 ok; -1
   with the log in err (may be NULL). */
int tb_gl_gbuffer_create_instanced(const tb_gl_funcs *gl, tb_gl_gbuffer *g, int alpha_test, char *err,
                                   size_t errlen);
/* tb_gl_gbuffer_render's pass, then the instances with gi (its alpha
   texture on unit 0 for u_alpha) into the same buffers. Saves and restores
   what tb_gl_gbuffer_render does, and the active texture unit and unit 0's
   2D texture. 0 ok, -1 on a GL error. */
int tb_gl_gbuffer_render_instanced(const tb_gl_funcs *gl, const tb_gl_gbuffer *g, const tb_gl_mesh *m,
                                   const tb_gl_gbuffer *gi, const tb_gl_instanced *inst, const tb_gl_fbo *f,
                                   const sk_mat4 *view_proj);

#ifdef __cplusplus
}
#endif
#endif /* TB_GL_SCENE_H */
