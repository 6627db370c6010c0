/* tb_metrics.h - error metrics of a shadow result against the reference.

   Conventions (tb_reference.h): visibility per pixel, 1 lit, 0 shadowed,
   values in between for soft shadows; a NEGATIVE reference value means the
   pixel has no receiver (background, out of light range) and is not
   "covered": every metric ignores it. A pixel's class is lit when
   visibility >= 0.5 (TB_LIT_THRESHOLD), else shadowed. A result value that
   is NaN or infinite on a covered pixel always counts as wrong (`invalid`).
   Percentages are in [0,100]; 0 covered pixels give 0. */
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
    uint64_t count;           /* values that were finite and >= 0 */
} tb_footprint_stats;

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
/* quantile p in [0,1] of an ascending sorted array, as defined above */
double tb_quantile_sorted(const float *sorted, size_t n, double p);

#ifdef __cplusplus
}
#endif
#endif /* TB_METRICS_H */
