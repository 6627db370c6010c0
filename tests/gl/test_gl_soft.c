/* test_gl_soft.c - area-light soft shadows (skgl_soft_*, Shen et al. 2011): PVSM
   and its PCSS baselines against the exact Embree area-light reference
   (tb_reference_trace_exact: traced primary hits, 24 x 24 stratified
   samples per pixel; receivers facing away from the whole light left out),
   at the configurations where they are known to fail. 320 x 180 on OSMesa.
   Figures below are from this machine (llvmpipe); each threshold is about
   1.5x the measured value. On the exact reference (figures in brackets:
   the legacy reference, 16 x 16 samples from unprojected depth): accuracy
   half 0.1 PVSM 0.00051 (0.00054), PCSS-4096 0.00090 (0.00086), PCSS-2048
   0.00138 (0.00130); half 0.4 PVSM 0.00039 (0.00042), PCSS-4096 0.00555
   (0.00523), PCSS-2048 0.00514 (0.00484); contact band 0.00360, elsewhere
   0.00410; temporal flip rate PVSM 0.0085%, PCSS-4096 0.0032%; the bounds
   were not changed. The penumbra-only error of both methods is measured
   against a closed form in test_gl_soft_closed_form.c.

   test_accuracy (scene "contact": a 2 x 1 x 2 box resting on the ground,
   light 5 above it, half sizes 0.1 and 0.4): mean absolute error
       half 0.1:  PVSM 0.00054   PCSS-4096 0.00086   PCSS-2048 0.00130   (legacy reference)
       half 0.4:  PVSM 0.00042   PCSS-4096 0.00523   PCSS-2048 0.00484
   (half 0.4 was PVSM 0.00093, PCSS-4096 0.00432, PCSS-2048 0.00398 before
   two fixes: PVSM's filter blocks no larger than the pixel's predicted
   texel, and the empty texels of the map no longer blockers. The second
   raised PCSS's figure: ground pixels near the box whose blocker search,
   cut at the near plane, reached texels the depth pass left empty had
   counted them as blockers at the far plane, which shrank their kernel and
   left them lit by accident; now only the box is found and PCSS's
   planar-blocker estimate shades some of them that the reference has lit.)
   PVSM must beat PCSS-4096 at both sizes and stay under 1.5x its figure.
   Can fail: SK_GL_TEST_RES_SCALE=0.03 caps the tiles at 122 texels (one
   tile): PVSM measured 0.00216 and 0.00343 and the test failed at both
   sizes (at 0.125, a 512 cap, PVSM measured 0.00054 and 0.00047: those
   sizes need no more and pass).

   test_contact: the error in a band of 4 pixels around the line where the
   box meets the ground stays within 2x the error over the rest of the
   shadow (reference or result below 0.99). Measured: band 0.0028,
   elsewhere 0.0028 (ratio 1.00) at half 0.4; elsewhere was 0.0076 before
   PVSM's filter blocks were bounded by the predicted texel (the rest of
   the shadow improved, the band did not).

   test_thin_caster: a pole 1/10 of a low-resolution texel wide (a 16^2
   low-res map, the camera close to the pole's shadow) still shadows the
   ground: of the pixels the reference puts below 0.5, PVSM
   puts 100% below 0.5 with conservative rasterisation; switched off
   (disable_conservative) the low-resolution map loses the pole, every pixel
   is taken as fully lit and the share is 0% (that run is part of the test).

   test_edges: zero-size light (hard shadows through the same path), a
   light larger than the receiver, sub-pixel kernels, every pixel lit (the
   SMTG empty: no tile), every pixel in umbra, a single tile demanded at
   the maximum resolution: finite visibility in [0,1], no GL error (debug
   context), error under the bounds given there. The umbra case looks at
   the ground in the box's shadow beside it (it looked at the box's side
   face, which the exact reference leaves out as facing away).

   test_pyramid: the SMTG pyramid read back equals sk_smtg_pyramid of its
   level 0, and the tiles equal sk_fvsm_tiles of it.

   test_temporal: a slow camera path of 6 frames; flip rate = pixels whose
   visibility changes by more than 0.1 between frames where the
   reference's changes by less than 0.02. Measured: PVSM 0.0075%, PCSS-4096
   0.0030%, all on the box's contact edge (bound 0.02%). Before the base
   frustum was snapped and tile sides rounded, PVSM measured 0.0130%.

   test_state: bad input, objects freed, GL state restored.

   HYGIENE. Under the sanitizers (build/hygiene/, __SANITIZE_ADDRESS__)
   only test_edges, test_pyramid and test_state run: measured with gcov,
   they reach the same 1530 lines of shadowkit_gl.h as the whole program
   (none fewer, none more; test_accuracy, test_contact, test_thin_caster
   and test_temporal are figures of the same passes, over other scenes),
   in 13 CPU s instead of 33; 55 checks instead of 90 (those four tests'
   35). */
/* reads skgl_soft's fields (light_view, desc, p00): its own copy of the implementation (tests/shared_impl.h) */
#define SK_TEST_OWN_IMPLEMENTATION 1
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "sk_test.h"
#include "gl/gl_test_util.h"

#include <stdio.h>

#define W 320
#define H 180
#define STRATA 0   /* the exact reference's default: TB_REF_EXACT_STRATA */
/* 1: the figure tests run (test_accuracy, test_contact, test_thin_caster,
   test_temporal); under the sanitizers they return at once (HYGIENE above) */
#ifdef __SANITIZE_ADDRESS__
#define FIGURES 0
#else
#define FIGURES 1
#endif

static skgl_area_light soft_light(sk_vec3 pos, sk_vec3 dir, float half) {
    skgl_area_light l;
    memset(&l, 0, sizeof l);
    l.position = pos;
    l.direction = dir;
    l.up = gt_v3(0, 0, 1);
    l.half_width = half;
    l.half_height = half;
    return l;
}

static skgl_camera contact_camera(void) {
    return gt_camera(gt_v3(3.0f, 2.2f, 3.6f), gt_v3(-0.6f, 0.2f, -0.4f), 0.9f, 0.05f, 60, W, H);
}
static skgl_area_light contact_light(float half) {
    return soft_light(gt_v3(2.0f, 5.0f, -2.5f), gt_v3(-0.4f, -1, 0.5f), half);
}

/* visibility in [0,1] on every covered pixel */
static int soft_valid(const gt_env *e, const float *v) {
    size_t i;
    for (i = 0; i < e->n; i++)
        if (e->depth[i] < 1.0f && !(v[i] >= 0.0f && v[i] <= 1.0f)) return 0;
    return 1;
}

/* one frame of a technique: the mask's MAE against ref; -1 on failure */
static double soft_frame(gt_env *e, const skgl_soft_desc *d, const skgl_camera *cam, const skgl_area_light *l,
                         const float *ref, float *mask, skgl_soft_frame_stats *st, const char *image) {
    skgl_soft *s = NULL;
    sk_result r = skgl_soft_create(e->sk, d, &s);
    double mae = -1.0;
    if (r != SK_OK) {
        SK_CHECK_MSG(0, "skgl_soft_create: %s (%s)", sk_result_string(r), skgl_error_log(e->sk));
        return -1.0;
    }
    if (gt_soft_mask(e, s, cam, l, mask, st) == 0) {
        SK_CHECK_MSG(soft_valid(e, mask), "visibility outside [0,1] or not finite");
        mae = tb_metric_soft(ref, mask, e->n).mae;
        if (image) gt_images(e, image, ref, mask);
    } else SK_CHECK_MSG(0, "skgl_soft_render failed");
    skgl_soft_destroy(e->sk, s);
    return mae;
}

static skgl_soft_desc soft_desc(skgl_soft_technique t, int res) {
    skgl_soft_desc d;
    memset(&d, 0, sizeof d);
    d.technique = t;
    d.resolution = res;
    return d;
}

static void test_accuracy(void) {
    static const float halves[2] = {0.1f, 0.4f};
    static const double bound[2] = {0.0008, 0.0007};
    gt_env e;
    skgl_camera cam = contact_camera();
    float *ref, *mask;
    int k;
    double scale = gt_res_scale();
    if (!FIGURES) return;
    if (gt_env_init_named(&e, "contact", W, H)) { gt_env_free(&e); return; }
    ref = gt_alloc(&e);
    mask = gt_alloc(&e);
    gt_gbuffer(&e, &cam);
    for (k = 0; k < 2; k++) {
        skgl_area_light l = contact_light(halves[k]);
        skgl_soft_desc pv = soft_desc(SKGL_SOFT_PVSM, (int)(4096 * scale));
        skgl_soft_desc p4 = soft_desc(SKGL_SOFT_PCSS, 4096), p2 = soft_desc(SKGL_SOFT_PCSS, 2048);
        skgl_soft_frame_stats st;
        double e_pv, e_p4, e_p2;
        char name[64];
        gt_area_reference(&e, &l, STRATA, ref);
        if (scale != 1.0) pv.max_tiles = 1;          /* one tile, clamped to the scaled limit */
        snprintf(name, sizeof name, "soft-contact-%d-pvsm", k);
        e_pv = soft_frame(&e, &pv, &cam, &l, ref, mask, &st, name);
        e_p4 = soft_frame(&e, &p4, &cam, &l, ref, mask, NULL, NULL);
        e_p2 = soft_frame(&e, &p2, &cam, &l, ref, mask, NULL, NULL);
        printf("accuracy half %.2f: pvsm %.5f (tiles %d, texels %.0f, lit %.3f) pcss-4096 %.5f pcss-2048 %.5f\n",
               halves[k], e_pv, st.tiles, st.texels, st.lit_fraction, e_p4, e_p2);
        SK_CHECK_MSG(e_pv >= 0.0 && e_pv < e_p4, "half %.2f: PVSM %.5f not below PCSS-4096 %.5f", halves[k], e_pv,
                     e_p4);
        SK_CHECK_MSG(e_pv >= 0.0 && e_pv < bound[k], "half %.2f: PVSM %.5f over %.5f", halves[k], e_pv, bound[k]);
        SK_CHECK_MSG(st.tiles >= 1 && st.lit_fraction > 0.0f && st.lit_fraction < 1.0f, "stats: tiles %d lit %g",
                     st.tiles, st.lit_fraction);
    }
    free(ref);
    free(mask);
    gt_env_free(&e);
}

static int is_box(const gt_env *e, size_t i, double *y) {
    double p[3];
    if (gt_world(e, i, p)) return -1;
    *y = p[1];
    return p[1] > 1e-3 ? 1 : 0;
}

static void test_contact(void) {
    gt_env e;
    skgl_camera cam = contact_camera();
    skgl_area_light l = contact_light(0.4f);
    skgl_soft_desc pv = soft_desc(SKGL_SOFT_PVSM, 0);
    float *ref, *mask;
    unsigned char *contact, *band;
    double sum_b = 0, sum_o = 0;
    size_t nb = 0, no = 0, i;
    int x, y, dx, dy;
    if (!FIGURES) return;
    if (gt_env_init_named(&e, "contact", W, H)) { gt_env_free(&e); return; }
    ref = gt_alloc(&e);
    mask = gt_alloc(&e);
    contact = (unsigned char *)calloc(e.n, 1);
    band = (unsigned char *)calloc(e.n, 1);
    gt_gbuffer(&e, &cam);
    gt_area_reference(&e, &l, STRATA, ref);
    soft_frame(&e, &pv, &cam, &l, ref, mask, NULL, "soft-contact-band");
    /* contact pixels: ground pixels next to a box pixel low on its side */
    for (y = 1; y < H - 1; y++)
        for (x = 1; x < W - 1; x++) {
            size_t c = (size_t)y * W + (size_t)x;
            double yc, yn;
            if (is_box(&e, c, &yc) != 0) continue;
            for (dy = -1; dy <= 1; dy++)
                for (dx = -1; dx <= 1; dx++) {
                    size_t q = (size_t)(y + dy) * W + (size_t)(x + dx);
                    if (is_box(&e, q, &yn) == 1 && yn < 0.05) contact[c] = 1;
                }
        }
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            size_t c = (size_t)y * W + (size_t)x;
            for (dy = -4; dy <= 4 && !band[c]; dy++)
                for (dx = -4; dx <= 4; dx++) {
                    int u = x + dx, v = y + dy;
                    if (u >= 0 && v >= 0 && u < W && v < H && contact[(size_t)v * W + (size_t)u]) { band[c] = 1; break; }
                }
        }
    for (i = 0; i < e.n; i++) {
        double err;
        if (ref[i] < 0.0f) continue;
        err = fabs((double)mask[i] - ref[i]);
        if (band[i]) { sum_b += err; nb++; }
        else if (ref[i] < 0.99f || mask[i] < 0.99f) { sum_o += err; no++; }
    }
    printf("contact: band %.5f over %zu pixels, elsewhere in the shadow %.5f over %zu\n", nb ? sum_b / nb : -1.0, nb,
           no ? sum_o / no : -1.0, no);
    SK_CHECK_MSG(nb > 50 && no > 500, "band %zu, elsewhere %zu pixels", nb, no);
    SK_CHECK_MSG(nb && no && sum_b / nb <= 2.0 * (sum_o / no), "contact band %.5f > 2 x %.5f", sum_b / (double)nb,
                 sum_o / (double)no);
    free(contact);
    free(band);
    free(ref);
    free(mask);
    gt_env_free(&e);
}

/* ground and one pole of side 2 r at the origin, 2 tall */
static int pole_env(gt_env *e, float r) {
    tb_scene s;
    tb_scene_init(&s);
    if (tb_scene_add_ground(&s, "ground", 0, 0, 6, 6, 0, 2, 2) < 0 || tb_scene_add_pole(&s, "pole", 0, 0, 0, r, 2) < 0) {
        tb_scene_free(&s);
        return -1;
    }
    return gt_env_init(e, &s, W, H);
}

static void test_thin_caster(void) {
    gt_env e;
    /* the camera looks down the pole's shadow (light behind the pole, the
       shadow towards +z) from close, so the shadow is pixels wide; the
       view reaches across the ground, so the light's frustum is wide */
    skgl_camera cam = gt_camera(gt_v3(0.0f, 0.25f, 1.6f), gt_v3(0.0f, 0.0f, 0.9f), 0.08f, 0.01f, 60, W, H);
    skgl_area_light l = soft_light(gt_v3(0.0f, 5.0f, -3.0f), gt_v3(0.0f, -1.0f, 0.6f), 0.0001f);
    float *ref, *mask, r = 0.00025f;
    int pass;
    if (!FIGURES) return;
    if (pole_env(&e, r)) { gt_env_free(&e); return; }
    ref = gt_alloc(&e);
    mask = gt_alloc(&e);
    gt_gbuffer(&e, &cam);
    gt_area_reference(&e, &l, STRATA, ref);
    for (pass = 0; pass < 2; pass++) {
        skgl_soft_desc d = soft_desc(SKGL_SOFT_PVSM, 0);
        skgl_soft *s = NULL;
        size_t i, dark = 0, hit = 0;
        double texel;
        d.disable_conservative = pass != 0;
        d.lowres = 16;           /* texels large enough to lose the pole */
        if (skgl_soft_create(e.sk, &d, &s) != SK_OK) { SK_CHECK_MSG(0, "create"); break; }
        if (gt_soft_mask(&e, s, &cam, &l, mask, NULL) != 0) { SK_CHECK_MSG(0, "render"); skgl_soft_destroy(e.sk, s); break; }
        /* the low-res texel at the pole's top, in world units (x axis) */
        {
            sk_vec3 top = sk_mat4_transform_point(s->light_view, gt_v3(0, 2, 0));
            texel = 2.0 / s->desc.lowres / s->p00 * -top.z;
        }
        for (i = 0; i < e.n; i++) {
            if (ref[i] < 0.0f || ref[i] >= 0.5f) continue;
            dark++;
            hit += mask[i] < 0.5f;
        }
        printf("thin caster (conservative %s): pole %.4f wide, low-res texel %.4f; %zu shadowed pixels, %.1f%% found\n",
               pass == 0 ? "on" : "off", 2.0 * r, texel, dark, dark ? 100.0 * (double)hit / (double)dark : 0.0);
        SK_CHECK_MSG(2.0 * r <= 0.1 * texel * 1.05, "pole %.5f not 1/10 of a texel %.5f", 2.0 * r, texel);
        SK_CHECK_MSG(dark > 100, "the reference has %zu shadowed pixels", dark);
        if (pass == 0)
            SK_CHECK_MSG(hit >= dark * 95 / 100, "conservative: %zu of %zu shadowed pixels found", hit, dark);
        else   /* the failing configuration: the pole is lost without conservative rasterisation */
            SK_CHECK_MSG(hit <= dark / 10, "plain rasterisation still found %zu of %zu", hit, dark);
        if (pass == 0) gt_images(&e, "soft-thin-pole", ref, mask);
        skgl_soft_destroy(e.sk, s);
    }
    free(ref);
    free(mask);
    gt_env_free(&e);
}

typedef struct edge_case {
    const char *name;
    skgl_camera cam;
    skgl_area_light light;
    int resolution, max_tiles;
    double bound;            /* MAE bound; hard shadows: % misclassified */
} edge_case;

static void edge_run(gt_env *e, const edge_case *c, float *ref, float *mask, skgl_soft_frame_stats *st, double *err) {
    skgl_soft_desc d = soft_desc(SKGL_SOFT_PVSM, c->resolution);
    char name[64];
    d.max_tiles = c->max_tiles;
    gt_gbuffer(e, &c->cam);
    gt_area_reference(e, &c->light, STRATA, ref);
    snprintf(name, sizeof name, "soft-edge-%s", c->name);
    *err = soft_frame(e, &d, &c->cam, &c->light, ref, mask, st, name);
    SK_CHECK_MSG(e->gl.GetError() == 0, "%s: GL error", c->name);
}

static void test_edges(void) {
    gt_env e;
    float *ref, *mask;
    skgl_soft_frame_stats st;
    double err;
    edge_case c;
    size_t i, lit, covered;
    if (gt_env_init_named(&e, "contact", W, H)) { gt_env_free(&e); return; }
    ref = gt_alloc(&e);
    mask = gt_alloc(&e);

    /* zero-size light: hard shadows, scored as misclassified pixels */
    memset(&c, 0, sizeof c);
    c.name = "hard"; c.cam = contact_camera(); c.light = contact_light(0.0f);
    edge_run(&e, &c, ref, mask, &st, &err);
    err = tb_metric_hard(ref, mask, e.n).pct;
    printf("edge hard: %.3f%% misclassified, %d tiles\n", err, st.tiles);
    SK_CHECK_MSG(err >= 0.0 && err < 0.5, "hard: %.3f%%", err);

    /* a light larger than the receiver (the ground is 10 x 10) */
    c.name = "huge"; c.light = contact_light(8.0f);
    edge_run(&e, &c, ref, mask, &st, &err);
    printf("edge huge light: mae %.5f, %d tiles\n", err, st.tiles);
    /* the blocker search cut at the near plane spans the whole map and
       the planar-blocker model breaks: PCSS-4096 measured 0.161 here too */
    SK_CHECK_MSG(err >= 0.0 && err < 0.2, "huge light: mae %.5f", err);

    /* sub-pixel kernels: a tiny light seen from far */
    c.name = "subpixel";
    c.cam = gt_camera(gt_v3(24.0f, 18.0f, 30.0f), gt_v3(0, 0, 0), 0.5f, 1.0f, 200, W, H);
    c.light = contact_light(0.001f);
    edge_run(&e, &c, ref, mask, &st, &err);
    printf("edge sub-pixel kernels: mae %.5f, %d tiles\n", err, st.tiles);
    SK_CHECK_MSG(err >= 0.0 && err < 0.03, "sub-pixel: mae %.5f", err);

    /* every pixel lit: ground far from the box, light straight above it */
    c.name = "all-lit";
    c.cam = gt_camera(gt_v3(4.0f, 1.0f, 4.0f), gt_v3(4.5f, 0.0f, 3.0f), 0.5f, 0.05f, 60, W, H);
    c.light = soft_light(gt_v3(0.0f, 5.0f, 0.0f), gt_v3(0, -1, 0), 0.2f);
    edge_run(&e, &c, ref, mask, &st, &err);
    for (i = 0, lit = 0, covered = 0; i < e.n; i++)
        if (ref[i] >= 0.0f) { covered++; lit += mask[i] == 1.0f && ref[i] == 1.0f; }
    printf("edge all lit: %zu of %zu covered pixels lit, %d tiles, lit fraction %.3f\n", lit, covered, st.tiles,
           st.lit_fraction);
    SK_CHECK_MSG(covered > 1000 && lit == covered, "all lit: %zu of %zu", lit, covered);
    SK_CHECK_MSG(st.tiles == 0 && st.lit_fraction == 1.0f, "empty SMTG: %d tiles, lit %g", st.tiles, st.lit_fraction);

    /* every pixel in umbra: a small light 45 degrees up on the -x side, the
       camera looking down at the ground in the box's shadow beside its +x
       face (x 1.27 .. 1.53: the umbra reaches x = 2 less a penumbra of a
       few cm), not at the box's own faces, which the exact reference leaves
       out as facing away from the light */
    c.name = "umbra";
    c.cam = gt_camera(gt_v3(1.5f, 0.5f, 0.05f), gt_v3(1.4f, 0.0f, 0.0f), 0.3f, 0.01f, 60, W, H);
    c.light = soft_light(gt_v3(-5.0f, 6.0f, 0.0f), gt_v3(0.70710678f, -0.70710678f, 0), 0.1f);
    edge_run(&e, &c, ref, mask, &st, &err);
    {
        float mx = 0.0f, rmx = 0.0f;
        for (i = 0, covered = 0; i < e.n; i++)
            if (ref[i] >= 0.0f) { covered++; if (mask[i] > mx) mx = mask[i]; if (ref[i] > rmx) rmx = ref[i]; }
        printf("edge umbra: %zu covered pixels, largest visibility %.4f (reference %.4f), mae %.5f\n", covered, mx, rmx,
               err);
        SK_CHECK_MSG(covered > 1000 && rmx == 0.0f && mx < 0.01f, "umbra: largest %g (reference %g)", mx, rmx);
    }

    /* a single tile demanded at the maximum resolution (256, one tile allowed) */
    c.name = "one-tile"; c.cam = contact_camera(); c.light = contact_light(0.05f);
    c.resolution = 256; c.max_tiles = 1;
    edge_run(&e, &c, ref, mask, &st, &err);
    printf("edge one tile at the limit: %d tiles at %d, mae %.5f\n", st.tiles, st.resolution, err);
    /* every demand halved until one tile fits: within a factor 2 of the limit */
    SK_CHECK_MSG(st.tiles == 1 && st.resolution > 128 && st.resolution <= 256, "one tile: %d tiles, resolution %d",
                 st.tiles, st.resolution);
    SK_CHECK_MSG(err >= 0.0 && err < 0.01, "one tile: mae %.5f", err);

    free(ref);
    free(mask);
    gt_env_free(&e);
}

static void test_pyramid(void) {
    gt_env e;
    skgl_camera cam = contact_camera();
    skgl_area_light l = contact_light(0.1f);
    skgl_soft *s;
    float *mask, *pyr, *cpu;
    sk_tile gpu_t[64], cpu_t[64];
    int n, levels, nt, ct, i, same = 1;
    if (gt_env_init_named(&e, "contact", W, H)) { gt_env_free(&e); return; }
    mask = gt_alloc(&e);
    gt_gbuffer(&e, &cam);
    s = gt_soft(&e, SKGL_SOFT_PVSM, 0);
    if (!s || gt_soft_mask(&e, s, &cam, &l, mask, NULL) != 0) { SK_CHECK_MSG(0, "render"); gt_env_free(&e); free(mask); return; }
    n = skgl_soft_pyramid(s, NULL, 0);
    pyr = (float *)malloc(sizeof(float) * (size_t)n);
    cpu = (float *)malloc(sizeof(float) * (size_t)n);
    SK_CHECK(n == sk_smtg_pyramid_size(64, 64));
    SK_CHECK(skgl_soft_pyramid(s, pyr, n) == n);
    levels = sk_smtg_pyramid(pyr, 64, 64, cpu, n);
    SK_CHECK(levels == 7);
    for (i = 0; i < n; i++) same &= pyr[i] == cpu[i];
    SK_CHECK_MSG(same, "the GPU pyramid differs from sk_smtg_pyramid of its level 0");
    nt = skgl_soft_tiles(s, gpu_t, 64);
    ct = sk_fvsm_tiles(pyr, 64, 64, 4096, cpu_t, 64);
    SK_CHECK_MSG(nt >= 1 && nt == ct, "tiles: %d on the GPU path, %d from sk_fvsm_tiles", nt, ct);
    /* the same cells; sides rounded up by at most a step of 2^(1/4) */
    for (i = 0; i < nt && i < ct; i++) {
        SK_CHECK(gpu_t[i].x0 == cpu_t[i].x0 && gpu_t[i].y0 == cpu_t[i].y0 && gpu_t[i].x1 == cpu_t[i].x1 &&
                 gpu_t[i].y1 == cpu_t[i].y1);
        SK_CHECK(gpu_t[i].res_x >= cpu_t[i].res_x && gpu_t[i].res_x <= cpu_t[i].res_x * 1.19 + 1);
        SK_CHECK(gpu_t[i].res_y >= cpu_t[i].res_y && gpu_t[i].res_y <= cpu_t[i].res_y * 1.19 + 1);
    }
    skgl_soft_destroy(e.sk, s);
    free(pyr);
    free(cpu);
    free(mask);
    gt_env_free(&e);
}

static void test_temporal(void) {
    enum { FRAMES = 6 };
    gt_env e;
    skgl_area_light l = contact_light(0.25f);
    float *ref[2], *res[2][2];
    size_t flips[2] = {0, 0}, covered = 0;
    int f, m, k;
    if (!FIGURES) return;
    if (gt_env_init_named(&e, "contact", W, H)) { gt_env_free(&e); return; }
    for (k = 0; k < 2; k++) {
        ref[k] = gt_alloc(&e);
        res[0][k] = gt_alloc(&e);
        res[1][k] = gt_alloc(&e);
    }
    for (f = 0; f < FRAMES; f++) {
        /* the camera moves 1 cm a frame, sideways */
        skgl_camera cam = gt_camera(gt_v3(3.0f + 0.01f * (float)f, 2.2f, 3.6f - 0.006f * (float)f),
                                    gt_v3(-0.6f, 0.2f, -0.4f), 0.9f, 0.05f, 60, W, H);
        int cur = f & 1;
        skgl_soft_desc pv = soft_desc(SKGL_SOFT_PVSM, 0), p4 = soft_desc(SKGL_SOFT_PCSS, 4096);
        gt_gbuffer(&e, &cam);
        gt_area_reference(&e, &l, STRATA, ref[cur]);
        soft_frame(&e, &pv, &cam, &l, ref[cur], res[0][cur], NULL, NULL);
        soft_frame(&e, &p4, &cam, &l, ref[cur], res[1][cur], NULL, NULL);
        if (f == 0) continue;
        for (size_t i = 0; i < e.n; i++) {
            float r0 = ref[cur ^ 1][i], r1 = ref[cur][i];
            if (r0 < 0.0f || r1 < 0.0f || fabsf(r1 - r0) >= 0.02f) continue;
            covered++;
            for (m = 0; m < 2; m++) flips[m] += fabsf(res[m][cur][i] - res[m][cur ^ 1][i]) > 0.1f;
        }
    }
    printf("temporal: flip rate PVSM %.4f%%, PCSS-4096 %.4f%% (%zu pixel pairs)\n", 100.0 * flips[0] / covered,
           100.0 * flips[1] / covered, covered);
    SK_CHECK_MSG(covered > 10000, "pixel pairs %zu", covered);
    /* bound ~2.5x the measured 0.0075% (PCSS-4096: 0.0030%): the flips are
       the few pixels on the box's contact edge, where the kernel shrinks
       to the footprint; the bench compares the methods on larger scenes */
    SK_CHECK_MSG(100.0 * flips[0] / covered < 0.02, "PVSM flip rate %.4f%%", 100.0 * flips[0] / covered);
    for (k = 0; k < 2; k++) { free(ref[k]); free(res[0][k]); free(res[1][k]); }
    gt_env_free(&e);
}

static void test_state(void) {
    gt_env e;
    skgl_camera cam = contact_camera();
    skgl_area_light l = contact_light(0.2f), bad;
    skgl_soft_desc d;
    skgl_soft *s = NULL;
    float *mask;
    skgl_scene sc;
    int objects, t;
    if (gt_env_init_named(&e, "contact", W, H)) { gt_env_free(&e); return; }
    mask = gt_alloc(&e);
    sc = gt_scene(&e);
    gt_gbuffer(&e, &cam);
    objects = skgl_gl_object_count(e.sk);
    /* bad descriptions */
    d = soft_desc(SKGL_SOFT_PVSM, 0); d.grid = 100;
    SK_CHECK(skgl_soft_create(e.sk, &d, &s) == SK_ERR_INVALID_ARG && s == NULL);
    d = soft_desc(SKGL_SOFT_PVSM, 0); d.lowres = 1000;
    SK_CHECK(skgl_soft_create(e.sk, &d, &s) == SK_ERR_INVALID_ARG);
    d = soft_desc((skgl_soft_technique)7, 0);
    SK_CHECK(skgl_soft_create(e.sk, &d, &s) == SK_ERR_INVALID_ARG);
    d = soft_desc(SKGL_SOFT_PCSS, 1 << 20);
    SK_CHECK(skgl_soft_create(e.sk, &d, &s) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_gl_object_count(e.sk) == objects);
    for (t = 0; t < 2; t++) {
        int fb = -1, prog = -1, eq = -1, vp[4] = {0, 0, 0, 0}, unit = -1;
        s = gt_soft(&e, t ? SKGL_SOFT_PVSM : SKGL_SOFT_PCSS, 1024);
        if (!s) break;
        /* bad light, mask, scene behind the light */
        bad = l; bad.position.x = NAN;
        SK_CHECK(skgl_soft_render(e.sk, s, &cam, &sc, &bad, e.gbuf.depth_tex, e.gbuf.color_tex, e.mask.color_tex) ==
                 SK_ERR_INVALID_ARG);
        bad = l; bad.half_width = -1.0f;
        SK_CHECK(skgl_soft_render(e.sk, s, &cam, &sc, &bad, e.gbuf.depth_tex, e.gbuf.color_tex, e.mask.color_tex) ==
                 SK_ERR_INVALID_ARG);
        SK_CHECK(skgl_soft_render(e.sk, s, &cam, &sc, &l, e.gbuf.depth_tex, e.gbuf.color_tex, 0) == SK_ERR_INVALID_ARG);
        bad = l; bad.position = gt_v3(0, -50, 0);
        SK_CHECK(skgl_soft_render(e.sk, s, &cam, &sc, &bad, e.gbuf.depth_tex, e.gbuf.color_tex, e.mask.color_tex) ==
                 SK_ERR_DEGENERATE);
        /* odd state in, the same state out */
        e.gl.BindFramebuffer(0x8D40, e.gbuf.fbo);
        e.gl.Viewport(3, 4, 50, 60);
        e.gl.UseProgram(0);
        e.gl.ActiveTexture(0x84C0 + 2);
        SK_CHECK(gt_soft_mask(&e, s, &cam, &l, mask, NULL) == 0);
        e.gl.GetIntegerv(0x8CA6, &fb);
        e.gl.GetIntegerv(0x0BA2, vp);
        e.gl.GetIntegerv(0x8B8D, &prog);
        e.gl.GetIntegerv(0x8009, &eq);
        e.gl.GetIntegerv(0x84E0, &unit);
        SK_CHECK(fb == (int)e.gbuf.fbo && vp[0] == 3 && vp[1] == 4 && vp[2] == 50 && vp[3] == 60);
        SK_CHECK(prog == 0 && eq == 0x8006 && unit == 0x84C0 + 2);
        SK_CHECK(!e.gl.IsEnabled(0x0BE2) && !e.gl.IsEnabled(0x864F));
        e.gl.BindFramebuffer(0x8D40, 0);
        e.gl.ActiveTexture(0x84C0);
        /* the G-buffer rendered by skgl_soft itself gives the same mask */
        {
            float *own = gt_alloc(&e);
            size_t i, differ = 0;
            SK_CHECK(skgl_soft_render(e.sk, s, &cam, &sc, &l, 0, 0, e.mask.color_tex) == SK_OK);
            tb_gl_read_texture_red(&e.gl, e.mask.color_tex, W, H, own);
            for (i = 0; i < e.n; i++)
                if (e.depth[i] < 1.0f && fabsf(own[i] - mask[i]) > 0.1f) differ++;
            printf("state %s: own G-buffer differs by > 0.1 on %zu pixels\n", t ? "pvsm" : "pcss", differ);
            SK_CHECK_MSG(differ < e.n / 200, "own G-buffer: %zu pixels differ", differ);
            free(own);
        }
        skgl_soft_destroy(e.sk, s);
        SK_CHECK_MSG(skgl_gl_object_count(e.sk) == objects, "objects %d, before %d", skgl_gl_object_count(e.sk),
                     objects);
    }
    free(mask);
    gt_env_free(&e);
}

SK_TEST_MAIN(test_accuracy, test_contact, test_thin_caster, test_edges, test_pyramid, test_temporal, test_state)
