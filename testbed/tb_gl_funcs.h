/* tb_gl_funcs.h - the GL 3.3 core entry points the testbed calls itself,
   loaded through a getproc function (tb_gl_context_getproc(),
   glfwGetProcAddress, ...) into a table: no system GL header, coexists with
   glad/GLEW and with shadowkit_gl.h's own private table. GL types are
   spelled as C types (GLenum/GLuint/GLbitfield = unsigned, GLint/GLsizei =
   int, GLfloat = float, GLdouble = double, GLboolean = unsigned char,
   GLsizeiptr = ptrdiff_t, GLchar = char). Call as gl->Clear(mask). */
#ifndef TB_GL_FUNCS_H
#define TB_GL_FUNCS_H

#include <stddef.h>
#include "tb_gl_context.h"

#ifdef __cplusplus
extern "C" {
#endif

#if defined(_WIN32) && !defined(__CYGWIN__)
#define TB_GLAPI __stdcall
#else
#define TB_GLAPI
#endif

/* X(return type, name without "gl", parameter list) */
#define TB_GL_FUNC_LIST(X) \
    X(unsigned, GetError, (void)) \
    X(void, GetIntegerv, (unsigned pname, int *data)) \
    X(const unsigned char *, GetString, (unsigned name)) \
    X(void, Finish, (void)) \
    X(void, Viewport, (int x, int y, int w, int h)) \
    X(void, ClearColor, (float r, float g, float b, float a)) \
    X(void, ClearDepth, (double d)) \
    X(void, Clear, (unsigned mask)) \
    X(void, Enable, (unsigned cap)) \
    X(void, Disable, (unsigned cap)) \
    X(unsigned char, IsEnabled, (unsigned cap)) \
    X(void, DepthFunc, (unsigned func)) \
    X(void, DepthMask, (unsigned char flag)) \
    X(void, PixelStorei, (unsigned pname, int param)) \
    X(void, ReadBuffer, (unsigned mode)) \
    X(void, ReadPixels, (int x, int y, int w, int h, unsigned format, unsigned type, void *data)) \
    X(void, GenTextures, (int n, unsigned *ids)) \
    X(void, DeleteTextures, (int n, const unsigned *ids)) \
    X(void, BindTexture, (unsigned target, unsigned id)) \
    X(void, ActiveTexture, (unsigned unit)) \
    X(void, TexImage2D, (unsigned target, int level, int internal, int w, int h, int border, \
                         unsigned format, unsigned type, const void *data)) \
    X(void, TexParameteri, (unsigned target, unsigned pname, int param)) \
    X(void, GenFramebuffers, (int n, unsigned *ids)) \
    X(void, DeleteFramebuffers, (int n, const unsigned *ids)) \
    X(void, BindFramebuffer, (unsigned target, unsigned id)) \
    X(void, FramebufferTexture2D, (unsigned target, unsigned attach, unsigned textarget, \
                                   unsigned tex, int level)) \
    X(unsigned, CheckFramebufferStatus, (unsigned target)) \
    X(void, DrawBuffers, (int n, const unsigned *bufs)) \
    X(unsigned, CreateShader, (unsigned type)) \
    X(void, ShaderSource, (unsigned sh, int count, const char *const *src, const int *len)) \
    X(void, CompileShader, (unsigned sh)) \
    X(void, GetShaderiv, (unsigned sh, unsigned pname, int *out)) \
    X(void, GetShaderInfoLog, (unsigned sh, int size, int *len, char *log)) \
    X(void, DeleteShader, (unsigned sh)) \
    X(unsigned, CreateProgram, (void)) \
    X(void, AttachShader, (unsigned prog, unsigned sh)) \
    X(void, BindAttribLocation, (unsigned prog, unsigned index, const char *name)) \
    X(void, LinkProgram, (unsigned prog)) \
    X(void, GetProgramiv, (unsigned prog, unsigned pname, int *out)) \
    X(void, GetProgramInfoLog, (unsigned prog, int size, int *len, char *log)) \
    X(void, DeleteProgram, (unsigned prog)) \
    X(void, UseProgram, (unsigned prog)) \
    X(int, GetUniformLocation, (unsigned prog, const char *name)) \
    X(void, UniformMatrix4fv, (int loc, int count, unsigned char transpose, const float *v)) \
    X(void, Uniform3f, (int loc, float x, float y, float z)) \
    X(void, GenVertexArrays, (int n, unsigned *ids)) \
    X(void, DeleteVertexArrays, (int n, const unsigned *ids)) \
    X(void, BindVertexArray, (unsigned id)) \
    X(void, GenBuffers, (int n, unsigned *ids)) \
    X(void, DeleteBuffers, (int n, const unsigned *ids)) \
    X(void, BindBuffer, (unsigned target, unsigned id)) \
    X(void, BufferData, (unsigned target, ptrdiff_t size, const void *data, unsigned usage)) \
    X(void, VertexAttribPointer, (unsigned index, int size, unsigned type, unsigned char norm, \
                                  int stride, const void *offset)) \
    X(void, EnableVertexAttribArray, (unsigned index)) \
    X(void, Uniform1i, (int loc, int v)) \
    X(void, VertexAttribDivisor, (unsigned index, unsigned divisor)) \
    X(void, DrawElementsInstanced, (unsigned mode, int count, unsigned type, const void *offset, int instances)) \
    X(void, DrawElements, (unsigned mode, int count, unsigned type, const void *offset))

#define TB_GL_DECLARE_(ret, name, params) ret (TB_GLAPI *name) params;
typedef struct tb_gl_funcs {
    TB_GL_FUNC_LIST(TB_GL_DECLARE_)
} tb_gl_funcs;
#undef TB_GL_DECLARE_

/* 0 when every entry point was found; -1 otherwise (missing ones are NULL,
   their names printed to stderr) */
int tb_gl_funcs_load(tb_gl_funcs *gl, tb_gl_getproc_fn getproc);

#ifdef __cplusplus
}
#endif
#endif /* TB_GL_FUNCS_H */
