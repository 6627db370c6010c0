/* tb_gl_egl.c - EGL backend of tb_gl_context (libEGL, pkg-config egl).
   Device platform (EGL_EXT_device_enumeration + EGL_EXT_platform_device),
   else Mesa's surfaceless platform; desktop GL 3.3 core, no window system. */
#include "tb_gl_backends.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <stdio.h>
#include <string.h>

#ifndef EGL_PLATFORM_SURFACELESS_MESA
#define EGL_PLATFORM_SURFACELESS_MESA 0x31DD
#endif
#ifndef EGL_PLATFORM_DEVICE_EXT
#define EGL_PLATFORM_DEVICE_EXT 0x313F
#endif

#define TB_EGL_MAX_DEVICES 16

static int tb_has_ext_(const char *list, const char *ext) {
    size_t n = strlen(ext);
    const char *p = list;
    if (!list) return 0;
    while ((p = strstr(p, ext)) != NULL) {
        if ((p == list || p[-1] == ' ') && (p[n] == 0 || p[n] == ' ')) return 1;
        p += n;
    }
    return 0;
}

/* function pointer from eglGetProcAddress, typed by the caller via memcpy */
static void tb_egl_proc_(const char *name, void *out, size_t size) {
    __eglMustCastToProperFunctionPointerType f = eglGetProcAddress(name);
    memset(out, 0, size);
    if (f) memcpy(out, &f, size < sizeof f ? size : sizeof f);
}

static EGLDisplay tb_platform_display_(EGLenum platform, void *native) {
    PFNEGLGETPLATFORMDISPLAYEXTPROC get_ext;
    tb_egl_proc_("eglGetPlatformDisplayEXT", &get_ext, sizeof get_ext);
    if (get_ext) return get_ext(platform, native, NULL);
    return EGL_NO_DISPLAY;
}

/* context on an initialised display; 0 ok */
static int tb_egl_context_on_(tb_gl_backend_handle *h, EGLDisplay dpy, int flags, char *err, size_t errlen) {
    const int debug = (flags & TB_GL_CONTEXT_DEBUG) != 0, es = (flags & TB_GL_CONTEXT_ES3) != 0;
    const EGLint es_attribs[] = {
        EGL_CONTEXT_MAJOR_VERSION, 3,
        EGL_CONTEXT_MINOR_VERSION, 0,
        EGL_NONE
    };
    const EGLint ctx_attribs[] = {
        EGL_CONTEXT_MAJOR_VERSION, 3,
        EGL_CONTEXT_MINOR_VERSION, 3,
        EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
        debug ? EGL_CONTEXT_OPENGL_DEBUG : EGL_NONE, EGL_TRUE,
        EGL_NONE
    };
    const EGLint cfg_attribs[] = {
        EGL_SURFACE_TYPE, EGL_PBUFFER_BIT,
        EGL_RENDERABLE_TYPE, es ? EGL_OPENGL_ES3_BIT : EGL_OPENGL_BIT,
        EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8,
        EGL_DEPTH_SIZE, 24,
        EGL_NONE
    };
    static const EGLint pb_attribs[] = { EGL_WIDTH, 16, EGL_HEIGHT, 16, EGL_NONE };
    const char *exts = eglQueryString(dpy, EGL_EXTENSIONS);
    int surfaceless = tb_has_ext_(exts, "EGL_KHR_surfaceless_context");
    EGLConfig cfg = (EGLConfig)0;
    EGLint ncfg = 0;
    EGLContext ctx;
    EGLSurface surf = EGL_NO_SURFACE;

    if (!eglBindAPI(es ? EGL_OPENGL_ES_API : EGL_OPENGL_API)) {
        snprintf(err, errlen, "eglBindAPI failed (0x%x)", (unsigned)eglGetError());
        return -1;
    }
    if (!surfaceless || !tb_has_ext_(exts, "EGL_KHR_no_config_context")) {
        if (!eglChooseConfig(dpy, cfg_attribs, &cfg, 1, &ncfg) || ncfg < 1) {
            snprintf(err, errlen, "eglChooseConfig: no pbuffer/OpenGL config");
            return -1;
        }
    }
    ctx = eglCreateContext(dpy, cfg, EGL_NO_CONTEXT, es ? es_attribs : ctx_attribs);
    if (ctx == EGL_NO_CONTEXT) {
        snprintf(err, errlen, "eglCreateContext (%s) failed (0x%x)", es ? "ES 3.0" : "3.3 core",
                 (unsigned)eglGetError());
        return -1;
    }
    if (!surfaceless) {
        surf = eglCreatePbufferSurface(dpy, cfg, pb_attribs);
        if (surf == EGL_NO_SURFACE) {
            eglDestroyContext(dpy, ctx);
            snprintf(err, errlen, "no surfaceless context and eglCreatePbufferSurface failed");
            return -1;
        }
    }
    if (!eglMakeCurrent(dpy, surf, surf, ctx)) {
        snprintf(err, errlen, "eglMakeCurrent failed (0x%x)", (unsigned)eglGetError());
        if (surf != EGL_NO_SURFACE) eglDestroySurface(dpy, surf);
        eglDestroyContext(dpy, ctx);
        return -1;
    }
    h->a = ctx;
    h->b = dpy;
    h->c = surf;
    h->es = es;
    return 0;
}

int tb_gl_egl_create(tb_gl_backend_handle *h, int hardware_only, int flags, char *err, size_t errlen) {
    char msg[256] = "no EGL display";
    const char *client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    PFNEGLQUERYDEVICESEXTPROC query_devices;
    PFNEGLQUERYDEVICESTRINGEXTPROC query_string;
    EGLDeviceEXT devs[TB_EGL_MAX_DEVICES];
    EGLint ndev = 0, i;
    int pass;

    memset(h, 0, sizeof *h);
    tb_egl_proc_("eglQueryDevicesEXT", &query_devices, sizeof query_devices);
    tb_egl_proc_("eglQueryDeviceStringEXT", &query_string, sizeof query_string);
    if (tb_has_ext_(client, "EGL_EXT_platform_device") && query_devices && query_string &&
        query_devices(TB_EGL_MAX_DEVICES, devs, &ndev) && ndev > 0) {
        /* pass 0: hardware devices; pass 1: software (Mesa swrast) devices */
        for (pass = 0; pass < (hardware_only ? 1 : 2); pass++)
            for (i = 0; i < ndev; i++) {
                const char *dext = query_string(devs[i], EGL_EXTENSIONS);
                int software = tb_has_ext_(dext, "EGL_MESA_device_software");
                EGLDisplay dpy;
                EGLint maj = 0, min = 0;
                if (software != pass) continue;
                dpy = tb_platform_display_(EGL_PLATFORM_DEVICE_EXT, devs[i]);
                if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, &maj, &min)) {
                    snprintf(msg, sizeof msg, "EGL device %d: eglInitialize failed", (int)i);
                    continue;
                }
                if (tb_egl_context_on_(h, dpy, flags, msg, sizeof msg) == 0) {
                    h->name = "egl-device";
                    return 0;
                }
                eglTerminate(dpy);
            }
    } else if (hardware_only) {
        snprintf(msg, sizeof msg, "EGL device enumeration unavailable");
    }
    if (!hardware_only && tb_has_ext_(client, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay dpy = tb_platform_display_(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY);
        EGLint maj = 0, min = 0;
        if (dpy != EGL_NO_DISPLAY && eglInitialize(dpy, &maj, &min)) {
            if (tb_egl_context_on_(h, dpy, flags, msg, sizeof msg) == 0) {
                h->name = "egl-surfaceless";
                return 0;
            }
            eglTerminate(dpy);
        } else {
            snprintf(msg, sizeof msg, "surfaceless platform: eglInitialize failed");
        }
    }
    if (hardware_only && ndev > 0 && strcmp(msg, "no EGL display") == 0)
        snprintf(msg, sizeof msg, "no hardware EGL device (%d software)", (int)ndev);
    if (err) snprintf(err, errlen, "%s", msg);
    return -1;
}

int tb_gl_egl_make_current(tb_gl_backend_handle *h) {
    EGLSurface s = (EGLSurface)h->c;
    if (!eglBindAPI(h->es ? EGL_OPENGL_ES_API : EGL_OPENGL_API)) return -1;
    return eglMakeCurrent((EGLDisplay)h->b, s, s, (EGLContext)h->a) ? 0 : -1;
}

/* The display is left initialised (no eglTerminate): terminating it makes
   Mesa unload its driver (dlclose), and what the driver still holds from
   its own globals (112 bytes after the first draw, on Mesa 22 llvmpipe)
   then looks leaked to LeakSanitizer, which can no longer see those
   globals. The next tb_gl_egl_create initialises the same display again (a
   no-op on an initialised one); the process exit releases it. */
void tb_gl_egl_destroy(tb_gl_backend_handle *h) {
    EGLDisplay dpy = (EGLDisplay)h->b;
    if (dpy) {
        eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (h->c) eglDestroySurface(dpy, (EGLSurface)h->c);
        if (h->a) eglDestroyContext(dpy, (EGLContext)h->a);
    }
    memset(h, 0, sizeof *h);
}

void *tb_gl_egl_getproc(const char *name) {
    void *p;
    tb_egl_proc_(name, &p, sizeof p);
    return p;
}
