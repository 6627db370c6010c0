/* tb_gl_context.c - backend selection and queries; see tb_gl_context.h */
#include "tb_gl_context.h"
#include "tb_gl_backends.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#if defined(_WIN32) && !defined(__CYGWIN__)
#define TB_APIENTRY __stdcall
#else
#define TB_APIENTRY
#endif

struct tb_gl_context {
    tb_gl_backend backend;           /* TB_GL_OSMESA or TB_GL_EGL */
    tb_gl_backend_handle h;
    char renderer[256];
    char version[256];
    int major, minor, core, debug;
};

typedef const unsigned char *(TB_APIENTRY *tb_pfn_get_string_)(unsigned name);
typedef void (TB_APIENTRY *tb_pfn_get_integerv_)(unsigned name, int *data);

static void tb_query_strings_(tb_gl_context *c) {
    tb_gl_getproc_fn gp = tb_gl_context_getproc(c);
    void *p1 = gp("glGetString"), *p2 = gp("glGetIntegerv");
    tb_pfn_get_string_ get_string;
    tb_pfn_get_integerv_ get_integerv;
    const unsigned char *s;
    int mask = 0;
    memcpy(&get_string, &p1, sizeof p1);
    memcpy(&get_integerv, &p2, sizeof p2);
    strcpy(c->renderer, "unknown");
    strcpy(c->version, "unknown");
    if (get_string) {
        if ((s = get_string(0x1F01 /* GL_RENDERER */)) != NULL)
            snprintf(c->renderer, sizeof c->renderer, "%s", (const char *)s);
        if ((s = get_string(0x1F02 /* GL_VERSION */)) != NULL)
            snprintf(c->version, sizeof c->version, "%s", (const char *)s);
    }
    if (get_integerv) {
        get_integerv(0x821B /* GL_MAJOR_VERSION */, &c->major);
        get_integerv(0x821C /* GL_MINOR_VERSION */, &c->minor);
        get_integerv(0x9126 /* GL_CONTEXT_PROFILE_MASK */, &mask);
        c->core = (mask & 1 /* GL_CONTEXT_CORE_PROFILE_BIT */) ? 1 : 0;
        mask = 0;
        get_integerv(0x821E /* GL_CONTEXT_FLAGS */, &mask);
        c->debug = (mask & 2 /* GL_CONTEXT_FLAG_DEBUG_BIT */) ? 1 : 0;
    }
    if (c->h.es) {   /* ES has no GL_CONTEXT_PROFILE_MASK: drop its GL_INVALID_ENUM */
        void *p3 = gp("glGetError");
        unsigned (*get_error)(void);
        memcpy(&get_error, &p3, sizeof p3);
        while (get_error && get_error() != 0) {}
    }
}

static void tb_append_(char *err, size_t errlen, const char *what, const char *msg) {
    size_t n;
    if (!err || errlen == 0) return;
    n = strlen(err);
    if (n + 1 < errlen) snprintf(err + n, errlen - n, "%s%s: %s", n ? "; " : "", what, msg);
}

tb_gl_context *tb_gl_context_create(tb_gl_backend want, char *err, size_t errlen) {
    return tb_gl_context_create_flags(want, 0, err, errlen);
}

tb_gl_context *tb_gl_context_create_flags(tb_gl_backend want, int flags, char *err, size_t errlen) {
    char msg[256];
    tb_gl_context *c = (tb_gl_context *)calloc(1, sizeof *c);
    int try_egl_hw = 0, try_egl_any = 0, try_osmesa = 0;
    if (err && errlen) err[0] = 0;
    if (!c) {
        tb_append_(err, errlen, "tb_gl_context", "out of memory");
        return NULL;
    }
    if (want == TB_GL_AUTO) {
        const char *env = getenv("SK_GL");
        if (env && strcmp(env, "osmesa") == 0) want = TB_GL_OSMESA;
        else if (env && strcmp(env, "egl") == 0) want = TB_GL_EGL;
        else if (env && env[0]) {
            tb_append_(err, errlen, "SK_GL", "expected \"osmesa\" or \"egl\"");
            free(c);
            return NULL;
        }
    }
    if (flags & TB_GL_CONTEXT_ES3) want = TB_GL_EGL;   /* OSMesa makes desktop contexts only */
    if (want == TB_GL_AUTO) try_egl_hw = try_osmesa = 1;
    else if (want == TB_GL_EGL) try_egl_any = 1;
    else try_osmesa = 1;

    msg[0] = 0;
    if (try_egl_hw || try_egl_any) {
        if (tb_gl_egl_create(&c->h, try_egl_hw, flags, msg, sizeof msg) == 0) {
            c->backend = TB_GL_EGL;
            tb_query_strings_(c);
            return c;
        }
        tb_append_(err, errlen, "egl", msg);
    }
    if (try_osmesa) {
        if (tb_gl_osmesa_create(&c->h, msg, sizeof msg) == 0) {
            c->backend = TB_GL_OSMESA;
            tb_query_strings_(c);
            return c;
        }
        tb_append_(err, errlen, "osmesa", msg);
    }
    free(c);
    return NULL;
}

void tb_gl_context_destroy(tb_gl_context *c) {
    if (!c) return;
    if (c->backend == TB_GL_EGL) tb_gl_egl_destroy(&c->h);
    else tb_gl_osmesa_destroy(&c->h);
    free(c);
}

int tb_gl_context_make_current(tb_gl_context *c) {
    if (!c) return -1;
    return c->backend == TB_GL_EGL ? tb_gl_egl_make_current(&c->h)
                                   : tb_gl_osmesa_make_current(&c->h);
}

tb_gl_getproc_fn tb_gl_context_getproc(const tb_gl_context *c) {
    if (c && c->backend == TB_GL_EGL) return tb_gl_egl_getproc;
    return tb_gl_osmesa_getproc;
}

const char *tb_gl_context_backend_name(const tb_gl_context *c) {
    return c && c->h.name ? c->h.name : "none";
}

const char *tb_gl_context_renderer(const tb_gl_context *c) { return c ? c->renderer : ""; }
const char *tb_gl_context_version(const tb_gl_context *c) { return c ? c->version : ""; }

int tb_gl_context_debug(const tb_gl_context *c) { return c ? c->debug : 0; }

void tb_gl_context_gl_version(const tb_gl_context *c, int *major, int *minor, int *core) {
    if (major) *major = c ? c->major : 0;
    if (minor) *minor = c ? c->minor : 0;
    if (core) *core = c ? c->core : 0;
}
