/* tb_gl_funcs.c - see tb_gl_funcs.h */
#include "tb_gl_funcs.h"

#include <stdio.h>
#include <string.h>

int tb_gl_funcs_load(tb_gl_funcs *gl, tb_gl_getproc_fn getproc) {
    struct { const char *name; void *slot; size_t size; } t[] = {
#define TB_GL_ENTRY_(ret, fn, params) { "gl" #fn, (void *)&gl->fn, sizeof gl->fn },
        TB_GL_FUNC_LIST(TB_GL_ENTRY_)
#undef TB_GL_ENTRY_
    };
    size_t i;
    int ok = 1;
    memset(gl, 0, sizeof *gl);
    if (!getproc) return -1;
    for (i = 0; i < sizeof t / sizeof t[0]; i++) {
        void *p = getproc(t[i].name);
        if (!p) {
            fprintf(stderr, "tb_gl_funcs_load: %s not found\n", t[i].name);
            ok = 0;
        }
        /* object pointer -> function pointer without the ISO C cast */
        memcpy(t[i].slot, &p, t[i].size < sizeof p ? t[i].size : sizeof p);
    }
    return ok ? 0 : -1;
}
