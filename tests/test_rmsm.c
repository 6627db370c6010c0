/* tests/test_rmsm.c - RMSM level of detail and page requests (Romanick's VGP353 notes,
   "Resolution Matched Shadow Maps", after Lefohn et al. 2007).

   Expected values come from the slide's formulas evaluated here in double:
     dX = (ds/dx, dt/dx), dY = (ds/dy, dt/dy), A = |dX x dY|, l = log2(sqrt(A))
   and from a brute-force page oracle: each sample's (level, px, py) computed
   in this file, then sorted by (level, py, px) and made unique. */
#define SHADOWKIT_IMPLEMENTATION
#include "shadowkit.h"
#include "tests/sk_test.h"
#include <stdlib.h>

static sk_vec2 v2(float x, float y) { sk_vec2 r; r.x = x; r.y = y; return r; }
static sk_vec3 v3(float x, float y, float z) { sk_vec3 r; r.x = x; r.y = y; r.z = z; return r; }

/* fixed-seed LCG: runs are reproducible */
static unsigned rng_state = 12345u;
static double rnd(void) {
    rng_state = rng_state * 1664525u + 1013904223u;
    return (double)(rng_state >> 8) / 16777216.0;          /* [0,1) */
}
static double rnd_range(double a, double b) { return a + (b - a) * rnd(); }

static double lod_ref(double ax, double ay, double bx, double by) {
    double a = fabs(ax * by - ay * bx);
    return log2(sqrt(a));
}

/* ---------------------------------------------------------------- lod */
static void test_rmsm_lod_values(void) {
    static const float c[][4] = {
        { 1, 0, 0, 1 },         /* one texel per pixel: lod 0 */
        { 4, 0, 0, 4 },         /* 4x4 texels per pixel: lod 2 */
        { 0.25f, 0, 0, 0.25f }, /* magnified: lod -2 */
        { 3, 1, -2, 5 },        /* skewed: |15 + 2| = 17 */
        { 1, 2, 3, 4 },         /* negative cross product: |4 - 6| = 2 */
        { 0, 1, 1, 0 },         /* mirrored axes: |0 - 1| = 1 */
        { 8, 0, 0, 0.5f },      /* anisotropic: area 4 -> lod 1 */
        { 1024, 0, 0, 1024 },   /* lod 10 */
        { -7.5f, 2.25f, 0.125f, -3 },
    };
    int i;
    for (i = 0; i < (int)(sizeof c / sizeof c[0]); i++) {
        double ref = lod_ref(c[i][0], c[i][1], c[i][2], c[i][3]);
        float got = sk_rmsm_lod(v2(c[i][0], c[i][1]), v2(c[i][2], c[i][3]));
        SK_CHECK_NEAR(got, ref, 1e-5 * (fabs(ref) > 1 ? fabs(ref) : 1));
    }
    /* exact spot values worked by hand */
    SK_CHECK_NEAR(sk_rmsm_lod(v2(4, 0), v2(0, 4)), 2.0, 1e-6);
    SK_CHECK_NEAR(sk_rmsm_lod(v2(0.25f, 0), v2(0, 0.25f)), -2.0, 1e-6);
    SK_CHECK_NEAR(sk_rmsm_lod(v2(8, 0), v2(0, 0.5f)), 1.0, 1e-6);
}

static void test_rmsm_lod_properties(void) {
    int i;
    for (i = 0; i < 200; i++) {
        double ax = rnd_range(-10, 10), ay = rnd_range(-10, 10);
        double bx = rnd_range(-10, 10), by = rnd_range(-10, 10);
        double ang = rnd_range(0, 6.283185307179586), k = rnd_range(0.1, 8);
        double cs = cos(ang), sn = sin(ang);
        double ref = lod_ref(ax, ay, bx, by);
        float l0, lr, ls;
        if (fabs(ax * by - ay * bx) < 1e-2) continue;   /* keep away from zero area */
        l0 = sk_rmsm_lod(v2((float)ax, (float)ay), v2((float)bx, (float)by));
        SK_CHECK_NEAR(l0, ref, 1e-4);
        /* rotating both derivatives keeps the area: same lod */
        lr = sk_rmsm_lod(v2((float)(cs * ax - sn * ay), (float)(sn * ax + cs * ay)),
                         v2((float)(cs * bx - sn * by), (float)(sn * bx + cs * by)));
        SK_CHECK_NEAR(lr, ref, 1e-3);
        /* scaling both by k scales the area by k^2: lod + log2 k */
        ls = sk_rmsm_lod(v2((float)(k * ax), (float)(k * ay)), v2((float)(k * bx), (float)(k * by)));
        SK_CHECK_NEAR(ls, ref + log2(k), 1e-3);
        /* swapping dX and dY flips the sign of the cross product only */
        SK_CHECK_NEAR(sk_rmsm_lod(v2((float)bx, (float)by), v2((float)ax, (float)ay)), ref, 1e-4);
    }
}

static void test_rmsm_lod_bad_input(void) {
    float r;
    /* zero area: -INFINITY (documented) */
    r = sk_rmsm_lod(v2(0, 0), v2(0, 0));
    SK_CHECK(isinf(r) && r < 0);
    r = sk_rmsm_lod(v2(1, 2), v2(2, 4));           /* parallel */
    SK_CHECK(isinf(r) && r < 0);
    r = sk_rmsm_lod(v2(3, 0), v2(0, 0));
    SK_CHECK(isinf(r) && r < 0);
    /* NaN anywhere: -INFINITY (documented) */
    r = sk_rmsm_lod(v2(NAN, 0), v2(0, 1));
    SK_CHECK(isinf(r) && r < 0);
    r = sk_rmsm_lod(v2(1, 0), v2(0, NAN));
    SK_CHECK(isinf(r) && r < 0);
    r = sk_rmsm_lod(v2(NAN, NAN), v2(NAN, NAN));
    SK_CHECK(isinf(r) && r < 0);
    /* infinities: never NaN (library-wide rule) */
    r = sk_rmsm_lod(v2(INFINITY, 1), v2(1, 0));   /* INF*0 inside the cross product */
    SK_CHECK_MSG(!isnan(r), "lod = %g", (double)r);
    r = sk_rmsm_lod(v2(INFINITY, 0), v2(0, 1));
    SK_CHECK_MSG(!isnan(r), "lod = %g", (double)r);
    r = sk_rmsm_lod(v2(-INFINITY, INFINITY), v2(INFINITY, -INFINITY));
    SK_CHECK_MSG(!isnan(r), "lod = %g", (double)r);
}

/* ---------------------------------------------------------------- pages */
static int ilog2i(int v) { int l = 0; while ((1 << l) < v) l++; return l; }

static int page_cmp(const void *pa, const void *pb) {
    const sk_page *a = (const sk_page *)pa, *b = (const sk_page *)pb;
    if (a->level != b->level) return a->level < b->level ? -1 : 1;
    if (a->py != b->py) return a->py < b->py ? -1 : 1;
    if (a->px != b->px) return a->px < b->px ? -1 : 1;
    return 0;
}

/* brute force: out must hold count entries */
static int oracle_pages(const sk_vec3 *s, int count, int vres, int psize, sk_page *out) {
    int levels = ilog2i(vres / psize), n = 0, i, u = 0;
    for (i = 0; i < count; i++) {
        double x = s[i].x, y = s[i].y, lod = s[i].z, fl;
        int level, pages;
        if (!(x >= 0.0 && x < 1.0 && y >= 0.0 && y < 1.0)) continue;
        fl = floor(lod);
        level = fl <= 0.0 ? 0 : (fl >= (double)levels ? levels : (int)fl);
        pages = (vres >> level) / psize;
        out[n].level = level;
        out[n].px = (int)floor(x * pages);
        out[n].py = (int)floor(y * pages);
        n++;
    }
    if (n == 0) return 0;
    qsort(out, (size_t)n, sizeof *out, page_cmp);
    for (i = 1; i < n; i++)
        if (page_cmp(&out[i], &out[u]) != 0) out[++u] = out[i];
    return u + 1;
}

static void check_against_oracle(const sk_vec3 *s, int count, int vres, int psize, const char *what) {
    sk_page *want = (sk_page *)malloc(sizeof(sk_page) * (size_t)(count + 1));
    sk_page *got = (sk_page *)malloc(sizeof(sk_page) * (size_t)(count + 1));
    int nw = oracle_pages(s, count, vres, psize, want), ng, i, same = 1;
    ng = sk_rmsm_page_requests(s, count, vres, psize, got, count + 1);
    SK_CHECK_MSG(ng == nw, "%s: %d requests, oracle %d", what, ng, nw);
    if (ng == nw)
        for (i = 0; i < nw; i++)
            if (page_cmp(&got[i], &want[i]) != 0) {
                SK_CHECK_MSG(0, "%s: request %d = (level %d, px %d, py %d), oracle (level %d, px %d, py %d)",
                             what, i, got[i].level, got[i].px, got[i].py,
                             want[i].level, want[i].px, want[i].py);
                same = 0;
                break;
            }
    if (ng == nw && same) SK_CHECK(1);
    /* exactly enough capacity works; one less is a capacity error */
    if (nw > 0) {
        SK_CHECK(sk_rmsm_page_requests(s, count, vres, psize, got, nw) == nw);
        SK_CHECK_MSG(sk_rmsm_page_requests(s, count, vres, psize, got, nw - 1) == -SK_ERR_CAPACITY,
                     "%s: cap %d < %d requests", what, nw - 1, nw);
    }
    free(want);
    free(got);
}

static void test_rmsm_pages_random(void) {
    static const int cfg[][2] = { { 1024, 64 }, { 256, 256 }, { 4096, 128 }, { 64, 1 }, { 1, 1 }, { 1 << 20, 1 << 12 } };
    int c;
    for (c = 0; c < (int)(sizeof cfg / sizeof cfg[0]); c++) {
        int n = 600, i;
        int levels = ilog2i(cfg[c][0] / cfg[c][1]);
        sk_vec3 *s = (sk_vec3 *)malloc(sizeof(sk_vec3) * (size_t)n);
        char what[128];
        for (i = 0; i < n; i++)
            s[i] = v3((float)rnd_range(-0.1, 1.1), (float)rnd_range(-0.1, 1.1),
                      (float)rnd_range(-2.0, levels + 2.5));
        sprintf(what, "random vres %d page %d", cfg[c][0], cfg[c][1]);
        check_against_oracle(s, n, cfg[c][0], cfg[c][1], what);
        /* samples concentrated near page borders at integer lods */
        for (i = 0; i < n; i++) {
            int pages = cfg[c][0] / cfg[c][1];
            float sx = (float)((double)(int)(rnd() * pages) / pages);
            s[i] = v3(sx, i % 2 ? nextafterf(sx, 0.0f) : sx, (float)(int)rnd_range(-1, levels + 2));
            if (!(s[i].y >= 0)) s[i].y = 0;
        }
        sprintf(what, "borders vres %d page %d", cfg[c][0], cfg[c][1]);
        check_against_oracle(s, n, cfg[c][0], cfg[c][1], what);
        free(s);
    }
}

static void test_rmsm_pages_hand(void) {
    /* virtual 1024^2, pages 64^2: level 0 has 16x16 pages, level 4 has 1 page */
    sk_vec3 s[16];
    sk_page out[16];
    int n;
    s[0] = v3(0.0f, 0.0f, 0.0f);                       /* level 0, page (0,0) */
    s[1] = v3(0.5f, 0.25f, 1.0f);                      /* level 1 (8x8 pages): (4,2) */
    s[2] = v3(0.5f, 0.25f, 0.999f);                    /* floor -> level 0: (8,4) */
    s[3] = v3(nextafterf(1.0f, 0.0f), 0.999f, 2.5f);   /* level 2 (4x4): (3,3) */
    s[4] = v3(1.0f, 0.5f, 0.0f);                       /* s == 1: skipped */
    s[5] = v3(0.5f, -0.001f, 0.0f);                    /* t < 0: skipped */
    s[6] = v3(NAN, 0.5f, 0.0f);                        /* NaN: skipped */
    s[7] = v3(0.5f, INFINITY, 0.0f);                   /* Inf: skipped */
    s[8] = v3(0.3f, 0.3f, -INFINITY);                  /* zero-area lod: clamped to 0: (4,4) */
    s[9] = v3(0.3f, 0.3f, INFINITY);                   /* clamped to level 4: (0,0) */
    s[10] = v3(0.9f, 0.1f, 100.0f);                    /* clamped to level 4: duplicate */
    s[11] = v3(0.0f, 0.0f, -3.0f);                     /* duplicate of s[0] */
    n = sk_rmsm_page_requests(s, 12, 1024, 64, out, 16);
    SK_CHECK(n == 6);
    if (n == 6) {
        /* sorted by (level, py, px) */
        SK_CHECK(out[0].level == 0 && out[0].px == 0 && out[0].py == 0);
        SK_CHECK(out[1].level == 0 && out[1].px == 4 && out[1].py == 4);
        SK_CHECK(out[2].level == 0 && out[2].px == 8 && out[2].py == 4);
        SK_CHECK(out[3].level == 1 && out[3].px == 4 && out[3].py == 2);
        SK_CHECK(out[4].level == 2 && out[4].px == 3 && out[4].py == 3);
        SK_CHECK(out[5].level == 4 && out[5].px == 0 && out[5].py == 0);
    }
    /* all samples in one page: one request */
    s[0] = v3(0.01f, 0.01f, 0.2f);
    s[1] = v3(0.05f, 0.02f, 0.7f);
    s[2] = v3(0.06f, 0.06f, -5.0f);
    n = sk_rmsm_page_requests(s, 3, 1024, 64, out, 16);
    SK_CHECK(n == 1);
    if (n == 1) SK_CHECK(out[0].level == 0 && out[0].px == 0 && out[0].py == 0);
    /* every sample skipped: no request */
    s[0] = v3(1.5f, 0.5f, 0.0f);
    s[1] = v3(-0.5f, 0.5f, 0.0f);
    s[2] = v3(0.5f, NAN, 0.0f);
    n = sk_rmsm_page_requests(s, 3, 1024, 64, out, 16);
    SK_CHECK(n == 0);
    /* page_size == virtual_res: a single level with a single page */
    s[0] = v3(0.9f, 0.9f, 7.0f);
    s[1] = v3(0.1f, 0.2f, 0.0f);
    n = sk_rmsm_page_requests(s, 2, 512, 512, out, 16);
    SK_CHECK(n == 1);
    if (n == 1) SK_CHECK(out[0].level == 0 && out[0].px == 0 && out[0].py == 0);
}

static void test_rmsm_pages_full_grid(void) {
    /* one sample in the middle of every level-0 page: all 8x8 pages, row by row */
    sk_vec3 s[64];
    sk_page out[64];
    int i, n, ok = 1;
    for (i = 0; i < 64; i++) {
        int px = 63 - i, x = px % 8, y = px / 8;       /* fed in reverse order */
        s[i] = v3((float)((x + 0.5) / 8.0), (float)((y + 0.5) / 8.0), 0.5f);
    }
    n = sk_rmsm_page_requests(s, 64, 256, 32, out, 64);
    SK_CHECK(n == 64);
    if (n == 64)
        for (i = 0; i < 64; i++)
            if (out[i].level != 0 || out[i].px != i % 8 || out[i].py != i / 8) ok = 0;
    SK_CHECK(ok);
    SK_CHECK(sk_rmsm_page_requests(s, 64, 256, 32, out, 63) == -SK_ERR_CAPACITY);
}

static int pages_untouched(const sk_page *p, int n) {
    int i;
    for (i = 0; i < n; i++)
        if (p[i].level != -7 || p[i].px != -7 || p[i].py != -7) return 0;
    return 1;
}

static void test_rmsm_pages_bad_input(void) {
    sk_vec3 s[2];
    sk_page out[4];
    int i, r;
    s[0] = v3(0.5f, 0.5f, 0.0f);
    s[1] = v3(0.25f, 0.75f, 1.0f);
#define BAD(call) do { for (i = 0; i < 4; i++) { out[i].level = out[i].px = out[i].py = -7; } \
        r = (call); SK_CHECK_MSG(r == -SK_ERR_INVALID_ARG, "%s -> %d", #call, r); \
        SK_CHECK_MSG(pages_untouched(out, 4), "%s wrote to out", #call); } while (0)
    BAD(sk_rmsm_page_requests(s, 2, 0, 64, out, 4));
    BAD(sk_rmsm_page_requests(s, 2, -1024, 64, out, 4));
    BAD(sk_rmsm_page_requests(s, 2, 1000, 8, out, 4));      /* not a power of two */
    BAD(sk_rmsm_page_requests(s, 2, 1024, 0, out, 4));
    BAD(sk_rmsm_page_requests(s, 2, 1024, -64, out, 4));
    BAD(sk_rmsm_page_requests(s, 2, 1024, 48, out, 4));     /* not a power of two */
    BAD(sk_rmsm_page_requests(s, 2, 1024, 2048, out, 4));   /* page larger than the map */
    BAD(sk_rmsm_page_requests(s, -1, 1024, 64, out, 4));
    BAD(sk_rmsm_page_requests(NULL, 2, 1024, 64, out, 4));
    BAD(sk_rmsm_page_requests(s, 2, 1024, 64, NULL, 4));
    BAD(sk_rmsm_page_requests(s, 2, 1024, 64, out, -1));
#undef BAD
    /* no sample at all: nothing to request (0), or rejected as a zero count */
    r = sk_rmsm_page_requests(s, 0, 1024, 64, out, 4);
    SK_CHECK_MSG(r == 0 || r == -SK_ERR_INVALID_ARG, "count 0 -> %d", r);
}

SK_TEST_MAIN(test_rmsm_lod_values, test_rmsm_lod_properties, test_rmsm_lod_bad_input,
             test_rmsm_pages_random, test_rmsm_pages_hand, test_rmsm_pages_full_grid,
             test_rmsm_pages_bad_input)
