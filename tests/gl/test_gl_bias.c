/* test_gl_bias.c - the two complaints users file most against shadow bias,
   measured apart, for both bias modes (the default receiver plane, and the
   normal offset: slope 2, constant 1, normal offset 1.5 texels) and both
   techniques, against the exact Embree reference:

   ACNE: false shadow on lit surfaces at grazing light. The "contact" scene
   (ground + a 2 m box) lit 80 and 85 degrees from the ground normal; among
   the pixels the reference says are lit and that are more than 3 pixels
   from any reference shadow boundary (so edge aliasing is not counted),
   the share the mask calls shadowed.

   PETER-PANNING: false light next to a contact. The contact scene plus a
   5 cm plank lying on the ground, light 67 degrees from the normal; among
   the ground pixels the reference says are shadowed and that lie within 3
   pixels (screen) of a contact (a side face of the box or the plank less
   than 5 cm above the ground), the share the mask calls lit. The closed box
   barely peter-pans (the map holds its lit face, far above the ground); the
   plank is where a light-leaking gap shows.

   Bounds, set from measurement (400 x 225, maps 1024^2 / PSSM 4 x 1024^2,
   Mesa 22.3 llvmpipe); the can-fail runs use the SB / DB / NB / PB
   environment variables (slope, constant, normal bias and receiver-plane
   tolerance; -1 = none):
     acne, 80 and 85 deg, both techniques, both modes: measured 0 of
       ~64000 lit pixels (0.0000%, as with the previous reference); bound
       0.005%, 3 pixels (previously 0.05%). With no bias at all
       (SB=DB=NB=PB=-1) the normal offset gives 50.0% (80 deg standard:
       32209 of 64439) and the receiver plane 0.0093% (6 pixels), 0.21%,
       17.4% and 26.0%: all eight fail.
     peter-panning near the box: 0 of 282 (0.000%), every case; bound 1%,
       2 pixels (previously 2%). With 4x the default bias (SB=8 DB=4 NB=6)
       3 of 282 (1.06%): fails; with a receiver-plane tolerance of 8
       texels (PB=8) 6 and 4 of 282: fails.
     peter-panning near the plank: receiver plane: standard 1 of 131
       (0.76%), pssm 4 of 131 (3.05%); bound 5% (6 pixels, 1.5x). Normal
       offset: standard 60 of 131 (45.8%), pssm 47 of 131 (35.9%); bound
       65% (1.42x; previously measured, with the old reference, 55 and 42
       of 128: 43.0% and 32.8%). With 4x the default bias (SB=8 DB=4 NB=6)
       81.7% (standard) / 80.2% (pssm), both modes: every plank bound
       fails; with PB=4 the receiver plane's standard case gives 72.5%:
       fails. With no bias: 0%.
   Pictures: out/tests/peter-*.png and -error.png (red = false light). */
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "sk_test.h"
#include "gl_test_util.h"

#define W 400
#define H 225
/* figures in the comment above */
#define ACNE_BOUND_PCT 0.005
#define PETER_BOX_BOUND_PCT 1.0
#define PETER_PLANK_BOUND_PCT 65.0
#define PETER_PLANK_PLANE_BOUND_PCT 5.0

/* the can-fail experiments: bias overrides from the environment (unset:
   default): SB slope, DB constant, NB normal offset, PB receiver-plane
   tolerance (-1 = none) */
static float envf(const char *n, float def) { const char *s = getenv(n); return s && *s ? (float)atof(s) : def; }

static void desc_bias(skgl_shadow_desc *d, skgl_bias mode) {
    d->bias = mode;
    d->slope_bias = envf("SB", 0);
    d->depth_bias = envf("DB", 0);
    d->normal_bias = envf("NB", 0);
    d->plane_bias = envf("PB", 0);
}

static const char *mode_name(skgl_bias m) { return m == SKGL_BIAS_NORMAL_OFFSET ? "normal-offset" : "receiver-plane"; }

static void acne(skgl_technique tech, skgl_bias mode, float angle_deg) {
    gt_env e;
    skgl_shadow_desc d;
    skgl_shadow *s;
    float a = angle_deg * 3.14159265f / 180.0f;
    sk_vec3 light = gt_v3(sinf(a) * 0.8f, -cosf(a), sinf(a) * 0.6f);
    skgl_camera cam = gt_camera(gt_v3(-6, 4, -5), gt_v3(0, 0, 0), 0.9f, 0.3f, 60, W, H);
    float *ref, *res;
    size_t i, lit = 0, fs = 0;
    double pct;
    if (gt_env_init_named(&e, "contact", W, H) != 0) { gt_env_free(&e); return; }
    memset(&d, 0, sizeof d);
    d.technique = tech;
    d.resolution = 1024;
    desc_bias(&d, mode);
    s = gt_shadow(&e, &d);
    ref = gt_alloc(&e); res = gt_alloc(&e);
    SK_CHECK(s && ref && res && gt_gbuffer(&e, &cam) == 0 && gt_reference(&e, light, ref) == 0 &&
             gt_mask(&e, s, &cam, light, res) == 0);
    for (i = 0; i < e.n; i++) {
        if (tb_visibility_class(ref[i]) != 1 || gt_near_boundary(&e, ref, i, 3)) continue;
        lit++;
        if (res[i] < 0.5f) fs++;
    }
    pct = lit ? 100.0 * (double)fs / (double)lit : 100.0;
    printf("acne %s %s, light %g deg: false shadow on %zu of %zu lit pixels away from edges = %.4f%%\n",
           tech == SKGL_PSSM ? "pssm" : "standard", mode_name(mode), angle_deg, fs, lit, pct);
    SK_CHECK(lit > e.n / 2);
    SK_CHECK_MSG(pct < ACNE_BOUND_PCT, "acne %.4f%% >= %.3f%%", pct, ACNE_BOUND_PCT);
    free(ref); free(res);
    skgl_shadow_destroy(e.sk, s);
    gt_env_free(&e);
}

static void peter(skgl_technique tech, skgl_bias mode, double plank_bound) {
    gt_env e;
    skgl_shadow_desc d;
    skgl_shadow *s;
    sk_vec3 light = gt_v3(2, -1, 1.2f);
    skgl_camera cam = gt_camera(gt_v3(6, 4, 7), gt_v3(0, 0.3f, 0), 0.9f, 0.3f, 60, W, H);
    tb_scene sc;
    float *ref, *res;
    unsigned char *contact;
    size_t i, n[2] = {0, 0}, fl[2] = {0, 0};
    int k;
    tb_scene_init(&sc);
    tb_scene_build_contact(&sc);
    tb_scene_add_box(&sc, "plank", gt_v3(-1, 0, 2), gt_v3(1, 0.05f, 3));
    if (gt_env_init(&e, &sc, W, H) != 0) { gt_env_free(&e); return; }
    memset(&d, 0, sizeof d);
    d.technique = tech;
    d.resolution = 1024;
    desc_bias(&d, mode);
    s = gt_shadow(&e, &d);
    ref = gt_alloc(&e); res = gt_alloc(&e);
    contact = (unsigned char *)calloc(e.n, 1);
    SK_CHECK(s && ref && res && contact && gt_gbuffer(&e, &cam) == 0 && gt_reference(&e, light, ref) == 0 &&
             gt_mask(&e, s, &cam, light, res) == 0);
    /* contact pixels: 1 box side, 2 plank side, both < 5 cm above the ground */
    for (i = 0; i < e.n; i++) {
        double p[3];
        if (gt_world(&e, i, p) || p[1] <= 1e-3 || p[1] >= 0.05 || fabsf(e.normals[3 * i + 1]) > 0.5f) continue;
        contact[i] = p[2] > 1.5 ? 2 : 1;
    }
    for (i = 0; i < e.n; i++) {
        double p[3];
        int x0 = (int)(i % W), y0 = (int)(i / W), x, y, near = 0;
        if (gt_world(&e, i, p) || p[1] > 1e-3 || tb_visibility_class(ref[i]) != 0) continue;
        for (y = y0 - 3; y <= y0 + 3; y++)
            for (x = x0 - 3; x <= x0 + 3; x++)
                if (x >= 0 && y >= 0 && x < W && y < H && contact[(size_t)y * W + (size_t)x])
                    near |= contact[(size_t)y * W + (size_t)x];
        for (k = 0; k < 2; k++) {
            if (!(near & (1 << k))) continue;
            n[k]++;
            if (res[i] >= 0.5f) fl[k]++;
        }
    }
    printf("peter-panning %s %s: false light on %zu of %zu shadowed ground pixels near the box (%.3f%%), %zu of %zu near the "
           "plank (%.3f%%)\n", tech == SKGL_PSSM ? "pssm" : "standard", mode_name(mode), fl[0], n[0], n[0] ? 100.0 * fl[0] / n[0] : 0.0,
           fl[1], n[1], n[1] ? 100.0 * fl[1] / n[1] : 0.0);
    SK_CHECK(n[0] > 100 && n[1] > 50);   /* the measured regions exist */
    SK_CHECK_MSG(n[0] && 100.0 * fl[0] / n[0] < PETER_BOX_BOUND_PCT, "box: %zu of %zu", fl[0], n[0]);
    SK_CHECK_MSG(n[1] && 100.0 * fl[1] / n[1] < plank_bound, "plank: %zu of %zu", fl[1], n[1]);
    {
        char name[64];
        snprintf(name, sizeof name, "peter-%s-%s", tech == SKGL_PSSM ? "pssm" : "standard", mode_name(mode));
        gt_images(&e, name, ref, res);
    }
    free(ref); free(res); free(contact);
    skgl_shadow_destroy(e.sk, s);
    gt_env_free(&e);
}

static void test_acne(void) {
    int m;
    for (m = 0; m < 2; m++) {
        skgl_bias mode = m ? SKGL_BIAS_NORMAL_OFFSET : SKGL_BIAS_RECEIVER_PLANE;
        acne(SKGL_STANDARD, mode, 80); acne(SKGL_PSSM, mode, 80);
        acne(SKGL_STANDARD, mode, 85); acne(SKGL_PSSM, mode, 85);
    }
}
static void test_peter(void) {
    peter(SKGL_STANDARD, SKGL_BIAS_RECEIVER_PLANE, PETER_PLANK_PLANE_BOUND_PCT);
    peter(SKGL_PSSM, SKGL_BIAS_RECEIVER_PLANE, PETER_PLANK_PLANE_BOUND_PCT);
    peter(SKGL_STANDARD, SKGL_BIAS_NORMAL_OFFSET, PETER_PLANK_BOUND_PCT);
    peter(SKGL_PSSM, SKGL_BIAS_NORMAL_OFFSET, PETER_PLANK_BOUND_PCT);
}

SK_TEST_MAIN(test_acne, test_peter)
