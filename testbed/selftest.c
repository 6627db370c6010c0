/* selftest.c - checks the testbed library on its own (no shadowkit code runs).
   Run from the repository root (testbed/build.sh does). Prints one line per
   failure, some information lines, and finally
       testbed-selftest: N passed, M failed
   Writes out/testbed-selftest.png (area-light visibility, top view),
   out/testbed-selftest-error.png (error-image colours on the box test) and
   out/testbed-selftest-gl.png (GL G-buffer + Embree sun shadows). */
#if !defined(_POSIX_C_SOURCE) || _POSIX_C_SOURCE < 200809L
#undef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L
#endif
#include "tb_gl_context.h"
#include "tb_gl_fbo.h"
#include "tb_gl_scene.h"
#include "tb_image.h"
#include "tb_metrics.h"
#include "tb_reference.h"
#include "tb_scene.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include <stb/stb_image.h>

static int g_pass = 0, g_fail = 0;

#define CHECK(cond) do { if (cond) g_pass++; else { g_fail++; \
    printf("FAIL %s:%d: %s\n", __FILE__, __LINE__, #cond); } } while (0)
#define CHECK_MSG(cond, ...) do { if (cond) g_pass++; else { g_fail++; \
    printf("FAIL %s:%d: %s: ", __FILE__, __LINE__, #cond); printf(__VA_ARGS__); printf("\n"); } } while (0)
#define CHECK_NEAR(a, b, tol) do { double a_ = (double)(a), b_ = (double)(b); \
    if (a_ == a_ && b_ == b_ && fabs(a_ - b_) <= (double)(tol)) g_pass++; else { g_fail++; \
    printf("FAIL %s:%d: %s = %.9g, expected %.9g (tol %g)\n", __FILE__, __LINE__, #a, a_, b_, \
    (double)(tol)); } } while (0)

static double now_s(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static sk_vec3 v3(float x, float y, float z) {
    sk_vec3 r;
    r.x = x; r.y = y; r.z = z;
    return r;
}

static int box_eq(sk_aabb b, float x0, float y0, float z0, float x1, float y1, float z1) {
    const float t = 1e-5f;
    return fabsf(b.min.x - x0) <= t && fabsf(b.min.y - y0) <= t && fabsf(b.min.z - z0) <= t &&
           fabsf(b.max.x - x1) <= t && fabsf(b.max.y - y1) <= t && fabsf(b.max.z - z1) <= t;
}

/* every triangle's winding agrees with its vertex normals; normals unit;
   object ranges tile the index buffer; object bounds inside scene bounds */
static void check_scene_consistency(const tb_scene *s, const char *name) {
    uint32_t t, bad_wind = 0, bad_norm = 0, covered = 0, o;
    for (t = 0; t < s->index_count / 3; t++) {
        const uint32_t *ix = s->indices + 3 * t;
        const float *a = s->positions + 3 * ix[0], *b = s->positions + 3 * ix[1], *c = s->positions + 3 * ix[2];
        const float *n = s->normals + 3 * ix[0];
        double e1[3], e2[3], cr[3], len;
        int k;
        for (k = 0; k < 3; k++) { e1[k] = b[k] - a[k]; e2[k] = c[k] - a[k]; }
        cr[0] = e1[1] * e2[2] - e1[2] * e2[1];
        cr[1] = e1[2] * e2[0] - e1[0] * e2[2];
        cr[2] = e1[0] * e2[1] - e1[1] * e2[0];
        if (cr[0] * n[0] + cr[1] * n[1] + cr[2] * n[2] <= 0) bad_wind++;
        len = sqrt((double)n[0] * n[0] + (double)n[1] * n[1] + (double)n[2] * n[2]);
        if (fabs(len - 1) > 1e-5) bad_norm++;
    }
    for (o = 0; o < s->object_count; o++) {
        const tb_object *ob = &s->objects[o];
        if (ob->first_index == covered) covered += ob->index_count;
        CHECK_MSG(ob->bounds.min.x >= s->bounds.min.x && ob->bounds.max.y <= s->bounds.max.y,
                  "%s: object %s bounds outside the scene", name, ob->name);
    }
    CHECK_MSG(bad_wind == 0, "%s: %u triangles wind against their normals", name, bad_wind);
    CHECK_MSG(bad_norm == 0, "%s: %u non-unit normals", name, bad_norm);
    CHECK_MSG(covered == s->index_count, "%s: object ranges do not tile the indices", name);
}

static void test_procedural(void) {
    static const struct {
        const char *name;
        uint32_t tris, objects;
        float b[6];
    } want[] = {
        {"ground-boxes", 188, 6, {-20, 0, -20, 20, 6, 20}},
        {"fence", 980, 31, {-15, 0, -15, 15, 3, 15}},
        {"terrace", 2240, 121, {-6, 0, -200, 6, 3, 0}},
        {"room", 252, 11, {-5, 0, -5, 5, 4, 5}},
        {"contact", 14, 2, {-10, 0, -10, 10, 1, 10}},
    };
    size_t i;
    for (i = 0; i < sizeof want / sizeof want[0]; i++) {
        tb_scene s;
        tb_scene_init(&s);
        CHECK(tb_scene_build(&s, want[i].name) == 0);
        printf("scene %-13s %6u triangles %3u objects bounds [%g %g %g]..[%g %g %g]\n", want[i].name,
               tb_scene_triangle_count(&s), s.object_count, s.bounds.min.x, s.bounds.min.y,
               s.bounds.min.z, s.bounds.max.x, s.bounds.max.y, s.bounds.max.z);
        CHECK_MSG(tb_scene_triangle_count(&s) == want[i].tris, "%s: %u triangles, expected %u",
                  want[i].name, tb_scene_triangle_count(&s), want[i].tris);
        CHECK_MSG(s.object_count == want[i].objects, "%s: %u objects, expected %u", want[i].name,
                  s.object_count, want[i].objects);
        CHECK_MSG(box_eq(s.bounds, want[i].b[0], want[i].b[1], want[i].b[2], want[i].b[3],
                         want[i].b[4], want[i].b[5]), "%s: bounds", want[i].name);
        check_scene_consistency(&s, want[i].name);
        tb_scene_free(&s);
        CHECK(s.index_count == 0 && s.positions == NULL);
    }
    {
        /* contact: the box rests exactly on the ground */
        tb_scene s;
        int b;
        tb_scene_init(&s);
        tb_scene_build_contact(&s);
        b = tb_scene_find_object(&s, "box");
        CHECK(b == 1);
        if (b >= 0) CHECK(box_eq(s.objects[b].bounds, -1, 0, -1, 1, 1, 1));
        CHECK(tb_scene_find_object(&s, "nope") == -1);
        CHECK(tb_scene_build(&s, "nope") == -1);
        tb_scene_free(&s);
    }
}

static int dir_exists(const char *p) {
    struct stat st;
    return stat(p, &st) == 0 && S_ISDIR(st.st_mode);
}

static void test_assets(void) {
    static const struct { const char *path; uint32_t tris; } want[] = {
        {"../shared/scenes/stanford-bunny.obj", 69451},
        {"../shared/scenes/sponza-ivy/sponza_ivy.gltf", 15870},
        {"../shared/scenes/sponza-curtains/sponza_curtains.gltf", 55115},
    };
    size_t i;
    if (!dir_exists("../shared/scenes")) {
        printf("assets: ../shared/scenes not found: skipped\n");
        return;
    }
    for (i = 0; i < sizeof want / sizeof want[0]; i++) {
        tb_scene s;
        double t0 = now_s();
        int r;
        tb_scene_init(&s);
        r = tb_scene_load(&s, want[i].path);
        CHECK_MSG(r == 0, "loading %s", want[i].path);
        printf("asset %-55s %6u triangles (README %u) %u objects %.2f s bounds [%g %g %g]..[%g %g %g]\n",
               want[i].path, tb_scene_triangle_count(&s), want[i].tris, s.object_count, now_s() - t0,
               s.bounds.min.x, s.bounds.min.y, s.bounds.min.z, s.bounds.max.x, s.bounds.max.y,
               s.bounds.max.z);
        CHECK_MSG(tb_scene_triangle_count(&s) == want[i].tris, "%s: %u triangles, expected %u",
                  want[i].path, tb_scene_triangle_count(&s), want[i].tris);
        tb_scene_free(&s);
    }
    {
        tb_scene s;
        tb_scene_init(&s);
        printf("assets: loading a missing file (an error message on stderr is expected)\n");
        fflush(stdout);
        CHECK(tb_scene_load(&s, "../shared/scenes/does-not-exist.obj") == -1);
        CHECK(s.index_count == 0);
        tb_scene_free(&s);
    }
}

/* ---- a small orthographic camera with its exact inverse, in double ---- */

typedef struct ortho_cam {
    double eye[3], r[3], u[3], f[3];   /* orthonormal: right, up, forward */
    double hw, hh, zn, zf;
    int w, h;
} ortho_cam;

static void normalize3(double v[3]) {
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    v[0] /= l; v[1] /= l; v[2] /= l;
}

static void cross3(const double a[3], const double b[3], double o[3]) {
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

/* camera at eye looking along fwd, with world up (0,1,0) (or (0,0,-1) when vertical) */
static ortho_cam make_ortho(const double eye[3], const double fwd[3], double hw, double hh,
                            double zn, double zf, int w, int h) {
    ortho_cam c;
    double up[3] = {0, 1, 0};
    int k;
    memset(&c, 0, sizeof c);
    for (k = 0; k < 3; k++) { c.eye[k] = eye[k]; c.f[k] = fwd[k]; }
    normalize3(c.f);
    if (fabs(c.f[1]) > 0.999) { up[1] = 0; up[2] = -1; }
    cross3(c.f, up, c.r);
    normalize3(c.r);
    cross3(c.r, c.f, c.u);
    c.hw = hw; c.hh = hh; c.zn = zn; c.zf = zf; c.w = w; c.h = h;
    return c;
}

/* world = E + R hw nx + U hh ny + F (zn + (nz+1)/2 (zf-zn)) as a column-major matrix */
static tb_view ortho_view(const ortho_cam *c) {
    tb_view v;
    double half = 0.5 * (c->zf - c->zn);
    int k;
    memset(&v, 0, sizeof v);
    for (k = 0; k < 3; k++) {
        v.inv_view_proj.m[0 * 4 + k] = (float)(c->r[k] * c->hw);
        v.inv_view_proj.m[1 * 4 + k] = (float)(c->u[k] * c->hh);
        v.inv_view_proj.m[2 * 4 + k] = (float)(c->f[k] * half);
        v.inv_view_proj.m[3 * 4 + k] = (float)(c->eye[k] + c->f[k] * (c->zn + half));
    }
    v.inv_view_proj.m[15] = 1.0f;
    v.width = c->w;
    v.height = c->h;
    return v;
}

/* the scene of the analytic tests: ground y = 0 on [-g,g]^2 and one box */
typedef struct box_scene { double g; double bmin[3], bmax[3]; } box_scene;

/* analytic ray cast of pixel (x, y): window depth (1 = background), hit
   point, normal and what was hit (0 none, 1 ground, 2 box top, 3 box side,
   4 box bottom) */
static int cast_pixel(const ortho_cam *c, const box_scene *bs, int x, int y, float *depth,
                      double hit[3], double n[3]) {
    double nx = 2.0 * (x + 0.5) / c->w - 1, ny = 2.0 * (y + 0.5) / c->h - 1;
    double o[3], best = INFINITY, t0 = -INFINITY, t1 = INFINITY;
    int k, what = 0, axis0 = -1;
    for (k = 0; k < 3; k++) o[k] = c->eye[k] + c->r[k] * c->hw * nx + c->u[k] * c->hh * ny;
    /* box slabs */
    for (k = 0; k < 3; k++) {
        if (fabs(c->f[k]) < 1e-12) {
            if (o[k] < bs->bmin[k] || o[k] > bs->bmax[k]) { t0 = INFINITY; break; }
        } else {
            double a = (bs->bmin[k] - o[k]) / c->f[k], b = (bs->bmax[k] - o[k]) / c->f[k];
            if (a > b) { double t = a; a = b; b = t; }
            if (a > t0) { t0 = a; axis0 = k; }
            if (b < t1) t1 = b;
        }
    }
    if (t0 <= t1 && t0 >= c->zn && t0 <= c->zf && axis0 >= 0) {
        best = t0;
        for (k = 0; k < 3; k++) n[k] = 0;
        n[axis0] = c->f[axis0] > 0 ? -1 : 1;
        what = axis0 == 1 ? (n[1] > 0 ? 2 : 4) : 3;
    }
    if (fabs(c->f[1]) > 1e-12) {
        double t = -o[1] / c->f[1];
        if (t >= c->zn && t <= c->zf && t < best) {
            double px = o[0] + c->f[0] * t, pz = o[2] + c->f[2] * t;
            if (fabs(px) <= bs->g && fabs(pz) <= bs->g) {
                best = t;
                n[0] = 0; n[1] = 1; n[2] = 0;
                what = 1;
            }
        }
    }
    if (!what) { *depth = 1.0f; return 0; }
    *depth = (float)((best - c->zn) / (c->zf - c->zn));
    for (k = 0; k < 3; k++) hit[k] = o[k] + c->f[k] * best;
    return what;
}

static tb_scene make_box_scene(const box_scene *bs) {
    tb_scene s;
    tb_scene_init(&s);
    tb_scene_add_ground(&s, "ground", 0, 0, (float)bs->g, (float)bs->g, 0, 4, 4);
    tb_scene_add_box(&s, "box", v3((float)bs->bmin[0], (float)bs->bmin[1], (float)bs->bmin[2]),
                     v3((float)bs->bmax[0], (float)bs->bmax[1], (float)bs->bmax[2]));
    return s;
}

/* pixel nearest to world point p for camera c */
static int pixel_of(const ortho_cam *c, const double p[3], int *x, int *y) {
    double d[3], nx, ny;
    int k;
    for (k = 0; k < 3; k++) d[k] = p[k] - c->eye[k];
    nx = (d[0] * c->r[0] + d[1] * c->r[1] + d[2] * c->r[2]) / c->hw;
    ny = (d[0] * c->u[0] + d[1] * c->u[1] + d[2] * c->u[2]) / c->hh;
    *x = (int)floor((nx + 1) * 0.5 * c->w);
    *y = (int)floor((ny + 1) * 0.5 * c->h);
    return *x >= 0 && *y >= 0 && *x < c->w && *y < c->h;
}

/* Hard shadows: a box floating above a ground plane, lit from straight above,
   seen by a low oblique orthographic camera that sees under the box. */
static void test_reference_hard(void) {
    const int W = 320, H = 240;
    box_scene bs = {10, {-1, 1, -1}, {1, 2, 1}};
    double eye[3] = {-19, 6.5, 0.5}, fwd[3] = {3, -1, 0};
    ortho_cam cam = make_ortho(eye, fwd, 7, 5.25, 1, 60, W, H);
    tb_view view = ortho_view(&cam);
    tb_scene s = make_box_scene(&bs);
    tb_reference *ref = tb_reference_create(&s);
    float *depth = (float *)malloc(sizeof(float) * W * H);
    float *nrm = (float *)malloc(sizeof(float) * 3 * W * H);
    float *gen_nrm = (float *)malloc(sizeof(float) * 3 * W * H);
    float *vis = (float *)malloc(sizeof(float) * W * H);
    float *vis_n = (float *)malloc(sizeof(float) * W * H);
    float *expect = (float *)malloc(sizeof(float) * W * H);
    unsigned char *what = (unsigned char *)malloc((size_t)W * H);
    tb_light sun;
    int x, y, px, py;
    long checked = 0, mism = 0, mism_n = 0, shadowed = 0, nrm_ok = 0, nrm_total = 0, side_dark = 0,
         side_total = 0, bg = 0, bg_wrong = 0;
    double t0;
    CHECK(ref != NULL);
    if (!ref || !depth || !nrm || !gen_nrm || !vis || !vis_n || !expect || !what) goto done;
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            size_t i = (size_t)y * W + x;
            double hit[3] = {0, 0, 0}, n[3] = {0, 0, 0};
            int k = cast_pixel(&cam, &bs, x, y, &depth[i], hit, n);
            what[i] = (unsigned char)k;
            nrm[3 * i] = (float)n[0]; nrm[3 * i + 1] = (float)n[1]; nrm[3 * i + 2] = (float)n[2];
            expect[i] = TB_VIS_BACKGROUND;
            if (k == 1) {
                int under = fabs(hit[0]) < 1 && fabs(hit[2]) < 1;
                int near_edge = fabs(fabs(hit[0]) - 1) < 0.02 || fabs(fabs(hit[2]) - 1) < 0.02;
                expect[i] = under ? 0.0f : 1.0f;
                if (near_edge) what[i] = 9;   /* not compared */
            } else if (k == 2) {
                expect[i] = 1.0f;
            } else if (k != 0) {
                expect[i] = 0.0f;   /* side: grazing (dot(n, L) = 0) */
            }
        }
    memset(&sun, 0, sizeof sun);
    sun.type = TB_LIGHT_DIRECTIONAL;
    sun.direction = v3(0, -1, 0);
    t0 = now_s();
    CHECK(tb_reference_trace(ref, &view, depth, NULL, &sun, NULL, vis) == 0);
    printf("reference: hard %dx%d without normals %.1f ms, epsilon %g\n", W, H,
           1e3 * (now_s() - t0), tb_reference_epsilon(ref, NULL));
    CHECK(tb_reference_trace(ref, &view, depth, nrm, &sun, NULL, vis_n) == 0);
    CHECK(tb_reference_normals(ref, &view, depth, NULL, gen_nrm) == 0);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            size_t i = (size_t)y * W + x;
            if (what[i] == 0) {
                bg++;
                if (vis[i] != TB_VIS_BACKGROUND) bg_wrong++;
                continue;
            }
            if (what[i] == 3) {
                side_total++;
                if (vis_n[i] == 0.0f) side_dark++;
            }
            if (what[i] == 1 || what[i] == 2) {
                checked++;
                if (vis[i] != expect[i]) mism++;
                if (vis_n[i] != expect[i]) mism_n++;
                if (expect[i] == 0.0f) shadowed++;
                nrm_total++;
                if (gen_nrm[3 * i] * nrm[3 * i] + gen_nrm[3 * i + 1] * nrm[3 * i + 1] +
                        gen_nrm[3 * i + 2] * nrm[3 * i + 2] > 0.9999f)
                    nrm_ok++;
            }
        }
    printf("reference: %ld pixels compared (%ld shadowed), %ld / %ld mismatches (no normals / normals),"
           " generated normals agree on %ld / %ld\n", checked, shadowed, mism, mism_n, nrm_ok, nrm_total);
    CHECK(checked > 20000 && shadowed > 300);
    CHECK_MSG(bg > 1000 && bg_wrong == 0, "background: %ld of %ld wrong", bg_wrong, bg);
    CHECK_MSG(mism == 0, "%ld mismatches without normals", mism);
    CHECK_MSG(mism_n == 0, "%ld mismatches with normals", mism_n);
    CHECK_MSG(nrm_ok >= nrm_total - nrm_total / 200, "generated normals: %ld of %ld", nrm_ok, nrm_total);
    CHECK_MSG(side_total > 0 && side_dark == side_total, "box side (grazing) with normals: %ld of %ld dark",
              side_dark, side_total);
    {
        /* named pixels: under the box shadowed, beside it lit, on top lit
           ((-3,0,0): in front of the box as the camera sees it) */
        double under[3] = {0, 0, 0}, beside[3] = {0, 0, 3}, beyond[3] = {-3, 0, 0}, top[3] = {0, 2, 0};
        CHECK(pixel_of(&cam, under, &px, &py));
        CHECK_MSG(vis[py * W + px] == 0.0f && what[py * W + px] == 1, "under the box: %g", vis[py * W + px]);
        CHECK(pixel_of(&cam, beside, &px, &py));
        CHECK_MSG(vis[py * W + px] == 1.0f, "beside the box: %g", vis[py * W + px]);
        CHECK(pixel_of(&cam, beyond, &px, &py));
        CHECK_MSG(vis[py * W + px] == 1.0f, "beyond the box: %g", vis[py * W + px]);
        CHECK(pixel_of(&cam, top, &px, &py));
        CHECK_MSG(vis[py * W + px] == 1.0f, "box top: %g", vis[py * W + px]);
    }
    {
        /* metrics on this image: reference vs itself and vs a corrupted copy */
        tb_hard_error e = tb_metric_hard(vis, vis, (size_t)W * H);
        size_t i, n = (size_t)W * H, flipped = 0;
        CHECK(e.pct == 0 && e.covered > 0);
        memcpy(vis_n, vis, n * sizeof(float));
        for (i = 0; i < n; i += 97)
            if (vis_n[i] >= 0) { vis_n[i] = vis_n[i] >= 0.5f ? 0.0f : 1.0f; flipped++; }
        e = tb_metric_hard(vis, vis_n, n);
        CHECK(e.wrong == flipped && e.false_lit + e.false_shadow == flipped);
        CHECK(tb_image_write_error("out/testbed-selftest-error.png", W, H, vis, vis_n) == 0);
    }
    {
        /* points API: straight below the box centre and far away */
        double pts[6] = {0, 0, 0, 5, 0, 5};
        float pv[2] = {-5, -5};
        CHECK(tb_reference_trace_points(ref, pts, NULL, 2, &sun, NULL, pv) == 0);
        CHECK(pv[0] == 0.0f && pv[1] == 1.0f);
    }
    {
        /* a slanted sun: the shadow of the box moves to +x by 0.5 * height */
        double p_in[3] = {1.6, 0, 0}, p_out[3] = {2.2, 0, 0};
        double pts[6];
        float pv[2];
        tb_light slant = sun;
        slant.direction = v3(1, -2, 0);
        memcpy(pts, p_in, sizeof p_in);
        memcpy(pts + 3, p_out, sizeof p_out);
        CHECK(tb_reference_trace_points(ref, pts, NULL, 2, &slant, NULL, pv) == 0);
        CHECK_MSG(pv[0] == 0.0f && pv[1] == 1.0f, "slanted sun: %g %g", pv[0], pv[1]);
    }
done:
    tb_reference_destroy(ref);
    tb_scene_free(&s);
    free(depth); free(nrm); free(gen_nrm); free(vis); free(vis_n); free(expect); free(what);
}

/* Soft shadows: a 10 x 10 slab at height 2..2.5 and a 2 x 2 light at height 10. */
static void test_reference_area(void) {
    box_scene bs = {20, {-5, 2, -5}, {5, 2.5, 5}};
    tb_scene s = make_box_scene(&bs);
    tb_reference *ref = tb_reference_create(&s);
    tb_light rect;
    double pts[3 * 8];
    float v[8];
    const double xs[8] = {0, 6.2, 6.45, 6.66, 6.85, 7.2, 12, 15};
    int i;
    CHECK(ref != NULL);
    if (!ref) { tb_scene_free(&s); return; }
    memset(&rect, 0, sizeof rect);
    rect.type = TB_LIGHT_RECT;
    rect.position = v3(0, 10, 0);
    rect.half_u = v3(1, 0, 0);
    rect.half_v = v3(0, 0, 1);
    rect.strata = 16;
    rect.seed = 1234;
    for (i = 0; i < 8; i++) { pts[3 * i] = xs[i]; pts[3 * i + 1] = 0; pts[3 * i + 2] = (i == 7) ? 15 : 0; }
    CHECK(tb_reference_trace_points(ref, pts, NULL, 8, &rect, NULL, v) == 0);
    printf("reference: area light visibility at x =");
    for (i = 0; i < 8; i++) printf(" %g:%.3f", xs[i], v[i]);
    printf("\n");
    CHECK_MSG(v[0] == 0.0f, "under the slab centre: %g", v[0]);
    CHECK_MSG(v[1] == 0.0f, "umbra (x = 6.2): %g", v[1]);
    CHECK_MSG(v[3] > 0.0f && v[3] < 1.0f, "penumbra (x = 6.66): %g", v[3]);
    /* exact fraction at x = 6.66, z = 0: light x > 20 - 3 x  ->  (1 - 0.02) / 2 = 0.49 */
    CHECK_NEAR(v[3], 0.49, 0.04);
    CHECK(v[2] <= v[3] && v[3] <= v[4] && v[2] < v[4]);
    CHECK_MSG(v[5] == 1.0f && v[6] == 1.0f && v[7] == 1.0f, "lit: %g %g %g", v[5], v[6], v[7]);
    {
        /* determinism: same seed, same answer, any thread count */
        float w[8];
        tb_ref_options one;
        memset(&one, 0, sizeof one);
        one.threads = 1;
        CHECK(tb_reference_trace_points(ref, pts, NULL, 8, &rect, &one, w) == 0);
        CHECK(memcmp(v, w, sizeof v) == 0);
    }
    {
        /* a top view of the penumbra, written as the selftest's PNG */
        const int W = 256, H = 256;
        double eye[3] = {0, 30, 0}, fwd[3] = {0, -1, 0};
        ortho_cam cam = make_ortho(eye, fwd, 10, 10, 1, 40, W, H);
        tb_view view = ortho_view(&cam);
        float *depth = (float *)malloc(sizeof(float) * W * H);
        float *vis = (float *)malloc(sizeof(float) * W * H);
        /* visible from above: the slab top (y = 2.5) inside |x|,|z| < 5, else the ground */
        box_scene below = {20, {-5, 2, -5}, {5, 2.5, 5}};
        int x, y;
        double t0;
        long pen = 0;
        if (depth && vis) {
            for (y = 0; y < H; y++)
                for (x = 0; x < W; x++) {
                    double hit[3], n[3];
                    cast_pixel(&cam, &below, x, y, &depth[y * W + x], hit, n);
                }
            t0 = now_s();
            CHECK(tb_reference_trace(ref, &view, depth, NULL, &rect, NULL, vis) == 0);
            printf("reference: area light %dx%d, %d samples/pixel: %.0f ms (%.1f Mrays/s)\n", W, H,
                   rect.strata * rect.strata, 1e3 * (now_s() - t0),
                   (double)W * H * rect.strata * rect.strata / (now_s() - t0) / 1e6);
            for (x = 0; x < W * H; x++) if (vis[x] > 0 && vis[x] < 1) pen++;
            CHECK_MSG(pen > 1000, "penumbra pixels: %ld", pen);
            CHECK(tb_image_write_visibility("out/testbed-selftest.png", W, H, vis) == 0);
        }
        free(depth);
        free(vis);
    }
    tb_reference_destroy(ref);
    tb_scene_free(&s);
}

/* Point light in the room: behind a pillar is dark, in the open is lit,
   beyond the range is out of range. */
static void test_reference_point(void) {
    tb_scene s;
    tb_reference *ref;
    tb_light lamp;
    double pts[9] = {-4, 0, -4, 1, 0, 2, 0, 4, 0};
    double nrm[9] = {0, 1, 0, 0, 1, 0, 0, -1, 0};
    float v[3];
    tb_scene_init(&s);
    tb_scene_build_room(&s);
    ref = tb_reference_create(&s);
    CHECK(ref != NULL);
    if (!ref) { tb_scene_free(&s); return; }
    memset(&lamp, 0, sizeof lamp);
    lamp.type = TB_LIGHT_POINT;
    lamp.position = v3(0, 2, 0);
    lamp.range = 0;
    CHECK(tb_reference_trace_points(ref, pts, nrm, 3, &lamp, NULL, v) == 0);
    CHECK_MSG(v[0] == 0.0f, "behind pillar0: %g", v[0]);
    CHECK_MSG(v[1] == 1.0f, "open floor: %g", v[1]);
    CHECK_MSG(v[2] == 1.0f, "ceiling above the lamp: %g", v[2]);
    lamp.range = 3;
    CHECK(tb_reference_trace_points(ref, pts, nrm, 3, &lamp, NULL, v) == 0);
    CHECK(v[0] == TB_VIS_OUT_OF_RANGE && v[1] == 1.0f && v[2] == 1.0f);
    tb_reference_destroy(ref);
    tb_scene_free(&s);
}

/* The interior: its size, its views inside the building, each light in
   its own room, and walls and doors as the reference sees them. */
static void test_interior(void) {
    tb_scene s;
    tb_reference *ref;
    tb_light lamp;
    /* floor under light 1 (r1), floor in r2 behind the solid partition,
       floor in r4 through r1's and r4's facing doors, the ground outside
       through r1's window, the ground beyond the light's range */
    double pts[15] = {0.5, 0, -3.0, 4.0, 0, -5.0, 0.3, 0, 3.0, 0, 0, -12, 0, 0, -19};
    double nrm[15] = {0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0};
    float v[5], r;
    sk_vec3 e, t;
    int i;
    tb_scene_init(&s);
    CHECK(tb_scene_build(&s, "interior") == 0);
    CHECK_MSG(tb_scene_triangle_count(&s) == 1652 && s.object_count == 60, "%u triangles, %u objects",
              tb_scene_triangle_count(&s), s.object_count);
    CHECK(box_eq(s.bounds, -20, -0.2f, -20, 20, 3.2f, 20));
    check_scene_consistency(&s, "interior");
    for (i = 0; i < TB_INTERIOR_VIEWS; i++) {
        CHECK(tb_interior_view(i, &e, &t) == 0);
        CHECK_MSG(tb_interior_region(e) >= 0 && e.y == 1.7f, "view %d eye region %d", i, tb_interior_region(e));
    }
    for (i = 0; i < TB_INTERIOR_LIGHTS; i++) {
        CHECK(tb_interior_light(i, &e, &r) == 0);
        CHECK_MSG(tb_interior_region(e) == i && r >= 7.0f && r <= 9.0f, "light %d region %d range %g", i,
                  tb_interior_region(e), r);
    }
    CHECK(tb_interior_view(TB_INTERIOR_VIEWS, &e, &t) == -1 && tb_interior_light(-1, &e, &r) == -1);
    CHECK(tb_interior_light(0, NULL, &r) == -1 && tb_interior_region(v3(0, 1, -12)) == -1);
    CHECK(tb_interior_region(v3(0, 1, 0)) == 6 && tb_interior_region(v3(5, 1, 4)) == 5);
    ref = tb_reference_create(&s);
    CHECK(ref != NULL);
    if (ref) {
        memset(&lamp, 0, sizeof lamp);
        lamp.type = TB_LIGHT_POINT;
        tb_interior_light(1, &lamp.position, &lamp.range);
        CHECK(tb_reference_trace_points(ref, pts, nrm, 5, &lamp, NULL, v) == 0);
        CHECK_MSG(v[0] == 1.0f && v[1] == 0.0f && v[2] == 1.0f && v[3] == 1.0f && v[4] == TB_VIS_OUT_OF_RANGE,
                  "light 1: %g %g %g %g %g", v[0], v[1], v[2], v[3], v[4]);
        tb_reference_destroy(ref);
    }
    tb_scene_free(&s);
}

/* perspective: tb_unproject_pixel inverts a double-precision view-projection */
static void mat4_mul(const double a[16], const double b[16], double o[16]) {
    int r, c, k;
    for (c = 0; c < 4; c++)
        for (r = 0; r < 4; r++) {
            double s = 0;
            for (k = 0; k < 4; k++) s += a[k * 4 + r] * b[c * 4 + k];
            o[c * 4 + r] = s;
        }
}


/* gluPerspective * gluLookAt (up = +y) in double: VP and its inverse */
static int perspective_look(double fovy, double aspect, double zn, double zf, const double eye[3],
                            const double target[3], double VP[16], double IVP[16]) {
    double P[16] = {0}, V[16] = {0}, f[3], r[3], u[3], upw[3] = {0, 1, 0};
    double t = 1.0 / tan(fovy / 2);
    int k;
    P[0] = t / aspect; P[5] = t; P[10] = (zf + zn) / (zn - zf); P[11] = -1; P[14] = 2 * zf * zn / (zn - zf);
    for (k = 0; k < 3; k++) f[k] = target[k] - eye[k];
    normalize3(f);
    cross3(f, upw, r);
    normalize3(r);
    cross3(r, f, u);
    for (k = 0; k < 3; k++) { V[k * 4 + 0] = r[k]; V[k * 4 + 1] = u[k]; V[k * 4 + 2] = -f[k]; }
    V[12] = -(r[0] * eye[0] + r[1] * eye[1] + r[2] * eye[2]);
    V[13] = -(u[0] * eye[0] + u[1] * eye[1] + u[2] * eye[2]);
    V[14] = f[0] * eye[0] + f[1] * eye[1] + f[2] * eye[2];
    V[15] = 1;
    mat4_mul(P, V, VP);
    return tb_mat4_inverse_d(VP, IVP);
}

static void test_unproject(void) {
    const double eye[3] = {2, 3, 8}, target[3] = {0, 0, 0};
    double VP[16], IVP[16];
    sk_mat4 ivp;
    int k, i, ok = 1;
    const int W = 1280, H = 720;
    CHECK(perspective_look(1.0, 16.0 / 9.0, 0.1, 200, eye, target, VP, IVP));
    for (k = 0; k < 16; k++) ivp.m[k] = (float)IVP[k];
    for (i = 0; i < 50; i++) {
        int x = (i * 997) % W, y = (i * 613) % H;
        float d = 0.5f + 0.0099f * (float)i;
        double w[3], clip[4], p4[4];
        if (tb_unproject_pixel(&ivp, W, H, x, y, d, w)) { ok = 0; continue; }
        p4[0] = w[0]; p4[1] = w[1]; p4[2] = w[2]; p4[3] = 1;
        for (k = 0; k < 4; k++)
            clip[k] = VP[k] * p4[0] + VP[4 + k] * p4[1] + VP[8 + k] * p4[2] + VP[12 + k] * p4[3];
        if (fabs((clip[0] / clip[3] + 1) * 0.5 * W - (x + 0.5)) > 2e-3 ||
            fabs((clip[1] / clip[3] + 1) * 0.5 * H - (y + 0.5)) > 2e-3 ||
            fabs((clip[2] / clip[3] + 1) * 0.5 - d) > 1e-5)
            ok = 0;
    }
    CHECK_MSG(ok, "perspective unproject round trip");
    {
        sk_mat4 zero;
        double w[3];
        memset(&zero, 0, sizeof zero);
        CHECK(tb_unproject_pixel(&zero, W, H, 0, 0, 0.5f, w) == -1);
    }
}

static void test_metrics(void) {
    const float ref[6] = {1, 0, 1, 0, -1, 0.6f};
    const float res[6] = {1, 1, 0, 0, 0, 0.6f};
    float nanres[6];
    tb_hard_error h = tb_metric_hard(ref, res, 6);
    tb_soft_error s = tb_metric_soft(ref, res, 6);
    float fp[101];
    tb_footprint_stats st;
    int i;
    CHECK(h.covered == 5 && h.false_lit == 1 && h.false_shadow == 1 && h.wrong == 2);
    CHECK_NEAR(h.pct, 40.0, 1e-9);
    CHECK(s.covered == 5);
    CHECK_NEAR(s.mae, 0.4, 1e-6);
    memcpy(nanres, res, sizeof res);
    nanres[0] = (float)NAN;
    h = tb_metric_hard(ref, nanres, 6);
    CHECK(h.invalid == 1 && h.wrong == 3);
    {
        const float r0[5] = {1, 1, 0, 0, -1}, r1[5] = {1, 0, 0, 0, 1};
        const float a0[5] = {1, 1, 0, 1, 1}, a1[5] = {0, 0, 0, 0, 0};
        tb_flip_rate f = tb_metric_flip(r0, r1, a0, a1, 5);
        /* covered in both: 4; reference flips at 1; result flips at 0 and 3 */
        CHECK(f.covered == 4 && f.ref_flips == 1 && f.flips == 2);
        CHECK_NEAR(f.pct, 50.0, 1e-9);
    }
    for (i = 0; i < 100; i++) fp[i] = (float)(100 - i);   /* 1..100 reversed */
    fp[100] = -1;                                          /* background: skipped */
    st = tb_metric_footprint(fp, 101);
    CHECK(st.count == 100);
    CHECK_NEAR(st.median, 50.5, 1e-9);
    CHECK_NEAR(st.p95, 95.05, 1e-4);
    CHECK_NEAR(st.min, 1, 0);
    CHECK_NEAR(st.max, 100, 0);
    CHECK_NEAR(st.mean, 50.5, 1e-9);
}

/* ---- tb_metric_shadow / tb_metric_penumbra on synthetic frames ---- */

/* the reference's other not-covered values (back-facing, silhouette): any
   negative value is out of every count, these two included */
#define ST_VIS_BACKFACING (-3.0f)
#define ST_VIS_SILHOUETTE (-4.0f)

static int shadow_zeroed(const tb_shadow_error *e) {
    return e->ok == 0 && e->area_pct == 0 && e->false_shadow_pct == 0 && e->false_light_pct == 0 &&
           e->edge_mean_px == 0 && e->edge_p95_px == 0 && e->covered_pct == 0 && e->covered == 0 &&
           e->shadow == 0 && e->lit == 0 && e->wrong == 0 && e->false_shadow == 0 && e->false_light == 0 &&
           e->invalid == 0 && e->edge_count == 0;
}

static int penumbra_zeroed(const tb_penumbra_error *e) {
    return e->ok == 0 && e->penumbra_mae == 0 && e->penumbra_max == 0 && e->umbra_mae == 0 && e->umbra_max == 0 &&
           e->lit_mae == 0 && e->lit_max == 0 && e->covered_mae == 0 && e->covered == 0 && e->penumbra_core == 0 &&
           e->penumbra == 0 && e->umbra == 0 && e->lit == 0 && e->invalid == 0;
}

/* shadowed (0) where x < edge_x, lit (1) elsewhere */
static void half_plane_x(float *img, int w, int h, int edge_x) {
    int x, y;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) img[y * w + x] = x < edge_x ? 0.0f : 1.0f;
}

/* the half-plane x < 32 on 64 x 32 against the same edge moved by k pixels:
   |k| columns wrong, at 0.5, 1.5, .., |k| - 0.5 px from the edge */
static void test_metric_shadow_half_plane(void) {
    enum { W = 64, H = 32 };
    static float ref[W * H], res[W * H];
    static const struct { int k; double p95; } cases[] = {{1, 0.5}, {3, 2.5}, {4, 3.5}, {-1, 0.5}, {-3, 2.5}, {-4, 3.5}};
    size_t c;
    half_plane_x(ref, W, H, 32);
    for (c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        int k = cases[c].k, ak = k < 0 ? -k : k;
        tb_shadow_error e;
        tb_hard_error hd;
        half_plane_x(res, W, H, 32 + k);
        e = tb_metric_shadow(ref, res, W, H);
        hd = tb_metric_hard(ref, res, (size_t)W * H);
        CHECK_MSG(e.ok == 1, "shift %d", k);
        CHECK_MSG(e.covered == W * H && e.shadow == 32 * H && e.lit == 32 * H, "shift %d: covered %llu shadow %llu",
                  k, (unsigned long long)e.covered, (unsigned long long)e.shadow);
        CHECK_MSG(e.wrong == (uint64_t)(ak * H) && e.invalid == 0, "shift %d: wrong %llu", k,
                  (unsigned long long)e.wrong);
        /* k > 0: the result's shadow reaches into the lit side (false shadow);
           k < 0: it stops short (false light) */
        CHECK_MSG(e.false_shadow == (uint64_t)(k > 0 ? ak * H : 0) && e.false_light == (uint64_t)(k < 0 ? ak * H : 0),
                  "shift %d: false shadow %llu, false light %llu", k, (unsigned long long)e.false_shadow,
                  (unsigned long long)e.false_light);
        CHECK_NEAR(e.area_pct, 100.0 * ak / 32.0, 1e-12);
        CHECK_NEAR(e.false_shadow_pct, k > 0 ? 100.0 * ak / 32.0 : 0.0, 1e-12);
        CHECK_NEAR(e.false_light_pct, k < 0 ? 100.0 * ak / 32.0 : 0.0, 1e-12);
        CHECK_NEAR(e.covered_pct, 100.0 * ak / 64.0, 1e-12);
        CHECK_NEAR(e.covered_pct, hd.pct, 1e-12);
        CHECK(e.edge_count == e.wrong);
        CHECK_NEAR(e.edge_mean_px, ak / 2.0, 1e-12);
        CHECK_NEAR(e.edge_p95_px, cases[c].p95, 1e-12);
    }
    {
        /* the dilution the shadow-area error removes: 3 of 32 shadow columns
           wrong read as 4.7% of the frame but 9.4% of the shadow */
        tb_shadow_error e;
        half_plane_x(res, W, H, 35);
        e = tb_metric_shadow(ref, res, W, H);
        printf("metrics: half-plane shifted 3 px: covered %.3f%%, shadow area %.3f%%, edge mean %.2f px p95 %.2f px\n",
               e.covered_pct, e.area_pct, e.edge_mean_px, e.edge_p95_px);
    }
    {
        /* the edge along rows: shadow y < 10 against y < 12 (row 0 at the bottom) */
        tb_shadow_error e;
        int x, y;
        for (y = 0; y < H; y++)
            for (x = 0; x < W; x++) {
                ref[y * W + x] = y < 10 ? 0.0f : 1.0f;
                res[y * W + x] = y < 12 ? 0.0f : 1.0f;
            }
        e = tb_metric_shadow(ref, res, W, H);
        CHECK(e.ok && e.shadow == 10 * W && e.false_shadow == 2 * W && e.false_light == 0);
        CHECK_NEAR(e.area_pct, 20.0, 1e-12);
        CHECK_NEAR(e.edge_mean_px, 1.0, 1e-12);
        CHECK_NEAR(e.edge_p95_px, 1.5, 1e-12);   /* 128 values, h = 120.65: both neighbours 1.5 */
    }
}

/* distances are Euclidean: one shadow pixel at (10,10); the result lights it
   (false light, 0.5 px: its lit neighbour is 1 px away) and shadows (13,14)
   (false shadow, 5 px from (10,10): 4.5; Chebyshev would say 3.5) */
static void test_metric_shadow_euclid(void) {
    enum { W = 32, H = 24 };
    static float ref[W * H], res[W * H];
    tb_shadow_error e;
    int i;
    for (i = 0; i < W * H; i++) ref[i] = res[i] = 1.0f;
    ref[10 * W + 10] = 0.0f;
    res[14 * W + 13] = 0.0f;
    e = tb_metric_shadow(ref, res, W, H);
    CHECK(e.ok && e.shadow == 1 && e.lit == W * H - 1 && e.false_light == 1 && e.false_shadow == 1 && e.wrong == 2);
    CHECK_NEAR(e.area_pct, 200.0, 1e-12);   /* not clamped: more wrong than shadow */
    CHECK_NEAR(e.false_shadow_pct, 100.0, 1e-12);
    CHECK_NEAR(e.false_light_pct, 100.0, 1e-12);
    CHECK(e.edge_count == 2);
    CHECK_NEAR(e.edge_mean_px, 2.5, 1e-12);
    CHECK_NEAR(e.edge_p95_px, 0.5 + 0.95 * 4.0, 1e-12);   /* between 0.5 and 4.5 at h = 0.95 */
    /* a false shadow 3 px to the right and 4 px down of the shadow pixel: row 0 at the bottom, same distance */
    res[14 * W + 13] = 1.0f;
    res[6 * W + 13] = 0.0f;
    e = tb_metric_shadow(ref, res, W, H);
    CHECK_NEAR(e.edge_mean_px, 2.5, 1e-12);
}

/* non-covered reference pixels (negative, NaN) are in no count, no
   denominator and no edge: on the 3-column shift, column 32 (the first lit
   one) is back-facing, column 0 silhouette, column 1 NaN, 24 pixels of the
   top row background; the result is wrong on all of them */
static void test_metric_shadow_excluded(void) {
    enum { W = 64, H = 32 };
    static float ref[W * H], res[W * H];
    tb_shadow_error e;
    tb_hard_error hd;
    int x, y;
    half_plane_x(ref, W, H, 32);
    half_plane_x(res, W, H, 35);
    for (y = 0; y < H; y++) {
        ref[y * W + 0] = ST_VIS_SILHOUETTE;
        res[y * W + 0] = 1.0f;
        ref[y * W + 1] = (float)NAN;
        res[y * W + 1] = 1.0f;
        ref[y * W + 32] = ST_VIS_BACKFACING;
    }
    for (x = 40; x < W; x++) {
        ref[(H - 1) * W + x] = TB_VIS_BACKGROUND;
        res[(H - 1) * W + x] = 0.0f;
    }
    e = tb_metric_shadow(ref, res, W, H);
    hd = tb_metric_hard(ref, res, (size_t)W * H);
    CHECK(e.ok);
    CHECK_MSG(e.shadow == 30 * H && e.lit == 31 * H - 24 && e.covered == 30 * H + 31 * H - 24,
              "shadow %llu lit %llu covered %llu", (unsigned long long)e.shadow, (unsigned long long)e.lit,
              (unsigned long long)e.covered);
    CHECK(e.wrong == 2 * H && e.false_shadow == 2 * H && e.false_light == 0 && e.invalid == 0);
    CHECK_NEAR(e.area_pct, 100.0 * 64.0 / 960.0, 1e-12);
    CHECK_NEAR(e.covered_pct, 100.0 * 64.0 / 1928.0, 1e-12);
    CHECK_NEAR(e.covered_pct, hd.pct, 1e-12);
    /* columns 33 and 34 measure to column 31 (32 is no site): 1.5 and 2.5 */
    CHECK(e.edge_count == 2 * H);
    CHECK_NEAR(e.edge_mean_px, 2.0, 1e-12);
    CHECK_NEAR(e.edge_p95_px, 2.5, 1e-12);
}

/* no shadow in the reference: the shadow-area figures are 0 and `shadow`
   says why; the false shadow still counts; no edge to measure */
static void test_metric_shadow_empty(void) {
    enum { W = 16, H = 8 };
    static float ref[W * H], res[W * H];
    tb_shadow_error e;
    int i;
    for (i = 0; i < W * H; i++) ref[i] = res[i] = 1.0f;
    e = tb_metric_shadow(ref, res, W, H);
    CHECK(e.ok && e.covered == W * H && e.shadow == 0 && e.wrong == 0);
    CHECK(e.area_pct == 0 && e.covered_pct == 0 && e.edge_mean_px == 0 && e.edge_p95_px == 0);
    for (i = 0; i < 5; i++) res[7 * i + 3] = 0.0f;
    e = tb_metric_shadow(ref, res, W, H);
    CHECK(e.ok && e.shadow == 0 && e.false_shadow == 5 && e.wrong == 5 && e.edge_count == 0);
    CHECK(e.area_pct == 0 && e.false_shadow_pct == 0 && e.false_light_pct == 0);
    CHECK(e.edge_mean_px == 0 && e.edge_p95_px == 0);
    CHECK_NEAR(e.covered_pct, 100.0 * 5 / (W * H), 1e-12);
    /* all shadow, 6 pixels lit by the result: false light, no lit class, no edge */
    for (i = 0; i < W * H; i++) { ref[i] = 0.0f; res[i] = i % 20 == 0 ? 1.0f : 0.0f; }
    e = tb_metric_shadow(ref, res, W, H);
    CHECK(e.ok && e.shadow == W * H && e.lit == 0 && e.false_light == 7 && e.edge_count == 0);
    CHECK_NEAR(e.area_pct, 100.0 * 7 / (W * H), 1e-12);
    CHECK_NEAR(e.false_light_pct, 100.0 * 7 / (W * H), 1e-12);
    /* nothing covered */
    for (i = 0; i < W * H; i++) ref[i] = TB_VIS_BACKGROUND;
    e = tb_metric_shadow(ref, res, W, H);
    CHECK(e.ok && e.covered == 0 && e.wrong == 0 && e.area_pct == 0 && e.covered_pct == 0);
}

/* NaN and infinite results are wrong (invalid), neither false shadow nor
   false light, and measured to the edge by their reference class */
static void test_metric_shadow_nan(void) {
    enum { W = 64, H = 32 };
    static float ref[W * H], res[W * H];
    tb_shadow_error e;
    half_plane_x(ref, W, H, 32);
    half_plane_x(res, W, H, 32);
    res[5 * W + 40] = (float)NAN;        /* lit, 9 px from column 31: 8.5 */
    res[7 * W + 10] = (float)INFINITY;   /* shadowed, 22 px from column 32: 21.5 */
    res[0 * W + 31] = -(float)INFINITY;  /* shadowed, next to the edge: 0.5 */
    e = tb_metric_shadow(ref, res, W, H);
    CHECK(e.ok && e.invalid == 3 && e.wrong == 3 && e.false_shadow == 0 && e.false_light == 0);
    CHECK_NEAR(e.area_pct, 100.0 * 3 / (32 * H), 1e-12);
    CHECK(e.edge_count == 3);
    CHECK_NEAR(e.edge_mean_px, (8.5 + 21.5 + 0.5) / 3.0, 1e-12);
    CHECK_NEAR(e.edge_p95_px, 8.5 + 0.9 * 13.0, 1e-12);   /* h = 1.9 between 8.5 and 21.5 */
}

static void test_metric_shadow_bad_input(void) {
    float one[4] = {0, 1, 0, 1};
    tb_shadow_error e;
    e = tb_metric_shadow(NULL, one, 2, 2);
    CHECK(shadow_zeroed(&e));
    e = tb_metric_shadow(one, NULL, 2, 2);
    CHECK(shadow_zeroed(&e));
    e = tb_metric_shadow(one, one, 0, 2);
    CHECK(shadow_zeroed(&e));
    e = tb_metric_shadow(one, one, 2, -1);
    CHECK(shadow_zeroed(&e));
    e = tb_metric_shadow(one, one, 2, 2);
    CHECK(e.ok && e.covered == 4 && e.wrong == 0);
}

static uint32_t lcg_next(uint32_t *s) {
    *s = *s * 1664525u + 1013904223u;
    return *s >> 8;
}

/* against a brute-force search over every pixel pair: random discs of
   shadow, random flips in the result, some pixels not covered. The
   distance transform must agree to rounding. */
static void test_metric_shadow_brute(void) {
    enum { W = 47, H = 39 };
    static float ref[W * H], res[W * H];
    static double d[W * H];
    int trial;
    for (trial = 0; trial < 6; trial++) {
        uint32_t s = 12345u + 977u * (uint32_t)trial;
        int i, j, m = 0, discs = 1 + trial % 4;
        double sum = 0, mean, p95, hp;
        tb_shadow_error e;
        for (i = 0; i < W * H; i++) ref[i] = 1.0f;
        for (j = 0; j < discs; j++) {
            double cx = lcg_next(&s) % W, cy = lcg_next(&s) % H, r = 1 + lcg_next(&s) % (trial < 3 ? 12 : 3);
            for (i = 0; i < W * H; i++) {
                double dx = i % W + 0.5 - cx, dy = i / W + 0.5 - cy;
                if (dx * dx + dy * dy < r * r) ref[i] = 0.0f;
            }
        }
        for (i = 0; i < W * H; i++) {
            uint32_t u = lcg_next(&s) % 100;
            res[i] = u < 7 ? 1.0f - ref[i] : ref[i];
            if (u >= 97) ref[i] = u == 99 ? ST_VIS_BACKFACING : TB_VIS_BACKGROUND;
        }
        for (i = 0; i < W * H; i++) {
            int k;
            double best = INFINITY;
            if (ref[i] < 0 || (res[i] >= 0.5f) == (ref[i] >= 0.5f)) continue;
            for (k = 0; k < W * H; k++) {
                double dx, dy, q;
                if (ref[k] < 0 || (ref[k] >= 0.5f) == (ref[i] >= 0.5f)) continue;
                dx = k % W - i % W;
                dy = k / W - i / W;
                q = sqrt(dx * dx + dy * dy) - 0.5;
                if (q < best) best = q;
            }
            if (best == INFINITY) continue;
            d[m++] = best < 0 ? 0 : best;
            sum += d[m - 1];
        }
        /* insertion sort, then the quantile definition of tb_metrics.h */
        for (i = 1; i < m; i++)
            for (j = i; j > 0 && d[j - 1] > d[j]; j--) { double t = d[j]; d[j] = d[j - 1]; d[j - 1] = t; }
        mean = m ? sum / m : 0;
        hp = (m - 1) * 0.95;
        p95 = m ? d[(int)hp] + (hp - floor(hp)) * ((int)hp + 1 < m ? d[(int)hp + 1] - d[(int)hp] : 0) : 0;
        e = tb_metric_shadow(ref, res, W, H);
        CHECK_MSG(e.ok && e.edge_count == (uint64_t)m && e.wrong == (uint64_t)m, "trial %d: %llu measured, brute %d",
                  trial, (unsigned long long)e.edge_count, m);
        CHECK_NEAR(e.edge_mean_px, mean, 1e-9);
        CHECK_NEAR(e.edge_p95_px, p95, 1e-9);
    }
}

/* one penumbra pixel in the middle of a lit 9 x 9 frame: its growth is a
   disc of lattice points, 1, 5, 13, 29 pixels for grow 0..3 (a square
   would give 1, 9, 25, 49) */
static void test_metric_penumbra_disc_growth(void) {
    enum { W = 9, H = 9 };
    float ref[W * H], res[W * H];
    static const uint64_t want[4] = {1, 5, 13, 29};
    tb_penumbra_error e;
    int i, g;
    for (i = 0; i < W * H; i++) ref[i] = res[i] = 1.0f;
    ref[4 * W + 4] = 0.5f;
    res[4 * W + 4] = 0.5f;
    for (g = 0; g < 4; g++) {
        e = tb_metric_penumbra(ref, res, W, H, g);
        CHECK_MSG(e.ok && e.penumbra_core == 1 && e.penumbra == want[g] && e.lit == W * H - want[g] && e.umbra == 0,
                  "grow %d: penumbra %llu, expected %llu", g, (unsigned long long)e.penumbra,
                  (unsigned long long)want[g]);
    }
    /* an uncovered pixel 2 px above never joins */
    ref[6 * W + 4] = TB_VIS_BACKGROUND;
    e = tb_metric_penumbra(ref, res, W, H, 2);
    CHECK(e.ok && e.covered == W * H - 1 && e.penumbra == 12 && e.lit == W * H - 13);
}

/* a disc penumbra: umbra r < 10, visibility (r - 10) / 10 up to r = 20,
   lit beyond, background beyond r = 30 (r from the frame centre). The
   result errs by 0.2 deep in the umbra (r < 5), by 0.05 in the penumbra's
   core, by 0.1 far out in the lit part (r >= 25), and is exact elsewhere
   (the 2-px grown rim included). */
static void test_metric_penumbra_disc(void) {
    enum { W = 64, H = 64 };
    static float ref[W * H], res[W * H];
    long core = 0, grown = 0, umbra = 0, lit = 0, deep = 0, far = 0, covered = 0;
    int x, y;
    tb_penumbra_error e, e0;
    tb_soft_error so;
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            double r = hypot(x + 0.5 - 32.0, y + 0.5 - 32.0);
            float v = r < 10 ? 0.0f : r < 20 ? (float)((r - 10) / 10) : 1.0f;
            float o = v;
            if (r > 30) { v = TB_VIS_BACKGROUND; o = 0.0f; }
            else if (r < 5) o = 0.2f;
            else if (v > 0.0f && v < 1.0f) o = v + 0.05f;
            else if (r >= 25) o = 0.9f;
            ref[y * W + x] = v;
            res[y * W + x] = o;
        }
    /* the expected regions, by direct search of the 5 x 5 neighbourhood */
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            float v = ref[y * W + x];
            int dx, dy, near = 0;
            double r = hypot(x + 0.5 - 32.0, y + 0.5 - 32.0);
            if (v < 0) continue;
            covered++;
            for (dy = -2; dy <= 2; dy++)
                for (dx = -2; dx <= 2; dx++) {
                    int xx = x + dx, yy = y + dy;
                    float q;
                    if (dx * dx + dy * dy > 4 || xx < 0 || yy < 0 || xx >= W || yy >= H) continue;
                    q = ref[yy * W + xx];
                    if (q > 0.0f && q < 1.0f) near = 1;
                }
            if (v > 0.0f && v < 1.0f) core++;
            if (near) grown++;
            else if (v == 0.0f) { umbra++; deep += r < 5; }
            else { lit++; far += r >= 25; }
        }
    e = tb_metric_penumbra(ref, res, W, H, 2);
    so = tb_metric_soft(ref, res, (size_t)W * H);
    printf("metrics: disc penumbra: %ld core, %ld grown, %ld umbra, %ld lit pixels; penumbra mae %.5f,"
           " covered mae %.5f\n", core, grown, umbra, lit, e.penumbra_mae, e.covered_mae);
    CHECK(e.ok && e.invalid == 0);
    CHECK(grown > core && core > 850 && deep > 60 && far > 750);
    CHECK_MSG(e.covered == (uint64_t)covered && e.penumbra_core == (uint64_t)core && e.penumbra == (uint64_t)grown &&
              e.umbra == (uint64_t)umbra && e.lit == (uint64_t)lit,
              "covered %llu core %llu penumbra %llu umbra %llu lit %llu", (unsigned long long)e.covered,
              (unsigned long long)e.penumbra_core, (unsigned long long)e.penumbra, (unsigned long long)e.umbra,
              (unsigned long long)e.lit);
    CHECK(e.penumbra + e.umbra + e.lit == e.covered);
    CHECK_NEAR(e.penumbra_mae, 0.05 * core / grown, 2e-7);
    CHECK_NEAR(e.penumbra_max, 0.05, 2e-7);
    CHECK_NEAR(e.umbra_mae, 0.2 * deep / umbra, 1e-7);
    CHECK_NEAR(e.umbra_max, 0.2, 1e-7);
    CHECK_NEAR(e.lit_mae, 0.1 * far / lit, 1e-7);
    CHECK_NEAR(e.lit_max, 0.1, 1e-7);
    CHECK_NEAR(e.covered_mae, so.mae, 1e-12);
    CHECK_NEAR(e.covered_mae, (0.05 * core + 0.2 * deep + 0.1 * far) / covered, 1e-7);
    /* grow 0: the core alone, its pixels all off by 0.05 */
    e0 = tb_metric_penumbra(ref, res, W, H, 0);
    CHECK(e0.ok && e0.penumbra == (uint64_t)core && e0.penumbra + e0.umbra + e0.lit == e0.covered);
    CHECK_NEAR(e0.penumbra_mae, 0.05, 2e-7);
}

/* NaN and infinite results count as error 1 */
static void test_metric_penumbra_nan(void) {
    enum { W = 8, H = 8 };
    float ref[W * H], res[W * H];
    tb_penumbra_error e;
    int i;
    for (i = 0; i < W * H; i++) ref[i] = res[i] = 1.0f;
    ref[3 * W + 3] = 0.5f;                 /* the core: its grown disc holds 13 pixels */
    ref[6 * W + 6] = res[6 * W + 6] = 0.0f;   /* umbra, sqrt(18) px from the core */
    res[3 * W + 3] = (float)NAN;
    res[0] = (float)INFINITY;              /* lit */
    e = tb_metric_penumbra(ref, res, W, H, 2);
    CHECK(e.ok && e.invalid == 2 && e.penumbra == 13 && e.umbra == 1 && e.lit == 50 && e.covered == 64);
    CHECK_NEAR(e.penumbra_mae, 1.0 / 13, 1e-12);
    CHECK_NEAR(e.penumbra_max, 1.0, 0);
    CHECK_NEAR(e.lit_mae, 1.0 / 50, 1e-12);
    CHECK_NEAR(e.lit_max, 1.0, 0);
    CHECK(e.umbra_mae == 0 && e.umbra_max == 0);
    CHECK_NEAR(e.covered_mae, 2.0 / 64, 1e-12);
    /* a hard reference: no penumbra, the regions are umbra and lit */
    ref[3 * W + 3] = 0.0f;
    res[3 * W + 3] = 0.0f;
    e = tb_metric_penumbra(ref, res, W, H, 2);
    CHECK(e.ok && e.penumbra == 0 && e.penumbra_core == 0 && e.penumbra_mae == 0 && e.umbra == 2 && e.lit == 62);
    CHECK_NEAR(e.lit_mae, 1.0 / 62, 1e-12);
}

static void test_metric_penumbra_bad_input(void) {
    float one[4] = {0, 0.5f, 1, 1};
    tb_penumbra_error e;
    e = tb_metric_penumbra(NULL, one, 2, 2, 2);
    CHECK(penumbra_zeroed(&e));
    e = tb_metric_penumbra(one, NULL, 2, 2, 2);
    CHECK(penumbra_zeroed(&e));
    e = tb_metric_penumbra(one, one, -2, 2, 2);
    CHECK(penumbra_zeroed(&e));
    e = tb_metric_penumbra(one, one, 2, 0, 2);
    CHECK(penumbra_zeroed(&e));
    e = tb_metric_penumbra(one, one, 2, 2, -1);
    CHECK(penumbra_zeroed(&e));
    e = tb_metric_penumbra(one, one, 2, 2, 2);
    CHECK(e.ok && e.covered == 4 && e.penumbra == 4 && e.penumbra_mae == 0);
}

static void test_metric_frames(void) {
    test_metric_shadow_half_plane();
    test_metric_shadow_euclid();
    test_metric_shadow_excluded();
    test_metric_shadow_empty();
    test_metric_shadow_nan();
    test_metric_shadow_bad_input();
    test_metric_shadow_brute();
    test_metric_penumbra_disc_growth();
    test_metric_penumbra_disc();
    test_metric_penumbra_nan();
    test_metric_penumbra_bad_input();
}

static void test_image(void) {
    /* 2 x 2, bottom row red, top row green: the PNG's first row must be green */
    const unsigned char px[12] = {255, 0, 0, 255, 0, 0, 0, 255, 0, 0, 255, 0};
    int w = 0, h = 0, c = 0;
    unsigned char *back;
    CHECK(tb_image_write_rgb8("out/testbed/flip.png", 2, 2, px) == 0);
    back = stbi_load("out/testbed/flip.png", &w, &h, &c, 3);
    CHECK(back != NULL);
    if (back) {
        CHECK(w == 2 && h == 2);
        CHECK(back[0] == 0 && back[1] == 255 && back[6] == 255 && back[7] == 0);
        stbi_image_free(back);
    }
    {
        const float g[4] = {0, 0.25f, 0.5f, 1};
        CHECK(tb_image_write_gray("out/testbed/gray.png", 2, 2, g, 0, 1) == 0);
    }
}

static void test_gl_one(tb_gl_backend want, const char *label, int required) {
    char err[512];
    tb_gl_context *ctx = tb_gl_context_create(want, err, sizeof err);
    tb_gl_funcs gl;
    tb_gl_fbo fbo;
    unsigned char rgba[8 * 8 * 4];
    float depth[64], red[64];
    int major = 0, minor = 0, core = 0;
    if (!ctx) {
        if (required) CHECK_MSG(ctx != NULL, "%s context: %s", label, err);
        else printf("gl %-7s skipped (%s)\n", label, err);
        return;
    }
    tb_gl_context_gl_version(ctx, &major, &minor, &core);
    printf("gl %-7s backend %s | GL_RENDERER %s | GL_VERSION %s | %d.%d %s\n", label,
           tb_gl_context_backend_name(ctx), tb_gl_context_renderer(ctx), tb_gl_context_version(ctx),
           major, minor, core ? "core" : "not core");
    CHECK_MSG(major > 3 || (major == 3 && minor >= 3), "%s: GL %d.%d", label, major, minor);
    CHECK_MSG(core, "%s: not a core profile", label);
    CHECK(tb_gl_funcs_load(&gl, tb_gl_context_getproc(ctx)) == 0);
    if (gl.Clear && tb_gl_fbo_create(&gl, &fbo, 8, 8, TB_GL_COLOR_RGBA8) == 0) {
        tb_gl_fbo_bind(&gl, &fbo);
        gl.ClearColor(0.25f, 0.5f, 1.0f, 1.0f);
        gl.ClearDepth(0.75);
        gl.Clear(0x00004000u | 0x00000100u);   /* COLOR | DEPTH */
        CHECK(tb_gl_read_rgba8(&gl, fbo.fbo, 8, 8, rgba) == 0);
        CHECK(tb_gl_read_depth(&gl, fbo.fbo, 8, 8, depth) == 0);
        CHECK_MSG(abs(rgba[4 * 27] - 64) <= 1 && abs(rgba[4 * 27 + 1] - 128) <= 1 &&
                  rgba[4 * 27 + 2] == 255 && rgba[4 * 27 + 3] == 255,
                  "%s: read back %d %d %d %d", label, rgba[108], rgba[109], rgba[110], rgba[111]);
        CHECK_NEAR(depth[27], 0.75, 1e-6);
        tb_gl_fbo_bind(&gl, NULL);
        tb_gl_fbo_destroy(&gl, &fbo);
        /* float visibility target, read back through its texture */
        CHECK(tb_gl_fbo_create(&gl, &fbo, 8, 8, TB_GL_COLOR_R16F) == 0);
        tb_gl_fbo_bind(&gl, &fbo);
        gl.ClearColor(0.5f, 0, 0, 0);
        gl.Clear(0x00004000u);
        tb_gl_fbo_bind(&gl, NULL);
        CHECK(tb_gl_read_texture_red(&gl, fbo.color_tex, 8, 8, red) == 0);
        CHECK_NEAR(red[9], 0.5, 1e-3);
        CHECK(tb_gl_read_texture_depth(&gl, fbo.depth_tex, 8, 8, depth) == 0);
        tb_gl_fbo_destroy(&gl, &fbo);
        CHECK(gl.GetError() == 0);
    } else {
        CHECK_MSG(0, "%s: FBO creation failed", label);
    }
    tb_gl_context_destroy(ctx);
}

/* The whole chain: the GL renderer draws "ground-boxes" (perspective), the
   depth and normals are read back, the reference finds the same surfaces at
   the reconstructed positions and traces the sun. */
static void test_gl_pipeline(void) {
    const int W = 320, H = 240;
    const double eye[3] = {-9, 7, 12}, target[3] = {0, 1, 0};
    char err[1024];
    tb_gl_context *ctx = tb_gl_context_create(TB_GL_AUTO, err, sizeof err);
    tb_gl_funcs gl;
    tb_gl_fbo fbo;
    tb_gl_mesh mesh;
    tb_gl_gbuffer gb;
    tb_scene s;
    tb_reference *ref = NULL;
    tb_view view;
    sk_mat4 vp;
    double VP[16], IVP[16];
    float *depth = (float *)malloc(sizeof(float) * W * H);
    float *rgba = (float *)malloc(sizeof(float) * 4 * W * H);
    float *nrm = (float *)malloc(sizeof(float) * 3 * W * H);
    float *gen = (float *)malloc(sizeof(float) * 3 * W * H);
    float *vis = (float *)malloc(sizeof(float) * W * H);
    float *vis0 = (float *)malloc(sizeof(float) * W * H);
    unsigned char *img = (unsigned char *)malloc((size_t)3 * W * H);
    tb_light sun;
    long covered = 0, found = 0, agree = 0, i;
    int k;
    tb_scene_init(&s);
    memset(&fbo, 0, sizeof fbo);
    memset(&mesh, 0, sizeof mesh);
    memset(&gb, 0, sizeof gb);
    CHECK_MSG(ctx != NULL, "context: %s", err);
    if (!ctx || !depth || !rgba || !nrm || !gen || !vis || !vis0 || !img) goto done;
    CHECK(tb_gl_funcs_load(&gl, tb_gl_context_getproc(ctx)) == 0);
    CHECK(tb_scene_build_ground_boxes(&s) == 0);
    CHECK(tb_gl_fbo_create(&gl, &fbo, W, H, TB_GL_COLOR_RGBA16F) == 0);
    CHECK(tb_gl_mesh_create(&gl, &mesh, &s) == 0);
    CHECK_MSG(tb_gl_gbuffer_create(&gl, &gb, err, sizeof err) == 0, "gbuffer program: %s", err);
    CHECK(perspective_look(0.9, (double)W / H, 0.5, 100, eye, target, VP, IVP));
    memset(&view, 0, sizeof view);
    for (k = 0; k < 16; k++) { vp.m[k] = (float)VP[k]; view.inv_view_proj.m[k] = (float)IVP[k]; }
    view.width = W;
    view.height = H;
    CHECK(tb_gl_gbuffer_render(&gl, &gb, &mesh, &fbo, &vp) == 0);
    CHECK(tb_gl_read_depth(&gl, fbo.fbo, W, H, depth) == 0);
    CHECK(tb_gl_read_rgba_float(&gl, fbo.fbo, W, H, rgba) == 0);
    for (i = 0; i < (long)W * H; i++)
        for (k = 0; k < 3; k++) nrm[3 * i + k] = rgba[4 * i + k];
    ref = tb_reference_create(&s);
    CHECK(ref != NULL);
    if (!ref) goto done;
    CHECK(tb_reference_normals(ref, &view, depth, NULL, gen) == 0);
    for (i = 0; i < (long)W * H; i++) {
        const float *a = gen + 3 * i, *b = nrm + 3 * i;
        if (!(depth[i] < 1.0f)) continue;
        covered++;
        if (a[0] != 0 || a[1] != 0 || a[2] != 0) found++;
        if (a[0] * b[0] + a[1] * b[1] + a[2] * b[2] > 0.99f) agree++;
    }
    printf("gl pipeline: %ld covered pixels; Embree finds the GL surface at %ld, normals agree at %ld\n",
           covered, found, agree);
    CHECK(covered > W * H / 2);
    CHECK_MSG(found >= covered - covered / 200, "primary hits %ld of %ld", found, covered);
    CHECK_MSG(agree >= covered - covered / 100, "normals agree %ld of %ld", agree, covered);
    memset(&sun, 0, sizeof sun);
    sun.type = TB_LIGHT_DIRECTIONAL;
    sun.direction = v3(-0.5f, -1.0f, -0.35f);
    CHECK(tb_reference_trace(ref, &view, depth, nrm, &sun, NULL, vis) == 0);
    CHECK(tb_reference_trace(ref, &view, depth, NULL, &sun, NULL, vis0) == 0);
    {
        tb_hard_error e = tb_metric_hard(vis, vis0, (size_t)W * H);
        long shadowed = 0;
        for (i = 0; i < (long)W * H; i++) if (vis[i] == 0.0f) shadowed++;
        printf("gl pipeline: sun shadows on %ld pixels; without normals the reference differs on %.3f%%"
               " (%llu false lit, %llu false shadow)\n", shadowed, e.pct,
               (unsigned long long)e.false_lit, (unsigned long long)e.false_shadow);
        CHECK(shadowed > covered / 20);
        CHECK_MSG(e.pct < 1.0, "normal offset vs none: %.3f%%", e.pct);
    }
    {
        /* shaded picture: albedo * (0.2 + 0.8 * visibility * max(0, n.l)) */
        double l[3] = {0.5, 1.0, 0.35};
        normalize3(l);
        for (i = 0; i < (long)W * H; i++) {
            unsigned char *p = img + 3 * i;
            if (!(depth[i] < 1.0f)) { p[0] = 150; p[1] = 180; p[2] = 220; continue; }
            {
                double nl = nrm[3 * i] * l[0] + nrm[3 * i + 1] * l[1] + nrm[3 * i + 2] * l[2];
                double c = 0.2 + 0.8 * (vis[i] > 0 ? vis[i] : 0) * (nl > 0 ? nl : 0);
                p[0] = (unsigned char)(230 * c);
                p[1] = (unsigned char)(220 * c);
                p[2] = (unsigned char)(200 * c);
            }
        }
        CHECK(tb_image_write_rgb8("out/testbed-selftest-gl.png", W, H, img) == 0);
    }
    CHECK(gl.GetError() == 0);
done:
    tb_reference_destroy(ref);
    if (ctx) {
        tb_gl_gbuffer_destroy(&gl, &gb);
        tb_gl_mesh_destroy(&gl, &mesh);
        tb_gl_fbo_destroy(&gl, &fbo);
        tb_gl_context_destroy(ctx);
    }
    tb_scene_free(&s);
    free(depth); free(rgba); free(nrm); free(gen); free(vis); free(vis0); free(img);
}

static void test_gl(void) {
    test_gl_one(TB_GL_OSMESA, "osmesa", 1);
    test_gl_one(TB_GL_EGL, "egl", 0);
    test_gl_one(TB_GL_AUTO, "auto", 1);
    test_gl_pipeline();
}

int main(void) {
    test_procedural();
    test_assets();
    test_unproject();
    test_reference_hard();
    test_reference_area();
    test_reference_point();
    test_interior();
    test_metrics();
    test_metric_frames();
    test_image();
    test_gl();
    printf("wrote out/testbed-selftest.png, out/testbed-selftest-error.png, out/testbed-selftest-gl.png\n");
    printf("testbed-selftest: %d passed, %d failed\n", g_pass, g_fail);
    return g_fail ? 1 : 0;
}
