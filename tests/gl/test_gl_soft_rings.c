/* test_gl_soft_rings.c - what an area light (skgl_soft) keeps between
   frames: PVSM's prediction read back through the ring of fenced pixel
   buffers (a frame late, the default) or at once (sync_readback), the
   light moved, the frame timer's query sets, and what the latency costs
   in error under camera motion. shadowkit gets its entry points through
   gl_wrap.h's getproc (fences "not ready", query results "not available"
   on demand). 320 x 180.

   test_pvsm_ring ("ground-boxes", the area light of test_gl_calls): a
   reference light with sync_readback gives the SMTG pyramids of views A
   (-9, 7, 12) and B (-3, 2.5, 4), which differ. A default light: frame 1
   (A) reads at once, one glReadPixels into client memory, age 0, A's
   pyramid; with every fence "not ready", frames 2 and 3 (A) and 4 and 5
   (B) keep A's pyramid and tiles (age 1 to 4), read nothing back and stall
   nowhere, and issue a read-back into the ring in frames 2, 3 and 4 but not
   in 5 (all three buffers in flight: readback_bytes 0); the fences ready
   again, frame 6 (B) reads one buffer, the newest (frame 4's: view B), has
   B's pyramid at age 2, and its mask equals the reference's mask of B
   value for value (the same prediction in the same frustum).
   test_light_moved: a default light, fences "not ready" in frames 2, 3
   and 5. Frame 3 moves the light 0.3 m: it does not read at once (no
   client read, age 2: frame 1's prediction), its one tile is carried into
   the moved light's frustum (the rectangle differs from the cell), and
   its mask differs from the one of its own prediction (a sync_readback
   reference of the moved light) by a mean 0.00073 (bound 0.0015); the
   fences ready, frame 4 lands frame 3's read-back: the moved light's
   pyramid, bit for bit, age 1. Frame 5 turns the light to the side: a
   carried tile would reach behind its plane, so it reads at once (one
   client read, age 0) although the fences are "not ready".
   test_soft_timer: desc.timing = 1, PVSM with .resolution 256 (several
   tiles: more timed passes than a query set starts with, so the set
   grows): stats.step_ms and shadow_ms, mask_ms are -1 after frames 1 and
   2 and times from frame 3 (frame 1's passes); with the results "not
   available" frames 4 and 5 keep them and read no GL_QUERY_RESULT, and
   frame 5 (its set, frame 2's, still busy) begins no query; available
   again, frame 6 reads two frames' sets. SKGL_TIMING_SYNC: times from
   frame 1. PCSS: steps 1 and 7 timed, the others -1.
   test_motion_cost ("contact", its light of half size 0.25, tiles of at
   most 256 texels: 2 or 3 of them): the camera moves sideways and turns
   for 8 frames, at 2, 10 and 30 cm a frame; then the light moves 5 cm a
   frame, the camera still; the latency-1 light's mean visibility error
   against the exact reference (tb_reference_trace_exact) next to the
   sync_readback light's, on the same frames; every frame after the first
   uses the prediction of the frame before (age 1; glFinish between
   frames: a GPU that keeps up).

   Measured (Mesa llvmpipe, OSMesa): every check above as stated (210,
   about 25 s); the frame timer's set grew to 19 queries (7 tiles); motion
   cost, mean MAE latency 1 / sync: camera at 2 cm a frame 0.000400 /
   0.000401, 10 cm 0.000406 / 0.000407, 30 cm 0.000394 / 0.000399; light
   at 5 cm 0.000396 / 0.000398: the base frustum is snapped to steps, a
   carried tile covers the same receivers, and the region a frame newly
   shows is lit on this scene's margins. With the largest tile at 1024
   (one tile) the same to within 2%. The bound: latency 1 within 5% (+
   1e-5 a frame) of sync in each case.
   Can fail (each shown once, in a local copy of shadowkit_gl.h): the ring
   poll taking the oldest landed buffer instead of the newest: "frame 6:
   age 4, pyramid of B 0, 1 buffers read" and "frame 6: 1811 mask values
   differ from the reference's of view B"; the ring reusing a buffer in
   flight: "frame 5: ... 1 read-backs into the ring" (and frame 6 then
   lands frame 5's, age 1); the light's frame not compared: "moved light,
   frame 3: 0 client reads, pyramid of the moved light 0"; the timer
   reading results without asking for their availability: "frame 4: 19
   results, 19 begun" (and frame 5); the tile rectangles not carried into
   this frame's frustum (the grid cells of the prediction's frustum used as
   this frame's): "motion cost at 10 cm a frame: 0.025225 against
   0.000407", and 0.013470 against 0.000399 at 30 cm; a moved light's
   tiles not carried (the cells of the old frustum used as this one's):
   "moved light, frame 3: 1 tiles, 0 carried", the turned light not read
   at once (frame 5), and "motion cost, light at 5 cm a frame: 0.025043
   against 0.000398".

   HYGIENE. Under the sanitizers (build/hygiene/, __SANITIZE_ADDRESS__)
   test_motion_cost runs the camera at 30 cm a frame and the light, 3
   frames each, not the four motions of 8 frames (its exact reference,
   traced on the CPU every frame, is most of the run): measured with gcov,
   the same 1572 lines of shadowkit_gl.h (none fewer, none more), in
   15 CPU s instead of 53; its checks 102 instead of 210 (the same
   ones, for the frames and motions left out). */
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "sk_test.h"
#include "gl_test_util.h"
#include "gl_wrap.h"

#define W 320
#define H 180
#ifndef MOTION_RES
#define MOTION_RES 256   /* the largest tile: several tiles on "contact" */
/* the first motion run and the frames of each; under the sanitizers the
   camera at 30 cm and the light, 3 frames each, over the same lines
   (HYGIENE above): the plain build keeps the figures' four motions of 8 */
#ifdef __SANITIZE_ADDRESS__
#define MOTION_FIRST 2
#define MOTION_FRAMES 3
#else
#define MOTION_FIRST 0
#define MOTION_FRAMES 8
#endif
#endif

static skgl_area_light calls_light(float dx) {
    skgl_area_light l;
    memset(&l, 0, sizeof l);
    l.position = gt_v3(2.0f + dx, 9.0f, -2.5f);
    l.direction = gt_v3(-0.3f, -1.0f, 0.4f);
    l.up = gt_v3(0, 0, 1);
    l.half_width = l.half_height = 0.3f;
    return l;
}
static skgl_camera view_a(void) { return gt_camera(gt_v3(-9, 7, 12), gt_v3(0, 1, 0), 1.0f, 0.1f, 250, W, H); }
static skgl_camera view_b(void) { return gt_camera(gt_v3(-3, 2.5f, 4), gt_v3(0, 0.5f, 0), 1.0f, 0.1f, 250, W, H); }

static skgl_soft *pvsm_light(skgl_context *sk, int sync, int resolution) {
    skgl_soft_desc d;
    skgl_soft *s = NULL;
    sk_result r;
    memset(&d, 0, sizeof d);
    d.technique = SKGL_SOFT_PVSM;
    d.sync_readback = sync;
    d.resolution = resolution;
    r = skgl_soft_create(sk, &d, &s);
    SK_CHECK_MSG(r == SK_OK, "skgl_soft_create: %s (%s)", sk_result_string(r), skgl_error_log(sk));
    return s;
}

/* a frame: the G-buffer of cam, the light's render and mask (into vis) */
static int soft_frame(gt_env *e, skgl_context *sk, skgl_soft *s, const skgl_camera *cam, const skgl_area_light *l,
                      float *vis) {
    skgl_context *own = e->sk;
    int r;
    if (gt_gbuffer(e, cam) != 0) return -1;
    counts_reset();
    e->sk = sk;
    r = gt_soft_mask(e, s, cam, l, vis, NULL);
    e->sk = own;
    return r;
}

/* the light's current pyramid, malloc'd (*n floats) */
static float *pyramid_of(const skgl_soft *s, int *n) {
    float *p;
    *n = skgl_soft_pyramid(s, NULL, 0);
    p = (float *)malloc(sizeof(float) * (size_t)(*n > 0 ? *n : 1));
    if (p && *n > 0) skgl_soft_pyramid(s, p, *n);
    return p;
}
static int same_pyramid(const skgl_soft *s, const float *ref, int n) {
    int m, same;
    float *p = pyramid_of(s, &m);
    same = p && m == n && n > 0 && memcmp(p, ref, sizeof(float) * (size_t)n) == 0;
    free(p);
    return same;
}

/* ---- PVSM: the prediction a frame late ---- */
static void test_pvsm_ring(void) {
    gt_env e;
    skgl_context *sk;
    skgl_soft *ref, *s;
    skgl_camera ca = view_a(), cb = view_b();
    skgl_area_light l = calls_light(0.0f);
    float *pa, *pb, *vis, *vis_b;
    int na, nb, f, base;
    if (gt_env_init_named(&e, "ground-boxes", W, H) != 0) { gt_env_free(&e); return; }
    ring_install(tb_gl_context_getproc(e.ctx));
    sk = ring_context(0, 0, 0);
    base = skgl_gl_object_count(sk);
    vis = gt_alloc(&e);
    vis_b = gt_alloc(&e);
    ref = pvsm_light(sk, 1, 0);
    s = pvsm_light(sk, 0, 0);
    if (!sk || !ref || !s) goto done;
    SK_CHECK(soft_frame(&e, sk, ref, &ca, &l, vis) == 0);
    pa = pyramid_of(ref, &na);
    SK_CHECK(soft_frame(&e, sk, ref, &cb, &l, vis_b) == 0);
    pb = pyramid_of(ref, &nb);
    SK_CHECK_MSG(na == nb && na > 0 && memcmp(pa, pb, sizeof(float) * (size_t)na) != 0,
                 "the pyramids of views A and B are the same (%d, %d floats)", na, nb);
    for (f = 1; f <= 6; f++) {
        const skgl_soft_frame_stats *st = skgl_soft_stats(s);
        const skgl_camera *cam = f <= 3 ? &ca : &cb;
        int is_a, is_b;
        R.not_ready = f >= 2 && f <= 5;
        SK_CHECK(soft_frame(&e, sk, s, cam, &l, vis) == 0);
        is_a = same_pyramid(s, pa, na);
        is_b = same_pyramid(s, pb, nb);
        printf("ring frame %d: age %d, sync %d, %ld client reads, %ld into the ring, %ld buffers read, "
               "%d bytes, pyramid of A %d, of B %d\n",
               f, st->prediction_age, st->readback_sync, R.client_reads, R.pbo_reads, R.buffer_reads,
               st->readback_bytes, is_a, is_b);
        if (f == 1)
            SK_CHECK_MSG(st->readback_sync == 1 && R.client_reads == 1 && R.pbo_reads == 0 && is_a &&
                             st->prediction_age == 0,
                         "frame 1: %ld client reads, age %d, pyramid of A %d", R.client_reads, st->prediction_age,
                         is_a);
        if (f >= 2 && f <= 5)
            SK_CHECK_MSG(R.client_reads == 0 && R.buffer_reads == 0 && R.pbo_reads == (f <= 4) && is_a &&
                             st->prediction_age == f - 1 && st->readback_bytes == (f <= 4 ? 64 * 65 * 16 : 0),
                         "frame %d: %ld client reads, %ld buffers read, %ld read-backs into the ring, age %d, "
                         "pyramid of A %d",
                         f, R.client_reads, R.buffer_reads, R.pbo_reads, st->prediction_age, is_a);
        if (f == 6) {
            size_t i, differ = 0;
            SK_CHECK_MSG(R.buffer_reads == 1 && R.client_reads == 0 && is_b && st->prediction_age == 2,
                         "frame 6: age %d, pyramid of B %d, %ld buffers read", st->prediction_age, is_b,
                         R.buffer_reads);
            for (i = 0; i < e.n; i++) differ += vis[i] != vis_b[i];
            SK_CHECK_MSG(differ == 0, "frame 6: %zu mask values differ from the reference's of view B", differ);
        }
        e.gl.Finish();
    }
    R.not_ready = 0;
    free(pa);
    free(pb);
done:
    SK_CHECK(e.gl.GetError() == 0);
    if (s) skgl_soft_destroy(sk, s);
    if (ref) skgl_soft_destroy(sk, ref);
    /* destroyed with fences and read-backs in flight: nothing left */
    SK_CHECK_MSG(skgl_gl_object_count(sk) == base, "%d objects after destroy, %d before", skgl_gl_object_count(sk),
                 base);
    skgl_destroy(sk);
    free(vis);
    free(vis_b);
    gt_env_free(&e);
}

/* ---- the light moves while predictions are in flight ---- */
static double mean_abs_diff(const float *a, const float *b, size_t n) {
    double s = 0.0;
    size_t i, k = 0;
    for (i = 0; i < n; i++) {
        if (!(a[i] >= 0.0f) || !(b[i] >= 0.0f)) continue;
        s += fabs((double)a[i] - b[i]);
        k++;
    }
    return k ? s / (double)k : 0.0;
}

static void test_light_moved(void) {
    gt_env e;
    skgl_context *sk;
    skgl_soft *ref, *s;
    skgl_camera ca = view_a();
    skgl_area_light l0 = calls_light(0.0f), l1 = calls_light(0.3f), l2 = calls_light(0.3f);
    float *vis, *vis_ref, *pm;
    sk_rect cells[64], rects[64];
    int nm, f, nt;
    l2.direction = gt_v3(1.0f, -0.25f, 0.0f);   /* turned to the side: the old tiles reach behind it */
    if (gt_env_init_named(&e, "ground-boxes", W, H) != 0) { gt_env_free(&e); return; }
    ring_install(tb_gl_context_getproc(e.ctx));
    sk = ring_context(0, 0, 0);
    vis = gt_alloc(&e);
    vis_ref = gt_alloc(&e);
    ref = pvsm_light(sk, 1, 0);
    s = pvsm_light(sk, 0, 0);
    if (!sk || !ref || !s) goto done;
    SK_CHECK(soft_frame(&e, sk, ref, &ca, &l1, vis_ref) == 0);
    pm = pyramid_of(ref, &nm);
    for (f = 1; f <= 5; f++) {
        const skgl_soft_frame_stats *st = skgl_soft_stats(s);
        int moved;
        R.not_ready = f == 2 || f == 3 || f == 5;
        SK_CHECK(soft_frame(&e, sk, s, &ca, f <= 2 ? &l0 : f <= 4 ? &l1 : &l2, vis) == 0);
        moved = same_pyramid(s, pm, nm);
        printf("moved light, frame %d: age %d, sync %d, %ld client reads, %ld into the ring, %ld buffers read, "
               "pyramid of the moved light %d, %d tiles\n",
               f, st->prediction_age, st->readback_sync, R.client_reads, R.pbo_reads, R.buffer_reads, moved,
               st->tiles);
        if (f == 3) {
            /* the old light's prediction (frame 1's), its tiles carried into the moved light's frustum */
            double d = mean_abs_diff(vis, vis_ref, e.n);
            int i, carried = 0;
            nt = skgl_soft_tile_rects(s, rects, 64);
            skgl_soft_tiles(s, NULL, 0);
            for (i = 0; i < nt && i < 64; i++) {
                sk_tile t;
                float g = 64.0f;
                skgl_soft_tiles(s, &t, 1);
                cells[i].x0 = -1.0f + 2.0f * (float)t.x0 / g;
                carried += rects[i].x0 != cells[i].x0;
            }
            printf("moved light, frame 3: mask against this frame's own prediction: mean |difference| %.6f, "
                   "%d of %d tiles carried\n", d, carried, nt);
            SK_CHECK_MSG(R.client_reads == 0 && st->readback_sync == 0 && st->prediction_age == 2 && !moved,
                         "moved light, frame 3: %ld client reads, age %d", R.client_reads, st->prediction_age);
            SK_CHECK_MSG(nt >= 1 && carried >= 1, "moved light, frame 3: %d tiles, %d carried", nt, carried);
            /* measured 0.00073 (0.3 m on a light 9 m above the ground): the
               carried tile's rectangle is a little larger, its texels too */
            SK_CHECK_MSG(d < 1.5e-3, "moved light, frame 3: mean |difference| %.6f from this frame's prediction", d);
        }
        if (f == 4)
            SK_CHECK_MSG(R.client_reads == 0 && R.buffer_reads == 1 && R.pbo_reads == 1 && moved &&
                             st->prediction_age == 1,
                         "moved light, frame 4: %ld buffers read, %ld into the ring, age %d, pyramid of the "
                         "moved light %d",
                         R.buffer_reads, R.pbo_reads, st->prediction_age, moved);
        if (f == 5)
            SK_CHECK_MSG(R.client_reads == 1 && st->readback_sync == 1 && st->prediction_age == 0,
                         "turned light, frame 5: %ld client reads, sync %d, age %d", R.client_reads,
                         st->readback_sync, st->prediction_age);
        e.gl.Finish();
    }
    R.not_ready = 0;
    free(pm);
done:
    SK_CHECK(e.gl.GetError() == 0);
    if (s) skgl_soft_destroy(sk, s);
    if (ref) skgl_soft_destroy(sk, ref);
    skgl_destroy(sk);
    free(vis);
    free(vis_ref);
    gt_env_free(&e);
}

/* ---- the frame timer: query sets read two or three frames late ---- */
static int all_untimed(const skgl_soft_frame_stats *st) {
    int k;
    for (k = 0; k < SKGL_SOFT_STEPS; k++)
        if (st->step_ms[k] != -1.0f) return 0;
    return st->shadow_ms == -1.0f && st->mask_ms == -1.0f;
}

static void test_soft_timer(void) {
    gt_env e;
    skgl_context *sk;
    skgl_soft *s, *pc;
    skgl_camera ca = view_a();
    skgl_area_light l = calls_light(0.0f);
    skgl_soft_frame_stats kept;
    skgl_soft_desc d;
    float *vis;
    int f, k;
    if (gt_env_init_named(&e, "ground-boxes", W, H) != 0) { gt_env_free(&e); return; }
    ring_install(tb_gl_context_getproc(e.ctx));
    sk = ring_context(0, 1, 0);
    vis = gt_alloc(&e);
    memset(&kept, 0, sizeof kept);
    s = pvsm_light(sk, 0, 256);
    if (!sk || !s) goto done;
    for (f = 1; f <= 6; f++) {
        const skgl_soft_frame_stats *st = skgl_soft_stats(s);
        R.not_available = f == 4 || f == 5;
        SK_CHECK(soft_frame(&e, sk, s, &ca, &l, vis) == 0);
        printf("timer frame %d: %d tiles, shadow %.4f ms, mask %.4f ms, steps 1 %.4f 5 %.4f 6 %.4f, %ld begun, "
               "%ld results\n",
               f, st->tiles, st->shadow_ms, st->mask_ms, st->step_ms[1], st->step_ms[5], st->step_ms[6], R.begins,
               R.results);
        if (f == 1) SK_CHECK_MSG(st->tiles >= 2, "%d tiles: the query set does not grow", st->tiles);
        if (f <= 2) SK_CHECK_MSG(all_untimed(st) && R.results == 0 && R.begins > 8, "frame %d: %ld begun", f, R.begins);
        if (f == 3) {
            SK_CHECK_MSG(st->shadow_ms >= 0.0f && st->mask_ms >= 0.0f && R.results > 8, "frame 3: %ld results",
                         R.results);
            for (k = 1; k <= 7; k++) SK_CHECK_MSG(st->step_ms[k] >= 0.0f, "frame 3: step %d untimed", k);
            SK_CHECK(st->step_ms[0] == -1.0f);   /* the G-buffer is given */
            kept = *st;
        }
        if (f == 4 || f == 5)
            SK_CHECK_MSG(memcmp(kept.step_ms, st->step_ms, sizeof kept.step_ms) == 0 && R.results == 0 &&
                             (f == 4 ? R.begins > 8 : R.begins == 0),
                         "frame %d: %ld results, %ld begun, shadow %g (frame 3: %g)", f, R.results, R.begins,
                         st->shadow_ms, kept.shadow_ms);
        if (f == 6) SK_CHECK_MSG(st->shadow_ms >= 0.0f && R.results > 16, "frame 6: %ld results", R.results);
        e.gl.Finish();
    }
    R.not_available = 0;
    skgl_soft_destroy(sk, s);
    skgl_destroy(sk);
    /* measuring mode: this frame's own times; PCSS: its map and its mask */
    sk = ring_context(0, SKGL_TIMING_SYNC, 0);
    s = pvsm_light(sk, 0, 0);
    memset(&d, 0, sizeof d);
    d.technique = SKGL_SOFT_PCSS;
    pc = NULL;
    SK_CHECK(sk && skgl_soft_create(sk, &d, &pc) == SK_OK);
    if (!s || !pc) goto done2;
    SK_CHECK(soft_frame(&e, sk, s, &ca, &l, vis) == 0);
    SK_CHECK_MSG(skgl_soft_stats(s)->shadow_ms >= 0.0f && skgl_soft_stats(s)->step_ms[4] >= 0.0f,
                 "SYNC, frame 1: shadow %g ms", skgl_soft_stats(s)->shadow_ms);
    SK_CHECK(soft_frame(&e, sk, pc, &ca, &l, vis) == 0);
    for (k = 0; k < SKGL_SOFT_STEPS; k++)
        SK_CHECK_MSG((skgl_soft_stats(pc)->step_ms[k] >= 0.0f) == (k == 1 || k == 7), "PCSS step %d: %g ms", k,
                     skgl_soft_stats(pc)->step_ms[k]);
done2:
    if (pc) skgl_soft_destroy(sk, pc);
done:
    SK_CHECK(e.gl.GetError() == 0);
    if (s) skgl_soft_destroy(sk, s);
    skgl_destroy(sk);
    free(vis);
    gt_env_free(&e);
}

/* ---- what a frame of latency costs under camera motion ---- */
static double mae(const float *ref, const float *v, size_t n) {
    double s = 0.0;
    size_t i, k = 0;
    for (i = 0; i < n; i++) {
        if (!(ref[i] >= 0.0f) || !(v[i] >= 0.0f)) continue;
        s += fabs((double)ref[i] - v[i]);
        k++;
    }
    return k ? s / (double)k : 0.0;
}

static void test_motion_cost(void) {
    /* the camera at 2, 10, 30 cm a frame; then the light at 5 cm, the camera still */
    static const float steps[4] = {0.02f, 0.10f, 0.30f, 0.05f};
    gt_env e;
    skgl_soft *late = NULL, *sync = NULL;
    skgl_area_light l;
    float *ref, *vis;
    int k, f;
    if (gt_env_init_named(&e, "contact", W, H) != 0) { gt_env_free(&e); return; }
    memset(&l, 0, sizeof l);
    l.position = gt_v3(2.0f, 5.0f, -2.5f);
    l.direction = gt_v3(-0.4f, -1, 0.5f);
    l.half_width = l.half_height = 0.25f;
    ref = gt_alloc(&e);
    vis = gt_alloc(&e);
    for (k = MOTION_FIRST; k < 4; k++) {
        double sum_late = 0.0, sum_sync = 0.0;
        late = pvsm_light(e.sk, 0, MOTION_RES);
        sync = pvsm_light(e.sk, 1, MOTION_RES);
        if (!late || !sync) break;
        for (f = 0; f < MOTION_FRAMES; f++) {
            float t = k < 3 ? steps[k] * (float)f : 0.0f;
            skgl_camera cam;
            l.position = gt_v3(2.0f + (k == 3 ? steps[k] * (float)f : 0.0f), 5.0f, -2.5f);
            cam = gt_camera(gt_v3(3.0f + t, 2.2f, 3.6f - 0.6f * t), gt_v3(-0.6f + 0.5f * t, 0.2f, -0.4f),
                                        0.9f, 0.05f, 60, W, H);
            double m_late, m_sync;
            SK_CHECK(gt_gbuffer(&e, &cam) == 0);
            gt_area_reference(&e, &l, 0, ref);
            SK_CHECK(gt_soft_mask(&e, late, &cam, &l, vis, NULL) == 0);
            m_late = mae(ref, vis, e.n);
            SK_CHECK(gt_soft_mask(&e, sync, &cam, &l, vis, NULL) == 0);
            m_sync = mae(ref, vis, e.n);
            if (f > 0)
                SK_CHECK_MSG(skgl_soft_stats(late)->prediction_age == 1, "%.0f cm, frame %d: age %d",
                             100.0 * steps[k], f, skgl_soft_stats(late)->prediction_age);
            sum_late += m_late;
            sum_sync += m_sync;
            e.gl.Finish();
        }
        printf("motion cost, %s at %.0f cm a frame: mean MAE latency 1 %.6f, sync %.6f (%+.1f%%), %d tiles\n",
               k < 3 ? "camera" : "light", 100.0 * steps[k], sum_late / MOTION_FRAMES, sum_sync / MOTION_FRAMES,
               100.0 * (sum_late / sum_sync - 1.0), skgl_soft_stats(late)->tiles);
        SK_CHECK_MSG(sum_late <= 1.05 * sum_sync + MOTION_FRAMES * 1e-5,
                     "motion cost, %s at %.0f cm a frame: %.6f against %.6f", k < 3 ? "camera" : "light",
                     100.0 * steps[k], sum_late / MOTION_FRAMES, sum_sync / MOTION_FRAMES);
        skgl_soft_destroy(e.sk, late);
        skgl_soft_destroy(e.sk, sync);
        late = sync = NULL;
    }
    if (late) skgl_soft_destroy(e.sk, late);
    if (sync) skgl_soft_destroy(e.sk, sync);
    free(ref);
    free(vis);
    gt_env_free(&e);
}

SK_TEST_MAIN(test_pvsm_ring, test_light_moved, test_soft_timer, test_motion_cost)
