/* bench/bench_common.h - what the GL benches (bench/bench.c, the sweep;
   bench/bench_cache.c, the cached maps) share: the scene table, the
   views, the GL context, the exact reference of a view, timing and the
   CSV / gnuplot output helpers. bench_common.c implements it; both
   programs link shadowkit's implementation once (mk/bench.mk).

   Scenes: bench_scene_table lists every scene of the benches, one entry a
   scene (its file under --scenes DIR, or procedural; which views; which
   bench runs it); bench_scenes() picks the selected ones. */
#ifndef BENCH_COMMON_H
#define BENCH_COMMON_H

#include "shadowkit_gl.h"

#include "tb_gl_context.h"
#include "tb_gl_fbo.h"
#include "tb_gl_funcs.h"
#include "tb_gl_scene.h"
#include "tb_reference.h"
#include "tb_scene.h"

#include <stdio.h>

#define BENCH_W 1280                 /* the camera's image */
#define BENCH_H 720
#define BENCH_FOVY 0.872665f         /* 50 degrees */
#define BENCH_VIEWS 3                /* views a scene has (make_views, make_open_world_views) */

/* ------------------------------------------------------------------ utils */
double now_s(void);                  /* CLOCK_MONOTONIC, seconds */
void fmt_duration(double s, char *buf, size_t n);   /* "42s", "3m05s", "1h02m" */
sk_vec3 v3(float x, float y, float z);
sk_vec3 v3_add(sk_vec3 a, sk_vec3 b);
sk_vec3 v3_sub(sk_vec3 a, sk_vec3 b);
sk_vec3 v3_scale(sk_vec3 a, float s);
float v3_len(sk_vec3 a);
sk_vec3 v3_norm(sk_vec3 a);          /* a zero vector stays zero */
sk_aabb aabb_union(sk_aabb a, sk_aabb b);
float median(float *v, int n);       /* sorts v; -1 when n <= 0 */
double median_d(double *v, int n);   /* the same for doubles */
int file_exists(const char *path);
int dir_exists(const char *path);
int mkdir_p(const char *dir);        /* 0 ok */

/* 1 when the GL renderer rasterises on the CPU (Mesa's llvmpipe or
   softpipe): its times depend on the machine's cores and load, so they
   compare configurations within one run only. Any other renderer (a GPU,
   Mesa's hardware drivers included) gives absolute GPU times. */
int software_renderer(const char *renderer);
/* how every output of a run labels its times */
const char *timing_label(const char *renderer);

void csv_field(FILE *f, const char *s);   /* quoted when it holds a comma, quote or newline */
void gp_string(FILE *f, const char *s);   /* a gnuplot single-quoted string: ' doubled */
/* gnuplot on the PATH and the script gp readable; else a message on
   stderr prefixed by prog, and 0 */
int gnuplot_ready(const char *prog, const char *gp);

/* The options both benches take: --scenes DIR (default BENCH_SCENES_DIR),
   --out DIR (BENCH_OUT_DIR), --only LIST, --gp FILE. When argv[*i] is one
   of them and has its value: stores the value, steps *i past it, returns
   1; else 0. */
#define BENCH_SCENES_DIR "../shared/scenes"
#define BENCH_OUT_DIR "out"
typedef struct bench_paths {
    const char *scenes_dir, *out_dir, *only, *gp;
} bench_paths;
int bench_path_option(bench_paths *p, int argc, char **argv, int *i);
void bench_paths_init(bench_paths *p, const char *gp);   /* the defaults; only NULL */

/* 1 when name is in the comma-separated list only (NULL or "": every name) */
int scene_selected(const char *only, const char *name);

/* ---------------------------------------------------------------- scenes */
enum {
    BENCH_IN_SWEEP = 1,              /* bench.c's sweep runs it */
    BENCH_IN_CACHE = 2,              /* bench_cache.c's walks run it */
    BENCH_OPEN_WORLD = 4,            /* the open world's head-height views and sun */
    BENCH_FOREST = 8                 /* the forest's trail views and sun; trees instanced and
                                        alpha-tested (bench_forest) */
};
typedef struct bench_scene_entry {
    const char *name;
    const char *file;                /* under the shared scenes folder; NULL: tb_scene_build(name) */
    unsigned flags;
} bench_scene_entry;
extern const bench_scene_entry bench_scene_table[];
extern const int bench_scene_count;

typedef struct bench_scene_def {
    char name[64];
    char path[1024];                 /* "" for procedural */
    sk_vec3 light_dir;               /* the directional light's travel direction */
    unsigned flags;
} bench_scene_def;

/* The table's scenes with flag `in` selected by `only`, in table order,
   into defs (at most cap): the shared ones when the folder scenes_dir
   exists (*shared = 1; a missing file is said on stderr and skipped), else
   procedural scenes only (said on stderr unless scenes_dir is NULL: the
   procedural ones asked for). Returns the count. */
int bench_scenes(const char *prog, unsigned in, const char *scenes_dir, const char *only, bench_scene_def *defs,
                 int cap, int *shared);
/* load a scene: a model on a ground plane 3x its horizontal extent, or a
   procedural one; 0 ok (free s with tb_scene_free either way) */
int load_scene(const bench_scene_def *def, tb_scene *s);
/* the union of the bounds of the objects that are not the ground */
sk_aabb content_bounds(const tb_scene *s);

/* ----------------------------------------------------------------- views */
typedef struct bench_view {
    char name[16];
    sk_vec3 eye, target;
    float zn, zf;
    skgl_camera cam;
    sk_mat4 view_proj;
} bench_view;

/* near 0.002 x the eye-target distance, far past every corner of `all`:
   the camera, projection and view-projection from eye and target */
void finish_view(bench_view *v, const sk_aabb *all);
/* Three views from the content bounds (the objects but the ground):
   overview: the whole content from 35 degrees up, seen along its long
     horizontal axis (20 degrees off it), its bounding box framed;
   low: eye low beyond one end of the long axis, looking along it to a point
     a quarter of the way in, near the ground (grazing, perspective
     aliasing); the nearer half of the content box is framed;
   close: the middle of the content (a box as wide as the content is high or
     deep) from 50 degrees up, framed so that it overflows the image.
   Returns 3. */
int make_views(const tb_scene *s, bench_view *v);
/* The open world's first three head-height views (tb_open_world_view):
   near 0.5 m, far 1000 m, the regime cascades, warps and virtual maps are
   made for; its sun (the scene's light_dir) is 20 degrees up behind view
   0, across view 1 and nearly against view 2. */
void make_open_world_views(bench_view *v);
/* The forest's first three trail views (tb_forest_view): near 0.3 m, far
   TB_FOREST_FAR; its sun (the scene's light_dir) is 20 degrees up behind
   view 0 (tb_forest_sun(0, 2)). */
void make_forest_views(bench_view *v);
/* the views of a scene by its flags */
void scene_views(const bench_scene_def *def, const tb_scene *s, bench_view *v);

/* -------------------------------------------------------------------- GL */
typedef struct bench_gl {
    tb_gl_context *ctx;
    tb_gl_funcs gl;
    tb_gl_gbuffer gb;
    tb_gl_fbo mask;                  /* R16F, BENCH_W x BENCH_H */
    skgl_context *sk;
    const char *renderer;
} bench_gl;

/* the GL context (SK_GL picks the backend), the G-buffer program, the
   mask target and the shadowkit context with skgl_desc.timing = timing
   (BENCH_TIMING_GPU_ONLY: SKGL_TIMING_SYNC on a GPU, none on a CPU
   rasteriser, whose passes are timed by the wall clock); messages on
   stderr prefixed by prog. 0 ok; else B is closed. */
#define BENCH_TIMING_GPU_ONLY (-1)
int bench_gl_open(bench_gl *B, const char *prog, int timing);
void bench_gl_close(bench_gl *B);

/* The forest on the GPU as test_gl_forest.c draws it: the ground a plain
   mesh, the trees one mesh instanced TB_FOREST_TREES times, in the shadow
   passes through a caster program (skgl_caster_create: the instance
   transform in the vertex hook, the leaf atlas's alpha test in the
   fragment hook), in the camera's G-buffer through a program of the same
   hooks, so the camera sees what casts. */
#define BENCH_FOREST_ALPHA_UNIT 4    /* casters' samplers use units 4 and up (skgl_caster_desc) */
typedef struct bench_forest {
    tb_gl_mesh ground;
    tb_gl_instanced trees;
    tb_gl_gbuffer gb_trees;          /* the camera's pass of the trees, alpha-tested */
    skgl_caster *caster;
    int failed_calls;                /* skgl_use_caster returned NULL */
} bench_forest;
/* the GL objects, the leaf atlas bound on BENCH_FOREST_ALPHA_UNIT, and the
   reference's alpha test (tb_reference_set_alpha and its primary rays) for
   ref, built from s = tb_scene_build_forest's scene. 0 ok; else closed. */
int bench_forest_open(bench_gl *B, bench_forest *f, const tb_scene *s, tb_reference *ref);
void bench_forest_close(bench_gl *B, bench_forest *f);
/* an skgl_scene draw callback: user is a bench_forest_draw_user */
typedef struct bench_forest_draw_user {
    const tb_gl_funcs *gl;
    skgl_context *sk;
    bench_forest *f;
} bench_forest_draw_user;
void bench_forest_draw(void *user, const skgl_draw_info *info);
/* the camera's G-buffer of the forest into fbo; 0 ok */
int bench_forest_gbuffer(bench_gl *B, const bench_forest *f, const tb_gl_fbo *fbo, const sk_mat4 *view_proj);

/* The exact reference (tb_reference_trace_exact) of the view whose
   G-buffer was drawn with the float view_proj and has window depth
   `depth` (BENCH_W x BENCH_H): traced with the exact double inverse of
   that matrix. normals (3 a pixel, the G-buffer's; may be NULL) leave
   out the pixels whose rasterised face is not the traced one
   (tb_ref_options.raster_normals). 0 ok. */
int bench_trace(const tb_reference *ref, const sk_mat4 *view_proj, const float *depth, const float *normals,
                const tb_light *light, float *vis);

#endif /* BENCH_COMMON_H */
