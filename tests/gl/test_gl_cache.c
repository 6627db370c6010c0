/* test_gl_cache.c - cached maps (desc.cache, CACHED MAPS): what a cached
   light renders equals what it renders uncached, frame by frame, while the
   cache redraws only what changed.

   Scene: "ground-boxes" plus a 0.8 m "mover" box, 320 x 180. Each
   scenario runs a cached light and its uncached twin: the same desc,
   skgl_shadow_invalidate(NULL) before every render, so the twin draws
   every layer whole with the same matrices (the uncached mask of the same
   frame), and a light with .cache 0 (the path every cached light takes
   apart from, its stable crops' depth range the sphere's instead of the
   scene's). Each frame the three masks are taken over that frame's
   G-buffer and the cached one compared with each by shadow class over the
   covered pixels.

   Scenarios, for STANDARD stable, PSSM-4 stable and LiSPSM (a warp that
   follows the camera: drawn whole whenever the camera moves, reused when
   it stops):
     walk     the camera walks 20 frames along the ground (static scene);
     dynamic  the mover, the dynamic casters (skgl_set_dynamic), crosses
              the view, its box their bounds;
     dynwhole the same without bounds (drawn over the whole map);
     static   box0, drawn by scene.draw, moves 6 frames; each move
              invalidates its old and its new box;
     light    the light turns a little every frame (drawn whole, by itself);
     appear   box3 disappears for 3 frames and comes back (its box
              invalidated each time);
     budget   PSSM-4 with cache_budget_kb for 2 layers: 2 cached, 2 drawn
              every frame, the walk again.
   RMSM (4096 virtual, 128-texel pages, sync_readback; analysed each frame)
   runs the same scenarios (its light: every page drawn, by itself), budget
   being the dynamic one with cache_budget_kb = 1 (no static copy of the
   pool: the pages the mover touches are drawn whole each frame), and
     pool     a 10 x 10 pool, fewer slots than the pages a frame asks
              for, the camera walking out and back: slots are taken back
              (least recently used) and evicted pages asked for again
              (196 evictions; with pages matched to the footprint's
              narrow side a 6 x 6 or 8 x 8 pool raises the finest level
              until every frame fits, and nothing is evicted).
   Point lights (cube and VSDCT, 256 a face, range 16, face and caster
   culling on, the light at (1.5, 4.5, 1)): walk (the camera every other
   frame of the walk: faces culled and back), dynamic, static, light (the
   light moves 5 cm a frame: every face drawn whole), appear.
   Spot lights (a 55 degree spot at the same place, axis (-0.3, -1, -0.2),
   512^2) run the point lights' scenarios; and test_spot_passes counts a
   cached spot's passes frame by frame (below).
   Also: verify_cache fails a render when a static caster moved without an
   invalidation (cube, VSDCT, spot), and the contracts (FERKO and layered
   refused, bad boxes, a cached spot in a shared atlas).

   Measured (Mesa 22.3 llvmpipe), pixels whose class differs from the
   twin's and from the .cache 0 light's, over all frames of a scenario: 0
   in every scenario and technique
   (the scrolled crops' texels land on the same samples: the shift is
   exact in float at these distances). Asserted: at most 0.001% of the
   covered pixels (the allowance for float rounding in a scrolled
   crop), every scenario, against both. Texels drawn after the first
   frame, cached / uncached: walk 0.004 (STANDARD) and 0.019 (PSSM-4),
   static 0.003 / 0.018, appear 0.0003 / 0.002; asserted below 0.35 on the
   walks (budget: 0.516, its two uncached cascades half of it by
   themselves; asserted below 0.5 + 0.35 / 2). Point lights, cube and
   VSDCT alike: walk 0 texels (every face reused), static 0.036, appear
   0.004 (asserted below 0.35). dynamic: 0.0004 (STANDARD), 0.002 (PSSM-4,
   LiSPSM), 0.008 (points), asserted below 0.1 (LiSPSM, whose warp may
   take the whole map, not asserted); dynwhole 0.5 (the dynamic pass
   counts its whole map).
   Can fail: SK_GL_TEST_NO_INVALIDATE=1 (the test makes no
   skgl_shadow_invalidate calls): static differs in 1.20% / 1.26% / 1.26%
   of the pixels, appear in 0.42% / 0.39% / 0.40% (6 checks fail). In a
   local copy of the header: skgl__cache_shift always "the same map": walk
   5.24% / 5.35% / 52.0%, light 33.3% / 43.5% / 2.2%, budget 0.82% (13
   checks); point lights: static 1.79% / 1.78% (4 checks); the light's
   position left out of the point cache's key: light 1.22% / 1.24% (6
   checks); no copy of the cache under the dynamic casters: dynamic 90.1%
   / 90.0% / 89.0% from the .cache 0 light (3 checks; the twin shares the
   fault, hence the second comparison); last frame's dynamic rectangle not
   copied back: dynamic and dynwhole 0.57% / 0.61% / 0.61%, points 1.44%
   (20 checks).
   Spots: 0 pixels differ in every scenario; texels after frame 0 cached /
   uncached: walk 0 (the view sees the whole cone: the window stays, the
   map is reused on all 11 frames), dynamic 0.019, static 0.144, appear 0
   (box3 is outside the cone: no region drawn), light 1.0. Passes
   (test_spot_passes): frame 0 one pass of 512^2 texels; 3 still frames 0
   passes, 0 texels (the uncached spot 1 pass, 262,144 texels each);
   box0 invalidated: 1 pass, 1 region, 17,550 texels (0.067 of the map);
   NULL, a moved light (5 cm) or a turned one: 1 pass, the whole map; the
   mover as the dynamic casters: 1 pass, 3,770 texels (0.014). Can fail:
   the light matrix left out of the spot cache's key (a local copy):
   light 0.644% differ from the twin and the .cache 0 spot, maps reused,
   and the moved and turned frames keep the map (5 checks fail).
   RMSM: 0 pixels differ in every scenario (a page is drawn with the same
   matrix cached or not, relative to the virtual map's own origin). Page
   texels drawn after frame 0, cached / uncached: walk 0.051, dynamic
   0.012, static 0.206, appear 0.095, budget 0.143, pool 0.030 (6 pages
   evicted), dynwhole 0.500, light 1.0; asserted below 0.35 but for
   dynwhole and light. Can fail: SK_GL_TEST_NO_INVALIDATE=1, static 1.20%
   and appear 0.39%; in a local copy, the dynamic pages not restored
   (dynamic, dynwhole, budget 0.57%), an evicted page left in the
   residency map (pool 2.11%), the virtual frustum left out of the key
   (light 28.9%).

   HYGIENE. Under the sanitizers (build/hygiene/, __SANITIZE_ADDRESS__)
   the walks take 10 frames (the first half of the path; the pool goes out
   to the same 40th camera and back in steps of 4), the point lights' walk
   6 and the other scenarios 6 (box0 still moves 5 times, box3 still comes
   back in the last): measured with gcov, the same 2830 lines of
   shadowkit_gl.h as 20 and 8 frames (none fewer, none more), in 38 CPU s
   instead of 60; its checks 1836 instead of 2510, the same ones, once per
   frame fewer. */
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "sk_test.h"
#include "gl_test_util.h"

#define W 320
#define H 180
#define RES 1024
#define ALLOW_PCT 0.001   /* the allowance; measured 0 */
#define WALK_TEXELS_MAX 0.35
/* frames of a scenario: the walks (directional lights; the point lights'
   walk takes every other camera of it), the others. Under the sanitizers
   (HYGIENE above) half the walks and 6 frames, over the same lines; the
   plain build keeps the figures' frames */
#ifdef __SANITIZE_ADDRESS__
#define WALK_FRAMES 10
#define STILL_FRAMES 6
#else
#define WALK_FRAMES 20
#define STILL_FRAMES 8
#endif

typedef gt_movers world;

static world W_;
static int no_invalidate;   /* SK_GL_TEST_NO_INVALIDATE set */

/* the mover as the dynamic casters, its box their bounds when `bounded` */
static void set_mover(world *w, int bounded) {
    skgl_dynamic dy;
    memset(&dy, 0, sizeof dy);
    dy.draw = gt_movers_draw_dynamic;
    dy.user = w;
    if (bounded) dy.bounds = gt_moved(w->e.scene.objects[w->mover].bounds, w->mover_at);
    SK_CHECK(skgl_set_dynamic(w->e.sk, &dy) == SK_OK);
}

static void invalidate(world *w, skgl_shadow *s, const sk_aabb *b) {
    if (no_invalidate) return;
    SK_CHECK(skgl_shadow_invalidate(w->e.sk, s, b) == SK_OK);
}

typedef enum { WALK, DYNAMIC, DYNWHOLE, STATIC, LIGHT, APPEAR, BUDGET, POOL, N_SCENARIOS } scenario;
static const char *scenario_name[N_SCENARIOS] = {"walk",  "dynamic", "dynwhole", "static",
                                                 "light", "appear",  "budget",   "pool"};

typedef struct tally {
    uint64_t differ, covered, differ_plain;
    double texels_cached, texels_twin;
    int scrolled, reused, full, regions, evicted;
} tally;

static skgl_camera walk_camera(int f) {
    float t = 0.23f * (float)f;
    return gt_camera(gt_v3(-9 + t, 6, 12 - 0.4f * t), gt_v3(t, 1, -0.4f * t), 0.9f, 0.5f, 60, W, H);
}

static int mask_of(world *w, skgl_shadow *s, const skgl_camera *cam, const skgl_scene *sc, sk_vec3 light,
                   float *out) {
    /* RMSM: this frame's page requests first (sync_readback: this frame's) */
    sk_result r = skgl_shadow_get_desc(s).technique == SKGL_RMSM
                      ? skgl_shadow_analyze(w->e.sk, s, cam, sc, light, w->e.gbuf.depth_tex)
                      : SK_OK;
    if (r == SK_OK) r = skgl_shadow_render(w->e.sk, s, cam, sc, light);
    if (r != SK_OK) {
        SK_CHECK_MSG(0, "skgl_shadow_render: %s (%s)", sk_result_string(r), skgl_error_log(w->e.sk));
        return -1;
    }
    return gt_mask_only(&w->e, s, cam, out);
}

static tally run(world *w, skgl_technique tech, scenario sc_kind) {
    skgl_shadow_desc d;
    skgl_shadow *cached, *twin, *plain;
    float *a = gt_alloc(&w->e), *b = gt_alloc(&w->e), *c = gt_alloc(&w->e);
    tally t;
    int walk = sc_kind == WALK || sc_kind == POOL || (sc_kind == BUDGET && tech != SKGL_RMSM);
    int moving = sc_kind == DYNAMIC || sc_kind == DYNWHOLE || (sc_kind == BUDGET && tech == SKGL_RMSM);
    int f, frames = walk ? WALK_FRAMES : STILL_FRAMES;
    skgl_scene sc = gt_movers_scene(w);
    const sk_aabb box0 = w->e.scene.objects[w->box0].bounds, box3 = w->e.scene.objects[w->box3].bounds;
    memset(&t, 0, sizeof t);
    memset(&d, 0, sizeof d);
    d.technique = tech;
    d.resolution = RES;
    d.stable = tech != SKGL_LISPSM;
    d.cascades = tech == SKGL_PSSM ? 4 : 1;
    d.max_distance = 40;
    d.cache = 1;
    if (sc_kind == BUDGET) d.cache_budget_kb = 2 * RES * RES * 4 / 1024;
    if (tech == SKGL_RMSM) {
        /* 4096 virtual, 128-texel pages: 32 a side at the finest level;
           budget: no room for the static copy under the dynamic casters;
           pool: 10 x 10 slots, fewer than the pages a frame asks for
           (the finest level rises), so the pages change as the walk
           goes and slots are taken back; the finer bands in 50 slots for
           the .cache 0 light too, the half a cached light keeps to itself
           by default (skgl__rmsm_band_cap): with the whole pool the
           uncached light takes a band capped in world size where the
           cached one has no room for it (109 pixels differ, 0.015%) */
        d.resolution = 4 * RES;
        d.sync_readback = 1;
        d.cache_budget_kb = sc_kind == BUDGET ? 1 : 0;
        if (sc_kind == POOL) {
            d.rmsm_pool_pages = 10;
            d.rmsm_band_pages = 50;
        }
    }
    cached = gt_shadow(&w->e, &d);
    twin = gt_shadow(&w->e, &d);
    d.cache = 0;
    d.cache_budget_kb = 0;
    /* a cached stable light fits spheres (STABLE CROPS); the same fit uncached */
    d.stable_sphere = d.stable;
    plain = gt_shadow(&w->e, &d);
    w->mover_at = gt_v3(-6, 0, -6);
    w->box0_shift = gt_v3(0, 0, 0);
    w->box3_hidden = 0;
    if (!cached || !twin || !plain || !a || !b || !c) goto done;
    if (sc_kind == BUDGET && tech != SKGL_RMSM)
        SK_CHECK_MSG(skgl_shadow_stats(cached)->cache_layers == 2, "budget: %d layers cached",
                     skgl_shadow_stats(cached)->cache_layers);
    for (f = 0; f < frames; f++) {
        /* pool: out to the walk's 40th camera and back, so that evicted
           pages are asked for again */
        int step = 40 / WALK_FRAMES;
        skgl_camera cam = !walk ? walk_camera(3)
                                : sc_kind == POOL ? walk_camera(step * (f <= WALK_FRAMES / 2 ? f : WALK_FRAMES - f))
                                                  : walk_camera(f);
        sk_vec3 light = gt_v3(-0.5f, -1, -0.35f);
        gt_agreement g;
        if (sc_kind == LIGHT) light = gt_v3(-0.5f + 0.01f * (float)f, -1, -0.35f + 0.007f * (float)f);
        if (f > 0 && moving) w->mover_at = gt_v3(-6 + 1.7f * (float)f, 0, -6 + 1.5f * (float)f);
        if (moving) set_mover(w, sc_kind != DYNWHOLE);
        if (f > 0 && sc_kind == STATIC) {
            sk_vec3 was = w->box0_shift, now = gt_v3(0.35f * (float)f, 0, 0.2f * (float)f);
            sk_aabb ob = gt_moved(box0, was), nb = gt_moved(box0, now);
            invalidate(w, cached, &ob);
            invalidate(w, cached, &nb);
            w->box0_shift = now;
        }
        if (sc_kind == APPEAR && (f == 2 || f == 5)) {
            w->box3_hidden = f == 2;
            invalidate(w, cached, &box3);
        }
        SK_CHECK(gt_gbuffer(&w->e, &cam) == 0);
        SK_CHECK(skgl_shadow_invalidate(w->e.sk, twin, NULL) == SK_OK);
        if (mask_of(w, cached, &cam, &sc, light, a) || mask_of(w, twin, &cam, &sc, light, b)) break;
        {
            const skgl_shadow_frame_stats *cs = skgl_shadow_stats(cached), *ts = skgl_shadow_stats(twin);
            if (f > 0) {   /* the first frame draws everything in both */
                t.texels_cached += cs->texels;
                t.texels_twin += ts->texels;
            }
            t.scrolled += cs->cache_scrolled;
            t.reused += cs->cache_reused;
            t.full += cs->cache_full;
            t.regions += cs->cache_regions;
            t.evicted += cs->pages_evicted;
            if (tech == SKGL_RMSM) {
                t.reused += cs->pages_reused;
                SK_CHECK(ts->pages_reused == 0 && ts->pages_rendered == ts->pages_resident);
                SK_CHECK(cs->pages_resident >= cs->pages_rendered);
                SK_CHECK(cs->cache_bytes == (sc_kind == BUDGET || !moving ? 0.0
                                             : 4.0 * cs->map_width * cs->map_height));
            } else SK_CHECK(ts->cache_full == ts->maps || ts->cache_layers < ts->maps);
        }
        g = gt_agree(a, b, w->e.n);
        t.differ += g.differ;
        t.covered += g.both;
        SK_CHECK(mask_of(w, plain, &cam, &sc, light, c) == 0);
        t.differ_plain += gt_agree(a, c, w->e.n).differ;
    }
done:
    SK_CHECK(skgl_set_dynamic(w->e.sk, NULL) == SK_OK);
    free(a); free(b); free(c);
    skgl_shadow_destroy(w->e.sk, cached);
    skgl_shadow_destroy(w->e.sk, twin);
    skgl_shadow_destroy(w->e.sk, plain);
    w->mover_at = gt_v3(-6, 0, -6);
    w->box0_shift = gt_v3(0, 0, 0);
    w->box3_hidden = 0;
    return t;
}

static void test_cached_equals_uncached(void) {
    static const skgl_technique techs[4] = {SKGL_STANDARD, SKGL_PSSM, SKGL_LISPSM, SKGL_RMSM};
    static const char *names[4] = {"standard-stable", "pssm4-stable", "lispsm", "rmsm"};
    world *w = &W_;
    int ti, k;
    for (ti = 0; ti < 4; ti++)
        for (k = 0; k < N_SCENARIOS; k++) {
            tally t;
            double pct;
            int rmsm = techs[ti] == SKGL_RMSM;
            if (k == BUDGET && techs[ti] != SKGL_PSSM && !rmsm) continue;
            if (k == POOL && !rmsm) continue;
            t = run(w, techs[ti], (scenario)k);
            pct = t.covered ? 100.0 * (double)t.differ / (double)t.covered : 100.0;
            printf("%-16s %-8s differ %llu of %llu (%.5f%%), from .cache 0 %llu; %s: full %d "
                   "scrolled %d reused %d, regions %d, evicted %d; texels after frame 0 cached/uncached "
                   "%.0f/%.0f = %.3f\n",
                   names[ti], scenario_name[k], (unsigned long long)t.differ, (unsigned long long)t.covered, pct,
                   (unsigned long long)t.differ_plain, rmsm ? "pages" : "cached layers", t.full, t.scrolled,
                   t.reused, t.regions, t.evicted, t.texels_cached, t.texels_twin,
                   t.texels_twin > 0 ? t.texels_cached / t.texels_twin : 0.0);
            SK_CHECK(t.covered > 0);
            SK_CHECK_MSG(pct <= ALLOW_PCT, "%s %s: %.5f%% of the pixels differ from the uncached mask", names[ti],
                         scenario_name[k], pct);
            pct = t.covered ? 100.0 * (double)t.differ_plain / (double)t.covered : 100.0;
            SK_CHECK_MSG(pct <= ALLOW_PCT, "%s %s: %.5f%% of the pixels differ from the .cache 0 light's mask",
                         names[ti], scenario_name[k], pct);
            if (rmsm) {
                /* pages reused along the walk; a pool of 16 evicts; a light
                   that turns draws every page */
                if (k == LIGHT) SK_CHECK(t.reused == 0);
                else SK_CHECK(t.reused > 0);
                if (k == POOL) SK_CHECK_MSG(t.evicted > 0, "rmsm pool: nothing evicted");
                else SK_CHECK(t.evicted == 0 || k == LIGHT);
                if (k == WALK || k == STATIC || k == APPEAR || k == DYNAMIC || k == BUDGET)
                    SK_CHECK_MSG(t.texels_cached < WALK_TEXELS_MAX * t.texels_twin, "rmsm %s: %.0f texels, "
                                 "uncached %.0f", scenario_name[k], t.texels_cached, t.texels_twin);
                if (k == STATIC || k == APPEAR) SK_CHECK(no_invalidate || t.regions > 0);
                continue;
            }
            /* the cache did its work: a stable walk scrolls, a still camera reuses */
            if ((k == WALK || k == BUDGET) && techs[ti] != SKGL_LISPSM) {
                /* the budget's two uncached cascades are half the texels by themselves */
                double bound = k == BUDGET ? 0.5 + WALK_TEXELS_MAX * 0.5 : WALK_TEXELS_MAX;
                SK_CHECK_MSG(t.scrolled > 0, "%s %s: no layer scrolled", names[ti], scenario_name[k]);
                SK_CHECK_MSG(t.texels_cached < bound * t.texels_twin, "%s %s: %.0f texels drawn, uncached %.0f",
                             names[ti], scenario_name[k], t.texels_cached, t.texels_twin);
            }
            if (k == DYNAMIC || k == DYNWHOLE || k == STATIC || k == APPEAR) SK_CHECK(t.reused > 0);
            /* the mover's rectangle alone, its last one restored */
            if (k == DYNAMIC && techs[ti] != SKGL_LISPSM)
                SK_CHECK_MSG(t.texels_cached < 0.1 * t.texels_twin, "%s dynamic: %.0f texels, uncached %.0f",
                             names[ti], t.texels_cached, t.texels_twin);
            if (k == STATIC || k == APPEAR) SK_CHECK(no_invalidate || t.regions > 0);
            if (k == LIGHT) SK_CHECK(t.reused == 0);
        }
}

/* ---- point lights: the cube and VSDCT ---- */
/* a spot light's direction (the spots' scenarios) */
#define SPOT_ANGLE 55.0f
static sk_vec3 spot_dir(void) { return gt_v3(-0.3f, -1, -0.2f); }

/* a point light's render, or a spot's (desc.spot_angle) down spot_dir() */
static sk_result point_render(world *w, skgl_point *p, const skgl_camera *cam, const skgl_scene *sc, sk_vec3 pos) {
    return skgl_point_get_desc(p).spot_angle > 0.0f ? skgl_spot_render(w->e.sk, p, cam, sc, pos, spot_dir())
                                                    : skgl_point_render(w->e.sk, p, cam, sc, pos);
}

static int point_mask_of(world *w, skgl_point *p, const skgl_camera *cam, const skgl_scene *sc, sk_vec3 pos,
                         float *out) {
    size_t i;
    sk_result r = point_render(w, p, cam, sc, pos);
    if (r == SK_OK) r = skgl_point_mask(w->e.sk, p, cam, w->e.gbuf.depth_tex, w->e.gbuf.color_tex, w->e.mask.color_tex);
    if (r != SK_OK) {
        SK_CHECK_MSG(0, "point: %s (%s)", sk_result_string(r), skgl_error_log(w->e.sk));
        return -1;
    }
    if (tb_gl_read_texture_red(&w->e.gl, w->e.mask.color_tex, w->e.w, w->e.h, out) != 0) return -1;
    for (i = 0; i < w->e.n; i++) if (!(w->e.depth[i] < 1.0f)) out[i] = -1.0f;
    return 0;
}

/* kind 0 cube, 1 VSDCT, 2 a spot (SPOT_ANGLE, a 512 map) */
static skgl_point *point_light(world *w, int kind, int cache) {
    skgl_point_desc d;
    skgl_point *p = NULL;
    sk_result r;
    memset(&d, 0, sizeof d);
    d.technique = kind == 0 ? SKGL_POINT_CUBE : SKGL_POINT_VSDCT;
    d.spot_angle = kind == 2 ? SPOT_ANGLE : 0.0f;
    d.resolution = kind == 2 ? 512 : 256;
    d.range = 16;
    d.cull_faces = 1;
    d.cull_casters = 1;
    d.cache = cache;
    gt_point_bias(&d);
    r = skgl_point_create(w->e.sk, &d, &p);
    SK_CHECK_MSG(r == SK_OK, "skgl_point_create: %s (%s)", sk_result_string(r), skgl_error_log(w->e.sk));
    return p;
}

static tally run_point(world *w, int kind, scenario sc_kind) {
    skgl_point *cached = point_light(w, kind, 1), *twin = point_light(w, kind, 1), *plain = point_light(w, kind, 0);
    float *a = gt_alloc(&w->e), *b = gt_alloc(&w->e), *c = gt_alloc(&w->e);
    tally t;
    int f, frames = sc_kind == WALK ? WALK_FRAMES * 3 / 5 : STILL_FRAMES;
    skgl_scene sc = gt_movers_scene(w);
    const sk_aabb box0 = w->e.scene.objects[w->box0].bounds, box3 = w->e.scene.objects[w->box3].bounds;
    memset(&t, 0, sizeof t);
    if (!cached || !twin || !plain || !a || !b || !c) goto done;
    for (f = 0; f < frames; f++) {
        skgl_camera cam = sc_kind == WALK ? walk_camera(2 * f) : walk_camera(3);
        sk_vec3 pos = gt_v3(1.5f, 4.5f, 1.0f);
        gt_agreement g;
        if (sc_kind == LIGHT) pos = gt_v3(1.5f + 0.05f * (float)f, 4.5f, 1.0f);
        if (f > 0 && (sc_kind == DYNAMIC || sc_kind == DYNWHOLE))
            w->mover_at = gt_v3(-6 + 1.7f * (float)f, 0, -6 + 1.5f * (float)f);
        if (sc_kind == DYNAMIC || sc_kind == DYNWHOLE) set_mover(w, sc_kind == DYNAMIC);
        if (f > 0 && sc_kind == STATIC) {
            sk_vec3 now = gt_v3(0.35f * (float)f, 0, 0.2f * (float)f);
            sk_aabb ob = gt_moved(box0, w->box0_shift), nb = gt_moved(box0, now);
            if (!no_invalidate) {
                SK_CHECK(skgl_point_invalidate(w->e.sk, cached, &ob) == SK_OK);
                SK_CHECK(skgl_point_invalidate(w->e.sk, cached, &nb) == SK_OK);
            }
            w->box0_shift = now;
        }
        if (sc_kind == APPEAR && (f == 2 || f == 5)) {
            w->box3_hidden = f == 2;
            if (!no_invalidate) SK_CHECK(skgl_point_invalidate(w->e.sk, cached, &box3) == SK_OK);
        }
        SK_CHECK(gt_gbuffer(&w->e, &cam) == 0);
        SK_CHECK(skgl_point_invalidate(w->e.sk, twin, NULL) == SK_OK);
        if (point_mask_of(w, cached, &cam, &sc, pos, a) || point_mask_of(w, twin, &cam, &sc, pos, b) ||
            point_mask_of(w, plain, &cam, &sc, pos, c))
            break;
        if (f > 0) {
            t.texels_cached += skgl_point_stats(cached)->texels;
            t.texels_twin += skgl_point_stats(twin)->texels;
        }
        t.reused += skgl_point_stats(cached)->faces_reused;
        t.regions += skgl_point_stats(cached)->cache_regions;
        SK_CHECK(skgl_point_stats(twin)->faces_reused == 0);
        g = gt_agree(a, b, w->e.n);
        t.differ += g.differ;
        t.covered += g.both;
        t.differ_plain += gt_agree(a, c, w->e.n).differ;
    }
done:
    SK_CHECK(skgl_set_dynamic(w->e.sk, NULL) == SK_OK);
    free(a); free(b); free(c);
    skgl_point_destroy(w->e.sk, cached);
    skgl_point_destroy(w->e.sk, twin);
    skgl_point_destroy(w->e.sk, plain);
    w->mover_at = gt_v3(-6, 0, -6);
    w->box0_shift = gt_v3(0, 0, 0);
    w->box3_hidden = 0;
    return t;
}

static void test_point_cached_equals_uncached(void) {
    world *w = &W_;
    static const char *const names[3] = {"point-cube", "point-vsdct", "spot"};
    int ti, k;
    for (ti = 0; ti < 3; ti++)
        for (k = 0; k < BUDGET; k++) {
            const char *name = names[ti];
            tally t = run_point(w, ti, (scenario)k);
            double pct = t.covered ? 100.0 * (double)t.differ / (double)t.covered : 100.0;
            double pct_plain = t.covered ? 100.0 * (double)t.differ_plain / (double)t.covered : 100.0;
            printf("%-16s %-8s differ %llu of %llu (%.5f%%), from .cache 0 %llu; faces reused %d, regions %d; "
                   "texels after frame 0 cached/uncached %.0f/%.0f = %.3f\n",
                   name, scenario_name[k], (unsigned long long)t.differ, (unsigned long long)t.covered, pct,
                   (unsigned long long)t.differ_plain, t.reused, t.regions, t.texels_cached, t.texels_twin,
                   t.texels_twin > 0 ? t.texels_cached / t.texels_twin : 0.0);
            SK_CHECK(t.covered > 0);
            SK_CHECK_MSG(pct <= ALLOW_PCT, "%s %s: %.5f%% differ from the uncached mask", name, scenario_name[k], pct);
            SK_CHECK_MSG(pct_plain <= ALLOW_PCT, "%s %s: %.5f%% differ from the .cache 0 light's mask", name,
                         scenario_name[k], pct_plain);
            if (k == LIGHT) SK_CHECK(t.reused == 0);
            else SK_CHECK(t.reused > 0);
            if (k == WALK || k == DYNAMIC || k == STATIC || k == APPEAR)
                SK_CHECK_MSG(t.texels_cached < WALK_TEXELS_MAX * t.texels_twin, "%s %s: %.0f texels, uncached %.0f",
                             name, scenario_name[k], t.texels_cached, t.texels_twin);
        }
}

/* a cached light under verify_cache: a shadow (s, lit from direction
   `light`) or a point light (p, at `light`) */
typedef struct verified {
    skgl_shadow *s;
    skgl_point *p;
    sk_vec3 light;
} verified;

static sk_result verified_render(world *w, const verified *v, const skgl_camera *cam, const skgl_scene *sc) {
    return v->s ? skgl_shadow_render(w->e.sk, v->s, cam, sc, v->light) : point_render(w, v->p, cam, sc, v->light);
}
static int verified_texels(const verified *v) {
    return v->s ? skgl_shadow_stats(v->s)->cache_verify_texels : skgl_point_stats(v->p)->cache_verify_texels;
}
static sk_result verified_invalidate(world *w, const verified *v, const sk_aabb *b) {
    return v->s ? skgl_shadow_invalidate(w->e.sk, v->s, b) : skgl_point_invalidate(w->e.sk, v->p, b);
}

/* box0 moved without an invalidation: the render fails naming the
   invalidate call, over 100 texels differing; with box0's old and new
   boxes invalidated it passes again. box0 is put back. */
static void check_unannounced_move(world *w, const verified *v, const skgl_camera *cam, const skgl_scene *sc,
                                   const char *label) {
    sk_result r;
    w->box0_shift = gt_v3(1.5f, 0, 0);   /* no invalidation */
    r = verified_render(w, v, cam, sc);
    printf("%s, a static caster moved unannounced: %s, %d texels differ (%s)\n", label, sk_result_string(r),
           verified_texels(v), skgl_error_log(w->e.sk));
    SK_CHECK(r == SK_ERR_INVALID_ARG);
    SK_CHECK(verified_texels(v) > 100);
    SK_CHECK(strstr(skgl_error_log(w->e.sk), v->s ? "skgl_shadow_invalidate" : "skgl_point_invalidate") != NULL);
    {
        sk_aabb b0 = w->e.scene.objects[w->box0].bounds, b1 = gt_moved(b0, w->box0_shift);
        SK_CHECK(verified_invalidate(w, v, &b0) == SK_OK);
        SK_CHECK(verified_invalidate(w, v, &b1) == SK_OK);
    }
    SK_CHECK(verified_render(w, v, cam, sc) == SK_OK);
    SK_CHECK(verified_texels(v) == 0);
    w->box0_shift = gt_v3(0, 0, 0);
}

/* verify_cache catches a static caster moved without an invalidation */
static void test_verify(void) {
    world *w = &W_;
    skgl_shadow_desc d;
    skgl_shadow *s;
    skgl_scene sc = gt_movers_scene(w);
    skgl_camera cam = walk_camera(3);
    sk_vec3 light = gt_v3(-0.5f, -1, -0.35f);
    verified v;
    memset(&v, 0, sizeof v);
    memset(&d, 0, sizeof d);
    d.resolution = 512;
    d.stable = 1;
    d.cache = 1;
    d.verify_cache = 1;
    s = gt_shadow(&w->e, &d);
    if (!s) return;
    SK_CHECK(skgl_shadow_render(w->e.sk, s, &cam, &sc, light) == SK_OK);
    SK_CHECK(skgl_shadow_stats(s)->cache_verify_texels == 0);
    v.s = s;
    v.light = light;
    check_unannounced_move(w, &v, &cam, &sc, "verify_cache");
    skgl_shadow_destroy(w->e.sk, s);
}

/* verify_cache of a point light (cube, VSDCT) and a spot: correct use
   passes, a static caster moved without skgl_point_invalidate fails naming it */
static void test_point_verify(void) {
    world *w = &W_;
    skgl_scene sc = gt_movers_scene(w);
    skgl_camera cam = walk_camera(3);
    sk_vec3 pos = gt_v3(1.5f, 4.5f, 1.0f);
    static const char *const labels[3] = {"point verify_cache (cube)", "point verify_cache (vsdct)",
                                          "spot verify_cache"};
    int ti;
    for (ti = 0; ti < 3; ti++) {
        skgl_point_desc d;
        skgl_point *p = NULL;
        sk_result r;
        verified v;
        memset(&d, 0, sizeof d);
        d.technique = ti ? SKGL_POINT_VSDCT : SKGL_POINT_CUBE;
        d.spot_angle = ti == 2 ? SPOT_ANGLE : 0.0f;
        d.resolution = 256;
        d.range = 16;
        d.verify_cache = 1;
        SK_CHECK(skgl_point_create(w->e.sk, &d, &p) == SK_ERR_INVALID_ARG && p == NULL);   /* without .cache */
        SK_CHECK(strstr(skgl_error_log(w->e.sk), "verify_cache") != NULL);
        d.cache = 1;
        r = skgl_point_create(w->e.sk, &d, &p);
        SK_CHECK_MSG(r == SK_OK, "skgl_point_create: %s (%s)", sk_result_string(r), skgl_error_log(w->e.sk));
        if (r != SK_OK) continue;
        SK_CHECK(skgl_point_stats(p)->cache_verify_texels == -1);
        SK_CHECK(point_render(w, p, &cam, &sc, pos) == SK_OK);
        SK_CHECK(skgl_point_stats(p)->cache_verify_texels == 0);
        SK_CHECK(point_render(w, p, &cam, &sc, pos) == SK_OK);   /* every face kept */
        SK_CHECK(skgl_point_stats(p)->faces_reused > 0 && skgl_point_stats(p)->cache_verify_texels == 0);
        memset(&v, 0, sizeof v);
        v.p = p;
        v.light = pos;
        check_unannounced_move(w, &v, &cam, &sc, labels[ti]);
        skgl_point_destroy(w->e.sk, p);
    }
}

/* A cached spot's passes frame by frame (stats: callbacks made, texels
   drawn, map reused, regions): drawn once, then not at all while nothing
   changes; an invalidated box redraws its rectangle, NULL the whole map; a
   light that moves or turns draws it whole; the dynamic casters alone
   each frame they are set. The uncached spot draws its one pass every
   frame. */
typedef struct spot_frame {
    int passes, reused, regions;
    double texels;
} spot_frame;

static spot_frame spot_frame_of(world *w, skgl_point *p, const skgl_camera *cam, const skgl_scene *sc, sk_vec3 pos,
                                sk_vec3 dir) {
    spot_frame f;
    const skgl_point_frame_stats *st = skgl_point_stats(p);
    sk_result r = skgl_spot_render(w->e.sk, p, cam, sc, pos, dir);
    SK_CHECK_MSG(r == SK_OK, "skgl_spot_render: %s (%s)", sk_result_string(r), skgl_error_log(w->e.sk));
    f.passes = st->passes;
    f.reused = st->faces_reused;
    f.regions = st->cache_regions;
    f.texels = st->texels;
    return f;
}

static void test_spot_passes(void) {
    world *w = &W_;
    skgl_scene sc = gt_movers_scene(w);
    skgl_camera cam = walk_camera(3);
    skgl_point *p = point_light(w, 2, 1), *plain = point_light(w, 2, 0);
    sk_vec3 pos = gt_v3(1.5f, 4.5f, 1.0f), dir = spot_dir();
    const sk_aabb box0 = w->e.scene.objects[w->box0].bounds;
    const double whole = 512.0 * 512.0;
    spot_frame f;
    int k;
    if (!p || !plain) goto done;
    SK_CHECK(skgl_point_stats(p)->cache_bytes == whole * 4);
    f = spot_frame_of(w, p, &cam, &sc, pos, dir);
    printf("spot cache: frame 0: %d passes, %.0f texels\n", f.passes, f.texels);
    SK_CHECK(f.passes == 1 && f.reused == 0 && f.texels == whole);
    for (k = 1; k <= 3; k++) {   /* nothing changed: not drawn */
        f = spot_frame_of(w, p, &cam, &sc, pos, dir);
        SK_CHECK_MSG(f.passes == 0 && f.reused == 1 && f.texels == 0.0, "still frame %d: %d passes, %.0f texels",
                     k, f.passes, f.texels);
        f = spot_frame_of(w, plain, &cam, &sc, pos, dir);
        SK_CHECK(f.passes == 1 && f.texels == whole);
    }
    SK_CHECK(skgl_point_invalidate(w->e.sk, p, &box0) == SK_OK);
    f = spot_frame_of(w, p, &cam, &sc, pos, dir);
    printf("spot cache: box0 invalidated: %d passes, %d regions, %.0f texels (%.3f of the map)\n", f.passes,
           f.regions, f.texels, f.texels / whole);
    SK_CHECK(f.passes == 1 && f.regions == 1 && f.reused == 1 && f.texels > 0 && f.texels < 0.25 * whole);
    f = spot_frame_of(w, p, &cam, &sc, pos, dir);
    SK_CHECK(f.passes == 0);
    SK_CHECK(skgl_point_invalidate(w->e.sk, p, NULL) == SK_OK);
    f = spot_frame_of(w, p, &cam, &sc, pos, dir);
    SK_CHECK(f.passes == 1 && f.reused == 0 && f.texels == whole);
    pos.x += 0.05f;   /* moved */
    f = spot_frame_of(w, p, &cam, &sc, pos, dir);
    SK_CHECK(f.passes == 1 && f.reused == 0 && f.texels == whole);
    SK_CHECK(spot_frame_of(w, p, &cam, &sc, pos, dir).passes == 0);
    dir.x += 0.01f;   /* turned */
    f = spot_frame_of(w, p, &cam, &sc, pos, dir);
    SK_CHECK(f.passes == 1 && f.reused == 0 && f.texels == whole);
    /* the mover, in the cone, as the dynamic casters: drawn alone, in its rectangle */
    w->mover_at = gt_v3(0, 0, 0);
    set_mover(w, 1);
    f = spot_frame_of(w, p, &cam, &sc, pos, dir);
    printf("spot cache: the mover dynamic: %d passes, %.0f texels (%.3f of the map)\n", f.passes, f.texels,
           f.texels / whole);
    SK_CHECK(f.passes == 1 && f.reused == 1 && f.texels > 0 && f.texels < 0.25 * whole);
    SK_CHECK(skgl_set_dynamic(w->e.sk, NULL) == SK_OK);
    f = spot_frame_of(w, p, &cam, &sc, pos, dir);
    SK_CHECK(f.passes == 0 && f.reused == 1);
    /* the contract: not in a shared atlas */
    {
        skgl_point_atlas *a = NULL;
        skgl_point_desc d = skgl_point_get_desc(p);
        skgl_point *q = NULL;
        SK_CHECK(skgl_point_atlas_create(w->e.sk, 1024, 1024, &a) == SK_OK);
        d.atlas = a;
        SK_CHECK(skgl_point_create(w->e.sk, &d, &q) == SK_ERR_INVALID_ARG && q == NULL);
        SK_CHECK(strstr(skgl_error_log(w->e.sk), "cache") != NULL);
        skgl_point_atlas_destroy(w->e.sk, a);
    }
done:
    w->mover_at = gt_v3(-6, 0, -6);
    skgl_point_destroy(w->e.sk, p);
    skgl_point_destroy(w->e.sk, plain);
}

static void test_contracts(void) {
    world *w = &W_;
    skgl_shadow_desc d;
    skgl_shadow *s = NULL;
    sk_aabb bad = gt_box(1, 0, 0, 0, 1, 1);
    int k;
    for (k = 0; k < 2; k++) {
        memset(&d, 0, sizeof d);
        d.cache = 1;
        if (k == 0) d.technique = SKGL_FERKO;
        if (k == 1) { d.technique = SKGL_PSSM; d.layered = 1; }
        SK_CHECK(skgl_shadow_create(w->e.sk, &d, &s) == SK_ERR_INVALID_ARG && s == NULL);
        SK_CHECK(strstr(skgl_error_log(w->e.sk), "desc.cache") != NULL);
    }
    memset(&d, 0, sizeof d);
    d.verify_cache = 1;
    SK_CHECK(skgl_shadow_create(w->e.sk, &d, &s) == SK_ERR_INVALID_ARG);
    SK_CHECK(strstr(skgl_error_log(w->e.sk), "desc.verify_cache") != NULL);
    {
        skgl_dynamic dy;
        memset(&dy, 0, sizeof dy);
        SK_CHECK(skgl_set_dynamic(w->e.sk, &dy) == SK_ERR_INVALID_ARG);
        SK_CHECK(strstr(skgl_error_log(w->e.sk), "dyn->draw") != NULL);
        dy.draw = gt_movers_draw_dynamic;
        dy.bounds = bad;
        SK_CHECK(skgl_set_dynamic(w->e.sk, &dy) == SK_ERR_INVALID_ARG);
        SK_CHECK(strstr(skgl_error_log(w->e.sk), "dyn->bounds") != NULL);
        SK_CHECK(skgl_set_dynamic(NULL, &dy) == SK_ERR_INVALID_ARG);
    }
    d.verify_cache = 0;
    d.cache = 1;
    d.cache_budget_kb = -1;
    SK_CHECK(skgl_shadow_create(w->e.sk, &d, &s) == SK_ERR_INVALID_ARG);
    d.cache_budget_kb = 1;   /* less than one layer: nothing cached, drawn every frame */
    d.resolution = 256;
    SK_CHECK(skgl_shadow_create(w->e.sk, &d, &s) == SK_OK);
    if (s) {
        SK_CHECK(skgl_shadow_stats(s)->cache_layers == 0 && skgl_shadow_stats(s)->cache_bytes == 0);
        SK_CHECK(skgl_shadow_invalidate(w->e.sk, s, &bad) == SK_ERR_INVALID_ARG);
        SK_CHECK(strstr(skgl_error_log(w->e.sk), "box") != NULL);
        SK_CHECK(skgl_shadow_invalidate(w->e.sk, NULL, NULL) == SK_ERR_INVALID_ARG);
        SK_CHECK(skgl_shadow_invalidate(NULL, s, NULL) == SK_ERR_INVALID_ARG);
        skgl_shadow_destroy(w->e.sk, s);
    }
    s = NULL;
    d.cache_budget_kb = 0;
    SK_CHECK(skgl_shadow_create(w->e.sk, &d, &s) == SK_OK);
    if (s) {
        SK_CHECK(skgl_shadow_stats(s)->cache_layers == 1 && skgl_shadow_stats(s)->cache_bytes == 256.0 * 256 * 4);
        skgl_shadow_destroy(w->e.sk, s);
    }
}

static void test_cache(void) {
    world *w = &W_;
    const char *ni = getenv("SK_GL_TEST_NO_INVALIDATE");
    int objects;
    no_invalidate = ni && *ni && *ni != '0';
    if (gt_movers_init(w, W, H) != 0) return;
    /* the mover's room: the scene's bounds hold its whole path */
    w->e.scene.bounds = gt_box(-10, 0, -10, 10, 6, 10);
    gt_warm_programs(w->e.sk);
    objects = skgl_gl_object_count(w->e.sk);
    test_cached_equals_uncached();
    test_point_cached_equals_uncached();
    test_verify();
    test_point_verify();
    test_spot_passes();
    test_contracts();
    /* every light's cache, framebuffers and verify map freed */
    SK_CHECK_MSG(skgl_gl_object_count(w->e.sk) == objects, "%d GL objects, %d before",
                 skgl_gl_object_count(w->e.sk), objects);
    SK_CHECK(w->e.gl.GetError() == 0);
    gt_env_free(&w->e);
}

SK_TEST_MAIN(test_cache)
