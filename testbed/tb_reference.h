/* tb_reference.h - the exact shadow reference: Embree 3 shadow rays.

   For each camera pixel, the world position is reconstructed from the same
   GL window-depth buffer the renderer used (so renderer and reference see
   the same positions), then shadow rays are traced against the same
   triangles (a tb_scene) with rtcOccluded1 / rtcOccluded16:

     pixel (x, y), row 0 at the bottom, depth d in [0,1] (glDepthRange 0..1):
       ndc   = (2 (x + 0.5) / width - 1,  2 (y + 0.5) / height - 1,  2 d - 1, 1)
       world = inv_view_proj * ndc, then divided by its w      (in double)
     d >= 1 (cleared depth) is background: visibility TB_VIS_BACKGROUND.

   Offset (documented epsilon): eps = eps_rel * scene diagonal, eps_rel =
   TB_REF_EPS_REL (1e-4) unless options say otherwise. The ray origin is
   moved eps along the unit normal when a normal buffer is given, and the
   ray starts at distance eps along itself (tnear). Toward a point or area
   light sample the ray stops eps short of the light.
   With normals, a surface facing away from the light (dot(n, to_light) <= 0)
   counts as shadowed (per sample for area lights), unless ignore_facing.

   Lights:
   - directional: `direction` is the direction the light TRAVELS (light ->
     scene), as in shadowkit.h's sk_light_view_directional(); rays go to -dir.
   - point: `position`; pixels farther than `range` (> 0) from it are
     TB_VIS_OUT_OF_RANGE; range <= 0 means unlimited.
   - rect (area): the parallelogram centre + a*half_u + b*half_v, a,b in
     [-1,1], sampled on strata x strata cells (strata >= 16, so >= 256
     samples), one sample jittered uniformly inside each cell; the jitter
     comes from a fixed-seed PRNG (PCG32) seeded by (seed, pixel index), so
     results do not depend on thread count. Visibility = fraction of samples
     unoccluded, in [0,1] (unweighted: no cosine or distance terms).

   Output per pixel: 1 lit, 0 shadowed (hard), [0,1] (area), negative for
   pixels without a visible receiver (TB_VIS_BACKGROUND, TB_VIS_OUT_OF_RANGE);
   tb_metrics ignores negative reference pixels.

   Threads: rows are interleaved over `threads` pthreads (0: all online CPUs).
   Depends on: shadowkit.h (types only), tb_scene.h, Embree 3, pthreads. */
#ifndef TB_REFERENCE_H
#define TB_REFERENCE_H

#include <stdint.h>
#include "shadowkit.h"
#include "tb_scene.h"

#ifdef __cplusplus
extern "C" {
#endif

#define TB_REF_EPS_REL 1e-4
#define TB_REF_MIN_STRATA 16
#define TB_VIS_BACKGROUND (-1.0f)
#define TB_VIS_OUT_OF_RANGE (-2.0f)

typedef enum tb_light_type {
    TB_LIGHT_DIRECTIONAL = 0,
    TB_LIGHT_POINT = 1,
    TB_LIGHT_RECT = 2
} tb_light_type;

typedef struct tb_light {
    tb_light_type type;
    sk_vec3 direction;        /* DIRECTIONAL: travel direction (any length > 0) */
    sk_vec3 position;         /* POINT: position; RECT: centre */
    float range;              /* POINT: <= 0 unlimited */
    sk_vec3 half_u, half_v;   /* RECT: half-axes */
    int strata;               /* RECT: per axis; values < 16 mean 16 */
    uint32_t seed;            /* RECT: jitter seed */
} tb_light;

typedef struct tb_view {
    sk_mat4 inv_view_proj;    /* clip -> world, column-major m[col*4+row] */
    int width, height;
} tb_view;

typedef struct tb_ref_options {   /* all-zero = defaults */
    double eps_rel;               /* <= 0: TB_REF_EPS_REL */
    int threads;                  /* <= 0: online CPUs (at most 64) */
    int ignore_facing;            /* 1: no back-facing test with normals */
} tb_ref_options;

typedef struct tb_reference tb_reference;

/* Builds the Embree scene (robust flag, high build quality) from the
   scene's triangles; the scene may be freed afterwards. NULL on failure. */
tb_reference *tb_reference_create(const tb_scene *scene);
void tb_reference_destroy(tb_reference *ref);
/* eps_rel * scene diagonal (opt may be NULL) */
double tb_reference_epsilon(const tb_reference *ref, const tb_ref_options *opt);

/* Inverse of a column-major 4x4 in double (Gauss-Jordan, partial
   pivoting), e.g. of the float view-projection a G-buffer was drawn with;
   1 ok, 0 if singular. */
int tb_mat4_inverse_d(const double m[16], double inv[16]);

/* World position of pixel (x, y) at window depth d (see the formula above);
   0 ok, -1 if w is 0 or not finite. */
int tb_unproject_pixel(const sk_mat4 *inv_view_proj, int width, int height, int x, int y,
                       float depth, double out[3]);

/* Per-pixel visibility from a window-depth buffer (width*height floats, row
   0 at the bottom) and optional world-space normals (3 floats per pixel, any
   length; a zero normal = none; NULL = no normals). vis: width*height floats.
   0 ok, -1 bad arguments or out of memory. */
int tb_reference_trace(const tb_reference *ref, const tb_view *view, const float *depth,
                       const float *normals, const tb_light *light,
                       const tb_ref_options *opt, float *vis);

/* The same for arbitrary world points (3 doubles each) and optional normals
   (3 doubles each, NULL = none); the jitter seed uses the point index. */
int tb_reference_trace_points(const tb_reference *ref, const double *points, const double *normals,
                              int count, const tb_light *light, const tb_ref_options *opt,
                              float *vis);

/* Geometric normals for a depth buffer, when the renderer has none: for each
   covered pixel a primary ray from the camera through the pixel centre
   (near-plane to far-plane point of the unprojected pixel) is intersected
   with the scene; if it hits within 1% of the scene diagonal of the
   reconstructed position, normals get the unit geometric normal of the
   triangle hit, turned to face the camera; else (0,0,0). Positions are not
   changed: pass the result to tb_reference_trace as `normals`.
   normals: 3*width*height floats. 0 ok, -1 on bad arguments. */
int tb_reference_normals(const tb_reference *ref, const tb_view *view, const float *depth,
                         const tb_ref_options *opt, float *normals);

#ifdef __cplusplus
}
#endif
#endif /* TB_REFERENCE_H */
