/* test_gl_rings.c - what shadowkit_gl.h keeps between frames for directional
   and point lights: the read-back rings (FERKO's estimate, RMSM's page
   requests), the timer-query ring, the cache of the user's program
   locations, and the two state modes (restored, caller-owns).

   shadowkit gets its entry points through a getproc of this test that
   counts some of them and can lie about two: glClientWaitSync answers
   GL_TIMEOUT_EXPIRED while `not_ready` is set (a fence the GPU has not
   reached: the ring's error path, which a GPU that keeps up, or llvmpipe,
   never takes on its own), and glGetQueryObjectuiv answers 0 for
   GL_QUERY_RESULT_AVAILABLE while `not_available` is set. 320 x 180,
   scene "ground-boxes", light (-0.5, -1, -0.35).

   test_ferko_ring: a reference shadow with sync_readback
   gives the estimates of views A (-9, 7, 12) and B (-3, 2.5, 4), which
   differ (measured 1907x1745 and 2048x2048, the latter clamped to the
   maximum). A default shadow (latency 1): frame 1 (view A) reads at once,
   one glReadPixels into client memory, and has A's estimate; with every
   fence "not ready", frames 2 and 3 (view A) and 4 and 5 (view B) keep A's
   estimate (the render draws A's map size), read nothing back and stall
   nowhere, and issue a read-back into the ring in frames 2, 3 and 4 but
   not in 5 (all three buffers in flight); the fences "ready" again, frame
   6 reads one buffer, the newest (frame 4's: view B), and has B's
   estimate. A shadow never analysed renders the focused map at full
   resolution, with no estimate.
   test_rmsm_ring: the same with RMSM page lists (the reference: sync_readback; view A 45 pages, B 59): A's pages kept while the
   fences are not ready, no page-table upload in those frames (the table
   did not change), B's pages and one upload of the changed rows once they
   land, none in the next frame of the same view.
   test_timer_ring: desc.timing = 1, a standard map, glFinish after each
   frame: stats.shadow_ms and mask_ms are -1 after frames 1 and 2 and a
   time from frame 3 (frame 1's passes, read two frames late); with the
   results "not available" the values are kept and no GL_QUERY_RESULT is
   read, and in frame 5, whose slots are still busy, no query is begun;
   available again, frame 6 reads the two pending results of each ring.
   test_program_cache: skgl_shadow_bind looks up 27 locations on a
   program's first bind (the snippet's 20 uniforms, 19 before
   sk_filter_world; EVSM's 3, SK_SHADOW_EVSM; the forward contact march's
   4, SK_SHADOW_CONTACT), none on the next; two lights with different .pcf_radius bound
   in turn to one program leave their own radius each (read back with
   glGetUniformiv); the program linked again (its uniforms back at 0) is
   found by the default mode's check (27 look-ups, the units set again), as
   is a program deleted and made anew (Mesa gave the new one another name
   here, 72 for 69; a reused name takes the same check); in caller-owns
   mode the cache is trusted (the relinked program's sampler stays 0) until
   skgl_forget_program; 17 programs in a 16-entry cache: the least recently
   bound is looked up again, the most recent is not.
   test_state_modes: for STANDARD, PSSM (3), FERKO and RMSM (each
   sync_readback), POINT_CUBE and POINT_VSDCT, the mask from a host left
   in wireframe (glPolygonMode GL_LINE) equals the one from a filled host,
   value for value, in both modes; the default mode gives GL_LINE back, the
   caller-owns mode leaves GL_FILL, framebuffer 0 (draw and read) and no
   pixel pack buffer, as the manual lists. The caller's program deleted
   while current (it lives only as long as it stays current; Dear ImGui's
   issue #6220): analyze, render and mask leave no GL error and program 0
   current. The draw callback's contract: with desc.debug, a callback that
   leaves its own program current gets SK_ERR_INVALID_ARG and the log names
   info->program; one that binds info->program again gets SK_OK and the
   same mask as the plain callback.
   test_callback_units: the caller's textures on units 0 and 3 and unit 5
   active; an RMSM render without analysis (its page table uploaded on
   unit 0 first) whose callback leaves unit 3 active: afterwards unit 0
   holds the caller's texture again, unit 3 its own, unit 5 is active.
   test_texture_cache: a mask texture of the test's, first half the
   G-buffer's size, then given the full size under the same name: with
   desc.debug (which asks for the size every time) the mask after the new
   storage is refused (SK_ERR_INVALID_ARG, the log names
   skgl_forget_texture); after skgl_forget_texture it is drawn, equal value
   for value to the mask drawn into the testbed's own target.

   Measured (Mesa llvmpipe, OSMesa): every check above as stated, 261 in
   about 1 s.
   Can fail (each shown once, in a local copy of shadowkit_gl.h):
   - the ring poll taking the oldest buffer landed instead of the newest:
     "frame 6: 1907x1745, view B's 2048x2048" (FERKO) and "frame 6: 45
     pages (B: 59)" (RMSM), 3 checks;
   - the ring reusing a buffer still in flight (its fence dropped): "frame
     5: ... 1 read-backs into the ring" (FERKO and RMSM);
   - the timer reading GL_QUERY_RESULT without waiting for
     GL_QUERY_RESULT_AVAILABLE: "frame 4: 1.65477 / 8.62532 ms (frame 3:
     6.13493 / 13.0085), 2 results, 2 begun", 3 checks;
   - no check of a cached program: "relinked: 0 look-ups, unit 0, radius 0";
   - the depth passes without glPolygonMode(GL_FILL): "standard, restored,
     wireframe host: 855 mask values differ from the filled host's", 10
     checks (every technique in both modes but FERKO's and RMSM's in
     caller-owns mode, whose analysis pass had set GL_FILL before the
     render);
   - the program restored without glIsProgram: "deleted current program:
     program 39 current after" and a GL_INVALID_VALUE caught by desc.debug
     in the point-light frames, where a caller-owns light's mask program,
     left current, was deleted with its light (5 checks);
   - the active unit still taken as known after a callback: "after a
     callback switching units: active 0x84c5, unit 0 holds 7 (was 8), unit
     3 8 (was 9)" (the table's unit put back on unit 3);
   - desc.debug not asking for a remembered texture's size: "new storage,
     not forgotten, debug: ok ()". */
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "sk_test.h"
#include "gl_test_util.h"

#define W 320
#define H 180

#include "gl_wrap.h"

/* the entry points the test itself needs beyond the testbed's table */
typedef struct ext_funcs {
    void (*PolygonMode)(unsigned, unsigned);
    void (*GetUniformiv)(unsigned, int, int *);
    void (*GetBooleanv)(unsigned, unsigned char *);
} ext_funcs;
static void ext_load(ext_funcs *x, tb_gl_getproc_fn gp) {
    void *p;
    p = gp("glPolygonMode"); PTR_TO_FN(p, x->PolygonMode);
    p = gp("glGetUniformiv"); PTR_TO_FN(p, x->GetUniformiv);
    p = gp("glGetBooleanv"); PTR_TO_FN(p, x->GetBooleanv);
    SK_CHECK(x->PolygonMode && x->GetUniformiv && x->GetBooleanv);
}

static sk_vec3 light_dir(void) { return gt_v3(-0.5f, -1, -0.35f); }
static skgl_camera view_a(void) { return gt_camera(gt_v3(-9, 7, 12), gt_v3(0, 1, 0), 1.0f, 0.1f, 250, W, H); }
static skgl_camera view_b(void) { return gt_camera(gt_v3(-3, 2.5f, 4), gt_v3(0, 0.5f, 0), 1.0f, 0.1f, 250, W, H); }

static int env_init(gt_env *e) {
    if (gt_env_init_named(e, "ground-boxes", W, H) != 0) { gt_env_free(e); return -1; }
    ring_install(tb_gl_context_getproc(e->ctx));
    return 0;
}

static int same_estimate(const sk_res_estimate *a, const sk_res_estimate *b) {
    return a->width == b->width && a->height == b->height && a->samples == b->samples &&
           a->bounds.x0 == b->bounds.x0 && a->bounds.x1 == b->bounds.x1 && a->bounds.y0 == b->bounds.y0 &&
           a->bounds.y1 == b->bounds.y1;
}

/* ---- FERKO: the estimate a frame late ---- */
static void test_ferko_ring(void) {
    gt_env e;
    skgl_context *sk;
    skgl_shadow_desc d;
    skgl_shadow *ref, *s, *bare;
    skgl_scene sc;
    skgl_camera ca = view_a(), cb = view_b();
    sk_res_estimate est_a, est_b;
    int f, map_a = 0;
    if (env_init(&e) != 0) return;
    sc = gt_scene(&e);
    sk = ring_context(0, 0, 0);
    memset(&d, 0, sizeof d);
    d.technique = SKGL_FERKO;
    d.resolution = 2048;
    d.sync_readback = 1;
    ref = gt_shadow(&e, &d);
    d.sync_readback = 0;   /* the default: a frame late */
    s = NULL;
    SK_CHECK(sk && skgl_shadow_create(sk, &d, &s) == SK_OK);
    SK_CHECK(skgl_shadow_get_desc(s).sync_readback == 0 && skgl_shadow_get_desc(ref).sync_readback == 1);
    if (!sk || !ref || !s) { skgl_shadow_destroy(e.sk, ref); skgl_destroy(sk); gt_env_free(&e); return; }
    /* the reference's estimates of both views (the stats have the
       estimate a render used) */
    SK_CHECK(gt_gbuffer(&e, &cb) == 0);
    SK_CHECK(skgl_shadow_analyze(e.sk, ref, &cb, &sc, light_dir(), e.gbuf.depth_tex) == SK_OK);
    SK_CHECK(skgl_shadow_render(e.sk, ref, &cb, &sc, light_dir()) == SK_OK);
    est_b = skgl_shadow_stats(ref)->estimate;
    SK_CHECK(gt_gbuffer(&e, &ca) == 0);
    SK_CHECK(skgl_shadow_analyze(e.sk, ref, &ca, &sc, light_dir(), e.gbuf.depth_tex) == SK_OK);
    SK_CHECK(skgl_shadow_render(e.sk, ref, &ca, &sc, light_dir()) == SK_OK);
    est_a = skgl_shadow_stats(ref)->estimate;
    printf("ferko: view A %dx%d, view B %dx%d\n", est_a.width, est_a.height, est_b.width, est_b.height);
    SK_CHECK(est_a.samples == 1 && est_b.samples == 1 && !same_estimate(&est_a, &est_b));
    /* frame 1: nothing to be late from, read at once */
    counts_reset();
    SK_CHECK(skgl_shadow_analyze(sk, s, &ca, &sc, light_dir(), e.gbuf.depth_tex) == SK_OK);
    SK_CHECK(skgl_shadow_render(sk, s, &ca, &sc, light_dir()) == SK_OK);
    map_a = skgl_shadow_stats(s)->map_width;
    SK_CHECK_MSG(R.client_reads == 1 && R.pbo_reads == 0 && R.buffer_reads == 0,
                 "frame 1: %ld reads into client memory, %ld into buffers, %ld buffer reads", R.client_reads,
                 R.pbo_reads, R.buffer_reads);
    SK_CHECK(same_estimate(&skgl_shadow_stats(s)->estimate, &est_a));
    e.gl.Finish();
    /* frames 2 and 3 on view A, 4 and 5 on view B, every fence "not ready" */
    R.not_ready = 1;
    for (f = 2; f <= 5; f++) {
        const skgl_camera *c = f < 4 ? &ca : &cb;
        if (f == 4) SK_CHECK(gt_gbuffer(&e, &cb) == 0);
        counts_reset();
        SK_CHECK(skgl_shadow_analyze(sk, s, c, &sc, light_dir(), e.gbuf.depth_tex) == SK_OK);
        SK_CHECK(skgl_shadow_render(sk, s, c, &sc, light_dir()) == SK_OK);
        SK_CHECK_MSG(same_estimate(&skgl_shadow_stats(s)->estimate, &est_a), "frame %d: not view A's estimate", f);
        SK_CHECK_MSG(skgl_shadow_stats(s)->map_width == map_a, "frame %d: map %d wide, A's is %d", f,
                     skgl_shadow_stats(s)->map_width, map_a);
        SK_CHECK_MSG(R.client_reads == 0 && R.buffer_reads == 0 && R.pbo_reads == (f < 5),
                     "frame %d: %ld client reads, %ld buffer reads, %ld read-backs into the ring", f, R.client_reads,
                     R.buffer_reads, R.pbo_reads);
        e.gl.Finish();
    }
    /* frame 6: the fences land; the newest buffer (frame 4, view B) is read */
    R.not_ready = 0;
    counts_reset();
    SK_CHECK(skgl_shadow_analyze(sk, s, &cb, &sc, light_dir(), e.gbuf.depth_tex) == SK_OK);
    SK_CHECK(skgl_shadow_render(sk, s, &cb, &sc, light_dir()) == SK_OK);
    SK_CHECK_MSG(same_estimate(&skgl_shadow_stats(s)->estimate, &est_b), "frame 6: %dx%d, view B's %dx%d",
                 skgl_shadow_stats(s)->estimate.width, skgl_shadow_stats(s)->estimate.height, est_b.width,
                 est_b.height);
    SK_CHECK_MSG(R.client_reads == 0 && R.buffer_reads == 1 && R.pbo_reads == 1,
                 "frame 6: %ld client reads, %ld buffer reads, %ld read-backs into the ring", R.client_reads,
                 R.buffer_reads, R.pbo_reads);
    /* never analysed: the focused map at full resolution */
    bare = NULL;
    SK_CHECK(skgl_shadow_create(sk, &d, &bare) == SK_OK && bare);
    if (bare) {
        SK_CHECK(skgl_shadow_render(sk, bare, &cb, &sc, light_dir()) == SK_OK);
        SK_CHECK(skgl_shadow_stats(bare)->map_width == 2048 && skgl_shadow_stats(bare)->estimate.samples == 0);
    }
    SK_CHECK(e.gl.GetError() == 0);
    skgl_shadow_destroy(sk, bare);
    skgl_shadow_destroy(sk, s);
    skgl_shadow_destroy(e.sk, ref);
    skgl_destroy(sk);
    gt_env_free(&e);
}

/* ---- RMSM: the page requests a frame late ---- */
#define MAX_PAGES 4096
static int same_pages(const sk_page *a, int na, const sk_page *b, int nb) {
    int i;
    if (na != nb) return 0;
    for (i = 0; i < na; i++)
        if (a[i].level != b[i].level || a[i].px != b[i].px || a[i].py != b[i].py) return 0;
    return 1;
}

static void test_rmsm_ring(void) {
    static sk_page pa[MAX_PAGES], pb[MAX_PAGES], got[MAX_PAGES];
    gt_env e;
    skgl_context *sk;
    skgl_shadow_desc d;
    skgl_shadow *ref, *s = NULL;
    skgl_scene sc;
    skgl_camera ca = view_a(), cb = view_b();
    int na, nb, n, f;
    if (env_init(&e) != 0) return;
    sc = gt_scene(&e);
    sk = ring_context(0, 0, 0);
    memset(&d, 0, sizeof d);
    d.technique = SKGL_RMSM;
    d.resolution = 16384;
    d.rmsm_pool_pages = 32;
    d.sync_readback = 1;
    ref = gt_shadow(&e, &d);
    d.sync_readback = 0;
    SK_CHECK(sk && skgl_shadow_create(sk, &d, &s) == SK_OK);
    if (!sk || !ref || !s) { skgl_shadow_destroy(e.sk, ref); skgl_destroy(sk); gt_env_free(&e); return; }
    SK_CHECK(gt_gbuffer(&e, &cb) == 0);
    SK_CHECK(skgl_shadow_analyze(e.sk, ref, &cb, &sc, light_dir(), e.gbuf.depth_tex) == SK_OK);
    nb = skgl_shadow_pages(ref, pb, MAX_PAGES);
    SK_CHECK(gt_gbuffer(&e, &ca) == 0);
    SK_CHECK(skgl_shadow_analyze(e.sk, ref, &ca, &sc, light_dir(), e.gbuf.depth_tex) == SK_OK);
    na = skgl_shadow_pages(ref, pa, MAX_PAGES);
    printf("rmsm: view A %d pages, view B %d\n", na, nb);
    SK_CHECK(na > 1 && nb > 1 && !same_pages(pa, na, pb, nb));
    counts_reset();
    SK_CHECK(skgl_shadow_analyze(sk, s, &ca, &sc, light_dir(), e.gbuf.depth_tex) == SK_OK);
    SK_CHECK(skgl_shadow_render(sk, s, &ca, &sc, light_dir()) == SK_OK);
    n = skgl_shadow_pages(s, got, MAX_PAGES);
    SK_CHECK_MSG(same_pages(got, n, pa, na) && R.client_reads == 1 && R.pbo_reads == 0 && R.subimages == 1,
                 "frame 1: %d pages (A: %d), %ld client reads, %ld ring read-backs, %ld table uploads", n, na,
                 R.client_reads, R.pbo_reads, R.subimages);
    e.gl.Finish();
    R.not_ready = 1;
    for (f = 2; f <= 5; f++) {
        const skgl_camera *c = f < 4 ? &ca : &cb;
        if (f == 4) SK_CHECK(gt_gbuffer(&e, &cb) == 0);
        counts_reset();
        SK_CHECK(skgl_shadow_analyze(sk, s, c, &sc, light_dir(), e.gbuf.depth_tex) == SK_OK);
        SK_CHECK(skgl_shadow_render(sk, s, c, &sc, light_dir()) == SK_OK);
        n = skgl_shadow_pages(s, got, MAX_PAGES);
        SK_CHECK_MSG(same_pages(got, n, pa, na) && skgl_shadow_stats(s)->pages_rendered == na,
                     "frame %d: %d pages, not view A's %d", f, n, na);
        SK_CHECK_MSG(R.client_reads == 0 && R.buffer_reads == 0 && R.pbo_reads == (f < 5) && R.subimages == 0,
                     "frame %d: %ld client reads, %ld buffer reads, %ld ring read-backs, %ld table uploads", f,
                     R.client_reads, R.buffer_reads, R.pbo_reads, R.subimages);
        e.gl.Finish();
    }
    R.not_ready = 0;
    counts_reset();
    SK_CHECK(skgl_shadow_analyze(sk, s, &cb, &sc, light_dir(), e.gbuf.depth_tex) == SK_OK);
    SK_CHECK(skgl_shadow_render(sk, s, &cb, &sc, light_dir()) == SK_OK);
    n = skgl_shadow_pages(s, got, MAX_PAGES);
    SK_CHECK_MSG(same_pages(got, n, pb, nb) && R.buffer_reads == 1 && R.subimages == 1 && R.client_reads == 0,
                 "frame 6: %d pages (B: %d), %ld buffer reads, %ld table uploads, %ld client reads", n, nb,
                 R.buffer_reads, R.subimages, R.client_reads);
    e.gl.Finish();
    /* the same view again: the table is as uploaded, no upload */
    counts_reset();
    SK_CHECK(skgl_shadow_analyze(sk, s, &cb, &sc, light_dir(), e.gbuf.depth_tex) == SK_OK);
    SK_CHECK_MSG(R.buffer_reads == 1 && R.subimages == 0, "frame 7: %ld buffer reads, %ld table uploads",
                 R.buffer_reads, R.subimages);
    SK_CHECK(e.gl.GetError() == 0);
    skgl_shadow_destroy(sk, s);
    skgl_shadow_destroy(e.sk, ref);
    skgl_destroy(sk);
    gt_env_free(&e);
}

/* ---- timer queries read late ---- */
static void test_timer_ring(void) {
    gt_env e;
    skgl_context *sk;
    skgl_shadow_desc d;
    skgl_shadow *s = NULL;
    skgl_scene sc;
    skgl_camera ca = view_a();
    float vis_shadow = -1.0f, vis_mask = -1.0f;
    int f;
    if (env_init(&e) != 0) return;
    sc = gt_scene(&e);
    sk = ring_context(0, 1, 0);
    memset(&d, 0, sizeof d);
    d.resolution = 1024;
    SK_CHECK(sk && skgl_shadow_create(sk, &d, &s) == SK_OK);
    if (!sk || !s) { skgl_destroy(sk); gt_env_free(&e); return; }
    SK_CHECK(gt_gbuffer(&e, &ca) == 0);
    for (f = 1; f <= 6; f++) {
        const skgl_shadow_frame_stats *st = skgl_shadow_stats(s);
        R.not_available = f == 4 || f == 5;
        counts_reset();
        SK_CHECK(skgl_shadow_render(sk, s, &ca, &sc, light_dir()) == SK_OK);
        SK_CHECK(skgl_shadow_mask(sk, s, &ca, e.gbuf.depth_tex, e.gbuf.color_tex, e.mask.color_tex) == SK_OK);
        printf("timer frame %d: shadow %.4f ms, mask %.4f ms, %ld queries begun, %ld results read\n", f,
               st->shadow_ms, st->mask_ms, R.begins, R.results);
        if (f <= 2) SK_CHECK(st->shadow_ms == -1.0f && st->mask_ms == -1.0f && R.begins == 2 && R.results == 0);
        if (f == 3) {
            SK_CHECK(st->shadow_ms >= 0.0f && st->mask_ms >= 0.0f && R.begins == 2 && R.results == 2);
            vis_shadow = st->shadow_ms;
            vis_mask = st->mask_ms;
        }
        if (f == 4 || f == 5)
            SK_CHECK_MSG(st->shadow_ms == vis_shadow && st->mask_ms == vis_mask && R.results == 0 &&
                             R.begins == (f == 4 ? 2 : 0),
                         "frame %d: %g / %g ms (frame 3: %g / %g), %ld results, %ld begun", f, st->shadow_ms,
                         st->mask_ms, vis_shadow, vis_mask, R.results, R.begins);
        if (f == 6) SK_CHECK(st->shadow_ms >= 0.0f && st->mask_ms >= 0.0f && R.results == 4 && R.begins == 2);
        e.gl.Finish();
    }
    R.not_available = 0;
    SK_CHECK(e.gl.GetError() == 0);
    skgl_shadow_destroy(sk, s);
    skgl_destroy(sk);
    gt_env_free(&e);
}

/* ---- the user's program locations, cached ---- */
static unsigned make_program(gt_env *e) {
    const tb_gl_funcs *gl = &e->gl;
    const char *vs[1], *fs[3];
    unsigned v, g, p;
    int ok = 0;
    vs[0] = gt_forward_vs;
    fs[0] = "#version 330 core\n";
    fs[1] = skgl_glsl_snippet();
    fs[2] = gt_forward_fs;
    v = gt_compile(gl, 0x8B31, 1, vs);
    g = gt_compile(gl, 0x8B30, 3, fs);
    if (!v || !g) { if (v) gl->DeleteShader(v); if (g) gl->DeleteShader(g); return 0; }
    p = gl->CreateProgram();
    gl->AttachShader(p, v);
    gl->AttachShader(p, g);
    gl->LinkProgram(p);
    gl->DeleteShader(v);
    gl->DeleteShader(g);
    gl->GetProgramiv(p, 0x8B82, &ok);
    if (!ok) { gl->DeleteProgram(p); return 0; }
    return p;
}

static int uniform_i(gt_env *e, const ext_funcs *x, unsigned p, const char *name) {
    int v = -12345, loc = e->gl.GetUniformLocation(p, name);
    if (loc >= 0) x->GetUniformiv(p, loc, &v);
    return v;
}

/* binds s to p (current) on unit 5; the look-ups it made */
static long bind_lookups(gt_env *e, skgl_context *sk, const skgl_shadow *s, unsigned p) {
    sk_result r;
    e->gl.UseProgram(p);
    counts_reset();
    r = skgl_shadow_bind(sk, s, p, 5);
    SK_CHECK_MSG(r == SK_OK, "skgl_shadow_bind: %s (%s)", sk_result_string(r), skgl_error_log(sk));
    e->gl.UseProgram(0);
    return R.locations;
}

static void test_program_cache(void) {
    gt_env e;
    ext_funcs x;
    skgl_context *sk, *own;
    skgl_shadow_desc d;
    skgl_shadow *s1 = NULL, *s2 = NULL, *o1 = NULL;
    skgl_scene sc;
    skgl_camera ca = view_a();
    unsigned p, p2, many[17];
    long n;
    int i;
    if (env_init(&e) != 0) return;
    ext_load(&x, tb_gl_context_getproc(e.ctx));
    sc = gt_scene(&e);
    sk = ring_context(0, 0, 0);
    own = ring_context(0, 0, 1);
    memset(&d, 0, sizeof d);
    d.resolution = 512;
    d.pcf_radius = 1;
    SK_CHECK(sk && skgl_shadow_create(sk, &d, &s1) == SK_OK);
    SK_CHECK(own && skgl_shadow_create(own, &d, &o1) == SK_OK);
    d.pcf_radius = 3;
    SK_CHECK(sk && skgl_shadow_create(sk, &d, &s2) == SK_OK);
    p = make_program(&e);
    SK_CHECK(p != 0);
    if (!sk || !own || !s1 || !s2 || !o1 || !p) goto done;
    SK_CHECK(skgl_shadow_render(sk, s1, &ca, &sc, light_dir()) == SK_OK);
    SK_CHECK(skgl_shadow_render(sk, s2, &ca, &sc, light_dir()) == SK_OK);
    SK_CHECK(skgl_shadow_render(own, o1, &ca, &sc, light_dir()) == SK_OK);
    /* first bind: the look-ups; the next: none */
    n = bind_lookups(&e, sk, s1, p);
    SK_CHECK_MSG(n == 27, "first bind: %ld look-ups", n);
    n = bind_lookups(&e, sk, s1, p);
    SK_CHECK_MSG(n == 0, "second bind: %ld look-ups", n);
    SK_CHECK(uniform_i(&e, &x, p, "sk_shadow_map") == 5 && uniform_i(&e, &x, p, "sk_pcf_radius") == 1);
    /* two lights in turn: each leaves its own constants */
    (void)bind_lookups(&e, sk, s2, p);
    SK_CHECK_MSG(uniform_i(&e, &x, p, "sk_pcf_radius") == 3, "after s2: radius %d",
                 uniform_i(&e, &x, p, "sk_pcf_radius"));
    (void)bind_lookups(&e, sk, s1, p);
    SK_CHECK_MSG(uniform_i(&e, &x, p, "sk_pcf_radius") == 1, "after s1: radius %d",
                 uniform_i(&e, &x, p, "sk_pcf_radius"));
    /* linked again: every uniform back at 0, found by the default mode */
    e.gl.LinkProgram(p);
    SK_CHECK(uniform_i(&e, &x, p, "sk_shadow_map") == 0);
    n = bind_lookups(&e, sk, s1, p);
    SK_CHECK_MSG(n == 27 && uniform_i(&e, &x, p, "sk_shadow_map") == 5 && uniform_i(&e, &x, p, "sk_pcf_radius") == 1,
                 "relinked: %ld look-ups, unit %d, radius %d", n, uniform_i(&e, &x, p, "sk_shadow_map"),
                 uniform_i(&e, &x, p, "sk_pcf_radius"));
    /* deleted and made anew: GL hands the freed name out again */
    e.gl.DeleteProgram(p);
    p2 = make_program(&e);
    printf("program %u deleted, the new one is %u\n", p, p2);
    SK_CHECK(p2 != 0);
    n = bind_lookups(&e, sk, s1, p2);
    SK_CHECK_MSG(n == 27 && uniform_i(&e, &x, p2, "sk_shadow_map") == 5, "made anew: %ld look-ups, unit %d", n,
                 uniform_i(&e, &x, p2, "sk_shadow_map"));
    /* caller-owns mode: the cache is trusted until skgl_forget_program */
    n = bind_lookups(&e, own, o1, p2);
    SK_CHECK(n == 27 && uniform_i(&e, &x, p2, "sk_shadow_map") == 5);
    e.gl.LinkProgram(p2);
    n = bind_lookups(&e, own, o1, p2);
    SK_CHECK_MSG(n == 0 && uniform_i(&e, &x, p2, "sk_shadow_map") == 0,
                 "caller owns, relinked, not forgotten: %ld look-ups, unit %d", n,
                 uniform_i(&e, &x, p2, "sk_shadow_map"));
    skgl_forget_program(own, p2);
    n = bind_lookups(&e, own, o1, p2);
    SK_CHECK_MSG(n == 27 && uniform_i(&e, &x, p2, "sk_shadow_map") == 5 && uniform_i(&e, &x, p2, "sk_pcf_radius") == 1,
                 "caller owns, forgotten: %ld look-ups, unit %d", n, uniform_i(&e, &x, p2, "sk_shadow_map"));
    /* 17 programs in 16 entries: the least recently bound goes first */
    for (i = 0; i < 17; i++) {
        many[i] = make_program(&e);
        SK_CHECK(many[i] != 0);
        if (many[i]) (void)bind_lookups(&e, sk, s1, many[i]);
    }
    n = bind_lookups(&e, sk, s1, many[16]);
    SK_CHECK_MSG(n == 0, "the most recent program: %ld look-ups", n);
    n = bind_lookups(&e, sk, s1, many[0]);
    SK_CHECK_MSG(n == 27, "the least recent program: %ld look-ups", n);
    for (i = 0; i < 17; i++) if (many[i]) e.gl.DeleteProgram(many[i]);
    e.gl.DeleteProgram(p2);
    SK_CHECK(e.gl.GetError() == 0);
done:
    skgl_shadow_destroy(sk, s1);
    skgl_shadow_destroy(sk, s2);
    skgl_shadow_destroy(own, o1);
    skgl_destroy(sk);
    skgl_destroy(own);
    gt_env_free(&e);
}

/* ---- the two state modes ---- */
enum { T_STANDARD, T_PSSM, T_FERKO, T_RMSM, T_CUBE, T_VSDCT, T_N };
static const char *const tech_names[T_N] = {"standard", "pssm", "ferko", "rmsm", "point-cube", "point-vsdct"};

/* one frame of technique t on context sk into vis; 0 ok */
static int mode_frame(gt_env *e, skgl_context *sk, int t, const skgl_camera *cam, float *vis) {
    skgl_scene sc = gt_scene(e);
    sk_vec3 lp = gt_v3(0.5f, 2.5f, 0.5f);
    sk_result r = SK_OK;
    size_t i;
    if (t >= T_CUBE) {
        skgl_point_desc pd;
        skgl_point *p = NULL;
        memset(&pd, 0, sizeof pd);
        pd.technique = t == T_CUBE ? SKGL_POINT_CUBE : SKGL_POINT_VSDCT;
        pd.resolution = 256;
        pd.range = 14.0f;
        r = skgl_point_create(sk, &pd, &p);
        if (r == SK_OK) r = skgl_point_render(sk, p, cam, &sc, lp);
        if (r == SK_OK) r = skgl_point_mask(sk, p, cam, e->gbuf.depth_tex, e->gbuf.color_tex, e->mask.color_tex);
        skgl_point_destroy(sk, p);
    } else {
        skgl_shadow_desc d;
        skgl_shadow *s = NULL;
        memset(&d, 0, sizeof d);
        d.technique = t == T_STANDARD ? SKGL_STANDARD : t == T_PSSM ? SKGL_PSSM : t == T_FERKO ? SKGL_FERKO : SKGL_RMSM;
        d.resolution = t == T_RMSM ? 8192 : 1024;
        d.cascades = 3;
        d.sync_readback = 1;
        r = skgl_shadow_create(sk, &d, &s);
        if (r == SK_OK && (t == T_FERKO || t == T_RMSM))
            r = skgl_shadow_analyze(sk, s, cam, &sc, light_dir(), e->gbuf.depth_tex);
        if (r == SK_OK) r = skgl_shadow_render(sk, s, cam, &sc, light_dir());
        if (r == SK_OK) r = skgl_shadow_mask(sk, s, cam, e->gbuf.depth_tex, e->gbuf.color_tex, e->mask.color_tex);
        skgl_shadow_destroy(sk, s);
    }
    if (r != SK_OK) {
        printf("%s: %s (%s)\n", tech_names[t], sk_result_string(r), skgl_error_log(sk));
        return -1;
    }
    if (tb_gl_read_texture_red(&e->gl, e->mask.color_tex, e->w, e->h, vis) != 0) return -1;
    for (i = 0; i < e->n; i++) if (!(e->depth[i] < 1.0f)) vis[i] = -1.0f;
    return 0;
}

/* a callback that binds a program of its own for its draws */
typedef struct own_prog_scene {
    gt_env *e;
    unsigned program;
    int bind_back;
} own_prog_scene;
static void own_prog_draw(void *user, const skgl_draw_info *info) {
    own_prog_scene *o = (own_prog_scene *)user;
    tb_gl_mesh_draw(&o->e->gl, &o->e->mesh, 0, 0);
    o->e->gl.UseProgram(o->program);   /* e.g. its alpha-tested foliage next */
    if (o->bind_back) o->e->gl.UseProgram(info->program);
}

static void test_state_modes(void) {
    gt_env e;
    ext_funcs x;
    skgl_context *restore, *own;
    skgl_camera ca = view_a();
    float *ref, *vis;
    int t, m, mode[2], diff;
    size_t i;
    if (env_init(&e) != 0) return;
    ext_load(&x, tb_gl_context_getproc(e.ctx));
    ref = gt_alloc(&e);
    vis = gt_alloc(&e);
    restore = ring_context(1, 0, 0);
    own = ring_context(1, 0, 1);
    SK_CHECK(gt_gbuffer(&e, &ca) == 0);
    if (!restore || !own || !ref || !vis) goto done;
    for (t = 0; t < T_N; t++) {
        size_t lit = 0, dark = 0;
        x.PolygonMode(0x0408 /* FRONT_AND_BACK */, 0x1B02 /* FILL */);
        SK_CHECK_MSG(mode_frame(&e, restore, t, &ca, ref) == 0, "%s: filled host", tech_names[t]);
        for (i = 0; i < e.n; i++) {
            if (ref[i] < 0.0f) continue;
            if (ref[i] >= 0.5f) lit++; else dark++;
        }
        SK_CHECK_MSG(lit > e.n / 10 && dark > e.n / 200, "%s: %zu lit, %zu shadowed", tech_names[t], lit, dark);
        for (m = 0; m < 2; m++) {
            int fb[2] = {-1, -1}, pack = -1;
            x.PolygonMode(0x0408, 0x1B01 /* LINE */);
            SK_CHECK_MSG(mode_frame(&e, m ? own : restore, t, &ca, vis) == 0, "%s, %s: wireframe host", tech_names[t],
                         m ? "caller owns" : "restored");
            e.gl.GetIntegerv(0x0B40 /* POLYGON_MODE */, mode);
            e.gl.GetIntegerv(0x8CA6 /* DRAW_FRAMEBUFFER_BINDING */, &fb[0]);
            e.gl.GetIntegerv(0x8CAA /* READ_FRAMEBUFFER_BINDING */, &fb[1]);
            e.gl.GetIntegerv(0x88ED /* PIXEL_PACK_BUFFER_BINDING */, &pack);
            for (diff = 0, i = 0; i < e.n; i++) diff += vis[i] != ref[i];
            SK_CHECK_MSG(diff == 0, "%s, %s, wireframe host: %d mask values differ from the filled host's",
                         tech_names[t], m ? "caller owns" : "restored", diff);
            if (m == 0)
                SK_CHECK_MSG(mode[0] == 0x1B01, "%s: polygon mode 0x%x, not given back", tech_names[t], mode[0]);
            else SK_CHECK_MSG(mode[0] == 0x1B02 && fb[0] == 0 && fb[1] == 0 && pack == 0,
                              "%s, caller owns: left polygon mode 0x%x, framebuffers %d %d, pack buffer %d",
                              tech_names[t], mode[0], fb[0], fb[1], pack);
            SK_CHECK(e.gl.GetError() == 0);
        }
    }
    x.PolygonMode(0x0408, 0x1B02);
    /* the caller's program deleted while current */
    {
        unsigned doomed = make_program(&e);
        skgl_shadow_desc d;
        skgl_shadow *s = NULL;
        skgl_scene sc = gt_scene(&e);
        int cur = -1;
        memset(&d, 0, sizeof d);
        d.technique = SKGL_FERKO;
        d.resolution = 1024;
        SK_CHECK(doomed != 0 && skgl_shadow_create(restore, &d, &s) == SK_OK);
        e.gl.UseProgram(doomed);
        e.gl.DeleteProgram(doomed);   /* flagged: lives while current */
        SK_CHECK(skgl_shadow_analyze(restore, s, &ca, &sc, light_dir(), e.gbuf.depth_tex) == SK_OK);
        SK_CHECK(skgl_shadow_render(restore, s, &ca, &sc, light_dir()) == SK_OK);
        SK_CHECK(skgl_shadow_mask(restore, s, &ca, e.gbuf.depth_tex, e.gbuf.color_tex, e.mask.color_tex) == SK_OK);
        e.gl.GetIntegerv(0x8B8D /* CURRENT_PROGRAM */, &cur);
        SK_CHECK_MSG(e.gl.GetError() == 0 && cur == 0, "deleted current program: program %d current after", cur);
        skgl_shadow_destroy(restore, s);
    }
    /* the draw callback's contract on the program */
    {
        own_prog_scene o;
        skgl_shadow_desc d;
        skgl_shadow *s = NULL;
        skgl_scene sc;
        sk_result r;
        memset(&d, 0, sizeof d);
        d.resolution = 1024;
        o.e = &e;
        o.program = make_program(&e);
        o.bind_back = 0;
        sc.draw = own_prog_draw;
        sc.user = &o;
        sc.bounds = e.scene.bounds;
        SK_CHECK(o.program != 0 && skgl_shadow_create(restore, &d, &s) == SK_OK);
        r = skgl_shadow_render(restore, s, &ca, &sc, light_dir());
        SK_CHECK_MSG(r == SK_ERR_INVALID_ARG && strstr(skgl_error_log(restore), "info->program"),
                     "a callback leaving its program: %s (%s)", sk_result_string(r), skgl_error_log(restore));
        o.bind_back = 1;
        r = skgl_shadow_render(restore, s, &ca, &sc, light_dir());
        SK_CHECK_MSG(r == SK_OK, "a callback binding info->program back: %s", sk_result_string(r));
        SK_CHECK(gt_mask_only(&e, s, &ca, vis) == 0);
        SK_CHECK(mode_frame(&e, restore, T_STANDARD, &ca, ref) == 0);
        for (diff = 0, i = 0; i < e.n; i++) diff += vis[i] != ref[i];
        SK_CHECK_MSG(diff == 0, "callback with its own program: %d mask values differ", diff);
        skgl_shadow_destroy(restore, s);
        e.gl.DeleteProgram(o.program);
    }
    SK_CHECK(e.gl.GetError() == 0);
done:
    free(ref);
    free(vis);
    skgl_destroy(restore);
    skgl_destroy(own);
    gt_env_free(&e);
}

/* ---- a callback that leaves another unit active ---- */
static void unit_draw(void *user, const skgl_draw_info *info) {
    gt_env *e = (gt_env *)user;
    (void)info;
    tb_gl_mesh_draw(&e->gl, &e->mesh, 0, 0);
    e->gl.ActiveTexture(0x84C0 + 3);   /* allowed: the contract leaves units to the callback */
}

static void test_callback_units(void) {
    gt_env e;
    skgl_context *sk;
    skgl_shadow_desc d;
    skgl_shadow *s = NULL;
    skgl_scene sc;
    skgl_camera ca = view_a();
    unsigned t0 = 0, t3 = 0;
    int b0 = -1, b3 = -1, active = -1;
    if (env_init(&e) != 0) return;
    sc = gt_scene(&e);
    sc.draw = unit_draw;
    sk = ring_context(1, 0, 0);
    memset(&d, 0, sizeof d);
    d.technique = SKGL_RMSM;
    d.resolution = 4096;
    SK_CHECK(sk && skgl_shadow_create(sk, &d, &s) == SK_OK);
    if (!s) { skgl_destroy(sk); gt_env_free(&e); return; }
    /* the caller: its textures on units 0 and 3, unit 5 active; an RMSM
       render without analysis uploads its page table on unit 0 first */
    e.gl.GenTextures(1, &t0);
    e.gl.GenTextures(1, &t3);
    e.gl.ActiveTexture(0x84C0 + 3);
    e.gl.BindTexture(0x0DE1, t3);
    e.gl.ActiveTexture(0x84C0);
    e.gl.BindTexture(0x0DE1, t0);
    e.gl.ActiveTexture(0x84C0 + 5);
    SK_CHECK(skgl_shadow_render(sk, s, &ca, &sc, light_dir()) == SK_OK);
    e.gl.GetIntegerv(0x84E0 /* ACTIVE_TEXTURE */, &active);
    e.gl.ActiveTexture(0x84C0);
    e.gl.GetIntegerv(0x8069 /* TEXTURE_BINDING_2D */, &b0);
    e.gl.ActiveTexture(0x84C0 + 3);
    e.gl.GetIntegerv(0x8069, &b3);
    SK_CHECK_MSG(active == 0x84C0 + 5 && b0 == (int)t0 && b3 == (int)t3,
                 "after a callback switching units: active 0x%x, unit 0 holds %d (was %u), unit 3 %d (was %u)",
                 (unsigned)active, b0, t0, b3, t3);
    e.gl.ActiveTexture(0x84C0);
    e.gl.DeleteTextures(1, &t0);
    e.gl.DeleteTextures(1, &t3);
    SK_CHECK(e.gl.GetError() == 0);
    skgl_shadow_destroy(sk, s);
    skgl_destroy(sk);
    gt_env_free(&e);
}

/* ---- the user's textures, remembered by name ---- */
static void test_texture_cache(void) {
    gt_env e;
    skgl_context *dbg;
    skgl_shadow_desc d;
    skgl_shadow *s = NULL;
    skgl_scene sc;
    skgl_camera ca = view_a();
    float *ref, *vis;
    unsigned tex = 0;
    sk_result r;
    size_t i;
    int diff = 0;
    if (env_init(&e) != 0) return;
    sc = gt_scene(&e);
    ref = gt_alloc(&e);
    vis = gt_alloc(&e);
    dbg = ring_context(1, 0, 0);
    memset(&d, 0, sizeof d);
    d.resolution = 1024;
    SK_CHECK(dbg && ref && vis && skgl_shadow_create(dbg, &d, &s) == SK_OK);
    if (!s) goto done;
    SK_CHECK(gt_gbuffer(&e, &ca) == 0);
    SK_CHECK(skgl_shadow_render(dbg, s, &ca, &sc, light_dir()) == SK_OK);
    SK_CHECK(gt_mask_only(&e, s, &ca, ref) == 0);
    /* a mask texture of the test's, first half the size, then given the
       G-buffer's size under the same name */
    e.gl.GenTextures(1, &tex);
    e.gl.BindTexture(0x0DE1, tex);
    e.gl.TexImage2D(0x0DE1, 0, 0x822D /* R16F */, W / 2, H / 2, 0, 0x1903 /* RED */, 0x1406 /* FLOAT */, NULL);
    e.gl.TexParameteri(0x0DE1, 0x2801, 0x2600);   /* MIN_FILTER NEAREST */
    SK_CHECK(skgl_shadow_mask(dbg, s, &ca, e.gbuf.depth_tex, e.gbuf.color_tex, tex) == SK_OK);
    e.gl.BindTexture(0x0DE1, tex);
    e.gl.TexImage2D(0x0DE1, 0, 0x822D, W, H, 0, 0x1903, 0x1406, NULL);
    e.gl.BindTexture(0x0DE1, 0);
    r = skgl_shadow_mask(dbg, s, &ca, e.gbuf.depth_tex, e.gbuf.color_tex, tex);
    SK_CHECK_MSG(r == SK_ERR_INVALID_ARG && strstr(skgl_error_log(dbg), "skgl_forget_texture"),
                 "new storage, not forgotten, debug: %s (%s)", sk_result_string(r), skgl_error_log(dbg));
    skgl_forget_texture(dbg, tex);
    r = skgl_shadow_mask(dbg, s, &ca, e.gbuf.depth_tex, e.gbuf.color_tex, tex);
    SK_CHECK_MSG(r == SK_OK, "forgotten: %s (%s)", sk_result_string(r), skgl_error_log(dbg));
    SK_CHECK(tb_gl_read_texture_red(&e.gl, tex, W, H, vis) == 0);
    for (i = 0; i < e.n; i++) {
        if (!(e.depth[i] < 1.0f)) vis[i] = -1.0f;
        diff += vis[i] != ref[i];
    }
    SK_CHECK_MSG(diff == 0, "the mask in the texture given new storage: %d values differ", diff);
    /* forgotten, it is no longer held by shadowkit's framebuffer */
    skgl_forget_texture(dbg, tex);
    e.gl.DeleteTextures(1, &tex);
    SK_CHECK(skgl_shadow_mask(dbg, s, &ca, e.gbuf.depth_tex, e.gbuf.color_tex, e.mask.color_tex) == SK_OK);
    SK_CHECK(e.gl.GetError() == 0);
done:
    skgl_shadow_destroy(dbg, s);
    skgl_destroy(dbg);
    free(ref);
    free(vis);
    gt_env_free(&e);
}

SK_TEST_MAIN(test_ferko_ring, test_rmsm_ring, test_timer_ring, test_program_cache, test_state_modes,
             test_callback_units, test_texture_cache)
