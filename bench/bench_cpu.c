/* bench/bench_cpu.c - CPU benchmark of shadowkit.h (issue 3, item 5)

   Build and run (what `make bench-cpu` does):
       gcc -std=c99 -O2 -I. bench/bench_cpu.c -o build/bench_cpu -lm
       ./build/bench_cpu

   What it measures
   1. Every public function of shadowkit.h: nanoseconds per call, the median
      over 31 batches (g_batches); each batch times enough calls to last at
      least 2.5 ms (g_batch_s). Inputs are realistic (a 60 degree 16:9 camera,
      zn 0.1, zf 100; a directional light 40 degrees above the horizon; a
      point light of range 5; caster boxes; ...) and vary from call to call,
      taken from precomputed arrays of BENCH_NV variants. Every call goes
      through a function pointer the compiler cannot see through (as a call
      from another translation unit would), so nothing is inlined, hoisted
      or folded; results are summed into a volatile sink. Target: < 1000 ns.
      Functions whose cost scales with their data are marked "scales with
      data" and their input size is printed instead of pass/fail.
   2. sk_estimate_resolution on a synthetic 1920x1080 depth buffer (ground
      plane and boxes, sky = 1.0), in Mpixel/s, and a naive per-pixel
      reference written here (each pixel's four corners computed
      independently, depth re-read and averaged each time, every point
      unprojected to world space and projected into light space with its own
      w-divides), timed in the same run. Both must agree: samples identical,
      width and height identical or within 5% (they hinge on the one smallest
      patch, on a depth edge, where float rounding moves it by a few per
      cent; a double-precision evaluation shows which is closer).
      Target: >= 50 Mpixel/s on one core.
   It always exits 0 (a report), after a summary line.
   Optional argument: "quick" (fewer, shorter batches; for a smoke test). */
#define _POSIX_C_SOURCE 199309L
#define SHADOWKIT_IMPLEMENTATION
#include "shadowkit.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define BENCH_PI 3.14159265358979323846
#define BENCH_NV 64                 /* input variants per function (power of two) */
#define BENCH_M (BENCH_NV - 1)
#define BENCH_TARGET_NS 1000.0
#define BENCH_TARGET_MPIX 50.0
#define RES_W 1920
#define RES_H 1080
#ifdef __OPTIMIZE__
#define BENCH_OPT_NOTE " (optimised)"
#else
#define BENCH_OPT_NOTE " (NOT optimised: build with -O2)"
#endif
#define RES_MAX 65536               /* max_res for the estimate (high enough not to clamp) */

static int g_batches = 31;          /* batches per function (median taken) */
static double g_batch_s = 2.5e-3;   /* minimum batch duration */
static int g_res_runs = 9;          /* full-HD estimate runs per variant */

/* ------------------------------------------------------------------------ */
/* timing and sinks                                                          */
/* ------------------------------------------------------------------------ */
static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static volatile double g_sink;      /* every kernel's accumulated results end here */
static long g_bad;                  /* calls that returned an error (per function) */

/* Opaque function pointers: the compiler cannot know which function is
   called, so it cannot inline it, hoist it out of the loop or drop it. */
typedef void (*bench_anyfn)(void);
static bench_anyfn volatile g_fnbox;
static bench_anyfn opaque(bench_anyfn f) { g_fnbox = f; return g_fnbox; }
#define OPAQUE(T, fn) ((T)opaque((bench_anyfn)(fn)))

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y ? 1 : 0;
}
static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return (n & 1) ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* ------------------------------------------------------------------------ */
/* small double-precision math, independent of the library (used to build   */
/* the full-HD scene so its set-up does not depend on what is measured)     */
/* ------------------------------------------------------------------------ */
typedef struct dmat4 { double m[16]; } dmat4;
typedef struct dvec3 { double x, y, z; } dvec3;

static dvec3 dv(double x, double y, double z) { dvec3 r; r.x = x; r.y = y; r.z = z; return r; }
static dvec3 dsub(dvec3 a, dvec3 b) { return dv(a.x - b.x, a.y - b.y, a.z - b.z); }
static double ddot(dvec3 a, dvec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static dvec3 dcross(dvec3 a, dvec3 b)
{
    return dv(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static dvec3 dnorm(dvec3 a)
{
    double l = sqrt(ddot(a, a));
    return dv(a.x / l, a.y / l, a.z / l);
}
static dmat4 dmul(dmat4 a, dmat4 b)
{
    dmat4 r;
    int c, i, k;
    for (c = 0; c < 4; ++c)
        for (i = 0; i < 4; ++i) {
            double s = 0.0;
            for (k = 0; k < 4; ++k) s += a.m[k * 4 + i] * b.m[c * 4 + k];
            r.m[c * 4 + i] = s;
        }
    return r;
}
static dmat4 dperspective(double fovy, double aspect, double zn, double zf)
{
    dmat4 r;
    double f = 1.0 / tan(fovy * 0.5);
    memset(&r, 0, sizeof r);
    r.m[0] = f / aspect;
    r.m[5] = f;
    r.m[10] = (zf + zn) / (zn - zf);
    r.m[11] = -1.0;
    r.m[14] = 2.0 * zf * zn / (zn - zf);
    return r;
}
static dmat4 dortho(double l, double r_, double b, double t, double zn, double zf)
{
    dmat4 r;
    memset(&r, 0, sizeof r);
    r.m[0] = 2.0 / (r_ - l);
    r.m[5] = 2.0 / (t - b);
    r.m[10] = -2.0 / (zf - zn);
    r.m[12] = -(r_ + l) / (r_ - l);
    r.m[13] = -(t + b) / (t - b);
    r.m[14] = -(zf + zn) / (zf - zn);
    r.m[15] = 1.0;
    return r;
}
static dmat4 dlookat(dvec3 eye, dvec3 target, dvec3 up)
{
    dmat4 r;
    dvec3 f = dnorm(dsub(target, eye));
    dvec3 s = dnorm(dcross(f, up));
    dvec3 u = dcross(s, f);
    memset(&r, 0, sizeof r);
    r.m[0] = s.x; r.m[4] = s.y; r.m[8] = s.z;
    r.m[1] = u.x; r.m[5] = u.y; r.m[9] = u.z;
    r.m[2] = -f.x; r.m[6] = -f.y; r.m[10] = -f.z;
    r.m[12] = -ddot(s, eye);
    r.m[13] = -ddot(u, eye);
    r.m[14] = ddot(f, eye);
    r.m[15] = 1.0;
    return r;
}
static int dinverse(dmat4 a, dmat4 *out)   /* Gauss-Jordan, partial pivoting */
{
    double t[4][8];
    int i, j, k;
    for (i = 0; i < 4; ++i)
        for (j = 0; j < 4; ++j) {
            t[i][j] = a.m[j * 4 + i];
            t[i][j + 4] = (i == j) ? 1.0 : 0.0;
        }
    for (k = 0; k < 4; ++k) {
        int p = k;
        double piv;
        for (i = k + 1; i < 4; ++i)
            if (fabs(t[i][k]) > fabs(t[p][k])) p = i;
        if (fabs(t[p][k]) < 1e-300) return 0;
        if (p != k)
            for (j = 0; j < 8; ++j) { double s = t[k][j]; t[k][j] = t[p][j]; t[p][j] = s; }
        piv = t[k][k];
        for (j = 0; j < 8; ++j) t[k][j] /= piv;
        for (i = 0; i < 4; ++i)
            if (i != k) {
                double f = t[i][k];
                for (j = 0; j < 8; ++j) t[i][j] -= f * t[k][j];
            }
    }
    for (i = 0; i < 4; ++i)
        for (j = 0; j < 4; ++j) out->m[j * 4 + i] = t[i][j + 4];
    return 1;
}
static void dxform(const dmat4 *m, double x, double y, double z, double w, double o[4])
{
    int i;
    for (i = 0; i < 4; ++i)
        o[i] = m->m[i] * x + m->m[4 + i] * y + m->m[8 + i] * z + m->m[12 + i] * w;
}
static sk_mat4 to_sk(dmat4 a)
{
    sk_mat4 r;
    int i;
    for (i = 0; i < 16; ++i) r.m[i] = (float)a.m[i];
    return r;
}

/* ------------------------------------------------------------------------ */
/* benchmark inputs                                                          */
/* ------------------------------------------------------------------------ */
static unsigned long g_rng = 0x2545F491UL;
static float rnd(void)                       /* uniform in [0,1) */
{
    g_rng = (g_rng * 1103515245UL + 12345UL) & 0x7fffffffUL;
    return (float)((g_rng >> 7) & 0xffffff) / 16777216.0f;
}
static float rnds(void) { return 2.0f * rnd() - 1.0f; }  /* [-1,1) */

static sk_vec2 v2(float x, float y) { sk_vec2 r; r.x = x; r.y = y; return r; }
static sk_vec3 v3(float x, float y, float z) { sk_vec3 r; r.x = x; r.y = y; r.z = z; return r; }
static sk_aabb box3(float x0, float y0, float z0, float x1, float y1, float z1)
{
    sk_aabb b;
    b.min = v3(x0, y0, z0);
    b.max = v3(x1, y1, z1);
    return b;
}

#define GRID_W 64
#define GRID_H 64
#define GRID_VARIANTS 4
#define RMSM_SAMPLES 10000
#define RMSM_VARIANTS 2
#define VSDCT_NI 16
#define SMOOTH_BOX 8.0f

static struct bench_inputs {
    /* camera */
    sk_vec3 eye[BENCH_NV], target[BENCH_NV], view_dir[BENCH_NV];
    float fovy[BENCH_NV], aspect[BENCH_NV];
    sk_mat4 view[BENCH_NV], proj[BENCH_NV], vp[BENCH_NV];
    sk_frustum frus[BENCH_NV];
    /* directional light */
    sk_vec3 ldir[BENCH_NV];
    sk_mat4 lview[BENCH_NV];
    /* point light (range 5) and casters */
    sk_vec3 lpos[BENCH_NV];
    sk_aabb caster[BENCH_NV];
    sk_frustum face_frus[BENCH_NV];
    float cube_zn[BENCH_NV], cube_zf[BENCH_NV];
    /* scene */
    sk_aabb scene, caster_bounds;
    sk_aabb casters4[4];
    /* derived from the library at set-up */
    sk_vec3 clip_pts[BENCH_NV][SK_CLIP_MAX_POINTS];
    int clip_n[BENCH_NV];
    float split_d0[BENCH_NV], split_d1[BENCH_NV];
    sk_frustum slice[BENCH_NV];
    sk_sphere sphere[BENCH_NV];
    sk_psm_desc psm[BENCH_NV];
    sk_lispsm_desc lispsm[BENCH_NV];
    sk_lspsm_region region[BENCH_NV];
    float part_n[BENCH_NV], part_L[BENCH_NV], part_theta[BENCH_NV];
    sk_lspsm_params params;
    sk_vsdct_layout layout;
    /* generic varied inputs */
    sk_vec3 wpt[BENCH_NV];            /* world points around the scene */
    sk_vec4 wpt4[BENCH_NV];
    sk_vec3 dir[BENCH_NV];            /* unit directions */
    sk_rect rect[BENCH_NV];           /* light-clip sub-rects */
    float zr0[BENCH_NV], zr1[BENCH_NV];
    float s[BENCH_NV][8];             /* scalars in [0,1) */
    int face_res[BENCH_NV], faces[BENCH_NV];
    sk_vec2 pu0[BENCH_NV], pv0[BENCH_NV], pu1[BENCH_NV], pv1[BENCH_NV];
    /* data-sized inputs */
    float grid[GRID_VARIANTS][GRID_W * GRID_H * 2];
    float pyramid[GRID_W * GRID_H * 2 * 2];
    sk_tile tiles[GRID_W * GRID_H];
    sk_vec3 rmsm[RMSM_VARIANTS][RMSM_SAMPLES];
    sk_page pages[RMSM_SAMPLES];
    unsigned short indirection[6 * VSDCT_NI * VSDCT_NI * 2];
    unsigned char litmap[64][64];
} g;

static int lit_cb(void *user, int tx, int ty)
{
    const unsigned char (*map)[64] = (const unsigned char (*)[64])user;
    return map[ty & 63][tx & 63];
}

static void setup_inputs(void)
{
    int i, j, x, y;
    const double el = 40.0 * BENCH_PI / 180.0;

    g.scene = box3(-30.0f, -0.5f, -30.0f, 30.0f, 5.0f, 30.0f);
    g.caster_bounds = box3(-6.0f, 0.0f, -12.0f, 6.0f, 4.0f, 3.0f);
    g.casters4[0] = box3(-3.0f, 0.0f, -2.0f, -1.0f, 2.0f, 0.0f);
    g.casters4[1] = box3(2.0f, 0.0f, -6.0f, 4.0f, 3.0f, -4.0f);
    g.casters4[2] = box3(-6.0f, 0.0f, -12.0f, -3.0f, 4.0f, -9.0f);
    g.casters4[3] = box3(0.8f, 0.0f, 11.0f, 1.0f, 3.0f, 11.2f);  /* behind the camera */
    g.params = sk_lspsm_default_params();

    for (i = 0; i < BENCH_NV; ++i) {
        double az = (30.0 + 4.0 * rnds()) * BENCH_PI / 180.0;
        double e = el + 0.02 * rnds();
        sk_vec3 up = v3(0.0f, 1.0f, 0.0f);
        float d;

        g.eye[i] = v3(0.5f * rnds(), 1.7f + 0.2f * rnds(), 8.0f + 0.5f * rnds());
        g.target[i] = v3(1.5f * rnds(), 1.0f + 0.3f * rnds(), 0.0f);
        g.view_dir[i] = v3(g.target[i].x - g.eye[i].x, g.target[i].y - g.eye[i].y,
                           g.target[i].z - g.eye[i].z);
        d = sqrtf(g.view_dir[i].x * g.view_dir[i].x + g.view_dir[i].y * g.view_dir[i].y +
                  g.view_dir[i].z * g.view_dir[i].z);
        g.view_dir[i].x /= d; g.view_dir[i].y /= d; g.view_dir[i].z /= d;
        g.fovy[i] = (float)((60.0 + 0.5 * rnds()) * BENCH_PI / 180.0);
        g.aspect[i] = 16.0f / 9.0f + 0.01f * rnds();
        g.view[i] = sk_mat4_look_at(g.eye[i], g.target[i], up);
        g.proj[i] = sk_mat4_perspective((float)(60.0 * BENCH_PI / 180.0), 16.0f / 9.0f, 0.1f, 100.0f);
        g.vp[i] = sk_mat4_mul(g.proj[i], g.view[i]);
        g.frus[i] = sk_frustum_from_matrix(g.vp[i]);

        g.ldir[i] = v3((float)(-cos(e) * cos(az)), (float)-sin(e), (float)(-cos(e) * sin(az)));
        g.lview[i] = sk_light_view_directional(g.ldir[i]);

        g.lpos[i] = v3(2.0f + 0.3f * rnds(), 3.0f + 0.3f * rnds(), 1.0f + 0.3f * rnds());
        {
            float cx = 1.5f + 0.3f * rnds(), cz = -0.5f + 0.3f * rnds();
            g.caster[i] = box3(cx - 0.5f, 0.0f, cz - 0.5f, cx + 0.5f, 1.5f + 0.2f * rnd(), cz + 0.5f);
        }
        g.cube_zn[i] = 0.05f + 0.01f * rnd();
        g.cube_zf[i] = 5.0f + rnd();
        g.face_frus[i] = sk_frustum_from_matrix(
            sk_mat4_mul(sk_cube_face_proj(0.05f, 5.0f), sk_cube_face_view(i % 6, g.lpos[i])));

        g.wpt[i] = v3(10.0f * rnds(), 2.5f + 2.5f * rnds(), 10.0f * rnds());
        g.wpt4[i].x = g.wpt[i].x; g.wpt4[i].y = g.wpt[i].y; g.wpt4[i].z = g.wpt[i].z; g.wpt4[i].w = 1.0f;
        {
            float a = rnd() * 6.2831853f, z = rnds(), r = sqrtf(1.0f - z * z);
            g.dir[i] = v3(r * cosf(a), r * sinf(a), z);
        }
        {
            float cx = 0.4f * rnds(), cy = 0.4f * rnds(), hw = 0.2f + 0.4f * rnd(), hh = 0.2f + 0.4f * rnd();
            g.rect[i].x0 = cx - hw; g.rect[i].x1 = cx + hw;
            g.rect[i].y0 = cy - hh; g.rect[i].y1 = cy + hh;
            g.zr0[i] = -1.0f + 0.3f * rnd();
            g.zr1[i] = 0.7f + 0.3f * rnd();
        }
        for (j = 0; j < 8; ++j) g.s[i][j] = rnd();
        g.face_res[i] = 256 << (i % 4);
        g.faces[i] = 1 + i % 6;
        g.pu0[i] = v2(0.01f + 0.01f * rnd(), 0.002f * rnds());
        g.pv0[i] = v2(0.002f * rnds(), 0.008f + 0.01f * rnd());
        g.pu1[i] = v2(0.0005f + 0.0005f * rnd(), 0.0001f * rnds());
        g.pv1[i] = v2(0.0001f * rnds(), 0.0006f + 0.0005f * rnd());
    }

    /* derived inputs (from the library itself) */
    for (i = 0; i < BENCH_NV; ++i) {
        int c = i & 3, k;
        double zn = 0.1, zf = 100.0, lambda = 0.75, f0, f1;
        k = sk_clip_frustum_aabb(&g.frus[i], g.scene, g.clip_pts[i], SK_CLIP_MAX_POINTS);
        g.clip_n[i] = k > 0 ? k : 0;
        if (g.clip_n[i] == 0) {          /* keep fit_ortho's input valid anyway */
            for (k = 0; k < 8; ++k) g.clip_pts[i][k] = g.frus[i].corners[k];
            g.clip_n[i] = 8;
        }
        f0 = lambda * zn * pow(zf / zn, c / 4.0) + (1.0 - lambda) * (zn + (zf - zn) * c / 4.0);
        f1 = lambda * zn * pow(zf / zn, (c + 1) / 4.0) + (1.0 - lambda) * (zn + (zf - zn) * (c + 1) / 4.0);
        g.split_d0[i] = (float)f0;
        g.split_d1[i] = (float)(c == 3 ? zf : f1);
        if (sk_frustum_slice(&g.frus[i], 0.1f, 100.0f, g.split_d0[i], g.split_d1[i], &g.slice[i]) != SK_OK)
            g.slice[i] = g.frus[i];
        g.sphere[i] = sk_frustum_bounding_sphere(&g.slice[i]);

        memset(&g.psm[i], 0, sizeof g.psm[i]);
        g.psm[i].cam_view = g.view[i];
        g.psm[i].fovy = (float)(60.0 * BENCH_PI / 180.0);
        g.psm[i].aspect = 16.0f / 9.0f;
        g.psm[i].zn = 0.1f;
        g.psm[i].zf = 100.0f;
        g.psm[i].light_dir = g.ldir[i];
        g.psm[i].casters = g.casters4;
        g.psm[i].caster_count = 4;

        memset(&g.lispsm[i], 0, sizeof g.lispsm[i]);
        g.lispsm[i].eye = g.eye[i];
        g.lispsm[i].view_dir = g.view_dir[i];
        g.lispsm[i].zn = 0.1f;
        g.lispsm[i].light_dir = g.ldir[i];
        g.lispsm[i].body = g.clip_pts[i];
        g.lispsm[i].body_count = g.clip_n[i];
        g.lispsm[i].casters = &g.caster_bounds;
        g.lispsm[i].n_override = 0.0f;

        memset(&g.region[i], 0, sizeof g.region[i]);
        if (sk_lspsm_region_extract(&g.frus[i], g.view_dir[i], g.scene, &g.caster_bounds,
                                    g.ldir[i], &g.region[i]) == SK_OK &&
            !g.region[i].fallback && g.region[i].n > 0.0f && g.region[i].L > 0.0f &&
            g.region[i].theta >= 0.0f && g.region[i].theta < 1.5f) {
            g.part_n[i] = g.region[i].n;
            g.part_L[i] = g.region[i].L;
            g.part_theta[i] = g.region[i].theta;
        } else {                          /* typical values if extraction fell back */
            g.part_n[i] = 2.0f + rnd();
            g.part_L[i] = 50.0f + 10.0f * rnd();
            g.part_theta[i] = 0.45f + 0.1f * rnd();
        }
    }
    if (sk_vsdct_layout_make(512, &g.layout) != SK_OK) {
        memset(&g.layout, 0, sizeof g.layout);   /* measured as-is; noted as errors */
    }

    /* SMTG grids: a camera at cell (32, 2) looking along +y, 70 degree wedge;
       near cells need ~1024 texels per cell span, far ones ~64; outside the
       wedge no sample (+INFINITY). Values are required texel sizes. */
    for (j = 0; j < GRID_VARIANTS; ++j)
        for (y = 0; y < GRID_H; ++y)
            for (x = 0; x < GRID_W; ++x) {
                float dx = (float)x + 0.5f - 32.0f + 1.5f * (float)j, dy = (float)y + 0.5f - 2.0f;
                float dist = sqrtf(dx * dx + dy * dy);
                float *c = &g.grid[j][(y * GRID_W + x) * 2];
                if (dy > 0.0f && fabsf(dx) < dy * 0.7f && dist < 60.0f) {
                    float need = 1024.0f / (1.0f + 0.25f * dist) * (0.9f + 0.2f * rnd());
                    float cell = 2.0f / (float)GRID_W;
                    c[0] = cell / need;
                    c[1] = cell / (need * (0.6f + 0.3f * rnd()));
                } else {
                    c[0] = c[1] = (float)INFINITY;
                }
            }

    /* RMSM samples as a 100x100 pixel read-back in scan-line order: a ground
       seen in perspective, s across, t along the view; near rows (small t)
       need fine levels, far rows coarse ones; a little per-pixel noise */
    for (j = 0; j < RMSM_VARIANTS; ++j)
        for (i = 0; i < RMSM_SAMPLES; ++i) {
            float u = ((float)(i % 100) + 0.5f) / 100.0f, v = ((float)(i / 100) + 0.5f) / 100.0f;
            float t = 0.05f + 0.9f * v * v + 0.001f * rnds() + 0.01f * (float)j;
            float s = 0.5f + (u - 0.5f) * (0.1f + 0.8f * v) + 0.001f * rnds();
            float lod = -1.0f + 8.0f * v + 0.3f * rnds();
            g.rmsm[j][i] = v3(s, t, lod);
        }

    for (y = 0; y < 64; ++y)
        for (x = 0; x < 64; ++x)
            g.litmap[y][x] = (unsigned char)(((x / 3 + y / 5) & 1) | (rnd() < 0.1f));
}

/* ------------------------------------------------------------------------ */
/* kernels: each makes n calls and returns the accumulated results           */
/* ------------------------------------------------------------------------ */
#define LOOP for (i = 0; i < n; ++i)
#define IX ((int)(i & BENCH_M))

static double k_result_string(long n)
{
    typedef const char *(*F)(sk_result);
    F f = OPAQUE(F, sk_result_string);
    double acc = 0.0; long i;
    LOOP { const char *s = f((sk_result)(i % 5)); acc += (unsigned char)s[0]; }
    return acc;
}
static double k_mat4_identity(long n)
{
    typedef sk_mat4 (*F)(void);
    F f = OPAQUE(F, sk_mat4_identity);
    double acc = 0.0; long i;
    LOOP { sk_mat4 r = f(); acc += r.m[i & 15]; }
    return acc;
}
static double k_mat4_mul(long n)
{
    typedef sk_mat4 (*F)(sk_mat4, sk_mat4);
    F f = OPAQUE(F, sk_mat4_mul);
    double acc = 0.0; long i;
    LOOP { sk_mat4 r = f(g.proj[IX], g.view[IX]); acc += r.m[0] + r.m[14]; }
    return acc;
}
static double k_mat4_inverse(long n)
{
    typedef int (*F)(sk_mat4, sk_mat4 *);
    F f = OPAQUE(F, sk_mat4_inverse);
    double acc = 0.0; long i; long bad = 0;
    LOOP { sk_mat4 r; int ok = f(g.vp[IX], &r); bad += !ok; acc += ok ? r.m[0] + r.m[15] : 0.0; }
    g_bad += bad;
    return acc;
}
static double k_mat4_perspective(long n)
{
    typedef sk_mat4 (*F)(float, float, float, float);
    F f = OPAQUE(F, sk_mat4_perspective);
    double acc = 0.0; long i;
    LOOP { sk_mat4 r = f(g.fovy[IX], g.aspect[IX], 0.1f, 100.0f); acc += r.m[0] + r.m[14]; }
    return acc;
}
static double k_mat4_ortho(long n)
{
    typedef sk_mat4 (*F)(float, float, float, float, float, float);
    F f = OPAQUE(F, sk_mat4_ortho);
    double acc = 0.0; long i;
    LOOP {
        const sk_rect *r = &g.rect[IX];
        sk_mat4 m = f(r->x0 * 40.0f, r->x1 * 40.0f, r->y0 * 40.0f, r->y1 * 40.0f, -50.0f, 50.0f + g.s[IX][0]);
        acc += m.m[0] + m.m[14];
    }
    return acc;
}
static double k_mat4_look_at(long n)
{
    typedef sk_mat4 (*F)(sk_vec3, sk_vec3, sk_vec3);
    F f = OPAQUE(F, sk_mat4_look_at);
    double acc = 0.0; long i;
    sk_vec3 up = v3(0.0f, 1.0f, 0.0f);
    LOOP { sk_mat4 r = f(g.eye[IX], g.target[IX], up); acc += r.m[0] + r.m[14]; }
    return acc;
}
static double k_mat4_transform_point(long n)
{
    typedef sk_vec3 (*F)(sk_mat4, sk_vec3);
    F f = OPAQUE(F, sk_mat4_transform_point);
    double acc = 0.0; long i;
    LOOP { sk_vec3 r = f(g.vp[IX], g.wpt[(i + 7) & BENCH_M]); acc += r.x + r.z; }
    return acc;
}
static double k_mat4_transform_vec4(long n)
{
    typedef sk_vec4 (*F)(sk_mat4, sk_vec4);
    F f = OPAQUE(F, sk_mat4_transform_vec4);
    double acc = 0.0; long i;
    LOOP { sk_vec4 r = f(g.vp[IX], g.wpt4[(i + 7) & BENCH_M]); acc += r.x + r.w; }
    return acc;
}
static double k_frustum_from_matrix(long n)
{
    typedef sk_frustum (*F)(sk_mat4);
    F f = OPAQUE(F, sk_frustum_from_matrix);
    double acc = 0.0; long i;
    LOOP { sk_frustum r = f(g.vp[IX]); acc += r.planes[5].d + r.corners[7].x; }
    return acc;
}
static double k_frustum_from_corners(long n)
{
    typedef sk_result (*F)(const sk_vec3 *, sk_frustum *);
    F f = OPAQUE(F, sk_frustum_from_corners);
    double acc = 0.0; long i, bad = 0;
    LOOP { sk_frustum r; sk_result e = f(g.frus[IX].corners, &r); bad += e != SK_OK; acc += r.planes[5].d; }
    g_bad += bad;
    return acc;
}
static double k_frustum_from_aabb(long n)
{
    typedef sk_result (*F)(sk_aabb, sk_frustum *);
    F f = OPAQUE(F, sk_frustum_from_aabb);
    double acc = 0.0; long i, bad = 0;
    LOOP { sk_frustum r; sk_result e = f(g.caster[IX], &r); bad += e != SK_OK; acc += r.planes[5].d; }
    g_bad += bad;
    return acc;
}
static double k_frustum_contains_point(long n)
{
    typedef int (*F)(const sk_frustum *, sk_vec3);
    F f = OPAQUE(F, sk_frustum_contains_point);
    double acc = 0.0; long i;
    LOOP acc += f(&g.frus[IX], g.wpt[(i + 13) & BENCH_M]);
    return acc;
}
static double k_clip_frustum_aabb(long n)
{
    typedef int (*F)(const sk_frustum *, sk_aabb, sk_vec3 *, int);
    F f = OPAQUE(F, sk_clip_frustum_aabb);
    sk_vec3 out[SK_CLIP_MAX_POINTS];
    double acc = 0.0; long i, bad = 0;
    LOOP { int k = f(&g.frus[IX], g.scene, out, SK_CLIP_MAX_POINTS); bad += k <= 0; acc += k > 0 ? k + out[0].x : 0.0; }
    g_bad += bad;
    return acc;
}
static double k_aliasing_error(long n)
{
    typedef float (*F)(float, float, float, float, float);
    F f = OPAQUE(F, sk_aliasing_error);
    double acc = 0.0; long i;
    LOOP {
        const float *s = g.s[IX];
        acc += f(0.5f + s[0], 1080.0f, 2048.0f, 0.2f + 0.8f * s[1], 0.1f + 0.9f * s[2]);
    }
    return acc;
}
static double k_rmsm_lod(long n)
{
    typedef float (*F)(sk_vec2, sk_vec2);
    F f = OPAQUE(F, sk_rmsm_lod);
    double acc = 0.0; long i;
    LOOP {
        const float *s = g.s[IX];
        acc += f(v2(0.5f + 4.0f * s[0], s[1] - 0.5f), v2(s[2] - 0.5f, 0.5f + 4.0f * s[3]));
    }
    return acc;
}
static double k_crop_matrix(long n)
{
    typedef sk_mat4 (*F)(sk_rect, float, float);
    F f = OPAQUE(F, sk_crop_matrix);
    double acc = 0.0; long i;
    LOOP { sk_mat4 r = f(g.rect[IX], g.zr0[IX], g.zr1[IX]); acc += r.m[0] + r.m[14]; }
    return acc;
}
static double k_pssm_splits(long n)
{
    typedef sk_result (*F)(float, float, int, float, float *);
    F f = OPAQUE(F, sk_pssm_splits);
    float out[SK_MAX_SPLITS + 1];
    double acc = 0.0; long i, bad = 0;
    LOOP { sk_result e = f(0.1f, 100.0f, 4, 0.5f + 0.5f * g.s[IX][0], out); bad += e != SK_OK; acc += out[1]; }
    g_bad += bad;
    return acc;
}
static double k_frustum_slice(long n)
{
    typedef sk_result (*F)(const sk_frustum *, float, float, float, float, sk_frustum *);
    F f = OPAQUE(F, sk_frustum_slice);
    double acc = 0.0; long i, bad = 0;
    LOOP {
        sk_frustum r;
        sk_result e = f(&g.frus[IX], 0.1f, 100.0f, g.split_d0[IX], g.split_d1[IX], &r);
        bad += e != SK_OK;
        acc += r.corners[7].x;
    }
    g_bad += bad;
    return acc;
}
static double k_frustum_bounding_sphere(long n)
{
    typedef sk_sphere (*F)(const sk_frustum *);
    F f = OPAQUE(F, sk_frustum_bounding_sphere);
    double acc = 0.0; long i;
    LOOP { sk_sphere s = f(&g.slice[IX]); acc += s.r + s.c.x; }
    return acc;
}
static double k_cascade_sphere(long n)
{
    typedef sk_sphere (*F)(sk_mat4, float, float, float, float);
    F f = OPAQUE(F, sk_cascade_sphere);
    double acc = 0.0; long i;
    LOOP { sk_sphere s = f(g.view[IX], g.fovy[IX], g.aspect[IX], g.split_d0[IX], g.split_d1[IX]); acc += s.r + s.c.x; }
    return acc;
}
static double k_light_view_directional(long n)
{
    typedef sk_mat4 (*F)(sk_vec3);
    F f = OPAQUE(F, sk_light_view_directional);
    double acc = 0.0; long i;
    LOOP { sk_mat4 r = f(g.ldir[IX]); acc += r.m[0] + r.m[14]; }
    return acc;
}
static double k_fit_ortho(long n)
{
    typedef sk_result (*F)(const sk_vec3 *, int, sk_mat4, const sk_aabb *, sk_mat4 *);
    F f = OPAQUE(F, sk_fit_ortho);
    double acc = 0.0; long i, bad = 0;
    LOOP {
        sk_mat4 r;
        sk_result e = f(g.clip_pts[IX], g.clip_n[IX], g.lview[IX], &g.scene, &r);
        bad += e != SK_OK;
        acc += r.m[0];
    }
    g_bad += bad;
    return acc;
}
static double k_stable_crop(long n)
{
    typedef sk_result (*F)(sk_sphere, sk_mat4, int, const sk_aabb *, sk_mat4 *);
    F f = OPAQUE(F, sk_stable_crop);
    double acc = 0.0; long i, bad = 0;
    LOOP {
        sk_mat4 r;
        sk_result e = f(g.sphere[IX], g.lview[IX], 2048, &g.scene, &r);
        bad += e != SK_OK;
        acc += r.m[0];
    }
    g_bad += bad;
    return acc;
}
static double k_psm_matrices(long n)
{
    typedef sk_result (*F)(const sk_psm_desc *, sk_psm_result *);
    F f = OPAQUE(F, sk_psm_matrices);
    double acc = 0.0; long i, bad = 0;
    LOOP {
        sk_psm_result r;
        sk_result e = f(&g.psm[IX], &r);
        bad += e != SK_OK;
        acc += r.light_view_proj.m[0];
    }
    g_bad += bad;
    return acc;
}
static double k_lispsm_matrices(long n)
{
    typedef sk_result (*F)(const sk_lispsm_desc *, sk_lispsm_result *);
    F f = OPAQUE(F, sk_lispsm_matrices);
    double acc = 0.0; long i, bad = 0;
    LOOP {
        sk_lispsm_result r;
        sk_result e = f(&g.lispsm[IX], &r);
        bad += e != SK_OK;
        acc += r.light_view_proj.m[0];
    }
    g_bad += bad;
    return acc;
}
static double k_lspsm_default_params(long n)
{
    typedef sk_lspsm_params (*F)(void);
    F f = OPAQUE(F, sk_lspsm_default_params);
    double acc = 0.0; long i;
    LOOP { sk_lspsm_params p = f(); acc += p.zeta + p.h_max; }
    return acc;
}
static double k_lspsm_partition(long n)
{
    typedef int (*F)(float, float, float, const sk_lspsm_params *, sk_rect *, int);
    F f = OPAQUE(F, sk_lspsm_partition);
    sk_rect out[64];
    double acc = 0.0; long i, bad = 0;
    LOOP {
        int k = f(g.part_n[IX], g.part_L[IX], g.part_theta[IX], &g.params, out, 64);
        bad += k <= 0;
        acc += k > 0 ? k + out[k - 1].y1 : 0.0;
    }
    g_bad += bad;
    return acc;
}
static double k_lspsm_region_extract(long n)
{
    typedef sk_result (*F)(const sk_frustum *, sk_vec3, sk_aabb, const sk_aabb *, sk_vec3, sk_lspsm_region *);
    F f = OPAQUE(F, sk_lspsm_region_extract);
    double acc = 0.0; long i, bad = 0;
    LOOP {
        sk_lspsm_region r;
        sk_result e = f(&g.frus[IX], g.view_dir[IX], g.scene, &g.caster_bounds, g.ldir[IX], &r);
        bad += e != SK_OK;
        acc += e == SK_OK ? r.L : 0.0;
    }
    g_bad += bad;
    return acc;
}
static double k_lspsm_crops(long n)
{
    typedef int (*F)(const sk_lspsm_region *, const sk_lspsm_params *, sk_mat4 *, sk_rect *, int);
    F f = OPAQUE(F, sk_lspsm_crops);
    sk_mat4 vps[64];
    sk_rect rects[64];
    double acc = 0.0; long i, bad = 0;
    LOOP {
        int k = f(&g.region[IX], &g.params, vps, rects, 64);
        bad += k <= 0;
        acc += k > 0 ? k + vps[k - 1].m[0] : 0.0;
    }
    g_bad += bad;
    return acc;
}
static double k_cube_face_view(long n)
{
    typedef sk_mat4 (*F)(int, sk_vec3);
    F f = OPAQUE(F, sk_cube_face_view);
    double acc = 0.0; long i;
    LOOP { sk_mat4 r = f((int)(i % 6), g.lpos[IX]); acc += r.m[0] + r.m[14]; }
    return acc;
}
static double k_cube_face_proj(long n)
{
    typedef sk_mat4 (*F)(float, float);
    F f = OPAQUE(F, sk_cube_face_proj);
    double acc = 0.0; long i;
    LOOP { sk_mat4 r = f(g.cube_zn[IX], g.cube_zf[IX]); acc += r.m[10] + r.m[14]; }
    return acc;
}
static double k_frustum_intersects(long n)
{
    typedef int (*F)(const sk_frustum *, const sk_frustum *);
    F f = OPAQUE(F, sk_frustum_intersects);
    double acc = 0.0; long i;
    LOOP acc += f(&g.frus[IX], &g.face_frus[(i * 5 + 3) & BENCH_M]);
    return acc;
}
static double k_cube_visible_faces(long n)
{
    typedef unsigned (*F)(sk_vec3, float, float, const sk_frustum *);
    F f = OPAQUE(F, sk_cube_visible_faces);
    double acc = 0.0; long i;
    LOOP acc += f(g.lpos[IX], 0.05f, 5.0f, &g.frus[(i + 11) & BENCH_M]);
    return acc;
}
static double k_caster_shadow_frustum(long n)
{
    typedef sk_result (*F)(sk_vec3, float, sk_aabb, sk_frustum *);
    F f = OPAQUE(F, sk_caster_shadow_frustum);
    double acc = 0.0; long i, bad = 0;
    LOOP {
        sk_frustum r;
        sk_result e = f(g.lpos[IX], 5.0f, g.caster[(i + 3) & BENCH_M], &r);
        bad += e != SK_OK;
        acc += e == SK_OK ? r.planes[0].d : 0.0;
    }
    g_bad += bad;
    return acc;
}
static double k_caster_visible(long n)
{
    typedef int (*F)(sk_vec3, float, sk_aabb, const sk_frustum *);
    F f = OPAQUE(F, sk_caster_visible);
    double acc = 0.0; long i;
    LOOP acc += f(g.lpos[IX], 5.0f, g.caster[(i + 3) & BENCH_M], &g.frus[(i + 17) & BENCH_M]);
    return acc;
}
static double k_light_scissor(long n)
{
    typedef int (*F)(sk_vec3, float, sk_mat4, int, int, int *);
    F f = OPAQUE(F, sk_light_scissor);
    double acc = 0.0; long i;
    LOOP {
        int rect[4];
        int k = f(g.lpos[IX], 5.0f, g.vp[(i + 5) & BENCH_M], 1920, 1080, rect);
        acc += k + rect[2];
    }
    return acc;
}
static double k_cube_resolution(long n)
{
    typedef int (*F)(int, float, float, int);
    F f = OPAQUE(F, sk_cube_resolution);
    double acc = 0.0; long i;
    LOOP acc += f(g.faces[IX], 2073600.0f * (0.1f + 0.9f * g.s[IX][0]), 1.0f + g.s[IX][1], 2048);
    return acc;
}
static double k_vsdct_layout_make(long n)
{
    typedef sk_result (*F)(int, sk_vsdct_layout *);
    F f = OPAQUE(F, sk_vsdct_layout_make);
    double acc = 0.0; long i, bad = 0;
    LOOP {
        sk_vsdct_layout l;
        sk_result e = f(g.face_res[IX], &l);
        bad += e != SK_OK;
        acc += e == SK_OK ? l.atlas_w + l.face_x[5] : 0;
    }
    g_bad += bad;
    return acc;
}
static double k_vsdct_indirection_size(long n)
{
    typedef int (*F)(int, int, int);
    F f = OPAQUE(F, sk_vsdct_indirection_size);
    double acc = 0.0; long i;
    LOOP acc += f(g.face_res[IX], 256 << (i & 7), 4 + (int)(i & 3));
    return acc;
}
static double k_vsdct_depth_coeffs(long n)
{
    typedef void (*F)(float, float, float *, float *);
    F f = OPAQUE(F, sk_vsdct_depth_coeffs);
    double acc = 0.0; long i;
    LOOP { float s, b; f(g.cube_zn[IX], g.cube_zf[IX], &s, &b); acc += s + b; }
    return acc;
}
static double k_vsdct_lookup(long n)
{
    typedef int (*F)(const sk_vsdct_layout *, sk_vec3, float *, float *);
    F f = OPAQUE(F, sk_vsdct_lookup);
    double acc = 0.0; long i, bad = 0;
    LOOP {
        float u = 0.0f, v = 0.0f;
        int face = f(&g.layout, g.dir[IX], &u, &v);
        bad += face < 0;
        acc += face + u + v;
    }
    g_bad += bad;
    return acc;
}
static double k_vsdct_indirection_fill(long n)
{
    typedef sk_result (*F)(const sk_vsdct_layout *, int, unsigned short *);
    F f = OPAQUE(F, sk_vsdct_indirection_fill);
    double acc = 0.0; long i, bad = 0;
    LOOP {
        sk_result e = f(&g.layout, VSDCT_NI, g.indirection);
        bad += e != SK_OK;
        acc += g.indirection[(i * 37) % (6 * VSDCT_NI * VSDCT_NI * 2)];
    }
    g_bad += bad;
    return acc;
}
static double k_rho_dynamic(long n)
{
    typedef float (*F)(float);
    F f = OPAQUE(F, sk_rho_dynamic);
    double acc = 0.0; long i;
    LOOP acc += f(1.0f + 3000.0f * g.s[IX][0]);
    return acc;
}
static double k_rho_static(long n)
{
    typedef float (*F)(float);
    F f = OPAQUE(F, sk_rho_static);
    double acc = 0.0; long i;
    LOOP acc += f(1.0f + 300.0f * g.s[IX][0]);
    return acc;
}
static double k_convolve_parallelograms(long n)
{
    typedef void (*F)(sk_vec2, sk_vec2, sk_vec2, sk_vec2, sk_vec2 *, sk_vec2 *);
    F f = OPAQUE(F, sk_convolve_parallelograms);
    double acc = 0.0; long i;
    LOOP {
        sk_vec2 u, v;
        f(g.pu0[IX], g.pv0[IX], g.pu1[(i + 9) & BENCH_M], g.pv1[(i + 9) & BENCH_M], &u, &v);
        acc += u.x + v.y;
    }
    return acc;
}
static double k_texel_box_coverage(long n)
{
    typedef float (*F)(float, float, float, float, int, int);
    F f = OPAQUE(F, sk_texel_box_coverage);
    double acc = 0.0; long i;
    LOOP {
        const float *s = g.s[IX];
        float x0 = 10.0f + s[0], y0 = 20.0f + s[1];
        acc += f(x0, y0, x0 + 0.5f + 2.0f * s[2], y0 + 0.5f + 2.0f * s[3], 10 + (int)(i & 1), 20 + (int)((i >> 1) & 1));
    }
    return acc;
}
static double k_smooth_box_visibility(long n)
{
    typedef float (*F)(float, float, float, float, int (*)(void *, int, int), void *);
    F f = OPAQUE(F, sk_smooth_box_visibility);
    double acc = 0.0; long i;
    LOOP {
        float x0 = 10.0f + 20.0f * g.s[IX][0], y0 = 5.0f + 20.0f * g.s[IX][1];
        acc += f(x0, y0, x0 + SMOOTH_BOX, y0 + SMOOTH_BOX, lit_cb, (void *)g.litmap);
    }
    return acc;
}
static double k_pvsm_predict(long n)
{
    typedef void (*F)(sk_vec2, sk_vec2, sk_vec2, sk_vec2, int, float *, float *);
    F f = OPAQUE(F, sk_pvsm_predict);
    double acc = 0.0; long i;
    LOOP {
        float r0, r1;
        f(g.pu0[IX], g.pv0[IX], g.pu1[(i + 9) & BENCH_M], g.pv1[(i + 9) & BENCH_M], (int)(i & 1), &r0, &r1);
        acc += r0 + r1;
    }
    return acc;
}
static double k_pvsm_merge(long n)
{
    typedef void (*F)(float *, float *, float, float);
    F f = OPAQUE(F, sk_pvsm_merge);
    double acc = 0.0; long i;
    LOOP {
        float v = g.s[IX][0], a = 1.0f + g.s[IX][1];
        f(&v, &a, g.s[IX][2], 0.5f + g.s[IX][3]);
        acc += v + a;
    }
    return acc;
}
static double k_smtg_pyramid_size(long n)
{
    typedef int (*F)(int, int);
    F f = OPAQUE(F, sk_smtg_pyramid_size);
    double acc = 0.0; long i;
    LOOP acc += f(16 << (i & 7), 9 << ((i >> 3) & 7));
    return acc;
}
static double k_smtg_pyramid(long n)
{
    typedef int (*F)(const float *, int, int, float *, int);
    F f = OPAQUE(F, sk_smtg_pyramid);
    double acc = 0.0; long i, bad = 0;
    LOOP {
        int k = f(g.grid[i & (GRID_VARIANTS - 1)], GRID_W, GRID_H, g.pyramid,
                  (int)(sizeof g.pyramid / sizeof g.pyramid[0]));
        bad += k <= 0;
        acc += k + g.pyramid[GRID_W * GRID_H * 2];
    }
    g_bad += bad;
    return acc;
}
static double k_fvsm_tiles(long n)
{
    typedef int (*F)(const float *, int, int, int, sk_tile *, int);
    F f = OPAQUE(F, sk_fvsm_tiles);
    double acc = 0.0; long i, bad = 0;
    LOOP {
        int k = f(g.grid[i & (GRID_VARIANTS - 1)], GRID_W, GRID_H, 2048, g.tiles,
                  (int)(sizeof g.tiles / sizeof g.tiles[0]));
        bad += k <= 0;
        acc += k > 0 ? k + g.tiles[k - 1].res_x : 0;
    }
    g_bad += bad;
    return acc;
}
static double k_rmsm_page_requests(long n)
{
    typedef int (*F)(const sk_vec3 *, int, int, int, sk_page *, int);
    F f = OPAQUE(F, sk_rmsm_page_requests);
    double acc = 0.0; long i, bad = 0;
    LOOP {
        int k = f(g.rmsm[i & (RMSM_VARIANTS - 1)], RMSM_SAMPLES, 16384, 128, g.pages, RMSM_SAMPLES);
        bad += k <= 0;
        acc += k > 0 ? k + g.pages[k - 1].px : 0;
    }
    g_bad += bad;
    return acc;
}

/* sk_estimate_resolution: timed in its own section (full HD), see below */
static double k_estimate_resolution(long n);

typedef double (*kernel_fn)(long n);
typedef struct bench_item {
    const char *name;
    kernel_fn fn;
    const char *size;          /* non-NULL: cost scales with data; the size used */
} bench_item;

static char g_size_smtg[64] = "64x64 grid";
static char g_size_fvsm[64] = "64x64 grid, max_res 2048";
static char g_size_rmsm[64] = "10000 samples";

static const bench_item g_items[] = {
    { "sk_result_string", k_result_string, NULL },
    { "sk_mat4_identity", k_mat4_identity, NULL },
    { "sk_mat4_mul", k_mat4_mul, NULL },
    { "sk_mat4_inverse", k_mat4_inverse, NULL },
    { "sk_mat4_perspective", k_mat4_perspective, NULL },
    { "sk_mat4_ortho", k_mat4_ortho, NULL },
    { "sk_mat4_look_at", k_mat4_look_at, NULL },
    { "sk_mat4_transform_point", k_mat4_transform_point, NULL },
    { "sk_mat4_transform_vec4", k_mat4_transform_vec4, NULL },
    { "sk_frustum_from_matrix", k_frustum_from_matrix, NULL },
    { "sk_frustum_from_corners", k_frustum_from_corners, NULL },
    { "sk_frustum_from_aabb", k_frustum_from_aabb, NULL },
    { "sk_frustum_contains_point", k_frustum_contains_point, NULL },
    { "sk_clip_frustum_aabb", k_clip_frustum_aabb, NULL },
    { "sk_aliasing_error", k_aliasing_error, NULL },
    { "sk_rmsm_lod", k_rmsm_lod, NULL },
    { "sk_crop_matrix", k_crop_matrix, NULL },
    { "sk_pssm_splits", k_pssm_splits, NULL },
    { "sk_frustum_slice", k_frustum_slice, NULL },
    { "sk_frustum_bounding_sphere", k_frustum_bounding_sphere, NULL },
    { "sk_cascade_sphere", k_cascade_sphere, NULL },
    { "sk_light_view_directional", k_light_view_directional, NULL },
    { "sk_fit_ortho", k_fit_ortho, NULL },
    { "sk_stable_crop", k_stable_crop, NULL },
    { "sk_psm_matrices", k_psm_matrices, NULL },
    { "sk_lispsm_matrices", k_lispsm_matrices, NULL },
    { "sk_lspsm_default_params", k_lspsm_default_params, NULL },
    { "sk_lspsm_partition", k_lspsm_partition, NULL },
    { "sk_lspsm_region_extract", k_lspsm_region_extract, NULL },
    { "sk_lspsm_crops", k_lspsm_crops, NULL },
    { "sk_cube_face_view", k_cube_face_view, NULL },
    { "sk_cube_face_proj", k_cube_face_proj, NULL },
    { "sk_frustum_intersects", k_frustum_intersects, NULL },
    { "sk_cube_visible_faces", k_cube_visible_faces, NULL },
    { "sk_caster_shadow_frustum", k_caster_shadow_frustum, NULL },
    { "sk_caster_visible", k_caster_visible, NULL },
    { "sk_light_scissor", k_light_scissor, NULL },
    { "sk_cube_resolution", k_cube_resolution, NULL },
    { "sk_vsdct_layout_make", k_vsdct_layout_make, NULL },
    { "sk_vsdct_indirection_size", k_vsdct_indirection_size, NULL },
    { "sk_vsdct_depth_coeffs", k_vsdct_depth_coeffs, NULL },
    { "sk_vsdct_lookup", k_vsdct_lookup, NULL },
    { "sk_vsdct_indirection_fill", k_vsdct_indirection_fill, "ni=16 (6x16x16 texels)" },
    { "sk_estimate_resolution", k_estimate_resolution, "1920x1080 depth buffer" },
    { "sk_rho_dynamic", k_rho_dynamic, NULL },
    { "sk_rho_static", k_rho_static, NULL },
    { "sk_convolve_parallelograms", k_convolve_parallelograms, NULL },
    { "sk_texel_box_coverage", k_texel_box_coverage, NULL },
    { "sk_smooth_box_visibility", k_smooth_box_visibility, "8x8 texel box" },
    { "sk_pvsm_predict", k_pvsm_predict, NULL },
    { "sk_pvsm_merge", k_pvsm_merge, NULL },
    { "sk_smtg_pyramid_size", k_smtg_pyramid_size, NULL },
    { "sk_smtg_pyramid", k_smtg_pyramid, g_size_smtg },
    { "sk_fvsm_tiles", k_fvsm_tiles, g_size_fvsm },
    { "sk_rmsm_page_requests", k_rmsm_page_requests, g_size_rmsm }
};
#define N_ITEMS ((int)(sizeof g_items / sizeof g_items[0]))

/* what the data-sized calls produce on these inputs, for the size column */
static void describe_sizes(void)
{
    int k = sk_smtg_pyramid(g.grid[0], GRID_W, GRID_H, g.pyramid, (int)(sizeof g.pyramid / sizeof g.pyramid[0]));
    snprintf(g_size_smtg, sizeof g_size_smtg, "%dx%d grid, %d levels", GRID_W, GRID_H, k);
    k = sk_fvsm_tiles(g.grid[0], GRID_W, GRID_H, 2048, g.tiles, (int)(sizeof g.tiles / sizeof g.tiles[0]));
    snprintf(g_size_fvsm, sizeof g_size_fvsm, "%dx%d grid, 2048 max -> %d tiles", GRID_W, GRID_H, k);
    k = sk_rmsm_page_requests(g.rmsm[0], RMSM_SAMPLES, 16384, 128, g.pages, RMSM_SAMPLES);
    snprintf(g_size_rmsm, sizeof g_size_rmsm, "%d samples -> %d pages", RMSM_SAMPLES, k);
}

/* ------------------------------------------------------------------------ */
/* full-HD scene for sk_estimate_resolution                                  */
/* ------------------------------------------------------------------------ */
#define N_BOXES 7
static const double g_boxes[N_BOXES][6] = {
    { -3.0, 0.0, -2.0, -1.0, 2.0, 0.0 },
    { 2.0, 0.0, -6.0, 4.0, 3.0, -4.0 },
    { -6.0, 0.0, -12.0, -3.0, 4.0, -9.0 },
    { 5.0, 0.0, 2.0, 6.0, 1.0, 3.0 },
    { 0.8, 0.0, 3.0, 1.0, 3.0, 3.2 },          /* a thin pole */
    { -10.0, 0.0, -20.0, 10.0, 1.0, -19.0 },    /* a long low wall */
    { -1.5, 0.0, 5.0, -0.5, 0.5, 6.0 }          /* a small box close to the camera */
};
#define GROUND_HALF 30.0

static struct res_scene {
    float *depth;
    sk_mat4 cam_inv_vp, light_vp;
    long valid;                   /* pixels with depth < 1 */
} g_rs;

static void build_res_scene(void)
{
    const double fovy = 60.0 * BENCH_PI / 180.0, el = 40.0 * BENCH_PI / 180.0, az = 30.0 * BENCH_PI / 180.0;
    dvec3 eye = dv(0.0, 4.0, 14.0), ldir;
    dmat4 vp = dmul(dperspective(fovy, (double)RES_W / RES_H, 0.1, 100.0),
                    dlookat(eye, dv(0.0, 0.5, 0.0), dv(0.0, 1.0, 0.0)));
    dmat4 inv, lview, lvp;
    double lo[3] = { 1e300, 1e300, 1e300 }, hi[3] = { -1e300, -1e300, -1e300 };
    int x, y, k;

    dinverse(vp, &inv);
    g_rs.depth = (float *)malloc(sizeof(float) * RES_W * RES_H);
    if (!g_rs.depth) { fprintf(stderr, "out of memory\n"); exit(0); }
    g_rs.valid = 0;
    for (y = 0; y < RES_H; ++y)
        for (x = 0; x < RES_W; ++x) {
            double nx = (x + 0.5) * 2.0 / RES_W - 1.0, ny = (y + 0.5) * 2.0 / RES_H - 1.0;
            double pf[4], clip[4];
            dvec3 d, p;
            double tbest = 1e300, dep = 1.0;
            dxform(&inv, nx, ny, 1.0, 1.0, pf);
            d = dnorm(dsub(dv(pf[0] / pf[3], pf[1] / pf[3], pf[2] / pf[3]), eye));
            if (d.y < 0.0) {                      /* ground plane y = 0, |x|,|z| <= 30 */
                double t = -eye.y / d.y;
                p = dv(eye.x + t * d.x, 0.0, eye.z + t * d.z);
                if (fabs(p.x) <= GROUND_HALF && fabs(p.z) <= GROUND_HALF) tbest = t;
            }
            for (k = 0; k < N_BOXES; ++k) {       /* slab test */
                double t0 = 0.0, t1 = tbest, o[3], dd[3];
                int a;
                o[0] = eye.x; o[1] = eye.y; o[2] = eye.z;
                dd[0] = d.x; dd[1] = d.y; dd[2] = d.z;
                for (a = 0; a < 3; ++a) {
                    double inv_d = 1.0 / dd[a];
                    double ta = (g_boxes[k][a] - o[a]) * inv_d, tb = (g_boxes[k][a + 3] - o[a]) * inv_d;
                    if (ta > tb) { double s = ta; ta = tb; tb = s; }
                    if (ta > t0) t0 = ta;
                    if (tb < t1) t1 = tb;
                }
                if (t0 <= t1 && t0 < tbest) tbest = t0;
            }
            if (tbest < 1e299) {
                p = dv(eye.x + tbest * d.x, eye.y + tbest * d.y, eye.z + tbest * d.z);
                dxform(&vp, p.x, p.y, p.z, 1.0, clip);
                dep = 0.5 * clip[2] / clip[3] + 0.5;
                if (!(dep < 1.0)) dep = 1.0;
            }
            g_rs.depth[y * RES_W + x] = (float)dep;
            if (g_rs.depth[y * RES_W + x] < 1.0f) g_rs.valid++;
        }

    /* directional light 40 degrees above the horizon; ortho around the scene */
    ldir = dv(-cos(el) * cos(az), -sin(el), -cos(el) * sin(az));
    lview = dlookat(dv(-ldir.x * 50.0, -ldir.y * 50.0, -ldir.z * 50.0), dv(0.0, 0.0, 0.0), dv(0.0, 1.0, 0.0));
    for (k = 0; k < 8; ++k) {
        double c[4], pt[3];
        int a;
        pt[0] = (k & 1) ? GROUND_HALF : -GROUND_HALF;
        pt[1] = (k & 2) ? 5.0 : 0.0;
        pt[2] = (k & 4) ? GROUND_HALF : -GROUND_HALF;
        dxform(&lview, pt[0], pt[1], pt[2], 1.0, c);
        for (a = 0; a < 3; ++a) {
            if (c[a] < lo[a]) lo[a] = c[a];
            if (c[a] > hi[a]) hi[a] = c[a];
        }
    }
    lvp = dmul(dortho(lo[0] - 0.5, hi[0] + 0.5, lo[1] - 0.5, hi[1] + 0.5, -hi[2] - 1.0, -lo[2] + 1.0), lview);
    g_rs.cam_inv_vp = to_sk(inv);
    g_rs.light_vp = to_sk(lvp);
}

/* The naive reference: per pixel, each of the four corners on its own (its
   depth the average of the valid pixels around it, re-read every time),
   each point unprojected to world space and then projected into light clip
   space, each with its own w-divide. Same outputs as sk_estimate_resolution. */
typedef struct naive_result {
    sk_rect bounds;
    float texel_w, texel_h;
    int width, height, samples;
} naive_result;

static void naive_xform(const sk_mat4 *m, float x, float y, float z, float w, float o[4])
{
    int i;
    for (i = 0; i < 4; ++i)
        o[i] = m->m[i] * x + m->m[4 + i] * y + m->m[8 + i] * z + m->m[12 + i] * w;
}
static int naive_valid(float d) { return d >= 0.0f && d < 1.0f; }

static void naive_estimate(const float *depth, int w, int h, sk_mat4 inv_vp, sk_mat4 light_vp,
                           int max_res, naive_result *out)
{
    int x, y, c, j;
    int samples = 0;
    float bx0 = 1.0f, by0 = 1.0f, bx1 = -1.0f, by1 = -1.0f;
    float tw = (float)INFINITY, th = (float)INFINITY;
    for (y = 0; y < h; ++y)
        for (x = 0; x < w; ++x) {
            float d = depth[y * w + x], wp[4], lc[4], lx, ly;
            float px0 = (float)INFINITY, py0 = (float)INFINITY, px1 = -(float)INFINITY, py1 = -(float)INFINITY;
            if (!naive_valid(d)) continue;
            /* the sample: pixel centre */
            naive_xform(&inv_vp, ((float)x + 0.5f) * 2.0f / (float)w - 1.0f,
                        ((float)y + 0.5f) * 2.0f / (float)h - 1.0f, 2.0f * d - 1.0f, 1.0f, wp);
            naive_xform(&light_vp, wp[0] / wp[3], wp[1] / wp[3], wp[2] / wp[3], 1.0f, lc);
            if (!(lc[3] > 0.0f && fabsf(lc[0]) <= lc[3] && fabsf(lc[1]) <= lc[3] && fabsf(lc[2]) <= lc[3]))
                continue;
            lx = lc[0] / lc[3];
            ly = lc[1] / lc[3];
            samples++;
            if (lx < bx0) bx0 = lx;
            if (lx > bx1) bx1 = lx;
            if (ly < by0) by0 = ly;
            if (ly > by1) by1 = ly;
            /* the patch: four corners, each computed independently */
            for (c = 0; c < 4; ++c) {
                int cx = x + (c & 1), cy = y + (c >> 1), cnt = 0;
                float sum = 0.0f, cd, cw[4], cl[4], qx, qy;
                for (j = 0; j < 4; ++j) {
                    int sx = cx - 1 + (j & 1), sy = cy - 1 + (j >> 1);
                    if (sx >= 0 && sx < w && sy >= 0 && sy < h && naive_valid(depth[sy * w + sx])) {
                        sum += depth[sy * w + sx];
                        cnt++;
                    }
                }
                cd = sum / (float)cnt;            /* cnt >= 1: the pixel itself is valid */
                naive_xform(&inv_vp, (float)cx * 2.0f / (float)w - 1.0f, (float)cy * 2.0f / (float)h - 1.0f,
                            2.0f * cd - 1.0f, 1.0f, cw);
                naive_xform(&light_vp, cw[0] / cw[3], cw[1] / cw[3], cw[2] / cw[3], 1.0f, cl);
                qx = cl[0] / cl[3];
                qy = cl[1] / cl[3];
                if (qx < px0) px0 = qx;
                if (qx > px1) px1 = qx;
                if (qy < py0) py0 = qy;
                if (qy > py1) py1 = qy;
            }
            if (px1 - px0 < tw) tw = px1 - px0;
            if (py1 - py0 < th) th = py1 - py0;
        }
    out->samples = samples;
    if (samples == 0) {
        out->bounds.x0 = out->bounds.y0 = -1.0f;
        out->bounds.x1 = out->bounds.y1 = 1.0f;
        out->texel_w = out->texel_h = 0.0f;
        out->width = out->height = 0;
        return;
    }
    out->bounds.x0 = bx0; out->bounds.y0 = by0; out->bounds.x1 = bx1; out->bounds.y1 = by1;
    out->texel_w = tw;
    out->texel_h = th;
    {
        double rw = tw > 0.0f ? ceil((double)(bx1 - bx0) / tw) : (double)max_res;
        double rh = th > 0.0f ? ceil((double)(by1 - by0) / th) : (double)max_res;
        out->width = rw < 1.0 ? 1 : rw > max_res ? max_res : (int)rw;
        out->height = rh < 1.0 ? 1 : rh > max_res ? max_res : (int)rh;
    }
}

/* The same definition evaluated in double precision (untimed): tells which
   of the two float results is closer where they differ. */
static void dxf4(const sk_mat4 *m, double x, double y, double z, double o[4])
{
    int i;
    for (i = 0; i < 4; ++i)
        o[i] = m->m[i] * x + m->m[4 + i] * y + m->m[8 + i] * z + m->m[12 + i];
}
static void double_estimate(const float *depth, int w, int h, sk_mat4 inv_vp, sk_mat4 light_vp,
                            double *res_w, double *res_h)
{
    int x, y, c, j;
    double bx0 = 1.0, by0 = 1.0, bx1 = -1.0, by1 = -1.0, tw = 1e300, th = 1e300;
    for (y = 0; y < h; ++y)
        for (x = 0; x < w; ++x) {
            double d = depth[y * w + x], wp[4], lc[4], lx, ly;
            double px0 = 1e300, py0 = 1e300, px1 = -1e300, py1 = -1e300;
            if (!naive_valid(depth[y * w + x])) continue;
            dxf4(&inv_vp, (x + 0.5) * 2.0 / w - 1.0, (y + 0.5) * 2.0 / h - 1.0, 2.0 * d - 1.0, wp);
            dxf4(&light_vp, wp[0] / wp[3], wp[1] / wp[3], wp[2] / wp[3], lc);
            if (!(lc[3] > 0.0 && fabs(lc[0]) <= lc[3] && fabs(lc[1]) <= lc[3] && fabs(lc[2]) <= lc[3]))
                continue;
            lx = lc[0] / lc[3];
            ly = lc[1] / lc[3];
            if (lx < bx0) bx0 = lx;
            if (lx > bx1) bx1 = lx;
            if (ly < by0) by0 = ly;
            if (ly > by1) by1 = ly;
            for (c = 0; c < 4; ++c) {
                int cx = x + (c & 1), cy = y + (c >> 1), cnt = 0;
                double sum = 0.0, cw[4], cl[4];
                for (j = 0; j < 4; ++j) {
                    int sx = cx - 1 + (j & 1), sy = cy - 1 + (j >> 1);
                    if (sx >= 0 && sx < w && sy >= 0 && sy < h && naive_valid(depth[sy * w + sx])) {
                        sum += depth[sy * w + sx];
                        cnt++;
                    }
                }
                dxf4(&inv_vp, cx * 2.0 / w - 1.0, cy * 2.0 / h - 1.0, 2.0 * (sum / cnt) - 1.0, cw);
                dxf4(&light_vp, cw[0] / cw[3], cw[1] / cw[3], cw[2] / cw[3], cl);
                if (cl[0] / cl[3] < px0) px0 = cl[0] / cl[3];
                if (cl[0] / cl[3] > px1) px1 = cl[0] / cl[3];
                if (cl[1] / cl[3] < py0) py0 = cl[1] / cl[3];
                if (cl[1] / cl[3] > py1) py1 = cl[1] / cl[3];
            }
            if (px1 - px0 < tw) tw = px1 - px0;
            if (py1 - py0 < th) th = py1 - py0;
        }
    *res_w = tw > 0.0 && tw < 1e300 ? (bx1 - bx0) / tw : 0.0;
    *res_h = th > 0.0 && th < 1e300 ? (by1 - by0) / th : 0.0;
}

static double g_est_ns = -1.0;   /* median ns per sk_estimate_resolution call, full HD */

static double k_estimate_resolution(long n)   /* not used for timing: see run_estimate */
{
    (void)n;
    return 0.0;
}

static int run_estimate(double *mpix_sk, double *mpix_naive, int *agree)
{
    typedef sk_result (*F)(const float *, int, int, sk_mat4, sk_mat4, int, sk_res_estimate *);
    F f = OPAQUE(F, sk_estimate_resolution);
    double t_sk[64], t_nv[64], t0, px = (double)RES_W * RES_H, best_sk, best_nv;
    sk_res_estimate est;
    naive_result nv;
    sk_result e;
    int r, runs = g_res_runs;

    build_res_scene();
    printf("sk_estimate_resolution, %dx%d depth buffer (%.1f%% covered: ground plane + %d boxes, sky = 1.0),\n"
           "directional light 40 deg, ortho view-projection around the scene, max_res %d\n",
           RES_W, RES_H, 100.0 * (double)g_rs.valid / px, N_BOXES, RES_MAX);

    memset(&est, 0, sizeof est);
    e = f(g_rs.depth, RES_W, RES_H, g_rs.cam_inv_vp, g_rs.light_vp, RES_MAX, &est);   /* warm-up */
    naive_estimate(g_rs.depth, RES_W, RES_H, g_rs.cam_inv_vp, g_rs.light_vp, RES_MAX, &nv);
    for (r = 0; r < runs; ++r) {       /* interleaved, so drift hits both alike */
        sk_res_estimate tmp;
        naive_result tmp2;
        t0 = now_s();
        f(g_rs.depth, RES_W, RES_H, g_rs.cam_inv_vp, g_rs.light_vp, RES_MAX, &tmp);
        t_sk[r] = now_s() - t0;
        g_sink += tmp.width + tmp.texel_w;
        t0 = now_s();
        naive_estimate(g_rs.depth, RES_W, RES_H, g_rs.cam_inv_vp, g_rs.light_vp, RES_MAX, &tmp2);
        t_nv[r] = now_s() - t0;
        g_sink += tmp2.width + tmp2.texel_w;
    }
    g_est_ns = median(t_sk, runs) * 1e9;
    *mpix_sk = px / median(t_sk, runs) * 1e-6;
    *mpix_naive = px / median(t_nv, runs) * 1e-6;

    best_sk = t_sk[0];
    best_nv = t_nv[0];
    for (r = 1; r < runs; ++r) {
        if (t_sk[r] < best_sk) best_sk = t_sk[r];
        if (t_nv[r] < best_nv) best_nv = t_nv[r];
    }
    printf("  %-16s %9s %6s %9s %8s %8s %9s %12s %12s  %s\n", "", "Mpixel/s", "best", "ms/frame", "width",
           "height", "samples", "texel_w", "texel_h", "bounds");
    printf("  %-16s %9.1f %6.1f %9.2f %8d %8d %9d %12.5g %12.5g  [%.4f,%.4f]x[%.4f,%.4f]%s%s\n",
           "shadowkit", *mpix_sk, px / best_sk * 1e-6, median(t_sk, runs) * 1e3, est.width, est.height, est.samples,
           (double)est.texel_w, (double)est.texel_h, (double)est.bounds.x0, (double)est.bounds.x1,
           (double)est.bounds.y0, (double)est.bounds.y1, e == SK_OK ? "" : "  returned ",
           e == SK_OK ? "" : sk_result_string(e));
    printf("  %-16s %9.1f %6.1f %9.2f %8d %8d %9d %12.5g %12.5g  [%.4f,%.4f]x[%.4f,%.4f]\n",
           "naive reference", *mpix_naive, px / best_nv * 1e-6, median(t_nv, runs) * 1e3, nv.width, nv.height, nv.samples,
           (double)nv.texel_w, (double)nv.texel_h, (double)nv.bounds.x0, (double)nv.bounds.x1,
           (double)nv.bounds.y0, (double)nv.bounds.y1);
    printf("  ratio shadowkit / naive: %.2fx   (Mpixel/s: median of %d runs each, interleaved, one core)\n",
           *mpix_sk / *mpix_naive, runs);
    /* width and height hinge on the single smallest patch of 1.3 million,
       which sits on a depth edge where float rounding of the unprojection
       moves it by a few per cent: exact equality is not expected there.
       Agree = samples identical and width, height within 5%. */
    {
        double dw = nv.width > 0 ? (double)est.width / nv.width - 1.0 : (est.width ? 1.0 : 0.0);
        double dh = nv.height > 0 ? (double)est.height / nv.height - 1.0 : (est.height ? 1.0 : 0.0);
        double rw, rh;
        int exact = e == SK_OK && est.width == nv.width && est.height == nv.height && est.samples == nv.samples;
        *agree = e == SK_OK && est.samples == nv.samples && fabs(dw) <= 0.05 && fabs(dh) <= 0.05;
        if (exact)
            printf("  result check: agree (width, height, samples identical)\n");
        else if (*agree)
            printf("  result check: agree within float rounding (samples identical; width %+.2f%%, "
                   "height %+.2f%% vs naive)\n", dw * 100.0, dh * 100.0);
        else
            printf("  result check: MISMATCH: shadowkit %dx%d, %d samples (%s); naive %dx%d, %d samples\n",
                   est.width, est.height, est.samples, sk_result_string(e), nv.width, nv.height, nv.samples);
        double_estimate(g_rs.depth, RES_W, RES_H, g_rs.cam_inv_vp, g_rs.light_vp, &rw, &rh);
        printf("  same definition in double precision (untimed): %.1f x %.1f; shadowkit off by %+.2f%% / %+.2f%%,"
               " naive by %+.2f%% / %+.2f%%\n", rw, rh,
               rw > 0.0 ? (est.width / rw - 1.0) * 100.0 : 0.0, rh > 0.0 ? (est.height / rh - 1.0) * 100.0 : 0.0,
               rw > 0.0 ? (nv.width / rw - 1.0) * 100.0 : 0.0, rh > 0.0 ? (nv.height / rh - 1.0) * 100.0 : 0.0);
    }
    free(g_rs.depth);
    return e == SK_OK;
}

/* ------------------------------------------------------------------------ */
/* header line, coverage check, main                                         */
/* ------------------------------------------------------------------------ */
static void cpu_name(char *buf, size_t cap)
{
    FILE *fp = fopen("/proc/cpuinfo", "r");
    char line[512];
    snprintf(buf, cap, "unknown CPU");
    if (!fp) return;
    while (fgets(line, sizeof line, fp)) {
        if (strncmp(line, "model name", 10) == 0) {
            char *p = strchr(line, ':');
            if (p) {
                size_t l;
                p++;
                while (*p == ' ' || *p == '\t') p++;
                l = strlen(p);
                while (l > 0 && (p[l - 1] == '\n' || p[l - 1] == '\r')) p[--l] = '\0';
                snprintf(buf, cap, "%s", p);
            }
            break;
        }
    }
    fclose(fp);
}

/* Lists the SKDEF functions of shadowkit.h that this bench does not time
   (so a function added to the header later shows up here). */
static int coverage_check(void)
{
    static const char *paths[] = { "shadowkit.h", "../shadowkit.h" };
    char line[1024], seen[256][64];
    int nseen = 0, missing = 0, p, i;
    FILE *fp = NULL;
    for (p = 0; p < 2 && !fp; ++p) fp = fopen(paths[p], "r");
    if (!fp) return 0;
    while (fgets(line, sizeof line, fp)) {
        char *s = line, *paren, *e, *b;
        char name[64];
        int known = 0;
        while (*s == ' ' || *s == '\t') s++;
        if (strncmp(s, "SKDEF ", 6) != 0) continue;
        paren = strchr(s, '(');
        if (!paren) continue;
        e = paren;
        while (e > s && e[-1] == ' ') e--;
        b = e;
        while (b > s && (b[-1] == '_' || (b[-1] >= 'a' && b[-1] <= 'z') || (b[-1] >= 'A' && b[-1] <= 'Z') ||
                         (b[-1] >= '0' && b[-1] <= '9')))
            b--;
        if (e - b <= 3 || e - b >= (long)sizeof name || strncmp(b, "sk_", 3) != 0) continue;
        memcpy(name, b, (size_t)(e - b));
        name[e - b] = '\0';
        for (i = 0; i < N_ITEMS; ++i)
            if (strcmp(name, g_items[i].name) == 0) known = 1;
        for (i = 0; i < nseen; ++i)
            if (strcmp(name, seen[i]) == 0) known = 1;
        if (known) continue;
        if (nseen < 256) snprintf(seen[nseen++], sizeof seen[0], "%s", name);
        printf("  NOT BENCHMARKED: %s (public in shadowkit.h, missing from bench/bench_cpu.c)\n", name);
        missing++;
    }
    fclose(fp);
    return missing;
}

int main(int argc, char **argv)
{
    char cpu[256];
    double times[64];
    double mpix_sk = 0.0, mpix_nv = 0.0;
    int it, b, slow = 0, fixed = 0, agree = 0, est_ok, suspicious = 0, missing;
    char slow_names[512] = "";
    double t_start = now_s();

    if (argc > 1 && strcmp(argv[1], "quick") == 0) {
        g_batches = 7;
        g_batch_s = 0.5e-3;
        g_res_runs = 3;
    }
    cpu_name(cpu, sizeof cpu);
    printf("shadowkit %d.%d.%d CPU benchmark\n", SHADOWKIT_VERSION_MAJOR, SHADOWKIT_VERSION_MINOR,
           SHADOWKIT_VERSION_PATCH);
    printf("CPU:      %s (single thread)\n", cpu);
    printf("compiler: %s%s\n", __VERSION__, BENCH_OPT_NOTE);
    printf("method:   median of %d batches, each >= %.1f ms of calls; inputs vary per call (%d variants);\n"
           "          calls go through an opaque function pointer (as from another translation unit)\n\n",
           g_batches, g_batch_s * 1e3, BENCH_NV);

    setup_inputs();
    describe_sizes();
    run_estimate(&mpix_sk, &mpix_nv, &agree);   /* first, so its row can go in the table */
    est_ok = mpix_sk >= BENCH_TARGET_MPIX;

    printf("\n%-28s %12s  %-34s %s\n", "function", "ns/call", "size", "target < 1000 ns");
    printf("%-28s %12s  %-34s %s\n", "----------------------------", "------------",
           "----------------------------------", "----------------");
    for (it = 0; it < N_ITEMS; ++it) {
        const bench_item *bi = &g_items[it];
        double ns, bad_frac = 0.0;
        long n = 1;
        char note[96] = "";
        if (bi->fn == k_estimate_resolution) {
            ns = g_est_ns;
        } else {
            double t;
            g_sink += bi->fn(1);                    /* warm-up */
            for (;;) {                              /* calibrate: one batch >= g_batch_s */
                t = now_s();
                g_sink += bi->fn(n);
                t = now_s() - t;
                if (t >= g_batch_s || n >= (1L << 30)) break;
                if (t < g_batch_s / 8.0) n *= 8;
                else {
                    long want = (long)((double)n * g_batch_s * 1.2 / t) + 1;
                    n = want > n ? want : n + 1;
                }
            }
            g_bad = 0;
            for (b = 0; b < g_batches; ++b) {
                t = now_s();
                g_sink += bi->fn(n);
                times[b] = (now_s() - t) / (double)n;
            }
            bad_frac = (double)g_bad / ((double)n * g_batches);
            ns = median(times, g_batches) * 1e9;
        }
        if (bad_frac > 0.0)
            snprintf(note, sizeof note, "  [%.0f%% of calls returned an error: timing of the error path]",
                     bad_frac * 100.0);
        if (ns < 0.5) {
            suspicious++;
            snprintf(note + strlen(note), sizeof note - strlen(note), "  [SUSPICIOUS: ~0 ns]");
        }
        if (bi->size) {
            printf("%-28s %12.1f  %-34s %s%s\n", bi->name, ns, bi->size, "scales with data", note);
        } else {
            fixed++;
            if (!(ns < BENCH_TARGET_NS)) {
                slow++;
                if (strlen(slow_names) + strlen(bi->name) + 3 < sizeof slow_names) {
                    strcat(slow_names, slow == 1 ? " (" : ", ");
                    strcat(slow_names, bi->name);
                }
            }
            printf("%-28s %12.1f  %-34s %s%s\n", bi->name, ns, "", ns < BENCH_TARGET_NS ? "pass" : "FAIL", note);
        }
    }
    missing = coverage_check();

    if (slow) strcat(slow_names, ")");
    printf("\nsummary: %d of %d fixed-cost functions missed the 1 us target%s; "
           "sk_estimate_resolution %.1f Mpixel/s (naive %.1f, %.2fx): 50 Mpixel/s target %s; "
           "results %s%s%s (%.1f s)\n",
           slow, fixed, slow_names, mpix_sk, mpix_nv, mpix_nv > 0.0 ? mpix_sk / mpix_nv : 0.0,
           est_ok ? "met" : "MISSED", agree ? "agree" : "MISMATCH",
           suspicious ? "; some timings ~0 ns (optimised away?)" : "",
           missing ? "; some public functions not benchmarked" : "", now_s() - t_start);
    return 0;
}
