/* tb_gl_scene.c - see tb_gl_scene.h */
#include "tb_gl_scene.h"

#include <stdio.h>
#include <string.h>

#define TB_GL_TRIANGLES 0x0004
#define TB_GL_UNSIGNED_INT 0x1405
#define TB_GL_FLOAT 0x1406
#define TB_GL_ARRAY_BUFFER 0x8892
#define TB_GL_ELEMENT_ARRAY_BUFFER 0x8893
#define TB_GL_STATIC_DRAW 0x88E4
#define TB_GL_ARRAY_BUFFER_BINDING 0x8894
#define TB_GL_VERTEX_ARRAY_BINDING 0x85B5
#define TB_GL_CURRENT_PROGRAM 0x8B8D
#define TB_GL_VERTEX_SHADER 0x8B31
#define TB_GL_FRAGMENT_SHADER 0x8B30
#define TB_GL_COMPILE_STATUS 0x8B81
#define TB_GL_LINK_STATUS 0x8B82
#define TB_GL_DEPTH_TEST 0x0B71
#define TB_GL_CULL_FACE 0x0B44
#define TB_GL_DEPTH_FUNC 0x0B74
#define TB_GL_DEPTH_WRITEMASK 0x0B72
#define TB_GL_LESS 0x0201
#define TB_GL_VIEWPORT 0x0BA2
#define TB_GL_DRAW_FRAMEBUFFER 0x8CA9
#define TB_GL_DRAW_FRAMEBUFFER_BINDING 0x8CA6
#define TB_GL_COLOR_BUFFER_BIT 0x4000
#define TB_GL_DEPTH_BUFFER_BIT 0x0100
#define TB_GL_TEXTURE_2D 0x0DE1
#define TB_GL_TEXTURE0 0x84C0
#define TB_GL_ACTIVE_TEXTURE 0x84E0
#define TB_GL_TEXTURE_BINDING_2D 0x8069
#define TB_GL_R8 0x8229
#define TB_GL_RED 0x1903
#define TB_GL_UNSIGNED_BYTE 0x1401
#define TB_GL_NEAREST 0x2600
#define TB_GL_REPEAT 0x2901
#define TB_GL_TEXTURE_MIN_FILTER 0x2801
#define TB_GL_TEXTURE_MAG_FILTER 0x2800
#define TB_GL_TEXTURE_WRAP_S 0x2802
#define TB_GL_TEXTURE_WRAP_T 0x2803
#define TB_GL_UNPACK_ALIGNMENT 0x0CF5

int tb_gl_mesh_create(const tb_gl_funcs *gl, tb_gl_mesh *m, const tb_scene *s) {
    int prev_vao = 0, prev_buf = 0;
    ptrdiff_t vbytes;
    memset(m, 0, sizeof *m);
    if (!s || s->index_count == 0 || !s->positions || !s->normals) return -1;
    vbytes = (ptrdiff_t)((size_t)s->vertex_count * 3 * sizeof(float));
    while (gl->GetError() != 0) {}
    gl->GetIntegerv(TB_GL_VERTEX_ARRAY_BINDING, &prev_vao);
    gl->GetIntegerv(TB_GL_ARRAY_BUFFER_BINDING, &prev_buf);
    gl->GenVertexArrays(1, &m->vao);
    gl->BindVertexArray(m->vao);
    gl->GenBuffers(1, &m->vbo_pos);
    gl->BindBuffer(TB_GL_ARRAY_BUFFER, m->vbo_pos);
    gl->BufferData(TB_GL_ARRAY_BUFFER, vbytes, s->positions, TB_GL_STATIC_DRAW);
    gl->VertexAttribPointer(0, 3, TB_GL_FLOAT, 0, 3 * (int)sizeof(float), NULL);
    gl->EnableVertexAttribArray(0);
    gl->GenBuffers(1, &m->vbo_nrm);
    gl->BindBuffer(TB_GL_ARRAY_BUFFER, m->vbo_nrm);
    gl->BufferData(TB_GL_ARRAY_BUFFER, vbytes, s->normals, TB_GL_STATIC_DRAW);
    gl->VertexAttribPointer(1, 3, TB_GL_FLOAT, 0, 3 * (int)sizeof(float), NULL);
    gl->EnableVertexAttribArray(1);
    gl->GenBuffers(1, &m->ibo);
    gl->BindBuffer(TB_GL_ELEMENT_ARRAY_BUFFER, m->ibo);   /* VAO state */
    gl->BufferData(TB_GL_ELEMENT_ARRAY_BUFFER, (ptrdiff_t)((size_t)s->index_count * sizeof(uint32_t)),
                   s->indices, TB_GL_STATIC_DRAW);
    m->index_count = s->index_count;
    gl->BindVertexArray((unsigned)prev_vao);
    gl->BindBuffer(TB_GL_ARRAY_BUFFER, (unsigned)prev_buf);
    if (gl->GetError() != 0) {
        tb_gl_mesh_destroy(gl, m);
        return -1;
    }
    return 0;
}

void tb_gl_mesh_destroy(const tb_gl_funcs *gl, tb_gl_mesh *m) {
    if (m->vao) gl->DeleteVertexArrays(1, &m->vao);
    if (m->vbo_pos) gl->DeleteBuffers(1, &m->vbo_pos);
    if (m->vbo_nrm) gl->DeleteBuffers(1, &m->vbo_nrm);
    if (m->ibo) gl->DeleteBuffers(1, &m->ibo);
    memset(m, 0, sizeof *m);
}

void tb_gl_mesh_draw(const tb_gl_funcs *gl, const tb_gl_mesh *m, uint32_t first_index,
                     uint32_t index_count) {
    int prev_vao = 0;
    if (first_index >= m->index_count) return;
    if (index_count == 0 || index_count > m->index_count - first_index)
        index_count = m->index_count - first_index;
    gl->GetIntegerv(TB_GL_VERTEX_ARRAY_BINDING, &prev_vao);
    gl->BindVertexArray(m->vao);
    gl->DrawElements(TB_GL_TRIANGLES, (int)index_count, TB_GL_UNSIGNED_INT,
                     (const void *)(uintptr_t)((size_t)first_index * sizeof(uint32_t)));
    gl->BindVertexArray((unsigned)prev_vao);
}

static const char *tb_gbuffer_vs_ =
    "#version 330 core\n"
    "layout(location = 0) in vec3 a_position;\n"
    "layout(location = 1) in vec3 a_normal;\n"
    "uniform mat4 u_view_proj;\n"
    "out vec3 v_normal;\n"
    "void main() {\n"
    "    v_normal = a_normal;\n"
    "    gl_Position = u_view_proj * vec4(a_position, 1.0);\n"
    "}\n";

static const char *tb_gbuffer_fs_ =
    "#version 330 core\n"
    "in vec3 v_normal;\n"
    "layout(location = 0) out vec4 o_normal;\n"
    "void main() {\n"
    "    vec3 n = normalize(v_normal);\n"
    "    o_normal = vec4(gl_FrontFacing ? n : -n, 1.0);   /* toward the camera */\n"
    "}\n";

/* a shader from count source strings; 0 (the log in err) when it fails */
static unsigned tb_compile_parts_(const tb_gl_funcs *gl, unsigned type, int count, const char *const *src, char *err,
                                  size_t errlen) {
    unsigned sh = gl->CreateShader(type);
    int ok = 0;
    gl->ShaderSource(sh, count, src, NULL);
    gl->CompileShader(sh);
    gl->GetShaderiv(sh, TB_GL_COMPILE_STATUS, &ok);
    if (!ok) {
        if (err && errlen) gl->GetShaderInfoLog(sh, (int)errlen, NULL, err);
        gl->DeleteShader(sh);
        return 0;
    }
    return sh;
}

static unsigned tb_compile_(const tb_gl_funcs *gl, unsigned type, const char *src, char *err, size_t errlen) {
    return tb_compile_parts_(gl, type, 1, &src, err, errlen);
}

/* the program of vs and fs (both deleted: flagged, freed with the
   program); 0 (the log in err) when it does not link */
static unsigned tb_link_(const tb_gl_funcs *gl, unsigned vs, unsigned fs, char *err, size_t errlen) {
    unsigned p = gl->CreateProgram();
    int ok = 0;
    gl->AttachShader(p, vs);
    gl->AttachShader(p, fs);
    gl->LinkProgram(p);
    gl->DeleteShader(vs);
    gl->DeleteShader(fs);
    gl->GetProgramiv(p, TB_GL_LINK_STATUS, &ok);
    if (!ok) {
        if (err && errlen) gl->GetProgramInfoLog(p, (int)errlen, NULL, err);
        gl->DeleteProgram(p);
        return 0;
    }
    return p;
}

int tb_gl_gbuffer_create(const tb_gl_funcs *gl, tb_gl_gbuffer *g, char *err, size_t errlen) {
    unsigned vs, fs;
    memset(g, 0, sizeof *g);
    if (err && errlen) err[0] = 0;
    vs = tb_compile_(gl, TB_GL_VERTEX_SHADER, tb_gbuffer_vs_, err, errlen);
    if (!vs) return -1;
    fs = tb_compile_(gl, TB_GL_FRAGMENT_SHADER, tb_gbuffer_fs_, err, errlen);
    if (!fs) { gl->DeleteShader(vs); return -1; }
    g->program = tb_link_(gl, vs, fs, err, errlen);
    if (!g->program) return -1;
    g->u_view_proj = gl->GetUniformLocation(g->program, "u_view_proj");
    g->u_alpha = -1;
    return 0;
}

void tb_gl_gbuffer_destroy(const tb_gl_funcs *gl, tb_gl_gbuffer *g) {
    if (g->program) gl->DeleteProgram(g->program);
    memset(g, 0, sizeof *g);
}

/* the G-buffer pass: m with g, then (when gi) inst with gi */
static int tb_gbuffer_pass_(const tb_gl_funcs *gl, const tb_gl_gbuffer *g, const tb_gl_mesh *m,
                            const tb_gl_gbuffer *gi, const tb_gl_instanced *inst, const tb_gl_fbo *f,
                            const sk_mat4 *view_proj) {
    int prev_fbo = 0, prev_prog = 0, prev_vp[4] = {0, 0, 0, 0}, prev_func = TB_GL_LESS, prev_mask = 1;
    unsigned char depth_on, cull_on;
    unsigned err;
    if (!g->program || !f || !f->fbo || !view_proj) return -1;
    while (gl->GetError() != 0) {}
    gl->GetIntegerv(TB_GL_DRAW_FRAMEBUFFER_BINDING, &prev_fbo);
    gl->GetIntegerv(TB_GL_CURRENT_PROGRAM, &prev_prog);
    gl->GetIntegerv(TB_GL_VIEWPORT, prev_vp);
    gl->GetIntegerv(TB_GL_DEPTH_FUNC, &prev_func);
    gl->GetIntegerv(TB_GL_DEPTH_WRITEMASK, &prev_mask);
    depth_on = gl->IsEnabled(TB_GL_DEPTH_TEST);
    cull_on = gl->IsEnabled(TB_GL_CULL_FACE);

    gl->BindFramebuffer(TB_GL_DRAW_FRAMEBUFFER, f->fbo);
    gl->Viewport(0, 0, f->width, f->height);
    gl->Enable(TB_GL_DEPTH_TEST);
    gl->DepthFunc(TB_GL_LESS);
    gl->DepthMask(1);
    gl->Disable(TB_GL_CULL_FACE);
    gl->ClearColor(0, 0, 0, 0);
    gl->ClearDepth(1.0);
    gl->Clear(TB_GL_COLOR_BUFFER_BIT | TB_GL_DEPTH_BUFFER_BIT);
    gl->UseProgram(g->program);
    gl->UniformMatrix4fv(g->u_view_proj, 1, 0, view_proj->m);
    if (m) tb_gl_mesh_draw(gl, m, 0, 0);
    if (gi && inst) {
        int prev_unit = TB_GL_TEXTURE0, prev_tex = 0;
        gl->GetIntegerv(TB_GL_ACTIVE_TEXTURE, &prev_unit);
        gl->ActiveTexture(TB_GL_TEXTURE0);
        gl->GetIntegerv(TB_GL_TEXTURE_BINDING_2D, &prev_tex);
        gl->BindTexture(TB_GL_TEXTURE_2D, inst->alpha_tex);
        gl->UseProgram(gi->program);
        gl->UniformMatrix4fv(gi->u_view_proj, 1, 0, view_proj->m);
        if (gi->u_alpha >= 0) gl->Uniform1i(gi->u_alpha, 0);
        tb_gl_instanced_draw(gl, inst);
        gl->BindTexture(TB_GL_TEXTURE_2D, (unsigned)prev_tex);
        gl->ActiveTexture((unsigned)prev_unit);
    }

    gl->UseProgram((unsigned)prev_prog);
    if (!depth_on) gl->Disable(TB_GL_DEPTH_TEST);
    if (cull_on) gl->Enable(TB_GL_CULL_FACE);
    gl->DepthFunc((unsigned)prev_func);
    gl->DepthMask((unsigned char)(prev_mask ? 1 : 0));
    gl->Viewport(prev_vp[0], prev_vp[1], prev_vp[2], prev_vp[3]);
    gl->BindFramebuffer(TB_GL_DRAW_FRAMEBUFFER, (unsigned)prev_fbo);
    err = gl->GetError();
    return err == 0 ? 0 : -1;
}

int tb_gl_gbuffer_render(const tb_gl_funcs *gl, const tb_gl_gbuffer *g, const tb_gl_mesh *m,
                         const tb_gl_fbo *f, const sk_mat4 *view_proj) {
    return tb_gbuffer_pass_(gl, g, m, NULL, NULL, f, view_proj);
}

/* ---- instanced, alpha-tested meshes ---- */

const char tb_gl_instanced_vertex_hook[] =
    "layout(location = 0) in vec3 a_pos;\n"
    "layout(location = 2) in vec2 a_uv;\n"
    "layout(location = 3) in vec4 a_offset;   /* x, y, z, scale s */\n"
    "layout(location = 4) in vec2 a_turn;     /* s cos(yaw), s sin(yaw) */\n"
    "vec4 skgl_caster_position()\n"
    "{\n"
    "    v_uv = a_uv;\n"
    "    return vec4(a_turn.x * a_pos.x - a_turn.y * a_pos.z + a_offset.x, a_offset.w * a_pos.y + a_offset.y,\n"
    "                a_turn.y * a_pos.x + a_turn.x * a_pos.z + a_offset.z, 1.0);\n"
    "}\n";

const char tb_gl_instanced_fragment_hook[] =
    "uniform sampler2D u_alpha;\n"
    "void skgl_caster_fragment()\n"
    "{\n"
    "    if (texture(u_alpha, v_uv).r < 0.5) discard;\n"
    "}\n";

static const char tb_instanced_vs_main_[] =
    "uniform mat4 u_view_proj;\n"
    "out vec3 v_world;\n"
    "void main() {\n"
    "    vec4 w = skgl_caster_position();\n"
    "    v_world = w.xyz;\n"
    "    gl_Position = u_view_proj * w;\n"
    "}\n";

/* cross(dFdx, dFdy) of the world position: the triangle's plane, and
   (window x right, y up) toward the camera whatever the winding */
static const char tb_instanced_fs_main_[] =
    "in vec3 v_world;\n"
    "layout(location = 0) out vec4 o_normal;\n"
    "void main() {\n"
    "    skgl_caster_fragment();\n"
    "    o_normal = vec4(normalize(cross(dFdx(v_world), dFdy(v_world))), 1.0);\n"
    "}\n";

static const char tb_no_alpha_test_[] = "void skgl_caster_fragment() {}\n";

int tb_gl_gbuffer_create_instanced(const tb_gl_funcs *gl, tb_gl_gbuffer *g, int alpha_test, char *err,
                                   size_t errlen) {
    const char *vs[4], *fs[4];
    unsigned v, f;
    memset(g, 0, sizeof *g);
    g->u_alpha = -1;
    if (err && errlen) err[0] = 0;
    vs[0] = "#version 330 core\nout " TB_GL_INSTANCED_VARYINGS "\n";
    vs[1] = tb_gl_instanced_vertex_hook;
    vs[2] = tb_instanced_vs_main_;
    fs[0] = "#version 330 core\nin " TB_GL_INSTANCED_VARYINGS "\n";
    fs[1] = alpha_test ? tb_gl_instanced_fragment_hook : tb_no_alpha_test_;
    fs[2] = tb_instanced_fs_main_;
    v = tb_compile_parts_(gl, TB_GL_VERTEX_SHADER, 3, vs, err, errlen);
    if (!v) return -1;
    f = tb_compile_parts_(gl, TB_GL_FRAGMENT_SHADER, 3, fs, err, errlen);
    if (!f) { gl->DeleteShader(v); return -1; }
    g->program = tb_link_(gl, v, f, err, errlen);
    if (!g->program) return -1;
    g->u_view_proj = gl->GetUniformLocation(g->program, "u_view_proj");
    g->u_alpha = gl->GetUniformLocation(g->program, "u_alpha");
    return 0;
}

int tb_gl_gbuffer_render_instanced(const tb_gl_funcs *gl, const tb_gl_gbuffer *g, const tb_gl_mesh *m,
                                   const tb_gl_gbuffer *gi, const tb_gl_instanced *inst, const tb_gl_fbo *f,
                                   const sk_mat4 *view_proj) {
    if (!gi || !gi->program || !inst) return -1;
    return tb_gbuffer_pass_(gl, g, m, gi, inst, f, view_proj);
}

static unsigned tb_buffer_(const tb_gl_funcs *gl, const void *data, size_t bytes) {
    unsigned b = 0;
    gl->GenBuffers(1, &b);
    gl->BindBuffer(TB_GL_ARRAY_BUFFER, b);
    gl->BufferData(TB_GL_ARRAY_BUFFER, (ptrdiff_t)bytes, data, TB_GL_STATIC_DRAW);
    return b;
}

int tb_gl_instanced_create(const tb_gl_funcs *gl, tb_gl_instanced *m, const tb_scene *mesh, const float *uv,
                           const float *instances, uint32_t instance_count, const unsigned char *alpha, int alpha_w,
                           int alpha_h) {
    int prev_vao = 0, prev_buf = 0, prev_tex = 0, prev_align = 4;
    size_t nv;
    memset(m, 0, sizeof *m);
    if (!mesh || mesh->index_count == 0 || !mesh->positions || !mesh->normals || !uv || !instances ||
        instance_count == 0 || instance_count > 0x7FFFFFFFu || (alpha && (alpha_w <= 0 || alpha_h <= 0)))
        return -1;
    nv = mesh->vertex_count;
    while (gl->GetError() != 0) {}
    gl->GetIntegerv(TB_GL_VERTEX_ARRAY_BINDING, &prev_vao);
    gl->GetIntegerv(TB_GL_ARRAY_BUFFER_BINDING, &prev_buf);
    gl->GenVertexArrays(1, &m->vao);
    gl->BindVertexArray(m->vao);
    m->vbo_pos = tb_buffer_(gl, mesh->positions, nv * 3 * sizeof(float));
    gl->VertexAttribPointer(0, 3, TB_GL_FLOAT, 0, 3 * (int)sizeof(float), NULL);
    gl->EnableVertexAttribArray(0);
    m->vbo_nrm = tb_buffer_(gl, mesh->normals, nv * 3 * sizeof(float));
    gl->VertexAttribPointer(1, 3, TB_GL_FLOAT, 0, 3 * (int)sizeof(float), NULL);
    gl->EnableVertexAttribArray(1);
    m->vbo_uv = tb_buffer_(gl, uv, nv * 2 * sizeof(float));
    gl->VertexAttribPointer(2, 2, TB_GL_FLOAT, 0, 2 * (int)sizeof(float), NULL);
    gl->EnableVertexAttribArray(2);
    m->vbo_inst = tb_buffer_(gl, instances, (size_t)instance_count * TB_FOREST_INSTANCE_FLOATS * sizeof(float));
    gl->VertexAttribPointer(3, 4, TB_GL_FLOAT, 0, TB_FOREST_INSTANCE_FLOATS * (int)sizeof(float), NULL);
    gl->VertexAttribPointer(4, 2, TB_GL_FLOAT, 0, TB_FOREST_INSTANCE_FLOATS * (int)sizeof(float), (const void *)(4 * sizeof(float)));
    gl->EnableVertexAttribArray(3);
    gl->EnableVertexAttribArray(4);
    gl->VertexAttribDivisor(3, 1);
    gl->VertexAttribDivisor(4, 1);
    gl->GenBuffers(1, &m->ibo);
    gl->BindBuffer(TB_GL_ELEMENT_ARRAY_BUFFER, m->ibo);   /* VAO state */
    gl->BufferData(TB_GL_ELEMENT_ARRAY_BUFFER, (ptrdiff_t)((size_t)mesh->index_count * sizeof(uint32_t)),
                   mesh->indices, TB_GL_STATIC_DRAW);
    m->index_count = mesh->index_count;
    m->instance_count = instance_count;
    gl->BindVertexArray((unsigned)prev_vao);
    gl->BindBuffer(TB_GL_ARRAY_BUFFER, (unsigned)prev_buf);
    if (alpha) {
        gl->GetIntegerv(TB_GL_TEXTURE_BINDING_2D, &prev_tex);
        gl->GetIntegerv(TB_GL_UNPACK_ALIGNMENT, &prev_align);
        gl->GenTextures(1, &m->alpha_tex);
        gl->BindTexture(TB_GL_TEXTURE_2D, m->alpha_tex);
        /* rows of alpha_w bytes: not necessarily a multiple of 4 */
        gl->PixelStorei(TB_GL_UNPACK_ALIGNMENT, 1);
        gl->TexImage2D(TB_GL_TEXTURE_2D, 0, TB_GL_R8, alpha_w, alpha_h, 0, TB_GL_RED, TB_GL_UNSIGNED_BYTE, alpha);
        gl->PixelStorei(TB_GL_UNPACK_ALIGNMENT, prev_align);
        /* nearest under GL_REPEAT: the texel tb_reference_set_alpha picks */
        gl->TexParameteri(TB_GL_TEXTURE_2D, TB_GL_TEXTURE_MIN_FILTER, TB_GL_NEAREST);
        gl->TexParameteri(TB_GL_TEXTURE_2D, TB_GL_TEXTURE_MAG_FILTER, TB_GL_NEAREST);
        gl->TexParameteri(TB_GL_TEXTURE_2D, TB_GL_TEXTURE_WRAP_S, TB_GL_REPEAT);
        gl->TexParameteri(TB_GL_TEXTURE_2D, TB_GL_TEXTURE_WRAP_T, TB_GL_REPEAT);
        gl->BindTexture(TB_GL_TEXTURE_2D, (unsigned)prev_tex);
    }
    if (gl->GetError() != 0) {
        tb_gl_instanced_destroy(gl, m);
        return -1;
    }
    return 0;
}

void tb_gl_instanced_destroy(const tb_gl_funcs *gl, tb_gl_instanced *m) {
    if (m->vao) gl->DeleteVertexArrays(1, &m->vao);
    if (m->vbo_pos) gl->DeleteBuffers(1, &m->vbo_pos);
    if (m->vbo_nrm) gl->DeleteBuffers(1, &m->vbo_nrm);
    if (m->vbo_uv) gl->DeleteBuffers(1, &m->vbo_uv);
    if (m->vbo_inst) gl->DeleteBuffers(1, &m->vbo_inst);
    if (m->ibo) gl->DeleteBuffers(1, &m->ibo);
    if (m->alpha_tex) gl->DeleteTextures(1, &m->alpha_tex);
    memset(m, 0, sizeof *m);
}

void tb_gl_instanced_draw(const tb_gl_funcs *gl, const tb_gl_instanced *m) {
    int prev_vao = 0;
    if (!m->vao || m->index_count == 0) return;
    gl->GetIntegerv(TB_GL_VERTEX_ARRAY_BINDING, &prev_vao);
    gl->BindVertexArray(m->vao);
    gl->DrawElementsInstanced(TB_GL_TRIANGLES, (int)m->index_count, TB_GL_UNSIGNED_INT, NULL, (int)m->instance_count);
    gl->BindVertexArray((unsigned)prev_vao);
}
