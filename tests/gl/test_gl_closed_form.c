/* test_gl_closed_form.c - the exact reference (tb_reference_trace_exact)
   against closed-form truth (tb_closed_form.h), 400 x 225 on OSMesa.

   Scenes "plate", "pole" and "box" on a ground plane; lights: a sun at elevations 80, 45, 20 and 8 degrees, each at
   azimuths 30, 150 and 260 degrees, a point light above the object and one
   beside it (range-limited, so some ground is out of range), and for the
   plate a square area light parallel to it. Per configuration the G-buffer
   is rendered, the exact reference traced with the G-buffer's raster depth,
   the closed form computed, and asserted:
   - agreement: of the pixels both cover (>= 0), the share whose lit /
     shadowed class agrees is at least 99.998% (per configuration and
     pooled); and of the pixels the reference does not leave out as
     silhouettes, the share whose code agrees (covered, background,
     back-facing, out of range) is at least 99.998%;
   - silhouettes: TB_VIS_SILHOUETTE pixels under 1% of the image;
   - area light: pixels the closed form puts in umbra or full light (0 or 1)
     agree exactly on 99.998%; inside the penumbra the mean |reference -
     closed form| stays under AREA_MAE_BOUND, and the reference's own noise
     (mean |difference| of two seeds / sqrt 2) under AREA_NOISE_BOUND.

   Each sun gets a camera that looks at the caster and its whole shadow
   (shadows are long at 8 degrees); the point and area lights one fixed
   camera per scene.

   Measured (Mesa 22.3 llvmpipe, OSMesa, 400 x 225):
   - exact reference vs closed form: 0 of 3,126,629 pooled pixels differ
     (100%), in every one of the 42 hard configurations; codes 0 of
     3,779,980 differ; silhouette exclusions 0.0005% pooled, at most 2
     pixels (0.002%) a configuration. The bound 99.998% is the issue's
     target: it allows 1 pixel in about 50,000.
   - legacy reference vs closed form, % of pixels covered in both that
     differ, pooled per elevation 80 / 45 / 20 / 8 degrees:
         0.0025  0.0151  0.0285  0.0413
     (plate alone up to 0.14% at 8 degrees; point lights up to 0.13%).
   - area light (half side 0.5, 3 above the ground, 24 x 24 samples):
     3281 penumbra pixels, noise 0.00261, mean |reference - closed form|
     0.00267; umbra and full light: 0 of 86,719 pixels differ. Bounds
     AREA_NOISE_BOUND and AREA_MAE_BOUND 0.004 (the target for the noise).
   - run time: about 13 s on an unloaded 2-core machine (test_hard 7 s,
     test_area 6 s, of which 4 s trace the area light on one thread to
     check that the result does not depend on the thread count).

   CAN FAIL (the runs are part of the record):
   - SK_GL_TEST_CF_OLD=1 ./build/gl/test_gl_closed_form asserts the class
     agreement with the legacy reference in place of the exact one: 722 of
     3,126,632 pooled pixels differ (99.97691% < 99.998%), 26 of the 42
     configurations fail (e.g. plate, sun 8/260: 109 of 76,887, 99.8582%),
     and the pooled check fails: 27 failed checks.
   - SK_GL_TEST_CF_STRATA=16 (the legacy default) puts the area light's noise
     at 0.00469 and its mean error at 0.00477: both checks fail (20: 0.00343
     and 0.00354, passing narrowly; hence the default 24).

   Spot lights (test_spot; skgl_spot_render + skgl_point_mask, map 1024^2,
   range 30) against tb_cf_spot_visibility, the point light's closed form
   cut by the cone, so both the cast shadow's edge and the cone's are exact:
   - "spot-plate": 3 above the plate scene's ground, axis (0.2, -1, 0.1),
     50 degrees: the plate's shadow and the cone's ellipse on the ground;
   - "spot-grazing": 0.35 above the box scene's ground, 2 degrees down past
     the box, 30 degrees: the ground lit at 1 to 10 degrees.
   Edge error: each pixel both cover whose lit / shadowed class differs
   from the closed form, its distance to the nearest pixel of the other
   exact class (the exact edge; searched within SPOT_SEARCH_PX).
   Measured (Mesa llvmpipe, 400 x 225): plate 3 wrong of 71,198 judged,
   grazing 9 of 69,054; every one 1.00 px from the exact edge (mean and max
   1.00 px, none farther). Maps 512^2: 15 and 11; 256^2: 28 and 57, still
   at 1 px (the window fitted to what the view sees). Bounds: edge error
   SPOT_EDGE_MAX_PX 1.5 (a wrong pixel must touch the exact edge), none
   farther (SPOT_FAR_MAX 0), at most SPOT_WRONG_MAX 20 wrong (2x the worst
   measured at 1024^2; SK_GL_TEST_CF_SPOT_RES=n sets the map side: 256
   fails it). 0.6 s.
   CAN FAIL: MA taken as the major axis (the point light's) in the spot's
   sk_point_ma_of: plate 12,666 wrong, edge error max 17 px (the search's
   end), mean 12.6 px, 11,955 farther than 1.5 px; grazing 720 wrong, max
   17 px: all three spot checks fail in both.

   Techniques (printed, not asserted): SKGL_STANDARD, SKGL_PSSM, SKGL_PSM,
   SKGL_LISPSM and SKGL_LSPSM at default settings, maps 2048^2 (PSSM
   4 x 2048^2), scored with tb_metric_hard against the exact reference and
   against the closed form (pooled over scenes and azimuths, per elevation).
   Against the closed form, pixels the reference leaves out as silhouettes
   are left out too (the mask has no receiver there when the raster saw
   background). Pictures: out/tests/cf-*.png. */
#if !defined(_POSIX_C_SOURCE) || _POSIX_C_SOURCE < 199309L
#undef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 199309L   /* clock_gettime */
#endif
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "sk_test.h"
#include "gl_test_util.h"

#include <time.h>

#define W 400
#define H 225
#define N_ELEV 4
#define N_AZIM 3
#define N_TECH 5

#define AGREE_MIN_PCT 99.998
#define SILHOUETTE_MAX_PCT 1.0
#define AREA_MAE_BOUND 0.004
#define AREA_NOISE_BOUND 0.004
#define SPOT_RANGE 30.0f
#define SPOT_SEARCH_PX 16
#define SPOT_NEAR_PX 1.5
#define SPOT_EDGE_MAX_PX 1.5
#define SPOT_FAR_MAX 0
#define SPOT_WRONG_MAX 20

static const double elevations[N_ELEV] = {80, 45, 20, 8};
static const double azimuths[N_AZIM] = {30, 150, 260};
static const skgl_technique techs[N_TECH] = {SKGL_STANDARD, SKGL_PSSM, SKGL_PSM, SKGL_LISPSM, SKGL_LSPSM};
static const char *const tech_names[N_TECH] = {"standard", "pssm", "psm", "lispsm", "lspsm"};

typedef struct cf_case {
    const char *scene;
    float eye[3], target[3];      /* the point-light camera */
    float height;                 /* of the caster's top */
    float above[3], beside[3];    /* point lights */
    float beside_range;
} cf_case;

static const cf_case cases[] = {
    {"plate", {4.5f, 3.5f, 6}, {0, 0.5f, 0}, 1, {0.25f, 3, 0.125f}, {3, 2.5f, -1}, 9},
    {"pole", {5, 3, 7}, {0, 1, 0}, 3, {0.375f, 4.5f, 0.25f}, {1.5f, 2, 1.25f}, 9},
    {"box", {5, 4, 6.5f}, {0, 0.5f, 0}, 1.5f, {0.25f, 3, 0.125f}, {3, 2.5f, -1.5f}, 9},
};

static int use_old(void) {
    const char *s = getenv("SK_GL_TEST_CF_OLD");
    return s && *s && *s != '0';
}

/* SK_GL_TEST_CF_STRATA=n: the area light's strata per axis (unset: the
   reference's default, TB_REF_EXACT_STRATA) */
static int env_strata(void) {
    const char *s = getenv("SK_GL_TEST_CF_STRATA");
    int v = s && *s ? atoi(s) : 0;
    return v > 0 && v <= 256 ? v : 0;
}

static double now_s(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static double pct_agree(gt_agreement g) { return g.both ? 100.0 * (double)(g.both - g.differ) / (double)g.both : 0.0; }

/* pixels the reference does not leave out: same code (covered = any value
   >= 0, else the negative code itself) */
static gt_agreement code_agree(const float *ref, const float *cf, size_t n) {
    gt_agreement g;
    size_t i;
    g.both = g.differ = 0;
    for (i = 0; i < n; i++) {
        float a = ref[i] >= 0 ? 0.0f : ref[i], b = cf[i] >= 0 ? 0.0f : cf[i];
        if (ref[i] == TB_VIS_SILHOUETTE) continue;
        g.both++;
        g.differ += a != b;
    }
    return g;
}

static void add(gt_agreement *to, gt_agreement g) { to->both += g.both; to->differ += g.differ; }

typedef struct cf_totals {
    gt_agreement exact, exact_code, old_by_elev[N_ELEV], exact_by_elev[N_ELEV];
    uint64_t silhouettes, pixels;
    tb_hard_error tech_ref[N_TECH][N_ELEV], tech_cf[N_TECH][N_ELEV];
} cf_totals;

static void tally_hard(tb_hard_error *to, tb_hard_error e) {
    to->covered += e.covered;
    to->wrong += e.wrong;
    to->false_lit += e.false_lit;
    to->false_shadow += e.false_shadow;
    to->invalid += e.invalid;
}

/* one light over the current G-buffer: reference, closed form, legacy
   reference; asserts; elev < 0 for point lights */
static void check_light(gt_env *e, const tb_cf_scene *cf, const tb_light *l, const char *label, int elev,
                        float *ref, float *truth, float *old, cf_totals *T) {
    tb_view v = gt_view(e);
    tb_ref_stats st;
    const float *judged;
    gt_agreement g, gc, go;
    double sil_pct;
    SK_CHECK(gt_reference_exact(e, l, ref, &st) == 0);
    SK_CHECK(tb_cf_visibility(cf, &v, l, truth) == 0);
    SK_CHECK(tb_reference_trace(e->ref, &v, e->depth, e->normals, l, NULL, old) == 0);
    SK_CHECK(st.pixels == e->n &&
             st.covered + st.background + st.backfacing + st.silhouette + st.out_of_range == st.pixels);
    SK_CHECK_MSG(st.covered > e->n / 3, "%s: %llu covered", label, (unsigned long long)st.covered);
    judged = use_old() ? old : ref;
    g = gt_agree(judged, truth, e->n);
    gc = code_agree(ref, truth, e->n);
    go = gt_agree(old, truth, e->n);
    sil_pct = 100.0 * (double)st.silhouette / (double)st.pixels;
    printf("  %-22s exact: %zu of %zu differ (%.4f%% agree), codes %zu of %zu differ, silhouette %.3f%%, "
           "back-facing %llu; legacy: %zu of %zu differ (%.4f%%)\n",
           label, g.differ, g.both, pct_agree(g), gc.differ, gc.both, sil_pct, (unsigned long long)st.backfacing,
           go.differ, go.both, pct_agree(go));
    SK_CHECK(g.both > e->n / 3);
    SK_CHECK_MSG(pct_agree(g) >= AGREE_MIN_PCT, "%s: %.4f%% agree < %.3f%%", label, pct_agree(g), AGREE_MIN_PCT);
    SK_CHECK_MSG(pct_agree(gc) >= AGREE_MIN_PCT, "%s: codes %.4f%% agree < %.3f%%", label, pct_agree(gc),
                 AGREE_MIN_PCT);
    SK_CHECK_MSG(sil_pct < SILHOUETTE_MAX_PCT, "%s: silhouettes %.3f%% >= %.1f%%", label, sil_pct,
                 SILHOUETTE_MAX_PCT);
    add(&T->exact, g);
    add(&T->exact_code, gc);
    T->silhouettes += st.silhouette;
    T->pixels += st.pixels;
    if (elev >= 0) {
        add(&T->old_by_elev[elev], go);
        add(&T->exact_by_elev[elev], g);
    }
}

static void run_case(const cf_case *c, cf_totals *T) {
    gt_env e;
    tb_cf_scene cf;
    skgl_camera cam;
    skgl_shadow *sh[N_TECH];
    float *ref, *truth, *old, *mask, *cfm;
    int i, a, t;
    char label[64], name[96];
    memset(sh, 0, sizeof sh);
    if (gt_env_init_cf(&e, &cf, c->scene, W, H) != 0) { gt_env_free(&e); return; }
    ref = gt_alloc(&e); truth = gt_alloc(&e); old = gt_alloc(&e); mask = gt_alloc(&e); cfm = gt_alloc(&e);
    for (t = 0; t < N_TECH; t++) {
        skgl_shadow_desc d;
        memset(&d, 0, sizeof d);
        d.technique = techs[t];
        d.resolution = 2048;
        if (techs[t] == SKGL_PSSM) d.cascades = 4;
        sh[t] = gt_shadow(&e, &d);
    }
    if (!ref || !truth || !old || !mask || !cfm) {
        SK_CHECK_MSG(0, "%s: setup", c->scene);
        goto done;
    }
    printf("%s:\n", c->scene);
    for (i = 0; i < N_ELEV; i++)
        for (a = 0; a < N_AZIM; a++) {
            sk_vec3 dir = gt_sun_dir(elevations[i], azimuths[a]);
            tb_light l = gt_sun(dir);
            cam = gt_cf_sun_camera(c->height, dir, W, H);
            if (gt_gbuffer(&e, &cam) != 0) { SK_CHECK_MSG(0, "%s: G-buffer", c->scene); continue; }
            snprintf(label, sizeof label, "sun %g/%g", elevations[i], azimuths[a]);
            check_light(&e, &cf, &l, label, i, ref, truth, old, T);
            if (a == 0) {
                snprintf(name, sizeof name, "out/tests/cf-%s-%g.png", c->scene, elevations[i]);
                tb_image_write_visibility(name, W, H, ref);
                snprintf(name, sizeof name, "out/tests/cf-%s-%g-legacy-error.png", c->scene, elevations[i]);
                tb_image_write_error(name, W, H, truth, old);
            }
            /* the closed form without the pixels the reference leaves out */
            for (t = 0; t < (int)e.n; t++) cfm[t] = ref[t] == TB_VIS_SILHOUETTE ? TB_VIS_SILHOUETTE : truth[t];
            for (t = 0; t < N_TECH; t++) {
                if (!sh[t] || gt_mask(&e, sh[t], &cam, dir, mask) != 0) {
                    SK_CHECK_MSG(0, "%s %s: mask", c->scene, tech_names[t]);
                    continue;
                }
                tally_hard(&T->tech_ref[t][i], tb_metric_hard(ref, mask, e.n));
                tally_hard(&T->tech_cf[t][i], tb_metric_hard(cfm, mask, e.n));
            }
        }
    {
        tb_light l;
        memset(&l, 0, sizeof l);
        l.type = TB_LIGHT_POINT;
        l.position = gt_v3(c->above[0], c->above[1], c->above[2]);
        cam = gt_camera(gt_v3(c->eye[0], c->eye[1], c->eye[2]), gt_v3(c->target[0], c->target[1], c->target[2]),
                        0.9f, 0.1f, 120, W, H);
        if (gt_gbuffer(&e, &cam) != 0) { SK_CHECK_MSG(0, "%s: G-buffer", c->scene); goto done; }
        check_light(&e, &cf, &l, "point above", -1, ref, truth, old, T);
        l.position = gt_v3(c->beside[0], c->beside[1], c->beside[2]);
        l.range = c->beside_range;
        check_light(&e, &cf, &l, "point beside", -1, ref, truth, old, T);
        snprintf(name, sizeof name, "out/tests/cf-%s-point-beside.png", c->scene);
        tb_image_write_visibility(name, W, H, ref);
    }
    SK_CHECK(e.gl.GetError() == 0);
done:
    for (t = 0; t < N_TECH; t++) skgl_shadow_destroy(e.sk, sh[t]);
    free(ref); free(truth); free(old); free(mask); free(cfm);
    gt_env_free(&e);
}

static void test_hard(void) {
    static cf_totals T;
    double t0 = now_s();
    int i, t;
    size_t k;
    memset(&T, 0, sizeof T);
    if (use_old()) printf("SK_GL_TEST_CF_OLD: asserting with the legacy reference\n");
    for (k = 0; k < sizeof cases / sizeof cases[0]; k++) run_case(&cases[k], &T);
    printf("pooled: exact reference %zu of %zu differ (%.5f%% agree), codes %zu of %zu, silhouettes %.4f%% of %llu "
           "pixels\n",
           T.exact.differ, T.exact.both, pct_agree(T.exact), T.exact_code.differ, T.exact_code.both,
           T.pixels ? 100.0 * (double)T.silhouettes / (double)T.pixels : 0.0, (unsigned long long)T.pixels);
    SK_CHECK_MSG(pct_agree(T.exact) >= AGREE_MIN_PCT, "pooled %.5f%%", pct_agree(T.exact));
    SK_CHECK_MSG(pct_agree(T.exact_code) >= AGREE_MIN_PCT, "pooled codes %.5f%%", pct_agree(T.exact_code));
    printf("sun elevation:            ");
    for (i = 0; i < N_ELEV; i++) printf("%10g deg", elevations[i]);
    printf("\nexact vs closed form, %%:  ");
    for (i = 0; i < N_ELEV; i++)
        printf("%14.4f", T.exact_by_elev[i].both ? 100.0 * (double)T.exact_by_elev[i].differ / (double)T.exact_by_elev[i].both : 0.0);
    printf("\nlegacy vs closed form, %%: ");
    for (i = 0; i < N_ELEV; i++)
        printf("%14.4f", T.old_by_elev[i].both ? 100.0 * (double)T.old_by_elev[i].differ / (double)T.old_by_elev[i].both : 0.0);
    printf("\n\ntechniques, %% of covered pixels wrong (vs exact reference / vs closed form), "
           "pooled over scenes and azimuths:\n%-10s", "");
    for (i = 0; i < N_ELEV; i++) printf("      %4g deg      ", elevations[i]);
    printf("\n");
    for (t = 0; t < N_TECH; t++) {
        printf("%-10s", tech_names[t]);
        for (i = 0; i < N_ELEV; i++) {
            const tb_hard_error *r = &T.tech_ref[t][i], *c = &T.tech_cf[t][i];
            printf("  %7.4f / %7.4f ", r->covered ? 100.0 * (double)r->wrong / (double)r->covered : 0.0,
                   c->covered ? 100.0 * (double)c->wrong / (double)c->covered : 0.0);
        }
        printf("\n");
    }
    printf("test_hard: %.1f s\n", now_s() - t0);
}

/* the square area light over the plate */
static void test_area(void) {
    gt_env e;
    tb_cf_scene cf;
    skgl_camera cam = gt_camera(gt_v3(3.5f, 4, 5), gt_v3(0, 0, 0), 0.9f, 0.1f, 120, W, H);
    tb_light l;
    tb_view v;
    tb_ref_stats st;
    float *r1, *r2, *truth;
    size_t i, pen = 0, ends = 0, ends_differ = 0;
    double noise = 0, mae = 0, t0 = now_s();
    if (gt_env_init_cf(&e, &cf, "plate", W, H) != 0) { gt_env_free(&e); return; }
    r1 = gt_alloc(&e); r2 = gt_alloc(&e); truth = gt_alloc(&e);
    memset(&l, 0, sizeof l);
    l.type = TB_LIGHT_RECT;
    l.position = gt_v3(0.25f, 3, -0.125f);
    l.half_u = gt_v3(0.5f, 0, 0);
    l.half_v = gt_v3(0, 0, 0.5f);
    l.strata = env_strata();
    if (!r1 || !r2 || !truth || gt_gbuffer(&e, &cam) != 0) { SK_CHECK_MSG(0, "area: setup"); goto done; }
    v = gt_view(&e);
    l.seed = 1;
    SK_CHECK(gt_reference_exact(&e, &l, r1, &st) == 0);
    l.seed = 2;
    SK_CHECK(gt_reference_exact(&e, &l, r2, NULL) == 0);
    SK_CHECK(tb_cf_visibility(&cf, &v, &l, truth) == 0);
    {
        /* deterministic: one thread gives the same image as all of them */
        tb_ref_options one = gt_ref_options(&e);
        one.threads = 1;
        l.seed = 2;
        SK_CHECK(tb_reference_trace_exact(e.ref, &v, e.depth, &l, &one, truth, NULL) == 0);
        SK_CHECK_MSG(memcmp(truth, r2, sizeof(float) * e.n) == 0, "one thread differs from many");
        SK_CHECK(tb_cf_visibility(&cf, &v, &l, truth) == 0);
    }
    for (i = 0; i < e.n; i++) {
        if (!(r1[i] >= 0) || !(truth[i] >= 0)) continue;
        if (truth[i] > 0 && truth[i] < 1) {
            pen++;
            noise += fabs((double)r1[i] - r2[i]);
            mae += fabs((double)r1[i] - truth[i]);
        } else {
            ends++;
            ends_differ += r1[i] != truth[i];
        }
    }
    noise = pen ? noise / (double)pen / sqrt(2.0) : 1.0;
    mae = pen ? mae / (double)pen : 1.0;
    printf("area light over the plate (%d x %d samples): %zu penumbra pixels, noise %.5f, mean |ref - closed form| "
           "%.5f; umbra/lit %zu of %zu differ; silhouettes %llu; %.1f s\n",
           l.strata ? (l.strata < TB_REF_MIN_STRATA ? TB_REF_MIN_STRATA : l.strata) : TB_REF_EXACT_STRATA,
           l.strata ? (l.strata < TB_REF_MIN_STRATA ? TB_REF_MIN_STRATA : l.strata) : TB_REF_EXACT_STRATA, pen, noise, mae, ends_differ, ends,
           (unsigned long long)st.silhouette, now_s() - t0);
    SK_CHECK(pen > 2000);
    SK_CHECK(ends > e.n / 3);
    SK_CHECK_MSG(noise <= AREA_NOISE_BOUND, "noise %.5f > %.4f", noise, AREA_NOISE_BOUND);
    SK_CHECK_MSG(mae <= AREA_MAE_BOUND, "mae %.5f > %.4f", mae, AREA_MAE_BOUND);
    SK_CHECK_MSG(100.0 * (double)(ends - ends_differ) / (double)(ends ? ends : 1) >= AGREE_MIN_PCT,
                 "umbra/lit: %zu of %zu differ", ends_differ, ends);
    tb_image_write_visibility("out/tests/cf-plate-area.png", W, H, r1);
done:
    free(r1); free(r2); free(truth);
    gt_env_free(&e);
}

/* ---- spot lights against the closed form (tb_cf_spot_visibility) -------- */

typedef struct spot_edge {
    size_t judged, lit, wrong, far;   /* far: wrong pixels more than SPOT_NEAR_PX from the exact edge */
    double max_px, sum_px;
} spot_edge;

/* pixel i's distance, in pixels, to the nearest covered pixel whose exact
   class is the other one (the analytic shadow or cone edge); r + 1 when
   none lies within r */
static double edge_distance(const gt_env *e, const float *truth, size_t i, int r) {
    int x0 = (int)(i % (size_t)e->w), y0 = (int)(i / (size_t)e->w), x, y, c = truth[i] > 0.5f;
    double best = r + 1.0;
    for (y = y0 - r; y <= y0 + r; y++)
        for (x = x0 - r; x <= x0 + r; x++) {
            size_t k;
            double d;
            if (x < 0 || y < 0 || x >= e->w || y >= e->h) continue;
            k = (size_t)y * (size_t)e->w + (size_t)x;
            if (!(truth[k] >= 0) || (truth[k] > 0.5f) == c) continue;
            d = sqrt((double)(x - x0) * (x - x0) + (double)(y - y0) * (y - y0));
            if (d < best) best = d;
        }
    return best;
}

/* the mask's edges against the exact ones: every pixel both cover whose
   lit / shadowed class differs lies at some distance from the exact edge */
static spot_edge score_edges(const gt_env *e, const float *truth, const float *mask) {
    spot_edge s;
    size_t i;
    memset(&s, 0, sizeof s);
    for (i = 0; i < e->n; i++) {
        double d;
        if (!(truth[i] >= 0) || !(mask[i] >= 0)) continue;
        s.judged++;
        s.lit += truth[i] > 0.5f;
        if ((truth[i] > 0.5f) == (mask[i] > 0.5f)) continue;
        d = edge_distance(e, truth, i, SPOT_SEARCH_PX);
        s.wrong++;
        s.sum_px += d;
        if (d > s.max_px) s.max_px = d;
        if (d > SPOT_NEAR_PX) s.far++;
    }
    return s;
}

/* the spot's mask over the current G-buffer (0 outside the scissor), background -1 */
static int spot_mask(gt_env *e, skgl_point *p, const skgl_camera *cam, sk_vec3 lp, sk_vec3 dir, float *vis) {
    skgl_scene sc = gt_scene(e);
    sc.draw = gt_point_draw;
    if (skgl_spot_render(e->sk, p, cam, &sc, lp, dir) != SK_OK) return -1;
    return gt_point_mask(e, p, cam, 0.0f, vis);
}

typedef struct spot_case {
    const char *label, *scene;
    float eye[3], target[3], pos[3], dir[3], angle;
} spot_case;

/* SK_GL_TEST_CF_SPOT_RES=n: the spots' map side (unset: 1024) */
static int env_spot_res(void) {
    const char *s = getenv("SK_GL_TEST_CF_SPOT_RES");
    int v = s && *s ? atoi(s) : 0;
    return v >= 16 && v <= 4096 ? v : 1024;
}

static void run_spot(const spot_case *c) {
    gt_env e;
    tb_cf_scene cf;
    skgl_camera cam;
    skgl_point_desc d;
    skgl_point *p = NULL;
    float *truth = NULL, *mask = NULL;
    tb_light l;
    tb_view v;
    spot_edge s;
    char name[64];
    sk_vec3 lp = gt_v3(c->pos[0], c->pos[1], c->pos[2]), dir = gt_v3(c->dir[0], c->dir[1], c->dir[2]);
    if (gt_env_init_cf(&e, &cf, c->scene, W, H) != 0) { gt_env_free(&e); return; }
    truth = gt_alloc(&e);
    mask = gt_alloc(&e);
    memset(&d, 0, sizeof d);
    d.resolution = env_spot_res();
    d.range = SPOT_RANGE;
    d.spot_angle = c->angle;
    d.cull_casters = 1;
    d.scissor = 1;
    SK_CHECK_MSG(skgl_point_create(e.sk, &d, &p) == SK_OK, "%s: skgl_point_create: %s", c->label,
                 skgl_error_log(e.sk));
    cam = gt_camera(gt_v3(c->eye[0], c->eye[1], c->eye[2]), gt_v3(c->target[0], c->target[1], c->target[2]), 0.9f,
                    0.1f, 120, W, H);
    if (!truth || !mask || !p || gt_gbuffer(&e, &cam) != 0) { SK_CHECK_MSG(0, "%s: setup", c->label); goto done; }
    memset(&l, 0, sizeof l);
    l.type = TB_LIGHT_POINT;
    l.position = lp;
    l.range = SPOT_RANGE;
    v = gt_view(&e);
    SK_CHECK(tb_cf_spot_visibility(&cf, &v, &l, dir, c->angle, truth) == 0);
    if (spot_mask(&e, p, &cam, lp, dir, mask) != 0) { SK_CHECK_MSG(0, "%s: %s", c->label, skgl_error_log(e.sk)); goto done; }
    snprintf(name, sizeof name, "cf-%s", c->label);
    gt_images(&e, name, truth, mask);
    s = score_edges(&e, truth, mask);
    printf("  %-14s map %d: %zu judged (%zu lit), %zu wrong: edge error mean %.2f px, max %.2f px, %zu more than "
           "%g px from the exact edge\n",
           c->label, d.resolution, s.judged, s.lit, s.wrong, s.wrong ? s.sum_px / (double)s.wrong : 0.0, s.max_px,
           s.far, SPOT_NEAR_PX);
    SK_CHECK(s.judged > e.n / 3);
    SK_CHECK(s.lit > 2000 && s.judged - s.lit > 2000);
    SK_CHECK_MSG(s.max_px <= SPOT_EDGE_MAX_PX, "%s: edge error %.2f px > %g", c->label, s.max_px, SPOT_EDGE_MAX_PX);
    SK_CHECK_MSG(s.far <= SPOT_FAR_MAX, "%s: %zu pixels more than %g px from the edge > %d", c->label, s.far,
                 SPOT_NEAR_PX, SPOT_FAR_MAX);
    SK_CHECK_MSG(s.wrong <= SPOT_WRONG_MAX, "%s: %zu wrong > %d", c->label, s.wrong, SPOT_WRONG_MAX);
    SK_CHECK(e.gl.GetError() == 0);
done:
    skgl_point_destroy(e.sk, p);
    free(truth); free(mask);
    gt_env_free(&e);
}

/* a spot over the plate (the plate's shadow and the cone's ellipse both on
   the ground), and one grazing the ground past the box */
static void test_spot(void) {
    static const spot_case spots[] = {
        {"spot-plate", "plate", {4.5f, 3.5f, 6}, {0, 0.5f, 0}, {0.25f, 3, 0.125f}, {0.2f, -1, 0.1f}, 50},
        {"spot-grazing", "box", {5, 4, 6.5f}, {0, 0.5f, 0}, {4.0f, 0.35f, 0.5f}, {-0.99939f, -0.0349f, 0}, 30},
    };
    double t0 = now_s();
    size_t k;
    for (k = 0; k < sizeof spots / sizeof spots[0]; k++) run_spot(&spots[k]);
    printf("test_spot: %.1f s\n", now_s() - t0);
}

/* bad input gets -1 */
static void test_bad_input(void) {
    tb_scene s;
    tb_cf_scene cf;
    tb_reference *ref;
    tb_view v;
    tb_light l, pl;
    tb_ref_stats st;
    float vis[16];
    tb_scene_init(&s);
    SK_CHECK(tb_cf_build(&s, &cf, "nothing") == -1);
    SK_CHECK(tb_cf_build(NULL, &cf, "plate") == -1);
    SK_CHECK(tb_cf_build(&s, &cf, "plate") == 0);
    ref = tb_reference_create(&s);
    SK_CHECK(ref != NULL);
    memset(&v, 0, sizeof v);
    v.inv_view_proj = sk_mat4_identity();
    v.width = 4;
    v.height = 4;
    l = gt_sun(gt_v3(0, -1, 0));
    SK_CHECK(tb_reference_trace_exact(ref, &v, NULL, &l, NULL, vis, &st) == 0 && st.pixels == 16);
    SK_CHECK(tb_reference_trace_exact(NULL, &v, NULL, &l, NULL, vis, NULL) == -1);
    SK_CHECK(tb_reference_trace_exact(ref, NULL, NULL, &l, NULL, vis, NULL) == -1);
    SK_CHECK(tb_reference_trace_exact(ref, &v, NULL, NULL, NULL, vis, NULL) == -1);
    SK_CHECK(tb_reference_trace_exact(ref, &v, NULL, &l, NULL, NULL, NULL) == -1);
    l.direction.x = NAN;
    SK_CHECK(tb_reference_trace_exact(ref, &v, NULL, &l, NULL, vis, NULL) == -1);
    l.direction = gt_v3(0, 0, 0);
    SK_CHECK(tb_reference_trace_exact(ref, &v, NULL, &l, NULL, vis, NULL) == -1);
    l.direction.x = NAN;
    SK_CHECK(tb_cf_visibility(&cf, &v, &l, vis) == -1);
    l = gt_sun(gt_v3(0, -1, 0));
    l.type = (tb_light_type)7;
    SK_CHECK(tb_reference_trace_exact(ref, &v, NULL, &l, NULL, vis, NULL) == -1);
    SK_CHECK(tb_cf_visibility(&cf, &v, &l, vis) == -1);
    v.width = 0;
    SK_CHECK(tb_reference_trace_exact(ref, &v, NULL, &l, NULL, vis, NULL) == -1);
    v.width = 4;
    v.inv_view_proj.m[15] = 0;
    v.inv_view_proj.m[0] = 0;
    l = gt_sun(gt_v3(0, -1, 0));
    SK_CHECK(tb_reference_trace_exact(ref, &v, NULL, &l, NULL, vis, NULL) == -1);   /* singular */
    v.inv_view_proj = sk_mat4_identity();
    /* a rect light the closed form does not cover: tilted */
    memset(&l, 0, sizeof l);
    l.type = TB_LIGHT_RECT;
    l.position = gt_v3(0, 3, 0);
    l.half_u = gt_v3(0.5f, 0.1f, 0);
    l.half_v = gt_v3(0, 0, 0.5f);
    SK_CHECK(tb_cf_visibility(&cf, &v, &l, vis) == -1);
    l.half_u = gt_v3(0.5f, 0, 0);
    SK_CHECK(tb_cf_visibility(&cf, &v, &l, vis) == 0);
    l.strata = TB_REF_MAX_STRATA + 1;
    SK_CHECK(tb_reference_trace_exact(ref, &v, NULL, &l, NULL, vis, NULL) == -1);
    l.strata = 0;
    l.position = gt_v3(0, 0.5f, 0);   /* below the plate */
    SK_CHECK(tb_cf_visibility(&cf, &v, &l, vis) == -1);
    /* a spot: a point light, a finite non-zero axis, an angle in (0, 90) */
    SK_CHECK(tb_cf_spot_visibility(&cf, &v, &l, gt_v3(0, -1, 0), 30, vis) == -1);   /* l: a rect light */
    pl = l;
    pl.type = TB_LIGHT_POINT;
    pl.position = gt_v3(0, 3, 0);
    SK_CHECK(tb_cf_spot_visibility(&cf, &v, &pl, gt_v3(0, -1, 0), 30, vis) == 0);
    SK_CHECK(tb_cf_spot_visibility(&cf, &v, &pl, gt_v3(0, 0, 0), 30, vis) == -1);
    SK_CHECK(tb_cf_spot_visibility(&cf, &v, &pl, gt_v3(0, NAN, 0), 30, vis) == -1);
    SK_CHECK(tb_cf_spot_visibility(&cf, &v, &pl, gt_v3(0, -1, 0), 0, vis) == -1);
    SK_CHECK(tb_cf_spot_visibility(&cf, &v, &pl, gt_v3(0, -1, 0), 90, vis) == -1);
    SK_CHECK(tb_cf_spot_visibility(&cf, &v, &pl, gt_v3(0, -1, 0), NAN, vis) == -1);
    SK_CHECK(tb_cf_spot_visibility(NULL, &v, &pl, gt_v3(0, -1, 0), 30, vis) == -1);
    tb_reference_destroy(ref);
    tb_scene_free(&s);
    SK_CHECK(tb_cf_build_box(&s, &cf) == 0 && cf.box_count == 1);
    l.position = gt_v3(0, 3, 0);
    SK_CHECK(tb_cf_visibility(&cf, &v, &l, vis) == -1);   /* rect lights: the plate scene only */
    tb_scene_free(&s);
}

SK_TEST_MAIN(test_bad_input, test_spot, test_hard, test_area)
