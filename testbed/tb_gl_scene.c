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

static unsigned tb_compile_(const tb_gl_funcs *gl, unsigned type, const char *src, char *err,
                            size_t errlen) {
    unsigned sh = gl->CreateShader(type);
    int ok = 0;
    gl->ShaderSource(sh, 1, &src, NULL);
    gl->CompileShader(sh);
    gl->GetShaderiv(sh, TB_GL_COMPILE_STATUS, &ok);
    if (!ok) {
        if (err && errlen) gl->GetShaderInfoLog(sh, (int)errlen, NULL, err);
        gl->DeleteShader(sh);
        return 0;
    }
    return sh;
}

int tb_gl_gbuffer_create(const tb_gl_funcs *gl, tb_gl_gbuffer *g, char *err, size_t errlen) {
    unsigned vs, fs;
    int ok = 0;
    memset(g, 0, sizeof *g);
    if (err && errlen) err[0] = 0;
    vs = tb_compile_(gl, TB_GL_VERTEX_SHADER, tb_gbuffer_vs_, err, errlen);
    if (!vs) return -1;
    fs = tb_compile_(gl, TB_GL_FRAGMENT_SHADER, tb_gbuffer_fs_, err, errlen);
    if (!fs) { gl->DeleteShader(vs); return -1; }
    g->program = gl->CreateProgram();
    gl->AttachShader(g->program, vs);
    gl->AttachShader(g->program, fs);
    gl->LinkProgram(g->program);
    gl->DeleteShader(vs);   /* flagged; freed with the program */
    gl->DeleteShader(fs);
    gl->GetProgramiv(g->program, TB_GL_LINK_STATUS, &ok);
    if (!ok) {
        if (err && errlen) gl->GetProgramInfoLog(g->program, (int)errlen, NULL, err);
        gl->DeleteProgram(g->program);
        g->program = 0;
        return -1;
    }
    g->u_view_proj = gl->GetUniformLocation(g->program, "u_view_proj");
    return 0;
}

void tb_gl_gbuffer_destroy(const tb_gl_funcs *gl, tb_gl_gbuffer *g) {
    if (g->program) gl->DeleteProgram(g->program);
    memset(g, 0, sizeof *g);
}

int tb_gl_gbuffer_render(const tb_gl_funcs *gl, const tb_gl_gbuffer *g, const tb_gl_mesh *m,
                         const tb_gl_fbo *f, const sk_mat4 *view_proj) {
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
