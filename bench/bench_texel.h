/* bench/bench_texel.h - the texel-to-pixel figure of a rendered light
   (Ferko 2013's measure, tb_texel_footprint): for every shaded pixel, how
   many pixels one texel of the map that pixel samples spans, the map
   picked as skgl_shadow_mask picks it (shaders_embedded/shadow_sample.glsl):
     standard, PSM, LiSPSM, FERKO   layer 0 (warped maps: the warped
                                    matrix; FERKO: its rendered extent)
     PSSM, LiSPSM per cascade       the layer of the pixel's view depth
                                    against the split depths (inside a
                                    blend band, the nearer of the two
                                    layers the mask mixes)
     LSPSM                          the first partition whose rect (less its
                                    margin, skgl_shadow_select_extent) holds
                                    the point
     RMSM                           the page level of the pixel's level of
                                    detail (the smallest singular value of
                                    the footprint in level-0 texels, as
                                    rmsm_analyze.frag takes it), or the
                                    nearest coarser level resident
                                    (skgl_shadow_pages)
   Pixels the mask does not look up in a map (outside the map or the split
   range: lit by default) are not shaded pixels and are left out. */
#ifndef BENCH_TEXEL_H
#define BENCH_TEXEL_H

#include "shadowkit_gl.h"
#include "tb_metrics.h"

/* a view's receivers: world position (3 doubles a pixel, NaN for the
   background) and view depth, from the window depth the G-buffer drew
   with view_proj (reconstructed as the mask does: pixel centre, inverse
   view-projection, w-divide, in double) */
typedef struct bench_receivers {
    int w, h;
    double *world;
    float *view_depth;
} bench_receivers;

int bench_receivers_init(bench_receivers *r, int w, int h, const sk_mat4 *view_proj, const sk_mat4 *view,
                         const float *depth);
void bench_receivers_free(bench_receivers *r);

/* scratch of bench_texel_stats, for w x h frames */
typedef struct bench_texel_scratch {
    double *texel;
    int *key;
    float *footprint, *deriv;
    unsigned char *resident;
    size_t resident_cap;
} bench_texel_scratch;

int bench_texel_scratch_init(bench_texel_scratch *t, int w, int h);
void bench_texel_scratch_free(bench_texel_scratch *t);

/* The footprint statistics (tb_metric_footprint: median, shares above 1,
   2 and 4 pixels) of light s's last render over the pixels covered by
   the reference (ref >= 0) that sample a map. count 0 when none does or
   on failure. */
tb_footprint_stats bench_texel_stats(const skgl_shadow *s, const bench_receivers *rc, const float *ref,
                                     bench_texel_scratch *t);

#endif /* BENCH_TEXEL_H */
