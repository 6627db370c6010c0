/* test_gl_rmsm.c - RMSM-style virtual shadow maps (Romanick's VGP353 notes, after Lefohn
   et al. 2007) through skgl_shadow_analyze + SKGL_RMSM: the pages reduced
   on the GPU against sk_rmsm_page_requests over the same samples, accuracy
   against the Embree reference, and the configurations where it degrades.
   400 x 225; virtual map 16384^2 in pages of 128^2 (8 levels).

   Measured (Mesa 22.3 llvmpipe, OSMesa):

   test_pages_match_cpu - pool of 64^2 pages: the GPU's resident pages are
   exactly sk_rmsm_page_requests over the analysis texture's samples, in
   order, plus the coarsest page (desc.rmsm_band_pages -1): boxes 155,
   terrace 434, fence 810 pages; with the finer bands (the default) the
   band the pool holds, exactly band_pages' over the same samples: boxes
   band 6 (1774 pages), terrace and fence band 7 (2315, 3088: level 0).
   Pool of 24^2 (test_accuracy): boxes band 6 (572 pages), covered
   0.0054%, area 0.25%; terrace a band capped in world size (522 pages,
   0.0579%, 2.18%), where it took the pixel-matched band 0 while the
   bands had to go a level finer (434 pages, 0.1480%, 5.58%); fence's 810
   pixel-matched pages do not fit: a cap above its finest level 2 (317
   pages, 0.8859%, 10.83%; band 0 folded to min level 1 before, 546
   pages, 1.1516%, 14.08%).

   test_accuracy - pool of 24^2 pages, against the focused 2048^2 map, on
   the exact reference with the default bias (receiver plane); covered %
   (tb_metric_hard) and shadow-area error (tb_metric_shadow):
       view     rmsm                                  standard-2048         old (rmsm vs 2048)
       boxes    0.0522%  2.44% (70 pages, 1.18 Mtex)  0.0288%  1.35% (4.19)  0.0921% vs 0.0608%
       terrace  0.4473% 16.87% (83 pages, 1.40 Mtex)  0.1899%  7.16%         0.5330% vs 0.3472%
       fence    1.7457% 21.35% (139 pages, 2.35 Mtex) 0.7400%  9.05%         2.3010% vs 2.8277%
     (reference shadow 1188, 824, 4708 pixels). With the receiver-plane
     bias the focused 2048 map gains more than RMSM: RMSM is now 1.8x
     (boxes) to 2.4x (terrace, fence) its error, where with the normal
     offset it was within 1.5x of it (fence: below it); on the terrace its
     wrong pixels reach
     4.7 px from the reference's edges (p95; 0.5 px for the 2048 map).
     Bounds about 1.4x: covered 0.075 / 0.63 / 2.45% (previously 0.16 /
     0.9 / 3.5%), area 3.4 / 23.6 / 30%. A 4x smaller virtual map changes
     nothing here (the view's pages sit at levels the smaller map still
     has: the same errors), so the can-fail runs drop the analysis
     (SK_RMSM_NO_ANALYSIS=1: only the coarsest page): 0.4986% / 23.3%,
     1.3193% / 49.8%, 9.3208% / 114%, or use the normal-offset bias
     (SK_GL_TEST_BIAS=normal-offset): 0.1116% / 5.22%, 0.6725% / 25.4%,
     3.3820% / 41.4%: every bound fails both ways.

   test_degraded - the boxes view with a pool of 2x2 pages: the finest level
   rises to 7 (one page), error 0.4986% (area 23.3%); 4x4: level 5, 14
   pages, 0.1260% (5.89%); no analysis: the coarsest page, 0.4986% (23.3%)
   (old 0.7614%, 0.1391%, 0.7614%). Bounds about 1.4x: 0.70 / 0.18 /
   0.70% and 33 / 8.3 / 33% (previously 10 / 5 / 10%, covered only). Can
   fail: normal-offset bias 0.8045% / 37.6% (2x2 and no analysis) fail;
   the 4x4 pool halved to 2x2 (the first case) gives 0.4986% / 23.3%
   against the 4x4 bounds: fails. Bad descriptions (virtual size
   not a power of two, page size 100, page larger than the map, pool 1 or
   65, 2048 pages a side) are refused with SK_ERR_INVALID_ARG.
   test_layered_batches - desc.layered: the boxes view, pool 24^2 (572
   pages of band 6), a pass per page against SKGL_MAX_CASCADES (8) pages a
   pass: 572 callbacks (722 culled draws) against 72 (128), each page
   handed to the callback once with the same matrix (info->layer_index,
   layer_view_proj, layer_frustum); the pool's depth in the pages' slots
   the same but 15744 of 9.67 M texels (0.16%, by up to 1.79e-7: the
   geometry shader's rounding), not one pixel of the mask: error 0.0054%,
   area 0.25% both; the render (no analysis) fastest of 5: 44.7 -> 35.9
   ms to 92.3 -> 67.4 ms as the machine's load varied, ratio 0.71 to 0.80
   (stats.layered 2; not asserted). The same through a caster program
   (its layered version): 572 -> 72 callbacks, the same 15744 texels, 0
   pixels. test_gl_rmsm_loop.c runs this test alone with the geometry
   shader's loop (SKGL_LAYERED_LOOP, stats.layered 1): the same figures,
   ratio 0.65. Can fail: each layer copied into the
   next page's slot of its batch: 9.47 M texels differ by up to 0.74,
   49073 pixels, error 88%; each page drawn with the next page's matrix
   (a wrong page offset): 572 pages with another matrix, 8694 pixels,
   error 15.6%; a batch's pages handed to the callback as layers 0..7
   (the cascades' layer_index): no page seen once.
   Pictures: out/tests/rmsm-*.png and -error.png. */
#if !defined(_POSIX_C_SOURCE) || _POSIX_C_SOURCE < 199309L
#undef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 199309L   /* clock_gettime */
#endif
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "sk_test.h"
#include "gl_test_util.h"

#include <math.h>
#include <time.h>

#define W 400
#define H 225
/* test_gl_rmsm_loop.c (SKGL_LAYERED_LOOP): the batches alone, through the
   geometry shader's loop; the other tests never reach it */
#ifdef SKGL_LAYERED_LOOP
#define BATCHES_ONLY 1
#else
#define BATCHES_ONLY 0
#endif
#define MAX_PAGES 4096

static int rmsm_frame(gt_env *e, skgl_shadow *s, const skgl_camera *cam, const skgl_scene *sc, sk_vec3 light,
                      int analyze, float *vis) {
    sk_result r = analyze ? skgl_shadow_analyze(e->sk, s, cam, sc, light, e->gbuf.depth_tex) : SK_OK;
    if (r == SK_OK) r = skgl_shadow_render(e->sk, s, cam, sc, light);
    if (r != SK_OK) {
        printf("rmsm frame: %s (%s)\n", sk_result_string(r), skgl_error_log(e->sk));
        return -1;
    }
    return vis ? gt_mask_only(e, s, cam, vis) : 0;
}

static skgl_shadow *rmsm_shadow_matched(gt_env *e, int vres, int page, int pool, int matched) {
    skgl_shadow_desc d;
    memset(&d, 0, sizeof d);
    d.technique = SKGL_RMSM;
    d.resolution = vres;
    d.rmsm_page_size = page;
    d.rmsm_pool_pages = pool;
    d.rmsm_band_pages = matched ? -1 : 0;
    return gt_shadow(e, &d);
}

static skgl_shadow *rmsm_shadow(gt_env *e, int vres, int page, int pool) {
    return rmsm_shadow_matched(e, vres, page, pool, 0);
}

/* The pages of request band b > 0 (rmsm_request.vert, skgl__rmsm_bands)
   of a 16384^2 map in pages of 128^2 (8 levels), sorted as
   sk_rmsm_page_requests sorts: per level-0 page the least and greatest
   pixel-matched level f of its samples, and its ancestors at the band
   levels (f - 1 with finer, else f; at most 7 - b) of every f between
   (stats.rmsm_band_finer); out holds up to cap. */
#define BAND_N0 128
static int band_pages(const sk_vec3 *pts, int n, int band, int finer, sk_page *out, int cap) {
    static int fmin[BAND_N0][BAND_N0], fmax[BAND_N0][BAND_N0];
    static unsigned char want[8][BAND_N0][BAND_N0];
    int i, x, y, l, f, count = 0;
    for (y = 0; y < BAND_N0; y++)
        for (x = 0; x < BAND_N0; x++) { fmin[y][x] = 99; fmax[y][x] = -1; }
    memset(want, 0, sizeof want);
    for (i = 0; i < n; i++) {
        int lv = (int)floorf(pts[i].z);
        lv = lv < 0 ? 0 : lv > 7 ? 7 : lv;
        x = (int)(pts[i].x * BAND_N0); y = (int)(pts[i].y * BAND_N0);
        x = x > BAND_N0 - 1 ? BAND_N0 - 1 : x; y = y > BAND_N0 - 1 ? BAND_N0 - 1 : y;
        if (lv < fmin[y][x]) fmin[y][x] = lv;
        if (lv > fmax[y][x]) fmax[y][x] = lv;
    }
    for (y = 0; y < BAND_N0; y++)
        for (x = 0; x < BAND_N0; x++)
            for (f = fmin[y][x]; f <= fmax[y][x]; f++) {
                l = finer && f > 0 ? f - 1 : f;
                if (l > 7 - band) l = 7 - band;
                want[l][y >> l][x >> l] = 1;
            }
    for (l = 0; l < 8; l++)
        for (y = 0; y < (BAND_N0 >> l); y++)
            for (x = 0; x < (BAND_N0 >> l); x++)
                if (want[l][y][x] && count < cap) {
                    out[count].level = l; out[count].px = x; out[count].py = y;
                    count++;
                }
    return count;
}

typedef struct view_case {
    const char *label, *scene;
    float eye[3], target[3], light[3];
    double max_pct, max_area_pct;   /* test_accuracy: covered %, shadow-area error % */
} view_case;

/* bounds about 1.4x the measurement (figures at the top) */
static const view_case views[] = {
    {"boxes", "ground-boxes", {-9, 7, 12}, {0, 1, 0}, {-0.5f, -1, -0.35f}, 0.075, 3.4},
    {"terrace", "terrace", {0, 2, 1}, {0, 0.5f, -30}, {0.7f, -1, 0.4f}, 0.63, 23.6},
    {"fence", "fence", {1, 1.6f, 3.5f}, {0, 0.5f, 0}, {0.3f, -1, 0.6f}, 2.45, 30},
};

/* the GPU's pages are exactly sk_rmsm_page_requests over the analysis's own
   samples, plus the coarsest page: pixel-matched (desc.rmsm_band_pages -1) and
   at the request band the pool held (the samples' levels as that band
   asks for them, band_pages) */
static void test_pages_match_cpu(void) {
    static sk_page gpu[MAX_PAGES], cpu[MAX_PAGES];
    size_t c;
    if (BATCHES_ONLY) return;
    for (c = 0; c < 2 * sizeof views / sizeof views[0]; c++) {
        const view_case *k = &views[c / 2];
        int matched = c % 2 == 0, band = 0;
        gt_env e;
        skgl_camera cam = gt_camera(gt_v3(k->eye[0], k->eye[1], k->eye[2]),
                                    gt_v3(k->target[0], k->target[1], k->target[2]), 1.0f, 0.1f, 250, W, H);
        sk_vec3 l = gt_v3(k->light[0], k->light[1], k->light[2]);
        skgl_shadow *s;
        skgl_scene sc;
        float *samp;
        sk_vec3 *pts;
        size_t i;
        int ns = 0, ng, nc, j, extra, mism = 0;
        const skgl_shadow_frame_stats *st;
        if (gt_env_init_named(&e, k->scene, W, H) != 0) { gt_env_free(&e); continue; }
        sc = gt_scene(&e);
        samp = (float *)malloc(sizeof(float) * 4 * e.n);
        pts = (sk_vec3 *)malloc(sizeof(sk_vec3) * e.n);
        s = rmsm_shadow_matched(&e, 16384, 128, 64, matched);
        if (!s || !samp || !pts || gt_gbuffer(&e, &cam) != 0 || rmsm_frame(&e, s, &cam, &sc, l, 1, NULL) != 0 ||
            tb_gl_read_texture_rgba_float(&e.gl, skgl_shadow_analysis_texture(s), W, H, samp) != 0) {
            SK_CHECK_MSG(0, "%s: frame failed", k->label);
        } else {
            int requested;
            st = skgl_shadow_stats(s);
            band = st->rmsm_band;
            for (i = 0; i < e.n; i++)
                if (samp[4 * i + 3] > 0.5f) pts[ns++] = gt_v3(samp[4 * i], samp[4 * i + 1], samp[4 * i + 2]);
            requested = sk_rmsm_page_requests(pts, ns, 16384, 128, cpu, MAX_PAGES);
            nc = band > 0 ? band_pages(pts, ns, band, st->rmsm_band_finer, cpu, MAX_PAGES) : requested;
            ng = skgl_shadow_pages(s, gpu, MAX_PAGES);
            /* the coarsest page is resident whether asked for or not */
            extra = !(nc > 0 && cpu[nc - 1].level == 7);
            printf("%-8s %s %d samples: cpu %d pages, gpu %d resident (%d requested, band %d, min level %d), levels:",
                   k->label, matched ? "matched" : "banded ", ns, nc, ng, st->pages_requested, band,
                   st->rmsm_min_level);
            for (j = 0; j < 8; j++) {
                int n = 0, m;
                for (m = 0; m < ng; m++) n += gpu[m].level == j;
                printf(" %d", n);
            }
            printf("\n");
            SK_CHECK(nc > 0 && st->rmsm_min_level == 0);
            /* matched: band 0 alone; the 64^2 pool holds finer pages on every view */
            SK_CHECK_MSG(matched ? band == 0 : band > 0, "%s: band %d", k->label, band);
            SK_CHECK_MSG(ng == nc + extra && st->pages_requested == requested, "%s: gpu %d (+%d) vs cpu %d", k->label,
                         ng, extra, nc);
            for (j = 0; j < nc && j < ng; j++)
                mism += gpu[j].level != cpu[j].level || gpu[j].px != cpu[j].px || gpu[j].py != cpu[j].py;
            SK_CHECK_MSG(mism == 0, "%s: %d pages differ", k->label, mism);
            SK_CHECK(st->pages_rendered == ng && st->passes == ng);
        }
        SK_CHECK(e.gl.GetError() == 0);
        skgl_shadow_destroy(e.sk, s);
        free(samp); free(pts);
        gt_env_free(&e);
    }
}

/* against the reference, next to the focused 2048^2 map */
static void test_accuracy(void) {
    size_t c;
    if (BATCHES_ONLY) return;
    for (c = 0; c < sizeof views / sizeof views[0]; c++) {
        const view_case *k = &views[c];
        gt_env e;
        skgl_camera cam = gt_camera(gt_v3(k->eye[0], k->eye[1], k->eye[2]),
                                    gt_v3(k->target[0], k->target[1], k->target[2]), 1.0f, 0.1f, 250, W, H);
        sk_vec3 l = gt_v3(k->light[0], k->light[1], k->light[2]);
        skgl_shadow_desc d;
        skgl_shadow *s, *ss;
        skgl_scene sc;
        float *ref, *m, *ms;
        double er = -1, es = -1;
        tb_shadow_error ser, ses;
        char img[64], buf[256];
        if (gt_env_init_named(&e, k->scene, W, H) != 0) { gt_env_free(&e); continue; }
        sc = gt_scene(&e);
        ref = gt_alloc(&e); m = gt_alloc(&e); ms = gt_alloc(&e);
        memset(&ser, 0, sizeof ser);
        memset(&ses, 0, sizeof ses);
        s = rmsm_shadow(&e, (int)(16384 * gt_res_scale()), 128, 24);
        memset(&d, 0, sizeof d);
        d.resolution = 2048;
        ss = gt_shadow(&e, &d);
        if (s && ss && gt_gbuffer(&e, &cam) == 0 && gt_reference(&e, l, ref) == 0 &&
            rmsm_frame(&e, s, &cam, &sc, l, !getenv("SK_RMSM_NO_ANALYSIS"), m) == 0 &&
            gt_mask(&e, ss, &cam, l, ms) == 0) {
            er = tb_metric_hard(ref, m, e.n).pct;
            ser = gt_shadow_error(&e, ref, m);
            es = tb_metric_hard(ref, ms, e.n).pct;
            ses = gt_shadow_error(&e, ref, ms);
            snprintf(img, sizeof img, "rmsm-%s", k->label);
            gt_images(&e, img, ref, m);
        }
        printf("%-8s rmsm %.4f%% (%d pages, %.2f Mtexels, min level %d)  standard-2048 %.4f%% (area %.4f%%; 4.19 "
               "Mtexels); rmsm %s\n", k->label, er, s ? skgl_shadow_stats(s)->pages_rendered : 0,
               s ? skgl_shadow_stats(s)->texels / 1e6 : 0.0, s ? skgl_shadow_stats(s)->rmsm_min_level : -1, es,
               ses.area_pct, gt_shadow_error_str(&ser, buf, sizeof buf));
        SK_CHECK(er >= 0 && es >= 0);
        SK_CHECK_MSG(er < k->max_pct, "%s: rmsm %.4f%% >= %.3f%%", k->label, er, k->max_pct);
        SK_CHECK_MSG(ser.ok && ser.area_pct < k->max_area_pct, "%s: rmsm shadow-area error %.4f%% >= %.1f%%", k->label,
                     ser.area_pct, k->max_area_pct);
        SK_CHECK(e.gl.GetError() == 0);
        skgl_shadow_destroy(e.sk, s);
        skgl_shadow_destroy(e.sk, ss);
        free(ref); free(m); free(ms);
        gt_env_free(&e);
    }
}

/* a pool too small for the view: the finest level rises until the pages
   fit; no analysis at all: the coarsest page alone. Both stay valid.
   Bounds per case (pool 2x2, pool 4x4, no analysis), about 1.4x the
   measurement: covered % 0.4986, 0.1260, 0.4986; area % 23.3, 5.89, 23.3 */
static const double degraded_max_pct[3] = {0.70, 0.18, 0.70};
static const double degraded_max_area_pct[3] = {33, 8.3, 33};

static void test_degraded(void) {
    const view_case *k = &views[0];
    gt_env e;
    skgl_camera cam = gt_camera(gt_v3(k->eye[0], k->eye[1], k->eye[2]),
                                gt_v3(k->target[0], k->target[1], k->target[2]), 1.0f, 0.1f, 250, W, H);
    sk_vec3 l = gt_v3(k->light[0], k->light[1], k->light[2]);
    skgl_scene sc;
    float *ref, *m;
    int t;
    if (BATCHES_ONLY) return;
    if (gt_env_init_named(&e, k->scene, W, H) != 0) { gt_env_free(&e); return; }
    sc = gt_scene(&e);
    ref = gt_alloc(&e); m = gt_alloc(&e);
    SK_CHECK(gt_gbuffer(&e, &cam) == 0 && gt_reference(&e, l, ref) == 0);
    for (t = 0; t < 3; t++) {
        static const char *const names[3] = {"pool 2x2", "pool 4x4", "no analysis"};
        skgl_shadow *s = rmsm_shadow(&e, 16384, 128, t == 0 ? 2 : t == 1 ? 4 : 24);
        const skgl_shadow_frame_stats *st;
        double er;
        tb_shadow_error se;
        char buf[256];
        size_t i, bad = 0;
        if (!s || rmsm_frame(&e, s, &cam, &sc, l, t < 2, m) != 0) { SK_CHECK(0); skgl_shadow_destroy(e.sk, s); continue; }
        st = skgl_shadow_stats(s);
        er = tb_metric_hard(ref, m, e.n).pct;
        se = gt_shadow_error(&e, ref, m);
        for (i = 0; i < e.n; i++) bad += !(m[i] >= 0.0f && m[i] <= 1.0f) && m[i] != -1.0f;
        printf("%-12s %d pages requested, %d resident, min level %d: error %.4f%%, %s\n", names[t], st->pages_requested,
               st->pages_rendered, st->rmsm_min_level, er, gt_shadow_error_str(&se, buf, sizeof buf));
        SK_CHECK(bad == 0 && er >= 0);
        if (t == 0) SK_CHECK(st->pages_rendered <= 4 && st->rmsm_min_level > 0);
        if (t == 1) SK_CHECK(st->pages_rendered <= 16 && st->rmsm_min_level > 0);
        if (t == 2) SK_CHECK(st->pages_rendered == 1);
        SK_CHECK_MSG(er < degraded_max_pct[t] && se.ok && se.area_pct < degraded_max_area_pct[t],
                     "%s: %.4f%% (bound %.2f%%), area %.4f%% (bound %.1f%%)", names[t], er, degraded_max_pct[t],
                     se.area_pct, degraded_max_area_pct[t]);
        SK_CHECK(e.gl.GetError() == 0);
        skgl_shadow_destroy(e.sk, s);
    }
    /* bad descriptions */
    {
        skgl_shadow_desc d;
        skgl_shadow *s = NULL;
        int b;
        for (b = 0; b < 6; b++) {
            memset(&d, 0, sizeof d);
            d.technique = SKGL_RMSM;
            if (b == 0) d.resolution = 3000;            /* not a power of two */
            if (b == 1) d.rmsm_page_size = 100;
            if (b == 2) { d.resolution = 64; d.rmsm_page_size = 128; }
            if (b == 3) d.rmsm_pool_pages = 1;
            if (b == 4) d.rmsm_pool_pages = 65;
            if (b == 5) { d.resolution = 1 << 18; d.rmsm_page_size = 128; }   /* 2048 pages a side */
            SK_CHECK_MSG(skgl_shadow_create(e.sk, &d, &s) == SK_ERR_INVALID_ARG, "bad desc %d accepted", b);
        }
    }
    /* a render without analysis uploads the page table: the caller's active
       unit (here 6, outside the units shadowkit saves) keeps its texture;
       the table's unit + 1 must exist, so bind refuses unit 31 */
    {
        skgl_shadow *s = rmsm_shadow(&e, 16384, 128, 8);
        unsigned tex = 0;
        int bound = -1, active = -1;
        e.gl.GenTextures(1, &tex);
        e.gl.ActiveTexture(0x84C0 + 6);
        e.gl.BindTexture(0x0DE1, tex);
        SK_CHECK(s && rmsm_frame(&e, s, &cam, &sc, l, 0, NULL) == 0);
        e.gl.GetIntegerv(0x84E0, &active);
        e.gl.GetIntegerv(0x8069, &bound);
        SK_CHECK_MSG(active == 0x84C0 + 6 && bound == (int)tex, "active unit 0x%x, its 2D texture %d (was %u)", active,
                     bound, tex);
        SK_CHECK(skgl_shadow_bind(e.sk, s, 1, 31) == SK_ERR_INVALID_ARG);
        e.gl.ActiveTexture(0x84C0);
        e.gl.DeleteTextures(1, &tex);
        skgl_shadow_destroy(e.sk, s);
    }
    free(ref); free(m);
    gt_env_free(&e);
}

/* ---- desc.layered: the pages SKGL_MAX_CASCADES at a pass ---- */

/* the callback of test_layered_batches: one draw per object, culled
   against the pass's frustums (any of a batch's), as an engine culls;
   what it saw: callbacks, draws, and per page (info->index or
   layer_index) the matrix it was handed and how often */
#define LB_PAGES 1024
typedef struct lb_counted {
    gt_env *e;
    skgl_caster *hook;             /* NULL: shadowkit's own program */
    void (*Uniform3f)(int, float, float, float);
    int callbacks, draws, bad_batch, seen[LB_PAGES];
    sk_mat4 vp[LB_PAGES];
} lb_counted;

static void lb_page_seen(lb_counted *c, int page, const sk_mat4 *vp) {
    if (page < 0 || page >= LB_PAGES) { c->bad_batch++; return; }
    c->seen[page]++;
    c->vp[page] = *vp;
}

static void lb_draw(void *user, const skgl_draw_info *info) {
    lb_counted *c = (lb_counted *)user;
    uint32_t i;
    int j;
    c->callbacks++;
    if (info->layers > 0) {
        if (info->index != -1 || info->layers > SKGL_MAX_CASCADES) c->bad_batch++;
        for (j = 0; j < info->layers; j++) lb_page_seen(c, info->layer_index[j], &info->layer_view_proj[j]);
    } else lb_page_seen(c, info->index, &info->view_proj);
    if (c->hook) {
        const int *loc = skgl_use_caster(c->e->sk, c->hook);
        if (!loc) { c->bad_batch++; return; }
        c->Uniform3f(loc[0], 0.0f, 0.0f, 0.0f);
    }
    for (i = 0; i < c->e->scene.object_count; i++) {
        const tb_object *o = &c->e->scene.objects[i];
        sk_frustum bf;
        int vis = sk_frustum_from_aabb(o->bounds, &bf) != SK_OK;
        if (!vis && info->layers == 0) vis = sk_frustum_intersects(&bf, &info->frustum);
        for (j = 0; !vis && j < info->layers; j++) vis = sk_frustum_intersects(&bf, &info->layer_frustum[j]);
        if (!vis) continue;
        tb_gl_mesh_draw(&c->e->gl, &c->e->mesh, o->first_index, o->index_count);
        c->draws++;
    }
}

/* texels of the first `slots` pool slots (pool a side, slot texels each)
   where the depth of two RMSM lights' pools differs (-1: not read) */
static long lb_pool_differ(gt_env *e, skgl_shadow *a, skgl_shadow *b, int pool, int slot, int slots,
                           double *worst) {
    typedef void (*fb_layer_fn)(unsigned, unsigned, unsigned, int, int);
    void *fp = tb_gl_context_getproc(e->ctx)("glFramebufferTextureLayer");
    fb_layer_fn layer;
    int side = pool * slot, k, x, y;
    float *d[2];
    unsigned fb = 0;
    long n = 0;
    skgl_shadow *s[2];
    s[0] = a; s[1] = b;
    memcpy(&layer, &fp, sizeof fp);
    d[0] = (float *)malloc(sizeof(float) * (size_t)side * (size_t)side);
    d[1] = (float *)malloc(sizeof(float) * (size_t)side * (size_t)side);
    if (!fp || !d[0] || !d[1]) n = -1;
    e->gl.GenFramebuffers(1, &fb);
    for (k = 0; k < 2 && n == 0; k++) {
        e->gl.BindFramebuffer(0x8D40 /* GL_FRAMEBUFFER */, fb);
        layer(0x8D40, 0x8D00 /* GL_DEPTH_ATTACHMENT */, skgl_shadow_texture(s[k]), 0, 0);
        if (tb_gl_read_depth(&e->gl, fb, side, side, d[k]) != 0) n = -1;
    }
    e->gl.BindFramebuffer(0x8D40, 0);
    e->gl.DeleteFramebuffers(1, &fb);
    for (k = 0; k < slots && n >= 0; k++)
        for (y = 0; y < slot; y++)
            for (x = 0; x < slot; x++) {
                size_t t = (size_t)((k / pool) * slot + y) * (size_t)side + (size_t)((k % pool) * slot + x);
                n += d[0][t] != d[1][t];
                if (fabs((double)d[0][t] - d[1][t]) > *worst) *worst = fabs((double)d[0][t] - d[1][t]);
            }
    free(d[0]); free(d[1]);
    return n;
}

static double lb_now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* The boxes view, pool 24^2 (572 pages of band 6), a pass per page
   (desc.layered 0) and SKGL_MAX_CASCADES pages a pass (desc.layered 1):
   the same pages, each handed to the callback once with the same matrix,
   the same shadow mask pixel for pixel (a page is drawn at the same
   window position either way: the same depth), ceil(pages / 8) callbacks;
   the render's CPU time, fastest of LB_RUNS each, in the same process. */
#define LB_RUNS 5
static void test_layered_batches(void) {
    const view_case *k = &views[0];
    gt_env e;
    skgl_camera cam = gt_camera(gt_v3(k->eye[0], k->eye[1], k->eye[2]),
                                gt_v3(k->target[0], k->target[1], k->target[2]), 1.0f, 0.1f, 250, W, H);
    sk_vec3 l = gt_v3(k->light[0], k->light[1], k->light[2]);
    static lb_counted c[2];
    skgl_shadow *s[2] = {NULL, NULL};
    skgl_scene sc;
    float *ref, *m[2];
    double best[2] = {1e30, 1e30}, er[2] = {-1, -1};
    tb_shadow_error se[2];
    int layered, pages[2] = {0, 0}, passes[2] = {0, 0}, stats_layered = 0, j, run;
    size_t i, differ = 0;
    long depth_differ;
    double worst = 0.0;
    if (gt_env_init_named(&e, k->scene, W, H) != 0) { gt_env_free(&e); return; }
    ref = gt_alloc(&e); m[0] = gt_alloc(&e); m[1] = gt_alloc(&e);
    memset(se, 0, sizeof se);
    SK_CHECK(gt_gbuffer(&e, &cam) == 0 && gt_reference(&e, l, ref) == 0);
    for (layered = 0; layered < 2; layered++) {
        skgl_shadow_desc d;
        const skgl_shadow_frame_stats *st;
        memset(&d, 0, sizeof d);
        d.technique = SKGL_RMSM;
        d.resolution = 16384;
        d.rmsm_page_size = 128;
        d.rmsm_pool_pages = 24;
        d.layered = layered;
        s[layered] = gt_shadow(&e, &d);
        memset(&c[layered], 0, sizeof c[layered]);
        c[layered].e = &e;
        sc = gt_scene(&e);
        sc.draw = lb_draw;
        sc.user = &c[layered];
        if (!s[layered] || rmsm_frame(&e, s[layered], &cam, &sc, l, 1, m[layered]) != 0) {
            SK_CHECK_MSG(0, "layered %d: frame failed", layered);
            continue;
        }
        st = skgl_shadow_stats(s[layered]);
        pages[layered] = st->pages_rendered;
        passes[layered] = st->passes;
        if (layered) stats_layered = st->layered;
        er[layered] = tb_metric_hard(ref, m[layered], e.n).pct;
        se[layered] = gt_shadow_error(&e, ref, m[layered]);
    }
    for (i = 0; i < e.n; i++) differ += m[0][i] != m[1][i];
    depth_differ = s[0] && s[1] ? lb_pool_differ(&e, s[0], s[1], 24, 130, pages[0], &worst) : -1;
    /* the render alone (the pages stay those of the analysis), in turns */
    for (run = 0; run < LB_RUNS && s[0] && s[1]; run++)
        for (layered = 0; layered < 2; layered++) {
            double t0;
            lb_counted scratch;
            memset(&scratch, 0, sizeof scratch);
            scratch.e = &e;
            sc = gt_scene(&e);
            sc.draw = lb_draw;
            sc.user = &scratch;
            e.gl.Finish();
            t0 = lb_now();
            SK_CHECK(skgl_shadow_render(e.sk, s[layered], &cam, &sc, l) == SK_OK);
            e.gl.Finish();
            t0 = lb_now() - t0;
            if (t0 < best[layered]) best[layered] = t0;
        }
    {
        char buf[2][256];
        int mism = 0, once = 0;
        for (j = 0; j < pages[0] && j < LB_PAGES; j++) {
            once += c[0].seen[j] == 1 && c[1].seen[j] == 1;
            mism += memcmp(&c[0].vp[j], &c[1].vp[j], sizeof(sk_mat4)) != 0;
        }
        printf("layered 0: %d pages, %d callbacks (%d draws), %.1f ms; error %.4f%%, %s\n", pages[0], c[0].callbacks,
               c[0].draws, 1e3 * best[0], er[0], gt_shadow_error_str(&se[0], buf[0], sizeof buf[0]));
        printf("layered 1: %d pages, %d callbacks (%d draws), %.1f ms; error %.4f%%, %s; stats.layered %d\n",
               pages[1], c[1].callbacks, c[1].draws, 1e3 * best[1], er[1],
               gt_shadow_error_str(&se[1], buf[1], sizeof buf[1]), stats_layered);
        printf("  %ld pool texels differ (by up to %.3g) and %zu pixels; time ratio %.2f; %d pages seen once each, "
               "%d with another matrix\n", depth_differ, worst, differ, best[1] / best[0], once, mism);
        SK_CHECK(pages[0] > 64 && pages[0] <= LB_PAGES && pages[1] == pages[0]);
        SK_CHECK_MSG(passes[0] == pages[0] && c[0].callbacks == pages[0], "per page: %d passes, %d callbacks",
                     passes[0], c[0].callbacks);
        SK_CHECK_MSG(passes[1] == (pages[1] + SKGL_MAX_CASCADES - 1) / SKGL_MAX_CASCADES &&
                         c[1].callbacks == passes[1] && stats_layered == (BATCHES_ONLY ? 1 : 2),
                     "batched: %d passes, %d callbacks for %d pages", passes[1], c[1].callbacks, pages[1]);
        SK_CHECK_MSG(once == pages[0] && mism == 0 && c[0].bad_batch == 0 && c[1].bad_batch == 0,
                     "%d of %d pages seen once each, %d with another matrix, %d bad batches", once, pages[0], mism,
                     c[1].bad_batch);
        /* the same depth but in the last bits: the geometry shader's
           matrix product rounds a few vertices otherwise than the vertex
           shader's (15744 of 9.67 M page texels, 0.16%, by up to 1.79e-7,
           3 ulps; bounds 0.23% and 2.5e-7), too little to move one pixel
           of the mask */
        SK_CHECK_MSG(depth_differ >= 0 && depth_differ <= (long)(0.0023 * pages[0] * 130.0 * 130.0) &&
                         worst <= 2.5e-7,
                     "%ld texels of the pages' slots differ, by up to %g", depth_differ, worst);
        SK_CHECK_MSG(differ == 0 && er[0] >= 0 && er[1] == er[0], "%zu pixels differ (%.4f%% vs %.4f%%)", differ,
                     er[1], er[0]);
    }
    /* through a caster program (skgl_caster_create; the batches through
       its layered version): the same pages again, the same comparison */
    if (s[0] && s[1]) {
        static lb_counted hc[2];
        skgl_caster *hook = NULL;
        void *fp = tb_gl_context_getproc(e.ctx)("glUniform3f");
        double hworst = 0.0;
        long hdepth = -1;
        size_t hdiffer = 0;
        hook = gt_offset_caster(&e);
        for (layered = 0; layered < 2 && hook; layered++) {
            memset(&hc[layered], 0, sizeof hc[layered]);
            hc[layered].e = &e;
            hc[layered].hook = hook;
            memcpy(&hc[layered].Uniform3f, &fp, sizeof fp);
            sc = gt_scene(&e);
            sc.draw = lb_draw;
            sc.user = &hc[layered];
            SK_CHECK(rmsm_frame(&e, s[layered], &cam, &sc, l, 0, m[layered]) == 0);
        }
        if (hook) {
            for (i = 0; i < e.n; i++) hdiffer += m[0][i] != m[1][i];
            hdepth = lb_pool_differ(&e, s[0], s[1], 24, 130, pages[0], &hworst);
        }
        printf("caster program: %d -> %d callbacks, %ld pool texels differ (by up to %.3g), %zu pixels\n",
               hc[0].callbacks, hc[1].callbacks, hdepth, hworst, hdiffer);
        SK_CHECK(hc[0].callbacks == pages[0] && hc[1].callbacks == passes[1] && hc[0].bad_batch == 0 &&
                 hc[1].bad_batch == 0);
        SK_CHECK_MSG(hdepth >= 0 && hdepth <= (long)(0.0023 * pages[0] * 130.0 * 130.0) && hworst <= 2.5e-7 &&
                         hdiffer == 0,
                     "caster program: %ld texels differ by up to %g, %zu pixels", hdepth, hworst, hdiffer);
        skgl_caster_destroy(e.sk, hook);
    }
    SK_CHECK(e.gl.GetError() == 0);
    skgl_shadow_destroy(e.sk, s[0]);
    skgl_shadow_destroy(e.sk, s[1]);
    free(ref); free(m[0]); free(m[1]);
    gt_env_free(&e);
}

SK_TEST_MAIN(test_pages_match_cpu, test_accuracy, test_degraded, test_layered_batches)
