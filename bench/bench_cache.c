/* bench/bench_cache.c - cached shadow maps (shadowkit_gl.h CACHED MAPS)
   against the same lights uncached, frame by frame along a camera walk.

   What it does
     Per scene, two walks of `--frames` frames (default 60) along one path:
       static  the camera walks; nothing moves;
       moving  the same walk, plus one box caster (the "mover", its side 5%
               of the scene's diagonal) given to skgl_set_dynamic each
               frame, crossing the view: it travels along the camera's
               sideways axis through the content's centre, from one side of
               the content to the other over the walk. skgl_dynamic.bounds
               is its box, so that a cached map draws it only where it is
               (and restores where it was): without it the dynamic pass
               covers every texel of every cached layer. The static walk
               sets no dynamic casters (skgl_set_dynamic NULL).
     Each technique runs twice in the same process, the same desc but
     .cache: "cached" (1) and "uncached" (0). Both render every frame, the
     one first on even frames and the other first on odd ones. Techniques:
       pssm4-stable     SKGL_PSSM, 4 cascades, .stable = 1, 2048^2 a cascade
       standard-stable  SKGL_STANDARD, .stable = 1 (the stable focused map), 2048^2
       point-cube       SKGL_POINT_CUBE, 512^2 a face, .cull_faces = 1; the
                        light inside the scene's bounds (see point_light_of),
                        its range reaching every corner of them
       rmsm             SKGL_RMSM, 8192^2 virtual, 128-texel pages, a pool of
                        24 x 24; analysed every frame (skgl_shadow_analyze
                        on the frame's G-buffer depth, the scene without the
                        mover, with .sync_readback = 1 so that both lights
                        see the same requests; the analysis is not timed:
                        the same in both modes)
     Directional light: the bench's, travelling along (-0.45, -1, -0.35).

   The walk: the bench's "overview" view (bench_common.c make_views: the
   content from 35 degrees up along its long axis, framed) moving each frame
   0.5% of the eye-target distance d sideways and 0.3% of d forward
   (horizontal), the target with it: several texels of the 2048^2 stable
   map a frame, more in the near cascades. The projection is fixed for the
   walk (50 degrees, 16:9, near 0.002 d, far past the farthest corner of the
   scene's bounds seen from either end of the path): a stable crop keeps its
   size only while the near and far planes do.

   The callbacks (draw_static; draw_dynamic, the skgl_dynamic's) cull each object by its box
   against the pass's frustum, and a pass that draws only a rectangle of
   its map (info->rect: a scrolled crop's exposed strip, an invalidated
   region) against the frustum of that rectangle alone, as CACHED MAPS
   suggests for callbacks that cull finely.

   Timing: shadow_ms is the CPU wall time of skgl_shadow_render /
   skgl_point_render between two glFinish calls on a CPU rasteriser
   (llvmpipe, softpipe: the times compare within this run only); on a GPU
   the GL timer query of the render (skgl_desc.timing = SKGL_TIMING_SYNC).
   The ratios take frames 1..N-1 (frame 0 draws everything in both modes).

   Error: every `--error-every` frames (default 6, frame 0 included) the
   G-buffer at 1280x720 is drawn (with the mover where it is on the moving
   walk), the exact Embree reference traced (tb_reference_trace_exact; on
   the moving walk the reference scene is rebuilt with the mover in place)
   and each light's mask scored: error = tb_metric_shadow's shadow-area
   error (% of the reference's shadow pixels misclassified, as bench.c's
   shadow_area_pct); differ_pct = the % of covered pixels whose lit/shadow
   class differs between the cached and the uncached mask of the frame
   (cached rows). Both are empty on the other frames.

   Output (under --out, default out/)
     bench-cache.csv   one row per (scene, technique, walk, mode, frame):
       scene,technique,walk,mode,frame,texels,passes,callbacks,shadow_ms,
       error,differ_pct,cache_full,cache_scrolled,cache_reused,
       cache_regions,cache_copied,cache_bytes,cache_layers,faces_reused,
       faces_rendered,faces_culled,device
       walk        static | moving;   mode  cached | uncached
       texels      the stats' texels (viewport areas drawn, exposed strips
                   and dynamic rectangles included)
       passes      the stats' passes; callbacks: the calls this bench's
                   draw callbacks received (scene.draw and the dynamic
                   one counted apart)
       cache_*     the directional stats' (empty on point rows but
                   cache_regions, cache_copied, cache_bytes); faces_*: the
                   point light's (empty on directional rows)
       device      GL renderer string (CSV-quoted)
     bench-cache.txt   per scene and technique, for each walk: the cached /
                   uncached ratios of the mean texels and passes per frame
                   and of the median shadow time, marked against the goals
                   (static walk: texels <= 0.2x, time <= 0.3x; moving walk:
                   texels and time <= 0.4x), the mean error of each mode and
                   the mean differ_pct; the cache memory of each technique
     bench-cache-<scene>.png  gnuplot (bench/cache.gp): shadow time per
                   frame along the walk, one line per technique and mode,
                   the static walk above, the moving walk below
     bench-cache-data/<scene>.dat, .vars.gp   that chart's data

   Scenes: those of bench_common.c's bench_scene_table marked
   BENCH_IN_CACHE: stanford-bunny, sponza-ivy and sponza-curtains from
   ../shared/scenes (--scenes DIR) when it exists, each on a ground plane
   3x its horizontal extent, then the procedural ground-boxes, fence and
   terrace.

   Usage (from the repository root; `make bench-cache`, `make bench-cache-demo`):
     build/bench/bench_cache [--quick] [--frames N] [--error-every K]
                             [--scenes DIR] [--out DIR] [--only LIST] [--gp FILE]
     --quick   procedural scenes only, 20 frames (make demo)
   Run time on 2 cores under llvmpipe: about 7 minutes with the shared
   scenes (70% of it the scored frames' references and masks), 1 minute
   with --quick.
   Exit status 0; 1 on a setup or render failure; 2 on a usage error. */
#define _POSIX_C_SOURCE 200809L
#include "bench_common.h"

#include "tb_metrics.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define CW BENCH_W                 /* the camera's image (aspect, scoring) */
#define CH BENCH_H
#define MAX_FRAMES 240
#define DIR_RES 2048
#define RMSM_RES 8192
#define POINT_RES 512
#define MOVER_FRAC 0.05f           /* the mover's side / the scene's diagonal */
#define STEP_SIDE 0.005f           /* camera step a frame, of the eye-target distance */
#define STEP_FWD 0.003f
#define GOAL_STATIC_TEXELS 0.2
#define GOAL_STATIC_TIME 0.3
#define GOAL_MOVING 0.4
#define CSV_HEADER                                                                                            \
    "scene,technique,walk,mode,frame,texels,passes,callbacks,shadow_ms,error,differ_pct,cache_full,"          \
    "cache_scrolled,cache_reused,cache_regions,cache_copied,cache_bytes,cache_layers,faces_reused,"            \
    "faces_rendered,faces_culled,pages_rendered,pages_reused,pages_evicted,device"

enum { T_PSSM, T_STANDARD, T_RMSM, T_POINT, NTECH };
#define NDIR 3                     /* the directional techniques, first */
enum { WALK_STATIC, WALK_MOVING, NWALK };
enum { M_CACHED, M_UNCACHED, NMODE };
static const char *const tech_name[NTECH] = {"pssm4-stable", "standard-stable", "rmsm", "point-cube"};
static const char *const walk_name[NWALK] = {"static", "moving"};
static const char *const mode_name[NMODE] = {"cached", "uncached"};

/* ---------------------------------------------------------- the walk */
/* farthest corner of b from p */
static float farthest(sk_vec3 p, const sk_aabb *b) {
    float m = 0.0f;
    int i;
    for (i = 0; i < 8; i++) {
        sk_vec3 c = v3(i & 1 ? b->max.x : b->min.x, i & 2 ? b->max.y : b->min.y, i & 4 ? b->max.z : b->min.z);
        float l = v3_len(v3_sub(c, p));
        if (l > m) m = l;
    }
    return m;
}

/* The walk of a scene: the benches' overview (eye0, target0) and the step a
   frame; proj fixed for the walk. The mover crosses the content along
   `side`, standing on its lowest point. */
typedef struct walk_path {
    sk_vec3 eye0, target0, side, fwd;   /* side, fwd: horizontal unit vectors */
    float d, zn, zf;
    sk_mat4 proj;
    sk_vec3 mover_a, mover_b;           /* the mover's base centre at the first and the last frame */
    float mover_size;
    sk_aabb bounds;                     /* scene.bounds: the scene's and the mover's whole path */
    sk_vec3 point_pos;                  /* the point light */
    float point_range;
} walk_path;

static void camera_at(const walk_path *w, int f, skgl_camera *cam, sk_mat4 *vp) {
    sk_vec3 off = v3_add(v3_scale(w->side, STEP_SIDE * w->d * (float)f), v3_scale(w->fwd, STEP_FWD * w->d * (float)f));
    cam->view = sk_mat4_look_at(v3_add(w->eye0, off), v3_add(w->target0, off), v3(0, 1, 0));
    cam->proj = w->proj;
    *vp = sk_mat4_mul(cam->proj, cam->view);
}

static sk_vec3 mover_at(const walk_path *w, int f, int frames) {
    float t = frames > 1 ? (float)f / (float)(frames - 1) : 0.0f;
    return v3_add(v3_scale(w->mover_a, 1.0f - t), v3_scale(w->mover_b, t));
}
static sk_aabb mover_box(const walk_path *w, sk_vec3 at) {
    sk_aabb b;
    float h = 0.5f * w->mover_size;
    b.min = v3(at.x - h, at.y, at.z - h);
    b.max = v3(at.x + h, at.y + w->mover_size, at.z + h);
    return b;
}

/* The point light: halfway from the content's centre toward its (+x, +z)
   edge, at 80% of its height (off the centre, where a model such as the
   bunny is solid; below the top, inside the scene's bounds); its range
   reaches every corner of the scene's bounds. */
static void point_light_of(const tb_scene *s, walk_path *w) {
    sk_aabb cb = content_bounds(s);
    sk_vec3 c = v3_scale(v3_add(cb.min, cb.max), 0.5f), ex = v3_scale(v3_sub(cb.max, cb.min), 0.5f);
    w->point_pos = v3(c.x + 0.5f * ex.x, cb.min.y + 1.6f * ex.y, c.z + 0.5f * ex.z);
    w->point_range = 1.01f * farthest(w->point_pos, &w->bounds);
}

static void make_walk(const tb_scene *s, int frames, walk_path *w) {
    sk_aabb cb = content_bounds(s), all = s->bounds, path;
    sk_vec3 c = v3_scale(v3_add(cb.min, cb.max), 0.5f), ex = v3_scale(v3_sub(cb.max, cb.min), 0.5f);
    sk_vec3 fwd, eye1;
    bench_view views[BENCH_VIEWS];
    float half, diag;
    memset(w, 0, sizeof *w);
    make_views(s, views);   /* the walk starts at the overview */
    w->target0 = views[0].target;
    w->eye0 = views[0].eye;
    w->d = v3_len(v3_sub(w->target0, w->eye0));
    fwd = v3_sub(w->target0, w->eye0);
    fwd.y = 0.0f;
    w->fwd = v3_norm(fwd);
    w->side = v3(-w->fwd.z, 0.0f, w->fwd.x);
    /* the mover: its side a fraction of the scene's diagonal, crossing the
       content along the camera's sideways axis through the centre */
    diag = (float)tb_scene_diagonal(s);
    w->mover_size = MOVER_FRAC * diag;
    half = 0.8f * (fabsf(w->side.x) * ex.x + fabsf(w->side.z) * ex.z);
    w->mover_a = v3(c.x - w->side.x * half, cb.min.y, c.z - w->side.z * half);
    w->mover_b = v3(c.x + w->side.x * half, cb.min.y, c.z + w->side.z * half);
    path = aabb_union(mover_box(w, w->mover_a), mover_box(w, w->mover_b));
    w->bounds = aabb_union(all, path);
    /* the projection: near 0.002 d, far past the bounds from both ends of the path */
    eye1 = v3_add(w->eye0, v3_add(v3_scale(w->side, STEP_SIDE * w->d * (float)(frames - 1)),
                                  v3_scale(w->fwd, STEP_FWD * w->d * (float)(frames - 1))));
    w->zf = 1.01f * (farthest(w->eye0, &w->bounds) > farthest(eye1, &w->bounds) ? farthest(w->eye0, &w->bounds)
                                                                                  : farthest(eye1, &w->bounds));
    w->zn = 0.002f * w->d;
    if (w->zn < w->zf * 1e-5f) w->zn = w->zf * 1e-5f;
    w->proj = sk_mat4_perspective(BENCH_FOVY, (float)CW / (float)CH, w->zn, w->zf);
    point_light_of(s, w);
}

/* -------------------------------------------------------- the callbacks */
typedef struct world {
    const tb_gl_funcs *gl;
    skgl_context *sk;
    const tb_scene *s;
    unsigned nstatic;          /* objects of s that scene.draw draws (the mover is appended after them) */
    const tb_gl_mesh *mesh, *mover_mesh;
    sk_vec3 mover_at;
    long callbacks;
    int target_res;            /* side of the map the pass draws into (info->rect's frame) */
} world;

/* the frustum of the texel rectangle rect (x, y, w, h) of a res x res
   pass with matrix vp, one texel wider each side */
static sk_frustum rect_frustum(const sk_mat4 *vp, const int rect[4], int res) {
    float l = 2.0f * (float)(rect[0] - 1) / (float)res - 1.0f;
    float r = 2.0f * (float)(rect[0] + rect[2] + 1) / (float)res - 1.0f;
    float b = 2.0f * (float)(rect[1] - 1) / (float)res - 1.0f;
    float t = 2.0f * (float)(rect[1] + rect[3] + 1) / (float)res - 1.0f;
    sk_mat4 m = sk_mat4_identity();
    m.m[0] = 2.0f / (r - l);
    m.m[12] = -(r + l) / (r - l);
    m.m[5] = 2.0f / (t - b);
    m.m[13] = -(t + b) / (t - b);
    return sk_frustum_from_matrix(sk_mat4_mul(m, *vp));
}

/* scene.draw: the static objects whose box meets the pass's frustum (or
   that of its rectangle) */
static void draw_static(void *user, const skgl_draw_info *info) {
    world *w = (world *)user;
    sk_frustum f = info->frustum;
    unsigned i;
    w->callbacks++;
    if (info->rect[2] > 0 && info->rect[3] > 0)
        f = rect_frustum(&info->view_proj, info->rect, info->kind == SKGL_PASS_CUBE_FACE ? POINT_RES : w->target_res);
    for (i = 0; i < w->nstatic; i++) {
        const tb_object *o = &w->s->objects[i];
        sk_frustum box;
        if (sk_frustum_from_aabb(o->bounds, &box) == SK_OK && !sk_frustum_intersects(&f, &box)) continue;
        tb_gl_mesh_draw(w->gl, w->mesh, o->first_index, o->index_count);
    }
}

/* the skgl_dynamic callback: the mover, translated to mover_at */
static void draw_dynamic(void *user, const skgl_draw_info *info) {
    world *w = (world *)user;
    float m[16];
    (void)info;
    w->callbacks++;
    memset(m, 0, sizeof m);
    m[0] = m[5] = m[10] = m[15] = 1.0f;
    m[12] = w->mover_at.x;
    m[13] = w->mover_at.y;
    m[14] = w->mover_at.z;
    skgl_set_model(w->sk, m);
    tb_gl_mesh_draw(w->gl, w->mover_mesh, 0, 0);
}

/* ------------------------------------------------------------ the record */
typedef struct frame_rec {
    int done;
    double texels, ms, err, differ, copied, bytes;
    int passes, callbacks, err_ok, differ_ok;
    int full, scrolled, reused, regions, layers;
    int faces_reused, faces_rendered, faces_culled;
    int pages_rendered, pages_reused, pages_evicted;
} frame_rec;

static frame_rec g_rec[NTECH][NWALK][NMODE][MAX_FRAMES];

typedef struct bench {
    bench_gl g;                /* context, G-buffer program, mask target, shadowkit */
    tb_gl_fbo gbuf;
    int wall;                  /* 1: time by the wall clock between glFinish calls */
    float *depth, *ref_dir, *ref_point, *mask_px[NTECH][NMODE];
    float *rgba, *nrm;             /* the G-buffer's normals (the reference's same-face test) */
} bench;


/* --------------------------------------------------------------- lights */
/* the lights of one walk, made anew for it (the caches start empty) */
typedef struct lights {
    skgl_shadow *dir[NDIR][NMODE];   /* [T_PSSM], [T_STANDARD], [T_RMSM] */
    skgl_point *point[NMODE];
} lights;

static void free_lights(bench *B, lights *L) {
    int m, t;
    for (m = 0; m < NMODE; m++) {
        for (t = 0; t < NDIR; t++) skgl_shadow_destroy(B->g.sk, L->dir[t][m]);
        skgl_point_destroy(B->g.sk, L->point[m]);
    }
    memset(L, 0, sizeof *L);
}

/* the same desc twice, .cache 1 (cached) and 0 (uncached) */
static int make_lights(bench *B, lights *L, float point_range) {
    int m, t;
    sk_result r;
    memset(L, 0, sizeof *L);
    for (m = 0; m < NMODE; m++) {
        skgl_point_desc pd;
        for (t = 0; t < NDIR; t++) {
            skgl_shadow_desc d;
            memset(&d, 0, sizeof d);
            d.technique = t == T_PSSM ? SKGL_PSSM : t == T_RMSM ? SKGL_RMSM : SKGL_STANDARD;
            d.cascades = t == T_PSSM ? 4 : 1;
            d.stable = t != T_RMSM;
            d.resolution = t == T_RMSM ? RMSM_RES : DIR_RES;
            d.sync_readback = t == T_RMSM;
            d.cache = m == M_CACHED;
            r = skgl_shadow_create(B->g.sk, &d, &L->dir[t][m]);
            if (r != SK_OK) {
                fprintf(stderr, "bench-cache: skgl_shadow_create %s %s: %s (%s)\n", tech_name[t], mode_name[m],
                        sk_result_string(r), skgl_error_log(B->g.sk));
                free_lights(B, L);
                return -1;
            }
        }
        memset(&pd, 0, sizeof pd);
        pd.technique = SKGL_POINT_CUBE;
        pd.resolution = POINT_RES;
        pd.range = point_range;
        pd.cull_faces = 1;
        pd.cache = m == M_CACHED;
        r = skgl_point_create(B->g.sk, &pd, &L->point[m]);
        if (r != SK_OK) {
            fprintf(stderr, "bench-cache: skgl_point_create %s: %s (%s)\n", mode_name[m], sk_result_string(r),
                    skgl_error_log(B->g.sk));
            free_lights(B, L);
            return -1;
        }
    }
    return 0;
}

/* One light's render of a frame, timed (the wall clock between two
   glFinish calls on a CPU rasteriser, else the timer query), its stats
   into fr. 0 ok. */
static int render_one(bench *B, lights *L, int t, int m, const skgl_camera *cam, const skgl_scene *sc,
                      sk_vec3 light_dir, sk_vec3 light_pos, world *w, frame_rec *fr) {
    double t0;
    sk_result r;
    w->callbacks = 0;
    /* info->rect's viewport: a face, a layer, an RMSM page's slot */
    w->target_res = t == T_POINT ? POINT_RES : t == T_RMSM ? skgl_shadow_get_desc(L->dir[t][m]).rmsm_page_size + 2
                                                           : DIR_RES;
    if (t == T_RMSM) {   /* the requests of this frame's view (not timed) */
        r = skgl_shadow_analyze(B->g.sk, L->dir[t][m], cam, sc, light_dir, B->gbuf.depth_tex);
        if (r != SK_OK) {
            fprintf(stderr, "bench-cache: rmsm %s analysis failed: %s (%s)\n", mode_name[m], sk_result_string(r),
                    skgl_error_log(B->g.sk));
            return -1;
        }
    }
    if (B->wall) B->g.gl.Finish();
    t0 = now_s();
    if (t == T_POINT) r = skgl_point_render(B->g.sk, L->point[m], cam, sc, light_pos);
    else r = skgl_shadow_render(B->g.sk, L->dir[t][m], cam, sc, light_dir);
    if (B->wall) B->g.gl.Finish();
    fr->ms = (now_s() - t0) * 1e3;
    if (r != SK_OK) {
        fprintf(stderr, "bench-cache: %s %s render failed: %s (%s)\n", tech_name[t], mode_name[m],
                sk_result_string(r), skgl_error_log(B->g.sk));
        return -1;
    }
    fr->callbacks = (int)w->callbacks;
    if (t == T_POINT) {
        const skgl_point_frame_stats *st = skgl_point_stats(L->point[m]);
        if (!B->wall) fr->ms = st->shadow_ms;
        fr->texels = st->texels;
        fr->passes = st->passes;
        fr->regions = st->cache_regions;
        fr->copied = st->cache_copied;
        fr->bytes = st->cache_bytes;
        fr->faces_reused = st->faces_reused;
        fr->faces_rendered = st->faces_rendered;
        fr->faces_culled = st->faces_culled;
    } else {
        const skgl_shadow_frame_stats *st = skgl_shadow_stats(L->dir[t][m]);
        if (!B->wall) fr->ms = st->shadow_ms;
        fr->texels = st->texels;
        fr->passes = st->passes;
        fr->full = st->cache_full;
        fr->scrolled = st->cache_scrolled;
        fr->reused = st->cache_reused;
        fr->regions = st->cache_regions;
        fr->copied = st->cache_copied;
        fr->bytes = st->cache_bytes;
        fr->layers = st->cache_layers;
        fr->pages_rendered = st->pages_rendered;
        fr->pages_reused = st->pages_reused;
        fr->pages_evicted = st->pages_evicted;
    }
    fr->done = 1;
    return 0;
}

/* this frame's G-buffer (mesh: the scene as it is now) and the exact
   references of both lights; 0 ok */
static int prepare_frame(bench *B, const tb_gl_mesh *mesh, const tb_reference *ref, const sk_mat4 *vp,
                         sk_vec3 light_dir, const walk_path *wp) {
    tb_light L;
    if (tb_gl_gbuffer_render(&B->g.gl, &B->g.gb, mesh, &B->gbuf, vp) != 0) return -1;
    if (tb_gl_read_depth(&B->g.gl, B->gbuf.fbo, CW, CH, B->depth) != 0) return -1;
    if (tb_gl_read_normals(&B->g.gl, B->gbuf.fbo, CW, CH, B->rgba, B->nrm) != 0) return -1;
    memset(&L, 0, sizeof L);
    L.type = TB_LIGHT_DIRECTIONAL;
    L.direction = light_dir;
    if (bench_trace(ref, vp, B->depth, B->nrm, &L, B->ref_dir) != 0) return -1;
    memset(&L, 0, sizeof L);
    L.type = TB_LIGHT_POINT;
    L.position = wp->point_pos;
    L.range = wp->point_range;
    return bench_trace(ref, vp, B->depth, B->nrm, &L, B->ref_point);
}

/* light (t, m)'s mask of this frame into B->mask_px[t][m]; 0 ok */
static int mask_of(bench *B, lights *L, int t, int m, const skgl_camera *cam) {
    sk_result r;
    if (t == T_POINT) {
        /* the mask starts lit: a scissored pass leaves the rest as it is */
        tb_gl_fbo_bind(&B->g.gl, &B->g.mask);
        B->g.gl.ClearColor(1, 1, 1, 1);
        B->g.gl.Clear(0x00004000u);
        tb_gl_fbo_bind(&B->g.gl, NULL);
        r = skgl_point_mask(B->g.sk, L->point[m], cam, B->gbuf.depth_tex, B->gbuf.color_tex, B->g.mask.color_tex);
    } else {
        r = skgl_shadow_mask(B->g.sk, L->dir[t][m], cam, B->gbuf.depth_tex, B->gbuf.color_tex, B->g.mask.color_tex);
    }
    if (r != SK_OK) {
        fprintf(stderr, "bench-cache: %s %s mask failed: %s (%s)\n", tech_name[t], mode_name[m], sk_result_string(r),
                skgl_error_log(B->g.sk));
        return -1;
    }
    return tb_gl_read_red(&B->g.gl, B->g.mask.fbo, CW, CH, B->mask_px[t][m]);
}

/* the scores of technique t this frame: each mode's shadow-area error, and
   the cached mask's class differences from the uncached one */
static void score(bench *B, int t, frame_rec *fc, frame_rec *fu) {
    const float *ref = t == T_POINT ? B->ref_point : B->ref_dir;
    const float *a = B->mask_px[t][M_CACHED], *b = B->mask_px[t][M_UNCACHED];
    size_t i, n = (size_t)CW * CH, covered = 0, differ = 0;
    tb_shadow_error e;
    e = tb_metric_shadow(ref, a, CW, CH);
    if (e.ok && e.shadow > 0) { fc->err = e.area_pct; fc->err_ok = 1; }
    e = tb_metric_shadow(ref, b, CW, CH);
    if (e.ok && e.shadow > 0) { fu->err = e.area_pct; fu->err_ok = 1; }
    for (i = 0; i < n; i++) {
        if (!(ref[i] >= 0.0f)) continue;
        covered++;
        differ += (a[i] >= TB_LIT_THRESHOLD) != (b[i] >= TB_LIT_THRESHOLD);
    }
    if (covered > 0) {
        fc->differ = 100.0 * (double)differ / (double)covered;
        fc->differ_ok = 1;
    }
}

/* the lit share of the covered pixels of a reference (the point light's
   placement check in the txt) */
static double lit_share(const float *ref) {
    size_t i, n = (size_t)CW * CH, c = 0, l = 0;
    for (i = 0; i < n; i++)
        if (ref[i] >= 0.0f) { c++; l += ref[i] >= TB_LIT_THRESHOLD; }
    return c ? 100.0 * (double)l / (double)c : 0.0;
}

/* ------------------------------------------------------------ the report */
typedef struct summary {
    double texels[NMODE], passes[NMODE], callbacks[NMODE], ms[NMODE], err[NMODE], differ;
    int err_n[NMODE], differ_n, n;
    int full, scrolled, reused, regions, faces_reused, faces_rendered;
    int pages_rendered, pages_reused, pages_evicted;
} summary;

/* frames 1.. for the ratios (frame 0 draws everything in both modes); the
   errors over every scored frame */
static summary summarise(int t, int wk, int frames) {
    summary s;
    double tmp[MAX_FRAMES];
    int m, f, n;
    memset(&s, 0, sizeof s);
    for (m = 0; m < NMODE; m++) {
        n = 0;
        for (f = 0; f < frames; f++) {
            const frame_rec *r = &g_rec[t][wk][m][f];
            if (!r->done) continue;
            if (r->err_ok) { s.err[m] += r->err; s.err_n[m]++; }
            if (m == M_CACHED && r->differ_ok) { s.differ += r->differ; s.differ_n++; }
            if (f == 0) continue;
            s.texels[m] += r->texels;
            s.passes[m] += r->passes;
            s.callbacks[m] += r->callbacks;
            tmp[n++] = r->ms;
            if (m == M_CACHED) {
                s.full += r->full;
                s.scrolled += r->scrolled;
                s.reused += r->reused;
                s.regions += r->regions;
                s.faces_reused += r->faces_reused;
                s.faces_rendered += r->faces_rendered;
                s.pages_rendered += r->pages_rendered;
                s.pages_reused += r->pages_reused;
                s.pages_evicted += r->pages_evicted;
            }
        }
        if (n > 0) {
            s.texels[m] /= n;
            s.passes[m] /= n;
            s.callbacks[m] /= n;
        }
        s.ms[m] = median_d(tmp, n);
        if (s.err_n[m]) s.err[m] /= s.err_n[m];
        if (m == M_CACHED) s.n = n;
    }
    if (s.differ_n) s.differ /= s.differ_n;
    return s;
}

static double ratio(double a, double b) { return b > 0.0 ? a / b : 0.0; }

static const char *mark(double r, double goal) { return r <= goal ? "ok" : "MISSED"; }

static void fmt_count(double v, char *buf, size_t n) {
    if (v >= 1e6) snprintf(buf, n, "%.2fM", v / 1e6);
    else if (v >= 1e3) snprintf(buf, n, "%.1fk", v / 1e3);
    else snprintf(buf, n, "%.0f", v);
}

static void write_summary(FILE *txt, int frames) {
    int t, wk;
    fprintf(txt, "  %-16s %-7s %-31s %-30s %-33s %-21s %-9s %s\n", "technique", "walk",
            "texels/frame cached/uncached", "passes/frame (callbacks)", "time/frame (median ms)", "error % cached/unc.",
            "differ %", "cached layers, frames 1..");
    for (t = 0; t < NTECH; t++)
        for (wk = 0; wk < NWALK; wk++) {
            summary s = summarise(t, wk, frames);
            char a[32], b[32], tx[128], ps[64], tm[96], er[64], df[32], ly[128];
            double rt = ratio(s.texels[M_CACHED], s.texels[M_UNCACHED]);
            double rp = ratio(s.passes[M_CACHED], s.passes[M_UNCACHED]);
            double rm = ratio(s.ms[M_CACHED], s.ms[M_UNCACHED]);
            double gt = wk == WALK_STATIC ? GOAL_STATIC_TEXELS : GOAL_MOVING;
            double gm = wk == WALK_STATIC ? GOAL_STATIC_TIME : GOAL_MOVING;
            if (s.n == 0) {
                fprintf(txt, "  %-16s %-7s (no frames rendered)\n", tech_name[t], walk_name[wk]);
                continue;
            }
            fmt_count(s.texels[M_CACHED], a, sizeof a);
            fmt_count(s.texels[M_UNCACHED], b, sizeof b);
            snprintf(tx, sizeof tx, "%s/%s = %.3fx %s", a, b, rt, mark(rt, gt));
            snprintf(ps, sizeof ps, "%.1f/%.1f = %.2fx (%.2fx)", s.passes[M_CACHED], s.passes[M_UNCACHED], rp,
                     ratio(s.callbacks[M_CACHED], s.callbacks[M_UNCACHED]));
            snprintf(tm, sizeof tm, "%.2f/%.2f = %.3fx %s", s.ms[M_CACHED], s.ms[M_UNCACHED], rm, mark(rm, gm));
            if (s.err_n[M_CACHED] && s.err_n[M_UNCACHED])
                snprintf(er, sizeof er, "%.2f/%.2f", s.err[M_CACHED], s.err[M_UNCACHED]);
            else
                snprintf(er, sizeof er, "-");
            if (s.differ_n) snprintf(df, sizeof df, "%.4f", s.differ);
            else snprintf(df, sizeof df, "-");
            if (t == T_POINT)
                snprintf(ly, sizeof ly, "faces reused %d of %d drawn", s.faces_reused, s.faces_rendered);
            else if (t == T_RMSM)
                snprintf(ly, sizeof ly, "pages drawn %d reused %d evicted %d, emptied by boxes %d", s.pages_rendered,
                         s.pages_reused, s.pages_evicted, s.regions);
            else
                snprintf(ly, sizeof ly, "full %d scrolled %d reused %d, regions %d", s.full, s.scrolled, s.reused,
                         s.regions);
            fprintf(txt, "  %-16s %-7s %-31s %-30s %-33s %-21s %-9s %s\n", tech_name[t], walk_name[wk], tx, ps, tm,
                    er, df, ly);
        }
}

/* the chart's data (one block per walk, technique and mode: frame ms), its
   variables, then gnuplot; 0 ok */
static int plot_scene(const char *out, const char *gp, const char *scene, const char *device, int frames, int wall) {
    char dat[1200], vars[1200], png[1200], cmd[3000];
    FILE *f;
    int wk, t, m, k;
    snprintf(dat, sizeof dat, "%.900s/bench-cache-data/%.100s.dat", out, scene);
    snprintf(vars, sizeof vars, "%.900s/bench-cache-data/%.100s.vars.gp", out, scene);
    snprintf(png, sizeof png, "%.900s/bench-cache-%.100s.png", out, scene);
    snprintf(cmd, sizeof cmd, "%.900s/bench-cache-data", out);
    mkdir_p(cmd);
    if (!(f = fopen(dat, "w"))) return -1;
    for (wk = 0; wk < NWALK; wk++)
        for (t = 0; t < NTECH; t++)
            for (m = 0; m < NMODE; m++) {
                fprintf(f, "# %s walk, %s %s: frame shadow_ms\n", walk_name[wk], tech_name[t], mode_name[m]);
                for (k = 0; k < frames; k++) {
                    const frame_rec *r = &g_rec[t][wk][m][k];
                    if (r->done) fprintf(f, "%d %.4f\n", k, r->ms > 1e-3 ? r->ms : 1e-3);   /* log axis */
                }
                fprintf(f, "\n\n");
            }
    fclose(f);
    if (!(f = fopen(vars, "w"))) return -1;
    fprintf(f, "# written by bench/bench_cache.c; draw with: gnuplot %s %s\nscene = ", vars, gp);
    gp_string(f, scene);
    fprintf(f, "\ndevice = ");
    gp_string(f, device);
    fprintf(f, "\ntiming = ");
    gp_string(f, wall ? "wall clock between glFinish calls, CPU rasteriser: compare within this chart only"
                      : "GPU ms, timer queries");
    fprintf(f, "\ndatafile = ");
    gp_string(f, dat);
    fprintf(f, "\noutfile = ");
    gp_string(f, png);
    fprintf(f, "\ntechniques = ");
    gp_string(f, "pssm4-stable standard-stable rmsm point-cube");
    fprintf(f, "\nntech = %d\nnmode = %d\nframes = %d\n", NTECH, NMODE, frames);
    fclose(f);
    snprintf(cmd, sizeof cmd, "gnuplot '%s' '%s'", vars, gp);
    if (system(cmd) != 0) {
        fprintf(stderr, "bench-cache: gnuplot failed: %s\n", cmd);
        return -1;
    }
    fprintf(stderr, "bench-cache: chart %s\n", png);
    return 0;
}

static void write_rows(FILE *csv, const char *scene, int frames, const char *device) {
    int t, wk, m, f;
    for (t = 0; t < NTECH; t++)
        for (wk = 0; wk < NWALK; wk++)
            for (m = 0; m < NMODE; m++)
                for (f = 0; f < frames; f++) {
                    const frame_rec *r = &g_rec[t][wk][m][f];
                    if (!r->done) continue;
                    csv_field(csv, scene);
                    fprintf(csv, ",%s,%s,%s,%d,%.0f,%d,%d,%.4f,", tech_name[t], walk_name[wk], mode_name[m], f,
                            r->texels, r->passes, r->callbacks, r->ms);
                    if (r->err_ok) fprintf(csv, "%.4f", r->err);
                    fputc(',', csv);
                    if (m == M_CACHED && r->differ_ok) fprintf(csv, "%.5f", r->differ);
                    if (t == T_POINT)
                        fprintf(csv, ",,,,%d,%.0f,%.0f,,%d,%d,%d,,,,", r->regions, r->copied, r->bytes,
                                r->faces_reused, r->faces_rendered, r->faces_culled);
                    else if (t == T_RMSM)
                        fprintf(csv, ",%d,%d,%d,%d,%.0f,%.0f,%d,,,,%d,%d,%d,", r->full, r->scrolled, r->reused,
                                r->regions, r->copied, r->bytes, r->layers, r->pages_rendered, r->pages_reused,
                                r->pages_evicted);
                    else
                        fprintf(csv, ",%d,%d,%d,%d,%.0f,%.0f,%d,,,,,,,", r->full, r->scrolled, r->reused, r->regions,
                                r->copied, r->bytes, r->layers);
                    csv_field(csv, device);
                    fputc('\n', csv);
                }
}

/* ------------------------------------------------------------- a scene */
typedef struct opts {
    int quick, frames, every;
    bench_paths p;             /* --scenes, --out, --only, --gp */
} opts;

/* both walks of one scene; rows to csv, the table to txt; 0 ok */
static int run_scene(bench *B, const opts *o, const bench_scene_def *def, FILE *csv, FILE *txt) {
    const sk_vec3 light_dir = v3_norm(v3(-0.45f, -1.0f, -0.35f));
    const int frames = o->frames;
    tb_scene s, ms;
    tb_gl_mesh mesh, mover_mesh;
    tb_reference *ref = NULL;
    walk_path wp;
    world w;
    lights L;
    int wk, f, t, k, status = 0, mover_v0 = -1, scored = 0;
    unsigned nobj;
    float *base = NULL;
    double ts = now_s(), t_ref = 0.0, lit_dir = 0.0, lit_point = 0.0;
    memset(&mesh, 0, sizeof mesh);
    memset(&mover_mesh, 0, sizeof mover_mesh);
    memset(&L, 0, sizeof L);
    tb_scene_init(&ms);
    if (load_scene(def, &s) != 0 || tb_gl_mesh_create(&B->g.gl, &mesh, &s) != 0 || !(ref = tb_reference_create(&s))) {
        fprintf(stderr, "bench-cache: scene %s %s: load, upload or reference failed: skipped\n", def->name, def->path);
        status = 1;
        goto out;
    }
    nobj = s.object_count;
    make_walk(&s, frames, &wp);
    /* the mover, its base at the origin: moved by the model matrix */
    {
        float h = 0.5f * wp.mover_size;
        if (tb_scene_add_box(&ms, "mover", v3(-h, 0, -h), v3(h, wp.mover_size, h)) < 0 ||
            tb_gl_mesh_create(&B->g.gl, &mover_mesh, &ms) != 0) {
            fprintf(stderr, "bench-cache: %s: the mover failed\n", def->name);
            status = 1;
            goto out;
        }
    }
    memset(&w, 0, sizeof w);
    w.gl = &B->g.gl;
    w.sk = B->g.sk;
    w.s = &s;
    w.nstatic = nobj;
    w.mesh = &mesh;
    w.mover_mesh = &mover_mesh;
    fprintf(stderr, "bench-cache: scene %s: %u triangles, %u objects; walk of %d frames from the overview (d %.3g, "
                    "step %.3g sideways, %.3g forward); mover %.3g; point light (%.3g %.3g %.3g) range %.3g\n",
            def->name, tb_scene_triangle_count(&s), nobj, frames, (double)wp.d, (double)(STEP_SIDE * wp.d),
            (double)(STEP_FWD * wp.d), (double)wp.mover_size, (double)wp.point_pos.x, (double)wp.point_pos.y,
            (double)wp.point_pos.z, (double)wp.point_range);
    memset(g_rec, 0, sizeof g_rec);
    for (wk = 0; wk < NWALK; wk++) {
        skgl_scene sc;
        memset(&sc, 0, sizeof sc);
        sc.draw = draw_static;
        sc.user = &w;
        sc.bounds = wp.bounds;
        if (wk == WALK_MOVING) {
            /* the reference's scene gets the mover (after the static
               objects, which draw_static alone draws), moved per scored frame */
            int v0 = (int)s.vertex_count, id;
            float h = 0.5f * wp.mover_size;
            tb_reference_destroy(ref);
            ref = NULL;
            id = tb_scene_add_box(&s, "mover", v3(-h, 0, -h), v3(h, wp.mover_size, h));
            base = (float *)malloc(sizeof(float) * 3 * (s.vertex_count - (uint32_t)v0));
            if (id < 0 || !base) { status = 1; break; }
            memcpy(base, s.positions + 3 * v0, sizeof(float) * 3 * (s.vertex_count - (uint32_t)v0));
            mover_v0 = v0;
        }
        skgl_set_dynamic(B->g.sk, NULL);   /* the static walk: none; the moving one sets it each frame */
        if (make_lights(B, &L, wp.point_range) != 0) { status = 1; break; }
        for (f = 0; f < frames; f++) {
            skgl_camera cam;
            sk_mat4 vp;
            int score_now = f % o->every == 0;
            camera_at(&wp, f, &cam, &vp);
            if (wk == WALK_MOVING) {
                skgl_dynamic dyn;
                memset(&dyn, 0, sizeof dyn);
                w.mover_at = mover_at(&wp, f, frames);
                dyn.draw = draw_dynamic;
                dyn.user = &w;
                dyn.bounds = mover_box(&wp, w.mover_at);
                if (skgl_set_dynamic(B->g.sk, &dyn) != SK_OK) {
                    fprintf(stderr, "bench-cache: skgl_set_dynamic: %s\n", skgl_error_log(B->g.sk));
                    status = 1;
                }
            }
            /* RMSM's analysis reads this frame's depth: the static scene's G-buffer */
            if (tb_gl_gbuffer_render(&B->g.gl, &B->g.gb, &mesh, &B->gbuf, &vp) != 0) status = 1;
            for (t = 0; t < NTECH; t++)
                for (k = 0; k < NMODE; k++) {
                    int m = f & 1 ? NMODE - 1 - k : k;   /* who goes first alternates */
                    if (render_one(B, &L, t, m, &cam, &sc, light_dir, wp.point_pos, &w, &g_rec[t][wk][m][f]) != 0)
                        status = 1;
                }
            if (!score_now) continue;
            /* the scored frame: G-buffer and references of the scene as it is, masks, scores */
            {
                double t0 = now_s();
                tb_gl_mesh now_mesh;
                const tb_gl_mesh *gm = &mesh;
                int ok = 1;
                memset(&now_mesh, 0, sizeof now_mesh);
                if (wk == WALK_MOVING) {
                    uint32_t i, nv = s.vertex_count - (uint32_t)mover_v0;
                    for (i = 0; i < nv; i++) {
                        s.positions[3 * (mover_v0 + (int)i) + 0] = base[3 * i + 0] + w.mover_at.x;
                        s.positions[3 * (mover_v0 + (int)i) + 1] = base[3 * i + 1] + w.mover_at.y;
                        s.positions[3 * (mover_v0 + (int)i) + 2] = base[3 * i + 2] + w.mover_at.z;
                    }
                    tb_reference_destroy(ref);
                    ref = tb_reference_create(&s);
                    ok = ref != NULL && tb_gl_mesh_create(&B->g.gl, &now_mesh, &s) == 0;
                    gm = &now_mesh;
                }
                if (!ok || prepare_frame(B, gm, ref, &vp, light_dir, &wp) != 0) {
                    fprintf(stderr, "bench-cache: %s %s walk frame %d: G-buffer / reference failed\n", def->name,
                            walk_name[wk], f);
                    status = 1;
                } else {
                    if (wk == WALK_STATIC && f == 0) {
                        lit_dir = lit_share(B->ref_dir);
                        lit_point = lit_share(B->ref_point);
                    }
                    for (t = 0; t < NTECH; t++) {
                        if (mask_of(B, &L, t, M_CACHED, &cam) != 0 || mask_of(B, &L, t, M_UNCACHED, &cam) != 0) {
                            status = 1;
                            continue;
                        }
                        score(B, t, &g_rec[t][wk][M_CACHED][f], &g_rec[t][wk][M_UNCACHED][f]);
                    }
                }
                if (now_mesh.vao) tb_gl_mesh_destroy(&B->g.gl, &now_mesh);
                t_ref += now_s() - t0;
                scored++;
            }
        }
        fprintf(stderr, "bench-cache: %s %s walk done (%.1f s so far)\n", def->name, walk_name[wk], now_s() - ts);
        if (wk == WALK_STATIC && L.dir[T_PSSM][M_CACHED])
            fprintf(txt, "  cache memory: pssm4-stable %.1f MiB (%d layers), standard-stable %.1f MiB, rmsm %.1f MiB "
                         "(the static copy of its %dx%d pool, made when dynamic casters come: none on this walk; "
                         "the pages are the pool's own), point-cube %.1f MiB\n",
                    skgl_shadow_stats(L.dir[T_PSSM][M_CACHED])->cache_bytes / 1048576.0,
                    skgl_shadow_stats(L.dir[T_PSSM][M_CACHED])->cache_layers,
                    skgl_shadow_stats(L.dir[T_STANDARD][M_CACHED])->cache_bytes / 1048576.0,
                    skgl_shadow_stats(L.dir[T_RMSM][M_CACHED])->cache_bytes / 1048576.0,
                    skgl_shadow_stats(L.dir[T_RMSM][M_CACHED])->map_width,
                    skgl_shadow_stats(L.dir[T_RMSM][M_CACHED])->map_height,
                    skgl_point_stats(L.point[M_CACHED])->cache_bytes / 1048576.0);
        if (wk == WALK_MOVING && L.dir[T_RMSM][M_CACHED])
            fprintf(txt, "  cache memory, moving walk: rmsm %.1f MiB (the static copy of the pool)\n",
                    skgl_shadow_stats(L.dir[T_RMSM][M_CACHED])->cache_bytes / 1048576.0);
        free_lights(B, &L);
    }
    fprintf(txt, "  reference at frame 0: %.1f%% of the covered pixels lit by the sun, %.1f%% by the point light\n",
            lit_dir, lit_point);
    write_summary(txt, frames);
    fprintf(txt, "  (%s: %.1f s, of which %.1f s for %d scored frames: G-buffers, references, masks)\n\n", def->name,
            now_s() - ts, t_ref, scored);
    fflush(txt);
    write_rows(csv, def->name, frames, B->g.renderer);
    fflush(csv);
    if (plot_scene(o->p.out_dir, o->p.gp, def->name, B->g.renderer, frames, B->wall) != 0) status = 1;
out:
    skgl_set_dynamic(B->g.sk, NULL);   /* the mover's callback points into this frame of the stack */
    free(base);
    free_lights(B, &L);
    tb_reference_destroy(ref);
    if (mesh.vao) tb_gl_mesh_destroy(&B->g.gl, &mesh);
    if (mover_mesh.vao) tb_gl_mesh_destroy(&B->g.gl, &mover_mesh);
    tb_scene_free(&ms);
    tb_scene_free(&s);
    return status;
}

static void usage(FILE *f, const char *argv0) {
    fprintf(f,
            "usage: %s [--quick] [--frames N] [--error-every K] [--scenes DIR] [--out DIR]\n"
            "          [--only SCENE[,SCENE..]] [--gp FILE]\n"
            "  --quick          procedural scenes only, 20 frames (make demo)\n"
            "  --frames N       frames of each walk (default 60, at most %d)\n"
            "  --error-every K  score every K-th frame against the reference (default 6)\n"
            "  --scenes DIR     the shared scenes (default ../shared/scenes)\n"
            "  --out DIR        output folder (default out)\n"
            "  --only LIST      only these scenes (comma separated names)\n"
            "  --gp FILE        the gnuplot script (default bench/cache.gp)\n"
            "Environment: SK_GL=osmesa|egl picks the GL backend.\n",
            argv0, MAX_FRAMES);
}

int main(int argc, char **argv) {
    opts o;
    bench_scene_def defs[16];
    bench B;
    FILE *csv = NULL, *txt = NULL;
    char path[1200];
    int ndefs = 0, i, t, m, status = 0, shared, frames_given = 0;
    double t_start = now_s();

    memset(&o, 0, sizeof o);
    bench_paths_init(&o.p, "bench/cache.gp");
    o.frames = 60;
    o.every = 6;
    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        int more = i + 1 < argc;
        if (strcmp(a, "--quick") == 0) o.quick = 1;
        else if (strcmp(a, "--frames") == 0 && more) { o.frames = atoi(argv[++i]); frames_given = 1; }
        else if (strcmp(a, "--error-every") == 0 && more) o.every = atoi(argv[++i]);
        else if (bench_path_option(&o.p, argc, argv, &i)) continue;
        else if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) { usage(stdout, argv[0]); return 0; }
        else { fprintf(stderr, "bench-cache: unknown or incomplete option %s\n", a); usage(stderr, argv[0]); return 2; }
    }
    if (o.quick && !frames_given) o.frames = 20;
    if (o.frames < 2 || o.frames > MAX_FRAMES || o.every < 1) {
        fprintf(stderr, "bench-cache: --frames takes 2..%d, --error-every 1 or more\n", MAX_FRAMES);
        return 2;
    }
    /* the quick run: the procedural scenes only */
    ndefs = bench_scenes("bench-cache", BENCH_IN_CACHE, o.quick ? NULL : o.p.scenes_dir, o.p.only, defs,
                         (int)(sizeof defs / sizeof defs[0]), &shared);
    if (ndefs == 0) { fprintf(stderr, "bench-cache: no scene selected (--only %s)\n", o.p.only ? o.p.only : ""); return 2; }
    if (!gnuplot_ready("bench-cache", o.p.gp)) return 1;

    /* ---- GL: no timer queries where the wall clock times */
    memset(&B, 0, sizeof B);
    if (bench_gl_open(&B.g, "bench-cache", BENCH_TIMING_GPU_ONLY) != 0) return 1;
    B.wall = software_renderer(B.g.renderer);
    fprintf(stderr, "bench-cache: shadow time: %s\n",
            B.wall ? "wall clock between glFinish calls (CPU rasteriser: compare within this run only)"
                   : "GL timer queries");
    if (tb_gl_fbo_create(&B.g.gl, &B.gbuf, CW, CH, TB_GL_COLOR_RGBA16F) != 0) {
        fprintf(stderr, "bench-cache: G-buffer target failed\n");
        status = 1;
        goto done;
    }
    B.depth = (float *)malloc(sizeof(float) * CW * CH);
    B.ref_dir = (float *)malloc(sizeof(float) * CW * CH);
    B.ref_point = (float *)malloc(sizeof(float) * CW * CH);
    B.rgba = (float *)malloc(sizeof(float) * 4 * CW * CH);
    B.nrm = (float *)malloc(sizeof(float) * 3 * CW * CH);
    for (t = 0; t < NTECH; t++)
        for (m = 0; m < NMODE; m++) {
            B.mask_px[t][m] = (float *)malloc(sizeof(float) * CW * CH);
            if (!B.mask_px[t][m]) status = 1;
        }
    if (status || !B.depth || !B.ref_dir || !B.ref_point || !B.rgba || !B.nrm) {
        fprintf(stderr, "bench-cache: out of memory\n");
        status = 1;
        goto done;
    }

    mkdir_p(o.p.out_dir);
    snprintf(path, sizeof path, "%.900s/bench-cache.csv", o.p.out_dir);
    csv = fopen(path, "w");
    snprintf(path, sizeof path, "%.900s/bench-cache.txt", o.p.out_dir);
    txt = fopen(path, "w");
    if (!csv || !txt) {
        fprintf(stderr, "bench-cache: cannot write under %s: %s\n", o.p.out_dir, strerror(errno));
        status = 1;
        goto done;
    }
    fprintf(csv, "%s\n", CSV_HEADER);
    fprintf(txt, "# shadowkit bench-cache: cached maps (desc.cache = 1) against the same desc uncached (0)\n"
                 "# device %s; shadow time: %s\n"
                 "# %s run: %d frames a walk, %s; error every %d-th frame from frame 0, %dx%d, against the exact "
                 "reference\n"
                 "# walks: static (the camera walks) and moving (plus a box caster from skgl_set_dynamic, with "
                 "its bounds)\n"
                 "# ratios cached/uncached over frames 1..%d: mean texels and passes a frame, median shadow time;\n"
                 "# goals: static walk texels <= %.1fx, time <= %.1fx; moving walk texels and time <= %.1fx\n"
                 "# error: mean shadow-area error (%% of the reference's shadow misclassified); differ: %% of the "
                 "covered pixels whose class the cached mask has otherwise than the uncached one\n"
                 "# passes: the stats' passes; (callbacks): the ratio of the draw callbacks the scene received, "
                 "scene.draw and the dynamic callback counted apart\n"
                 "# directional maps 2048^2 (PSSM: a cascade), RMSM 8192^2 virtual (128-texel pages, a 24x24 "
                 "pool; its analysis untimed), point light 512^2 a face\n\n",
            B.g.renderer,
            B.wall ? "CPU wall clock of each render between glFinish calls (CPU rasteriser: relative, this run only)"
                   : "GL timer queries (GPU ms)",
            o.quick ? "quick" : "full", o.frames, shared ? "shared and procedural scenes" : "procedural scenes only",
            o.every, CW, CH, o.frames - 1, GOAL_STATIC_TEXELS, GOAL_STATIC_TIME, GOAL_MOVING);
    for (i = 0; i < ndefs; i++) {
        fprintf(txt, "scene %s\n", defs[i].name);
        if (run_scene(&B, &o, &defs[i], csv, txt) != 0) status = 1;
    }
    {
        double el = now_s() - t_start;
        fprintf(txt, "total run time %dm%02ds\n", (int)(el / 60), (int)el % 60);
        fprintf(stderr, "bench-cache: done in %dm%02ds: %s/bench-cache.{csv,txt}, %s/bench-cache-<scene>.png\n",
                (int)(el / 60), (int)el % 60, o.p.out_dir, o.p.out_dir);
    }

done:
    if (csv) fclose(csv);
    if (txt) fclose(txt);
    free(B.depth);
    free(B.ref_dir);
    free(B.ref_point);
    free(B.rgba);
    free(B.nrm);
    for (t = 0; t < NTECH; t++)
        for (m = 0; m < NMODE; m++) free(B.mask_px[t][m]);
    if (B.gbuf.fbo) tb_gl_fbo_destroy(&B.g.gl, &B.gbuf);
    bench_gl_close(&B.g);
    return status;
}
