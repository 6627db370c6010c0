/* test_gl_texel_limit.c - the bench's texel-to-pixel figure (Ferko 2013's
   measure: testbed/tb_metrics.h tb_texel_footprint; bench/bench_texel.c,
   which picks the map each pixel samples as skgl_shadow_mask does) and the
   shadow-area error by band (tb_metric_shadow_bands).

   test_footprint_synthetic  affine texel maps with known footprints, a
                             jump across a depth edge, map boundaries
   test_bands                band counts on a small frame
   test_texel_methods        the open world (head-height view, 320x180):
                             a standard map's footprint halves when its
                             resolution doubles; PSSM's cascades and
                             LSPSM's partitions (skgl_shadow_select_extent)
                             give finer texels than one map of the same
                             size; RMSM's page levels, recomputed on the CPU,
                             match the GPU's analysis pixel by pixel, and
                             its texels hardly ever span more than a pixel */
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "sk_test.h"
#include "gl_test_util.h"

#include "bench/bench_texel.c"

#include <float.h>
#include <stdio.h>

#define W 320
#define H 180
#define SW 16   /* synthetic frames */
#define SH 12

/* texel coordinates u = a x + b y + c, v = d x + e y + f of pixel (x, y) */
static void affine(double *tex, int *key, double a, double b, double c, double d, double e, double f) {
    int x, y;
    for (y = 0; y < SH; y++)
        for (x = 0; x < SW; x++) {
            size_t i = (size_t)y * SW + x;
            tex[2 * i] = a * x + b * y + c;
            tex[2 * i + 1] = d * x + e * y + f;
            key[i] = 0;
        }
}

static void test_footprint_synthetic(void) {
    double tex[2 * SW * SH];
    int key[SW * SH], i, minus = 0;
    float fp[SW * SH], der[4 * SW * SH];
    tb_footprint_stats st;
    /* 0.2 texels a pixel across, 0.5 up: a texel spans 5 pixels along x */
    affine(tex, key, 0.2, 0.0, 3.0, 0.0, 0.5, 7.0);
    SK_CHECK(tb_texel_footprint(tex, key, SW, SH, fp, der) == 0);
    for (i = 0; i < SW * SH; i++) SK_CHECK_MSG(fabs(fp[i] - 5.0) < 1e-4, "pixel %d: %g", i, (double)fp[i]);
    SK_CHECK(fabs(der[0] - 0.2) < 1e-6 && der[1] == 0.0f && der[2] == 0.0f && fabs(der[3] - 0.5) < 1e-6);
    st = tb_metric_footprint(fp, SW * SH);
    SK_CHECK(st.count == SW * SH && st.over1_pct == 100.0 && st.over4_pct == 100.0);
    /* 2 texels a pixel: half a pixel */
    affine(tex, key, 2.0, 0.0, 0.0, 0.0, 2.0, 0.0);
    tb_texel_footprint(tex, key, SW, SH, fp, NULL);
    st = tb_metric_footprint(fp, SW * SH);
    SK_CHECK(fabs(st.median - 0.5) < 1e-6 && st.over1_pct == 0.0);
    /* a map at 45 degrees to the screen: the patch's bounding box (Ferko's
       measure) is 1 x 1 texels, though its narrow side is 0.71 texels */
    affine(tex, key, 0.5, -0.5, 0.0, 0.5, 0.5, 0.0);
    tb_texel_footprint(tex, key, SW, SH, fp, NULL);
    SK_CHECK_MSG(fabs(fp[5 * SW + 5] - 1.0) < 1e-5, "rotated: %g", (double)fp[5 * SW + 5]);
    /* a depth edge between columns 7 and 8: the far side lands 100 texels
       off; the pixels beside the edge take the change to their other
       neighbour, so every pixel reads 4 */
    affine(tex, key, 0.25, 0.0, 0.0, 0.0, 0.25, 0.0);
    for (i = 0; i < SW * SH; i++)
        if (i % SW >= 8) tex[2 * i] += 100.0;
    tb_texel_footprint(tex, key, SW, SH, fp, NULL);
    for (i = 0; i < SW * SH; i++) SK_CHECK_MSG(fabs(fp[i] - 4.0) < 1e-4, "edge pixel %d: %g", i, (double)fp[i]);
    /* another map (key) on column 8 alone: no neighbour along x samples
       the same map there (-1); keys < 0 and non-finite coordinates: -1,
       and so is pixel (3, 0), whose one neighbour along y is the
       non-finite (3, 1) */
    for (i = 0; i < SW * SH; i++) key[i] = i % SW == 8 ? 1 : 0;
    key[0] = -1;
    tex[2 * (SW + 3)] = NAN;
    tb_texel_footprint(tex, key, SW, SH, fp, NULL);
    for (i = 0; i < SW * SH; i++) minus += fp[i] < 0.0f;
    SK_CHECK_MSG(minus == SH + 3, "%d pixels without a footprint, expected %d", minus, SH + 3);
    SK_CHECK(fp[8] < 0.0f && fp[0] < 0.0f && fp[SW + 3] < 0.0f && fp[3] < 0.0f && fp[SW + 2] > 0.0f &&
             fp[2 * SW + 3] > 0.0f);
    /* a zero extent: FLT_MAX, counted above every threshold */
    affine(tex, key, 0.0, 0.0, 1.0, 0.0, 1.0, 1.0);
    tb_texel_footprint(tex, key, SW, SH, fp, NULL);
    SK_CHECK(fp[SW + 1] == FLT_MAX);
    SK_CHECK(tb_texel_footprint(NULL, key, SW, SH, fp, NULL) == -1);
    SK_CHECK(tb_texel_footprint(tex, key, 0, SH, fp, NULL) == -1);
}

static void test_bands(void) {
    /* reference: lit 1, shadow 0, not covered -1; result; band */
    const float ref[8] = {0, 0, 1, 0, 1, -1, 0, 0};
    const float res[8] = {0, 1, 0, 0, 1, 0, NAN, 1};
    const int band[8] = {0, 0, 0, 1, 1, 1, 2, 7};
    uint64_t sh[3], wr[3];
    SK_CHECK(tb_metric_shadow_bands(ref, res, band, 8, 3, sh, wr) == 0);
    /* band 0: shadow 2 (one false light), one false shadow; band 1: shadow 1,
       none wrong (pixel 5 not covered); band 2: the non-finite result */
    SK_CHECK_MSG(sh[0] == 2 && wr[0] == 2 && sh[1] == 1 && wr[1] == 0 && sh[2] == 1 && wr[2] == 1,
                 "bands: %llu/%llu %llu/%llu %llu/%llu", (unsigned long long)wr[0], (unsigned long long)sh[0],
                 (unsigned long long)wr[1], (unsigned long long)sh[1], (unsigned long long)wr[2],
                 (unsigned long long)sh[2]);
    SK_CHECK(tb_metric_shadow_bands(ref, res, NULL, 8, 3, sh, wr) == -1);
    SK_CHECK(tb_metric_shadow_bands(ref, res, band, 8, 0, sh, wr) == -1);
}

/* one light rendered and masked on the view; its texel figure */
static tb_footprint_stats method_stats(gt_env *e, skgl_shadow *s, const skgl_camera *cam, sk_vec3 light,
                                       const bench_receivers *rc, const float *ref, float *res,
                                       bench_texel_scratch *t) {
    tb_footprint_stats none;
    skgl_shadow_desc d = skgl_shadow_get_desc(s);
    skgl_scene sc = gt_scene(e);
    memset(&none, 0, sizeof none);
    if (d.technique == SKGL_RMSM && skgl_shadow_analyze(e->sk, s, cam, &sc, light, e->gbuf.depth_tex) != SK_OK)
        return none;
    if (gt_mask(e, s, cam, light, res) != 0) return none;
    return bench_texel_stats(s, rc, ref, t);
}

/* RMSM: the share of pixels whose page level (bench_texel's, in t->key)
   is the GPU analysis's level of detail (rmsm_analyze.frag, floored and
   clamped as the mask takes it), the share within one level, and among
   the pixels on a level coarser than the finest (their level of detail
   was not clamped), the share whose texel spans more than a pixel */
static void rmsm_levels_agree(gt_env *e, skgl_shadow *s, const bench_texel_scratch *t, double *same, double *near,
                              double *coarse_over1) {
    const skgl_shadow_frame_stats *st = skgl_shadow_stats(s);
    float *samp = (float *)malloc(sizeof(float) * 4 * e->n);
    size_t i, n = 0, eq = 0, close = 0, coarse = 0, over = 0;
    int u = st->rmsm_band > 0 ? -st->rmsm_band : st->rmsm_min_level;
    *same = *near = *coarse_over1 = 0.0;
    if (!samp || tb_gl_read_texture_rgba_float(&e->gl, skgl_shadow_analysis_texture(s), W, H, samp) != 0) {
        free(samp);
        return;
    }
    for (i = 0; i < e->n; i++) {
        int lv;
        if (t->key[i] < 0 || !(samp[4 * i + 3] > 0.5f)) continue;
        /* the shader's first level: the pixel's, b finer in request band b
           (its sk_rmsm_min_level u = -rmsm_band, else stats.rmsm_min_level),
           never below the finest rendered */
        lv = (int)floorf(samp[4 * i + 2]) - (u < 0 ? -u : 0);
        if (lv < (u > 0 ? u : 0)) lv = u > 0 ? u : 0;
        n++;
        eq += t->key[i] == lv;
        close += abs(t->key[i] - lv) <= 1;
        if (t->key[i] > (u > 0 ? u : 0) && t->footprint[i] >= 0.0f) {
            coarse++;
            over += t->footprint[i] > 1.0f;
        }
    }
    free(samp);
    if (n) {
        *same = 100.0 * (double)eq / (double)n;
        *near = 100.0 * (double)close / (double)n;
    }
    if (coarse) *coarse_over1 = 100.0 * (double)over / (double)coarse;
}

/* Measured (Mesa 22.3 llvmpipe, 320x180, open-world view 0, sun 2, 60
   degree view): shaded pixels whose texel spans over 1 / 2 / 4 px, median
   footprint:
     standard 1024  93.7% 89.3% 84.0%  23.9 px
     standard 2048  89.3% 84.0% 72.2%  11.9 px
     pssm 4x1024    66.0% 47.9% 21.8%  1.86 px
     lspsm 1024      3.9%  1.6%  0.0%  0.36 px
     rmsm 16384     62.5% 42.5% 15.3%  1.64 px (level 0 is too coarse
                                       near the eye: 16384 texels over the
                                       map's 1 km)
   RMSM's page level on the CPU (request band 7 of this frame, as the
   shader takes it) equals the GPU analysis's on 100.0% of the pixels
   (98.0%, within one level 99.7%, pixel-matched before the bands); above
   level 0 no texel spans more than a pixel (0.00%). Before the model knew
   the bands: 88.7% equal and 91.8% over a pixel above level 0. With the level one coarser on purpose: 83.1%,
   99.0% and 51.9%. */
static void test_texel_methods(void) {
    static const struct { skgl_technique t; int res, cascades; } m[5] = {
        {SKGL_STANDARD, 1024, 1}, {SKGL_STANDARD, 2048, 1}, {SKGL_PSSM, 1024, 4}, {SKGL_LSPSM, 1024, 0},
        {SKGL_RMSM, 16384, 1}};
    static const char *names[5] = {"standard 1024", "standard 2048", "pssm 4x1024", "lspsm 1024", "rmsm 16384"};
    gt_env e;
    tb_scene sc;
    sk_vec3 eye, target, light;
    skgl_camera cam;
    bench_receivers rc;
    bench_texel_scratch t;
    tb_footprint_stats st[5];
    float *ref, *res;
    int k;
    memset(&rc, 0, sizeof rc);
    tb_scene_init(&sc);
    if (tb_scene_build_open_world(&sc) != 0 || gt_env_init(&e, &sc, W, H) != 0) {
        SK_CHECK_MSG(0, "open world");
        return;
    }
    tb_open_world_view(0, &eye, &target);
    tb_open_world_sun(0, 2, &light);
    cam = gt_camera(eye, target, 1.0471976f, 0.5f, 1000.0f, W, H);
    ref = gt_alloc(&e);
    res = gt_alloc(&e);
    if (!ref || !res || bench_texel_scratch_init(&t, W, H) != 0 || gt_gbuffer(&e, &cam) != 0 ||
        gt_reference(&e, light, ref) != 0 ||
        bench_receivers_init(&rc, W, H, &(sk_mat4){0}, &cam.view, e.depth) != -1) {
        SK_CHECK_MSG(0, "setup");
        goto out;
    }
    /* a singular view-projection is refused; the real one is not */
    {
        sk_mat4 vp = sk_mat4_mul(cam.proj, cam.view);
        SK_CHECK(bench_receivers_init(&rc, W, H, &vp, &cam.view, e.depth) == 0);
    }
    for (k = 0; k < 5; k++) {
        skgl_shadow_desc d = gt_shadow_desc(m[k].t, m[k].res, m[k].cascades, 0);
        skgl_shadow *s;
        d.sync_readback = m[k].t == SKGL_RMSM;
        s = gt_shadow(&e, &d);
        memset(&st[k], 0, sizeof st[k]);
        if (!s) { SK_CHECK_MSG(0, "%s: create", names[k]); continue; }
        SK_CHECK(skgl_shadow_select_extent(s) == 1.0f);
        st[k] = method_stats(&e, s, &cam, light, &rc, ref, res, &t);
        printf("  %-14s texel > 1 / 2 / 4 px %5.1f%% %5.1f%% %5.1f%%, median %.3f px (%llu pixels)\n", names[k],
               st[k].over1_pct, st[k].over2_pct, st[k].over4_pct, st[k].median, (unsigned long long)st[k].count);
        SK_CHECK_MSG(st[k].count > e.n / 4, "%s: %llu pixels with a footprint", names[k],
                     (unsigned long long)st[k].count);
        if (m[k].t == SKGL_LSPSM) {
            /* the partitions' rects less their margin: 1 - 2 (pcf + 3) / res */
            float x = skgl_shadow_select_extent(s);
            SK_CHECK_MSG(x > 0.5f && x < 1.0f, "LSPSM select extent %g", (double)x);
        }
        if (m[k].t == SKGL_RMSM) {
            double same, near, coarse_over1;
            rmsm_levels_agree(&e, s, &t, &same, &near, &coarse_over1);
            printf("  rmsm page level = the GPU analysis's on %.1f%% of the pixels, within one level on %.1f%%; "
                   "texel > 1 px on %.2f%% of the pixels above level 0\n", same, near, coarse_over1);
            /* a page level is the floor of log2 of the footprint's narrow
               side in level-0 texels, so there a texel spans at most a
               pixel along either axis of the map (Ferko's bounding box is
               no narrower); over a pixel only where the pool fell back to a
               coarser page */
            SK_CHECK_MSG(coarse_over1 < 2.0, "rmsm: texel > 1 px on %.2f%% above level 0", coarse_over1);
            /* 98.0% and 99.7% measured; the rest sit where the floored level
               of detail changes: llvmpipe differences a 2x2 quad, bench_texel
               the nearer neighbour */
            SK_CHECK_MSG(same >= 90.0 && near >= 99.3, "rmsm levels: %.1f%% equal, %.1f%% within one", same, near);
        }
        skgl_shadow_destroy(e.sk, s);
    }
    SK_CHECK(skgl_shadow_select_extent(NULL) == 1.0f);
    /* a texel is half as wide at twice the resolution: the median halves */
    SK_CHECK_MSG(fabs(st[0].median / st[1].median - 2.0) < 0.04, "standard medians %.3f %.3f", st[0].median,
                 st[1].median);
    /* cascades and partitions spend their 1024^2 maps near the eye: 66.0%
       and 3.9% over a pixel against 93.7%, medians 0.08x and 0.02x */
    SK_CHECK_MSG(st[2].over1_pct < 82.0 && st[2].median < 0.2 * st[0].median, "pssm %.1f%% median %.3f",
                 st[2].over1_pct, st[2].median);
    SK_CHECK_MSG(st[3].over1_pct < 82.0 && st[3].median < 0.2 * st[0].median, "lspsm %.1f%% median %.3f",
                 st[3].over1_pct, st[3].median);
out:
    bench_receivers_free(&rc);
    bench_texel_scratch_free(&t);
    free(ref);
    free(res);
    gt_env_free(&e);
    tb_scene_free(&sc);
}

SK_TEST_MAIN(test_footprint_synthetic, test_bands, test_texel_methods)
