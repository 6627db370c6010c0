/* test_gl_open_world.c - the regime cascades, warps and virtual maps are
   made for: the testbed's "open-world" (2 km of ground, 300 buildings,
   2000 poles, a camera at head height, far plane 1000 m; tb_scene.h), its
   5 views x 6 suns (45, 20 and 8 degrees, behind and across the viewer),
   every directional technique against the exact Embree reference.

   Scores: the shadow-area error (misclassified pixels over the
   reference's shadowed ones, tb_metric_shadow's definition), pooled over
   frames (the sums of wrong and of shadow pixels, so a frame with a large
   shadow weighs more), and pooled by view-depth band: 0-10, 10-50, 50-200
   and 200+ m, so near-camera aliasing and far-field loss both show.

   test_open_world        the table (figures in its comment), the
                          techniques against standard 2048^2 pooled and
                          frame by frame, PSM's slide
   test_lispsm_low_sun_wall  a 4 x 8 m wall from 15 m behind to 40 m
                          ahead of the camera, the sun 20 and 8 degrees
                          behind the viewer: the share of the wall's
                          shadow each technique loses

   SK_GL_TEST_SURVEY=1 also prints every frame and every wall row;
   SK_GL_TEST_IMAGES=1 writes out/tests/open-world-v<view>-s<sun>-<method
   index>.png and -error.png for every frame of the table. */
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "sk_test.h"
#include "gl_test_util.h"
#include "gt_bands.h"

#include <stdio.h>

#define W 320
#define H 180
#define FOVY 1.0471976f   /* 60 degrees */
#define ZN 0.5f
#define ZF 1000.0f
/* pixels one shadow texel covers, counted over the frames (see
   footprint_add): shares above 1, 2 and 4 pixels */
typedef struct footprint { double over[3], counted; } footprint;

/* the pooled counts (gt_bands.h), the texels, the failed frames */
typedef struct pool {
    gt_band_pool b;
    double texels;
    int failed;
    footprint fp;             /* single maps and cascades only (fp.counted 0 otherwise) */
} pool;

static skgl_camera ow_camera(int view) {
    sk_vec3 eye, target;
    tb_open_world_view(view, &eye, &target);
    return gt_camera(eye, target, FOVY, ZN, ZF, W, H);
}

static sk_vec3 ow_sun(int view, int sun) {
    sk_vec3 l;
    tb_open_world_sun(view, sun, &l);
    return l;
}

/* one technique of the survey */
typedef struct method {
    const char *name;
    skgl_technique technique;
    int resolution, cascades, stable, analyze;
    int pool;                 /* RMSM: desc.rmsm_pool_pages (0: the default 24) */
} method;

static const method methods[] = {
    {"standard 2048", SKGL_STANDARD, 2048, 1, 0, 0, 0},
    {"standard 4096", SKGL_STANDARD, 4096, 1, 0, 0, 0},
    {"pssm 4x1024", SKGL_PSSM, 1024, 4, 0, 0, 0},
    {"pssm-stable 4x1024", SKGL_PSSM, 1024, 4, 1, 0, 0},
    {"lispsm 2048", SKGL_LISPSM, 2048, 1, 0, 0, 0},
    {"psm 2048", SKGL_PSM, 2048, 1, 0, 0, 0},
    {"lspsm", SKGL_LSPSM, 2048, 0, 0, 0, 0},
    {"ferko max 4096", SKGL_FERKO, 4096, 1, 0, 1, 0},
    {"rmsm 16384", SKGL_RMSM, 16384, 1, 0, 1, 0},
    {"rmsm 65536", SKGL_RMSM, 65536, 1, 0, 1, 0},
    {"lspsm 1024", SKGL_LSPSM, 1024, 0, 0, 0, 0},
    {"rmsm 65536 pool 48", SKGL_RMSM, 65536, 1, 0, 1, 48},
};
#define METHODS ((int)(sizeof methods / sizeof methods[0]))

static skgl_shadow_desc method_desc(const method *m) {
    skgl_shadow_desc d = gt_shadow_desc(m->technique, m->resolution, m->cascades, m->stable);
    d.sync_readback = m->analyze;
    d.rmsm_pool_pages = m->pool;
    return d;
}

/* render (analysis first where the technique has one) + mask; 0 ok */
static int ow_frame(gt_env *e, skgl_shadow *s, const method *m, const skgl_camera *cam, sk_vec3 light, float *vis) {
    skgl_scene sc = gt_scene(e);
    if (m->analyze) {
        sk_result r = skgl_shadow_analyze(e->sk, s, cam, &sc, light, e->gbuf.depth_tex);
        if (r != SK_OK) {
            printf("skgl_shadow_analyze: %s (%s)\n", sk_result_string(r), skgl_error_log(e->sk));
            return -1;
        }
    }
    return gt_mask(e, s, cam, light, vis);
}

static void print_pool(const char *name, const pool *p) {
    gt_band_pool_print(name, &p->b);
    printf("  texels %.1fM", p->texels / (double)(p->b.frames ? p->b.frames : 1) / 1e6);
    if (p->fp.counted > 0)
        printf("  texel > 1/2/4 px %5.1f%% %5.1f%% %5.1f%%", 100.0 * p->fp.over[0] / p->fp.counted,
               100.0 * p->fp.over[1] / p->fp.counted, 100.0 * p->fp.over[2] / p->fp.counted);
    printf("%s\n", p->failed ? "  FAILED" : "");
}

/* ---- the limit: how many pixels one shadow texel covers (Ferko 2013) --
   Per covered pixel whose right and upper neighbours lie on the same
   surface (normals within 1 degree, view depths within 2%): J, the change of
   the map's texel coordinates from one pixel to the next, from the three
   world points through the layer's matrix (the layer the mask would pick:
   by view depth for cascades). A texel spans 1 / s pixels along the
   direction where J's smallest singular value s is taken: more than 1 is
   magnification, a staircase the view can see. Counted into shares of
   more than 1, 2 and 4 pixels. Single maps and cascades only (LSPSM's
   partitions and RMSM's pages choose per point on the GPU). */

static int layer_of(const skgl_shadow_frame_stats *st, double depth) {
    int i;
    for (i = 0; i < st->maps; i++)
        if (depth < st->splits[i + 1]) return i;
    return st->maps - 1;
}

static void texel_x_y(const sk_mat4 *m, const double p[3], double sx, double sy, double *x, double *y) {
    sk_vec4 h, c;
    h.x = (float)p[0]; h.y = (float)p[1]; h.z = (float)p[2]; h.w = 1.0f;
    c = sk_mat4_transform_vec4(*m, h);
    *x = (c.x / c.w * 0.5 + 0.5) * sx;
    *y = (c.y / c.w * 0.5 + 0.5) * sy;
}

static void footprint_add(footprint *fp, const gt_env *e, const skgl_shadow *s, const float *ref) {
    const skgl_shadow_frame_stats *st = skgl_shadow_stats(s);
    double sx = st->map_width > 0 ? st->map_width : st->resolution;
    double sy = st->map_height > 0 ? st->map_height : st->resolution;
    int x, y;
    for (y = 0; y + 1 < e->h; y++)
        for (x = 0; x + 1 < e->w; x++) {
            size_t i = (size_t)y * e->w + x, ix = i + 1, iy = i + (size_t)e->w;
            double p[3], px[3], py[3], d = gt_view_depth(e, i), tx, ty, ax, ay, bx, by;
            double a, b, c, tr, det, smax, smin, over;
            const float *n = e->normals;
            sk_mat4 m;
            int k;
            if (ref[i] < 0 || gt_world(e, i, p) || gt_world(e, ix, px) || gt_world(e, iy, py)) continue;
            if (fabs(gt_view_depth(e, ix) - d) > 0.02 * d || fabs(gt_view_depth(e, iy) - d) > 0.02 * d) continue;
            if (n[3 * i] * n[3 * ix] + n[3 * i + 1] * n[3 * ix + 1] + n[3 * i + 2] * n[3 * ix + 2] < 0.99985 ||
                n[3 * i] * n[3 * iy] + n[3 * i + 1] * n[3 * iy + 1] + n[3 * i + 2] * n[3 * iy + 2] < 0.99985)
                continue;
            m = skgl_shadow_matrix(s, layer_of(st, d));
            texel_x_y(&m, p, sx, sy, &tx, &ty);
            texel_x_y(&m, px, sx, sy, &ax, &ay);
            texel_x_y(&m, py, sx, sy, &bx, &by);
            ax -= tx; ay -= ty; bx -= tx; by -= ty;
            /* singular values of [a b; c d]: smax smin = |det|, smax^2 + smin^2 = trace of J^T J */
            a = ax * ax + ay * ay;
            b = bx * bx + by * by;
            c = ax * by - ay * bx;
            tr = a + b;
            det = fabs(c);
            smax = sqrt(0.5 * (tr + sqrt(fmax(tr * tr - 4.0 * det * det, 0.0))));
            smin = smax > 0.0 ? det / smax : 0.0;
            over = smin > 0.0 ? 1.0 / smin : 1e30;
            fp->counted += 1;
            for (k = 0; k < 3; k++) fp->over[k] += over > (double)(1 << k);
        }
}

/* covered pixels the reference calls lit while the G-buffer's normal faces
   away from the sun. At a box's vertical edge the rasteriser may shade the
   face turned from the sun while the pixel centre's ray meets the lit one
   at the same depth; every technique's mask calls that face its own shadow
   (sk_shadow_map_visibility) whatever its map holds, so the reference
   leaves such pixels out (tb_ref_options.raster_normals, the same-face
   test). With the flat faces of this scene none may remain. */
static double lit_faced_away(const gt_env *e, const float *ref, sk_vec3 light) {
    double n = 0;
    size_t i;
    for (i = 0; i < e->n; i++) {
        const float *nn = e->normals + 3 * i;
        if (tb_visibility_class(ref[i]) != 1) continue;
        n += nn[0] * light.x + nn[1] * light.y + nn[2] * light.z >= 0.0f;
    }
    return n;
}

/* The pixels the same-face test left out of ref (traced with the G-buffer's
   normals): a trace without them, counted where it calls them lit and
   shadowed, in all and beyond 200 m (out[0..3]) */
static void same_face_left_out(gt_env *e, sk_vec3 light, const float *ref, float *scratch, double out[4]) {
    tb_view v = gt_view(e);
    tb_light l = gt_sun(light);
    size_t i;
    if (tb_reference_trace_exact(e->ref, &v, e->depth, &l, NULL, scratch, NULL) != 0) {
        SK_CHECK_MSG(0, "reference without normals");
        return;
    }
    for (i = 0; i < e->n; i++) {
        int far = gt_band_of(gt_view_depth(e, i)) == GT_BANDS - 1;
        if (ref[i] != TB_VIS_SILHOUETTE || scratch[i] < 0.0f) continue;
        out[scratch[i] > 0.5f ? 0 : 1] += 1;
        if (far) out[scratch[i] > 0.5f ? 2 : 3] += 1;
    }
}

/* "  <name>  wrong / shadow px  0-10 a/b ..." */
static void print_band_px(const char *name, const gt_band_pool *p) {
    int b;
    printf("  %-20s wrong / shadow px by band:", name);
    for (b = 0; b < GT_BANDS; b++) printf("  %s %.0f/%.0f", gt_band_name[b], p->band_wrong[b], p->band_shadow[b]);
    printf("\n");
}

/* method indices the checks name */
enum { M_STD2048, M_STD4096, M_PSSM, M_PSSM_STABLE, M_LISPSM, M_PSM, M_LSPSM, M_FERKO, M_RMSM, M_RMSM64K, M_LSPSM1K,
       M_RMSM64K_POOL48 };
#define FRAMES (TB_OPEN_WORLD_VIEWS * TB_OPEN_WORLD_SUNS)

static int verbose(void) {
    const char *v = getenv("SK_GL_TEST_SURVEY");
    return v && *v && *v != '0';
}

/* SK_GL_TEST_METHODS=rmsm runs only the methods whose name contains the
   string (a quicker survey; the checks across methods are skipped then) */
static int method_selected(int k) {
    const char *f = getenv("SK_GL_TEST_METHODS");
    return !f || !*f || strstr(methods[k].name, f) != NULL;
}

static int methods_filtered(void) {
    const char *f = getenv("SK_GL_TEST_METHODS");
    return f && *f;
}

/* Every technique over every view and sun. Measured (Mesa 22.3 llvmpipe,
   320x180), pooled shadow-area error % and by band (0-10, 10-50, 50-200,
   200+ m), texels per frame:
     standard 2048      11.94   9.25 19.83 14.71  4.17   4.2M
     standard 4096       6.97   5.28 11.79  9.71  2.20  16.8M
     pssm 4x1024         1.50   1.21  1.92  4.56  4.50   4.2M
     pssm-stable 4x1024  1.39   0.99  2.02  5.34  3.29   4.2M
     lispsm 2048         1.52   0.79  3.05  5.86  7.24   4.2M
     psm 2048            3.15   2.05  5.61  9.09  8.56   4.2M
     lspsm               1.23   1.03  1.44  3.95  2.85  27.3M
     ferko max 4096      3.62   2.81  6.12  3.49  1.43  16.8M
     rmsm 16384          2.29   1.93  3.29  3.08  1.65   3.2M
     rmsm 65536          0.84   0.62  1.31  2.42  1.32   8.4M
     lspsm 1024          3.05   2.54  4.24  5.59  3.51   6.8M
     rmsm 65536 pool 48  0.72   0.61  1.06  0.70  0.77  16.1M
   The reference's same-face test leaves out the pixels at a box's edge
   where the rasteriser shaded one face and the traced ray met the other:
   51 px over the 30 frames, 45 that a trace without it calls lit and 6
   shadowed (24 beyond 200 m, 2 of them shadowed). 23 of the lit ones, 9
   beyond 200 m, lie on a face the G-buffer turned from the sun, which
   every technique's mask calls shadowed: counted, they were 1% of the
   911 reference shadow pixels beyond 200 m for every technique.
   LSPSM at 1024^2 a partition (1.6x PSSM 4x1024^2's texels: 6.5
   partitions a frame on average) has 2.0x PSSM's error, 2.1x in the
   0-10 m band: the partitions of the view's trapezoid (Tang et al. 2017,
   Eq. 1) give the near field less of the map than the practical split
   scheme's first cascade. At 2048^2 a partition it beats PSSM (1.23%) with
   6.5x the texels.
   The limit, the share of pixels one texel spans more than 1 / 2 / 4
   times: standard 2048 98.2 94.7 86.9%, 4096 94.7 86.9 70.1, PSSM 81.3
   68.7 65.9, PSSM stable 83.4 69.1 66.5, LiSPSM 77.2 37.3 13.5, PSM 70.8
   44.4 25.4, FERKO 84.8 73.8 66.9.
   PSM before its casters became the hull of what can shadow the view
   (skgl__caster_hull; the whole scene box before): 10.22% pooled (0.86x
   standard 2048's; 7.21 18.13 19.64 5.91 by band), the virtual camera
   slid back 1005 to 1273 m in every frame, and two frames (view 0, suns
   at 45 and 20 degrees across) lost every shadow (100%): the box's far
   corners lay beyond the light in post-perspective space, the fit failed
   and fell back to a uniform map. Now the slide is 13 to 296 m (the
   height of the scene over the tangent of a low sun behind the viewer)
   and those frames 3.09% and 2.17%.
   RMSM before its pages' level came from the smallest singular value of
   the footprint (the area's square root before, which is coarser than a
   grazing receiver's narrow side needs): 4.36% pooled at 16384^2 (1.95
   8.81 22.78 34.28 by band, 1.1M texels) and 3.50% at 65536^2 (0.79 8.72
   22.77 34.28, 2.2M): the virtual size hardly mattered. Pixel-matched
   (desc.rmsm_band_pages -1), 2.65% (1.94 4.02 7.90 9.97, 2.3M) and 1.38%
   (0.62 2.73 7.53 9.97, 5.2M): beyond 200 m the same at both sizes, as
   the page matches the pixel there (a 2-3 m texel at 500 m) and a pole's
   0.3 m shadow is a point sample inside one texel. The pages now go a
   level finer than the pixel, capped in world size, as far as the pool
   holds them (request bands, stats.rmsm_band): at 16384^2 every frame
   takes level 0. At 65536^2 the bands once had to go a level finer than
   the pixel everywhere: 9 frames found none that fit and kept the
   pixel-matched band 0 (two of them over the pool even so, their finest
   level raised), 1.09% (0.62 1.96 4.76 3.29, 8.1M), the far field
   worse than at 16384^2. Now the finest world-size cap the pool holds
   comes first, a level finer than the pixel only where the pool holds
   that too (stats.rmsm_band_finer), and a pool too short for the
   pixel-matched pages seeks the cap above a raised floor: band 6-9 in
   28 frames, 0 in 2. Pixels beyond 200 m (all shadow-area figures
   there are of 911 reference shadow px, so 1% allows 9): 12 wrong at
   65536^2, 15 at 16384^2 (21 and 24 while the reference counted the 9
   box-edge pixels above). Of the 12, 1 is a receiver 2 cm from its
   caster (a contact, inside the receiver's 4-ulp depth slack of ~12 cm
   at 500 m) and 11 sit on shadow edges, res 0.05-0.73, where the 24^2
   pool affords a cap of 9-35 cm (bands 6-8). A 48^2 pool (band 9, level
   0's ~4 cm texels everywhere; 16.1M texels, 4x the memory) leaves 7
   (0.77%): that contact and edges at the depth buffer's precision (a
   float depth at 700 m is 3 cm along the ray). */
static void test_open_world(void) {
    gt_env e;
    pool pools[METHODS];
    skgl_shadow *sh[METHODS];
    double frame_err[METHODS][FRAMES];
    float *ref, *res, max_slide = 0.0f;
    int v, s, k, f, ferko_below_cap = 0;
    double faced_away = 0, left_out[4] = {0, 0, 0, 0};
    tb_scene sc;
    tb_scene_init(&sc);
    if (tb_scene_build_open_world(&sc) != 0 || gt_env_init(&e, &sc, W, H) != 0) {
        SK_CHECK_MSG(0, "open world");
        return;
    }
    memset(pools, 0, sizeof pools);
    ref = gt_alloc(&e);
    res = gt_alloc(&e);
    for (k = 0; k < METHODS; k++) {
        skgl_shadow_desc d = method_desc(&methods[k]);
        sh[k] = method_selected(k) ? gt_shadow(&e, &d) : NULL;
    }
    for (v = 0; v < TB_OPEN_WORLD_VIEWS; v++) {
        skgl_camera cam = ow_camera(v);
        if (gt_gbuffer(&e, &cam) != 0) { SK_CHECK_MSG(0, "G-buffer"); break; }
        for (s = 0; s < TB_OPEN_WORLD_SUNS; s++) {
            sk_vec3 light = ow_sun(v, s);
            f = v * TB_OPEN_WORLD_SUNS + s;
            if (gt_reference(&e, light, ref) != 0) { SK_CHECK_MSG(0, "reference"); continue; }
            faced_away += lit_faced_away(&e, ref, light);
            same_face_left_out(&e, light, ref, res, left_out);
            for (k = 0; k < METHODS; k++) {
                const skgl_shadow_frame_stats *st;
                pool one;
                memset(&one, 0, sizeof one);
                frame_err[k][f] = -1.0;
                if (!method_selected(k)) continue;
                if (!sh[k] || ow_frame(&e, sh[k], &methods[k], &cam, light, res) != 0) {
                    pools[k].failed++;
                    continue;
                }
                st = skgl_shadow_stats(sh[k]);
                gt_band_pool_add(&pools[k].b, &e, ref, res);
                gt_band_pool_add(&one.b, &e, ref, res);
                pools[k].texels += st->texels;
                if (methods[k].technique != SKGL_LSPSM && methods[k].technique != SKGL_RMSM) footprint_add(&pools[k].fp, &e, sh[k], ref);
                frame_err[k][f] = gt_pool_pct(one.b.wrong, one.b.shadow);
                if (getenv("SK_GL_TEST_IMAGES")) {
                    char nm[96];
                    snprintf(nm, sizeof nm, "open-world-v%d-s%d-%d", v, s, k);
                    gt_images(&e, nm, ref, res);
                }
                if (k == M_PSM && st->psm_slide > max_slide) max_slide = st->psm_slide;
                if (k == M_FERKO) ferko_below_cap += st->map_width < methods[k].resolution;
                if (verbose())
                    printf("view %d sun %d %-20s %7.2f%% (shadow %6.0f px) slide %.1f n %.1f map %dx%d pages %d/%d "
                           "min level %d band %d, 200+ m %.0f of %.0f px wrong\n",
                           v, s, methods[k].name, frame_err[k][f], one.b.shadow, st->psm_slide, st->warp_n[0],
                           st->map_width, st->map_height, st->pages_rendered, st->pages_requested,
                           st->rmsm_min_level, st->rmsm_band, one.b.band_wrong[3], one.b.band_shadow[3]);
            }
        }
    }
    printf("open world, %d views x %d suns, %dx%d, pooled shadow-area error %% and by view-depth band (m):\n",
           TB_OPEN_WORLD_VIEWS, TB_OPEN_WORLD_SUNS, W, H);
    for (k = 0; k < METHODS; k++)
        if (method_selected(k)) print_pool(methods[k].name, &pools[k]);
    printf("PSM: largest slide %.1f m; FERKO: %d of %d frames below its cap\n", max_slide, ferko_below_cap, FRAMES);
    for (k = 0; k < METHODS; k++)
        if (method_selected(k) && methods[k].technique == SKGL_RMSM) print_band_px(methods[k].name, &pools[k].b);
    printf("the same-face test left out %.0f px the reference would call lit and %.0f shadowed (beyond 200 m: "
           "%.0f and %.0f)\n", left_out[0], left_out[1], left_out[2], left_out[3]);
    SK_CHECK_MSG(faced_away == 0, "%.0f px the reference calls lit face away from the sun in the G-buffer",
                 faced_away);
    /* and it leaves out box edges only: 51 of the 30 frames' 1.73M pixels
       (0.003%), bound 0.01% */
    SK_CHECK_MSG(left_out[0] + left_out[1] <= 1e-4 * (double)e.n * FRAMES, "the same-face test left out %.0f px",
                 left_out[0] + left_out[1]);
    for (k = 0; k < METHODS; k++) SK_CHECK_MSG(pools[k].failed == 0, "%s: %d frames failed", methods[k].name,
                                               pools[k].failed);
    if (!methods_filtered()) {
        double std = gt_pool_pct(pools[M_STD2048].b.wrong, pools[M_STD2048].b.shadow);
        double pssm = gt_pool_pct(pools[M_PSSM].b.wrong, pools[M_PSSM].b.shadow);
        double lis = gt_pool_pct(pools[M_LISPSM].b.wrong, pools[M_LISPSM].b.shadow);
        double psm = gt_pool_pct(pools[M_PSM].b.wrong, pools[M_PSM].b.shadow);
        /* the regime the papers were written for: at standard 2048^2's
           texels, PSSM 0.13x its error (1.50 / 11.94), LiSPSM 0.13x
           (1.52), PSM 0.26x (3.15; 0.86x with the scene box as casters).
           Bounds: the targets (LiSPSM at most 0.5x, PSM at most
           0.7x) and PSSM at most 0.25x (1/9 in an independent check) */
        SK_CHECK_MSG(pssm <= 0.25 * std, "PSSM pooled %.2f%% against standard 2048's %.2f%%", pssm, std);
        /* stable cascades at most 1.3x the focused ones: measured 0.93x
           (1.39%; each crop's width and height step on a 2^(1/8) ladder,
           texel-snapped); 1.77x with the sphere fit (2.68%, .stable_sphere) */
        {
            double stable = gt_pool_pct(pools[M_PSSM_STABLE].b.wrong, pools[M_PSSM_STABLE].b.shadow);
            SK_CHECK_MSG(stable <= 1.3 * pssm, "PSSM stable pooled %.2f%% against PSSM's %.2f%%", stable, pssm);
        }
        SK_CHECK_MSG(lis <= 0.5 * std, "LiSPSM pooled %.2f%% against standard 2048's %.2f%%", lis, std);
        SK_CHECK_MSG(psm <= 0.7 * std, "PSM pooled %.2f%% against standard 2048's %.2f%%", psm, std);
        /* RMSM pooled 0.19x standard 2048's (0.22x pixel-matched, 0.36x
           with the area's square root) */
        double rmsm = gt_pool_pct(pools[M_RMSM].b.wrong, pools[M_RMSM].b.shadow);
        SK_CHECK_MSG(rmsm <= 0.3 * std, "RMSM pooled %.2f%% against standard 2048's %.2f%%", rmsm, std);
        /* the warps and cascades spend texels where the view needs them:
           a texel over 2 px on 68.7% (PSSM), 37.3% (LiSPSM) and 44.4%
           (PSM) of the pixels, against 94.7% for standard 2048 */
        for (k = M_PSSM; k <= M_PSM; k++) {
            double share = pools[k].fp.counted > 0 ? pools[k].fp.over[1] / pools[k].fp.counted : 1.0;
            double base = pools[M_STD2048].fp.over[1] / pools[M_STD2048].fp.counted;
            if (k == M_PSSM_STABLE) continue;
            SK_CHECK_MSG(share < 0.8 * base, "%s: texel over 2 px on %.1f%% of the pixels (standard 2048 %.1f%%)",
                         methods[k].name, 100.0 * share, 100.0 * base);
        }
        /* the slide from the casters that can shadow the view: at most the
           scene's 40 m over tan 8 degrees (285 m) and the body's extent
           behind the camera; measured 295.8 m (1273 m with the scene box) */
        SK_CHECK_MSG(max_slide > 0.0f && max_slide <= 320.0f, "PSM slide %.1f m", max_slide);
    }
    if (method_selected(M_RMSM) && method_selected(M_RMSM64K)) {
        /* RMSM's pages capped in world size, and a level finer than the
           pixel, where the pool holds them (desc.rmsm_band_pages): 50-200 m
           3.08% at 16384^2 (7.90% pixel-matched, 22.78% with the area's
           square root) and 2.42% at 65536^2 (4.76% when every band had to
           go a level finer); the error falls as the virtual map grows,
           pooled (65536^2 0.84%, 0.37x 16384^2's 2.29%; 1.09%, 0.47x, so)
           and beyond 200 m (1.32%, 12 of 911 px, against 1.65%, 15 px;
           2.30% and 2.63% when the reference still counted the box edges
           the same-face test leaves out; 9.97% at both pixel-matched; 34.28%
           with the level from the area). Bounds about 1.25x, the 200+ m
           ones 3 and 4 px over the measurement */
        double rmsm = gt_pool_pct(pools[M_RMSM].b.wrong, pools[M_RMSM].b.shadow);
        double rmsm64 = gt_pool_pct(pools[M_RMSM64K].b.wrong, pools[M_RMSM64K].b.shadow);
        double rmsm_mid = gt_pool_pct(pools[M_RMSM].b.band_wrong[2], pools[M_RMSM].b.band_shadow[2]);
        double mid64 = gt_pool_pct(pools[M_RMSM64K].b.band_wrong[2], pools[M_RMSM64K].b.band_shadow[2]);
        double far16 = gt_pool_pct(pools[M_RMSM].b.band_wrong[3], pools[M_RMSM].b.band_shadow[3]);
        double far64 = gt_pool_pct(pools[M_RMSM64K].b.band_wrong[3], pools[M_RMSM64K].b.band_shadow[3]);
        SK_CHECK_MSG(rmsm_mid <= 4.0 && mid64 <= 3.1, "RMSM 50-200 m: 16384^2 %.2f%%, 65536^2 %.2f%%", rmsm_mid, mid64);
        SK_CHECK_MSG(rmsm64 <= 0.42 * rmsm, "RMSM 65536^2 %.2f%%, 16384^2 %.2f%%", rmsm64, rmsm);
        SK_CHECK_MSG(far64 < far16 && far16 <= 2.1 && far64 <= 1.75,
                     "RMSM beyond 200 m: 16384^2 %.2f%%, 65536^2 %.2f%%", far16, far64);
    }
    if (method_selected(M_RMSM64K) && method_selected(M_RMSM64K_POOL48)) {
        /* the far field near the limit: a 65536^2 virtual map whose pool
           holds the pages it asks for (48^2 = 2304 pages of 128^2, 156 MB;
           the default 24^2 overflows beyond 50 m, its bands settle at
           9-35 cm texels there): pooled 0.72%, 50-200 m 0.70% (2.42% at
           24^2), beyond 200 m 0.77%, 7 of 911 px (12 at 24^2): one
           receiver 2 cm under its caster, inside its 4-ulp depth slack
           at 500 m, the rest on shadow edges within a float depth's
           precision (3 cm along the ray at 700 m). The target, at
           most 1% beyond 200 m, is the bound (9 px); 50-200 m at most 1%
           too (129 px, measured 91) */
        double mid48 = gt_pool_pct(pools[M_RMSM64K_POOL48].b.band_wrong[2], pools[M_RMSM64K_POOL48].b.band_shadow[2]);
        double far48 = gt_pool_pct(pools[M_RMSM64K_POOL48].b.band_wrong[3], pools[M_RMSM64K_POOL48].b.band_shadow[3]);
        double far64 = gt_pool_pct(pools[M_RMSM64K].b.band_wrong[3], pools[M_RMSM64K].b.band_shadow[3]);
        SK_CHECK_MSG(far48 <= 1.0 && far48 < far64 && mid48 <= 1.0,
                     "RMSM 65536^2, 48^2 pool: 50-200 m %.2f%%, beyond 200 m %.2f%% (%.2f%% with 24^2)", mid48,
                     far48, far64);
    }
    for (f = 0; f < FRAMES; f++) {
        /* LiSPSM never loses to the plain map in any frame: measured at
           most 0.63x standard 2048's frame error (view 0, 8 degrees
           behind the viewer: 2.45% against 3.92%; every frame is listed
           with SK_GL_TEST_SURVEY=1) */
        SK_CHECK_MSG(frame_err[M_LISPSM][f] <= frame_err[M_STD2048][f] + 0.5,
                     "frame %d: LiSPSM %.2f%%, standard 2048 %.2f%%", f, frame_err[M_LISPSM][f],
                     frame_err[M_STD2048][f]);
        /* PSM never loses a whole frame's shadows: measured at most
           64.4% (view 3, 8 degrees behind, where standard 2048 has
           73.7%); with the scene box, 100% in two frames */
        SK_CHECK_MSG(frame_err[M_PSM][f] < 90.0, "frame %d: PSM %.2f%%", f, frame_err[M_PSM][f]);
    }
    for (k = 0; k < METHODS; k++) skgl_shadow_destroy(e.sk, sh[k]);
    free(ref);
    free(res);
    gt_env_free(&e);
}

/* ---- a single wall and a low sun behind the viewer ------------------- */
/* The wall: 4 m wide (x in [2, 6]), 8 m high, 0.4 m thick, its centre d m
   ahead of view 0's camera (which looks along -z from the origin). */
#define WALL_X0 2.0f
#define WALL_X1 6.0f
#define WALL_H 8.0f

static sk_aabb wall_box(float d) { return gt_box(WALL_X0, 0, -d - 0.2f, WALL_X1, WALL_H, -d + 0.2f); }

/* 1 when the world point p is in the wall's shadow: the ray toward the
   light (against light_dir) meets the wall's box (slab test) */
static int in_wall_shadow(const double p[3], sk_vec3 light_dir, sk_aabb b) {
    double o[3], dir[3], t0 = 1e-3, t1 = 1e30;
    const double lo[3] = {b.min.x, b.min.y, b.min.z}, hi[3] = {b.max.x, b.max.y, b.max.z};
    int k;
    dir[0] = -light_dir.x; dir[1] = -light_dir.y; dir[2] = -light_dir.z;
    for (k = 0; k < 3; k++) o[k] = p[k];
    for (k = 0; k < 3; k++) {
        double a, c;
        if (fabs(dir[k]) < 1e-12) {
            if (o[k] < lo[k] || o[k] > hi[k]) return 0;
            continue;
        }
        a = (lo[k] - o[k]) / dir[k];
        c = (hi[k] - o[k]) / dir[k];
        if (a > c) { double t = a; a = c; c = t; }
        if (a > t0) t0 = a;
        if (c < t1) t1 = c;
        if (t0 > t1) return 0;
    }
    return 1;
}

/* of the wall's shadow pixels the reference calls shadowed, the % the
   result calls lit; *count: how many there are */
static double wall_shadow_lost(const gt_env *e, const float *ref, const float *res, sk_vec3 light, sk_aabb b,
                               int *count) {
    size_t i;
    int n = 0, lost = 0;
    for (i = 0; i < e->n; i++) {
        double p[3];
        if (tb_visibility_class(ref[i]) != 0 || gt_world(e, i, p) != 0) continue;
        if (p[1] > 0.05) continue;   /* on the ground */
        if (!in_wall_shadow(p, light, b)) continue;
        n++;
        lost += tb_visibility_class(res[i]) != 0;
    }
    *count = n;
    return n ? 100.0 * lost / n : 0.0;
}

static void test_lispsm_low_sun_wall(void) {
    static const float dist[] = {-15, -5, 5, 15, 40};
    static const int suns[] = {2, 4};   /* 20 and 8 degrees, behind the viewer */
    static const int wm[] = {M_STD2048, M_STD4096, M_LISPSM, M_PSM, M_PSSM};
    int di, si, k, walls = 0;
    for (di = 0; di < (int)(sizeof dist / sizeof dist[0]); di++) {
        gt_env e;
        tb_scene sc;
        skgl_camera cam = ow_camera(0);
        sk_aabb b = wall_box(dist[di]);
        float *ref, *res;
        tb_scene_init(&sc);
        if (tb_scene_build_open_world(&sc) != 0 || tb_scene_add_box(&sc, "wall", b.min, b.max) < 0 ||
            gt_env_init(&e, &sc, W, H) != 0) {
            SK_CHECK_MSG(0, "wall scene");
            return;
        }
        ref = gt_alloc(&e);
        res = gt_alloc(&e);
        gt_gbuffer(&e, &cam);
        for (si = 0; si < 2; si++) {
            sk_vec3 light = ow_sun(0, suns[si]);
            gt_reference(&e, light, ref);
            for (k = 0; k < (int)(sizeof wm / sizeof wm[0]); k++) {
                const method *m = &methods[wm[k]];
                skgl_shadow_desc d = method_desc(m);
                skgl_shadow *s = gt_shadow(&e, &d);
                int n = 0;
                double lost;
                if (!s || ow_frame(&e, s, m, &cam, light, res) != 0) { SK_CHECK_MSG(0, "render"); continue; }
                lost = wall_shadow_lost(&e, ref, res, light, b, &n);
                if (verbose() || k == 2)
                    printf("wall %5.1f m, sun %s: %-14s lost %6.2f%% of its %d shadow px (n %.1f)\n", dist[di],
                           si ? "8 deg" : "20 deg", m->name, lost, n, skgl_shadow_stats(s)->warp_n[0]);
                /* walls whose shadow the view shows (at least 20 px: up
                   to 15 m ahead); measured: LiSPSM loses at most 0.00%
                   of such a shadow, standard 4096 at most 0.11%, PSSM
                   0.11% (at 15 m ahead, 31 px, LiSPSM 3.2%) */
                if (n >= 20) {
                    SK_CHECK_MSG(lost <= 8.0, "wall at %.0f m, sun %d: %s lost %.2f%% of %d px", dist[di], suns[si],
                                 m->name, lost, n);
                    walls++;
                }
                skgl_shadow_destroy(e.sk, s);
            }
        }
        free(ref);
        free(res);
        gt_env_free(&e);
    }
    /* 4 of the 5 distances x 2 suns x 5 techniques show a shadow */
    SK_CHECK_MSG(walls == 40, "%d wall shadows measured", walls);
}

SK_TEST_MAIN(test_open_world, test_lispsm_low_sun_wall)
