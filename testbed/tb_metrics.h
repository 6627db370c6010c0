/* tb_metrics.h - error metrics of a shadow result against the reference.

   Conventions (tb_reference.h): visibility per pixel, 1 lit, 0 shadowed,
   values in between for soft shadows; a NEGATIVE reference value means the
   pixel has no receiver (background, out of light range) and is not
   "covered": every metric ignores it. A pixel's class is lit when
   visibility >= 0.5 (TB_LIT_THRESHOLD), else shadowed. A result value that
   is NaN or infinite on a covered pixel always counts as wrong (`invalid`).
   Percentages of covered pixels are in [0,100]; 0 covered pixels give 0
   (percentages of the reference's shadow can exceed 100: tb_shadow_error). */
#ifndef TB_METRICS_H
#define TB_METRICS_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define TB_LIT_THRESHOLD 0.5f

typedef struct tb_hard_error {
    double pct;               /* 100 * wrong / covered */
    uint64_t covered;         /* reference >= 0 */
    uint64_t wrong;           /* false_lit + false_shadow + invalid */
    uint64_t false_lit;       /* result lit, reference shadowed */
    uint64_t false_shadow;    /* result shadowed, reference lit */
    uint64_t invalid;         /* result not finite */
} tb_hard_error;

typedef struct tb_soft_error {
    double mae;               /* mean |result - reference| over covered pixels; an
                                 invalid result counts as error 1 */
    double max_abs;           /* largest |result - reference| */
    uint64_t covered;
    uint64_t invalid;
} tb_soft_error;

typedef struct tb_flip_rate {
    double pct;               /* 100 * flips / covered */
    uint64_t covered;         /* covered by the reference in both frames */
    uint64_t flips;           /* result class changes, reference class does not (a
                                 non-finite result in either frame counts as a flip) */
    uint64_t ref_flips;       /* reference class changes (not counted) */
} tb_flip_rate;

typedef struct tb_footprint_stats {
    double median, p95;       /* linear interpolation between order statistics:
                                 q(p) = x[floor(h)] + frac(h) (x[floor(h)+1] - x[floor(h)]),
                                 h = (count - 1) p, x sorted ascending */
    double min, max, mean;
    double over1_pct, over2_pct, over4_pct;  /* % of the counted values above 1, 2 and 4
                                 (texel footprints: a texel spanning more than that many pixels) */
    uint64_t count;           /* values that were finite and >= 0 */
} tb_footprint_stats;

/* Hard shadows measured against the reference's shadow instead of the whole
   frame (tb_metric_shadow). The reference classes are those of
   tb_visibility_class; a covered pixel is one whose reference value is
   finite and >= 0 (back-facing, silhouette, background and out-of-range
   pixels are negative: in no count and no denominator). A result that is
   NaN or infinite on a covered pixel is wrong (`invalid`) but neither false
   shadow nor false light. */
typedef struct tb_shadow_error {
    int ok;                   /* 1 computed; 0 bad input or out of memory (all else 0) */
    double area_pct;          /* shadow-area error: 100 * wrong / shadow; 0 when shadow == 0
                                 (read `shadow` to tell). Can exceed 100: false shadow
                                 in the lit part is not bounded by the shadow's area */
    double false_shadow_pct;  /* 100 * false_shadow / shadow (0 when shadow == 0) */
    double false_light_pct;   /* 100 * false_light / shadow (0 when shadow == 0) */
    double edge_mean_px;      /* mean edge displacement of the measured wrong pixels, px */
    double edge_p95_px;       /* its 95th percentile (tb_quantile_sorted's definition) */
    double covered_pct;       /* 100 * wrong / covered: tb_metric_hard()'s pct */
    uint64_t covered;         /* reference finite and >= 0 */
    uint64_t shadow;          /* covered, reference shadowed (< TB_LIT_THRESHOLD) */
    uint64_t lit;             /* covered, reference lit */
    uint64_t wrong;           /* false_shadow + false_light + invalid */
    uint64_t false_shadow;    /* result shadowed, reference lit */
    uint64_t false_light;     /* result lit, reference shadowed */
    uint64_t invalid;         /* result not finite */
    uint64_t edge_count;      /* wrong pixels with an edge distance: all of them unless the
                                 reference has covered pixels of one class only (no edge) */
} tb_shadow_error;

/* Soft shadows measured where soft methods differ (tb_metric_penumbra).
   Every covered pixel (reference finite and >= 0) is in exactly one region:
   penumbra = reference in (0,1), grown by grow_px (Euclidean, see below);
   umbra = reference 0 outside it; lit = reference >= 1 outside it. The
   error of a pixel is |result - reference|, 1 when the result is NaN or
   infinite. A region with no pixel has mean and max 0. */
typedef struct tb_penumbra_error {
    int ok;                   /* 1 computed; 0 bad input or out of memory (all else 0) */
    double penumbra_mae, penumbra_max;
    double umbra_mae, umbra_max;
    double lit_mae, lit_max;
    double covered_mae;       /* over every covered pixel: tb_metric_soft()'s mae */
    uint64_t covered;
    uint64_t penumbra_core;   /* covered with 0 < reference < 1 */
    uint64_t penumbra;        /* the grown penumbra (core included) */
    uint64_t umbra, lit;
    uint64_t invalid;         /* covered pixels whose result is not finite */
} tb_penumbra_error;

int tb_visibility_class(float v);   /* 1 lit, 0 shadowed, -1 not covered (v < 0) */

tb_hard_error tb_metric_hard(const float *ref, const float *result, size_t n);
tb_soft_error tb_metric_soft(const float *ref, const float *result, size_t n);
/* frame 0 and frame 1 of the reference and of the result (same camera path) */
tb_flip_rate tb_metric_flip(const float *ref0, const float *ref1, const float *res0,
                            const float *res1, size_t n);
/* footprint: per-pixel shadow-texel footprint in screen pixels; negative or
   non-finite values (background) are skipped. Sorts a copy (qsort).
   count 0 (all zero stats) when nothing qualifies or out of memory. */
tb_footprint_stats tb_metric_footprint(const float *footprint, size_t n);
/* Ferko's texel-to-pixel measure (Ferko 2013, Sec. 3.2: a pixel's patch,
   projected into the light's clip space, should span at least one texel
   along each axis). texel: 2 doubles per pixel of a w x h frame (row 0 at
   the bottom, index y * w + x): the texel coordinates of the map at which
   the pixel's centre samples it (texel j spanning [j, j+1)); key: per
   pixel, which map it samples (a layer, an RMSM page level, ...), < 0
   where it samples none. Per pixel and screen axis, the change of the
   texel coordinates to a neighbour on that axis that samples the same map
   (equal key): of the two neighbours the one with the shorter change (a
   neighbour across a depth discontinuity lands far off in the map, the
   other does not), one-sided at the frame's border. The patch's bounding
   rectangle in the map is then ex = |du/dx| + |du/dy| by
   ey = |dv/dx| + |dv/dy| texels, and one texel spans 1/ex pixels along
   the map's x and 1/ey along its y: footprint = the larger of the two, in
   pixels (FLT_MAX for a zero extent). Above 1, one texel covers several
   pixels: magnification, the staircase the view can see. footprint: w*h
   floats, -1 where key < 0 or a screen axis has no neighbour with the
   same key. deriv (may be NULL): 4 floats per pixel, (du/dx, dv/dx,
   du/dy, dv/dy), NaN where footprint is -1. A non-finite texel coordinate
   counts as key < 0. 0 ok; -1 NULL texel/key/footprint, w or h <= 0. */
int tb_texel_footprint(const double *texel, const int *key, int w, int h, float *footprint, float *deriv);

/* The shadow-area error (tb_metric_shadow's classes) split into bands, e.g.
   of view depth: band[i] is pixel i's band, in 0..nbands-1 (any other
   value: in no band). Per band b: shadow[b] = covered pixels whose
   reference is shadowed, wrong[b] = covered pixels misclassified (false
   shadow, false light or a non-finite result); the band's error is
   100 wrong / shadow, pooled over frames by adding the counts. 0 ok; -1
   NULL pointers or nbands <= 0. */
int tb_metric_shadow_bands(const float *ref, const float *res, const int *band, size_t n, int nbands,
                           uint64_t *shadow, uint64_t *wrong);

/* quantile p in [0,1] of an ascending sorted array, as defined above */
double tb_quantile_sorted(const float *sorted, size_t n, double p);

/* Hard-shadow error of one frame of w x h pixels, row-major, row 0 at the
   bottom (index y * w + x), against the reference's shadow.
   Edge displacement: for each wrong pixel, the distance from its centre to
   the nearest centre of a covered pixel whose reference class is the
   opposite of its own, minus 0.5 (the exact edge lies between the two
   centres), at least 0; in pixels, Euclidean, from an exact Euclidean
   distance transform (Felzenszwalb and Huttenlocher 2012), O(w h).
   A pixel one step on the wrong side of the edge is 0.5; one sitting
   k pixels into the other class is k - 0.5.
   NULL pointers, w <= 0 or h <= 0: a zeroed result (ok = 0). */
tb_shadow_error tb_metric_shadow(const float *ref, const float *res, int w, int h);

/* Soft-shadow error of one frame (layout as tb_metric_shadow). The
   penumbra's core (covered, 0 < reference < 1) grows by grow_px pixels
   into covered pixels: a covered pixel joins when the Euclidean distance
   between its centre and a core pixel's centre is <= grow_px (a disc, not
   a square: at grow_px = 2, offsets (2,0) and (1,1) join, (2,1) does not).
   Distances are in the image plane, across uncovered pixels too, which
   never join. grow_px = 0: the core alone.
   NULL pointers, w <= 0, h <= 0 or grow_px < 0: a zeroed result (ok = 0). */
tb_penumbra_error tb_metric_penumbra(const float *ref, const float *res, int w, int h, int grow_px);

#ifdef __cplusplus
}
#endif
#endif /* TB_METRICS_H */
