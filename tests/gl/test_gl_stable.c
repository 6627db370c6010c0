/* test_gl_stable.c - stable (texel-snapped) crops do not shimmer under
   sub-texel camera translation; unsnapped crops do.

   The camera ("ground-boxes", 400 x 225) slides along a fixed oblique
   direction, 24 frames (23 frame pairs), each step 0.37 of the finer of the
   two maps' texels (so sub-texel for both; over the path the snapped crop
   crosses several texel steps, and the test checks that it moved). The
   same path runs with .stable = 1 and .stable = 0, both techniques, maps
   1024^2, max_distance 45 m (the scene's far corner is 42.5 m away).

   Measurement: every frame's map (fitted to that frame's camera) is applied
   to the SAME world points, those of the first frame's G-buffer, through
   skgl_shadow_mask. The reference of both frames of a pair is then the
   same, and tb_metric_flip(ref, ref, frame k-1, frame k) counts exactly the
   pixels whose shadow changed because the map was refitted: shimmer. (If
   the G-buffer moves too, pixels crossing the thin band where any map's
   edge differs from the true edge flip as well, stable or not; measured
   that way on this path the rates were 0.123% stable vs 0.047% unstable,
   the stable map's texels being larger: that measures edge accuracy.)

   Measured (Mesa 22.3 llvmpipe), default bias (receiver plane), the
   exact reference (its back-facing pixels out of the count), flips /
   covered pixels over the 23 pairs:
     standard: stable 0 (0.0000%), unstable 723 of 1324179 (0.0546%, worst pair 0.1077%)
     pssm:     stable 0 (0.0000%), unstable 194 of 1324179 (0.0147%, worst pair 0.0504%)
   (previously, old reference and normal-offset bias: stable 0, unstable
   655 and 223 of 1382277, 0.0474% / 0.0161%.)
   Asserted: stable < 0.005% over the path (the issue asks < 0.05%) and
   < 0.01% in every pair; unstable strictly higher than stable. The stable
   figures are 0 as before, so the bounds stay.
   Can fail: with the snapping disabled in a local copy of the header
   (stable mode taking the focused branch) stable 0.0546% (worst pair
   0.1077%, standard) and 0.0148% (0.0591%, pssm), unstable 0.0546% and
   0.0147%: the path bound, the pair bound and the comparison all fail.
   Before commit c90830e the standard stable map changed size once on this
   kind of path (its slice ended at a camera-dependent depth): 30 flips in
   one pair (0.05% of that pair), caught by the per-pair bound. */
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "sk_test.h"
#include "gl_test_util.h"

#define W 400
#define H 225
#define FRAMES 24
#define MAX_DISTANCE 45.0f   /* the scene's far corner is 42.5 m away */
#define STEP_TEXELS 0.37f
#define STABLE_MAX_PCT 0.005       /* the issue asks < 0.05%; measured 0 */
#define STABLE_MAX_PAIR_PCT 0.01    /* any single frame pair; measured 0 */

typedef struct path_result {
    double pct, max_pair_pct;
    uint64_t flips, covered;
} path_result;

static skgl_camera cam_at(float t, sk_vec3 dir) {
    sk_vec3 eye = gt_v3(-9 + dir.x * t, 7 + dir.y * t, 12 + dir.z * t);
    sk_vec3 target = gt_v3(dir.x * t, 1 + dir.y * t, dir.z * t);
    return gt_camera(eye, target, 0.9f, 0.5f, 100, W, H);
}

/* world size of one texel of layer 0 of s (after a render) */
static float texel_world(const skgl_shadow *s) {
    sk_mat4 m = skgl_shadow_matrix(s, 0);
    float sx = sqrtf(m.m[0] * m.m[0] + m.m[4] * m.m[4] + m.m[8] * m.m[8]);
    return sx > 0 ? 2.0f / (sx * (float)skgl_shadow_get_desc(s).resolution) : 0;
}

static path_result run_path(gt_env *e, skgl_technique tech, int stable, float step, const float *ref) {
    skgl_shadow_desc d;
    skgl_shadow *s;
    path_result pr;
    float *out[2];
    sk_vec3 light = gt_v3(-0.5f, -1, -0.35f), dir = gt_v3(0.6f, 0.13f, 0.79f);
    skgl_camera cam0 = cam_at(0, dir);
    skgl_scene sc = gt_scene(e);
    sk_mat4 first;
    int f;
    memset(&pr, 0, sizeof pr);
    memset(&d, 0, sizeof d);
    d.technique = tech;
    d.resolution = 1024;
    d.stable = stable;
    d.max_distance = MAX_DISTANCE;
    s = gt_shadow(e, &d);
    out[0] = gt_alloc(e);
    out[1] = gt_alloc(e);
    if (!s || !out[0] || !out[1]) { free(out[0]); free(out[1]); skgl_shadow_destroy(e->sk, s); return pr; }
    for (f = 0; f < FRAMES; f++) {
        skgl_camera cam = cam_at(step * (float)f, dir);
        int k = f & 1;
        sk_result r = skgl_shadow_render(e->sk, s, &cam, &sc, light);
        SK_CHECK_MSG(r == SK_OK, "render: %s", sk_result_string(r));
        if (f == 0) first = skgl_shadow_matrix(s, 0);
        if (f == FRAMES - 1) {
            /* the crop followed the camera (for stable crops: by whole texels) */
            sk_mat4 last = skgl_shadow_matrix(s, 0);
            SK_CHECK_MSG(memcmp(&first, &last, sizeof first) != 0, "the crop did not move");
        }
        SK_CHECK(gt_mask_only(e, s, &cam0, out[k]) == 0);
        if (f > 0) {
            tb_flip_rate fr = tb_metric_flip(ref, ref, out[k ^ 1], out[k], e->n);
            double pair = fr.covered ? 100.0 * (double)fr.flips / (double)fr.covered : 0;
            SK_CHECK(fr.ref_flips == 0);
            pr.flips += fr.flips;
            pr.covered += fr.covered;
            if (pair > pr.max_pair_pct) pr.max_pair_pct = pair;
        }
    }
    pr.pct = pr.covered ? 100.0 * (double)pr.flips / (double)pr.covered : 100.0;
    free(out[0]); free(out[1]);
    skgl_shadow_destroy(e->sk, s);
    return pr;
}

static void test_stable_crops(void) {
    gt_env e;
    float *ref;
    int t;
    sk_vec3 light = gt_v3(-0.5f, -1, -0.35f);
    if (gt_env_init_named(&e, "ground-boxes", W, H) != 0) { gt_env_free(&e); return; }
    ref = gt_alloc(&e);
    {
        /* the G-buffer and reference of the first frame: the fixed world points */
        skgl_camera cam0 = cam_at(0, gt_v3(0.6f, 0.13f, 0.79f));
        SK_CHECK(ref && gt_gbuffer(&e, &cam0) == 0 && gt_reference(&e, light, ref) == 0);
    }
    for (t = 0; t < 2; t++) {
        skgl_technique tech = t ? SKGL_PSSM : SKGL_STANDARD;
        const char *tn = t ? "pssm" : "standard";
        skgl_shadow_desc d;
        skgl_shadow *probe;
        float texel[2] = {0, 0}, step;
        int k;
        path_result st, un;
        /* the finer of the two maps' texels (world units) sets the step */
        for (k = 0; k < 2; k++) {
            memset(&d, 0, sizeof d);
            d.technique = tech;
            d.resolution = 1024;
            d.stable = k;
            d.max_distance = MAX_DISTANCE;
            probe = gt_shadow(&e, &d);
            if (probe) {
                skgl_camera cam0 = cam_at(0, gt_v3(0.6f, 0.13f, 0.79f));
                skgl_scene sc = gt_scene(&e);
                SK_CHECK(skgl_shadow_render(e.sk, probe, &cam0, &sc, light) == SK_OK);
                texel[k] = texel_world(probe);
                skgl_shadow_destroy(e.sk, probe);
            }
            SK_CHECK(texel[k] > 0);
        }
        step = STEP_TEXELS * (texel[0] < texel[1] ? texel[0] : texel[1]);
        st = run_path(&e, tech, 1, step, ref);
        un = run_path(&e, tech, 0, step, ref);
        printf("%s: texel %.4f m (unstable) %.4f m (stable), step %.4f m; flips / covered over %d pairs: stable %llu/%llu = %.4f%% "
               "(worst pair %.4f%%), unstable %llu/%llu = %.4f%% (worst pair %.4f%%)\n", tn, texel[0], texel[1], step,
               FRAMES - 1, (unsigned long long)st.flips, (unsigned long long)st.covered, st.pct, st.max_pair_pct,
               (unsigned long long)un.flips, (unsigned long long)un.covered, un.pct, un.max_pair_pct);
        SK_CHECK(st.covered > (uint64_t)(FRAMES - 1) * (W * H / 2));
        SK_CHECK_MSG(st.pct < STABLE_MAX_PCT, "%s stable: %.4f%% >= %.3f%%", tn, st.pct, STABLE_MAX_PCT);
        SK_CHECK_MSG(st.max_pair_pct < STABLE_MAX_PAIR_PCT, "%s stable, worst pair: %.4f%% >= %.3f%%", tn,
                     st.max_pair_pct, STABLE_MAX_PAIR_PCT);
        SK_CHECK_MSG(un.pct > st.pct, "%s: unstable %.4f%% not above stable %.4f%%", tn, un.pct, st.pct);
    }
    SK_CHECK(e.gl.GetError() == 0);
    free(ref);
    gt_env_free(&e);
}

/* every layer's crop, its width and height in world units (after a render) */
static void crop_sides(const skgl_shadow *s, double *tx) {
    int i;
    for (i = 0; i < 4; i++) {
        sk_mat4 m = skgl_shadow_matrix(s, i);
        double sx = sqrt((double)m.m[0] * m.m[0] + (double)m.m[4] * m.m[4] + (double)m.m[8] * m.m[8]);
        double sy = sqrt((double)m.m[1] * m.m[1] + (double)m.m[5] * m.m[5] + (double)m.m[9] * m.m[9]);
        tx[2 * i] = sx > 0 ? 2.0 / sx : 0;
        tx[2 * i + 1] = sy > 0 ? 2.0 / sy : 0;
    }
}

/* layer i's texel size in world units (along the lookup matrix's x) */
static double layer_texel(const skgl_shadow *s, int i) {
    double sides[8];
    crop_sides(s, sides);
    return sides[2 * i] / (double)skgl_shadow_get_desc(s).resolution;
}

/* A camera turning in place (1 degree a frame, 120 frames) and a camera
   walking 30 m, both over ground-boxes, PSSM 4x1024: in how many frames a
   layer's texel changed size. A stepped stable crop (the default) changes
   only when the view's need crosses a ladder step, or has stayed two steps
   below its size for SKGL__LADDER_SETTLE renders; the sphere fit never;
   an unstable crop nearly every frame. Measured: stepped 14 and 8 frames
   (11 and 9 before crops settled to a need that stays below them), the
   sphere 0 and 0, unstable 119 and 119. */
static void test_stable_turning(void) {
    gt_env e;
    int mode, f, i;
    int resized[3][2];
    static const char *names[3] = {"stable (stepped)", "stable_sphere", "unstable"};
    sk_vec3 light = gt_v3(-0.5f, -1, -0.35f);
    if (gt_env_init_named(&e, "ground-boxes", W, H) != 0) { gt_env_free(&e); return; }
    memset(resized, 0, sizeof resized);
    for (mode = 0; mode < 3; mode++) {
        int path;
        for (path = 0; path < 2; path++) {
            skgl_shadow_desc d;
            skgl_shadow *s;
            skgl_scene sc = gt_scene(&e);
            double prev[SKGL_MAX_CASCADES];
            memset(&d, 0, sizeof d);
            d.technique = SKGL_PSSM;
            d.resolution = 1024;
            d.stable = mode < 2;
            d.stable_sphere = mode == 1;
            s = gt_shadow(&e, &d);
            if (!s) continue;
            for (f = 0; f < 120; f++) {
                float a = 0.0174533f * (float)f, t = 0.25f * (float)f;
                sk_vec3 eye = path ? gt_v3(-12.0f + t, 1.7f, 8.0f) : gt_v3(-9, 4, 12);
                sk_vec3 target = path ? gt_v3(-12.0f + t + 10.0f, 1.2f, 0.0f)
                                      : gt_v3(-9.0f + 12.0f * sinf(a), 2.0f, 12.0f - 12.0f * cosf(a));
                skgl_camera cam = gt_camera(eye, target, 0.9f, 0.5f, 100, W, H);
                int changed = 0;
                SK_CHECK(skgl_shadow_render(e.sk, s, &cam, &sc, light) == SK_OK);
                for (i = 0; i < 4; i++) {
                    double tx = layer_texel(s, i);
                    if (f > 0 && fabs(tx - prev[i]) > 1e-6 * prev[i]) changed = 1;
                    prev[i] = tx;
                }
                resized[mode][path] += changed;
            }
            skgl_shadow_destroy(e.sk, s);
        }
        printf("%-17s frames with a resized layer, of 119: turning %d, walking %d\n", names[mode], resized[mode][0],
               resized[mode][1]);
    }
    SK_CHECK_MSG(resized[1][0] == 0 && resized[1][1] == 0, "sphere fit resized %d, %d", resized[1][0], resized[1][1]);
    SK_CHECK_MSG(resized[2][0] > 100 && resized[2][1] > 100, "unstable resized %d, %d", resized[2][0], resized[2][1]);
    SK_CHECK_MSG(resized[0][0] <= 15 && resized[0][1] <= 15, "stepped resized %d, %d", resized[0][0], resized[0][1]);
    gt_env_free(&e);
}

static skgl_camera settle_cam(float t) {
    /* t = 0: an overview; t = 1: at head height, looking along the ground */
    sk_vec3 eye = gt_v3(-9.0f + 3.0f * t, 12.0f - 10.3f * t, 14.0f - 8.0f * t);
    sk_vec3 target = gt_v3(4.0f * t, 1.2f * t, -2.0f * t);
    return gt_camera(eye, target, 0.9f, 0.5f, 100, W, H);
}

/* A stepped stable crop keeps its size while the view's need wavers below
   it, but not for good. Two ways the need falls, PSSM 4x1024 stable over
   ground-boxes, from an overview to head height:
   - a camera cut (one render at each view): every crop afresh, the same
     as a new light's at the second view;
   - a slow descent (100 renders) then 62 still renders (more than
     SKGL__LADDER_SETTLE, 60): every crop within one ladder step (9%) of a new light's,
     and at most three of the still renders resizing a crop (measured 2:
     the shadow range's end settles, then the crops).
   Without either rule the crops stayed up to six steps (1.68x) larger
   than the new view needs (figures printed). */
static void test_stable_settles(void) {
    gt_env e;
    skgl_shadow_desc d;
    skgl_shadow *s, *fresh;
    skgl_scene sc;
    sk_vec3 light = gt_v3(-0.5f, -1, -0.35f);
    double want[8], got[8], prev[8], worst_cut = 0, worst_drift = 0;
    skgl_camera a = settle_cam(0), b = settle_cam(1);
    int f, i, resizes = 0;
    if (gt_env_init_named(&e, "ground-boxes", W, H) != 0) { gt_env_free(&e); return; }
    sc = gt_scene(&e);
    memset(&d, 0, sizeof d);
    d.technique = SKGL_PSSM;
    d.resolution = 1024;
    d.stable = 1;
    fresh = gt_shadow(&e, &d);
    s = gt_shadow(&e, &d);
    if (!fresh || !s) { skgl_shadow_destroy(e.sk, fresh); skgl_shadow_destroy(e.sk, s); gt_env_free(&e); return; }
    SK_CHECK(skgl_shadow_render(e.sk, fresh, &b, &sc, light) == SK_OK);
    crop_sides(fresh, want);
    /* the cut */
    SK_CHECK(skgl_shadow_render(e.sk, s, &a, &sc, light) == SK_OK);
    crop_sides(s, prev);
    SK_CHECK(skgl_shadow_render(e.sk, s, &b, &sc, light) == SK_OK);
    crop_sides(s, got);
    for (i = 0; i < 8; i++) {
        double q = got[i] / want[i];
        if (q > worst_cut) worst_cut = q;
        SK_CHECK_MSG(fabs(q - 1.0) < 1e-6, "after a cut, layer %d axis %d: crop side %.5f m, a new light's %.5f m (%.3fx; "
                     "the overview's %.5f m)", i / 2, i & 1, got[i], want[i], q, prev[i]);
    }
    skgl_shadow_destroy(e.sk, s);
    /* the descent, then still */
    s = gt_shadow(&e, &d);
    if (!s) { skgl_shadow_destroy(e.sk, fresh); gt_env_free(&e); return; }
    for (f = 0; f <= 100 + 61; f++) {
        skgl_camera c = settle_cam(f < 100 ? (float)f / 100.0f : 1.0f);
        SK_CHECK(skgl_shadow_render(e.sk, s, &c, &sc, light) == SK_OK);
        crop_sides(s, got);
        if (f > 100) {
            int changed = 0;
            for (i = 0; i < 8; i++) changed |= fabs(got[i] - prev[i]) > 1e-6 * prev[i];
            resizes += changed;
        }
        memcpy(prev, got, sizeof prev);
    }
    for (i = 0; i < 8; i++) {
        double q = got[i] / want[i];
        if (q > worst_drift) worst_drift = q;
        SK_CHECK_MSG(q < 1.0906 && q > 0.999999, "after the descent, layer %d axis %d: crop side %.5f m, a new light's "
                     "%.5f m (%.3fx)", i / 2, i & 1, got[i], want[i], q);
    }
    printf("stepped crops against a new light's at head height: after a cut %.3fx, after a slow descent %.3fx "
           "(%d renders resized a crop while still)\n", worst_cut, worst_drift, resizes);
    SK_CHECK_MSG(resizes <= 3, "%d of 62 still renders resized a crop", resizes);
    skgl_shadow_destroy(e.sk, s);
    skgl_shadow_destroy(e.sk, fresh);
    gt_env_free(&e);
}

SK_TEST_MAIN(test_stable_crops, test_stable_turning, test_stable_settles)
