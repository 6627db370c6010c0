/* test_gl_bias_cf.c - the two bias schemes of shadowkit_gl.h, measured on
   the closed-form scenes (tb_closed_form.h) against their exact truth,
   400 x 225 on OSMesa: the default SKGL_BIAS_RECEIVER_PLANE and the classic
   SKGL_BIAS_NORMAL_OFFSET (1.5 texels).

   Scenes "plate" (a 2 x 2 square 1 above the ground), "pole" and "box"; a
   sun at elevations 80, 45, 20 and 8 degrees, each at azimuths 30, 150 and
   260, seen by gt_cf_sun_camera; point lights above and beside each caster.
   Directional techniques at default settings with 2048^2 maps (PSSM
   4 x 2048^2): standard, pssm, psm, lispsm, lspsm; point lights: the cube
   map and VSDCT at 512^2 faces. Each mask is scored against the closed form
   (the pixels the exact reference leaves out as silhouettes left out too)
   with tb_metric_shadow; printed per technique and elevation, old scheme
   against new:
   - the shadow-area error (misclassified / shadow pixels, %);
   - "open" false shadow: false-shadow pixels more than 1 px from the exact
     edge (no truth pixel of the other class in their 5 x 5, see
     gt_open_false_shadow), i.e. acne;
   - the plate at 8 degrees, standard 2048^2: misclassified ground pixels,
     % of the ground pixels.

   Asserted, for the default scheme (set from the measurements below):
   - no open false shadow anywhere, in any configuration (0 pixels);
   - the plate at 8 degrees, standard 2048^2: at most PLATE8_GROUND_PCT of
     the ground pixels wrong;
   - every technique's pooled shadow-area error at least 2x lower than with
     the normal offset (pooled over scenes, elevations and azimuths);
   - contact shadows no worse: per scene (box and pole stand on the ground)
     the pooled shadow-area error of every technique no higher than with
     the normal offset;
   - point lights: no open false shadow, and the pooled error no higher
     than with the normal offset.
   The normal offset's own figures are printed, not asserted: it is the
   baseline the goals are measured against.

   Measured (Mesa 22.3 llvmpipe, OSMesa; shadow-area error %, normal offset
   -> receiver plane, pooled over the three scenes and azimuths):
                 80 deg        45 deg        20 deg        8 deg         pooled
     standard   1.78 -> 1.64  4.41 -> 1.22  8.09 -> 1.16  12.19 -> 1.15  7.09 -> 1.27 (5.6x)
     pssm       0.37 -> 0.37  1.28 -> 0.37  2.81 -> 0.54   5.73 -> 0.64  2.78 -> 0.49 (5.6x)
     psm        1.40 -> 0.98  3.80 -> 0.71  5.98 -> 0.72   9.33 -> 0.92  5.48 -> 0.83 (6.6x)
     lispsm     0.57 -> 0.41  2.48 -> 0.46  4.57 -> 0.66   7.48 -> 0.95  4.08 -> 0.65 (6.3x)
     lspsm      0.22 -> 0.11  3.17 -> 0.66  3.01 -> 0.32   6.39 -> 0.89  3.44 -> 0.52 (6.6x)
   open false shadow with the normal offset: 0 at 80-20 degrees, at 8
   degrees 67 (standard), 18 (psm), 2 (lispsm), 1 (lspsm); with the receiver
   plane 0 everywhere. Per scene (contact: pole, box) standard 8.32 -> 6.49
   and 4.35 -> 0.89, every technique lower. The plate at 8 degrees,
   standard 2048^2: 0.328% -> 0.010% of 227,110 ground pixels. Point
   lights, both storages: 4.48% -> 0.36% of 16,268 shadow pixels, no open
   false shadow with either. About 35 s.

   CAN FAIL (record): with the receiver plane's slope forced to zero in
   shadow_sample.glsl (sk_plane_slope returning vec2(0.0)), the vertical
   faces the 80-degree sun grazes get acne: 12 checks fail (box, sun 80/30,
   standard: 63 open false-shadow pixels; pole 80/30 standard 8; box 80/30
   pssm 17), and standard's pooled error rises from 1.27% to 1.64%. */
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "sk_test.h"
#include "gl_test_util.h"

#define W 400
#define H 225
#define N_ELEV 4
#define N_AZIM 3
#define N_TECH 5
#define N_SCENE 3
#define N_POINT 2

/* Measured with the receiver plane: 0.010% of the plate's ground pixels at
   8 degrees (normal offset: 0.328%); bound 5x the measurement (the issue's
   goal was 0.35%). */
#define PLATE8_GROUND_PCT 0.05
/* the normal offset's pooled error over the receiver plane's, at least */
#define POOLED_RATIO_MIN 2.0

static const double elevations[N_ELEV] = {80, 45, 20, 8};
static const double azimuths[N_AZIM] = {30, 150, 260};
static const skgl_technique techs[N_TECH] = {SKGL_STANDARD, SKGL_PSSM, SKGL_PSM, SKGL_LISPSM, SKGL_LSPSM};
static const char *const tech_names[N_TECH] = {"standard", "pssm", "psm", "lispsm", "lspsm"};
static const char *const scene_names[N_SCENE] = {"plate", "pole", "box"};
static const float scene_heights[N_SCENE] = {1.0f, 3.0f, 1.5f};
static const skgl_point_technique point_techs[N_POINT] = {SKGL_POINT_CUBE, SKGL_POINT_VSDCT};
static const char *const point_names[N_POINT] = {"cube", "vsdct"};

/* accumulated misclassifications over the reference's shadow pixels */
typedef struct tally {
    uint64_t wrong, shadow, open_fs;
} tally;

static void tally_add(tally *t, const tb_shadow_error *e, uint64_t open_fs) {
    t->wrong += e->wrong;
    t->shadow += e->shadow;
    t->open_fs += open_fs;
}

static double tally_pct(const tally *t) { return t->shadow ? 100.0 * (double)t->wrong / (double)t->shadow : 0.0; }

typedef struct totals {
    tally dir[2][N_TECH][N_ELEV];      /* [mode][technique][elevation] */
    tally dir_scene[2][N_TECH][N_SCENE];
    tally point[2][N_POINT];
    uint64_t plate8_wrong[2], plate8_ground[2];
} totals;

/* the open false-shadow pixels of res (gt_open_false_shadow) */
static uint64_t open_false_shadow(const gt_env *e, const float *truth, const float *res) {
    uint64_t n = 0;
    size_t i;
    for (i = 0; i < e->n; i++) n += gt_open_false_shadow(e, truth, res, i);
    return n;
}

static void run_scene(int sc, totals *T) {
    gt_env e;
    tb_cf_scene cf;
    skgl_shadow *sh[2][N_TECH];
    skgl_point *pt[2][N_POINT];
    float *ref, *truth, *res;
    int m, t, i, a, k;
    memset(sh, 0, sizeof sh);
    memset(pt, 0, sizeof pt);
    if (gt_env_init_cf(&e, &cf, scene_names[sc], W, H) != 0) { gt_env_free(&e); return; }
    ref = gt_alloc(&e); truth = gt_alloc(&e); res = gt_alloc(&e);
    for (m = 0; m < 2; m++) {
        for (t = 0; t < N_TECH; t++) {
            skgl_shadow_desc d;
            memset(&d, 0, sizeof d);
            d.technique = techs[t];
            d.resolution = 2048;
            d.bias = m ? SKGL_BIAS_NORMAL_OFFSET : SKGL_BIAS_RECEIVER_PLANE;
            sh[m][t] = gt_shadow(&e, &d);
        }
        for (k = 0; k < N_POINT; k++) {
            skgl_point_desc d;
            memset(&d, 0, sizeof d);
            d.technique = point_techs[k];
            d.range = 20;
            d.bias = m ? SKGL_BIAS_NORMAL_OFFSET : SKGL_BIAS_RECEIVER_PLANE;
            SK_CHECK(skgl_point_create(e.sk, &d, &pt[m][k]) == SK_OK);
        }
    }
    if (!ref || !truth || !res) { SK_CHECK_MSG(0, "%s: out of memory", scene_names[sc]); goto done; }
    for (i = 0; i < N_ELEV; i++)
        for (a = 0; a < N_AZIM; a++) {
            sk_vec3 dir;
            skgl_camera cam;
            if (gt_cf_sun_frame(&e, &cf, scene_heights[sc], elevations[i], azimuths[a], ref, truth, &dir, &cam) != 0)
                continue;
            for (m = 0; m < 2; m++)
                for (t = 0; t < N_TECH; t++) {
                    tb_shadow_error se;
                    uint64_t ofs;
                    if (!sh[m][t] || gt_mask(&e, sh[m][t], &cam, dir, res) != 0) {
                        SK_CHECK_MSG(0, "%s %s: mask", scene_names[sc], tech_names[t]);
                        continue;
                    }
                    se = tb_metric_shadow(truth, res, W, H);
                    ofs = open_false_shadow(&e, truth, res);
                    tally_add(&T->dir[m][t][i], &se, ofs);
                    tally_add(&T->dir_scene[m][t][sc], &se, ofs);
                    if (m == 0)
                        SK_CHECK_MSG(ofs == 0, "%s sun %g/%g %s: %llu open false-shadow pixels", scene_names[sc],
                                     elevations[i], azimuths[a], tech_names[t], (unsigned long long)ofs);
                    if (sc == 0 && i == N_ELEV - 1 && t == 0) {
                        /* the plate at 8 degrees: wrong ground pixels over ground pixels */
                        size_t p;
                        for (p = 0; p < e.n; p++) {
                            double w[3];
                            if (!(truth[p] >= 0) || gt_world(&e, p, w) || fabs(w[1]) > 1e-3) continue;
                            T->plate8_ground[m]++;
                            T->plate8_wrong[m] += (truth[p] >= 0.5f) != (res[p] >= 0.5f);
                        }
                        if (a == 2) {
                            char name[64];
                            snprintf(name, sizeof name, "bias-cf-plate-8-%s", m ? "normal" : "plane");
                            gt_images(&e, name, truth, res);
                        }
                    }
                }
        }
    /* point lights above and beside the caster, one camera */
    {
        skgl_camera cam = gt_camera(gt_v3(4.5f, 4, 6), gt_v3(0, 0.5f, 0), 0.9f, 0.1f, 120, W, H);
        sk_vec3 pos[2];
        skgl_scene scn = gt_scene(&e);
        pos[0] = gt_v3(0.25f, scene_heights[sc] + 2.0f, 0.125f);
        pos[1] = gt_v3(3, scene_heights[sc] + 1.0f, -1);
        if (gt_gbuffer(&e, &cam) != 0) { SK_CHECK_MSG(0, "%s: G-buffer", scene_names[sc]); goto done; }
        for (a = 0; a < 2; a++) {
            tb_light l;
            memset(&l, 0, sizeof l);
            l.type = TB_LIGHT_POINT;
            l.position = pos[a];
            l.range = 20;
            if (gt_cf_truth(&e, &cf, &l, ref, truth) != 0) { SK_CHECK_MSG(0, "point truth"); continue; }
            for (m = 0; m < 2; m++)
                for (k = 0; k < N_POINT; k++) {
                    tb_shadow_error se;
                    uint64_t ofs;
                    size_t p;
                    if (!pt[m][k] || skgl_point_render(e.sk, pt[m][k], &cam, &scn, pos[a]) != SK_OK ||
                        skgl_point_mask(e.sk, pt[m][k], &cam, e.gbuf.depth_tex, e.gbuf.color_tex,
                                        e.mask.color_tex) != SK_OK ||
                        tb_gl_read_texture_red(&e.gl, e.mask.color_tex, W, H, res) != 0) {
                        SK_CHECK_MSG(0, "%s %s: point mask (%s)", scene_names[sc], point_names[k], skgl_error_log(e.sk));
                        continue;
                    }
                    for (p = 0; p < e.n; p++)
                        if (!(e.depth[p] < 1.0f)) res[p] = -1.0f;
                    se = tb_metric_shadow(truth, res, W, H);
                    ofs = open_false_shadow(&e, truth, res);
                    tally_add(&T->point[m][k], &se, ofs);
                    if (m == 0)
                        SK_CHECK_MSG(ofs == 0, "%s point %d %s: %llu open false-shadow pixels", scene_names[sc], a,
                                     point_names[k], (unsigned long long)ofs);
                }
        }
    }
    SK_CHECK(e.gl.GetError() == 0);
done:
    for (m = 0; m < 2; m++) {
        for (t = 0; t < N_TECH; t++) skgl_shadow_destroy(e.sk, sh[m][t]);
        for (k = 0; k < N_POINT; k++) skgl_point_destroy(e.sk, pt[m][k]);
    }
    free(ref); free(truth); free(res);
    gt_env_free(&e);
}

static void test_bias_closed_form(void) {
    static totals T;
    int t, i, sc, k;
    memset(&T, 0, sizeof T);
    for (sc = 0; sc < N_SCENE; sc++) run_scene(sc, &T);
    printf("shadow-area error %% against the closed form, normal offset -> receiver plane (open false-shadow px)\n");
    printf("%-9s", "");
    for (i = 0; i < N_ELEV; i++) printf("  %18g deg", elevations[i]);
    printf("  %18s\n", "pooled");
    for (t = 0; t < N_TECH; t++) {
        tally pooled[2];
        int m;
        memset(pooled, 0, sizeof pooled);
        printf("%-9s", tech_names[t]);
        for (i = 0; i < N_ELEV; i++) {
            for (m = 0; m < 2; m++) {
                pooled[m].wrong += T.dir[m][t][i].wrong;
                pooled[m].shadow += T.dir[m][t][i].shadow;
                pooled[m].open_fs += T.dir[m][t][i].open_fs;
            }
            printf("  %6.2f (%4llu) -> %5.2f", tally_pct(&T.dir[1][t][i]), (unsigned long long)T.dir[1][t][i].open_fs,
                   tally_pct(&T.dir[0][t][i]));
        }
        printf("  %6.2f -> %5.2f (%.1fx)\n", tally_pct(&pooled[1]), tally_pct(&pooled[0]),
               tally_pct(&pooled[0]) > 0 ? tally_pct(&pooled[1]) / tally_pct(&pooled[0]) : 0.0);
        SK_CHECK_MSG(pooled[0].shadow > 10000, "%s: %llu shadow pixels", tech_names[t],
                     (unsigned long long)pooled[0].shadow);
        SK_CHECK_MSG(tally_pct(&pooled[1]) >= POOLED_RATIO_MIN * tally_pct(&pooled[0]),
                     "%s: pooled %.3f%% with the receiver plane, not %gx below the normal offset's %.3f%%",
                     tech_names[t], tally_pct(&pooled[0]), POOLED_RATIO_MIN, tally_pct(&pooled[1]));
        for (sc = 1; sc < N_SCENE; sc++)
            SK_CHECK_MSG(tally_pct(&T.dir_scene[0][t][sc]) <= tally_pct(&T.dir_scene[1][t][sc]),
                         "%s on %s (contact): %.3f%% with the receiver plane > %.3f%% with the normal offset",
                         tech_names[t], scene_names[sc], tally_pct(&T.dir_scene[0][t][sc]),
                         tally_pct(&T.dir_scene[1][t][sc]));
    }
    printf("per scene, pooled:");
    for (sc = 0; sc < N_SCENE; sc++) {
        printf("  %s", scene_names[sc]);
        for (t = 0; t < N_TECH; t++)
            printf(" %s %.2f->%.2f", tech_names[t], tally_pct(&T.dir_scene[1][t][sc]), tally_pct(&T.dir_scene[0][t][sc]));
        printf("\n                  ");
    }
    printf("\nplate at 8 deg, standard 2048^2: %.3f%% -> %.3f%% of %llu ground pixels wrong\n",
           T.plate8_ground[1] ? 100.0 * (double)T.plate8_wrong[1] / (double)T.plate8_ground[1] : 0.0,
           T.plate8_ground[0] ? 100.0 * (double)T.plate8_wrong[0] / (double)T.plate8_ground[0] : 0.0,
           (unsigned long long)T.plate8_ground[0]);
    SK_CHECK(T.plate8_ground[0] > 50000);
    SK_CHECK_MSG(100.0 * (double)T.plate8_wrong[0] / (double)(T.plate8_ground[0] ? T.plate8_ground[0] : 1) <=
                     PLATE8_GROUND_PCT,
                 "plate at 8 deg: %llu of %llu ground pixels wrong", (unsigned long long)T.plate8_wrong[0],
                 (unsigned long long)T.plate8_ground[0]);
    for (k = 0; k < N_POINT; k++) {
        printf("point %-5s: %.2f%% (%llu open) -> %.2f%% (%llu open) of %llu shadow pixels\n", point_names[k],
               tally_pct(&T.point[1][k]), (unsigned long long)T.point[1][k].open_fs, tally_pct(&T.point[0][k]),
               (unsigned long long)T.point[0][k].open_fs, (unsigned long long)T.point[0][k].shadow);
        SK_CHECK(T.point[0][k].shadow > 5000);
        SK_CHECK_MSG(tally_pct(&T.point[0][k]) <= tally_pct(&T.point[1][k]), "point %s: %.3f%% > %.3f%%",
                     point_names[k], tally_pct(&T.point[0][k]), tally_pct(&T.point[1][k]));
    }
}

SK_TEST_MAIN(test_bias_closed_form)
