/* test_gl_auto.c - SKGL_AUTO chooses one focused map or cascades from the
   view's depth range, and .fit_to_depth (sample distribution shadow maps,
   Lauritzen, Salvi and Lefohn 2011) splits over the depths the view holds.

   Scenes at both ends of the scale, every frame against the exact Embree
   reference, the shadow-area error pooled over the frames (the sums of
   wrong and of reference-shadow pixels):
     the open world (tb_scene.h: 2 km, a camera at head height, far plane
       1000 m), its 5 views x 3 suns (45 and 8 degrees behind the viewer,
       20 degrees across);
     small scenes (terrace, ground-boxes, fence), each seen from above
       (an overview 35 degrees up) and from low at one end (far plane
       well past the scene).

   test_auto_choice     AUTO's map count per frame: more than one in every
                        open-world frame, 1 on every small-scene overview, a
                        warped one on every low view; its pooled error
                        against standard 2048^2 and PSSM 4x1024^2 (the same
                        texels) on each kind of scene
   test_auto_front      AUTO's open-world error against PSSM 4x1024^2 at
                        lambda 0.9 (the bench's front there), each count's
                        crops fitted once
   test_auto_analysis_gate  the analysis re-run only when the camera moved
                        or turned, or every 8th frame
   test_fit_to_depth    PSSM 4x1024^2 with .fit_to_depth against without,
                        and STANDARD likewise on the low small-scene views
   test_stable_ratio    stable crops (texel-snapped, stepped sizes) at most
                        1.3x the focused crops' error on each kind of scene
   test_auto_hysteresis a camera rising slowly from the ground to 60 m over
                        a terrace: the count changes a few times, never back
                        and forth between two frames, and the stats say why
                        and AUTO's depth texture (stats.auto_bytes) holds
                        the count, is exactly its n layers of
                        floor(2048 / sqrt(n))^2 once a count has been kept
                        30 renders, and is resized at most twice a change:
                        measured rising 3 changes, 4 resizes, 16 MiB at the
                        end (one 2048^2 map; 64 MiB before, 4 x 2048^2
                        whatever the count); bobbing 0 and 0. Broken on
                        purpose: the texture never shrinking
                        (SKGL__AUTO_SHRINK 1000000) fails from frame 60,
                        "1 maps kept 30 renders, 67108864 bytes, 16777216
                        needed"
   (test_gl_calls counts AUTO's GL calls and stalls without
   .sync_readback: FERKO's analysis and ring, no stall.)

   Measured (Mesa 22.3 llvmpipe, 320x180), pooled shadow-area error %,
   AUTO's map counts:
                        open world  overviews  low views
     standard 2048        12.53       6.40       5.99
     standard 2048 fit    11.28       6.40       6.07
     pssm 4x1024           1.77      18.51       7.36
     pssm 4x1024 fit       1.03      16.78       6.78
     (fit, lambda 0.75     1.70      15.92       6.49, before the log splits)
     auto 2048^2           1.12       6.06       3.04
     (auto, focused only   1.03       6.40       5.90, .disable_auto_warp)
     (auto, lambda 0.75    1.69       6.40       5.86, before the log splits)
     pssm 4x1024 l0.9      1.02      18.69       7.94
     standard 2048 stable 13.87       5.54       6.57
     pssm 4x1024 stable    1.80      15.57       7.11
     AUTO's maps           4 (10/15)  1 (3/3)    1 (3/3)
                           2 (5/15)
     warped (LiSPSM)       14/15      1/3        3/3
   At lambda 0.75 the depth-buffer fit gained little at a kilometre (the
   nearest receiver, the ground 2.7 m ahead, is near the near plane; the
   uniform term set most splits): with the log splits it takes over an
   analysed range it gains 42% there and 9% on the overviews, whose
   receivers start tens of metres away. Broken on purpose: AUTO with its count fixed at 4
   (overviews 15.92%, 0 of 3 frames with one map) fails the choice checks;
   without the hysteresis (always the newest pick) the bobbing camera
   below changes count 14 times.

   SK_GL_TEST_SURVEY=1 prints every frame. */
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "sk_test.h"
#include "gl_test_util.h"

#include <math.h>
#include <stdio.h>

#define W 320
#define H 180
#define FOVY 1.0471976f   /* 60 degrees */

static int verbose(void) {
    const char *v = getenv("SK_GL_TEST_SURVEY");
    return v && *v && *v != '0';
}

/* pooled counts of one method */
typedef struct pool {
    double wrong, shadow;
    int frames, failed, maps_hist[SKGL_MAX_CASCADES + 1];
    int warped;                 /* AUTO: frames it chose warped maps (SKGL_LISPSM) */
    int crops_min, crops_max;   /* AUTO: stats.auto_crops over the frames */
} pool;

static double pool_pct(const pool *p) { return p->shadow > 0 ? 100.0 * p->wrong / p->shadow : 0.0; }

/* one method of the comparison */
typedef struct method {
    const char *name;
    skgl_technique technique;
    int resolution, cascades, fit_to_depth, stable;
} method;

static const method methods[] = {
    {"standard 2048", SKGL_STANDARD, 2048, 1, 0, 0},
    {"standard 2048 fit", SKGL_STANDARD, 2048, 1, 1, 0},
    {"pssm 4x1024", SKGL_PSSM, 1024, 4, 0, 0},
    {"pssm 4x1024 fit", SKGL_PSSM, 1024, 4, 1, 0},
    {"auto 2048^2", SKGL_AUTO, 2048, 4, 0, 0},
    {"standard 2048 stable", SKGL_STANDARD, 2048, 1, 0, 1},
    {"pssm 4x1024 stable", SKGL_PSSM, 1024, 4, 0, 1},
    {"pssm 4x1024 l0.9", SKGL_PSSM, 1024, 4, 0, 0},
    {"auto focused only", SKGL_AUTO, 2048, 4, 0, 0},
};
enum { M_STD, M_STD_FIT, M_PSSM, M_PSSM_FIT, M_AUTO, M_STD_STABLE, M_PSSM_STABLE, M_PSSM_09, M_AUTO_FOCUSED, METHODS };

static int analyzes(const method *m) { return m->fit_to_depth || m->technique == SKGL_AUTO; }

static skgl_shadow_desc method_desc(const method *m) {
    skgl_shadow_desc d = gt_shadow_desc(m->technique, m->resolution, m->cascades, m->stable);
    d.fit_to_depth = m->fit_to_depth;
    d.sync_readback = 1;
    if (m == &methods[M_PSSM_09]) d.lambda = 0.9f;
    d.disable_auto_warp = m == &methods[M_AUTO_FOCUSED];
    return d;
}

/* analysis (where the light has one), render, mask; 0 ok */
static int frame(gt_env *e, skgl_shadow *s, const method *m, const skgl_camera *cam, sk_vec3 light, float *vis) {
    skgl_scene sc = gt_scene(e);
    if (analyzes(m) && skgl_shadow_analyze(e->sk, s, cam, &sc, light, e->gbuf.depth_tex) != SK_OK) {
        printf("analyze: %s\n", skgl_error_log(e->sk));
        return -1;
    }
    return gt_mask(e, s, cam, light, vis);
}

static void pool_frame(pool *p, const gt_env *e, const float *ref, const float *res, const skgl_shadow *s) {
    tb_shadow_error se = gt_shadow_error(e, ref, res);
    int maps = skgl_shadow_stats(s)->maps;
    p->wrong += (double)se.wrong;
    p->shadow += (double)se.shadow;
    int crops = skgl_shadow_stats(s)->auto_crops;
    if (!p->frames || crops < p->crops_min) p->crops_min = crops;
    if (!p->frames || crops > p->crops_max) p->crops_max = crops;
    p->frames++;
    if (maps >= 0 && maps <= SKGL_MAX_CASCADES) p->maps_hist[maps]++;
    p->warped += skgl_shadow_get_desc(s).technique == SKGL_AUTO && skgl_shadow_stats(s)->auto_technique == SKGL_LISPSM;
}

/* every method over the frames of one scene; pools[METHODS] */
typedef struct view { sk_vec3 eye, target, light; float zn, zf; } view;

static void run_views(gt_env *e, const view *v, int nv, pool *pools, const char *label) {
    skgl_shadow *sh[METHODS];
    float *ref = gt_alloc(e), *res = gt_alloc(e);
    int i, k;
    for (k = 0; k < METHODS; k++) {
        skgl_shadow_desc d = method_desc(&methods[k]);
        sh[k] = gt_shadow(e, &d);
        SK_CHECK_MSG(sh[k] != NULL, "%s: create", methods[k].name);
    }
    for (i = 0; i < nv; i++) {
        skgl_camera cam = gt_camera(v[i].eye, v[i].target, FOVY, v[i].zn, v[i].zf, W, H);
        if (gt_gbuffer(e, &cam) != 0 || gt_reference(e, v[i].light, ref) != 0) {
            SK_CHECK_MSG(0, "%s view %d: G-buffer or reference", label, i);
            continue;
        }
        if (verbose()) {
            double lo = 1e30, hi = 0;
            size_t j;
            for (j = 0; j < e->n; j++) {
                double dd = gt_view_depth(e, j);
                if (ref[j] < 0 || !(dd > 0)) continue;
                if (dd < lo) lo = dd;
                if (dd > hi) hi = dd;
            }
            printf("%s %d: view depths %.2f..%.2f (near %.3f far %.1f)\n", label, i, lo, hi, v[i].zn, v[i].zf);
        }
        for (k = 0; k < METHODS; k++) {
            pool one;
            if (!sh[k] || frame(e, sh[k], &methods[k], &cam, v[i].light, res) != 0) {
                pools[k].failed++;
                continue;
            }
            memset(&one, 0, sizeof one);
            pool_frame(&pools[k], e, ref, res, sh[k]);
            pool_frame(&one, e, ref, res, sh[k]);
            if (getenv("SK_GL_TEST_IMAGES")) {
                char nm[96];
                snprintf(nm, sizeof nm, "auto-%s-%d-%d", label, i, k);
                gt_images(e, nm, ref, res);
            }
            if (verbose()) {
                tb_shadow_error se = gt_shadow_error(e, ref, res);
                printf("   false light %.2f%% false shadow %.2f%% shadow px %llu\n", se.false_light_pct,
                       se.false_shadow_pct, (unsigned long long)se.shadow);
            }
            if (verbose()) {
                const skgl_shadow_frame_stats *st = skgl_shadow_stats(sh[k]);
                int q;
                printf("   splits");
                for (q = 0; q <= st->maps; q++) printf(" %.2f", st->splits[q]);
                printf("  view %dx%d  scores %.2f %.2f %.2f %.2f, warped %.2f %.2f %.2f %.2f\n", st->map_width,
                       st->map_height, st->auto_texel_px[0], st->auto_texel_px[1], st->auto_texel_px[2],
                       st->auto_texel_px[3], st->auto_texel_px_warped[0], st->auto_texel_px_warped[1],
                       st->auto_texel_px_warped[2], st->auto_texel_px_warped[3]);
            }
            if (verbose())
                printf("%s %d %-18s %7.2f%%  maps %d  depths %.2f..%.1f  %s\n", label, i, methods[k].name,
                       pool_pct(&one), skgl_shadow_stats(sh[k])->maps, skgl_shadow_stats(sh[k])->depth_lo,
                       skgl_shadow_stats(sh[k])->depth_hi,
                       k == M_AUTO ? skgl_shadow_stats(sh[k])->auto_reason : "");
        }
    }
    for (k = 0; k < METHODS; k++) skgl_shadow_destroy(e->sk, sh[k]);
    free(ref);
    free(res);
}

static void print_pools(const char *label, const pool *pools) {
    int k;
    for (k = 0; k < METHODS; k++) {
        const pool *p = &pools[k];
        printf("  %-12s %-18s %6.2f%%  maps 1/2/3/4: %d %d %d %d, warped %d%s\n", label, methods[k].name, pool_pct(p),
               p->maps_hist[1], p->maps_hist[2], p->maps_hist[3], p->maps_hist[4], p->warped, p->failed ? "  FAILED" : "");
    }
}

/* the open world's frames: views 0-4, suns 4 (8 degrees behind), 0 (45
   behind) and 3 (20 across) */
static int open_world_views(view *v) {
    static const int suns[3] = {0, 3, 4};
    int i, s, n = 0;
    for (i = 0; i < TB_OPEN_WORLD_VIEWS; i++)
        for (s = 0; s < 3; s++) {
            tb_open_world_view(i, &v[n].eye, &v[n].target);
            tb_open_world_sun(i, suns[s], &v[n].light);
            v[n].zn = 0.5f;
            v[n].zf = 1000.0f;
            n++;
        }
    return n;
}

/* a small scene's two views from its non-ground bounds: an overview 35
   degrees up from 2.2 radii, and a low view from beyond one end looking
   along the long axis; the far plane 4 radii past the eye */
static int small_views(const tb_scene *sc, view *v) {
    sk_aabb b;
    double c[3], r, ext[3];
    int k, first = 1;
    uint32_t o;
    memset(&b, 0, sizeof b);
    for (o = 0; o < sc->object_count; o++) {
        sk_aabb ob = sc->objects[o].bounds;
        if (strstr(sc->objects[o].name, "ground")) continue;
        if (first) { b = ob; first = 0; continue; }
        for (k = 0; k < 3; k++) {
            if ((&ob.min.x)[k] < (&b.min.x)[k]) (&b.min.x)[k] = (&ob.min.x)[k];
            if ((&ob.max.x)[k] > (&b.max.x)[k]) (&b.max.x)[k] = (&ob.max.x)[k];
        }
    }
    for (k = 0; k < 3; k++) {
        c[k] = 0.5 * ((&b.min.x)[k] + (&b.max.x)[k]);
        ext[k] = (&b.max.x)[k] - (&b.min.x)[k];
    }
    r = 0.5 * sqrt(ext[0] * ext[0] + ext[1] * ext[1] + ext[2] * ext[2]);
    v[0].target = gt_v3((float)c[0], (float)c[1], (float)c[2]);
    v[0].eye = gt_v3((float)(c[0] + 2.2 * r * cos(0.61) * 0.6), (float)(c[1] + 2.2 * r * sin(0.61)),
                     (float)(c[2] + 2.2 * r * cos(0.61) * 0.8));
    v[0].zn = (float)(0.01 * r);
    v[0].zf = (float)(8.0 * r);
    if (ext[0] >= ext[2]) {
        v[1].eye = gt_v3((float)(b.min.x - 0.3 * r), (float)(b.min.y + 0.15 * r + 0.3), (float)c[2]);
        v[1].target = gt_v3((float)b.max.x, (float)(b.min.y + 0.1 * r), (float)c[2]);
    } else {
        v[1].eye = gt_v3((float)c[0], (float)(b.min.y + 0.15 * r + 0.3), (float)(b.min.z - 0.3 * r));
        v[1].target = gt_v3((float)c[0], (float)(b.min.y + 0.1 * r), (float)b.max.z);
    }
    v[1].zn = (float)(0.005 * r);
    v[1].zf = (float)(8.0 * r);
    v[0].light = v[1].light = gt_v3(-0.45f, -1.0f, -0.35f);
    return 2;
}

static const char *small_scenes[] = {"terrace", "ground-boxes", "fence"};
#define SMALL ((int)(sizeof small_scenes / sizeof small_scenes[0]))

static pool ow_pools[METHODS], overview_pools[METHODS], low_pools[METHODS];

static void run_all(void) {
    static int done;
    view v[TB_OPEN_WORLD_VIEWS * 3];
    gt_env e;
    tb_scene sc;
    int n, i;
    if (done) return;
    done = 1;
    tb_scene_init(&sc);
    if (tb_scene_build_open_world(&sc) != 0 || gt_env_init(&e, &sc, W, H) != 0) {
        SK_CHECK_MSG(0, "open world");
        return;
    }
    n = open_world_views(v);
    run_views(&e, v, n, ow_pools, "open-world");
    gt_env_free(&e);
    for (i = 0; i < SMALL; i++) {
        tb_scene s2;
        tb_scene_init(&s2);
        if (tb_scene_build(&s2, small_scenes[i]) != 0 || gt_env_init(&e, &s2, W, H) != 0) {
            SK_CHECK_MSG(0, "%s", small_scenes[i]);
            continue;
        }
        n = small_views(&e.scene, v);
        run_views(&e, &v[0], 1, overview_pools, small_scenes[i]);
        run_views(&e, &v[1], 1, low_pools, small_scenes[i]);
        gt_env_free(&e);
        (void)n;
    }
    printf("pooled shadow-area error, %dx%d:\n", W, H);
    print_pools("open world", ow_pools);
    print_pools("overviews", overview_pools);
    print_pools("low views", low_pools);
}

static void test_auto_choice(void) {
    int k;
    run_all();
    for (k = 0; k < METHODS; k++)
        SK_CHECK_MSG(ow_pools[k].failed + overview_pools[k].failed + low_pools[k].failed == 0, "%s failed",
                     methods[k].name);
    /* the open world: a kilometre of view depth, cascades in every frame
       (the worst focused texel spans 18 to 48 px with one map, 1.2 to 1.3
       with 4; warped, 1.2 to 25 with one, 0.4 to 1.3 with 4): measured 4
       maps in 10 frames and 2 in 5, warped in 14 of 15 */
    SK_CHECK_MSG(ow_pools[M_AUTO].maps_hist[1] == 0, "open world: AUTO chose 1 map in %d of %d",
                 ow_pools[M_AUTO].maps_hist[1], ow_pools[M_AUTO].frames);
    /* a small scene seen from low at one end: a warp is where LiSPSM
       pays (Wimmer et al. 2004): one warped map in every frame, at most
       0.7x the error of the better of standard and PSSM at the same
       texels. Measured 3.04% against 5.99% (0.51x); with
       .disable_auto_warp 5.90% (0.98x) */
    SK_CHECK_MSG(low_pools[M_AUTO].warped == low_pools[M_AUTO].frames, "low views: AUTO warped %d of %d frames",
                 low_pools[M_AUTO].warped, low_pools[M_AUTO].frames);
    /* .disable_auto_warp: never warped; the open world on 4 cascades in
       every frame (the focused maps' worst texel 1.2 to 1.3 px with 4) */
    SK_CHECK_MSG(ow_pools[M_AUTO_FOCUSED].warped + overview_pools[M_AUTO_FOCUSED].warped +
                     low_pools[M_AUTO_FOCUSED].warped == 0,
                 "focused only: warped in %d, %d, %d frames", ow_pools[M_AUTO_FOCUSED].warped,
                 overview_pools[M_AUTO_FOCUSED].warped, low_pools[M_AUTO_FOCUSED].warped);
    SK_CHECK_MSG(ow_pools[M_AUTO_FOCUSED].maps_hist[4] == ow_pools[M_AUTO_FOCUSED].frames,
                 "open world, focused only: 4 maps in %d of %d", ow_pools[M_AUTO_FOCUSED].maps_hist[4],
                 ow_pools[M_AUTO_FOCUSED].frames);
    {
        double best = pool_pct(&low_pools[M_STD]) < pool_pct(&low_pools[M_PSSM]) ? pool_pct(&low_pools[M_STD])
                                                                              : pool_pct(&low_pools[M_PSSM]);
        SK_CHECK_MSG(pool_pct(&low_pools[M_AUTO]) <= 0.7 * best, "low views: AUTO %.2f%%, best of standard and PSSM %.2f%%",
                     pool_pct(&low_pools[M_AUTO]), best);
    }
    /* a small scene seen whole: one map (its worst focused texel 0.10 to
       0.27 px; one of the three warped) */
    SK_CHECK_MSG(overview_pools[M_AUTO].maps_hist[1] == overview_pools[M_AUTO].frames,
                 "overviews: AUTO chose 1 map in %d of %d", overview_pools[M_AUTO].maps_hist[1],
                 overview_pools[M_AUTO].frames);
    /* at the same texels, AUTO is never far from the better of standard and
       PSSM on either kind of scene: measured 0.63x (open world), 0.95x
       (overviews), 0.51x (low views) */
    {
        const pool *sets[3] = {ow_pools, overview_pools, low_pools};
        const char *names[3] = {"open world", "overviews", "low views"};
        int j;
        for (j = 0; j < 3; j++) {
            double best = pool_pct(&sets[j][M_STD]) < pool_pct(&sets[j][M_PSSM]) ? pool_pct(&sets[j][M_STD])
                                                                                : pool_pct(&sets[j][M_PSSM]);
            SK_CHECK_MSG(pool_pct(&sets[j][M_AUTO]) <= 1.25 * best + 0.1, "%s: AUTO %.2f%%, best of standard and PSSM %.2f%%",
                         names[j], pool_pct(&sets[j][M_AUTO]), best);
        }
    }
}

/* AUTO's splits and count against the bench's Pareto front in the open
   world (PSSM lambda 0.9): at the same texels, AUTO's pooled error within
   1.15x of PSSM 4x1024^2 at lambda 0.9. Measured: AUTO 1.12% (warped in
   14 of 15 frames, 2 maps in 5 of them, log splits over the analysed
   range) against 1.02% (1.10x); 1.03% (1.01x) with focused maps only
   (4 in every frame). Broken on
   purpose: AUTO's lambda forced back to .lambda (0.75), 1.70% (1.66x),
   fails; one map would be the standard fit row, 11.28%. Each count's
   crops fitted once: 1 + 2 + 3 + 4 = 10 a frame with 4 layers; with the
   chosen count's crops fitted again, 14 in the open world and 11 or 12
   on the small scenes (seen failing). */
static void test_auto_front(void) {
    run_all();
    printf("open world: AUTO %.2f%%, PSSM 4x1024 lambda 0.9 %.2f%% (%.2fx); AUTO crops a frame %d..%d\n",
           pool_pct(&ow_pools[M_AUTO]), pool_pct(&ow_pools[M_PSSM_09]),
           pool_pct(&ow_pools[M_AUTO]) / pool_pct(&ow_pools[M_PSSM_09]), ow_pools[M_AUTO].crops_min,
           ow_pools[M_AUTO].crops_max);
    SK_CHECK_MSG(pool_pct(&ow_pools[M_AUTO]) <= 1.15 * pool_pct(&ow_pools[M_PSSM_09]),
                 "open world: AUTO %.2f%%, PSSM 4x1024 lambda 0.9 %.2f%%", pool_pct(&ow_pools[M_AUTO]),
                 pool_pct(&ow_pools[M_PSSM_09]));
    SK_CHECK_MSG(ow_pools[M_AUTO].crops_min == 10 && ow_pools[M_AUTO].crops_max == 10,
                 "AUTO fitted %d..%d crops a frame, 10 expected", ow_pools[M_AUTO].crops_min,
                 ow_pools[M_AUTO].crops_max);
    SK_CHECK_MSG(overview_pools[M_AUTO].crops_min == 10 && low_pools[M_AUTO].crops_max == 10,
                 "small scenes: AUTO fitted %d / %d crops a frame, 10 expected", overview_pools[M_AUTO].crops_min,
                 low_pools[M_AUTO].crops_max);
}

/* AUTO's analysis runs when the view may have changed, not every frame
   (CHOOSING FOR YOU): over 16 frames, a still camera analyses on frames 0
   and 8 (2 of 16), a camera creeping 1 mm a frame likewise, one walking
   1 m a frame (more than 5% of the nearest depth, about 2.7 m) or turning
   3 degrees a frame on all 16; the kept frames do no analysis (0 ms) and
   the shadows of a still camera stay the same (0 pixels differ between
   frame 1 and frame 7). Broken on purpose: the analysis on every call,
   the still camera analysed 16 of 16. */
static int gated_path(gt_env *e, int frames, float step_m, float turn_deg, int *differ) {
    skgl_shadow_desc d = gt_shadow_desc(SKGL_AUTO, 2048, 4, 0);
    skgl_shadow *s;
    sk_vec3 light = gt_v3(-0.45f, -1.0f, -0.35f);
    float *first = gt_alloc(e), *vis = gt_alloc(e);
    int f, ran = 0;
    size_t j;
    d.sync_readback = 0;
    s = gt_shadow(e, &d);
    *differ = 0;
    SK_CHECK(s != NULL);
    for (f = 0; s && f < frames; f++) {
        float a = turn_deg * (float)f * 0.0174533f;
        sk_vec3 eye = gt_v3(0.0f, 1.7f, -step_m * (float)f);
        skgl_camera cam = gt_camera(eye, gt_v3(eye.x + 80.0f * sinf(a), 0.0f, eye.z - 80.0f * cosf(a)), FOVY, 0.5f,
                                    1000.0f, W, H);
        skgl_scene sc = gt_scene(e);
        if (gt_gbuffer(e, &cam) != 0 || skgl_shadow_analyze(e->sk, s, &cam, &sc, light, e->gbuf.depth_tex) != SK_OK ||
            gt_mask(e, s, &cam, light, vis) != 0) {
            SK_CHECK_MSG(0, "frame %d: %s", f, skgl_error_log(e->sk));
            break;
        }
        ran += skgl_shadow_stats(s)->auto_analysed;
        if (!skgl_shadow_stats(s)->auto_analysed)
            SK_CHECK_MSG(skgl_shadow_stats(s)->analysis_ms == 0.0f, "frame %d kept: analysis_ms %g", f,
                         (double)skgl_shadow_stats(s)->analysis_ms);
        if (f == 1) memcpy(first, vis, e->n * sizeof *vis);
        if (f == 7)
            for (j = 0; j < e->n; j++) *differ += first[j] != vis[j];
    }
    skgl_shadow_destroy(e->sk, s);
    free(first);
    free(vis);
    return ran;
}

static void test_auto_analysis_gate(void) {
    gt_env e;
    tb_scene sc0;
    int still, creep, walk, turn, d_still, d_other;
    tb_scene_init(&sc0);
    if (tb_scene_build_open_world(&sc0) != 0 || gt_env_init(&e, &sc0, W, H) != 0) {
        SK_CHECK_MSG(0, "open world");
        return;
    }
    still = gated_path(&e, 16, 0.0f, 0.0f, &d_still);
    creep = gated_path(&e, 16, 0.001f, 0.0f, &d_other);
    walk = gated_path(&e, 16, 1.0f, 0.0f, &d_other);
    turn = gated_path(&e, 16, 0.0f, 3.0f, &d_other);
    printf("analyses in 16 frames: still %d, creeping 1 mm %d, walking 1 m %d, turning 3 deg %d; still camera: %d px "
           "differ\n", still, creep, walk, turn, d_still);
    SK_CHECK_MSG(still == 2 && creep == 2, "still %d, creeping %d analyses of 16 (2 expected)", still, creep);
    SK_CHECK_MSG(walk == 16 && turn == 16, "walking %d, turning %d analyses of 16 (16 expected)", walk, turn);
    SK_CHECK_MSG(d_still == 0, "still camera: %d px differ between frames 1 and 7", d_still);
    gt_env_free(&e);
}

/* Stable crops (stepped on the 2^(1/8) ladder, texel-snapped) against the
   focused ones at the same texels: measured stable / focused 1.11 and 1.02
   (open world, standard and PSSM), 0.87 and 0.84 (overviews), 1.10 and
   0.97 (low views). With the sphere fit (.stable_sphere, the stable crop
   before) the open world's PSSM was 1.77x (test_gl_open_world) and the
   fence's overview 55% worse with 19% ladder steps. */
static void test_stable_ratio(void) {
    const pool *sets[3] = {ow_pools, overview_pools, low_pools};
    const char *names[3] = {"open world", "overviews", "low views"};
    int j;
    run_all();
    for (j = 0; j < 3; j++) {
        SK_CHECK_MSG(pool_pct(&sets[j][M_STD_STABLE]) <= 1.3 * pool_pct(&sets[j][M_STD]) + 0.1,
                     "%s: standard stable %.2f%%, focused %.2f%%", names[j], pool_pct(&sets[j][M_STD_STABLE]),
                     pool_pct(&sets[j][M_STD]));
        SK_CHECK_MSG(pool_pct(&sets[j][M_PSSM_STABLE]) <= 1.3 * pool_pct(&sets[j][M_PSSM]) + 0.1,
                     "%s: PSSM stable %.2f%%, focused %.2f%%", names[j], pool_pct(&sets[j][M_PSSM_STABLE]),
                     pool_pct(&sets[j][M_PSSM]));
    }
}

static void test_fit_to_depth(void) {
    run_all();
    /* the splits over the depths the view holds, not from the near plane,
       logarithmic once analysed (.lambda left 0): measured 1.03 against
       1.77% (open world; 1.70% with the practical scheme's 0.75 over the
       analysed range, which fails the 0.7x bound), 16.78 against 18.51%
       (overviews; 15.92 at 0.75), standard 6.40 and 6.40% */
    SK_CHECK_MSG(pool_pct(&ow_pools[M_PSSM_FIT]) <= 0.7 * pool_pct(&ow_pools[M_PSSM]),
                 "open world: PSSM fit %.2f%%, %.2f%%", pool_pct(&ow_pools[M_PSSM_FIT]), pool_pct(&ow_pools[M_PSSM]));
    SK_CHECK_MSG(pool_pct(&overview_pools[M_PSSM_FIT]) < pool_pct(&overview_pools[M_PSSM]),
                 "overviews: PSSM fit %.2f%%, %.2f%%", pool_pct(&overview_pools[M_PSSM_FIT]),
                 pool_pct(&overview_pools[M_PSSM]));
    SK_CHECK_MSG(pool_pct(&overview_pools[M_STD_FIT]) <= pool_pct(&overview_pools[M_STD]) + 0.1,
                 "overviews: standard fit %.2f%%, %.2f%%", pool_pct(&overview_pools[M_STD_FIT]),
                 pool_pct(&overview_pools[M_STD]));
}

/* A camera rising from head height to 600 m above the open world, looking
   at a point 80 m ahead, 90 frames, the analysis a frame late (the ring):
   the view goes from a kilometre of depth (cascades) to a steep view down
   of a few hundred metres' depth range (one map). */
/* one AUTO light along a camera path; the count changes and A -> B -> A
   returns (consecutive changes) */
typedef struct path_counts { int first, last, changes, returns, resizes; double bytes; } path_counts;

/* the depth texture n maps of 2048^2 / n texels each need: n layers of
   floor(2048 / sqrt(n))^2 32-bit texels (CHOOSING FOR YOU, Memory) */
static double auto_need_bytes(int n) {
    double side = floor(2048.0 / sqrt((double)n));
    return 4.0 * n * side * side;
}

static path_counts auto_path(gt_env *e, int frames, float (*height)(int f, int frames)) {
    skgl_shadow_desc d = gt_shadow_desc(SKGL_AUTO, 2048, 4, 0);
    skgl_shadow *s = gt_shadow(e, &d);
    sk_vec3 light = gt_v3(-0.45f, -1.0f, -0.35f);
    path_counts pc;
    int f, prev = 0, kept = 0, set, prev_set = 0, prev2_set = 0;
    memset(&pc, 0, sizeof pc);
    SK_CHECK(s != NULL);
    for (f = 0; s && f < frames; f++) {
        float y = height(f, frames);
        skgl_camera cam = gt_camera(gt_v3(0.0f, y, 0.0f), gt_v3(0.0f, 0.0f, -80.0f), FOVY, 0.5f, 1000.0f, W, H);
        skgl_scene sc = gt_scene(e);
        const skgl_shadow_frame_stats *st;
        if (gt_gbuffer(e, &cam) != 0 || skgl_shadow_analyze(e->sk, s, &cam, &sc, light, e->gbuf.depth_tex) != SK_OK ||
            skgl_shadow_render(e->sk, s, &cam, &sc, light) != SK_OK) {
            SK_CHECK_MSG(0, "frame %d: %s", f, skgl_error_log(e->sk));
            break;
        }
        st = skgl_shadow_stats(s);
        SK_CHECK_MSG(strstr(st->auto_reason, "map") != NULL, "frame %d: reason '%s'", f, st->auto_reason);
        {
            int i, warped = 0;
            for (i = 0; i < st->maps; i++) warped |= st->warped[i];
            SK_CHECK_MSG(st->auto_technique == (warped ? SKGL_LISPSM : st->maps == 1 ? SKGL_STANDARD : SKGL_PSSM),
                         "frame %d: technique %d, %d maps, warped %d", f, (int)st->auto_technique, st->maps, warped);
        }
        if (verbose())
            printf("  %.1f m up: predicted texel %.2f %.2f %.2f %.2f px with 1-4 maps -> %d\n", y, st->auto_texel_px[0],
                   st->auto_texel_px[1], st->auto_texel_px[2], st->auto_texel_px[3], st->maps);
        /* the texture holds the count; exactly its size once the count
           has been kept 30 renders (SKGL__AUTO_SHRINK); never more than
           .cascades layers of 2048^2 */
        kept = st->maps == prev ? kept + 1 : 1;
        SK_CHECK_MSG(st->auto_bytes >= auto_need_bytes(st->maps) && st->auto_bytes <= 4.0 * 4 * 2048.0 * 2048.0,
                     "frame %d: %d maps in %.0f bytes", f, st->maps, st->auto_bytes);
        SK_CHECK_MSG(kept < 30 || st->auto_bytes == auto_need_bytes(st->maps),
                     "frame %d: %d maps kept %d renders, %.0f bytes, %.0f needed", f, st->maps, kept, st->auto_bytes,
                     auto_need_bytes(st->maps));
        if (f > 0 && st->auto_bytes != pc.bytes) pc.resizes++;
        pc.bytes = st->auto_bytes;
        if (f == 0) pc.first = st->maps;
        /* the set in use: its map count, and whether warped (a focused /
           warped swap at the same count is a change too) */
        set = 2 * st->maps + (st->auto_technique == SKGL_LISPSM);
        if (prev_set && set != prev_set) {
            pc.changes++;
            if (set == prev2_set) pc.returns++;
            if (verbose()) printf("frame %d (%.1f m up): %s\n", f, y, st->auto_reason);
            prev2_set = prev_set;
        }
        prev_set = set;
        prev = pc.last = st->maps;
    }
    skgl_shadow_destroy(e->sk, s);
    return pc;
}

/* from head height to 600 m */
static float rising(int f, int frames) {
    float t = (float)f / (float)(frames - 1);
    return 1.7f + 598.3f * t * t;
}

/* bobbing 3 m about 65 m, where one map starts to meet the target (a crane shot) */
static float bobbing(int f, int frames) {
    (void)frames;
    return 65.0f + 3.0f * (float)sin(0.7 * f);
}

/* The open world, the camera looking at a point 80 m ahead, the analysis a
   frame late (the ring): rising from head height to 600 m over 90 frames
   (a kilometre of depth, cascades, to a steep view down, one map), then 60
   frames bobbing 3 m about the height where the count changes. */
static void test_auto_hysteresis(void) {
    gt_env e;
    tb_scene sc0;
    path_counts up, bob;
    tb_scene_init(&sc0);
    if (tb_scene_build_open_world(&sc0) != 0 || gt_env_init(&e, &sc0, W, H) != 0) {
        SK_CHECK_MSG(0, "open world");
        return;
    }
    up = auto_path(&e, 90, rising);
    bob = auto_path(&e, 60, bobbing);
    printf("hysteresis: rising %d -> %d maps, %d changes, %d returns; bobbing %d changes, %d returns\n", up.first,
           up.last, up.changes, up.returns, bob.changes, bob.returns);
    printf("memory: rising %d resizes, %.1f MiB at the end; bobbing %d resizes, %.1f MiB\n", up.resizes,
           up.bytes / 1048576.0, bob.resizes, bob.bytes / 1048576.0);
    /* a grow and a shrink at most per change of count (the texture grows
       to hold both counts, then shrinks once one is kept) */
    SK_CHECK_MSG(up.resizes <= 2 * up.changes && bob.resizes <= 2 * bob.changes,
                 "rising: %d resizes for %d changes; bobbing: %d for %d", up.resizes, up.changes, bob.resizes,
                 bob.changes);
    SK_CHECK_MSG(up.bytes == auto_need_bytes(1), "rising: %.0f bytes at the end, one map of 2048^2", up.bytes);
    /* measured: rising 4 maps at head height, 1 at 600 m, 3 changes with
       the log splits (2 before them: 2 maps from 65 m, 1 from 74 m); bobbing 0 changes (2 maps kept: one map's worst texel
       swings between 0.94 and 1.2 px, never 15% under the target).
       Without the hysteresis (always the newest pick): bobbing 14
       changes, 13 of them back */
    SK_CHECK_MSG(up.first > 1 && up.last == 1, "first %d, last %d maps", up.first, up.last);
    SK_CHECK_MSG(up.changes <= 4 && up.returns == 0, "rising: %d changes, %d returns", up.changes, up.returns);
    SK_CHECK_MSG(bob.changes <= 2 && bob.returns == 0, "bobbing: %d changes, %d returns", bob.changes, bob.returns);
    gt_env_free(&e);
}

/* AUTO's rule where no set meets the target (.auto_texel_px 0.05, below
   any set's ratio): the fewest maps within 25% of the finest set, a new
   light each open-world view, rendered RULE_FRAMES times through the
   read-back ring (the first render has no analysed range yet: the set it
   picks over the whole view is no set in use to keep once the range
   lands: with the 9% margin for fewer maps, a light would otherwise keep
   more maps than the analysed view needs; on these frames keeping it
   happens to pass as well). Checked on the predictions
   each frame reports (stats.auto_texel_px and .auto_texel_px_warped):
   the chosen set within 1.25x of the finest, and no set of fewer maps
   within it. Measured: the finest set has 4 maps in every frame, the
   choice fewer in 10 of 15 (6 of 15 with a 15% margin; seen failing with
   the old rule, the finest set: those frames, and the count of frames
   with fewer maps). */
#define RULE_FRAMES 3
static void test_auto_rule(void) {
    view v[TB_OPEN_WORLD_VIEWS * 3];
    gt_env e;
    tb_scene sc;
    int n, i, fewer = 0;
    tb_scene_init(&sc);
    if (tb_scene_build_open_world(&sc) != 0 || gt_env_init(&e, &sc, W, H) != 0) {
        SK_CHECK_MSG(0, "open world");
        gt_env_free(&e);
        return;
    }
    n = open_world_views(v);
    for (i = 0; i < n; i++) {
        skgl_camera cam = gt_camera(v[i].eye, v[i].target, FOVY, v[i].zn, v[i].zf, W, H);
        skgl_shadow_desc d = gt_shadow_desc(SKGL_AUTO, 2048, 4, 0);
        skgl_scene scene = gt_scene(&e);
        skgl_shadow *s;
        const skgl_shadow_frame_stats *st;
        float best = 0.0f, chosen;
        int k, best_maps = 0;
        int w, failed = 0;
        d.auto_texel_px = 0.05f;   /* the read-back ring, as a game runs it */
        s = gt_shadow(&e, &d);
        failed = !s || gt_gbuffer(&e, &cam) != 0;
        for (w = 0; w < RULE_FRAMES && !failed; w++)
            failed = skgl_shadow_analyze(e.sk, s, &cam, &scene, v[i].light, e.gbuf.depth_tex) != SK_OK ||
                     skgl_shadow_render(e.sk, s, &cam, &scene, v[i].light) != SK_OK;
        if (failed) {
            SK_CHECK_MSG(0, "frame %d: %s", i, skgl_error_log(e.sk));
            skgl_shadow_destroy(e.sk, s);
            continue;
        }
        st = skgl_shadow_stats(s);
        SK_CHECK_MSG(st->depth_hi > 0.0f, "frame %d: no analysed range after %d renders", i, RULE_FRAMES);
        for (k = 0; k < 4; k++) {
            float f = st->auto_texel_px[k], w = st->auto_texel_px_warped[k];
            if (f > 0.0f && (!best || f < best)) { best = f; best_maps = k + 1; }
            if (w > 0.0f && (!best || w < best)) { best = w; best_maps = k + 1; }
        }
        chosen = st->auto_technique == SKGL_LISPSM ? st->auto_texel_px_warped[st->maps - 1]
                                                   : st->auto_texel_px[st->maps - 1];
        SK_CHECK_MSG(best > 0.05f && chosen <= 1.25f * best, "frame %d: chose %d maps at %.3f px, the finest %.3f", i,
                     st->maps, chosen, best);
        for (k = 0; k < st->maps - 1; k++)
            SK_CHECK_MSG(!(st->auto_texel_px[k] > 0.0f && st->auto_texel_px[k] <= 1.25f * best) &&
                             !(st->auto_texel_px_warped[k] > 0.0f && st->auto_texel_px_warped[k] <= 1.25f * best),
                         "frame %d: %d maps chosen, %d within 25%% of the finest (%.3f / %.3f against %.3f)", i,
                         st->maps, k + 1, st->auto_texel_px[k], st->auto_texel_px_warped[k], best);
        fewer += st->maps < best_maps;
        skgl_shadow_destroy(e.sk, s);
    }
    printf("rule without a set meeting the target: fewer maps than the finest set in %d of %d frames\n", fewer, n);
    SK_CHECK_MSG(fewer > 0, "the rule never chose fewer maps than the finest set (%d frames)", n);
    gt_env_free(&e);
}

SK_TEST_MAIN(test_auto_rule, test_auto_choice, test_auto_front, test_fit_to_depth, test_stable_ratio, test_auto_hysteresis,
             test_auto_analysis_gate)
