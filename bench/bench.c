/* bench/bench.c - speed against accuracy of every shadowkit_gl.h method
   (issue 4, item 4; DESIGN.md "Measuring").

   What it does
     For every scene, view and method configuration: render the camera
     G-buffer (window depth + world normals, 1280x720), then
     skgl_shadow_render + skgl_shadow_mask with GL timer queries
     (skgl_desc.timing = SKGL_TIMING_SYNC), read the R16F mask back and compare it with the
     exact Embree reference (tb_reference_trace_exact, traced ONCE per
     (scene, view): primary rays through the pixel centres, shadow rays from
     the exact hits with only a float-error offset; back-facing receivers and
     pixels whose rasterised surface differs from the traced one are left
     out and counted in excluded_px). Scores (testbed/tb_metrics.h): tb_metric_hard(), the % of
     covered pixels whose lit/shadowed class differs from the reference (the
     `error` column, kept for continuity), and tb_metric_shadow(), the same
     errors against the reference's shadow: the lit majority of a frame
     dilutes the covered %, so the charts plot the shadow-area error.
     Area-light rows: tb_metric_soft() (`error`) and tb_metric_penumbra().
     Directional rows also get the texel-to-pixel figure (bench_texel.h:
     Ferko 2013's measure, how many pixels one texel of the map each pixel
     samples spans) and the shadow-area error by view-depth band; each
     view of a scene also gets a floor row, the error of an over-resolved
     map (floor_runs), drawn on its chart as the limit.

   Output (everything under --out, default out/)
     bench.csv                  one row per run, the columns (the first 14
                                fixed by DESIGN.md "Output", the rest
                                appended after them, never inserted)
       method,params,scene,view,width,height,error_kind,error,texels,passes,
       shadow_ms,analysis_ms,total_ms,device,shadow_area_pct,false_shadow_pct,
       false_light_pct,edge_mean_px,edge_p95_px,covered_pct,penumbra_mae,
       penumbra_max,umbra_mae,lit_mae,excluded_px,texel_over1_pct,
       texel_over2_pct,texel_over4_pct,texel_median_px,area_0_10_pct,
       area_10_50_pct,area_50_200_pct,area_200_pct
       method     standard | standard-stable | pssm | pssm-stable (stable
                  cascades, lambda 0.9) | psm | lispsm |
                  lispsm-pssm (LiSPSM per cascade) | lspsm | ferko | rmsm |
                  auto (SKGL_AUTO: one focused map or up to 4 cascades
                  sharing resolution^2 texels, chosen per frame) |
                  evsm (desc.filter = SKGL_FILTER_EVSM: one map, or 4 PSSM
                  cascades; blur = desc.evsm_blur) |
                  pssm-fit | standard-fit (desc.fit_to_depth: the splits
                  over the analysed depth range, SDSM; params as the
                  practical pssm / standard row they are compared with) |
                  cube-naive | cube | vsdct (point lights, "room"; all six
                  lights of "interior" at once) |
                  spot | cube-cone | vsdct-cone (spot lights, "room-spot") |
                  floor (the limit: params say which over-resolved map)
                  (DESIGN.md names)
       params     key=value;key=value (resolution is per map / per cascade)
       error_kind hard_pct (directional and point lights, the walk) or
                  soft_mae (area lights)
       error      hard_pct: tb_metric_hard's % of covered pixels misclassified;
                  soft_mae: tb_metric_soft's mean absolute visibility error over
                  the covered pixels
       texels     shadow texels rendered (the stats' texels)
       passes     draw callbacks made (the stats' passes)
       shadow_ms  GPU time of the depth passes (timer query; on a CPU
                  rasteriser the wall clock between two glFinish calls, see
                  g_wall_timing), median of
                  --repeat timing passes
       analysis_ms GPU time of skgl_shadow_analyze (FERKO, RMSM, AUTO,
                  the -fit rows; median, like shadow_ms); 0 for the methods
                  that analyse nothing
       total_ms   shadow_ms + analysis_ms + mask_ms (the deferred mask pass,
                  one sample)
       device     GL renderer string (CSV-quoted: llvmpipe's has commas)
       hard rows only (tb_metric_shadow; empty on soft rows):
       shadow_area_pct   misclassified (false shadow + false light + non-finite)
                         / the reference's shadow pixels, %; may exceed 100
       false_shadow_pct  result shadowed, reference lit, % of the shadow pixels
       false_light_pct   result lit, reference shadowed, % of the shadow pixels
                         (these three empty when the reference has no shadow)
       edge_mean_px      mean distance of the wrong pixels to the exact shadow
                         edge, pixels (nearest covered pixel centre of the other
                         reference class, minus 0.5); 0 when nothing is wrong,
                         empty when the reference has one class only
       edge_p95_px       its 95th percentile (same cases)
       covered_pct       = error: the % of covered pixels misclassified
       (interior rows: every light's pixels pooled, the counts of all the
       lights' masks against their references; edge_mean_px over all their
       wrong pixels, edge_p95_px the largest light's)
       soft rows only (tb_metric_penumbra, the penumbra grown by 2 px, a
       Euclidean disc; empty on hard rows, and where the reference frame has
       no pixel of that region):
       penumbra_mae      mean |result - reference| in the grown penumbra
                         (0 < reference < 1)
       penumbra_max      its largest value
       umbra_mae         mean over reference 0 outside the grown penumbra
       lit_mae           mean over reference 1 outside the grown penumbra
       every row:
       excluded_px       reference pixels marked back-facing (-3) or
                         silhouette (-4): left out of every denominator
       directional rows only (empty on point and area-light rows):
       texel_over1_pct,  % of the shaded pixels (covered by the reference,
       texel_over2_pct,  looking up a map) whose shadow texel spans more
       texel_over4_pct   than 1, 2, 4 pixels (tb_texel_footprint: the
                         bounding box of the pixel's patch in the map it
                         samples, Ferko 2013 Sec. 3.2)
       texel_median_px   the median of that footprint, pixels
       area_0_10_pct ..  the shadow-area error within 0-10, 10-50, 50-200
       area_200_pct      and 200+ scene units (metres in the open world) of
                         view depth (tb_metric_shadow_bands); empty where
                         the band holds no reference shadow
     bench-data/<scene>.*.dat   the chart data: per configuration the mean
                                shadow_area_pct (soft: penumbra_mae) over the
                                views where it is defined and the mean
                                shadow_ms + analysis_ms over the views
     pareto-<scene>.png         gnuplot (bench/pareto.gp): shadow-area error
                                (soft charts, pareto-<scene>-soft.png: the
                                penumbra MAE) against shadow time, one
                                series per method, the
                                Pareto front (configurations no other beats
                                in both time and error) drawn as a staircase
                                through circled points
     bench-data/sweep.txt       repeat count, sweep, views, runs, device, timing
     bench-limit.txt            per chart: the floor, then every configuration
                                in order of time with its error, its
                                distance from the floor and its texel
                                figures (means over the views); the
                                companion table of the charts
     bench-auto.txt             issue 28's acceptance figure, per chart: each
                                AUTO point (time, error), the time of the
                                other configurations' Pareto front at
                                AUTO's error (their staircase: the fastest
                                at least as accurate), the ratio, whether
                                AUTO is on the front, PASS (on it or within
                                1.25x) or MISS; AUTO's choice per view
                                (stats.auto_reason); and each -fit row
                                against its practical twin (error and time
                                ratios)
     bench-data/auto-choices.txt  the sweep's AUTO choices, one line a run
     bench-bands.txt            per scene and configuration: the shadow-area
                                error by view-depth band, pooled over the
                                views (sums of wrong and of shadow pixels),
                                the floor's included
     bench/<scene>-<view>-*.png with --images: a shaded picture of the
                                reference and the error image of the first
                                configuration (tb_image_write_error colours)

   Scenes
     ../shared/scenes/ (relative to the repository root; --scenes DIR):
     stanford-bunny.obj, sponza-ivy/sponza_ivy.gltf and
     sponza-curtains/sponza_curtains.gltf, each standing on a ground plane
     added here (y = the model's lowest point, 3x its horizontal extent) so
     that its shadows have a receiver. When the folder is missing only the
     procedural scenes run, and stderr says so. Procedural (testbed):
     ground-boxes, fence, terrace, open-world (2 km, a camera at
     head height, far plane 1000 m: the regime of cascades, warps and
     virtual maps; its own views, see make_open_world_views) and forest
     (600 m, 600 instanced trees whose leaf cards are alpha-tested, a
     camera walking among them, far plane 400 m; its own views,
     make_forest_views; drawn as test_gl_forest.c draws it, bench_forest:
     the trees through a caster program in the shadow passes and through
     the same hooks in the G-buffer, the reference tracing the expanded
     trees through the same alpha texture). The scenes
     are bench_common.c's bench_scene_table, one entry a scene. One
     directional light per scene; and the "room" with a point light for the omnidirectional methods (see
     point_bench: cube-naive, cube, vsdct), and again under a spot light,
     "room-spot" (spot_bench: spot against cube-cone and vsdct-cone; its
     own chart, pareto-room-spot.png; --only room-spot runs it alone);
     and "interior", a building of six rooms with six point lights all
     shadowed every frame (interior_bench: the point methods, a row's error
     pooled over the lights, its shadow_ms their passes summed; its own
     chart, pareto-interior.png; --only interior runs it alone).

   Views (3, derived from the bounds of the non-ground objects, so they work
   for any scene; see bench_common.h make_views): "overview" (the whole content from 35
   degrees up), "low" (eye low beyond one end of the longest horizontal
   axis, looking along it: perspective aliasing), "close" (a close-up of
   the centre from 50 degrees up). 50 degree vertical field of view; near
   plane 0.002 x the eye-target distance, far plane past the scene.
   Light: one directional light travelling along (-0.45, -1, -0.35).

   Timing: per scene, `--repeat` timing passes (default 5) go over every
   configuration; in each pass a configuration gets a new map, one warm-up
   render (not timed: texture allocation, llvmpipe shader variants) and one
   timed render per view. A light that analyses the depth buffer through
   the read-back ring (AUTO and the -fit rows: sync_readback 0, the range
   of an earlier frame, as a game runs them) gets instead a new map and
   ANALYSIS_WARM untimed frames on each view, so that the ring holds that
   view's own range; its analysis time is counted like FERKO's.
   shadow_ms is the median over the passes.
   Interleaving the repetitions this way means a slow spell of a shared
   machine spoils one sample of many configurations instead of every sample
   of one. The last pass also runs the mask pass once per view (its time is
   mask_ms in total_ms; one sample) and scores the mask. On llvmpipe
   (OSMesa, CPU) the times are comparable only within one run of the bench
   on one machine; on a GPU (SK_GL=egl) they are absolute GPU times. The
   GL_RENDERER string decides which (software_renderer(): "llvmpipe" or
   "softpipe" in it means relative), and every output says so: the notes
   on stderr at the start and the end, the "timing" line of
   bench-data/sweep.txt, the first line of bench-walk.txt and
   bench-soft.txt, the time axis of each chart; bench.csv's device column
   holds the renderer string of every row.

   Usage (from the repository root; `make bench`, `make bench-demo`):
     build/bench/bench [--quick] [--repeat N] [--scenes DIR] [--out DIR]
                       [--only SCENE[,SCENE..]] [--views N] [--images]
                       [--views-only] [--gp FILE] [--plot-only] [--dry-run]
                       [--methods M[,M..]] [--match P[,P..]] [--no-floor] [--no-soft]
     --quick      the small sweep of `make demo` (also SK_BENCH_QUICK=1)
     --methods    only these methods of the directional sweep (bench_methods)
     --match      of those, only the configurations whose "method params"
                  hold every '+'-joined part of one of the patterns
     --no-floor   no floor rows (two over-resolved maps a view)
     --no-soft    no area-light rows (the soft_bench part)
     --plot-only  redraw the charts from an existing OUT/bench.csv
     --dry-run    print the sweep (configurations, runs) and exit
     --help       all options
   Exit status: 0; 1 on a setup failure (context, scene, gnuplot missing,
   chart failure); 2 on a usage error. A run whose shadowkit call fails is
   reported on stderr and skipped (no CSV row); the exit status is then 1.

   Note on skgl_shadow_desc.pcf_radius: zero means "default" (1), so the
   sweep asks for radius 0 (one hardware 2x2 comparison) with
   disable_pcf_kernel. */
#define _POSIX_C_SOURCE 200809L
#include "bench_common.h"
#include "bench_texel.h"

#include "tb_image.h"
#include "tb_metrics.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define BENCH_MAX_CFG 512
#define BENCH_MAX_SCENES 16
#define BENCH_MAX_VIEWS BENCH_VIEWS
#define BENCH_MAX_REPEAT 31
/* the first 14 columns are DESIGN.md's; the others are appended after them */
#define BENCH_CSV_HEADER \
    "method,params,scene,view,width,height,error_kind,error,texels,passes,shadow_ms,analysis_ms,total_ms,device," \
    "shadow_area_pct,false_shadow_pct,false_light_pct,edge_mean_px,edge_p95_px,covered_pct," \
    "penumbra_mae,penumbra_max,umbra_mae,lit_mae,excluded_px," \
    "texel_over1_pct,texel_over2_pct,texel_over4_pct,texel_median_px," \
    "area_0_10_pct,area_10_50_pct,area_50_200_pct,area_200_pct"
#define BENCH_CSV_COLS 33
#define BENCH_COL_SHADOW_AREA 14   /* 0-based: the hard charts' y */
#define BENCH_COL_PENUMBRA_MAE 20  /* the soft charts' y */
#define BENCH_COL_TEXEL 25         /* texel_over1_pct, then over2, over4, median */
#define BENCH_PENUMBRA_GROW 2      /* px, DESIGN.md "Measuring" */
/* view-depth bands of the band columns (scene units: metres in the open world) */
#define BENCH_BANDS 4
static const double band_edge[BENCH_BANDS + 1] = {0.0, 10.0, 50.0, 200.0, 1e30};
static const char *const band_name[BENCH_BANDS] = {"0-10", "10-50", "50-200", "200+"};
/* the floor's method name in bench.csv (see floor_runs) */
#define BENCH_FLOOR "floor"
/* AUTO's choice per view (maps, stats.auto_reason), one line a run, written
   by the sweep and quoted in bench-auto.txt */
#define BENCH_AUTO_CHOICES "bench-data/auto-choices.txt"
/* the reference's marks for pixels it leaves out (tb_reference.h), besides
   background and out of range */
#define BENCH_VIS_BACKFACING TB_VIS_BACKFACING
#define BENCH_VIS_SILHOUETTE TB_VIS_SILHOUETTE

/* -------------------------------------------------------- configurations */
typedef struct bench_cfg {
    char method[32];
    char params[160];
    skgl_shadow_desc desc;
} bench_cfg;

static int g_ncfg;
static bench_cfg g_cfg[BENCH_MAX_CFG];
/* --bias: every directional and point configuration's bias scheme (the
   default receiver plane, or the normal offset, to compare the two) */
static skgl_bias g_bias = SKGL_BIAS_RECEIVER_PLANE;

/* pcf: the radius to measure (0 = one hardware 2x2 comparison). In
   skgl_shadow_desc a zero pcf_radius means "default" (1), so 0 is asked
   for with a negative value (skgl__defaults: < 0 -> 0). */
static void add_standard(int stable, int res, int pcf) {
    bench_cfg *c = &g_cfg[g_ncfg++];
    memset(c, 0, sizeof *c);
    snprintf(c->method, sizeof c->method, "%s", stable ? "standard-stable" : "standard");
    snprintf(c->params, sizeof c->params, "resolution=%d;pcf=%d", res, pcf);
    c->desc.technique = SKGL_STANDARD;
    c->desc.resolution = res;
    c->desc.stable = stable;
    c->desc.pcf_radius = pcf;
    c->desc.disable_pcf_kernel = !(pcf > 0);
}

static void add_pssm(int cascades, float lambda, int res, float blend, int pcf) {
    bench_cfg *c = &g_cfg[g_ncfg++];
    memset(c, 0, sizeof *c);
    snprintf(c->method, sizeof c->method, "pssm");
    snprintf(c->params, sizeof c->params, "cascades=%d;lambda=%g;resolution=%d;blend=%g;pcf=%d", cascades,
             (double)lambda, res, (double)blend, pcf);
    c->desc.technique = SKGL_PSSM;
    c->desc.cascades = cascades;
    c->desc.lambda = lambda;
    c->desc.uniform_splits = !(lambda > 0.0f);
    c->desc.resolution = res;
    c->desc.blend_band = blend;
    c->desc.pcf_radius = pcf;
    c->desc.disable_pcf_kernel = !(pcf > 0);
}

/* stable cascades (desc.stable: each cascade's crop a sphere snapped to
   its texel grid), lambda 0.9 and no blend band, to set against the
   unstable rows of the same params */
static void add_pssm_stable(int cascades, int res) {
    add_pssm(cascades, 0.9f, res, 0.0f, 1);
    snprintf(g_cfg[g_ncfg - 1].method, sizeof g_cfg[0].method, "pssm-stable");
    g_cfg[g_ncfg - 1].desc.stable = 1;
}

/* PSM: slide = the virtual-camera slide in sqrt(near*far) units (< 0: plain PSM) */
static void add_psm(int res, float slide) {
    bench_cfg *c = &g_cfg[g_ncfg++];
    memset(c, 0, sizeof *c);
    snprintf(c->method, sizeof c->method, "psm");
    snprintf(c->params, sizeof c->params, "resolution=%d;slide=%g;pcf=1", res, slide < 0.0f ? 0.0 : (double)slide);
    c->desc.technique = SKGL_PSM;
    c->desc.resolution = res;
    c->desc.psm_slide = slide;
    c->desc.disable_psm_slide = slide < 0.0f;
    if (slide < 0.0f) c->desc.psm_slide = 0.0f;
}

/* LiSPSM, alone (cascades = 1) or one warp per PSSM cascade */
static void add_lispsm(int cascades, int res) {
    bench_cfg *c = &g_cfg[g_ncfg++];
    memset(c, 0, sizeof *c);
    snprintf(c->method, sizeof c->method, "%s", cascades > 1 ? "lispsm-pssm" : "lispsm");
    snprintf(c->params, sizeof c->params, "cascades=%d;lambda=0.75;resolution=%d;pcf=1", cascades, res);
    c->desc.technique = SKGL_LISPSM;
    c->desc.cascades = cascades;
    c->desc.resolution = res;
}

/* LSPSM with the paper's parameters; res per partition */
static void add_lspsm(int res) {
    bench_cfg *c = &g_cfg[g_ncfg++];
    memset(c, 0, sizeof *c);
    snprintf(c->method, sizeof c->method, "lspsm");
    snprintf(c->params, sizeof c->params, "resolution=%d;pcf=1", res);
    c->desc.technique = SKGL_LSPSM;
    c->desc.resolution = res;
}

/* FERKO: res = the maximum resolution of its estimate */
static void add_ferko(int res) {
    bench_cfg *c = &g_cfg[g_ncfg++];
    memset(c, 0, sizeof *c);
    snprintf(c->method, sizeof c->method, "ferko");
    snprintf(c->params, sizeof c->params, "max_resolution=%d;pcf=1", res);
    c->desc.technique = SKGL_FERKO;
    c->desc.resolution = res;
    /* this frame's estimate: the sweep renders the views of a configuration
       in turn, so a frame-late one would be another view's */
    c->desc.sync_readback = 1;
}

/* RMSM: a virtual map of vres^2 texels in pages of 128^2, a pool of
   pool^2 pages (24: the default, 39 MB; 48: 156 MB) */
static void add_rmsm(int vres, int pool) {
    bench_cfg *c = &g_cfg[g_ncfg++];
    memset(c, 0, sizeof *c);
    snprintf(c->method, sizeof c->method, "rmsm");
    snprintf(c->params, sizeof c->params, "virtual_resolution=%d;page=128;pool=%d;pcf=0", vres, pool);
    c->desc.technique = SKGL_RMSM;
    c->desc.resolution = vres;
    c->desc.rmsm_pool_pages = pool;
    c->desc.sync_readback = 1;   /* this view's pages (see add_ferko) */
}

/* SKGL_AUTO at a texel budget of res^2 (one map or up to 4 cascades
   sharing it, focused or warped, desc.auto_texel_px's default target of
   1 px). Its
   analysis runs each frame without a stall (sync_readback 0: the depth
   range of an earlier frame through the read-back ring, widened by 10%),
   as a game would run it; the sweep gives each view a fresh light and
   ANALYSIS_WARM frames of that view first, so that the ring has landed
   with the view's own range (analysing_async). */
static void add_auto(int res) {
    bench_cfg *c = &g_cfg[g_ncfg++];
    memset(c, 0, sizeof *c);
    snprintf(c->method, sizeof c->method, "auto");
    snprintf(c->params, sizeof c->params, "resolution=%d;cascades=4;texel_px=1;pcf=1", res);
    c->desc.technique = SKGL_AUTO;
    c->desc.resolution = res;
    c->desc.cascades = 4;
}

/* desc.fit_to_depth (sample distribution shadow maps, Lauritzen, Salvi and
   Lefohn 2011): PSSM's splits at the default .lambda (0: logarithmic over
   an analysed range, 0.75 before the first analysis), or the standard
   focused map, over the view depths the analysis found; analysed each
   frame like AUTO. Paired in bench-auto.txt with the practical scheme at
   lambda 0.75 (FIT_PAIR_LAMBDA). */
#define FIT_PAIR_LAMBDA "lambda=0.75;"
static void add_pssm_fit(int cascades, int res) {
    bench_cfg *c;
    add_pssm(cascades, 0.75f, res, 0.0f, 1);
    c = &g_cfg[g_ncfg - 1];
    snprintf(c->method, sizeof c->method, "pssm-fit");
    snprintf(c->params, sizeof c->params, "cascades=%d;lambda=0;resolution=%d;blend=0;pcf=1", cascades, res);
    c->desc.lambda = 0.0f;
    c->desc.fit_to_depth = 1;
}

static void add_standard_fit(int res) {
    add_standard(0, res, 1);
    snprintf(g_cfg[g_ncfg - 1].method, sizeof g_cfg[0].method, "standard-fit");
    g_cfg[g_ncfg - 1].desc.fit_to_depth = 1;
}

/* EVSM (skgl_shadow_desc.filter): one map or PSSM cascades, the blur's
   radius in texels */
static void add_evsm(int cascades, int res, int blur) {
    bench_cfg *c = &g_cfg[g_ncfg++];
    memset(c, 0, sizeof *c);
    snprintf(c->method, sizeof c->method, "evsm");
    snprintf(c->params, sizeof c->params, "cascades=%d;resolution=%d;blur=%d", cascades, res, blur);
    c->desc.technique = cascades > 1 ? SKGL_PSSM : SKGL_STANDARD;
    c->desc.cascades = cascades;
    c->desc.resolution = res;
    c->desc.filter = SKGL_FILTER_EVSM;
    c->desc.evsm_blur = blur;
}

/* The sweep, one entry a method: its configurations in the quick sweep
   (`make demo`) and the full one. A new method is an add_<method> above
   and one entry here (its chart series and front labels follow from the
   method name; short_label may give it a shorter label). */
static const int std_res[] = {512, 1024, 2048, 4096};
static const int pssm_res[] = {512, 1024, 2048};

static void sweep_standard(int quick) {
    int stable, r, p;
    if (quick) {
        /* the resolution ladder with both filters at two sizes, the stable map */
        for (r = 0; r < 4; r++) add_standard(0, std_res[r], 1);
        add_standard(0, 1024, 0);
        add_standard(0, 2048, 0);
        add_standard(1, 1024, 1);
        add_standard(1, 2048, 1);
        return;
    }
    for (stable = 0; stable <= 1; stable++)
        for (r = 0; r < 4; r++)
            for (p = 0; p <= 1; p++) add_standard(stable, std_res[r], p);
}

static void sweep_pssm(int quick) {
    static const float lambdas[] = {0.5f, 0.75f, 0.9f};
    static const float blends[] = {0.0f, 0.1f};
    int c, l, r, b;
    if (quick) {
        /* the cascade count at two resolutions, lambda at both ends, one blend band */
        for (c = 1; c <= 8; c *= 2) {
            add_pssm(c, 0.75f, 512, 0.0f, 1);
            add_pssm(c, 0.75f, 1024, 0.0f, 1);
        }
        add_pssm(4, 0.5f, 1024, 0.0f, 1);
        add_pssm(4, 0.9f, 1024, 0.0f, 1);
        add_pssm(4, 0.75f, 1024, 0.1f, 1);
        add_pssm_stable(4, 1024);
        return;
    }
    for (c = 2; c <= 4; c++)
        for (r = 0; r < 3; r++) add_pssm_stable(c, pssm_res[r]);
    for (c = 1; c <= SKGL_MAX_CASCADES; c++)
        for (l = 0; l < 3; l++)
            for (r = 0; r < 3; r++)
                for (b = 0; b < 2; b++) {
                    /* one cascade: lambda and the blend band change nothing */
                    if (c == 1 && (l != 1 || b != 0)) continue;
                    add_pssm(c, lambdas[l], pssm_res[r], blends[b], 1);
                }
}

static void sweep_psm(int quick) {
    static const float slides[] = {-1.0f, 0.25f, 0.5f, 1.0f};
    int r, p;
    if (quick) {
        for (r = 0; r < 3; r++) add_psm(std_res[r], 0.5f);
        add_psm(1024, -1.0f);
        return;
    }
    for (r = 0; r < 4; r++)
        for (p = 0; p < 4; p++) add_psm(std_res[r], slides[p]);
}

static void sweep_lispsm(int quick) {
    int r, c;
    for (r = 0; r < (quick ? 3 : 4); r++) add_lispsm(1, std_res[r]);
    if (quick) {
        add_lispsm(4, 512);
        add_lispsm(4, 1024);
        return;
    }
    for (c = 2; c <= 8; c *= 2)
        for (r = 0; r < 3; r++) add_lispsm(c, pssm_res[r]);
}

static void sweep_lspsm(int quick) {
    int r;
    for (r = 0; r < (quick ? 2 : 3); r++) add_lspsm(pssm_res[r]);
}

static void sweep_ferko(int quick) {
    int r;
    if (quick) {
        add_ferko(2048);
        add_ferko(4096);
        return;
    }
    for (r = 1; r < 4; r++) add_ferko(std_res[r]);
    add_ferko(8192);
}

static void sweep_rmsm(int quick) {
    if (!quick) add_rmsm(8192, 24);
    add_rmsm(16384, 24);
    if (!quick) add_rmsm(16384, 48);   /* the pool's size against the default's */
    if (!quick) add_rmsm(32768, 24);
}

static void sweep_auto(int quick) {
    int r;
    for (r = 1; r < (quick ? 3 : 4); r++) add_auto(std_res[r]);
}

/* the fitted rows mirror practical ones of sweep_pssm and sweep_standard
   (lambda 0.75, no blend band, pcf 1), which bench-auto.txt pairs them with */
static void sweep_fit(int quick) {
    int c, r;
    if (quick) {
        add_pssm_fit(4, 512);
        add_pssm_fit(4, 1024);
        add_standard_fit(2048);
        return;
    }
    for (c = 2; c <= 8; c *= 2)
        for (r = 0; r < 3; r++) add_pssm_fit(c, pssm_res[r]);
    for (r = 1; r < 4; r++) add_standard_fit(std_res[r]);
}

static void sweep_evsm(int quick) {
    static const int blurs[] = {1, 2, 4, 8};
    int r, b;
    if (quick) {
        add_evsm(1, 1024, 2);
        add_evsm(4, 1024, 2);
        return;
    }
    for (r = 1; r < 3; r++)
        for (b = 0; b < 4; b++) add_evsm(1, std_res[r], blurs[b]);
    for (b = 0; b < 3; b++) add_evsm(4, 1024, blurs[b]);
}

typedef struct bench_method {
    const char *name;              /* --methods picks by it; the rows' method starts with it */
    void (*sweep)(int quick);
} bench_method;

static const bench_method bench_methods[] = {
    {"standard", sweep_standard}, {"pssm", sweep_pssm},   {"psm", sweep_psm},   {"lispsm", sweep_lispsm},
    {"lspsm", sweep_lspsm},       {"ferko", sweep_ferko}, {"rmsm", sweep_rmsm}, {"auto", sweep_auto},
    {"fit", sweep_fit},           {"evsm", sweep_evsm},
};

/* the configurations of the methods selected by `methods` (a comma list of
   bench_methods names; NULL or "": all) */
static void build_sweep(int quick, const char *methods) {
    int m;
    g_ncfg = 0;
    for (m = 0; m < (int)(sizeof bench_methods / sizeof bench_methods[0]); m++)
        if (scene_selected(methods, bench_methods[m].name)) bench_methods[m].sweep(quick);
}

/* --match: 1 when "method params" of c holds every '+'-joined part of one
   of the comma-separated patterns ("auto,pssm+lambda=0.9;+blend=0;") */
static int cfg_matches(const bench_cfg *c, const char *patterns) {
    char text[sizeof c->method + sizeof c->params + 2], pat[256], *save = NULL, *one;
    snprintf(text, sizeof text, "%.31s %.159s", c->method, c->params);
    snprintf(pat, sizeof pat, "%s", patterns);
    for (one = strtok_r(pat, ",", &save); one; one = strtok_r(NULL, ",", &save)) {
        char *save2 = NULL, *part;
        int all = 1;
        for (part = strtok_r(one, "+", &save2); part; part = strtok_r(NULL, "+", &save2))
            if (!strstr(text, part)) all = 0;
        if (all) return 1;
    }
    return 0;
}

/* keeps the configurations --match selects, in order */
static void filter_sweep(const char *patterns) {
    int i, n = 0;
    if (!patterns || !*patterns) return;
    for (i = 0; i < g_ncfg; i++)
        if (cfg_matches(&g_cfg[i], patterns)) g_cfg[n++] = g_cfg[i];
    g_ncfg = n;
}

/* ---------------------------------------------------- the draw callback */
typedef struct draw_user {
    const tb_gl_funcs *gl;
    const tb_scene *scene;
    const tb_gl_mesh *mesh;
} draw_user;

/* positions are in world space (assimp pre-transforms); objects whose box
   misses the pass's frustum are skipped */
static void draw_casters(void *user, const skgl_draw_info *info) {
    const draw_user *u = (const draw_user *)user;
    unsigned i;
    for (i = 0; i < u->scene->object_count; i++) {
        const tb_object *o = &u->scene->objects[i];
        sk_frustum box;
        if (sk_frustum_from_aabb(o->bounds, &box) == SK_OK && !sk_frustum_intersects(&info->frustum, &box))
            continue;
        tb_gl_mesh_draw(u->gl, u->mesh, o->first_index, o->index_count);
    }
}

/* ------------------------------------------------------------- options */
typedef struct bench_opts {
    int quick, repeat, repeat_given, views, images, plot_only, dry_run, views_only, soft_only, no_floor, no_soft;
    bench_paths p;             /* --scenes, --out, --only, --gp */
    const char *methods;
    const char *match;         /* --match */
} bench_opts;

static void usage(FILE *f, const char *argv0) {
    fprintf(f,
            "usage: %s [--quick] [--repeat N] [--scenes DIR] [--out DIR] [--only SCENE[,SCENE..]]\n"
            "          [--views N] [--images] [--views-only] [--soft-only] [--bias B] [--gp FILE] [--plot-only]\n"
            "          [--methods M[,M..]] [--match P[,P..]] [--no-floor] [--no-soft] [--dry-run]\n"
            "  --quick        small sweep (make demo); also SK_BENCH_QUICK=1\n"
            "  --repeat N     timing passes, the median is reported (default 5)\n"
            "  --scenes DIR   the shared scenes (default ../shared/scenes)\n"
            "  --out DIR      output folder (default out)\n"
            "  --only LIST    only these scenes (comma separated names)\n"
            "  --methods LIST only these methods of the directional sweep (standard, pssm, psm,\n"
            "                 lispsm, lspsm, ferko, rmsm, auto, fit; default all)\n"
            "  --match LIST   of those, only the configurations whose \"method params\" hold every\n"
            "                 '+'-joined part of one pattern: auto,pssm+lambda=0.9;+blend=0;\n"
            "  --no-floor     no floor runs (the over-resolved maps of each view)\n"
            "  --no-soft      no area-light rows (PCSS, PVSM on sponza and the fence)\n"
            "  --views N      first N of the views overview,low,close (default 3)\n"
            "  --images       write reference and error PNGs per view to OUT/bench/\n"
            "  --views-only   only the reference PNGs of each view (no sweep, no CSV rows)\n"
            "  --soft-only    only the area-light rows (PCSS, PVSM; out/bench-soft.txt)\n"
            "  --bias B       directional and point lights' bias: plane (the default receiver\n"
            "                 plane) or normal (the normal offset), for comparing the two\n"
            "  --gp FILE      the gnuplot script (default bench/pareto.gp)\n"
            "  --plot-only    only redraw the charts from OUT/bench.csv\n"
            "  --dry-run      print the sweep and exit\n"
            "Environment: SK_GL=osmesa|egl picks the GL backend (default: a GPU through EGL, else OSMesa).\n",
            argv0);
}


/* ---------------------------------------------------------------- plot */
/* one chart point: a configuration on a scene, averaged over its views.
   err is the chart's y: shadow_area_pct (hard) or penumbra_mae (soft),
   averaged over the views where the reference defines it (err_n). */
typedef struct plot_pt {
    int scene;                /* index into the scene names */
    char method[32], params[160];
    double err_sum, ms_sum;
    double an_sum;            /* analysis_ms summed over the views (part of ms_sum) */
    int n;                    /* views */
    int err_n;                /* views with a y value */
    double err, ms;           /* means */
    int front;
    double texel_sum[4];      /* texel_over1/2/4_pct, texel_median_px: summed over the views */
    int texel_n;              /* views with texel figures */
} plot_pt;

typedef struct plot_data {
    plot_pt *pts;
    int npts, cap;
    char scenes[BENCH_MAX_SCENES * 4][64];
    int nscenes;
    /* per scene: the floor rows' shadow_area_pct summed over the views
       where defined, their count, and their texel_over1_pct */
    double floor_sum[BENCH_MAX_SCENES * 4], floor_texel[BENCH_MAX_SCENES * 4];
    int floor_n[BENCH_MAX_SCENES * 4], floor_texel_n[BENCH_MAX_SCENES * 4];
    char floor_what[BENCH_MAX_SCENES * 4][96];   /* which over-resolved map (floor_describe) */
    char device[512];
} plot_data;

/* what a floor row's params say the over-resolved map was: the directional
   floor's "source=..." (floor_runs), or the point lights' cube map
   (interior_floor, params as a point row's) */
static void floor_describe(const char *params, char *out, size_t n) {
    int res = 0;
    if (strncmp(params, "source=", 7) == 0 || sscanf(params, "resolution=%d", &res) != 1)
        snprintf(out, n, "the finer of RMSM 65536^2 and a standard 16384^2 map per view");
    else
        snprintf(out, n, "a cube map of %d^2 per face on every light, per view", res);
}

static int cmp_pt(const void *a, const void *b) {
    const plot_pt *p = *(const plot_pt *const *)a, *q = *(const plot_pt *const *)b;
    if (p->ms != q->ms) return p->ms < q->ms ? -1 : 1;
    if (p->err != q->err) return p->err < q->err ? -1 : 1;
    return 0;
}

/* a short label for a front point: "2048 pcf1", "stable 1024 pcf0", "4×1024 λ0.75 blend" (UTF-8) */
static void short_label(const plot_pt *p, char *buf, size_t n) {
    int res = 0, pcf = 0, casc = 0;
    double lambda = 0, blend = 0;
    const char *s;
    if ((s = strstr(p->params, "resolution="))) res = atoi(s + 11);
    if ((s = strstr(p->params, "pcf="))) pcf = atoi(s + 4);
    if ((s = strstr(p->params, "cascades="))) casc = atoi(s + 9);
    if ((s = strstr(p->params, "lambda="))) lambda = atof(s + 7);
    if ((s = strstr(p->params, "blend="))) blend = atof(s + 6);
    if (strcmp(p->method, "pcss") == 0 || strncmp(p->method, "pvsm", 4) == 0) {
        char light[16] = "";
        if ((s = strstr(p->params, "light="))) sscanf(s + 6, "%15[a-z]", light);
        if (strcmp(p->method, "pcss") == 0) snprintf(buf, n, "pcss %d %s", res, light);
        else snprintf(buf, n, "%s %s", p->method, light);
    } else if (strncmp(p->method, "cube", 4) == 0 || strncmp(p->method, "vsdct", 5) == 0 ||
               strcmp(p->method, "spot") == 0) {
        /* the point-light switches that are on: faces, casters, scissor, resolution */
        static const char *const keys[4] = {"faces=1", "casters=1", "scissor=1", "select=1"};
        static const char *const tags[4] = {" faces", " casters", " scissor", " res"};
        int k;
        size_t used = (size_t)snprintf(buf, n, "%s %d", p->method, res);
        for (k = 0; k < 4 && used < n; k++)
            if (strstr(p->params, keys[k])) used += (size_t)snprintf(buf + used, n - used, "%s", tags[k]);
    } else if (strcmp(p->method, "psm") == 0)
        snprintf(buf, n, "psm %d slide %g", res, (s = strstr(p->params, "slide=")) ? atof(s + 6) : 0.0);
    else if (strncmp(p->method, "lispsm", 6) == 0)
    {
        if (casc > 1) snprintf(buf, n, "lispsm %d\xc3\x97%d", casc, res);
        else snprintf(buf, n, "lispsm %d", res);
    }
    else if (strcmp(p->method, "ferko") == 0)
        snprintf(buf, n, "ferko max %d", (s = strstr(p->params, "max_resolution=")) ? atoi(s + 15) : 0);
    else if (strcmp(p->method, "rmsm") == 0) {
        const char *pool = strstr(p->params, "pool=");
        snprintf(buf, n, "rmsm %d", (s = strstr(p->params, "virtual_resolution=")) ? atoi(s + 19) : 0);
        if (pool && atoi(pool + 5) != 24)
            snprintf(buf + strlen(buf), n - strlen(buf), " pool %d\xc2\xb2", atoi(pool + 5));
    }
    else if (strcmp(p->method, "lspsm") == 0)
        snprintf(buf, n, "lspsm %d", res);
    else if (strcmp(p->method, "auto") == 0)
        snprintf(buf, n, "AUTO %d", res);
    else if (strcmp(p->method, "evsm") == 0) {
        int blur = (s = strstr(p->params, "blur=")) ? atoi(s + 5) : 0;
        if (casc > 1) snprintf(buf, n, "evsm %d\xc3\x97%d r%d", casc, res, blur);
        else snprintf(buf, n, "evsm %d r%d", res, blur);
    }
    else if (strcmp(p->method, "pssm-fit") == 0)
        snprintf(buf, n, "%d\xc3\x97%d fit", casc, res);
    else if (strcmp(p->method, "standard-fit") == 0)
        snprintf(buf, n, "%d fit", res);
    else if (strncmp(p->method, "pssm", 4) == 0)
        snprintf(buf, n, "%d\xc3\x97%d \xce\xbb%g%s%s", casc, res, lambda, blend > 0 ? " blend" : "",
                 strcmp(p->method, "pssm-stable") == 0 ? " stable" : "");
    else
        snprintf(buf, n, "%s%d pcf%d", strstr(p->method, "stable") ? "stable " : "", res, pcf);
}

/* splits one line of bench.csv into its BENCH_CSV_COLS fields (any may be
   quoted); returns the count, BENCH_CSV_COLS + 1 when there are more */
static int csv_split(char *line, char **f) {
    int n = 0;
    char *p = line;
    size_t l = strlen(line);
    while (l && (line[l - 1] == '\n' || line[l - 1] == '\r')) line[--l] = 0;
    for (;;) {
        if (n == BENCH_CSV_COLS) return BENCH_CSV_COLS + 1;   /* too many */
        if (*p == '"') {
            char *w = ++p;
            f[n++] = w;
            for (;;) {
                if (!*p) break;
                if (*p == '"' && p[1] == '"') { *w++ = '"'; p += 2; }
                else if (*p == '"') { p++; break; }
                else *w++ = *p++;
            }
            if (*p == ',') { *w = 0; p++; continue; }
            *w = 0;
            return n;
        } else {
            char *e = strchr(p, ',');
            f[n++] = p;
            if (!e) return n;
            *e = 0;
            p = e + 1;
        }
    }
}

static int plot_read(const char *csv, plot_data *d) {
    char line[4096];
    FILE *f = fopen(csv, "r");
    memset(d, 0, sizeof *d);
    if (!f) { fprintf(stderr, "bench: cannot read %s: %s\n", csv, strerror(errno)); return -1; }
    if (!fgets(line, sizeof line, f) || strncmp(line, BENCH_CSV_HEADER, strlen(BENCH_CSV_HEADER)) != 0) {
        fprintf(stderr, "bench: %s does not start with the bench header (%s); one without the last columns "
                        "(texel_over1_pct .. area_200_pct, or shadow_area_pct .. in an older one) comes from an older "
                        "bench: run the bench again\n", csv, BENCH_CSV_HEADER);
        fclose(f);
        return -1;
    }
    while (fgets(line, sizeof line, f)) {
        char *fld[BENCH_CSV_COLS + 1];
        const char *y;
        int si, k;
        plot_pt *p = NULL;
        char key[64];
        int soft;
        if (csv_split(line, fld) != BENCH_CSV_COLS) continue;
        soft = strcmp(fld[6], "soft_mae") == 0;
        if (!soft && strcmp(fld[6], "hard_pct") != 0) continue;
        /* soft-shadow rows chart apart: "<scene>-soft", against the total time */
        snprintf(key, sizeof key, "%.58s%s", fld[2], soft ? "-soft" : "");
        for (si = 0; si < d->nscenes; si++)
            if (strcmp(d->scenes[si], key) == 0) break;
        if (si == d->nscenes) {
            if (d->nscenes == (int)(sizeof d->scenes / sizeof d->scenes[0])) continue;
            snprintf(d->scenes[d->nscenes++], sizeof d->scenes[0], "%s", key);
        }
        snprintf(d->device, sizeof d->device, "%s", fld[13]);
        if (strcmp(fld[0], BENCH_FLOOR) == 0) {   /* the limit: a line on the chart, not a series */
            if (!d->floor_what[si][0]) floor_describe(fld[1], d->floor_what[si], sizeof d->floor_what[si]);
            if (*fld[BENCH_COL_SHADOW_AREA]) {
                d->floor_sum[si] += atof(fld[BENCH_COL_SHADOW_AREA]);
                d->floor_n[si]++;
            }
            if (*fld[BENCH_COL_TEXEL]) {
                d->floor_texel[si] += atof(fld[BENCH_COL_TEXEL]);
                d->floor_texel_n[si]++;
            }
            continue;
        }
        for (k = 0; k < d->npts; k++)
            if (d->pts[k].scene == si && strcmp(d->pts[k].method, fld[0]) == 0 &&
                strcmp(d->pts[k].params, fld[1]) == 0) {
                p = &d->pts[k];
                break;
            }
        if (!p) {
            if (d->npts == d->cap) {
                int nc = d->cap ? 2 * d->cap : 256;
                plot_pt *np = (plot_pt *)realloc(d->pts, sizeof *np * (size_t)nc);
                if (!np) { fclose(f); return -1; }
                d->pts = np;
                d->cap = nc;
            }
            p = &d->pts[d->npts++];
            memset(p, 0, sizeof *p);
            p->scene = si;
            snprintf(p->method, sizeof p->method, "%s", fld[0]);
            snprintf(p->params, sizeof p->params, "%s", fld[1]);
        }
        /* y: the shadow-area error, or the penumbra MAE; empty where the
           reference frame has no shadow (no penumbra): that view adds no y */
        y = fld[soft ? BENCH_COL_PENUMBRA_MAE : BENCH_COL_SHADOW_AREA];
        if (*y) {
            p->err_sum += atof(y);
            p->err_n++;
        }
        p->ms_sum += soft ? atof(fld[12]) : atof(fld[10]) + atof(fld[11]);   /* depth passes + analysis (FERKO) */
        if (!soft) p->an_sum += atof(fld[11]);
        p->n++;
        if (*fld[BENCH_COL_TEXEL]) {
            for (k = 0; k < 4; k++) p->texel_sum[k] += atof(fld[BENCH_COL_TEXEL + k]);
            p->texel_n++;
        }
    }
    fclose(f);
    return 0;
}

/* the data files and variables of one scene's chart, then gnuplot */
/* the mean of a point's texel column k over its views, -1 without one */
static double pt_texel(const plot_pt *p, int k) { return p->texel_n ? p->texel_sum[k] / p->texel_n : -1.0; }

/* The companion table of a chart (bench-limit.txt): every configuration in
   order of time, its error, how far it is from the scene's floor, and its
   texel-to-pixel figures, all means over the views. */
static void write_limit_table(FILE *t, const plot_data *d, int si, plot_pt *const *sel, int nsel, double floor) {
    int k;
    fprintf(t, "scene %s: floor %s", d->scenes[si], floor >= 0 ? "" : "- (no floor rows)");
    if (floor >= 0) fprintf(t, "%.3f%% (%s)", floor, d->floor_what[si]);
    if (floor >= 0 && d->floor_texel_n[si])
        fprintf(t, ", its texels over 1 px %.1f%%", d->floor_texel[si] / d->floor_texel_n[si]);
    fprintf(t, "\n  %-16s %-52s %10s %9s %9s %8s %8s %8s %8s %s\n", "method", "params", "shadow_ms", "error%",
            "-floor", "texel>1", ">2px", ">4px", "median", "front");
    for (k = 0; k < nsel; k++) {
        const plot_pt *p = sel[k];
        char gap[16] = "-";
        if (floor >= 0) snprintf(gap, sizeof gap, "%+.3f", p->err - floor);
        fprintf(t, "  %-16s %-52s %10.3f %9.3f %9s", p->method, p->params, p->ms, p->err, gap);
        if (p->texel_n)
            fprintf(t, " %7.1f%% %7.1f%% %7.1f%% %8.3f", pt_texel(p, 0), pt_texel(p, 1), pt_texel(p, 2), pt_texel(p, 3));
        else
            fprintf(t, " %8s %8s %8s %8s", "-", "-", "-", "-");
        fprintf(t, " %s\n", p->front ? "*" : "");
    }
    fputc('\n', t);
}

/* The acceptance figure of SKGL_AUTO (bench-auto.txt), per chart: each
   AUTO point; the Pareto front of the other configurations (AUTO left
   out) read as a staircase, whose time at AUTO's error is that of its
   fastest point at least as accurate; the ratio of AUTO's time to it
   (below 1: AUTO is faster than anything as accurate); whether AUTO is on
   the chart's front (every configuration); pass = on the front or within
   AUTO_FRONT_RATIO of it. Then AUTO's choice per view (BENCH_AUTO_CHOICES)
   and the fitted splits (.fit_to_depth, SDSM) against the same practical
   configuration. sel: the chart's points in order of time. */
#define AUTO_FRONT_RATIO 1.25
static double front_time_at(plot_pt *const *sel, int nsel, double err) {
    double best = 1e300;
    int k;
    for (k = 0; k < nsel; k++) {
        if (strcmp(sel[k]->method, "auto") == 0 || !(sel[k]->err < best)) continue;
        best = sel[k]->err;   /* a front point of the others */
        if (best <= err) return sel[k]->ms;
    }
    return -1.0;
}

static void write_auto_table(FILE *t, const plot_data *d, int si, plot_pt *const *sel, int nsel, const char *out_dir,
                             FILE *lab) {
    char path[1100], line[512];
    int k, j, nauto = 0, npass = 0;
    fprintf(t, "scene %s\n  %-44s %10s %11s %9s %12s %8s %6s %-5s %s\n", d->scenes[si], "AUTO params", "chart_ms",
            "analysis_ms", "error%", "front_ms@err", "ratio", "front", "pass", "ratio w/o analysis");
    for (k = 0; k < nsel; k++) {
        const plot_pt *p = sel[k];
        double ft;
        char ratio[24] = "-", fts[24] = "-", lb[64];
        int pass;
        if (strcmp(p->method, "auto") != 0) continue;
        ft = front_time_at(sel, nsel, p->err);
        if (ft > 0) {
            snprintf(fts, sizeof fts, "%.3f", ft);
            snprintf(ratio, sizeof ratio, "%.3f", p->ms / ft);
        }
        pass = p->front || ft <= 0 || p->ms / ft <= AUTO_FRONT_RATIO;
        nauto++;
        npass += pass;
        fprintf(t, "  %-44s %10.3f %11.3f %9.3f %12s %8s %6s %-5s", p->params, p->ms, p->an_sum / p->n, p->err, fts,
                ratio, p->front ? "yes" : "no", pass ? "PASS" : "MISS");
        if (ft > 0) fprintf(t, " %.3f", (p->ms - p->an_sum / p->n) / ft);
        fputc('\n', t);
        short_label(p, lb, sizeof lb);
        if (lab)
            fprintf(lab, "%.4f %.4f \"%s: %s\"\n", p->ms, p->err, lb,
                    ft > 0 ? (snprintf(fts, sizeof fts, "%.2fx front", p->ms / ft), fts) : "below the front");
    }
    if (nauto == 0) fprintf(t, "  (no AUTO rows)\n");
    else fprintf(t, "  AUTO: %d of %d points on the front or within %.2fx of its time\n", npass, nauto, AUTO_FRONT_RATIO);
    snprintf(path, sizeof path, "%.900s/" BENCH_AUTO_CHOICES, out_dir);
    {
        FILE *f = fopen(path, "r");
        size_t sl = strlen(d->scenes[si]);
        if (f) {
            fprintf(t, "  AUTO's choice per view (stats.auto_reason):\n");
            while (fgets(line, sizeof line, f))
                if (strncmp(line, d->scenes[si], sl) == 0 && line[sl] == ' ') fprintf(t, "    %s", line + sl + 1);
            fclose(f);
        }
    }
    fprintf(t, "  fitted to the depth buffer (SDSM) vs the practical split scheme, same texels:\n");
    fprintf(t, "    %-14s %-44s %9s %9s %8s %9s %9s %8s\n", "method", "params", "fit err%", "prac err%", "err x",
            "fit ms", "prac ms", "time x");
    for (k = 0; k < nsel; k++) {
        const plot_pt *p = sel[k];
        const char *base = strcmp(p->method, "pssm-fit") == 0 ? "pssm"
                           : strcmp(p->method, "standard-fit") == 0 ? "standard" : NULL;
        char want[sizeof p->params + 8];
        const char *lz;
        if (!base) continue;
        /* a pssm-fit row's "lambda=0;" pairs with the practical scheme's FIT_PAIR_LAMBDA */
        if ((lz = strstr(p->params, "lambda=0;")) != NULL)
            snprintf(want, sizeof want, "%.*s%s%s", (int)(lz - p->params), p->params, FIT_PAIR_LAMBDA, lz + 9);
        else
            snprintf(want, sizeof want, "%s", p->params);
        for (j = 0; j < nsel; j++)
            if (strcmp(sel[j]->method, base) == 0 && strcmp(sel[j]->params, want) == 0) break;
        if (j == nsel) continue;
        fprintf(t, "    %-14s %-44s %9.3f %9.3f %8.3f %9.3f %9.3f %8.3f\n", p->method, p->params, p->err, sel[j]->err,
                sel[j]->err > 0 ? p->err / sel[j]->err : 0.0, p->ms, sel[j]->ms, sel[j]->ms > 0 ? p->ms / sel[j]->ms : 0.0);
    }
    fputc('\n', t);
}

static int plot_scene(const bench_opts *o, plot_data *d, int si, int repeat, FILE *limit, FILE *autotab) {
    plot_pt **sel = (plot_pt **)malloc(sizeof *sel * (size_t)(d->npts > 0 ? d->npts : 1));
    char methods[16][32], path[1400], base[1200], list[600] = "", cmd[3000];
    int nsel = 0, nm = 0, m, k, maxn = 0, logy = 1, nfront = 0, rc = 0;
    double best = 1e300, emin = 1e300, emax = 0, tmin = 1e300, tmax = 0, floor;
    const int soft = strstr(d->scenes[si], "-soft") != NULL;
    const char *ykind = soft ? "penumbra_mae" : "shadow_area_pct";
    FILE *g;
    if (!sel) return -1;
    for (k = 0; k < d->npts; k++)
        if (d->pts[k].scene == si && d->pts[k].n > maxn) maxn = d->pts[k].n;
    for (k = 0; k < d->npts; k++) {
        plot_pt *p = &d->pts[k];
        /* only configurations seen from every view, with a y in at least one */
        if (p->scene != si || p->n < maxn || p->err_n == 0) continue;
        p->err = p->err_sum / p->err_n;
        p->ms = p->ms_sum / p->n;
        if (p->ms < 1e-3) p->ms = 1e-3;
        if (!(p->err > 0.0)) logy = 0;
        if (p->err < emin) emin = p->err;
        if (p->err > emax) emax = p->err;
        if (p->ms < tmin) tmin = p->ms;
        if (p->ms > tmax) tmax = p->ms;
        p->front = 0;
        sel[nsel++] = p;
        for (m = 0; m < nm; m++)
            if (strcmp(methods[m], p->method) == 0) break;
        if (m == nm && nm < 16) snprintf(methods[nm++], sizeof methods[0], "%s", p->method);
    }
    if (nsel == 0) { free(sel); return 0; }
    /* the limit: the floor's error, a horizontal line inside the range */
    floor = !soft && d->floor_n[si] ? d->floor_sum[si] / d->floor_n[si] : -1.0;
    if (floor >= 0.0) {
        if (!(floor > 0.0)) logy = 0;
        else if (floor < emin) emin = floor;
    }
    if (logy && emax < 4.0 * emin) logy = 0;   /* a narrow range reads better linear */
    /* Pareto front: in order of time, a point is on it when its error is
       below that of every point at least as fast */
    qsort(sel, (size_t)nsel, sizeof *sel, cmp_pt);
    for (k = 0; k < nsel; k++)
        if (sel[k]->err < best) {
            sel[k]->front = 1;
            best = sel[k]->err;
            nfront++;
        }
    snprintf(base, sizeof base, "%s/bench-data/%s", o->p.out_dir, d->scenes[si]);
    for (m = 0; m < nm; m++) {
        snprintf(path, sizeof path, "%s.%s.dat", base, methods[m]);
        if (!(g = fopen(path, "w"))) { rc = -1; continue; }
        fprintf(g, "# %s on %s, mean over %d view(s): shadow_ms %s params\n", methods[m], d->scenes[si], maxn,
                ykind);
        for (k = 0; k < nsel; k++)
            if (strcmp(sel[k]->method, methods[m]) == 0)
                fprintf(g, "%.4f %.4f %s\n", sel[k]->ms, sel[k]->err, sel[k]->params);
        fclose(g);
        if (m) strncat(list, " ", sizeof list - strlen(list) - 1);
        strncat(list, methods[m], sizeof list - strlen(list) - 1);
    }
    snprintf(path, sizeof path, "%s.front.dat", base);
    if ((g = fopen(path, "w"))) {
        /* labels only where they do not crowd the previous label: chart
           coordinates in [0,1] (log time; log or linear error) */
        double lu = -1.0, lv = -1.0, ut = log(tmax / tmin), ue = logy ? log(emax / emin) : emax;
        fprintf(g, "# Pareto front on %s: shadow_ms %s label (\"\" where it would crowd) method params\n",
                d->scenes[si], ykind);
        for (k = 0; k < nsel; k++)
            if (sel[k]->front) {
                char lab[64];
                double u = ut > 0.0 ? log(sel[k]->ms / tmin) / ut : 0.0;
                double w = ue > 0.0 ? (logy ? log(sel[k]->err / emin) : sel[k]->err) / ue : 0.0;
                short_label(sel[k], lab, sizeof lab);
                if (sel[k]->texel_n) {   /* the texel figure: pixels whose texel spans over 1 px */
                    size_t used = strlen(lab);
                    snprintf(lab + used, sizeof lab - used, " [%.0f%%]", pt_texel(sel[k], 0));
                }
                if (lu >= 0.0 && fabs(u - lu) < 0.12 && fabs(w - lv) < 0.07) lab[0] = 0;
                else { lu = u; lv = w; }
                fprintf(g, "%.4f %.4f \"%s\" %s %s\n", sel[k]->ms, sel[k]->err, lab, sel[k]->method, sel[k]->params);
            }
        fclose(g);
    } else rc = -1;
    /* AUTO's points with their distance from the front, labelled on the chart */
    snprintf(path, sizeof path, "%s.autolab.dat", base);
    g = fopen(path, "w");
    if (g) fprintf(g, "# AUTO on %s: shadow_ms %s label\n", d->scenes[si], ykind);
    if (!soft && autotab) write_auto_table(autotab, d, si, sel, nsel, o->p.out_dir, g);
    if (g) fclose(g);
    snprintf(path, sizeof path, "%s.vars.gp", base);
    if (!(g = fopen(path, "w"))) { free(sel); return -1; }
    fprintf(g, "# written by bench/bench.c; draw with: gnuplot %s %s\nscene = ", path, o->p.gp);
    gp_string(g, d->scenes[si]);
    fprintf(g, "\ndevice = ");
    gp_string(g, d->device);
    fprintf(g, "\ntiming = ");
    gp_string(g, software_renderer(d->device) ? "relative: CPU rasteriser, compare within this chart only"
                                              : "absolute GPU ms");
    fprintf(g, "\ndatabase = ");
    gp_string(g, base);
    fprintf(g, "\noutfile = ");
    snprintf(base, sizeof base, "%s/pareto-%s.png", o->p.out_dir, d->scenes[si]);
    gp_string(g, base);
    fprintf(g, "\nmethods = ");
    gp_string(g, list);
    fprintf(g, "\nnviews = %d\nrepeat = %d\nlogy = %d\nwidth = %d\nheight = %d\n", maxn, repeat, logy, BENCH_W, BENCH_H);
    fprintf(g, "soft = %d\n", soft);
    for (k = 0; k < nsel && strcmp(sel[k]->method, "auto") != 0; k++) {}
    fprintf(g, "has_auto = %d\n", k < nsel);
    fprintf(g, "tmin = %g\ntmax = %g\nemin = %g\nemax = %g\n", tmin, tmax, emin, emax);
    fprintf(g, "floor = %g\nfloor_texel = %g\nfloor_what = ", floor,
            d->floor_texel_n[si] ? d->floor_texel[si] / d->floor_texel_n[si] : -1.0);
    gp_string(g, d->floor_what[si]);
    fputc('\n', g);
    fclose(g);
    snprintf(cmd, sizeof cmd, "gnuplot '%s' '%s'", path, o->p.gp);
    if (system(cmd) != 0) {
        fprintf(stderr, "bench: gnuplot failed for %s: %s\n", d->scenes[si], cmd);
        rc = -1;
    } else {
        fprintf(stderr, "bench: chart %s (%d configurations, %d on the Pareto front)\n", base, nsel, nfront);
    }
    if (limit && !soft) write_limit_table(limit, d, si, sel, nsel, floor);
    free(sel);
    return rc;
}

/* OUT/bench-limit.txt with its header; NULL when it cannot be written */
static FILE *open_limit_table(const char *out_dir, const char *device) {
    static const char *const head =
        "# how far each configuration is from the limit, per chart (means over the views): error = "
        "shadow_area_pct; -floor = error minus the floor's (an over-resolved map's) error; texel>1, >2px, >4px = "
        "% of the shaded pixels whose shadow texel spans more than 1, 2, 4 pixels (Ferko 2013's measure), "
        "median = the median texel footprint in pixels; * = on the Pareto front";
    char path[1100];
    FILE *f;
    snprintf(path, sizeof path, "%.900s/bench-limit.txt", out_dir);
    if ((f = fopen(path, "w")) != NULL) fprintf(f, "%s\n# device %s\n\n", head, device);
    return f;
}

static int plot_all(const bench_opts *o, int repeat) {
    plot_data d;
    char csv[1100], dir[1100];
    int i, rc = 0;
    FILE *limit, *autotab;
    if (!gnuplot_ready("bench", o->p.gp)) return -1;
    snprintf(csv, sizeof csv, "%s/bench.csv", o->p.out_dir);
    if (plot_read(csv, &d) != 0) return -1;
    snprintf(dir, sizeof dir, "%s/bench-data", o->p.out_dir);
    mkdir_p(dir);
    limit = open_limit_table(o->p.out_dir, d.device);
    snprintf(dir, sizeof dir, "%.900s/bench-auto.txt", o->p.out_dir);
    if ((autotab = fopen(dir, "w")) != NULL)
        fprintf(autotab, "# SKGL_AUTO against the Pareto front, per chart (means over the views): front_ms@err = the "
                         "time of the fastest configuration other than AUTO at least as accurate as AUTO (the others' "
                         "front read as a staircase; - : none is); ratio = AUTO's time / that; front = AUTO on the "
                         "chart's front; pass = on it or ratio <= %.2f (issue 28). chart_ms = shadow_ms + analysis_ms, the "
                         "chart's time (front_ms@err likewise); ratio w/o analysis: AUTO's depth passes alone over "
                         "front_ms@err (what the ratio would be were its analysis free).\n"
                         "# device %s\n\n", AUTO_FRONT_RATIO, d.device);
    for (i = 0; i < d.nscenes; i++)
        if (plot_scene(o, &d, i, repeat, limit, autotab) != 0) rc = -1;
    if (limit) fclose(limit);
    if (autotab) fclose(autotab);
    if (d.nscenes == 0) fprintf(stderr, "bench: %s has no rows: no charts\n", csv);
    free(d.pts);
    return rc;
}

/* ------------------------------------------------------------- the sweep */
typedef struct view_data {
    bench_view v;
    tb_gl_fbo gbuf;            /* depth + normals, kept on the GPU for the mask pass */
    float *ref;                /* reference visibility */
    long covered;
    bench_receivers rc;        /* world positions and view depths (directional sweep only) */
    int *band;                 /* each pixel's view-depth band (band_edge), -1 background */
} view_data;

/* progress: runs scored, and timed renders done (the ETA unit) */
typedef struct progress {
    int done, total;
    long units, total_units;
    double t0;
} progress;

static void progress_times(const progress *pg, char *el_s, char *eta_s, size_t n) {
    double el = now_s() - pg->t0;
    double eta = pg->units > 0 ? el / (double)pg->units * (double)(pg->total_units - pg->units) : 0.0;
    fmt_duration(el, el_s, n);
    fmt_duration(eta, eta_s, n);
}

/* the result of one run (configuration x view) */
typedef struct run_rec {
    float shadow[BENCH_MAX_REPEAT];   /* shadow_ms of each timing pass */
    float analysis[BENCH_MAX_REPEAT]; /* analysis_ms (FERKO's skgl_shadow_analyze), 0 for the others */
    int n;
    float mask_ms;
    double err, texels;
    int passes;
    int state;                        /* 0 pending, 1 scored, -1 failed */
    const char *kind;                 /* error_kind: NULL hard_pct, else e.g. soft_mae */
    tb_shadow_error hard;             /* hard rows: against the reference's shadow */
    tb_penumbra_error pen;            /* soft rows: penumbra, umbra, lit */
    uint64_t excluded;                /* reference pixels marked back-facing or silhouette */
    tb_footprint_stats texel;         /* directional rows: the texel-to-pixel figure (count 0: none) */
    int has_bands;                    /* directional rows: the band counts below are set */
    uint64_t band_shadow[BENCH_BANDS], band_wrong[BENCH_BANDS];
    int maps;                         /* the stats' maps (AUTO: its choice) */
    char reason[192];                 /* AUTO: the stats' auto_reason */
} run_rec;

/* scratch of the texel-to-pixel figure (bench_texel_stats), one frame's worth */
static bench_texel_scratch g_texel;

/* pixels the reference left out for what they are (back-facing,
   silhouette), not for having no receiver */
static uint64_t count_excluded(const float *ref, size_t n) {
    uint64_t c = 0;
    size_t i;
    for (i = 0; i < n; i++) c += ref[i] == BENCH_VIS_BACKFACING || ref[i] == BENCH_VIS_SILHOUETTE;
    return c;
}

/* the scores of a hard-shadow frame: error = tb_metric_hard's covered %,
   plus tb_metric_shadow's figures for the appended columns */
static void score_hard(const float *ref, const float *res, run_rec *rr) {
    rr->err = tb_metric_hard(ref, res, (size_t)BENCH_W * BENCH_H).pct;
    rr->hard = tb_metric_shadow(ref, res, BENCH_W, BENCH_H);
    rr->excluded = count_excluded(ref, (size_t)BENCH_W * BENCH_H);
    if (!rr->hard.ok) fprintf(stderr, "bench: tb_metric_shadow failed (out of memory): shadow columns left empty\n");
}

/* the scores of a soft-shadow frame: error = tb_metric_soft's covered mae,
   plus tb_metric_penumbra's */
static void score_soft(const float *ref, const float *res, run_rec *rr) {
    rr->err = tb_metric_soft(ref, res, (size_t)BENCH_W * BENCH_H).mae;
    rr->pen = tb_metric_penumbra(ref, res, BENCH_W, BENCH_H, BENCH_PENUMBRA_GROW);
    rr->excluded = count_excluded(ref, (size_t)BENCH_W * BENCH_H);
    if (!rr->pen.ok) fprintf(stderr, "bench: tb_metric_penumbra failed (out of memory): penumbra columns left empty\n");
}

/* the mask of the map just rendered for this view, read back and scored */
static int score_run(bench_gl *B, skgl_shadow *sh, view_data *vd, float *mask_px, run_rec *rr, const char **why) {
    const skgl_shadow_frame_stats *st;
    sk_result r = skgl_shadow_mask(B->sk, sh, &vd->v.cam, vd->gbuf.depth_tex, vd->gbuf.color_tex, B->mask.color_tex);
    if (r != SK_OK) { *why = "skgl_shadow_mask"; return -1; }
    if (tb_gl_read_red(&B->gl, B->mask.fbo, BENCH_W, BENCH_H, mask_px) != 0) { *why = "mask readback"; return -1; }
    st = skgl_shadow_stats(sh);
    rr->mask_ms = st->mask_ms;
    rr->texels = st->texels;
    rr->passes = st->passes;
    rr->maps = st->maps;
    if (skgl_shadow_get_desc(sh).technique == SKGL_AUTO)
        snprintf(rr->reason, sizeof rr->reason, "%s", st->auto_reason);
    score_hard(vd->ref, mask_px, rr);
    if (vd->rc.world) rr->texel = bench_texel_stats(sh, &vd->rc, vd->ref, &g_texel);
    if (vd->band)
        rr->has_bands = tb_metric_shadow_bands(vd->ref, mask_px, vd->band, (size_t)BENCH_W * BENCH_H, BENCH_BANDS,
                                               rr->band_shadow, rr->band_wrong) == 0;
    return 0;
}

/* one CSV row of a scored run */
static void write_row(FILE *csv, const char *method, const char *params, const char *scene, const char *view,
                      const run_rec *rr, float sms, const char *renderer) {
    float tmp[BENCH_MAX_REPEAT], ams;
    int b;
    memcpy(tmp, rr->analysis, sizeof tmp);
    ams = rr->n > 0 ? median(tmp, rr->n) : 0.0f;
    csv_field(csv, method);
    fputc(',', csv);
    csv_field(csv, params);
    fputc(',', csv);
    csv_field(csv, scene);
    fputc(',', csv);
    csv_field(csv, view);
    fprintf(csv, ",%d,%d,%s,%.*f,%.0f,%d,%.4f,%.4f,%.4f,", BENCH_W, BENCH_H, rr->kind ? rr->kind : "hard_pct",
            rr->kind ? 6 : 4, rr->err, rr->texels, rr->passes, (double)sms, (double)ams,
            (double)(sms + ams + rr->mask_ms));
    csv_field(csv, renderer);
    /* the appended columns: hard ones, soft ones (empty where they do not
       apply), excluded_px */
    if (!rr->kind && rr->hard.ok) {
        const tb_shadow_error *h = &rr->hard;
        if (h->shadow > 0)
            fprintf(csv, ",%.4f,%.4f,%.4f", h->area_pct, h->false_shadow_pct, h->false_light_pct);
        else
            fputs(",,,", csv);
        if (h->wrong == 0 || h->edge_count > 0)
            fprintf(csv, ",%.4f,%.4f", h->edge_mean_px, h->edge_p95_px);
        else
            fputs(",,", csv);
        fprintf(csv, ",%.4f", h->covered_pct);
    } else {
        fputs(",,,,,,", csv);
    }
    if (rr->kind && rr->pen.ok) {
        const tb_penumbra_error *q = &rr->pen;
        if (q->penumbra > 0) fprintf(csv, ",%.6f,%.6f", q->penumbra_mae, q->penumbra_max);
        else fputs(",,", csv);
        if (q->umbra > 0) fprintf(csv, ",%.6f", q->umbra_mae);
        else fputc(',', csv);
        if (q->lit > 0) fprintf(csv, ",%.6f", q->lit_mae);
        else fputc(',', csv);
    } else {
        fputs(",,,,", csv);
    }
    fprintf(csv, ",%llu", (unsigned long long)rr->excluded);
    /* the texel-to-pixel figure, the shadow-area error by view-depth band
       (empty where a band has no reference shadow) */
    if (rr->texel.count > 0)
        fprintf(csv, ",%.3f,%.3f,%.3f,%.4f", rr->texel.over1_pct, rr->texel.over2_pct, rr->texel.over4_pct,
                rr->texel.median);
    else
        fputs(",,,,", csv);
    for (b = 0; b < BENCH_BANDS; b++)
        if (rr->has_bands && rr->band_shadow[b] > 0)
            fprintf(csv, ",%.4f", 100.0 * (double)rr->band_wrong[b] / (double)rr->band_shadow[b]);
        else
            fputc(',', csv);
    fputc('\n', csv);
}

/* On a CPU rasteriser the directional passes are timed by the wall clock
   between two glFinish calls, not by timer queries: llvmpipe reports a
   single-layer depth pass at about 1/50 of its wall time (a 2048^2 map of
   the bunny: 0.4 ms by the query, 30 ms between the glFinish calls), while
   passes that switch framebuffers inside the query (cascades, pages) agree
   with the wall clock. On a GPU the queries are what is reported. */
static int g_wall_timing;

static double bench_wall_ms(bench_gl *B, double *t) {
    double now;
    B->gl.Finish();
    now = now_s();
    double ms = (now - *t) * 1e3;
    *t = now;
    return ms;
}

/* the shadow_ms of the last render: the wall clock's or the query's */
static float g_last_render_ms;
static float render_ms(skgl_shadow *sh) {
    return g_wall_timing ? g_last_render_ms : skgl_shadow_stats(sh)->shadow_ms;
}

/* 1 when a light analyses the view's depth buffer before each render */
static int analyses(const skgl_shadow_desc *d) {
    return d->technique == SKGL_FERKO || d->technique == SKGL_RMSM || d->technique == SKGL_AUTO || d->fit_to_depth;
}

/* analysing through the read-back ring (an earlier frame's figures): the
   sweep warms such a light up on each view (ANALYSIS_WARM frames) */
#define ANALYSIS_WARM 2
static int analysing_async(const skgl_shadow_desc *d) { return analyses(d) && !d->sync_readback; }

/* one frame's shadow work: FERKO, RMSM, AUTO and .fit_to_depth first analyse
   the view's depth buffer; *analysis_ms gets that pass's time (0 for the
   other methods) */
static sk_result render_frame(bench_gl *B, skgl_shadow *sh, const view_data *vd, const skgl_scene *sc,
                              sk_vec3 light_dir, float *analysis_ms) {
    skgl_shadow_desc d = skgl_shadow_get_desc(sh);
    double clock = 0.0;
    sk_result r;
    *analysis_ms = 0.0f;
    if (g_wall_timing) bench_wall_ms(B, &clock);
    if (analyses(&d)) {
        r = skgl_shadow_analyze(B->sk, sh, &vd->v.cam, sc, light_dir, vd->gbuf.depth_tex);
        if (r != SK_OK) return r;
        *analysis_ms = g_wall_timing ? (float)bench_wall_ms(B, &clock) : skgl_shadow_stats(sh)->analysis_ms;
    }
    r = skgl_shadow_render(B->sk, sh, &vd->v.cam, sc, light_dir);
    if (g_wall_timing) g_last_render_ms = (float)bench_wall_ms(B, &clock);
    return r;
}

/* each pixel's view-depth band (band_edge), -1 for the background */
static int *depth_bands(const bench_receivers *rc) {
    size_t i, n = (size_t)rc->w * (size_t)rc->h;
    int *band = (int *)malloc(sizeof(int) * n), k;
    if (!band) return NULL;
    for (i = 0; i < n; i++) {
        band[i] = -1;
        for (k = 0; k < BENCH_BANDS && rc->view_depth[i] >= 0.0f; k++)
            if (rc->view_depth[i] < band_edge[k + 1]) { band[i] = k; break; }
    }
    return band;
}

/* G-buffer (the forest's when forest is given) and reference of one view;
   for a directional light (area NULL)
   also its receivers (the texel-to-pixel figure) and view-depth bands.
   0 ok; free with free_view either way. */
static int prepare_view(bench_gl *B, const tb_gl_mesh *mesh, const bench_forest *forest, const tb_reference *ref,
                        sk_vec3 light_dir, const tb_light *area, view_data *vd, float *depth, float *rgba,
                        float *nrm) {
    tb_light L;
    size_t i, n = (size_t)BENCH_W * BENCH_H;
    if (tb_gl_fbo_create(&B->gl, &vd->gbuf, BENCH_W, BENCH_H, TB_GL_COLOR_RGBA16F) != 0) return -1;
    if (forest ? bench_forest_gbuffer(B, forest, &vd->gbuf, &vd->v.view_proj) != 0
               : tb_gl_gbuffer_render(&B->gl, &B->gb, mesh, &vd->gbuf, &vd->v.view_proj) != 0)
        return -1;
    if (tb_gl_read_depth(&B->gl, vd->gbuf.fbo, BENCH_W, BENCH_H, depth) != 0) return -1;
    if (tb_gl_read_normals(&B->gl, vd->gbuf.fbo, BENCH_W, BENCH_H, rgba, nrm) != 0) return -1;
    memset(&L, 0, sizeof L);
    L.type = TB_LIGHT_DIRECTIONAL;
    L.direction = light_dir;
    if (area) L = *area;
    vd->ref = (float *)malloc(sizeof(float) * n);
    if (!vd->ref || bench_trace(ref, &vd->v.view_proj, depth, nrm, &L, vd->ref) != 0) return -1;
    vd->covered = 0;
    for (i = 0; i < n; i++)
        if (vd->ref[i] >= 0.0f) vd->covered++;
    if (area) return 0;
    if (bench_receivers_init(&vd->rc, BENCH_W, BENCH_H, &vd->v.view_proj, &vd->v.cam.view, depth) != 0) return -1;
    return (vd->band = depth_bands(&vd->rc)) != NULL ? 0 : -1;
}

static void free_view(bench_gl *B, view_data *vd) {
    if (vd->gbuf.fbo) tb_gl_fbo_destroy(&B->gl, &vd->gbuf);
    free(vd->ref);
    free(vd->band);
    bench_receivers_free(&vd->rc);
    memset(vd, 0, sizeof *vd);
}

/* a shaded picture of the reference: grey * (ambient + direct * visibility), sky blue background */
static void write_shaded(const char *path, const float *vis, const float *nrm, sk_vec3 light_dir) {
    size_t i, n = (size_t)BENCH_W * BENCH_H;
    unsigned char *rgb = (unsigned char *)malloc(3 * n);
    if (!rgb) return;
    for (i = 0; i < n; i++) {
        unsigned char *p = rgb + 3 * i;
        if (vis[i] < 0.0f) { p[0] = 150; p[1] = 180; p[2] = 220; continue; }
        {
            float nl = -(nrm[3 * i] * light_dir.x + nrm[3 * i + 1] * light_dir.y + nrm[3 * i + 2] * light_dir.z);
            float c = 0.25f + 0.75f * vis[i] * (nl > 0.0f ? nl : 0.0f);
            p[0] = (unsigned char)(235.0f * c);
            p[1] = (unsigned char)(225.0f * c);
            p[2] = (unsigned char)(205.0f * c);
        }
    }
    tb_image_write_rgb8(path, BENCH_W, BENCH_H, rgb);
    free(rgb);
}

/* ------------------------------------------------------- point lights */
/* The room scene with a point light (King and Newhall 2004): the native cube map and
   VSDCT, each of the seed's optimizations alone and all together, against
   the naive cube map (six faces, every caster, full resolution, the whole
   screen). Views: "inside" (the light in the view, all faces visible),
   "away" (the light behind the camera: faces culled; its range still
   covers the room), "torch" (a small light far off, small on the
   screen: scissor and resolution selection), "outside" (a small light
   beside and behind the camera, reaching into the view).
   Rows as the directional ones; shadow_ms is the six-face depth pass,
   total_ms adds the mask pass (the lighting pass a point light needs).
   Methods: cube-naive, cube (params say which optimizations are on),
   vsdct. */
typedef struct point_cfg {
    const char *method;
    skgl_point_technique technique;
    int faces, casters, scissor, select;
} point_cfg;

static const point_cfg point_cfgs[] = {
    {"cube-naive", SKGL_POINT_CUBE, 0, 0, 0, 0},
    {"cube", SKGL_POINT_CUBE, 1, 0, 0, 0},
    {"cube", SKGL_POINT_CUBE, 0, 1, 0, 0},
    {"cube", SKGL_POINT_CUBE, 0, 0, 1, 0},
    {"cube", SKGL_POINT_CUBE, 0, 0, 0, 1},
    {"cube", SKGL_POINT_CUBE, 1, 1, 1, 1},
    {"vsdct", SKGL_POINT_VSDCT, 0, 0, 0, 0},
    {"vsdct", SKGL_POINT_VSDCT, 1, 1, 1, 0},
    {"vsdct", SKGL_POINT_VSDCT, 1, 1, 1, 1},
};

typedef struct point_view {
    const char *name;
    float eye[3], target[3], light[3], range;
} point_view;

static const point_view point_views[] = {
    {"inside", {4.2f, 3.2f, 4.2f}, {-1.0f, 1.0f, -1.0f}, {0.5f, 2.0f, 0.5f}, 8.0f},
    {"away", {3.2f, 1.7f, -1.8f}, {4.9f, 1.0f, -4.9f}, {0.5f, 2.0f, 0.5f}, 8.0f},
    {"torch", {4.5f, 2.5f, 4.5f}, {-3.0f, 1.0f, -3.0f}, {-3.6f, 1.0f, -3.2f}, 2.5f},
    {"outside", {0.5f, 2.0f, 4.8f}, {2.5f, 1.2f, -5.0f}, {-4.2f, 1.5f, -1.0f}, 2.0f},
};

/* the face side of the room's and the interior's point-light rows */
#define POINT_RES 512

static void point_draw_casters(void *user, const skgl_draw_info *info) {
    const draw_user *u = (const draw_user *)user;
    unsigned i;
    for (i = 0; i < u->scene->object_count; i++) {
        const tb_object *o = &u->scene->objects[i];
        if (skgl_point_caster_visible(info, o->bounds)) tb_gl_mesh_draw(u->gl, u->mesh, o->first_index, o->index_count);
    }
}

/* the most lights a room_bench shadows at once (the interior's) */
#define ROOM_MAX_LIGHTS TB_INTERIOR_LIGHTS

/* What the room's point- and spot-light rows and the interior's share: the
   scene, its mesh and exact reference, the casters drawn through
   point_draw_casters, the mask's value before each pass, and the reference
   visibility of the view being scored (refv: nlights images of BENCH_W x
   BENCH_H, light l's at refv + l * BENCH_W * BENCH_H). */
typedef struct room_bench {
    bench_gl *B;
    const char *scene;     /* the rows' scene column: "room", "room-spot", "interior" */
    int nlights;           /* lights shadowed every frame, 1 to ROOM_MAX_LIGHTS */
    float mask_clear;      /* 1 (the point rows): a scissored pass leaves the rest lit; 0 (the spot
                              rows): nothing outside a spot's scissor is lit by it */
    int reps;              /* timed passes after the warm-up */
    FILE *csv;
    float *depth, *mask_px;
    float *rgba, *nrm;     /* the G-buffer's normals read back (the reference's same-face test) */
    tb_scene s;
    tb_gl_mesh mesh;
    tb_reference *ref;
    draw_user du;
    skgl_scene sc;
    float *refv;
} room_bench;

static void room_bench_close(room_bench *R) {
    free(R->refv);
    free(R->rgba);
    free(R->nrm);
    tb_reference_destroy(R->ref);
    if (R->mesh.vao) tb_gl_mesh_destroy(&R->B->gl, &R->mesh);
    tb_scene_free(&R->s);
}

/* The scene `build` makes, for the rows of `scene` with nlights lights
   (1 to ROOM_MAX_LIGHTS); depth and mask_px are the caller's scratch
   images. 0 ok (room_bench_close frees it); -1: the rows are said skipped
   on stderr and nothing is held. */
static int room_bench_open(room_bench *R, bench_gl *B, const char *scene, int (*build)(tb_scene *), int nlights,
                           float mask_clear, int repeat, FILE *csv, float *depth, float *mask_px) {
    memset(R, 0, sizeof *R);
    R->B = B;
    R->scene = scene;
    R->nlights = nlights < 1 ? 1 : nlights > ROOM_MAX_LIGHTS ? ROOM_MAX_LIGHTS : nlights;
    R->mask_clear = mask_clear;
    R->reps = repeat < 1 ? 1 : repeat > BENCH_MAX_REPEAT ? BENCH_MAX_REPEAT : repeat;
    R->csv = csv;
    R->depth = depth;
    R->mask_px = mask_px;
    R->refv = (float *)malloc(sizeof(float) * BENCH_W * BENCH_H * (size_t)R->nlights);
    R->rgba = (float *)malloc(sizeof(float) * 4 * BENCH_W * BENCH_H);
    R->nrm = (float *)malloc(sizeof(float) * 3 * BENCH_W * BENCH_H);
    tb_scene_init(&R->s);
    if (!R->refv || !R->rgba || !R->nrm || build(&R->s) != 0 || tb_gl_mesh_create(&B->gl, &R->mesh, &R->s) != 0 ||
        !(R->ref = tb_reference_create(&R->s))) {
        fprintf(stderr, "bench: %s scene setup failed: its rows skipped\n", scene);
        room_bench_close(R);
        return -1;
    }
    R->du.gl = &B->gl;
    R->du.scene = &R->s;
    R->du.mesh = &R->mesh;
    R->sc.draw = point_draw_casters;
    R->sc.user = &R->du;
    R->sc.bounds = R->s.bounds;
    return 0;
}

/* One view of the room: its camera, its G-buffer (its depth in R->depth),
   the view the reference traced and the lights it traced. */
typedef struct room_view {
    bench_view bv;
    tb_gl_fbo gbuf;
    tb_view tv;
    sk_vec3 lp[ROOM_MAX_LIGHTS];
    float range[ROOM_MAX_LIGHTS];
} room_view;

/* The view `name` from eye to target, and in R->refv the exact visibility
   of R->nlights point lights, light l at lp[l] reaching range[l]. 0 ok
   (room_view_close frees it); -1: the view is skipped and nothing is held. */
static int room_view_open(room_bench *R, room_view *V, const char *name, const float eye[3], const float target[3],
                          const sk_vec3 *lp, const float *range) {
    bench_gl *B = R->B;
    tb_light L;
    tb_ref_options opt;
    int l, bad;
    memset(V, 0, sizeof *V);
    snprintf(V->bv.name, sizeof V->bv.name, "%s", name);
    V->bv.eye = v3(eye[0], eye[1], eye[2]);
    V->bv.target = v3(target[0], target[1], target[2]);
    finish_view(&V->bv, &R->s.bounds);
    if (tb_gl_fbo_create(&B->gl, &V->gbuf, BENCH_W, BENCH_H, TB_GL_COLOR_RGBA16F) != 0 ||
        tb_gl_gbuffer_render(&B->gl, &B->gb, &R->mesh, &V->gbuf, &V->bv.view_proj) != 0 ||
        tb_gl_read_depth(&B->gl, V->gbuf.fbo, BENCH_W, BENCH_H, R->depth) != 0 ||
        tb_gl_read_normals(&B->gl, V->gbuf.fbo, BENCH_W, BENCH_H, R->rgba, R->nrm) != 0) {
        fprintf(stderr, "bench: %s view %s: G-buffer failed\n", R->scene, name);
        if (V->gbuf.fbo) tb_gl_fbo_destroy(&B->gl, &V->gbuf);
        return -1;
    }
    V->tv.width = BENCH_W;
    V->tv.height = BENCH_H;
    bad = !sk_mat4_inverse(V->bv.view_proj, &V->tv.inv_view_proj);
    memset(&opt, 0, sizeof opt);
    opt.raster_normals = R->nrm;
    for (l = 0; l < R->nlights && !bad; l++) {
        memset(&L, 0, sizeof L);
        L.type = TB_LIGHT_POINT;
        L.position = V->lp[l] = lp[l];
        L.range = V->range[l] = range[l];
        bad = tb_reference_trace_exact(R->ref, &V->tv, R->depth, &L, &opt, R->refv + (size_t)l * BENCH_W * BENCH_H,
                                       NULL) != 0;
    }
    if (bad) {
        tb_gl_fbo_destroy(&B->gl, &V->gbuf);
        return -1;
    }
    return 0;
}

static void room_view_close(room_bench *R, room_view *V) { tb_gl_fbo_destroy(&R->B->gl, &V->gbuf); }

/* one room row as run_room_row measured it */
typedef struct room_row {
    run_rec rr;                    /* the masks' median time, texels, passes and scores against R->refv
                                      (summed / pooled over the lights) */
    float shadow_ms;               /* the median shadow time (the lights' face passes summed) */
    skgl_point_frame_stats st;     /* the last frame's; with several lights the counts summed over
                                      them and the resolution the largest */
    char params[160];              /* the configuration only, so that a chart point is a mean over views:
                                      what the culling found goes to stderr, a spot's cone is its view's */
} room_row;

/* light `one`'s hard scores added into `sum`, which holds the lights
   before it: the pixel counts summed and the percentages taken over the
   sums (test_gl_interior's pooled error), the edge mean weighted by the
   lights' edge pixels, the edge p95 the largest light's */
static void pool_hard(run_rec *sum, const run_rec *one) {
    tb_shadow_error *s = &sum->hard;
    const tb_shadow_error *o = &one->hard;
    double edge = s->edge_mean_px * (double)s->edge_count + o->edge_mean_px * (double)o->edge_count;
    sum->excluded += one->excluded;
    if (!s->ok || !o->ok) {
        memset(s, 0, sizeof *s);
        sum->err = 0.0;
        return;
    }
    s->covered += o->covered;
    s->shadow += o->shadow;
    s->lit += o->lit;
    s->wrong += o->wrong;
    s->false_shadow += o->false_shadow;
    s->false_light += o->false_light;
    s->invalid += o->invalid;
    s->edge_count += o->edge_count;
    s->edge_mean_px = s->edge_count ? edge / (double)s->edge_count : 0.0;
    if (o->edge_p95_px > s->edge_p95_px) s->edge_p95_px = o->edge_p95_px;
    s->area_pct = s->shadow ? 100.0 * (double)s->wrong / (double)s->shadow : 0.0;
    s->false_shadow_pct = s->shadow ? 100.0 * (double)s->false_shadow / (double)s->shadow : 0.0;
    s->false_light_pct = s->shadow ? 100.0 * (double)s->false_light / (double)s->shadow : 0.0;
    s->covered_pct = s->covered ? 100.0 * (double)s->wrong / (double)s->covered : 0.0;
    sum->err = s->covered_pct;
}

/* light l's stats of the frame added into *sum (light 0's copied) */
static void sum_point_stats(skgl_point_frame_stats *sum, const skgl_point_frame_stats *st, int l) {
    if (l == 0) {
        *sum = *st;
        return;
    }
    sum->shadow_ms += st->shadow_ms;
    sum->mask_ms += st->mask_ms;
    sum->texels += st->texels;
    sum->passes += st->passes;
    if (st->resolution > sum->resolution) sum->resolution = st->resolution;
    sum->faces_rendered += st->faces_rendered;
    sum->faces_culled += st->faces_culled;
    sum->casters_drawn += st->casters_drawn;
    sum->casters_culled += st->casters_culled;
}

/* Light l's mask of V's G-buffer into B->mask cleared to R->mask_clear;
   on the scored frame read back and its scores pooled into out->rr */
static sk_result room_light_mask(room_bench *R, const room_view *V, skgl_point *p, int l, int scored, room_row *out) {
    bench_gl *B = R->B;
    sk_result r;
    tb_gl_fbo_bind(&B->gl, &B->mask);
    B->gl.ClearColor(R->mask_clear, R->mask_clear, R->mask_clear, R->mask_clear);
    B->gl.Clear(0x00004000u);
    tb_gl_fbo_bind(&B->gl, NULL);
    r = skgl_point_mask(B->sk, p, &V->bv.cam, V->gbuf.depth_tex, V->gbuf.color_tex, B->mask.color_tex);
    if (r != SK_OK || !scored) return r;
    if (tb_gl_read_red(&B->gl, B->mask.fbo, BENCH_W, BENCH_H, R->mask_px) != 0) return SK_ERR_GL;
    if (l == 0) {
        score_hard(R->refv, R->mask_px, &out->rr);
    } else {
        run_rec one;
        memset(&one, 0, sizeof one);
        score_hard(R->refv + (size_t)l * BENCH_W * BENCH_H, R->mask_px, &one);
        pool_hard(&out->rr, &one);
    }
    return SK_OK;
}

/* R->nlights lights of desc d (the technique, resolution, spot angle and
   optimizations; each light's range V's, the bias and the screen set
   here), light l at V->lp[l], over view V: R->reps + 1 frames, the first a
   warm-up, each rendering every light (skgl_spot_render along *spot_dir,
   or skgl_point_render without one) before each light's mask
   (room_light_mask); the last frame's masks scored against their
   references, pooled, and written as a row of `method` to R->csv, its
   shadow_ms the median over the timed frames of the lights' face passes
   summed. 0 ok; -1 said on stderr, no row. */
static int run_room_row(room_bench *R, const room_view *V, const char *method, const skgl_point_desc *d,
                        const sk_vec3 *spot_dir, room_row *out) {
    bench_gl *B = R->B;
    skgl_point *p[ROOM_MAX_LIGHTS];
    float sms[BENCH_MAX_REPEAT], mms[BENCH_MAX_REPEAT];
    sk_result r = SK_OK;
    int k, l, made = 0;
    for (l = 0; l < R->nlights && r == SK_OK; l++) {
        skgl_point_desc dd = *d;
        dd.range = V->range[l];
        dd.bias = g_bias;
        dd.screen_w = BENCH_W;
        dd.screen_h = BENCH_H;
        p[l] = NULL;
        r = skgl_point_create(B->sk, &dd, &p[l]);
        made += r == SK_OK;
    }
    if (r != SK_OK) {
        fprintf(stderr, "bench: skgl_point_create %s: %s (%s)\n", method, sk_result_string(r), skgl_error_log(B->sk));
        for (l = 0; l < made; l++) skgl_point_destroy(B->sk, p[l]);
        return -1;
    }
    memset(&out->rr, 0, sizeof out->rr);
    for (k = 0; k <= R->reps && r == SK_OK; k++) {   /* one warm-up, then the timed ones */
        for (l = 0; l < R->nlights && r == SK_OK; l++)
            r = spot_dir ? skgl_spot_render(B->sk, p[l], &V->bv.cam, &R->sc, V->lp[l], *spot_dir)
                         : skgl_point_render(B->sk, p[l], &V->bv.cam, &R->sc, V->lp[l]);
        for (l = 0; l < R->nlights && r == SK_OK; l++) {
            r = room_light_mask(R, V, p[l], l, k == R->reps, out);
            if (r == SK_OK) sum_point_stats(&out->st, skgl_point_stats(p[l]), l);
        }
        if (r == SK_OK && k > 0) {
            sms[k - 1] = out->st.shadow_ms;
            mms[k - 1] = out->st.mask_ms;
        }
    }
    for (l = 0; l < R->nlights; l++) skgl_point_destroy(B->sk, p[l]);
    if (r != SK_OK) {
        fprintf(stderr, "bench: %s on %s %s failed: %s\n", method, R->scene, V->bv.name, skgl_error_log(B->sk));
        return -1;
    }
    out->rr.mask_ms = median(mms, R->reps);
    out->rr.texels = out->st.texels;
    out->rr.passes = out->st.passes;
    out->shadow_ms = median(sms, R->reps);
    snprintf(out->params, sizeof out->params, "resolution=%d;pcf=1;faces=%d;casters=%d;scissor=%d;select=%d",
             d->resolution, d->cull_faces, d->cull_casters, d->scissor, d->select_resolution);
    write_row(R->csv, method, out->params, R->scene, V->bv.name, &out->rr, out->shadow_ms, B->renderer);
    return 0;
}

/* the desc of a point light of technique t at res per face with King and
   Newhall's optimizations as given (the rest run_room_row sets) */
static skgl_point_desc point_desc(skgl_point_technique t, int res, int faces, int casters, int scissor, int select) {
    const skgl_point_desc d = {.technique = t, .resolution = res, .cull_faces = faces, .cull_casters = casters,
                               .scissor = scissor, .select_resolution = select};
    return d;
}

/* Every configuration of point_cfgs at `resolution` per face over view V
   of R, a row each; stderr says what culling and selection did and the
   time against the naive cube map's (the first configuration). */
/* point_cfgs[first..last] at face side `resolution` */
static void run_point_cfgs_range(room_bench *R, const room_view *V, int resolution, int first, int last) {
    double naive_total = 0.0;
    int c;
    for (c = first; c <= last; c++) {
        const point_cfg *pc = &point_cfgs[c];
        skgl_point_desc d = point_desc(pc->technique, resolution, pc->faces, pc->casters, pc->scissor, pc->select);
        room_row w;
        if (run_room_row(R, V, pc->method, &d, NULL, &w) != 0) continue;
        if (c == 0) naive_total = w.shadow_ms + w.rr.mask_ms;
        fprintf(stderr, "bench: %s %-6s %-10s %s: face %d^2, %d faces rendered, %d culled, %d casters culled: err "
                        "%.3f%% (shadow area %.3f%%, edge p95 %.2f px) shadow %.2f ms mask %.2f ms",
                R->scene, V->bv.name, pc->method, w.params, w.st.resolution, w.st.faces_rendered, w.st.faces_culled,
                w.st.casters_culled, w.rr.err, w.rr.hard.area_pct, w.rr.hard.edge_p95_px, (double)w.shadow_ms,
                (double)w.rr.mask_ms);
        if (naive_total > 0) fprintf(stderr, " (%.2fx naive)", (w.shadow_ms + w.rr.mask_ms) / naive_total);
        fputc('\n', stderr);
    }
    fflush(R->csv);
}

static void run_point_cfgs(room_bench *R, const room_view *V, int resolution) {
    run_point_cfgs_range(R, V, resolution, 0, (int)(sizeof point_cfgs / sizeof point_cfgs[0]) - 1);
}

static void point_bench(bench_gl *B, int repeat, FILE *csv, float *depth, float *mask_px) {
    room_bench R;
    int v;
    if (room_bench_open(&R, B, "room", tb_scene_build_room, 1, 1.0f, repeat, csv, depth, mask_px) != 0) return;
    for (v = 0; v < (int)(sizeof point_views / sizeof point_views[0]); v++) {
        const point_view *pv = &point_views[v];
        room_view V;
        sk_vec3 lp = v3(pv->light[0], pv->light[1], pv->light[2]);
        if (room_view_open(&R, &V, pv->name, pv->eye, pv->target, &lp, &pv->range) != 0) continue;
        run_point_cfgs(&R, &V, POINT_RES);
        room_view_close(&R, &V);
    }
    room_bench_close(&R);
}

/* ------------------------------------------------------------ interior */
/* The interior (tb_scene_build_interior; scene "interior" in bench.csv,
   its own chart, pareto-interior.png; --only interior runs it alone): six
   rooms and a corridor, TB_INTERIOR_LIGHTS point lights, one a room, each
   reaching through its doors into the corridor and other rooms (King and
   Newhall 2004's regime: most of a light's range behind walls). Every
   frame shadows all of them as a multi-light renderer does: every light
   rendered, then each light's mask. Views: the testbed's head-height
   cameras through doorways (tb_interior_view), the first INTERIOR_VIEWS of
   them (--quick: the first), named v0, v1, ... Each point_cfgs configuration at POINT_RES per face,
   every light its own map (the bench has no shared-atlas method). A row is
   one view: its error pools the lights' masks against their exact
   references (the misclassified pixels of every light over the shadowed
   ones of every light, as test_gl_interior scores), shadow_ms sums the
   lights' face passes, texels and passes sum over the lights. The floor
   row of a view: the naive cube map at INTERIOR_FLOOR_RES per face on
   every light (the limit line of the chart). */
#define INTERIOR_VIEWS 3
#define INTERIOR_FLOOR_RES 2048

static void interior_floor(room_bench *R, const room_view *V) {
    skgl_point_desc d = point_desc(SKGL_POINT_CUBE, INTERIOR_FLOOR_RES, 0, 0, 0, 0);
    room_row w;
    int reps = R->reps;
    R->reps = 1;   /* a limit, not a timing: one timed frame after the warm-up */
    if (run_room_row(R, V, BENCH_FLOOR, &d, NULL, &w) == 0)
        fprintf(stderr, "bench: %s %-6s floor (cube %d^2, every light): err %.3f%% (shadow area %.3f%%)\n", R->scene,
                V->bv.name, INTERIOR_FLOOR_RES, w.rr.err, w.rr.hard.area_pct);
    R->reps = reps;
}

static void interior_bench(bench_gl *B, int quick, int repeat, FILE *csv, float *depth, float *mask_px) {
    room_bench R;
    sk_vec3 lp[TB_INTERIOR_LIGHTS];
    float range[TB_INTERIOR_LIGHTS];
    int v, l;
    for (l = 0; l < TB_INTERIOR_LIGHTS; l++)
        if (tb_interior_light(l, &lp[l], &range[l]) != 0) return;
    if (room_bench_open(&R, B, "interior", tb_scene_build_interior, TB_INTERIOR_LIGHTS, 1.0f, repeat, csv, depth,
                        mask_px) != 0)
        return;
    for (v = 0; v < (quick ? 1 : INTERIOR_VIEWS); v++) {
        room_view V;
        sk_vec3 e, t;
        float eye[3], target[3];
        char name[16];
        if (tb_interior_view(v, &e, &t) != 0) continue;
        eye[0] = e.x, eye[1] = e.y, eye[2] = e.z;
        target[0] = t.x, target[1] = t.y, target[2] = t.z;
        snprintf(name, sizeof name, "v%d", v);
        if (room_view_open(&R, &V, name, eye, target, lp, range) != 0) continue;
        run_point_cfgs(&R, &V, POINT_RES);
        /* the speed/accuracy front: the cube map and VSDCT with every
           option (point_cfgs' last "cube" and "vsdct" rows) at half and
           twice the face side */
        run_point_cfgs_range(&R, &V, POINT_RES / 2, 5, 5);
        run_point_cfgs_range(&R, &V, POINT_RES * 2, 5, 5);
        run_point_cfgs_range(&R, &V, POINT_RES / 2, 8, 8);
        run_point_cfgs_range(&R, &V, POINT_RES * 2, 8, 8);
        interior_floor(&R, &V);
        fflush(csv);
        room_view_close(&R, &V);
    }
    room_bench_close(&R);
}

/* -------------------------------------------------------- spot lights */
/* The room scene under a spot light (scene "room-spot" in bench.csv, a
   chart of its own): skgl_spot_render's one perspective map at 256 to
   2048, plain and with caster culling, scissor and resolution selection,
   against what a spot costs without it: a point light (cube, VSDCT, every
   optimization on, faces culled by the view) at the spot's place, whose
   shader would cut it by the cone. Scored inside the cone: the point
   light's exact reference there, the receivers outside the cone left out
   (as out of range) and those within SPOT_EDGE_DEG of its edge too
   (counted as silhouettes in excluded_px). Views: "inside" (the spot in view, aimed
   down past the crate), "away" (behind the camera, aimed into the view).
   Methods: spot, cube-cone, vsdct-cone. */
#define SPOT_EDGE_DEG 0.5

typedef struct spot_cfg {
    const char *method;
    skgl_point_technique technique;
    int spot, resolution, opt;   /* opt: caster culling, scissor, resolution selection (and faces) */
} spot_cfg;

static const spot_cfg spot_cfgs[] = {
    {"spot", SKGL_POINT_VSDCT, 1, 256, 0},       {"spot", SKGL_POINT_VSDCT, 1, 512, 0},
    {"spot", SKGL_POINT_VSDCT, 1, 1024, 0},      {"spot", SKGL_POINT_VSDCT, 1, 2048, 0},
    {"spot", SKGL_POINT_VSDCT, 1, 1024, 1},      {"cube-cone", SKGL_POINT_CUBE, 0, 512, 1},
    {"cube-cone", SKGL_POINT_CUBE, 0, 1024, 1},  {"vsdct-cone", SKGL_POINT_VSDCT, 0, 512, 1},
};

typedef struct spot_view {
    const char *name;
    float eye[3], target[3], light[3], dir[3], angle, range;
} spot_view;

static const spot_view spot_views[] = {
    {"inside", {4.2f, 3.2f, 4.2f}, {-1.0f, 1.0f, -1.0f}, {0.5f, 2.4f, 0.5f}, {0.3f, -1.0f, -0.6f}, 45.0f, 8.0f},
    {"away", {3.2f, 1.7f, -1.8f}, {4.9f, 1.0f, -4.9f}, {0.5f, 2.4f, 0.5f}, {1.0f, -0.9f, -1.2f}, 35.0f, 8.0f},
};

/* the degrees between the axis and the direction from lp to pixel i's
   receiver (depth buffer, view_proj's inverse); -1 on background */
static double spot_angle_of(const sk_mat4 *inv, const float *depth, size_t i, sk_vec3 lp, sk_vec3 axis) {
    double p[3], v[3], vl, al, c;
    if (!(depth[i] < 1.0f) ||
        tb_unproject_pixel(inv, BENCH_W, BENCH_H, (int)(i % BENCH_W), (int)(i / BENCH_W), depth[i], p) != 0)
        return -1.0;
    v[0] = p[0] - lp.x; v[1] = p[1] - lp.y; v[2] = p[2] - lp.z;
    vl = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    al = sqrt((double)axis.x * axis.x + (double)axis.y * axis.y + (double)axis.z * axis.z);
    c = vl > 0 && al > 0 ? (v[0] * axis.x + v[1] * axis.y + v[2] * axis.z) / (vl * al) : 1.0;
    return acos(c < -1 ? -1 : c > 1 ? 1 : c) * 57.29577951308232;
}

static void spot_bench(bench_gl *B, int repeat, FILE *csv, float *depth, float *mask_px) {
    room_bench R;
    size_t n = (size_t)BENCH_W * BENCH_H, i;
    int v, c;
    if (room_bench_open(&R, B, "room-spot", tb_scene_build_room, 1, 0.0f, repeat, csv, depth, mask_px) != 0) return;
    for (v = 0; v < (int)(sizeof spot_views / sizeof spot_views[0]); v++) {
        const spot_view *pv = &spot_views[v];
        room_view V;
        sk_vec3 lp = v3(pv->light[0], pv->light[1], pv->light[2]), dir = v3(pv->dir[0], pv->dir[1], pv->dir[2]);
        if (room_view_open(&R, &V, pv->name, pv->eye, pv->target, &lp, &pv->range) != 0) continue;
        /* the spot's reference: the point light's inside the cone, the rest left out */
        for (i = 0; i < n; i++) {
            double a = spot_angle_of(&V.tv.inv_view_proj, depth, i, lp, dir);
            if (!(R.refv[i] >= 0.0f) || a < 0.0) continue;
            if (fabs(a - pv->angle) < SPOT_EDGE_DEG) R.refv[i] = BENCH_VIS_SILHOUETTE;
            else if (a > pv->angle) R.refv[i] = TB_VIS_OUT_OF_RANGE;
        }
        for (c = 0; c < (int)(sizeof spot_cfgs / sizeof spot_cfgs[0]); c++) {
            const spot_cfg *pc = &spot_cfgs[c];
            skgl_point_desc d =
                point_desc(pc->technique, pc->resolution, pc->opt && !pc->spot, pc->opt, pc->opt, pc->opt);
            room_row w;
            d.spot_angle = pc->spot ? pv->angle : 0.0f;
            if (run_room_row(&R, &V, pc->method, &d, pc->spot ? &dir : NULL, &w) != 0) continue;
            fprintf(stderr, "bench: room-spot %-6s %-10s %s: side %d, %d faces, %d casters culled: err %.3f%% "
                            "(shadow area %.3f%% of %llu px, edge p95 %.2f px) shadow %.2f ms mask %.2f ms\n",
                    pv->name, pc->method, w.params, w.st.resolution, w.st.faces_rendered, w.st.casters_culled,
                    w.rr.err, w.rr.hard.area_pct, (unsigned long long)w.rr.hard.shadow, w.rr.hard.edge_p95_px,
                    (double)w.shadow_ms, (double)w.rr.mask_ms);
        }
        fflush(csv);
        room_view_close(&R, &V);
    }
    room_bench_close(&R);
}

/* The walk-through of Tang et al. 2017's Table 1: the camera moves in `frames`
   steps from the "low" view to the "overview" one; at each step LSPSM and
   PSSM with 8 cascades at the same per-map resolution (1024) render and are
   scored. Rows go to bench-walk.csv (the bench.csv columns, view walkNN);
   the summary (mean partitions, the shadow-time ratio LSPSM / PSSM-8, the
   mean errors: covered %, shadow-area % over the frames whose reference
   has shadow, edge p95) to bench-walk.txt and stderr. */
/* ------------------------------------------- area lights: PCSS and PVSM */
/* The area-light rows: on sponza-ivy, sponza-curtains (when ../shared is
   there) and the procedural fence, one rectangular light above the content
   at three sizes; PCSS on a 2048^2 and a 4096^2 map against PVSM in the
   three variants of soft_cfgs (tiles up to 4096^2, 64^2 SMTG); error = mean
   absolute visibility error against the Embree reference with 16 x 16
   stratified light samples per pixel (soft_mae, in [0,1]) over the covered
   pixels, and apart inside the penumbra (0 < reference < 1, grown by
   BENCH_PENUMBRA_GROW px), the umbra and the lit part (tb_metric_penumbra:
   the covered mean is mostly exact lit and umbra pixels, so it is many
   times smaller than the error where the methods differ). shadow_ms = the
   depth passes (PCSS: its map; PVSM: the low-res map and the tiles),
   analysis_ms = PVSM's kernel-shape, prediction and pyramid passes (0 for
   PCSS), total_ms = every pass but the G-buffer (the masks included).
   Then a slow camera path (3 frames, the medium light) for the flip rate:
   visibility changes > 0.1 where the reference changes < 0.02.
   out/bench-soft.txt holds the table and the ratios. */
#define SOFT_STRATA TB_REF_EXACT_STRATA   /* the reference's noise in the penumbra: tb_reference.h */
static const char *const soft_size_names[3] = {"small", "medium", "large"};
static const float soft_size_fracs[3] = {0.01f, 0.04f, 0.12f};   /* half size / content half length */
typedef struct soft_cfg {
    const char *method, *label;
    skgl_soft_technique technique;
    int resolution;
    int antialias;            /* PVSM: 1 the paper's footprint-convolved kernel, -1 point samples */
    float scale;              /* PVSM: resolution_scale */
    int lowres;               /* PVSM: the low-res map's side */
} soft_cfg;
/* PVSM three ways: the paper's defaults (1024^2 low-res map, the filter
   convolved with the pixel footprint); the filter without the footprint
   (the reference is point-sampled at pixel centres); and that with a
   2048^2 low-res map at twice the predicted resolutions (the quality knob
   of Sec. 7) */
#define SOFT_CFGS 5
static const soft_cfg soft_cfgs[SOFT_CFGS] = {
    {"pcss", "pcss-2048", SKGL_SOFT_PCSS, 2048, 0, 0.0f, 0},
    {"pcss", "pcss-4096", SKGL_SOFT_PCSS, 4096, 0, 0.0f, 0},
    {"pvsm", "pvsm", SKGL_SOFT_PVSM, 4096, 1, 1.0f, 1024},
    {"pvsm-point", "pvsm-point", SKGL_SOFT_PVSM, 4096, -1, 1.0f, 1024},
    {"pvsm-fine", "pvsm-fine", SKGL_SOFT_PVSM, 4096, -1, 2.0f, 2048}};

/* above the content, 1.2 content lengths up and off to one side */
static skgl_area_light soft_light_for(const tb_scene *s, int size) {
    sk_aabb cb = content_bounds(s);
    sk_vec3 c = v3(0.5f * (cb.min.x + cb.max.x), 0.5f * (cb.min.y + cb.max.y), 0.5f * (cb.min.z + cb.max.z));
    float hx = 0.5f * (cb.max.x - cb.min.x), hz = 0.5f * (cb.max.z - cb.min.z), L = hx > hz ? hx : hz;
    skgl_area_light l;
    memset(&l, 0, sizeof l);
    l.position = v3(c.x + 0.35f * L, cb.max.y + 1.2f * L, c.z + 0.25f * L);
    l.direction = v3_add(c, v3_scale(l.position, -1.0f));
    l.up = v3(0, 0, 1);
    l.half_width = l.half_height = soft_size_fracs[size] * L;
    return l;
}

static tb_light soft_tb_light(const skgl_area_light *l) {
    tb_light t;
    memset(&t, 0, sizeof t);
    t.type = TB_LIGHT_RECT;
    t.position = l->position;
    skgl_area_light_axes(l, &t.half_u, &t.half_v);
    t.strata = SOFT_STRATA;
    t.seed = 11;
    return t;
}

/* one method on one prepared view: reps timed frames (after a warm-up),
   the last mask scored; 0 ok */
static int soft_run(bench_gl *B, const soft_cfg *cfg, const view_data *vd, const skgl_scene *sc,
                    const skgl_area_light *l, int reps, float *mask_px, run_rec *rr, skgl_soft_frame_stats *st) {
    skgl_soft_desc d;
    skgl_soft *so = NULL;
    float tot[BENCH_MAX_REPEAT], sh[BENCH_MAX_REPEAT], an[BENCH_MAX_REPEAT];
    sk_result r;
    int k;
    memset(&d, 0, sizeof d);
    d.technique = cfg->technique;
    d.resolution = cfg->resolution;
    d.disable_antialias = cfg->antialias < 0;
    d.resolution_scale = cfg->scale;
    d.lowres = cfg->lowres;
    if (skgl_soft_create(B->sk, &d, &so) != SK_OK) return -1;
    memset(rr, 0, sizeof *rr);
    rr->kind = "soft_mae";
    for (k = 0; k <= reps; k++) {
        const skgl_soft_frame_stats *s;
        r = skgl_soft_render(B->sk, so, &vd->v.cam, sc, l, vd->gbuf.depth_tex, vd->gbuf.color_tex, B->mask.color_tex);
        if (r != SK_OK) {
            fprintf(stderr, "bench: skgl_soft_render %s: %s (%s)\n", cfg->method, sk_result_string(r),
                    skgl_error_log(B->sk));
            skgl_soft_destroy(B->sk, so);
            return -1;
        }
        s = skgl_soft_stats(so);
        if (k == 0) continue;
        sh[k - 1] = s->shadow_ms;
        an[k - 1] = 0.0f;
        if (cfg->technique == SKGL_SOFT_PVSM) an[k - 1] = s->step_ms[2] + s->step_ms[3] + s->step_ms[4];
        tot[k - 1] = s->shadow_ms + s->mask_ms;
    }
    *st = *skgl_soft_stats(so);
    skgl_soft_destroy(B->sk, so);
    if (tb_gl_read_red(&B->gl, B->mask.fbo, BENCH_W, BENCH_H, mask_px) != 0) return -1;
    rr->n = reps;
    for (k = 0; k < reps; k++) rr->analysis[k] = an[k];
    rr->shadow[0] = median(sh, reps);
    rr->mask_ms = median(tot, reps) - rr->shadow[0] - median(an, reps);
    rr->texels = st->texels;
    rr->passes = st->passes;
    score_soft(vd->ref, mask_px, rr);
    rr->state = 1;
    return 0;
}

static void soft_bench(bench_gl *B, const bench_opts *o, FILE *csv, float *depth, float *rgba, float *nrm,
                       float *mask_px) {
    static const char *const names[3] = {"sponza-ivy", "sponza-curtains", "fence"};
    static const char *const files[3] = {"sponza-ivy/sponza_ivy.gltf", "sponza-curtains/sponza_curtains.gltf", ""};
    size_t n = (size_t)BENCH_W * BENCH_H, i;
    char path[1200];
    FILE *txt;
    int sc_i, reps = o->quick ? 1 : (o->repeat < 3 ? o->repeat : 3);
    snprintf(path, sizeof path, "%.900s/bench-soft.txt", o->p.out_dir);
    txt = fopen(path, "w");
    if (txt)
        fprintf(txt, "# area-light soft shadows, %dx%d, error = mean absolute visibility error against %d "
                     "stratified light samples per pixel: mae over the covered pixels; pen_mae, pen_max inside the "
                     "penumbra (0 < reference < 1, grown by %d px); umbra_mae, lit_mae outside it (\"-\": the "
                     "reference has no such pixel); total = every pass but the G-buffer (median of %d)\n"
                     "# device %s, times %s\n# %-16s %-8s %-6s %-10s %9s %9s %9s %9s %9s %9s %9s %9s %6s %6s\n",
                BENCH_W, BENCH_H, SOFT_STRATA * SOFT_STRATA, BENCH_PENUMBRA_GROW, reps, B->renderer,
                timing_label(B->renderer), "scene", "view", "light", "method", "mae", "pen_mae", "pen_max",
                "umbra_mae", "lit_mae", "total_ms", "shadow_ms", "texels", "tiles", "lit");
    for (sc_i = 0; sc_i < 3; sc_i++) {
        bench_scene_def def;
        tb_scene s;
        tb_gl_mesh mesh;
        tb_reference *ref = NULL;
        bench_view views[3];
        draw_user du;
        skgl_scene sc;
        int v, z, c, nviews = o->quick ? 1 : 2;
        double ts = now_s();
        if (!scene_selected(o->p.only, names[sc_i])) continue;
        if (o->quick && files[sc_i][0]) continue;            /* the demo: the fence only */
        memset(&def, 0, sizeof def);
        snprintf(def.name, sizeof def.name, "%s", names[sc_i]);
        if (files[sc_i][0]) {
            snprintf(def.path, sizeof def.path, "%.900s/%s", o->p.scenes_dir, files[sc_i]);
            if (!file_exists(def.path)) continue;
        }
        memset(&mesh, 0, sizeof mesh);
        if (load_scene(&def, &s) != 0 || tb_gl_mesh_create(&B->gl, &mesh, &s) != 0 || !(ref = tb_reference_create(&s))) {
            fprintf(stderr, "bench: soft shadows: scene %s failed to load\n", def.name);
            if (mesh.vao) tb_gl_mesh_destroy(&B->gl, &mesh);
            tb_scene_free(&s);
            continue;
        }
        make_views(&s, views);
        du.gl = &B->gl;
        du.scene = &s;
        du.mesh = &mesh;
        sc.draw = draw_casters;
        sc.user = &du;
        sc.bounds = s.bounds;
        for (v = 0; v < nviews; v++) {
            const int vi = v == 0 ? 0 : 2;                    /* overview, close */
            for (z = 0; z < 3; z++) {
                view_data vd;
                skgl_area_light l = soft_light_for(&s, z);
                tb_light tl = soft_tb_light(&l);
                double t0 = now_s(), e4 = -1, p4 = -1, t4 = -1;
                memset(&vd, 0, sizeof vd);
                vd.v = views[vi];
                if (prepare_view(B, &mesh, NULL, ref, def.light_dir, &tl, &vd, depth, rgba, nrm) != 0) {
                    fprintf(stderr, "bench: soft shadows: %s %s: G-buffer / reference failed\n", def.name, vd.v.name);
                    free_view(B, &vd);
                    continue;
                }
                fprintf(stderr, "bench: soft %s %s %s light (half %.3g): reference in %.1f s\n", def.name,
                        vd.v.name, soft_size_names[z], (double)l.half_width, now_s() - t0);
                for (c = 0; c < SOFT_CFGS; c++) {
                    run_rec rr;
                    skgl_soft_frame_stats st;
                    char params[160], view[40];
                    float tot;
                    if (soft_run(B, &soft_cfgs[c], &vd, &sc, &l, reps, mask_px, &rr, &st) != 0) continue;
                    tot = rr.shadow[0] + median(rr.analysis, rr.n) + rr.mask_ms;
                    if (soft_cfgs[c].technique == SKGL_SOFT_PVSM)
                        snprintf(params, sizeof params,
                                 "max_resolution=%d;lowres=%d;grid=64;antialias=%d;scale=%g;light=%s;half=%.4g",
                                 soft_cfgs[c].resolution, soft_cfgs[c].lowres, soft_cfgs[c].antialias > 0,
                                 (double)soft_cfgs[c].scale,
                                 soft_size_names[z], (double)l.half_width);
                    else
                        snprintf(params, sizeof params, "resolution=%d;light=%s;half=%.4g", soft_cfgs[c].resolution,
                                 soft_size_names[z], (double)l.half_width);
                    snprintf(view, sizeof view, "%s", vd.v.name);
                    write_row(csv, soft_cfgs[c].method, params, def.name, view, &rr, rr.shadow[0], B->renderer);
                    fprintf(stderr, "bench: soft %-15s %-8s %-6s %-13s: mae %.5f (penumbra %.5f, max %.3f; umbra "
                                    "%.5f; lit %.5f) total %.1f ms (depth %.1f) texels %.0f (%.2fx 4096^2) tiles %d "
                                    "lit %.2f\n", def.name, vd.v.name, soft_size_names[z], soft_cfgs[c].label,
                            rr.err, rr.pen.penumbra_mae, rr.pen.penumbra_max, rr.pen.umbra_mae, rr.pen.lit_mae,
                            (double)tot,
                            (double)rr.shadow[0], rr.texels, rr.texels / (4096.0 * 4096.0), st.tiles,
                            (double)st.lit_fraction);
                    if (soft_cfgs[c].technique == SKGL_SOFT_PVSM) {
                        int q;
                        fprintf(stderr, "bench:   pvsm steps (ms):");
                        for (q = 1; q < SKGL_SOFT_STEPS; q++) fprintf(stderr, " %d:%.1f", q + 1, (double)st.step_ms[q]);
                        fprintf(stderr, "\n");
                    }
                    if (txt) {
                        char pm[16] = "-", px[16] = "-", um[16] = "-", lm[16] = "-";
                        if (rr.pen.penumbra > 0) {
                            snprintf(pm, sizeof pm, "%.5f", rr.pen.penumbra_mae);
                            snprintf(px, sizeof px, "%.4f", rr.pen.penumbra_max);
                        }
                        if (rr.pen.umbra > 0) snprintf(um, sizeof um, "%.5f", rr.pen.umbra_mae);
                        if (rr.pen.lit > 0) snprintf(lm, sizeof lm, "%.5f", rr.pen.lit_mae);
                        fprintf(txt, "  %-16s %-8s %-6s %-10s %9.5f %9s %9s %9s %9s %9.1f %9.1f %9.0f %6d %6.2f\n",
                                def.name, vd.v.name, soft_size_names[z], soft_cfgs[c].label, rr.err, pm, px, um, lm,
                                (double)tot, (double)rr.shadow[0], rr.texels, st.tiles, (double)st.lit_fraction);
                    }
                    if (c == 1) { e4 = rr.err; p4 = rr.pen.penumbra > 0 ? rr.pen.penumbra_mae : -1; t4 = tot; }
                    if (c >= 2 && txt && e4 >= 0) {
                        char pr[64] = "no penumbra";
                        if (p4 > 0 && rr.pen.penumbra > 0)
                            snprintf(pr, sizeof pr, "%.2fx (%s)", rr.pen.penumbra_mae / p4,
                                     rr.pen.penumbra_mae < p4 ? "lower" : "NOT lower");
                        fprintf(txt, "  %-16s %-8s %-6s %s / pcss-4096: error %.2fx (%s), penumbra error %s, "
                                     "time %.2fx, texels %.2fx of 4096^2\n", def.name, vd.v.name,
                                soft_size_names[z], soft_cfgs[c].label, rr.err / e4, rr.err < e4 ? "lower" : "NOT lower",
                                pr, tot / t4, rr.texels / (4096.0 * 4096.0));
                    }
                }
                fflush(csv);
                if (txt) fflush(txt);
                free_view(B, &vd);
            }
        }
        /* temporal: the overview's eye moving 0.05% of its distance a frame, sideways */
        {
            enum { FR = 3 };
            skgl_area_light l = soft_light_for(&s, 1);
            tb_light tl = soft_tb_light(&l);
            float *prev_ref = (float *)malloc(sizeof(float) * n), *prev[SOFT_CFGS], *cur[SOFT_CFGS];
            size_t flips[SOFT_CFGS], pairs = 0;
            int f, ok = prev_ref != NULL;
            memset(flips, 0, sizeof flips);
            for (c = 0; c < SOFT_CFGS; c++) {
                prev[c] = (float *)malloc(sizeof(float) * n);
                cur[c] = (float *)malloc(sizeof(float) * n);
                ok = ok && prev[c] && cur[c];
            }
            for (f = 0; ok && f < FR; f++) {
                view_data vd;
                bench_view bv = views[0];
                sk_vec3 fwd = v3_norm(v3_add(bv.target, v3_scale(bv.eye, -1.0f)));
                sk_vec3 side = v3_norm(v3(fwd.z, 0.0f, -fwd.x));
                float d = v3_len(v3_add(bv.target, v3_scale(bv.eye, -1.0f)));
                bv.eye = v3_add(bv.eye, v3_scale(side, 0.0005f * d * (float)f));
                bv.target = v3_add(bv.target, v3_scale(side, 0.0005f * d * (float)f));
                finish_view(&bv, &s.bounds);
                memset(&vd, 0, sizeof vd);
                vd.v = bv;
                if (prepare_view(B, &mesh, NULL, ref, def.light_dir, &tl, &vd, depth, rgba, nrm) != 0) {
                    free_view(B, &vd);
                    ok = 0;
                    break;
                }
                for (c = 0; c < SOFT_CFGS && ok; c++) {
                    run_rec rr;
                    skgl_soft_frame_stats st;
                    if (soft_run(B, &soft_cfgs[c], &vd, &sc, &l, 1, cur[c], &rr, &st) != 0) ok = 0;
                }
                if (ok && f > 0)
                    for (i = 0; i < n; i++) {
                        if (vd.ref[i] < 0.0f || prev_ref[i] < 0.0f || fabsf(vd.ref[i] - prev_ref[i]) >= 0.02f) continue;
                        pairs++;
                        for (c = 0; c < SOFT_CFGS; c++) flips[c] += fabsf(cur[c][i] - prev[c][i]) > 0.1f;
                    }
                memcpy(prev_ref, vd.ref, sizeof(float) * n);
                for (c = 0; c < SOFT_CFGS; c++) memcpy(prev[c], cur[c], sizeof(float) * n);
                free_view(B, &vd);
            }
            if (ok && pairs > 0) {
                fprintf(stderr, "bench: soft %s temporal (medium light, %d frames, %zu pixel pairs): flip rate",
                        def.name, FR, pairs);
                if (txt)
                    fprintf(txt, "  %-16s temporal (medium light, %d frames, %zu pixel pairs): flip rate", def.name,
                            FR, pairs);
                for (c = 0; c < SOFT_CFGS; c++) {
                    fprintf(stderr, " %s %.4f%%", soft_cfgs[c].label, 100.0 * flips[c] / pairs);
                    if (txt) fprintf(txt, "  %s %.4f%%", soft_cfgs[c].label, 100.0 * flips[c] / pairs);
                }
                fprintf(stderr, "\n");
                if (txt) fprintf(txt, "\n");
            }
            free(prev_ref);
            for (c = 0; c < SOFT_CFGS; c++) { free(prev[c]); free(cur[c]); }
        }
        fprintf(stderr, "bench: soft shadows on %s done in %.1f s\n", def.name, now_s() - ts);
        tb_reference_destroy(ref);
        tb_gl_mesh_destroy(&B->gl, &mesh);
        tb_scene_free(&s);
    }
    if (txt) fclose(txt);
}

static const struct walk_cfg {
    const char *method, *params;
    skgl_technique technique;
    int cascades;
} walk_cfgs[2] = {
    {"lspsm", "resolution=1024;pcf=1", SKGL_LSPSM, 0},
    {"pssm", "cascades=8;lambda=0.75;resolution=1024;blend=0;pcf=1", SKGL_PSSM, 8},
};

static void walk_scene(bench_gl *B, const bench_scene_def *def, const tb_scene *s, const tb_gl_mesh *mesh,
                       const bench_forest *forest, const tb_reference *ref, const bench_view *views, const skgl_scene *sc, int frames,
                       int repeat, float *depth, float *rgba, float *nrm, float *mask_px, FILE *csv, FILE *txt) {
    skgl_shadow *sh[2] = {NULL, NULL};
    double ms[2] = {0, 0}, err[2] = {0, 0}, area[2] = {0, 0}, p95[2] = {0, 0}, parts = 0;
    int k, m, i, nf = 0, na[2] = {0, 0};
    for (m = 0; m < 2; m++) {
        skgl_shadow_desc d;
        memset(&d, 0, sizeof d);
        d.technique = walk_cfgs[m].technique;
        d.cascades = walk_cfgs[m].cascades;
        d.resolution = 1024;
        if (skgl_shadow_create(B->sk, &d, &sh[m]) != SK_OK ||
            skgl_shadow_render(B->sk, sh[m], &views[1].cam, sc, def->light_dir) != SK_OK) {   /* warm-up */
            fprintf(stderr, "bench: walk %s: %s failed: %s\n", def->name, walk_cfgs[m].method, skgl_error_log(B->sk));
            goto done;
        }
    }
    for (k = 0; k < frames; k++) {
        view_data vd;
        float t = frames > 1 ? (float)k / (float)(frames - 1) : 0.0f;
        memset(&vd, 0, sizeof vd);
        vd.v.eye = v3_add(v3_scale(views[1].eye, 1.0f - t), v3_scale(views[0].eye, t));
        vd.v.target = v3_add(v3_scale(views[1].target, 1.0f - t), v3_scale(views[0].target, t));
        snprintf(vd.v.name, sizeof vd.v.name, "walk%02d", k);
        finish_view(&vd.v, &s->bounds);
        if (prepare_view(B, mesh, forest, ref, def->light_dir, NULL, &vd, depth, rgba, nrm) == 0) {
            for (m = 0; m < 2; m++) {
                run_rec rr;
                const char *why = "";
                memset(&rr, 0, sizeof rr);
                for (i = 0; i < repeat && i < BENCH_MAX_REPEAT; i++) {
                    float unused;
                    if (render_frame(B, sh[m], &vd, sc, def->light_dir, &unused) != SK_OK) break;
                    rr.shadow[rr.n++] = render_ms(sh[m]);
                }
                if (rr.n == 0 || score_run(B, sh[m], &vd, mask_px, &rr, &why) != 0) {
                    fprintf(stderr, "bench: walk %s %s frame %d failed %s\n", def->name, walk_cfgs[m].method, k, why);
                    continue;
                }
                write_row(csv, walk_cfgs[m].method, walk_cfgs[m].params, def->name, vd.v.name, &rr,
                          median(rr.shadow, rr.n), B->renderer);
                ms[m] += median(rr.shadow, rr.n);
                err[m] += rr.err;
                if (rr.hard.ok && rr.hard.shadow > 0) {
                    area[m] += rr.hard.area_pct;
                    p95[m] += rr.hard.edge_p95_px;
                    na[m]++;
                }
                if (m == 0) parts += rr.passes;
            }
            nf++;
        }
        free_view(B, &vd);
    }
    fflush(csv);
    if (nf > 0) {
        char line[640];
        snprintf(line, sizeof line,
                 "%-16.64s %2d frames: lspsm %.2f partitions on average, shadow time %.2fx pssm-8 (%.2f vs %.2f ms "
                 "per frame), error %.3f%% vs %.3f%% of covered pixels, shadow area %.3f%% vs %.3f%%, edge p95 "
                 "%.2f vs %.2f px\n",
                 def->name, nf, parts / nf, ms[1] > 0 ? ms[0] / ms[1] : 0.0, ms[0] / nf, ms[1] / nf, err[0] / nf,
                 err[1] / nf, na[0] ? area[0] / na[0] : 0.0, na[1] ? area[1] / na[1] : 0.0,
                 na[0] ? p95[0] / na[0] : 0.0, na[1] ? p95[1] / na[1] : 0.0);
        fprintf(stderr, "bench: walk %s", line);
        if (txt) { fputs(line, txt); fflush(txt); }
    }
done:
    for (m = 0; m < 2; m++) skgl_shadow_destroy(B->sk, sh[m]);
}

/* ------------------------------------------------------------ the limit */
/* The floor of a view: the error of an over-resolved map, the limit the
   charts measure every method against. Two candidates, each rendered
   once and scored like a sweep run: RMSM with a 65536^2 virtual map (a
   48 x 48 page pool, so that the pool does not run short and coarsen the
   pages) and a standard focused map of 16384^2 (or GL_MAX_TEXTURE_SIZE,
   when smaller); the floor is the finer of the two on that view: the one
   with fewer shaded pixels whose texel spans more than a pixel (then the
   smaller median footprint). Its row in bench.csv is method "floor",
   params naming the source. */
#define FLOOR_RMSM_RES 65536
#define FLOOR_RMSM_POOL 48
#define FLOOR_STD_RES 16384

static int floor_finer(const run_rec *a, const run_rec *b) {
    if (a->texel.count == 0) return 0;
    if (b->texel.count == 0) return 1;
    if (a->texel.over1_pct != b->texel.over1_pct) return a->texel.over1_pct < b->texel.over1_pct;
    return a->texel.median <= b->texel.median;
}

/* one floor candidate on one view, scored into rr; 0 ok */
static int floor_run(bench_gl *B, const skgl_shadow_desc *d, view_data *vd, const skgl_scene *sc, sk_vec3 light_dir,
                     float *mask_px, run_rec *rr) {
    skgl_shadow *sh = NULL;
    const char *why = "";
    float analysis = 0.0f;
    int rc = -1;
    memset(rr, 0, sizeof *rr);
    if (skgl_shadow_create(B->sk, d, &sh) == SK_OK && render_frame(B, sh, vd, sc, light_dir, &analysis) == SK_OK) {
        rr->shadow[0] = render_ms(sh);
        rr->analysis[0] = analysis;
        rr->n = 1;
        rc = score_run(B, sh, vd, mask_px, rr, &why);
    }
    if (rc != 0)
        fprintf(stderr, "bench: floor %s on %s failed %s: %s\n", d->technique == SKGL_RMSM ? "rmsm" : "standard",
                vd->v.name, why, skgl_error_log(B->sk));
    skgl_shadow_destroy(B->sk, sh);
    return rc;
}

/* the floor of every view of a scene: rows to csv, into floors[v]
   (state 1 where one was measured) */
static void floor_runs(bench_gl *B, const bench_scene_def *def, view_data *vd, int nviews, const skgl_scene *sc,
                       float *mask_px, FILE *csv, run_rec *floors) {
    skgl_shadow_desc rd, sd;
    int v, max_res = skgl_get_caps(B->sk).max_texture_size;
    char rp[160], sp[160];
    memset(&rd, 0, sizeof rd);
    rd.technique = SKGL_RMSM;
    rd.resolution = FLOOR_RMSM_RES;
    rd.rmsm_pool_pages = FLOOR_RMSM_POOL;
    rd.sync_readback = 1;
    rd.bias = g_bias;
    memset(&sd, 0, sizeof sd);
    sd.technique = SKGL_STANDARD;
    sd.resolution = max_res > 0 && max_res < FLOOR_STD_RES ? max_res : FLOOR_STD_RES;
    sd.bias = g_bias;
    snprintf(rp, sizeof rp, "source=rmsm;virtual_resolution=%d;page=128;pool=%d;pcf=0", rd.resolution,
             rd.rmsm_pool_pages);
    snprintf(sp, sizeof sp, "source=standard;resolution=%d;pcf=1", sd.resolution);
    for (v = 0; v < nviews; v++) {
        run_rec a, b;
        int ok_a = floor_run(B, &rd, &vd[v], sc, def->light_dir, mask_px, &a) == 0;
        int ok_b = floor_run(B, &sd, &vd[v], sc, def->light_dir, mask_px, &b) == 0;
        int pick_a = ok_a && (!ok_b || floor_finer(&a, &b));
        memset(&floors[v], 0, sizeof floors[v]);
        if (!ok_a && !ok_b) continue;
        floors[v] = pick_a ? a : b;
        floors[v].state = 1;
        write_row(csv, BENCH_FLOOR, pick_a ? rp : sp, def->name, vd[v].v.name, &floors[v], floors[v].shadow[0],
                  B->renderer);
        fprintf(stderr, "bench: floor %-15s %-8s rmsm %d: shadow area %.3f%%, texel > 1 px %.1f%% (median %.3f) | "
                        "standard %d: %.3f%%, %.1f%% (%.3f) -> %s\n", def->name, vd[v].v.name, rd.resolution,
                ok_a ? a.hard.area_pct : -1.0, a.texel.over1_pct, a.texel.median, sd.resolution,
                ok_b ? b.hard.area_pct : -1.0, b.texel.over1_pct, b.texel.median, pick_a ? "rmsm" : "standard");
    }
    fflush(csv);
}

/* The shadow-area error by view-depth band, pooled over the views (the
   sums of wrong and of shadow pixels), one line a configuration and one
   for the floor: bench-bands.txt. */
static void bands_line(FILE *t, const char *method, const char *params, const run_rec *rr, int nviews) {
    uint64_t sh[BENCH_BANDS], wr[BENCH_BANDS], ts = 0, tw = 0;
    int v, b, n = 0;
    memset(sh, 0, sizeof sh);
    memset(wr, 0, sizeof wr);
    for (v = 0; v < nviews; v++) {
        if (rr[v].state != 1 || !rr[v].has_bands) continue;
        for (b = 0; b < BENCH_BANDS; b++) {
            sh[b] += rr[v].band_shadow[b];
            wr[b] += rr[v].band_wrong[b];
            ts += rr[v].band_shadow[b];
            tw += rr[v].band_wrong[b];
        }
        n++;
    }
    if (n == 0) return;
    fprintf(t, "  %-15s %-52s %8.3f", method, params, ts ? 100.0 * (double)tw / (double)ts : 0.0);
    for (b = 0; b < BENCH_BANDS; b++)
        if (sh[b]) fprintf(t, " %8.3f", 100.0 * (double)wr[b] / (double)sh[b]);
        else fprintf(t, " %8s", "-");
    fprintf(t, "   (%d view%s)\n", n, n == 1 ? "" : "s");
}

int main(int argc, char **argv) {
    bench_opts o;
    bench_scene_def defs[BENCH_MAX_SCENES];
    int ndefs = 0, i, c, v, status = 0, shared = 0;
    const char *env;
    bench_gl B;
    FILE *csv = NULL, *walk = NULL, *walk_txt = NULL, *bands = NULL, *autoch = NULL;
    char path[1200];
    progress pg;
    float *depth = NULL, *rgba = NULL, *nrm = NULL, *mask_px = NULL;
    size_t npx = (size_t)BENCH_W * BENCH_H;
    double t_start = now_s();

    memset(&o, 0, sizeof o);
    bench_paths_init(&o.p, "bench/pareto.gp");
    o.repeat = 5;
    o.views = 0;
    env = getenv("SK_BENCH_QUICK");
    if (env && *env && strcmp(env, "0") != 0) o.quick = 1;
    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        int more = i + 1 < argc;
        if (strcmp(a, "--quick") == 0) o.quick = 1;
        else if (strcmp(a, "--full") == 0) o.quick = 0;
        else if (strcmp(a, "--repeat") == 0 && more) { o.repeat = atoi(argv[++i]); o.repeat_given = 1; }
        else if (strcmp(a, "--views") == 0 && more) o.views = atoi(argv[++i]);
        else if (bench_path_option(&o.p, argc, argv, &i)) continue;
        else if (strcmp(a, "--images") == 0) o.images = 1;
        else if (strcmp(a, "--soft-only") == 0) o.soft_only = 1;
        else if (strcmp(a, "--methods") == 0 && more) o.methods = argv[++i];
        else if (strcmp(a, "--match") == 0 && more) o.match = argv[++i];
        else if (strcmp(a, "--no-floor") == 0) o.no_floor = 1;
        else if (strcmp(a, "--no-soft") == 0) o.no_soft = 1;
        else if (strcmp(a, "--bias") == 0 && more) {
            const char *b = argv[++i];
            if (strcmp(b, "plane") == 0) g_bias = SKGL_BIAS_RECEIVER_PLANE;
            else if (strcmp(b, "normal") == 0) g_bias = SKGL_BIAS_NORMAL_OFFSET;
            else { fprintf(stderr, "bench: --bias takes plane or normal, not %s\n", b); return 2; }
        }
        else if (strcmp(a, "--plot-only") == 0) o.plot_only = 1;
        else if (strcmp(a, "--dry-run") == 0) o.dry_run = 1;
        else if (strcmp(a, "--views-only") == 0) { o.views_only = 1; o.images = 1; }
        else if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) { usage(stdout, argv[0]); return 0; }
        else { fprintf(stderr, "bench: unknown or incomplete option %s\n", a); usage(stderr, argv[0]); return 2; }
    }
    if (o.repeat < 1) o.repeat = 1;
    if (o.repeat > BENCH_MAX_REPEAT) o.repeat = BENCH_MAX_REPEAT;
    if (o.views <= 0) o.views = 3;
    if (o.views > BENCH_MAX_VIEWS) o.views = BENCH_MAX_VIEWS;

    if (o.plot_only) {
        /* the repeat count of the sweep that wrote the CSV, for the chart titles */
        FILE *m;
        snprintf(path, sizeof path, "%.900s/bench-data/sweep.txt", o.p.out_dir);
        if (!o.repeat_given && (m = fopen(path, "r"))) {
            if (fscanf(m, "repeat %d", &o.repeat) != 1) o.repeat = 5;
            fclose(m);
        }
        return plot_all(&o, o.repeat) == 0 ? 0 : 1;
    }

    /* ---- scenes */
    {
        ndefs = bench_scenes("bench", BENCH_IN_SWEEP, o.p.scenes_dir, o.p.only, defs, BENCH_MAX_SCENES, &shared);
        if (o.soft_only) ndefs = 0;
        if (ndefs == 0 && !scene_selected(o.p.only, "room") && !scene_selected(o.p.only, "room-spot") &&
            !scene_selected(o.p.only, "interior") && !o.soft_only) {
            fprintf(stderr, "bench: no scene selected (--only %s)\n", o.p.only ? o.p.only : "");
            return 2;
        }
    }
    build_sweep(o.quick, o.methods);
    filter_sweep(o.match);
    for (i = 0; i < g_ncfg; i++) g_cfg[i].desc.bias = g_bias;
    memset(&pg, 0, sizeof pg);
    pg.total = ndefs * o.views * g_ncfg;
    pg.total_units = (long)pg.total * o.repeat;
    {
        /* a priori estimate, measured on a 2-core machine under llvmpipe
           (full sweep, repeat 5: 2610 runs in about 10 minutes): seconds
           per run (timed renders, warm-ups, mask pass, readback, scoring)
           and per scene view (G-buffer, Embree reference) */
        double per_run = 0.04 + 0.04 * o.repeat, per_view = 0.5;
        char est[32];
        fmt_duration(pg.total * per_run + ndefs * o.views * per_view, est, sizeof est);
        fprintf(stderr,
                "bench: %s sweep: %d configurations x %d scene(s) x %d view(s) = %d runs at %dx%d, timings the "
                "median of %d; estimate ~%s on 2-core llvmpipe (much less on a GPU)\n",
                o.quick ? "quick" : "full", g_ncfg, ndefs, o.views, pg.total, BENCH_W, BENCH_H, o.repeat, est);
    }
    if (o.dry_run) {
        for (i = 0; i < ndefs; i++) fprintf(stderr, "  scene %s %s\n", defs[i].name, defs[i].path);
        for (c = 0; c < g_ncfg; c++) fprintf(stderr, "  %-16s %s\n", g_cfg[c].method, g_cfg[c].params);
        return 0;
    }

    /* ---- GL */
    if (bench_gl_open(&B, "bench", SKGL_TIMING_SYNC) != 0) return 1;   /* each run's own times (a stall per pass) */
    g_wall_timing = software_renderer(B.renderer);
    if (software_renderer(B.renderer))
        fprintf(stderr, "bench: NOTE: %s renders on the CPU: its times are comparable only within this run "
                        "(same machine, same load); compare ratios, not absolute ms\n", B.renderer);
    else
        fprintf(stderr, "bench: times are absolute GPU milliseconds on %s (GL timer queries)\n", B.renderer);
    depth = (float *)malloc(sizeof(float) * npx);
    rgba = (float *)malloc(sizeof(float) * 4 * npx);
    nrm = (float *)malloc(sizeof(float) * 3 * npx);
    mask_px = (float *)malloc(sizeof(float) * npx);
    if (!depth || !rgba || !nrm || !mask_px || bench_texel_scratch_init(&g_texel, BENCH_W, BENCH_H) != 0) {
        fprintf(stderr, "bench: out of memory\n");
        status = 1;
        goto done;
    }

    mkdir_p(o.p.out_dir);
    snprintf(path, sizeof path, "%.900s/bench-data", o.p.out_dir);
    mkdir_p(path);
    /* charts of an earlier sweep would no longer match bench.csv */
    for (i = 0; i < bench_scene_count + 3; i++) {
        static const char *const point_scenes[3] = {"room", "room-spot", "interior"};
        snprintf(path, sizeof path, "%.900s/pareto-%s.png", o.p.out_dir,
                 i < bench_scene_count ? bench_scene_table[i].name : point_scenes[i - bench_scene_count]);
        remove(path);
    }
    snprintf(path, sizeof path, "%s/bench.csv", o.p.out_dir);
    csv = fopen(path, "w");
    snprintf(path, sizeof path, "%.900s/bench-walk.csv", o.p.out_dir);
    walk = fopen(path, "w");
    if (walk) fprintf(walk, "%s\n", BENCH_CSV_HEADER);
    snprintf(path, sizeof path, "%.900s/bench-walk.txt", o.p.out_dir);
    walk_txt = fopen(path, "w");
    if (walk_txt) fprintf(walk_txt, "# device %s, times %s\n", B.renderer, timing_label(B.renderer));
    snprintf(path, sizeof path, "%.900s/" BENCH_AUTO_CHOICES, o.p.out_dir);
    autoch = fopen(path, "w");
    snprintf(path, sizeof path, "%.900s/bench-bands.txt", o.p.out_dir);
    bands = fopen(path, "w");
    if (bands) {
        fprintf(bands, "# shadow-area error (%% of the reference's shadow pixels misclassified) by view depth from the "
                       "camera (scene units: metres in the open world), pooled over the views: the sums of wrong and "
                       "of shadow pixels; \"-\": no reference shadow in that band; floor: the over-resolved map "
                       "(bench-limit.txt)\n# device %s\n", B.renderer);
        fprintf(bands, "  %-15s %-52s %8s", "method", "params", "all");
        for (v = 0; v < BENCH_BANDS; v++) fprintf(bands, " %8s", band_name[v]);
        fputc('\n', bands);
    }
    if (!csv) { fprintf(stderr, "bench: cannot write %s: %s\n", path, strerror(errno)); status = 1; goto done; }
    fprintf(csv, "%s\n", BENCH_CSV_HEADER);
    fflush(csv);
    if (!shared) fprintf(stderr, "bench: (reminder) procedural scenes only: %s is missing\n", o.p.scenes_dir);

    pg.t0 = now_s();
    for (i = 0; i < ndefs; i++) {
        const bench_scene_def *def = &defs[i];
        tb_scene s;
        tb_gl_mesh mesh;
        tb_reference *ref = NULL;
        view_data vd[BENCH_MAX_VIEWS];
        bench_view views[3];
        draw_user du;
        skgl_scene sc;
        double ts = now_s();
        run_rec *recs = NULL, floors[BENCH_MAX_VIEWS];
        int pass;
        double last_note = now_s();
        bench_forest fo;
        bench_forest_draw_user fdu;
        const int forest = (def->flags & BENCH_FOREST) != 0;
        memset(vd, 0, sizeof vd);
        memset(&mesh, 0, sizeof mesh);
        memset(&fo, 0, sizeof fo);
        if (load_scene(def, &s) != 0) {
            fprintf(stderr, "bench: cannot load scene %s %s: skipped\n", def->name, def->path);
            tb_scene_free(&s);
            status = 1;
            pg.total -= o.views * g_ncfg;
            pg.total_units -= (long)o.views * g_ncfg * o.repeat;
            continue;
        }
        /* the forest: its ground and instanced trees (bench_forest), not the
           expanded mesh, which only the reference traces */
        if ((!forest && tb_gl_mesh_create(&B.gl, &mesh, &s) != 0) || !(ref = tb_reference_create(&s)) ||
            (forest && bench_forest_open(&B, &fo, &s, ref) != 0)) {
            fprintf(stderr, "bench: cannot upload / build the reference of %s: skipped\n", def->name);
            tb_reference_destroy(ref);
            if (mesh.vao) tb_gl_mesh_destroy(&B.gl, &mesh);
            tb_scene_free(&s);
            status = 1;
            pg.total -= o.views * g_ncfg;
            pg.total_units -= (long)o.views * g_ncfg * o.repeat;
            continue;
        }
        scene_views(def, &s, views);
        for (v = 0; v < o.views; v++) {
            vd[v].v = views[v];
            if (prepare_view(&B, &mesh, forest ? &fo : NULL, ref, def->light_dir, NULL, &vd[v], depth, rgba, nrm) !=
                0) {
                fprintf(stderr, "bench: G-buffer / reference failed for %s view %s\n", def->name, views[v].name);
                status = 1;
                goto scene_done;
            }
            if (o.images) {
                snprintf(path, sizeof path, "%.900s/bench/%.63s-%.15s-reference.png", o.p.out_dir, def->name,
                         views[v].name);
                write_shaded(path, vd[v].ref, nrm, def->light_dir);
            }
        }
        fprintf(stderr, "bench: scene %s: %u triangles, %d view(s) (", def->name, tb_scene_triangle_count(&s), o.views);
        for (v = 0; v < o.views; v++)
            fprintf(stderr, "%s%s %.0f%% covered", v ? ", " : "", vd[v].v.name, 100.0 * vd[v].covered / (double)npx);
        fprintf(stderr, "); references traced in %.1f s\n", now_s() - ts);

        if (o.views_only) goto scene_done;
        du.gl = &B.gl;
        du.scene = &s;
        du.mesh = &mesh;
        sc.draw = draw_casters;
        sc.user = &du;
        sc.bounds = s.bounds;
        if (forest) {
            fdu.gl = &B.gl;
            fdu.sk = B.sk;
            fdu.f = &fo;
            sc.draw = bench_forest_draw;
            sc.user = &fdu;
        }
        /* Timing passes: every configuration once per pass, `repeat` passes,
           so that a slow spell of the machine (other jobs on a shared CPU
           under llvmpipe) touches one sample of many configurations rather
           than every sample of one. Per configuration and pass: a new map,
           one warm-up render (not timed), then one timed render per view;
           a light analysing through the read-back ring (AUTO, .fit_to_depth)
           gets a new map and ANALYSIS_WARM untimed frames on each view
           instead, so that it renders from that view's own depth range.
           The last pass also runs the mask pass once per view and scores it. */
        recs = (run_rec *)calloc((size_t)g_ncfg * (size_t)o.views, sizeof *recs);
        if (!recs) { fprintf(stderr, "bench: out of memory\n"); status = 1; goto scene_done; }
        for (pass = 0; pass < o.repeat; pass++) {
            int last = pass == o.repeat - 1;
            for (c = 0; c < g_ncfg; c++) {
                const bench_cfg *cfg = &g_cfg[c];
                run_rec *rc = recs + (size_t)c * (size_t)o.views;
                skgl_shadow *sh = NULL;
                sk_result r;
                float warm_ms;
                int live = 0;
                for (v = 0; v < o.views; v++) live += rc[v].state >= 0;
                if (!live) continue;
                r = skgl_shadow_create(B.sk, &cfg->desc, &sh);
                if (r == SK_OK) r = render_frame(&B, sh, &vd[0], &sc, def->light_dir, &warm_ms);   /* warm-up */
                if (r != SK_OK) {
                    fprintf(stderr, "bench: FAILED %s %s %s: skgl_shadow_create/render: %s %s\n", def->name,
                            cfg->method, cfg->params, sk_result_string(r), skgl_error_log(B.sk));
                    for (v = 0; v < o.views; v++)
                        if (rc[v].state >= 0) { rc[v].state = -1; pg.total--; pg.total_units -= o.repeat - pass; }
                    status = 1;
                    skgl_shadow_destroy(B.sk, sh);
                    continue;
                }
                for (v = 0; v < o.views; v++) {
                    run_rec *rr = &rc[v];
                    const char *why = "skgl_shadow_render";
                    if (rr->state < 0) continue;
                    r = SK_OK;
                    if (analysing_async(&cfg->desc)) {
                        int w;
                        if (v > 0) {
                            skgl_shadow_destroy(B.sk, sh);
                            sh = NULL;
                            r = skgl_shadow_create(B.sk, &cfg->desc, &sh);
                        }
                        for (w = v > 0 ? 0 : 1; w < ANALYSIS_WARM && r == SK_OK; w++)
                            r = render_frame(&B, sh, &vd[v], &sc, def->light_dir, &warm_ms);
                        if (r != SK_OK) why = "skgl_shadow_create/render (warm-up)";
                    }
                    if (r == SK_OK) r = render_frame(&B, sh, &vd[v], &sc, def->light_dir, &rr->analysis[rr->n]);
                    if (r == SK_OK) {
                        rr->shadow[rr->n++] = render_ms(sh);
                        pg.units++;
                    }
                    if (r != SK_OK || (last && score_run(&B, sh, &vd[v], mask_px, rr, &why) != 0)) {
                        fprintf(stderr, "bench: FAILED %s %s %s %s: %s: %s\n", def->name, vd[v].v.name, cfg->method,
                                cfg->params, why, skgl_error_log(B.sk));
                        rr->state = -1;
                        status = 1;
                        pg.total--;
                        pg.total_units -= o.repeat - rr->n;
                        continue;
                    }
                    if (last) {
                        char el_s[32], eta_s[32];
                        float tmp[BENCH_MAX_REPEAT];
                        memcpy(tmp, rr->shadow, sizeof tmp);
                        rr->state = 1;
                        pg.done++;
                        progress_times(&pg, el_s, eta_s, sizeof el_s);
                        fprintf(stderr, "[%4d/%d %s, eta %s] %-15s %-8s %-15s %-48s err %7.3f%% (shadow area "
                                        "%7.3f%%, edge p95 %5.2f px)  shadow %8.2f ms  mask %7.2f ms\n", pg.done,
                                pg.total, el_s, eta_s, def->name, vd[v].v.name, cfg->method, cfg->params, rr->err,
                                rr->hard.area_pct, rr->hard.edge_p95_px, (double)median(tmp, rr->n),
                                (double)rr->mask_ms);
                        if (rr->reason[0]) {
                            fprintf(stderr, "        auto on %s: %s\n", vd[v].v.name, rr->reason);
                            if (autoch)
                            {
                                fprintf(autoch, "%s %s %s %s\n", def->name, cfg->params, vd[v].v.name, rr->reason);
                                fflush(autoch);
                            }
                        }
                        if (o.images && c == 0) {
                            snprintf(path, sizeof path, "%.900s/bench/%.63s-%.15s-error-%.31s.png", o.p.out_dir,
                                     def->name, vd[v].v.name, cfg->method);
                            tb_image_write_error(path, BENCH_W, BENCH_H, vd[v].ref, mask_px);
                        }
                    }
                }
                skgl_shadow_destroy(B.sk, sh);
                if (!last && now_s() - last_note > 15.0) {   /* a sign of life between the scored lines */
                    char el_s[32], eta_s[32];
                    progress_times(&pg, el_s, eta_s, sizeof el_s);
                    fprintf(stderr, "[%s, eta %s] %s: timing pass %d of %d: %d of %d configurations\n", el_s, eta_s,
                            def->name, pass + 1, o.repeat, c + 1, g_ncfg);
                    last_note = now_s();
                }
            }
            if (!last) {
                char el_s[32], eta_s[32];
                progress_times(&pg, el_s, eta_s, sizeof el_s);
                fprintf(stderr, "[%s, eta %s] %s: timing pass %d of %d done (%d configurations x %d views); "
                                "scores follow in the last pass\n", el_s, eta_s, def->name, pass + 1, o.repeat,
                        g_ncfg, o.views);
            }
        }
        /* the scene's rows: shadow_ms the median over the passes */
        for (c = 0; c < g_ncfg; c++)
            for (v = 0; v < o.views; v++) {
                const bench_cfg *cfg = &g_cfg[c];
                run_rec *rr = &recs[(size_t)c * (size_t)o.views + (size_t)v];
                float sms;
                if (rr->state != 1) continue;
                sms = median(rr->shadow, rr->n);
                write_row(csv, cfg->method, cfg->params, def->name, vd[v].v.name, rr, sms, B.renderer);
            }
        fflush(csv);
        if (!o.no_floor) floor_runs(&B, def, vd, o.views, &sc, mask_px, csv, floors);
        if (bands) {
            fprintf(bands, "scene %s\n", def->name);
            for (c = 0; c < g_ncfg; c++)
                bands_line(bands, g_cfg[c].method, g_cfg[c].params, recs + (size_t)c * (size_t)o.views, o.views);
            if (!o.no_floor) bands_line(bands, BENCH_FLOOR, "the finer of rmsm 65536 and standard 16384 per view",
                                        floors, o.views);
            fflush(bands);
        }
        if (walk) walk_scene(&B, def, &s, &mesh, forest ? &fo : NULL, ref, views, &sc, o.quick ? 6 : 12, o.repeat, depth, rgba, nrm,
                             mask_px, walk, walk_txt);
        fprintf(stderr, "bench: scene %s done in %.1f s\n", def->name, now_s() - ts);
    scene_done:
        free(recs);
        recs = NULL;
        for (v = 0; v < BENCH_MAX_VIEWS; v++) {
            free_view(&B, &vd[v]);
        }
        tb_reference_destroy(ref);
        if (mesh.vao) tb_gl_mesh_destroy(&B.gl, &mesh);
        if (forest) {
            if (fo.failed_calls) {
                fprintf(stderr, "bench: forest: skgl_use_caster failed %d times: %s\n", fo.failed_calls,
                        skgl_error_log(B.sk));
                status = 1;
            }
            bench_forest_close(&B, &fo);
        }
        tb_scene_free(&s);
    }
    if (scene_selected(o.p.only, "room") && !o.soft_only) point_bench(&B, o.repeat, csv, depth, mask_px);
    if (scene_selected(o.p.only, "room-spot") && !o.soft_only) spot_bench(&B, o.repeat, csv, depth, mask_px);
    if (scene_selected(o.p.only, "interior") && !o.soft_only) interior_bench(&B, o.quick, o.repeat, csv, depth, mask_px);
    if (!o.no_soft) soft_bench(&B, &o, csv, depth, rgba, nrm, mask_px);
    fclose(csv);
    csv = NULL;
    if (walk) fclose(walk);
    if (walk_txt) fclose(walk_txt);
    if (bands) fclose(bands);
    if (autoch) fclose(autoch);
    walk = walk_txt = bands = autoch = NULL;
    {
        char a[32];
        fmt_duration(now_s() - t_start, a, sizeof a);
        fprintf(stderr, "bench: %d runs in %s; wrote %s/bench.csv\n", pg.done, a, o.p.out_dir);
    }
    {
        FILE *m;
        snprintf(path, sizeof path, "%.900s/bench-data", o.p.out_dir);
        mkdir_p(path);
        snprintf(path, sizeof path, "%.900s/bench-data/sweep.txt", o.p.out_dir);
        if ((m = fopen(path, "w"))) {
            fprintf(m, "repeat %d\nsweep %s\nviews %d\nruns %d\ndevice %s\ntiming %s\nbias %s\n", o.repeat,
                    o.quick ? "quick" : "full", o.views, pg.done, B.renderer, timing_label(B.renderer),
                    g_bias == SKGL_BIAS_NORMAL_OFFSET ? "normal" : "plane");
            fclose(m);
        }
    }
    if (plot_all(&o, o.repeat) != 0) status = 1;
    fprintf(stderr, "bench: device %s: times %s\n", B.renderer, timing_label(B.renderer));

done:
    if (csv) fclose(csv);
    free(depth);
    free(rgba);
    free(nrm);
    free(mask_px);
    bench_texel_scratch_free(&g_texel);
    bench_gl_close(&B);
    return status;
}
