/* gt_bands.h - shadow-area errors pooled over frames and by view-depth
   band (test_gl_open_world.c, test_gl_forest.c): the sums of wrong and of
   reference-shadow pixels (tb_metric_shadow's definition: misclassified
   pixels over the reference's shadowed ones; a frame with a large shadow
   weighs more), overall and in the bands 0-10, 10-50, 50-200 and 200+ m of
   view depth, so near-camera aliasing and far-field loss both show.
   Include after gl_test_util.h. All functions are static inline. */
#ifndef GT_BANDS_H
#define GT_BANDS_H

#include <stdio.h>

#define GT_BANDS 4

static const double gt_band_edge[GT_BANDS + 1] = {0, 10, 50, 200, 1e30};
static const char *const gt_band_name[GT_BANDS] = {"0-10", "10-50", "50-200", "200+"};

/* pooled counts: wrong and reference-shadow pixels, overall and per band */
typedef struct gt_band_pool {
    double wrong, shadow, false_light;
    double band_wrong[GT_BANDS], band_shadow[GT_BANDS];
    int frames;
} gt_band_pool;

static inline double gt_pool_pct(double wrong, double shadow) { return shadow > 0 ? 100.0 * wrong / shadow : 0.0; }

static inline int gt_band_of(double depth) {
    int b;
    for (b = 0; b < GT_BANDS; b++)
        if (depth < gt_band_edge[b + 1]) return b;
    return GT_BANDS - 1;
}

/* adds one frame: every pixel the reference counts (ref >= 0) of the last
   G-buffer; a result that is not a number counts as wrong */
static inline void gt_band_pool_add(gt_band_pool *p, const gt_env *e, const float *ref, const float *res) {
    size_t i;
    for (i = 0; i < e->n; i++) {
        int rc = tb_visibility_class(ref[i]), wrong, b;
        if (rc < 0) continue;
        b = gt_band_of(gt_view_depth(e, i));
        wrong = !(res[i] >= 0.0f) || tb_visibility_class(res[i]) != rc;
        if (rc == 0) {
            p->shadow += 1;
            p->band_shadow[b] += 1;
            if (wrong) p->false_light += 1;
        }
        if (wrong) {
            p->wrong += 1;
            p->band_wrong[b] += 1;
        }
    }
    p->frames++;
}

/* the pooled error % and band b's (b < 0: all bands) */
static inline double gt_band_pool_pct(const gt_band_pool *p, int b) {
    return b < 0 ? gt_pool_pct(p->wrong, p->shadow) : gt_pool_pct(p->band_wrong[b], p->band_shadow[b]);
}

/* "  <name>  12.34%  (false light  5.67%)  bands  0-10   1.23 ..." without
   the line's end */
static inline void gt_band_pool_print(const char *name, const gt_band_pool *p) {
    int b;
    printf("  %-20s %6.2f%%  (false light %6.2f%%)  bands", name, gt_pool_pct(p->wrong, p->shadow),
           gt_pool_pct(p->false_light, p->shadow));
    for (b = 0; b < GT_BANDS; b++) printf("  %s %6.2f", gt_band_name[b], gt_band_pool_pct(p, b));
}

#endif /* GT_BANDS_H */
