/* es_web_test.c - the browser test (emcc; tests/es/web_test.sh drives it in
   headless Chromium): every technique on WebGL2, each mask compared with the
   desktop OpenGL 3.3 mask of the same scene, camera and light and the hard
   ones with the exact reference, both read from the embedded es_data.bin
   (tests/es/es_dump.c). Then one interaction: a drag event moves the light,
   and the shadow must follow.

   It reports in the page: one line per technique in <pre id="log">, and the
   title "ESWEB PASS <n>" or "ESWEB FAIL <n> ..." for the driver to read
   with --dump-dom. Thresholds (measured on Chromium 156 SwiftShader against
   Mesa 22.3 llvmpipe, see ESX_LIMIT_*) are per technique kind. */
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "es/es_core.h"

#include <emscripten.h>
#include <emscripten/html5.h>

/* the WebGL2 library's own entry point (no GLES header declares it) */
extern void glGetBufferSubData(unsigned target, long offset, long size, void *data);

/* Emscripten 3.1's emscripten_webgl_get_proc_address leaves out
   glGetBufferSubData, which its WebGL2 library has: the loader adds it */
static void *web_getproc(const char *name)
{
    if (strcmp(name, "glGetBufferSubData") == 0) return (void *)glGetBufferSubData;
    return emscripten_webgl_get_proc_address(name);
}

/* Mask against the desktop's: hard, % of the pixels whose class differs
   (measured 0.019% to 0.030%: SwiftShader and llvmpipe round the depth
   passes' edges differently); soft, mean |difference| over the penumbra and
   umbra (PCSS 0.0023, PVSM 0.0032 with its ES 3.0 fallbacks). */
#define LIMIT_HARD_DESKTOP 0.1
#define LIMIT_SOFT_DESKTOP 0.01
/* Against the exact reference, at most the desktop mask's error plus this
   much (measured: hard +0.11 to +0.91 of the shadow's area, FERKO the most;
   RMSM 0.54 below; soft +0.0002 PCSS, +0.0020 PVSM) */
#define LIMIT_HARD_REF 1.5
#define LIMIT_SOFT_REF 0.005

static esx_run g_run;
static esx_data_header g_h;
static float *g_pos, *g_nrm, *g_vis, g_spot[ESX_W * ESX_H];
static unsigned *g_idx;
static unsigned char *g_desk;
static char g_out[8192];
static int g_fail, g_pass;

static void say(const char *fmt, ...)
{
    va_list ap;
    size_t n = strlen(g_out);
    va_start(ap, fmt);
    vsnprintf(g_out + n, sizeof g_out - n, fmt, ap);
    va_end(ap);
}

static int load(const char *path)
{
    FILE *f = fopen(path, "rb");
    size_t nv, ni, ok;
    if (!f) return -1;
    ok = fread(&g_h, sizeof g_h, 1, f) == 1 && g_h.magic == ESX_MAGIC && g_h.techs == ESX_TECHS && g_h.w == ESX_W &&
         g_h.h == ESX_H;
    nv = g_h.vertices;
    ni = g_h.indices;
    g_pos = (float *)malloc(12 * nv);
    g_nrm = (float *)malloc(12 * nv);
    g_idx = (unsigned *)malloc(4 * ni);
    g_desk = (unsigned char *)malloc((size_t)ESX_TECHS * ESX_W * ESX_H);
    g_vis = (float *)malloc(sizeof(float) * 3 * ESX_W * ESX_H);
    ok = ok && g_pos && g_nrm && g_idx && g_desk && g_vis && fread(g_pos, 12, nv, f) == nv &&
         fread(g_nrm, 12, nv, f) == nv && fread(g_idx, 4, ni, f) == ni &&
         fread(g_desk, (size_t)ESX_W * ESX_H, ESX_TECHS, f) == (size_t)ESX_TECHS &&
         fread(g_vis, sizeof(float) * ESX_W * ESX_H, 3, f) == 3;
    fclose(f);
    return ok ? 0 : -1;
}

static void check(int cond, const char *fmt, const char *a, double x, double lim)
{
    if (cond) { g_pass++; return; }
    g_fail++;
    say("FAIL ");
    say(fmt, a, x, lim);
    say("\n");
}

static void report(void)
{
    char title[200];
    EM_ASM({ document.getElementById('log').textContent = UTF8ToString($0); }, g_out);
    snprintf(title, sizeof title, "ESWEB %s %d passed %d failed", g_fail ? "FAIL" : "PASS", g_pass, g_fail);
    emscripten_set_window_title(title);
}

/* ---- the interaction: a drag on the canvas turns the sun about the
   vertical, 0.005 radians a pixel (the demo page's own binding) ---- */
static int g_dragging, g_last_x;
static EM_BOOL on_mouse(int type, const EmscriptenMouseEvent *e, void *user)
{
    (void)user;
    if (type == EMSCRIPTEN_EVENT_MOUSEDOWN) { g_dragging = 1; g_last_x = (int)e->targetX; }
    else if (type == EMSCRIPTEN_EVENT_MOUSEUP) g_dragging = 0;
    else if (type == EMSCRIPTEN_EVENT_MOUSEMOVE && g_dragging) {
        float a = 0.005f * (float)((int)e->targetX - g_last_x), c = cosf(a), s = sinf(a);
        sk_vec3 d = g_run.sun;
        g_run.sun.x = c * d.x + s * d.z;
        g_run.sun.z = -s * d.x + c * d.z;
        g_last_x = (int)e->targetX;
    }
    return EM_TRUE;
}

/* the window position of a world point under the test camera */
static void to_pixel(sk_vec3 p, int *x, int *y)
{
    skgl_camera cam = esx_camera();
    sk_vec3 q = sk_mat4_transform_point(sk_mat4_mul(cam.proj, cam.view), p);
    *x = (int)floorf((q.x * 0.5f + 0.5f) * ESX_W);
    *y = (int)floorf((q.y * 0.5f + 0.5f) * ESX_H);
}

/* shadowed pixels (< 128) of a mask in the 5 x 5 pixels around (x, y) */
static int dark_near(const unsigned char *m, int x, int y)
{
    int i, j, n = 0;
    for (j = y - 2; j <= y + 2; j++)
        for (i = x - 2; i <= x + 2; i++)
            if (i >= 0 && j >= 0 && i < ESX_W && j < ESX_H) n += m[j * ESX_W + i] < 128;
    return n;
}

/* where the top of the narrow tower (box4, [6,0,5]..[6.5,6,5.5]) casts
   its shadow on the ground under sun direction d */
static sk_vec3 tower_tip(sk_vec3 d)
{
    sk_vec3 top = esx_v3(6.25f, 6.0f, 5.25f);
    float t = top.y / -d.y;
    return esx_v3(top.x + t * d.x, 0.0f, top.z + t * d.z);
}

/* a drag from x0 to x1 across the canvas, as the browser would send it */
EM_JS(void, drag, (int x0, int x1), {
    var c = document.getElementById('canvas');
    var r = c.getBoundingClientRect();
    function send(type, x) {
        c.dispatchEvent(new MouseEvent(type, {clientX: r.left + x, clientY: r.top + 90, buttons: 1, bubbles: true}));
    }
    send('mousedown', x0);
    for (var i = 1; i <= 10; i++) send('mousemove', x0 + (x1 - x0) * i / 10);
    send('mouseup', x1);
});

static void test_drag(void)
{
    static unsigned char before[ESX_W * ESX_H];
    sk_vec3 sun0 = g_run.sun;
    int x0, y0, x1, y1, t;
    emscripten_set_mousedown_callback("#canvas", NULL, EM_TRUE, on_mouse);
    emscripten_set_mousemove_callback("#canvas", NULL, EM_TRUE, on_mouse);
    emscripten_set_mouseup_callback("#canvas", NULL, EM_TRUE, on_mouse);
    memcpy(before, g_run.mask[0], sizeof before);   /* STANDARD under the first sun */
    drag(60, 220);                                  /* 160 pixels: 0.8 radians */
    check(fabsf(g_run.sun.x - sun0.x) + fabsf(g_run.sun.z - sun0.z) > 0.3f, "%s: the sun moved %.3f, limit %.3f",
          "drag", (double)(fabsf(g_run.sun.x - sun0.x) + fabsf(g_run.sun.z - sun0.z)), 0.3);
    esx_only(&g_run, "STANDARD");
    while (!esx_step(&g_run)) {}
    t = 0;
    to_pixel(tower_tip(sun0), &x0, &y0);
    to_pixel(tower_tip(g_run.sun), &x1, &y1);
    say("drag: the tower's shadow tip went from pixel (%d, %d) to (%d, %d); %.2f%% of the pixels changed; dark "
        "pixels around the old tip %d then %d, around the new %d then %d\n",
        x0, y0, x1, y1, esx_mask_diff(before, g_run.mask[t], 0), dark_near(before, x0, y0),
        dark_near(g_run.mask[t], x0, y0), dark_near(before, x1, y1), dark_near(g_run.mask[t], x1, y1));
    /* measured: 12 of the 25 pixels around the old tip dark before, 0 after;
       around the new tip 0 before, 20 after (a tip sits on the shadow's edge) */
    check(dark_near(before, x0, y0) >= 6 && dark_near(g_run.mask[t], x0, y0) <= 2,
          "%s: %.0f dark pixels around the old tip after the drag, limit %.0f", "drag",
          (double)dark_near(g_run.mask[t], x0, y0), 2.0);
    check(dark_near(g_run.mask[t], x1, y1) >= 6 && dark_near(before, x1, y1) <= 2,
          "%s: %.0f dark pixels around the new tip after the drag, at least %.0f", "drag",
          (double)dark_near(g_run.mask[t], x1, y1), 6.0);
}

int main(void)
{
    EmscriptenWebGLContextAttributes attr;
    EMSCRIPTEN_WEBGL_CONTEXT_HANDLE gl;
    esx_scene sc;
    int t;
    if (load("/es_data.bin") != 0) { say("FAIL es_data.bin missing or stale\n"); g_fail++; report(); return 0; }
    emscripten_webgl_init_context_attributes(&attr);
    attr.majorVersion = 2;
    attr.depth = 0;
    attr.antialias = 0;
    gl = emscripten_webgl_create_context("#canvas", &attr);
    if (gl <= 0) { say("FAIL no WebGL2 context\n"); g_fail++; report(); return 0; }
    emscripten_webgl_make_context_current(gl);
    /* WebGL2 extensions are off until asked for */
    emscripten_webgl_enable_extension(gl, "EXT_color_buffer_float");
    emscripten_webgl_enable_extension(gl, "EXT_float_blend");
    emscripten_webgl_enable_extension(gl, "EXT_disjoint_timer_query_webgl2");
    sc.pos = g_pos;
    sc.nrm = g_nrm;
    sc.idx = g_idx;
    sc.vertices = (int)g_h.vertices;
    sc.indices = (int)g_h.indices;
    memcpy(&sc.bounds, g_h.bounds, sizeof sc.bounds);
    esx_spot_reference(&sc, g_vis + ESX_W * ESX_H, g_spot);   /* the point light's cut by the cone */
    if (esx_begin(&g_run, web_getproc, &sc, 0) != 0) {
        say("FAIL %s\n", g_run.log);
        g_fail++;
        report();
        return 0;
    }
    {
        skgl_caps c = skgl_get_caps(g_run.sk);
        say("caps: ES %d.%d webgl %d geometry_shader %d float_render %d float_blend %d norm16 %d depth_clamp %d "
            "timer %d texture_size %d buffer_read %d mip_render_level %d\n",
            c.major, c.minor, c.webgl, c.geometry_shader, c.float_render, c.float_blend, c.norm16, c.depth_clamp,
            c.timer_query, c.texture_size, c.buffer_read, c.mip_render_level);
    }
    while (!esx_step(&g_run)) {}
    for (t = 0; t < ESX_TECHS; t++) {
        const esx_tech *e = &esx_techs[t];
        int soft = e->kind == ESX_SOFT;
        const float *vis = e->kind == ESX_SPOT ? g_spot
                           : g_vis + (size_t)(e->kind == ESX_DIR ? 0 : e->kind == ESX_POINT ? 1 : 2) * ESX_W * ESX_H;
        const unsigned char *desk = g_desk + (size_t)t * ESX_W * ESX_H;
        double d, re, rd;
        if (g_run.result[t] != SK_OK) {
            say("FAIL %s: %s\n", e->name, g_run.why[t]);
            g_fail++;
            continue;
        }
        d = esx_mask_diff(desk, g_run.mask[t], soft);
        re = esx_ref_error(vis, g_run.mask[t], soft);
        rd = esx_ref_error(vis, desk, soft);
        say("%-8s vs desktop %.4f%s  vs reference %.4f (desktop %.4f)\n", e->name, d, soft ? "" : "%", re, rd);
        check(d <= (soft ? LIMIT_SOFT_DESKTOP : LIMIT_HARD_DESKTOP), "%s: %.4f from desktop, limit %.4f", e->name,
              d, soft ? LIMIT_SOFT_DESKTOP : LIMIT_HARD_DESKTOP);
        check(re <= rd + (soft ? LIMIT_SOFT_REF : LIMIT_HARD_REF), "%s: %.4f from the reference, limit %.4f",
              e->name, re, rd + (soft ? LIMIT_SOFT_REF : LIMIT_HARD_REF));
    }
    test_drag();
#ifdef ESWEB_DUMP   /* debugging: one technique's mask in hex after the lines */
    {
        static char hex[ESX_W * ESX_H * 2 + 16];
        int i;
        for (i = 0; i < ESX_W * ESX_H; i++) sprintf(hex + 2 * i, "%02x", g_run.mask[ESWEB_DUMP][i]);
        EM_ASM({ var p = document.createElement('pre'); p.id = 'dump'; p.textContent = UTF8ToString($0);
                 document.body.appendChild(p); }, hex);
    }
#endif
    t = esx_end(&g_run);
    check(t == 0, "%s: %.0f GL objects left, limit %.0f", "objects", (double)t, 0.0);
    report();
    return 0;
}
