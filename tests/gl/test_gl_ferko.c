/* test_gl_ferko.c - resolution estimation on the GPU (Ferko 2013)
   through skgl_shadow_analyze + SKGL_FERKO: against the CPU oracle
   sk_estimate_resolution on the same depth buffer, against the Embree
   reference, and at its failure configurations. 400 x 225.

   Measured (Mesa 22.3 llvmpipe, OSMesa):

   test_matches_cpu - maximum 8192, both read-back modes (this frame's
   estimate, and last frame's through the pixel buffer):
       view         GPU          CPU          bounds apart (texels)
       boxes        2355x2192    2353x2192    0.005 x 0.001
       boxes-close  4070x4922    4071x4922    0.005 x 0.002
       terrace      1303x8192    1303x8192    0.001 x 0.312
       fence        8192x5652    8192x5649    0.006 x 0.004
     Asserted: bounds within one texel of the map asked for (extent over
     resolution), width and height within 1% (+1). The 0.3 texel on the
     terrace is its horizon: window depth near 1, where the float light-clip
     position of a sample loses digits the CPU's double keeps (with the
     corners projected absolutely instead of relative to the pixel centre
     the terrace's texel height comes out 3.5% small; clamped here, so the
     test does not see it). Can fail: with the corners at the pixel's own
     depth instead of the average of the pixels sharing them (a local copy
     of ferko_analyze.frag) boxes gives 835x811 against 2353x2192: fails.

   test_against_4096 - FERKO with a 4096 maximum against the focused 4096^2
   map, on the exact reference with the default bias (receiver plane),
   covered % (tb_metric_hard) and shadow-area error (tb_metric_shadow),
   wrong pixels:
       view         ferko (texels)                  4096^2              old (ferko vs 4096)
       boxes        0.0162% 0.758%  9 px (0.31)     0.0144% 0.673% 8    0.0278% vs 0.0156%
       boxes-close  0.0076% 0.213%  5 px (1.00)     0.0076% 0.213% 5    0.0028% vs 0.0112%
       terrace      0.0869% 3.277% 27 px (0.32)     0.1126% 4.248% 35   0.1265% vs 0.1777%
       fence        0.3335% 4.078% 192 px (1.00)    0.3266% 3.993% 188  0.9564% vs 1.0103%
     ((1.00): clamped at the maximum.) Asserted: never more texels than
     the 4096 map, at most NO_WORSE_PX (6) wrong pixels more than it
     (previously +0.1 pp: 60 pixels of a 60000-pixel view), and about
     1.4x: covered under 0.023 / 0.011 / 0.125 / 0.47% (previously 0.05 /
     0.01 / 0.21 / 1.6%), area under 1.07 / 0.30 / 4.6 / 5.7%.
     Can fail: at 1/4 resolution (SK_GL_TEST_RES_SCALE=0.25: maximum
     1024) covered 0.0396, 0.0273, 0.5856, 1.5494%, area 1.85, 0.77, 22.1,
     18.9%: all eight bounds fail; with the normal-offset bias
     (SK_GL_TEST_BIAS=normal-offset) boxes 0.0450% / 2.10%, 7 pixels more
     than the 4096 map (terrace 0.1899%, fence 1.9924%); in a local copy of
     the header rendering half the estimated resolution on each side,
     10, 5, 12 and 228 pixels more than the 4096 map: boxes, terrace and
     fence fail.

   test_failure_cases - empty G-buffer (sky only), every sample outside the
   light frustum (scene bounds away from the view), a 2-pixel object, a
   maximum resolution of 1; sync and late: estimates finite, a 1x1 map when
   nothing is visible in the light, the mask in [0, 1], no GL error. */
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "sk_test.h"
#include "gl_test_util.h"

#include <math.h>

#define W 400
#define H 225

/* analyze + render + mask of one frame; 0 ok */
static int ferko_frame(gt_env *e, skgl_shadow *s, const skgl_camera *cam, const skgl_scene *sc, sk_vec3 light,
                       float *vis) {
    sk_result r = skgl_shadow_analyze(e->sk, s, cam, sc, light, e->gbuf.depth_tex);
    if (r != SK_OK) {
        printf("skgl_shadow_analyze: %s (%s)\n", sk_result_string(r), skgl_error_log(e->sk));
        return -1;
    }
    r = skgl_shadow_render(e->sk, s, cam, sc, light);
    if (r != SK_OK) {
        printf("skgl_shadow_render: %s (%s)\n", sk_result_string(r), skgl_error_log(e->sk));
        return -1;
    }
    return vis ? gt_mask_only(e, s, cam, vis) : 0;
}

typedef struct view_case {
    const char *label, *scene;
    float eye[3], target[3], light[3];
    double max_pct;              /* FERKO's error bounds (test_against_4096): covered % */
    double max_area_pct;         /* and shadow-area error % */
} view_case;

/* bounds about 1.4x the measurement (figures at the top) */
static const view_case views[] = {
    {"boxes", "ground-boxes", {-9, 7, 12}, {0, 1, 0}, {-0.5f, -1, -0.35f}, 0.023, 1.07},
    {"boxes-close", "ground-boxes", {-3, 2.5f, 4}, {0, 0.5f, 0}, {-0.5f, -1, -0.35f}, 0.011, 0.30},
    {"terrace", "terrace", {0, 2, 1}, {0, 0.5f, -30}, {0.7f, -1, 0.4f}, 0.125, 4.6},
    {"fence", "fence", {1, 1.6f, 3.5f}, {0, 0.5f, 0}, {0.3f, -1, 0.6f}, 0.47, 5.7},
};

/* FERKO may misclassify this many pixels more than the focused 4096^2
   map: measured at most 4 (fence) */
#define NO_WORSE_PX 6

static void test_matches_cpu(void) {
    size_t c;
    for (c = 0; c < sizeof views / sizeof views[0]; c++) {
        const view_case *k = &views[c];
        gt_env e;
        skgl_camera cam = gt_camera(gt_v3(k->eye[0], k->eye[1], k->eye[2]),
                                    gt_v3(k->target[0], k->target[1], k->target[2]), 1.0f, 0.1f, 250, W, H);
        sk_vec3 l = gt_v3(k->light[0], k->light[1], k->light[2]);
        skgl_shadow_desc d;
        skgl_shadow *s;
        skgl_scene sc;
        sk_res_estimate cpu;
        const skgl_shadow_frame_stats *st;
        int lat;
        if (gt_env_init_named(&e, k->scene, W, H) != 0) { gt_env_free(&e); continue; }
        sc = gt_scene(&e);
        SK_CHECK(gt_gbuffer(&e, &cam) == 0);
        for (lat = 0; lat < 2; lat++) {
            memset(&d, 0, sizeof d);
            d.technique = SKGL_FERKO;
            d.resolution = 8192;
            d.sync_readback = !lat;   /* both modes: this frame's estimate, and one frame late */
            s = gt_shadow(&e, &d);
            if (!s) continue;
            SK_CHECK(ferko_frame(&e, s, &cam, &sc, l, NULL) == 0);
            if (lat) SK_CHECK(ferko_frame(&e, s, &cam, &sc, l, NULL) == 0);   /* the second frame uses the first's */
            st = skgl_shadow_stats(s);
            SK_CHECK(sk_estimate_resolution(e.depth, W, H, e.inv_vp, st->estimate_light, 8192, &cpu) == SK_OK);
            printf("%-12s %s gpu %dx%d [%.5f,%.5f]x[%.5f,%.5f] texel %.4g x %.4g | cpu %dx%d [%.5f,%.5f]x[%.5f,%.5f] "
                   "texel %.4g x %.4g (%d samples)\n",
                   k->label, lat ? "late" : "sync", st->estimate.width, st->estimate.height, st->estimate.bounds.x0,
                   st->estimate.bounds.x1, st->estimate.bounds.y0, st->estimate.bounds.y1, st->estimate.texel_w,
                   st->estimate.texel_h, cpu.width, cpu.height, cpu.bounds.x0, cpu.bounds.x1, cpu.bounds.y0,
                   cpu.bounds.y1, cpu.texel_w, cpu.texel_h, cpu.samples);
            SK_CHECK(cpu.samples > 0 && st->estimate.samples == 1);
            /* bounds within one texel of the map the estimate asks for (its
               extent over its resolution: the estimated texel, or larger
               where the resolution is clamped), resolution within 1% */
            {
                double tx = (cpu.bounds.x1 - cpu.bounds.x0) / cpu.width, ty = (cpu.bounds.y1 - cpu.bounds.y0) / cpu.height;
                double ex = fabs(st->estimate.bounds.x0 - cpu.bounds.x0), ey = fabs(st->estimate.bounds.y0 - cpu.bounds.y0);
                if (fabs(st->estimate.bounds.x1 - cpu.bounds.x1) > ex) ex = fabs(st->estimate.bounds.x1 - cpu.bounds.x1);
                if (fabs(st->estimate.bounds.y1 - cpu.bounds.y1) > ey) ey = fabs(st->estimate.bounds.y1 - cpu.bounds.y1);
                printf("    bounds differ by %.3f x %.3f texels\n", ex / tx, ey / ty);
                SK_CHECK_MSG(ex <= tx && ey <= ty, "%s: bounds off by %.3f x %.3f texels", k->label, ex / tx, ey / ty);
            }
            SK_CHECK_MSG(fabs((double)(st->estimate.width - cpu.width)) <= 0.01 * cpu.width + 1 &&
                             fabs((double)(st->estimate.height - cpu.height)) <= 0.01 * cpu.height + 1,
                         "%s: %dx%d against %dx%d", k->label, st->estimate.width, st->estimate.height, cpu.width,
                         cpu.height);
            SK_CHECK(e.gl.GetError() == 0);
            skgl_shadow_destroy(e.sk, s);
        }
        gt_env_free(&e);
    }
}

/* against the reference: FERKO with a 4096 maximum next to the focused
   4096^2 map, texels rendered and error */
static void test_against_4096(void) {
    size_t c;
    int below = 0;
    for (c = 0; c < sizeof views / sizeof views[0]; c++) {
        const view_case *k = &views[c];
        gt_env e;
        skgl_camera cam = gt_camera(gt_v3(k->eye[0], k->eye[1], k->eye[2]),
                                    gt_v3(k->target[0], k->target[1], k->target[2]), 1.0f, 0.1f, 250, W, H);
        sk_vec3 l = gt_v3(k->light[0], k->light[1], k->light[2]);
        skgl_shadow_desc d;
        skgl_shadow *sf = NULL, *ss = NULL;
        skgl_scene sc;
        float *ref, *mf, *ms;
        double ef = -1, es = -1, tf = 0, ts = 0;
        tb_shadow_error sef, ses;
        char img[64], buf[256];
        if (gt_env_init_named(&e, k->scene, W, H) != 0) { gt_env_free(&e); continue; }
        sc = gt_scene(&e);
        ref = gt_alloc(&e); mf = gt_alloc(&e); ms = gt_alloc(&e);
        memset(&sef, 0, sizeof sef);
        memset(&ses, 0, sizeof ses);
        memset(&d, 0, sizeof d);
        d.technique = SKGL_FERKO;
        d.resolution = (int)(4096 * gt_res_scale());
        sf = gt_shadow(&e, &d);
        d.technique = SKGL_STANDARD;
        ss = gt_shadow(&e, &d);
        if (sf && ss && ref && mf && ms && gt_gbuffer(&e, &cam) == 0 && gt_reference(&e, l, ref) == 0 &&
            ferko_frame(&e, sf, &cam, &sc, l, mf) == 0 && gt_mask(&e, ss, &cam, l, ms) == 0) {
            ef = tb_metric_hard(ref, mf, e.n).pct;
            sef = gt_shadow_error(&e, ref, mf);
            tf = skgl_shadow_stats(sf)->texels;
            es = tb_metric_hard(ref, ms, e.n).pct;
            ses = gt_shadow_error(&e, ref, ms);
            ts = skgl_shadow_stats(ss)->texels;
            snprintf(img, sizeof img, "ferko-%s", k->label);
            gt_images(&e, img, ref, mf);
        }
        printf("%-12s ferko %.4f%% (%dx%d, %.2f of the texels)  standard-4096 %.4f%% (area %.4f%%, %llu px); ferko %s\n",
               k->label, ef, skgl_shadow_stats(sf)->map_width, skgl_shadow_stats(sf)->map_height,
               ts > 0 ? tf / ts : -1.0, es, ses.area_pct, (unsigned long long)ses.wrong,
               gt_shadow_error_str(&sef, buf, sizeof buf));
        SK_CHECK(ef >= 0 && es >= 0);
        SK_CHECK_MSG(ef < k->max_pct, "%s: ferko %.4f%% >= %.3f%%", k->label, ef, k->max_pct);
        SK_CHECK_MSG(sef.ok && sef.area_pct < k->max_area_pct, "%s: ferko shadow-area error %.4f%% >= %.2f%%", k->label,
                     sef.area_pct, k->max_area_pct);
        SK_CHECK_MSG(sef.wrong <= ses.wrong + NO_WORSE_PX, "%s: ferko %llu pixels wrong (%.4f%%), the 4096 map %llu (%.4f%%)",
                     k->label, (unsigned long long)sef.wrong, ef, (unsigned long long)ses.wrong, es);
        SK_CHECK(tf <= ts);
        below += ts > 0 && tf < 0.5 * ts;
        SK_CHECK(e.gl.GetError() == 0);
        skgl_shadow_destroy(e.sk, sf);
        skgl_shadow_destroy(e.sk, ss);
        free(ref); free(mf); free(ms);
        gt_env_free(&e);
    }
    /* the estimate is respected below the cap where the view needs less:
       measured boxes 2361x2198 (0.31 of the 4096^2 map's texels, 9 wrong
       pixels against its 8) and terrace 1309x4096 (0.32, 27 against 35);
       the close-up and the fence need the cap. (In the open world it needs
       more than 4096: test_gl_open_world counts its frames at the cap.) */
    SK_CHECK_MSG(below >= 2, "FERKO took under half the texels of the 4096^2 map in %d views", below);
}

/* where it fails: an empty G-buffer, every sample outside the light
   frustum, a single visible pixel, max resolution 1; both latency modes */
static void test_failure_cases(void) {
    gt_env e;
    tb_scene scn;
    skgl_scene sc;
    float *ref, *mask;
    int c, lat;
    sk_vec3 l = gt_v3(-0.5f, -1, -0.35f);
    tb_scene_init(&scn);
    tb_scene_add_ground(&scn, "ground", 0, 0, 20, 20, 0, 4, 4);
    tb_scene_add_box(&scn, "box", gt_v3(-1, 0, -1), gt_v3(1, 2, 1));
    tb_scene_add_box(&scn, "speck", gt_v3(60, 30, -200), gt_v3(60.05f, 30.05f, -199.95f));   /* far, tiny */
    if (gt_env_init(&e, &scn, W, H) != 0) { gt_env_free(&e); return; }
    ref = gt_alloc(&e); mask = gt_alloc(&e);
    for (c = 0; c < 4; c++)
        for (lat = 0; lat < 2; lat++) {
            static const char *const names[4] = {"empty", "outside", "one-pixel", "max-res-1"};
            skgl_camera cam;
            skgl_shadow_desc d;
            skgl_shadow *s;
            const skgl_shadow_frame_stats *st;
            size_t i, covered = 0, bad = 0;
            int f;
            sc = gt_scene(&e);
            memset(&d, 0, sizeof d);
            d.technique = SKGL_FERKO;
            d.resolution = c == 3 ? 1 : 2048;
            d.sync_readback = !lat;   /* both modes: this frame's estimate, and one frame late */
            if (c == 0) cam = gt_camera(gt_v3(0, 5, 10), gt_v3(0, 30, 0), 1.0f, 0.1f, 100, W, H);     /* sky */
            else if (c == 2) cam = gt_camera(gt_v3(60.025f, 30.025f, -150), gt_v3(60.025f, 30.025f, -200), 0.2f, 1, 100, W, H);
            else cam = gt_camera(gt_v3(-9, 7, 12), gt_v3(0, 1, 0), 1.0f, 0.1f, 100, W, H);
            if (c == 1) sc.bounds = gt_box(100, 0, 100, 110, 5, 110);   /* the light frustum misses the view */
            s = gt_shadow(&e, &d);
            if (!s || gt_gbuffer(&e, &cam) != 0) { SK_CHECK(0); skgl_shadow_destroy(e.sk, s); continue; }
            for (f = 0; f < 2; f++) SK_CHECK_MSG(ferko_frame(&e, s, &cam, &sc, l, mask) == 0, "%s frame %d", names[c], f);
            st = skgl_shadow_stats(s);
            for (i = 0; i < e.n; i++) {
                if (e.depth[i] < 1.0f) covered++;
                if (!(mask[i] >= 0.0f && mask[i] <= 1.0f) && mask[i] != -1.0f) bad++;
            }
            printf("%-10s %s: covered %zu px, estimate %dx%d (%d samples), map %dx%d, texels %.0f, finite %d\n",
                   names[c], lat ? "late" : "sync", covered, st->estimate.width, st->estimate.height,
                   st->estimate.samples, st->map_width, st->map_height, st->texels,
                   isfinite(st->estimate.texel_w) && isfinite(st->estimate.bounds.x0));
            SK_CHECK_MSG(bad == 0, "%s: %zu mask values outside [0,1]", names[c], bad);
            SK_CHECK(st->map_width >= 1 && st->map_height >= 1 && st->map_width <= d.resolution &&
                     st->map_height <= d.resolution);
            SK_CHECK(isfinite(st->estimate.bounds.x0) && isfinite(st->estimate.bounds.x1) &&
                     isfinite(st->estimate.bounds.y0) && isfinite(st->estimate.bounds.y1));
            if (c == 0) SK_CHECK(covered == 0 && st->estimate.samples == 0 && st->map_width == 1);
            if (c == 1) SK_CHECK(covered > 0 && st->estimate.samples == 0 && st->map_width == 1);
            if (c == 2) SK_CHECK(covered > 0 && covered <= 4 && st->estimate.samples == 1);
            SK_CHECK(e.gl.GetError() == 0);
            skgl_shadow_destroy(e.sk, s);
        }
    free(ref); free(mask);
    gt_env_free(&e);
}

SK_TEST_MAIN(test_matches_cpu, test_against_4096, test_failure_cases)
