/* tb_gl_osmesa.c - OSMesa backend of tb_gl_context (libOSMesa, pkg-config osmesa).
   The only testbed file that includes a system GL header (osmesa.h pulls in
   GL/gl.h). */
#include "tb_gl_backends.h"

#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TB_OSMESA_BUF 16   /* side of the private colour buffer OSMesa renders to */

/* Mesa 22 (Debian 12) libOSMesa keeps 480 bytes per context after
   OSMesaDestroyContext: allocations made inside OSMesaCreateContextAttribs
   and the first OSMesaMakeCurrent (its framebuffer state). LeakSanitizer
   would report them in every program that creates a context. With a
   sanitizer runtime linked in, leak detection is switched off for exactly
   those two calls on this thread (__lsan_disable/__lsan_enable, weak: absent
   and not called in plain builds), so nothing else is exempt: a leak in
   shadowkit_gl.h, the testbed or a test is still reported. With fast
   unwinding (LeakSanitizer's default) the stacks of these allocations stop
   inside libOSMesa, which is why a suppression by function name cannot
   match them and a suppression by library would be too wide. */
#if defined(__GNUC__) || defined(__clang__)
extern void __lsan_disable(void) __attribute__((weak));
extern void __lsan_enable(void) __attribute__((weak));
#define TB_LSAN_OFF() do { if (__lsan_disable) __lsan_disable(); } while (0)
#define TB_LSAN_ON() do { if (__lsan_enable) __lsan_enable(); } while (0)
#else
#define TB_LSAN_OFF() ((void)0)
#define TB_LSAN_ON() ((void)0)
#endif

int tb_gl_osmesa_create(tb_gl_backend_handle *h, char *err, size_t errlen) {
    static const int attribs[] = {
        OSMESA_FORMAT, OSMESA_RGBA,
        OSMESA_DEPTH_BITS, 24,
        OSMESA_STENCIL_BITS, 8,
        OSMESA_PROFILE, OSMESA_CORE_PROFILE,
        OSMESA_CONTEXT_MAJOR_VERSION, 3,
        OSMESA_CONTEXT_MINOR_VERSION, 3,
        0
    };
    OSMesaContext ctx;
    void *buf;
    int current;
    TB_LSAN_OFF();
    ctx = OSMesaCreateContextAttribs(attribs, NULL);
    TB_LSAN_ON();
    if (!ctx) {
        if (err) snprintf(err, errlen, "OSMesaCreateContextAttribs (3.3 core) failed");
        return -1;
    }
    buf = calloc((size_t)TB_OSMESA_BUF * TB_OSMESA_BUF, 4);
    if (!buf) {
        OSMesaDestroyContext(ctx);
        if (err) snprintf(err, errlen, "out of memory");
        return -1;
    }
    TB_LSAN_OFF();
    current = OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, TB_OSMESA_BUF, TB_OSMESA_BUF);
    TB_LSAN_ON();
    if (!current) {
        OSMesaDestroyContext(ctx);
        free(buf);
        if (err) snprintf(err, errlen, "OSMesaMakeCurrent failed");
        return -1;
    }
    memset(h, 0, sizeof *h);
    h->a = ctx;
    h->b = buf;
    h->name = "osmesa";
    return 0;
}

int tb_gl_osmesa_make_current(tb_gl_backend_handle *h) {
    return OSMesaMakeCurrent((OSMesaContext)h->a, h->b, GL_UNSIGNED_BYTE, TB_OSMESA_BUF,
                             TB_OSMESA_BUF) ? 0 : -1;
}

void tb_gl_osmesa_destroy(tb_gl_backend_handle *h) {
    if (h->a) {
        if (OSMesaGetCurrentContext() == (OSMesaContext)h->a)
            OSMesaMakeCurrent(NULL, NULL, GL_UNSIGNED_BYTE, 0, 0);
        OSMesaDestroyContext((OSMesaContext)h->a);
    }
    free(h->b);
    memset(h, 0, sizeof *h);
}

void *tb_gl_osmesa_getproc(const char *name) {
    OSMESAproc f = OSMesaGetProcAddress(name);
    void *p;
    /* function pointer -> object pointer without the ISO C cast warning */
    memcpy(&p, &f, sizeof p);
    return p;
}
