/* test_gl_debug.c - GL_KHR_debug output across every technique: no message
   of severity MEDIUM or HIGH.

   Two runs: OSMesa (what CI runs; OSMesa cannot make a debug context, so
   this is a plain context with GL_DEBUG_OUTPUT enabled, which on Mesa
   reports every API error and the messages Mesa raises on any context),
   then an EGL debug context (EGL_CONTEXT_OPENGL_DEBUG: on Mesa's
   surfaceless llvmpipe, or a GPU), where the driver may also report
   performance and undefined-behaviour warnings; a machine without EGL
   skips that run and says so. In each: glDebugMessageCallback with
   GL_DEBUG_OUTPUT_SYNCHRONOUS (the callback runs inside the offending
   call), every source, type and severity enabled; then each case of
   gl_exercise.h (every directional technique with skgl_shadow_analyze
   where it has one, point lights cube and VSDCT naive and optimized, the
   shared atlas, area lights PCSS and PVSM, a bare context) on a shadowkit context of its own with
   desc.debug = 1 (glGetError after every pass, a GL error returned as
   SK_ERR_GL) and desc.timing = 1. Messages are counted per case and
   severity; every one is printed once with its case. The testbed's own
   calls (G-buffer, forward pass) count too.

   The channel is checked first: glEnable(0xFFFF) must arrive as exactly
   one HIGH message of type ERROR, or the run proves nothing.

   Measured (Mesa 22.3 llvmpipe): no message of any severity in any case,
   on OSMesa and on the EGL debug context alike (llvmpipe raises no
   performance warnings for these passes). Found and fixed: the area
   lights (skgl_soft) checked the status of their framebuffer after
   detaching everything from it, which Mesa reports as "MEDIUM, API, type
   OTHER: FBO incomplete: no attachments and default width or height is 0"
   (4 messages in the PCSS case, 16 in the PVSM case, on both contexts);
   skgl__soft_detach no longer checks. Can also fail: in local copies of the
   header, skgl__uniforms setting the int sk_pcf_radius with glUniform1f
   gave "HIGH, API: GL_INVALID_OPERATION in glUniform1(sk_pcf_radius is
   int, not float)" in every directional case (and SK_ERR_GL from the mask
   and bind through desc.debug); skgl_point_render calling
   glDrawBuffer(GL_BACK) on its framebuffer gave "HIGH, API:
   GL_INVALID_OPERATION in glDrawBuffer(invalid buffer GL_BACK)" three times
   in every point-light case. */
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "sk_test.h"
#include "gl_test_util.h"
#include "gl_exercise.h"

#define E_DEBUG_OUTPUT 0x92E0
#define E_DEBUG_OUTPUT_SYNCHRONOUS 0x8242
#define E_DONT_CARE 0x1100
#define E_DEBUG_SEVERITY_HIGH 0x9146
#define E_DEBUG_SEVERITY_MEDIUM 0x9147
#define E_DEBUG_SEVERITY_LOW 0x9148
#define E_DEBUG_SEVERITY_NOTIFICATION 0x826B
#define E_DEBUG_TYPE_ERROR 0x824C

typedef void (*debug_proc)(unsigned source, unsigned type, unsigned id, unsigned severity, int length,
                           const char *message, const void *user);
typedef struct debug_funcs {
    void (*DebugMessageCallback)(debug_proc cb, const void *user);
    void (*DebugMessageControl)(unsigned source, unsigned type, unsigned severity, int count, const unsigned *ids,
                                unsigned char enabled);
} debug_funcs;

enum { S_HIGH, S_MEDIUM, S_LOW, S_NOTE, S_N };
static const char *const sev_names[S_N] = {"HIGH", "MEDIUM", "LOW", "NOTIFICATION"};
static int counts[S_N], type_error;
static const char *current_case = "";
#define MAX_SEEN 32
static char seen[MAX_SEEN][256];
static int nseen;

static const char *source_name(unsigned s) {
    switch (s) {
    case 0x8246: return "API";
    case 0x8247: return "window system";
    case 0x8248: return "shader compiler";
    case 0x8249: return "third party";
    case 0x824A: return "application";
    default: return "other";
    }
}

static void on_message(unsigned source, unsigned type, unsigned id, unsigned severity, int length,
                       const char *message, const void *user) {
    int k = severity == E_DEBUG_SEVERITY_HIGH ? S_HIGH : severity == E_DEBUG_SEVERITY_MEDIUM ? S_MEDIUM
          : severity == E_DEBUG_SEVERITY_LOW ? S_LOW : S_NOTE;
    char line[256];
    int i;
    (void)user;
    counts[k]++;
    if (type == E_DEBUG_TYPE_ERROR) type_error++;
    snprintf(line, sizeof line, "%s: %s, %s, type 0x%x id %u: %.*s", current_case, sev_names[k], source_name(source),
             type, id, length < 0 ? 160 : (length < 160 ? length : 160), message);
    for (i = 0; i < nseen; i++) if (!strcmp(seen[i], line)) return;
    if (nseen < MAX_SEEN) {
        snprintf(seen[nseen++], sizeof seen[0], "%s", line);
        printf("  message: %s\n", line);
    }
}

static void reset_counts(void) { memset(counts, 0, sizeof counts); type_error = 0; }

static int load(void *dst, tb_gl_getproc_fn gp, const char *name) {
    void *p = gp(name);
    memcpy(dst, &p, sizeof p);
    return p != NULL;
}

static void run_backend(tb_gl_backend backend, int flags, const char *label) {
    gx_env x;
    debug_funcs d;
    tb_gl_getproc_fn gp;
    int c, total[S_N] = {0, 0, 0, 0}, k;
    if (gx_env_init_on(&x, backend, flags) != 0) { gx_env_free(&x); return; }
    gp = tb_gl_context_getproc(x.e.ctx);
    printf("%s: %s, %s context\n", label, tb_gl_context_renderer(x.e.ctx),
           tb_gl_context_debug(x.e.ctx) ? "debug" : "non-debug");
    if (flags & TB_GL_CONTEXT_DEBUG)
        SK_CHECK_MSG(tb_gl_context_debug(x.e.ctx), "%s: asked for a debug context, got none", label);
    SK_CHECK(load(&d.DebugMessageCallback, gp, "glDebugMessageCallback"));
    SK_CHECK(load(&d.DebugMessageControl, gp, "glDebugMessageControl"));
    if (!d.DebugMessageCallback || !d.DebugMessageControl) { gx_env_free(&x); return; }
    d.DebugMessageCallback(on_message, NULL);
    x.e.gl.Enable(E_DEBUG_OUTPUT);
    x.e.gl.Enable(E_DEBUG_OUTPUT_SYNCHRONOUS);
    d.DebugMessageControl(E_DONT_CARE, E_DONT_CARE, E_DONT_CARE, 0, NULL, 1);

    /* the channel: one known error */
    reset_counts();
    current_case = "channel check (glEnable(0xFFFF), expected)";
    x.e.gl.Enable(0xFFFF);
    SK_CHECK_MSG(counts[S_HIGH] == 1 && type_error == 1, "%s: the provoked error gave %d HIGH, %d ERROR messages",
                 label, counts[S_HIGH], type_error);
    SK_CHECK(x.e.gl.GetError() == 0x0500 /* GL_INVALID_ENUM */);

    for (c = 0; c < GX_NCASES; c++) {
        skgl_desc desc;
        skgl_context *sk = NULL;
        sk_result r;
        int calls;
        reset_counts();
        current_case = gx_cases[c].name;
        memset(&desc, 0, sizeof desc);
        desc.getproc = (skgl_getproc_fn)gp;
        desc.debug = 1;
        desc.timing = 1;
        r = skgl_create(&desc, &sk);
        SK_CHECK_MSG(r == SK_OK, "%s %s: skgl_create: %s", label, gx_cases[c].name, sk_result_string(r));
        if (r != SK_OK) continue;
        calls = gx_run(&x, sk, &gx_cases[c]);
        skgl_destroy(sk);
        SK_CHECK_MSG(calls >= 0, "%s %s did not run", label, gx_cases[c].name);
        printf("  %-18s %3d calls: HIGH %d, MEDIUM %d, LOW %d, NOTIFICATION %d\n", gx_cases[c].name, calls,
               counts[S_HIGH], counts[S_MEDIUM], counts[S_LOW], counts[S_NOTE]);
        SK_CHECK_MSG(counts[S_HIGH] == 0 && counts[S_MEDIUM] == 0, "%s %s: %d HIGH, %d MEDIUM messages", label,
                     gx_cases[c].name, counts[S_HIGH], counts[S_MEDIUM]);
        SK_CHECK_MSG(x.e.gl.GetError() == 0, "%s %s: GL error left", label, gx_cases[c].name);
        for (k = 0; k < S_N; k++) total[k] += counts[k];
    }
    printf("%s: %d cases: HIGH %d, MEDIUM %d, LOW %d, NOTIFICATION %d\n", label, GX_NCASES, total[S_HIGH],
           total[S_MEDIUM], total[S_LOW], total[S_NOTE]);
    x.e.gl.Disable(E_DEBUG_OUTPUT);
    d.DebugMessageCallback(NULL, NULL);
    current_case = "";
    gx_env_free(&x);
}

static void test_osmesa(void) { run_backend(TB_GL_OSMESA, 0, "osmesa"); }

static void test_egl_debug_context(void) {
    char err[512] = "";
    tb_gl_context *probe = tb_gl_context_create_flags(TB_GL_EGL, TB_GL_CONTEXT_DEBUG, err, sizeof err);
    if (!probe) {
        printf("egl: no EGL debug context here (%s): that run is skipped\n", err);
        return;
    }
    tb_gl_context_destroy(probe);
    run_backend(TB_GL_EGL, TB_GL_CONTEXT_DEBUG, "egl");
}

SK_TEST_MAIN(test_osmesa, test_egl_debug_context)
