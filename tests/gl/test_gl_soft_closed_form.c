/* test_gl_soft_closed_form.c - PCSS and PVSM (skgl_soft_*) against a
   closed-form soft shadow, per pixel, in double.

   The scene: a square plate (half size a, at height h_p, two triangles)
   over a receiver, lit by a square light of half size L parallel to the
   plate at height h_l. From a receiver point p below the plate, the plate
   covers on the light's plane the square centred at p + (c - p) k with
   half size a k, k = (h_l - p_y) / (h_p - p_y), c the plate's centre; the
   visible fraction of the light is 1 - (overlap of that square with the
   light) / (2L)^2, exact as long as the whole light is in front of the
   receiver's tangent plane (true in every scene here). The receiver is
   the ground (y = 0) or the ground turned about z ("tilted"). Points are
   the G-buffer's (gt_world, row 0 at the bottom); penumbra = pixels with
   0 < truth < 1 grown by 2 pixels; umbra and lit are the other pixels
   with truth 0 and 1. This is the soft-shadow error of DESIGN.md, with an
   exact truth instead of a sampled one.

   Displacement: for every penumbra pixel with 0.05 < truth < 0.95 whose
   truth gradient (along the receiver) lies along one axis (away from the
   shadow's corners, where the other factor of the overlap is constant), the
   result is the truth moved by d = (truth - result) / gradient; the mean d
   per edge of the shadow (-x, +x, -z, +z) is where the result's iso-lines
   sit against the truth's. A blocker edge rasterised into a map lands on
   the nearest texel boundary: the shift that rounding predicts is printed
   beside the measured one (flat receivers).

   Scenes (all five at L = 0.1, 0.2, 0.4; plate half 0.6 at 1 m unless
   said; W x H pixels):
     offset    light (2, 4, 0), camera far (400 x 300): penumbrae 4-20 px
     overhead  light (0, 5, 0), plate half 0.5, the contact camera of
               test_gl_soft (320 x 180): penumbrae 2-8 px
     close     light (2, 4, 0), camera 1.5 m from the shadow: 15-65 px
     tilted    the offset scene on a ground turned by 0.6 rad
     low       the plate 8 cm above the ground: penumbrae of 0.4-1.6 px
   Runs: PCSS at 2048^2 and 4096^2 and PVSM with every default (tiles up
   to 4096^2, rho_dynamic, anti-aliasing on) everywhere; PVSM at
   resolution_scale 4 (not on the low plate), PVSM at resolution_scale 8
   with disable_antialias (the filter is the light's alone, point-sampled like
   the truth; overhead and low), and PVSM at resolution_scale 4 with tiles
   of at most 256^2 (offset: several tiles, merged).

   The measured figures, the diagnosis and the thresholds are after the
   helpers (MEASURED). Pictures: out/tests/soft-cf-<scene>-<light>-<run>.png
   and -error.png. */
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "sk_test.h"
#include "gl/gl_test_util.h"

#include <stdio.h>
#include <stdlib.h>

#define NSCENES 5
#define NLIGHTS 3
#define NRUNS 6

typedef struct cf_run {
    const char *name;
    skgl_soft_technique technique;
    int resolution;
    float scale;
    int antialias;
    float rel_bias, slope_bias, depth_bias;   /* 0: the default; both biases < 0: disable_polygon_offset */
} cf_run;

static const cf_run cf_runs[NRUNS] = {
    {"pcss-2048", SKGL_SOFT_PCSS, 2048, 0.0f, 0, 0.0f, 0.0f, 0.0f},
    {"pcss-4096", SKGL_SOFT_PCSS, 4096, 0.0f, 0, 0.0f, 0.0f, 0.0f},
    {"pvsm", SKGL_SOFT_PVSM, 0, 0.0f, 0, 0.0f, 0.0f, 0.0f},
    {"pvsm-x4", SKGL_SOFT_PVSM, 0, 4.0f, 0, 0.0f, 0.0f, 0.0f},
    {"pvsm-x8-pt", SKGL_SOFT_PVSM, 0, 8.0f, -1, 0.0f, 0.0f, 0.0f},
    {"pvsm-x4-256", SKGL_SOFT_PVSM, 256, 4.0f, 0, 0.0f, 0.0f, 0.0f},
};
enum { R_PCSS2048, R_PCSS4096, R_PVSM, R_PVSM_X4, R_PVSM_X8_PT, R_PVSM_X4_256 };
#define CF_BIT(r) (1u << (r))
#define CF_BASE (CF_BIT(R_PCSS2048) | CF_BIT(R_PCSS4096) | CF_BIT(R_PVSM))

typedef struct cf_scene {
    const char *name;
    unsigned runs;                /* bit r: cf_runs[r] is measured here */
    int w, h;
    double plate_y, plate_half;   /* plate: y = plate_y, |x|, |z| <= plate_half */
    double tilt;                  /* receiver: the ground turned by tilt about z: y = x tan(tilt) */
    double light[3];              /* centre of the light, parallel to the plate */
    float eye[3], target[3], fovy;
} cf_scene;

static const cf_scene cf_scenes[NSCENES] = {
    {"offset", CF_BASE | CF_BIT(R_PVSM_X4) | CF_BIT(R_PVSM_X4_256), 400, 300,
     1.0, 0.6, 0.0, {2.0, 4.0, 0.0}, {-3.5f, 3.5f, 1.5f}, {-0.6f, 0.0f, 0.0f}, 0.8f},
    {"overhead", CF_BASE | CF_BIT(R_PVSM_X4) | CF_BIT(R_PVSM_X8_PT), 320, 180,
     1.0, 0.5, 0.0, {0.0, 5.0, 0.0}, {3.0f, 2.2f, 3.6f}, {-0.6f, 0.2f, -0.4f}, 0.9f},
    {"close", CF_BASE | CF_BIT(R_PVSM_X4), 400, 300,
     1.0, 0.6, 0.0, {2.0, 4.0, 0.0}, {-1.8f, 1.2f, 0.8f}, {-1.2f, 0.0f, 0.3f}, 0.8f},
    {"tilted", CF_BASE | CF_BIT(R_PVSM_X4), 400, 300,
     1.0, 0.6, 0.6, {2.0, 4.0, 0.0}, {-3.5f, 3.5f, 1.5f}, {-0.6f, 0.0f, 0.0f}, 0.8f},
    {"low", CF_BASE | CF_BIT(R_PVSM_X8_PT), 400, 300,
     0.08, 0.6, 0.0, {2.0, 4.0, 0.0}, {-2.5f, 2.5f, 1.5f}, {-0.2f, 0.0f, 0.0f}, 0.8f},
};
static const float cf_halves[NLIGHTS] = {0.1f, 0.2f, 0.4f};


/* overlap length of [a0, a1] and [b0, b1] */
static double cf_overlap(double a0, double a1, double b0, double b1) {
    double lo = a0 > b0 ? a0 : b0, hi = a1 < b1 ? a1 : b1;
    return hi > lo ? hi - lo : 0.0;
}

/* the visible fraction of the light from p (the closed form above) */
static double cf_truth(const cf_scene *c, const double p[3], double L) {
    double k, a = c->plate_half, ov;
    if (p[1] >= c->plate_y - 1e-4) return 1.0;          /* the plate's top, or receivers above it */
    k = (c->light[1] - p[1]) / (c->plate_y - p[1]);
    ov = cf_overlap(p[0] + (-a - p[0]) * k, p[0] + (a - p[0]) * k, c->light[0] - L, c->light[0] + L) *
         cf_overlap(p[2] + (-a - p[2]) * k, p[2] + (a - p[2]) * k, c->light[2] - L, c->light[2] + L);
    ov = 1.0 - ov / (4.0 * L * L);
    /* the light wholly covered (or wholly free) rounds to a few 1e-16 off 0 (1) */
    return ov < 1e-9 ? 0.0 : ov > 1.0 - 1e-9 ? 1.0 : ov;
}

static skgl_camera cf_camera(const cf_scene *c) {
    return gt_camera(gt_v3(c->eye[0], c->eye[1], c->eye[2]), gt_v3(c->target[0], c->target[1], c->target[2]),
                     c->fovy, 0.05f, 30, c->w, c->h);
}

static skgl_area_light cf_light(const cf_scene *c, float half) {
    skgl_area_light l;
    memset(&l, 0, sizeof l);
    l.position = gt_v3((float)c->light[0], (float)c->light[1], (float)c->light[2]);
    l.direction = gt_v3(0, -1, 0);
    l.up = gt_v3(0, 0, 1);          /* the light's axes are world x and z */
    l.half_width = half;
    l.half_height = half;
    return l;
}

/* ground (8 x 8, turned by the scene's tilt) and plate */
static int cf_env(gt_env *e, const cf_scene *c) {
    tb_scene s;
    uint32_t i;
    double cs = cos(c->tilt), sn = sin(c->tilt);
    tb_scene_init(&s);
    if (tb_scene_add_ground(&s, "ground", 0, 0, 4, 4, 0, 1, 1) < 0) { tb_scene_free(&s); return -1; }
    for (i = 0; i < s.vertex_count; i++) {
        float *p = s.positions + 3 * i, *n = s.normals + 3 * i;
        double x = p[0], y = p[1], nx = n[0], ny = n[1];
        p[0] = (float)(x * cs - y * sn); p[1] = (float)(x * sn + y * cs);
        n[0] = (float)(nx * cs - ny * sn); n[1] = (float)(nx * sn + ny * cs);
    }
    s.bounds.min = s.bounds.max = gt_v3(s.positions[0], s.positions[1], s.positions[2]);
    for (i = 1; i < s.vertex_count; i++) {
        const float *p = s.positions + 3 * i;
        s.bounds.min.x = p[0] < s.bounds.min.x ? p[0] : s.bounds.min.x;
        s.bounds.min.y = p[1] < s.bounds.min.y ? p[1] : s.bounds.min.y;
        s.bounds.min.z = p[2] < s.bounds.min.z ? p[2] : s.bounds.min.z;
        s.bounds.max.x = p[0] > s.bounds.max.x ? p[0] : s.bounds.max.x;
        s.bounds.max.y = p[1] > s.bounds.max.y ? p[1] : s.bounds.max.y;
        s.bounds.max.z = p[2] > s.bounds.max.z ? p[2] : s.bounds.max.z;
    }
    s.objects[0].bounds = s.bounds;
    if (tb_scene_add_ground(&s, "plate", 0, 0, (float)c->plate_half, (float)c->plate_half, (float)c->plate_y, 1,
                            1) < 0) {
        tb_scene_free(&s);
        return -1;
    }
    return gt_env_init(e, &s, c->w, c->h);
}

/* The truth of one light over the last G-buffer: per pixel the visibility
   (-1 background), its gradient along the receiver's axes t1 (the turned
   x axis) and z, the pixel's box average (8 x 8 rays against the two
   planes, penumbra pixels only: what anti-aliasing aims at), and the
   penumbra mask. */
typedef struct cf_truth_buf {
    double *v, *grad, *avg;
    unsigned char *pen;
    size_t npen;
} cf_truth_buf;

/* the camera ray through window point (sx, sy): the plate, else the receiver; -1 none */
static int cf_hit(const gt_env *e, const cf_scene *c, double sx, double sy, double out[3]) {
    double a[4] = {0, 0, 0, 0}, b[4] = {0, 0, 0, 0}, o[3], d[3], t, n[3];
    double ndc0[4], ndc1[4];
    const float *m = e->inv_vp.m;
    int j, k;
    ndc0[0] = ndc1[0] = 2.0 * sx / e->w - 1.0;
    ndc0[1] = ndc1[1] = 2.0 * sy / e->h - 1.0;
    ndc0[2] = -1.0; ndc1[2] = 1.0;
    ndc0[3] = ndc1[3] = 1.0;
    for (j = 0; j < 4; j++)
        for (k = 0; k < 4; k++) { a[j] += m[k * 4 + j] * ndc0[k]; b[j] += m[k * 4 + j] * ndc1[k]; }
    for (j = 0; j < 3; j++) { o[j] = a[j] / a[3]; d[j] = b[j] / b[3] - o[j]; }
    if (d[1] != 0.0) {
        t = (c->plate_y - o[1]) / d[1];
        if (t > 0 && fabs(o[0] + t * d[0]) <= c->plate_half && fabs(o[2] + t * d[2]) <= c->plate_half) {
            for (j = 0; j < 3; j++) out[j] = o[j] + t * d[j];
            return 0;
        }
    }
    n[0] = -sin(c->tilt); n[1] = cos(c->tilt); n[2] = 0.0;
    t = n[0] * d[0] + n[1] * d[1];
    if (t == 0.0) return -1;
    t = -(n[0] * o[0] + n[1] * o[1]) / t;
    if (t <= 0) return -1;
    for (j = 0; j < 3; j++) out[j] = o[j] + t * d[j];
    return 0;
}

static void cf_fill_truth(const gt_env *e, const cf_scene *c, double L, cf_truth_buf *tb) {
    double t1[3], t2[3] = {0, 0, 1};
    unsigned char *core = (unsigned char *)calloc(e->n, 1);
    size_t i;
    int x, y, W = e->w, H = e->h;
    t1[0] = cos(c->tilt); t1[1] = sin(c->tilt); t1[2] = 0.0;
    tb->npen = 0;
    for (i = 0; i < e->n; i++) {
        double p[3], q[3], r[3];
        int j;
        tb->pen[i] = 0;
        tb->grad[2 * i] = tb->grad[2 * i + 1] = 0.0;
        tb->avg[i] = -1.0;
        if (gt_world(e, i, p)) { tb->v[i] = -1.0; continue; }
        tb->v[i] = tb->avg[i] = cf_truth(c, p, L);
        for (j = 0; j < 3; j++) { q[j] = p[j] + 5e-4 * t1[j]; r[j] = p[j] - 5e-4 * t1[j]; }
        tb->grad[2 * i] = (cf_truth(c, q, L) - cf_truth(c, r, L)) / 1e-3;
        for (j = 0; j < 3; j++) { q[j] = p[j] + 5e-4 * t2[j]; r[j] = p[j] - 5e-4 * t2[j]; }
        tb->grad[2 * i + 1] = (cf_truth(c, q, L) - cf_truth(c, r, L)) / 1e-3;
        if (core) core[i] = tb->v[i] > 0.0 && tb->v[i] < 1.0;
    }
    for (y = 0; y < H && core; y++)
        for (x = 0; x < W; x++) {
            size_t cc = (size_t)y * W + (size_t)x;
            int dx, dy, sx, sy, cnt = 0;
            double sum = 0.0;
            if (tb->v[cc] < 0.0) continue;
            for (dy = -2; dy <= 2 && !tb->pen[cc]; dy++)
                for (dx = -2; dx <= 2; dx++) {
                    int u = x + dx, v = y + dy;
                    if (u >= 0 && v >= 0 && u < W && v < H && core[(size_t)v * W + (size_t)u]) {
                        tb->pen[cc] = 1;
                        break;
                    }
                }
            if (!tb->pen[cc]) continue;
            tb->npen++;
            for (sy = 0; sy < 8; sy++)
                for (sx = 0; sx < 8; sx++) {
                    double h[3];
                    if (cf_hit(e, c, x + (sx + 0.5) / 8.0, y + (sy + 0.5) / 8.0, h)) continue;
                    sum += cf_truth(c, h, L);
                    cnt++;
                }
            if (cnt) tb->avg[cc] = sum / cnt;
        }
    free(core);
}

typedef struct cf_err {
    double pen_mae, pen_max, pen_signed, umb_mae, umb_max, lit_mae, lit_max;
    double pen_mae_avg;          /* penumbra against the pixel's box average */
    double shift[4], snap[4];    /* per edge (-x, +x, -z, +z): measured shift, rounding's prediction (m) */
    size_t shift_n[4];
    double texel[4];             /* the map's texel on the receiver across that edge (m) */
    int tiles, resolution;
} cf_err;

static cf_err cf_measure(const gt_env *e, const cf_truth_buf *tb, const float *res) {
    cf_err s;
    size_t i, np = 0, nu = 0, nl = 0;
    memset(&s, 0, sizeof s);
    for (i = 0; i < e->n; i++) {
        double t = tb->v[i], d;
        if (t < 0.0) continue;
        d = (double)res[i] - t;
        if (tb->pen[i]) {
            s.pen_mae += fabs(d); s.pen_signed += d; np++;
            s.pen_mae_avg += fabs((double)res[i] - tb->avg[i]);
            if (fabs(d) > s.pen_max) s.pen_max = fabs(d);
            if (t > 0.05 && t < 0.95) {
                double gx = tb->grad[2 * i], gz = tb->grad[2 * i + 1];
                int q = -1;
                double g = 0.0;
                if (gz == 0.0 && gx != 0.0) { q = gx < 0.0 ? 0 : 1; g = gx; }
                else if (gx == 0.0 && gz != 0.0) { q = gz < 0.0 ? 2 : 3; g = gz; }
                if (q >= 0) { s.shift[q] += -d / g; s.shift_n[q]++; }
            }
        } else if (t <= 0.0) {
            s.umb_mae += fabs(d); nu++;
            if (fabs(d) > s.umb_max) s.umb_max = fabs(d);
        } else {
            s.lit_mae += fabs(d); nl++;
            if (fabs(d) > s.lit_max) s.lit_max = fabs(d);
        }
    }
    if (np) { s.pen_mae /= (double)np; s.pen_signed /= (double)np; s.pen_mae_avg /= (double)np; }
    if (nu) s.umb_mae /= (double)nu;
    if (nl) s.lit_mae /= (double)nl;
    for (i = 0; i < 4; i++)
        if (s.shift_n[i]) s.shift[i] /= (double)s.shift_n[i];
    return s;
}

/* Where texel rounding puts each edge of the plate (flat receivers): the
   plate's edge midpoint in the map (PVSM: the tile holding it, its rect in
   SMTG cells and resolution; PCSS: the whole base map), the shift to the
   nearest texel boundary, carried to the ground through the map's
   constant Jacobian there (the ground is parallel to the map plane). */
static void cf_snap(const cf_scene *c, const skgl_soft *so, cf_err *s) {
    sk_mat4 vp = skgl_soft_matrix(so);
    skgl_soft_desc d = skgl_soft_get_desc(so);
    sk_tile tiles[64];
    int q, j, nt = d.technique == SKGL_SOFT_PVSM ? skgl_soft_tiles(so, tiles, 64) : 0;
    double sx = c->light[0] - c->light[0] * c->light[1] / (c->light[1] - c->plate_y);
    double sz = c->light[2] - c->light[2] * c->light[1] / (c->light[1] - c->plate_y);
    if (nt > 64) nt = 64;
    if (c->tilt != 0.0) return;
    for (q = 0; q < 4; q++) {
        float ph = (float)c->plate_half, py = (float)c->plate_y;
        sk_vec3 mid = q < 2 ? gt_v3(q == 0 ? -ph : ph, py, 0) : gt_v3(0, py, q == 2 ? -ph : ph);
        sk_vec3 m = sk_mat4_transform_point(vp, mid);
        sk_vec3 g0 = sk_mat4_transform_point(vp, gt_v3((float)sx, 0, (float)sz));
        sk_vec3 g1 = sk_mat4_transform_point(vp, gt_v3((float)sx + (q < 2 ? 0.01f : 0.0f), 0,
                                                       (float)sz + (q < 2 ? 0.0f : 0.01f)));
        double v = q < 2 ? m.x : m.y, other = q < 2 ? m.y : m.x;
        double per = 0.01 / (q < 2 ? g1.x - g0.x : g1.y - g0.y);      /* ground metres per NDC unit */
        double r0 = -1.0, r1 = 1.0, res = d.resolution, u;
        if (nt > 0) {
            double g = (double)d.grid;
            for (j = 0; j < nt; j++) {
                double a0 = -1.0 + 2.0 * (q < 2 ? tiles[j].x0 : tiles[j].y0) / g;
                double a1 = -1.0 + 2.0 * (q < 2 ? tiles[j].x1 : tiles[j].y1) / g;
                double b0 = -1.0 + 2.0 * (q < 2 ? tiles[j].y0 : tiles[j].x0) / g;
                double b1 = -1.0 + 2.0 * (q < 2 ? tiles[j].y1 : tiles[j].x1) / g;
                if (v >= a0 && v <= a1 && other >= b0 && other <= b1) {
                    r0 = a0; r1 = a1;
                    res = q < 2 ? tiles[j].res_x : tiles[j].res_y;
                    break;
                }
            }
            if (j == nt) continue;
        }
        u = (v - r0) * res / (r1 - r0);
        s->snap[q] = (floor(u + 0.5) - u) * (r1 - r0) / res * per;
        s->texel[q] = fabs((r1 - r0) / res * per);
    }
}

/* one run over the last G-buffer; image: out/tests/<image>.png or NULL */
static cf_err cf_frame(gt_env *e, const cf_scene *c, const cf_run *r, const skgl_area_light *l,
                       const cf_truth_buf *tb, float *mask, const char *image) {
    skgl_soft_desc d;
    skgl_soft *so = NULL;
    skgl_camera cam = cf_camera(c);
    skgl_soft_frame_stats st;
    cf_err s;
    sk_result rr;
    memset(&s, 0, sizeof s);
    s.pen_mae = -1.0;
    memset(&d, 0, sizeof d);
    d.technique = r->technique;
    d.resolution = r->resolution;
    d.resolution_scale = r->scale;
    d.disable_antialias = r->antialias < 0;
    d.rel_bias = r->rel_bias;
    d.slope_bias = r->slope_bias < 0.0f ? 0.0f : r->slope_bias;
    d.depth_bias = r->depth_bias < 0.0f ? 0.0f : r->depth_bias;
    d.disable_polygon_offset = r->slope_bias < 0.0f && r->depth_bias < 0.0f;
    rr = skgl_soft_create(e->sk, &d, &so);
    if (rr != SK_OK) {
        SK_CHECK_MSG(0, "skgl_soft_create: %s (%s)", sk_result_string(rr), skgl_error_log(e->sk));
        return s;
    }
    if (gt_soft_mask(e, so, &cam, l, mask, &st) == 0) {
        s = cf_measure(e, tb, mask);
        s.tiles = st.tiles;
        s.resolution = st.resolution;
        cf_snap(c, so, &s);
        if (image) {
            float *tv = gt_alloc(e);
            size_t i;
            for (i = 0; tv && i < e->n; i++) tv[i] = (float)tb->v[i];
            if (tv) gt_images(e, image, tv, mask);
            free(tv);
        }
    } else
        SK_CHECK_MSG(0, "%s %s: skgl_soft_render failed", c->name, r->name);
    SK_CHECK_MSG(e->gl.GetError() == 0, "%s %s: GL error", c->name, r->name);
    skgl_soft_destroy(e->sk, so);
    return s;
}

/* a scene's GL environment, its G-buffer and the truth buffers */
typedef struct cf_ctx {
    gt_env e;
    cf_truth_buf tb;
    float *mask;
    int objects;          /* shadowkit's GL objects before any run */
} cf_ctx;

static void cf_close(cf_ctx *x) {
    free(x->tb.v); free(x->tb.avg); free(x->tb.grad); free(x->tb.pen); free(x->mask);
    if (x->e.sk)
        SK_CHECK_MSG(skgl_gl_object_count(x->e.sk) == x->objects, "GL objects %d, before %d",
                     skgl_gl_object_count(x->e.sk), x->objects);
    gt_env_free(&x->e);
}

/* 0 ok; -1 (counted as a failed check) otherwise, x closed */
static int cf_open(cf_ctx *x, const cf_scene *c) {
    skgl_camera cam = cf_camera(c);
    memset(x, 0, sizeof *x);
    if (cf_env(&x->e, c)) { gt_env_free(&x->e); return -1; }
    x->objects = skgl_gl_object_count(x->e.sk);
    x->tb.v = (double *)malloc(sizeof(double) * x->e.n);
    x->tb.avg = (double *)malloc(sizeof(double) * x->e.n);
    x->tb.grad = (double *)malloc(sizeof(double) * 2 * x->e.n);
    x->tb.pen = (unsigned char *)calloc(x->e.n, 1);
    x->mask = gt_alloc(&x->e);
    if (!x->tb.v || !x->tb.avg || !x->tb.grad || !x->tb.pen || !x->mask || gt_gbuffer(&x->e, &cam)) {
        SK_CHECK_MSG(0, "%s: setup", c->name);
        cf_close(x);
        return -1;
    }
    return 0;
}

static cf_err cf_results[NSCENES][NLIGHTS][NRUNS];

static void cf_measure_all(void) {
    int sc, k, r, q;
    for (sc = 0; sc < NSCENES; sc++) {
        const cf_scene *c = &cf_scenes[sc];
        cf_ctx x;
        if (cf_open(&x, c)) continue;
        for (k = 0; k < NLIGHTS; k++) {
            skgl_area_light l = cf_light(c, cf_halves[k]);
            cf_fill_truth(&x.e, c, cf_halves[k], &x.tb);
            printf("%s L %.1f: %zu penumbra pixels\n", c->name, cf_halves[k], x.tb.npen);
            SK_CHECK_MSG(x.tb.npen > 500, "%s L %.1f: %zu penumbra pixels", c->name, cf_halves[k], x.tb.npen);
            for (r = 0; r < NRUNS; r++) {
                cf_err *s = &cf_results[sc][k][r];
                char image[64];
                if (!(c->runs >> r & 1u)) { s->pen_mae = -1.0; continue; }
                snprintf(image, sizeof image, "soft-cf-%s-%d-%s", c->name, k, cf_runs[r].name);
                *s = cf_frame(&x.e, c, &cf_runs[r], &l, &x.tb, x.mask,
                              r == R_PCSS4096 || r == R_PVSM ? image : NULL);
                printf("  %-10s pen %.4f (max %.3f, signed %+.4f, vs box avg %.4f) umbra %.4f (max %.3f) lit %.4f"
                       " (max %.3f)",
                       cf_runs[r].name, s->pen_mae, s->pen_max, s->pen_signed, s->pen_mae_avg, s->umb_mae, s->umb_max,
                       s->lit_mae, s->lit_max);
                if (cf_runs[r].technique == SKGL_SOFT_PVSM) printf(" tiles %d res %d", s->tiles, s->resolution);
                printf("\n              edge shift cm (measured / texel rounding / texel):");
                for (q = 0; q < 4; q++)
                    printf(" %+.2f/%+.2f/%.2f", 100 * s->shift[q], 100 * s->snap[q], 100 * s->texel[q]);
                printf("\n");
            }
        }
        cf_close(&x);
    }
}

/* MEASURED (Mesa llvmpipe through OSMesa). Mean |error| inside the
   penumbra; in brackets the figure before the two fixes below where it
   differed. Umbra and lit are exact (0) for every run but the low plate's
   (there the 1-pixel penumbra grown by 2 pixels leaves edge pixels outside
   it: umbra mean 0.0039 / 0.0003 / 0.0009 for PCSS-2048 / PCSS-4096 / PVSM
   at L 0.1, lit mean <= 0.0001), and PVSM on the tilted ground at L 0.4
   before the first fix (lit max 0.053, umbra max 0.021).

     scene    L    pcss-2048        pcss-4096        pvsm             pvsm-x4          pvsm-x8-pt
     offset   0.1  0.0127           0.0115           0.0159           0.0064           -
     offset   0.2  0.0163           0.0166           0.0136           0.0027           -
     offset   0.4  0.0197           0.0206           0.0148           0.0043 (0.0044)  -
     overhead 0.1  0.0046           0.0049           0.0243           0.0171           0.0039
     overhead 0.2  0.0071           0.0075           0.0264           0.0096           0.0025 (0.0026)
     overhead 0.4  0.0118           0.0123           0.0145           0.0037 (0.0040)  0.0015
     close    0.1  0.0197           0.0203           0.0213           0.0071 (0.0072)  -
     close    0.2  0.0233           0.0238           0.0085           0.0049 (0.0139)  -
     close    0.4  0.0257           0.0261           0.0071           0.0067 (0.0071)  -
     tilted   0.1  0.0155           0.0159           0.0225           0.0037 (0.0040)  -
     tilted   0.2  0.0188 (0.0208)  0.0201 (0.0221)  0.0178           0.0040 (0.0120)  -
     tilted   0.4  0.0224 (0.0425)  0.0233 (0.0432)  0.0072 (0.0479)  0.0052 (0.0420)  -
     low      0.1  0.0187           0.0059           0.0480           -                0.0098
     low      0.2  0.0182           0.0088           0.0518           -                0.0061
     low      0.4  0.0149           0.0055           0.0291           -                0.0044
   pvsm-x4-256 (offset; tiles of at most 256^2, 6 / 4 / 4 of them):
   0.0061 / 0.0037 / 0.0047, as one tile (the V*A / A merge loses nothing).

   Fixed 1: texels left at the clear depth were blockers. A receiver steep
   to the light (the tilted ground), far from it, with a wide kernel: its
   plane carried across the blocker search region or the kernel passes the
   far plane (window depth > 1), and the empty texels (1) past the end of
   the ground compared as nearer: counted as blockers at the far plane
   (PCSS's average blocker depth measured 4.15 m where the plate is at 3 m)
   and, DEPTH_COMPONENT32F not clamping the comparison reference, shadowing
   in the filters. Tilted L 0.4: PCSS-4096 0.0432 -> 0.0233 (max 0.377 ->
   0.118), PVSM 0.0479 -> 0.0072 (max 0.230 -> 0.029).
   Fixed 2: PVSM integrates kernels wider than 24 texels over blocks of 2^k
   texels with one 2x2 comparison each, so an edge is resolved to a block;
   the block came from the kernel alone (1/24 of it) and threw away the
   resolution of a tile finer than that (resolution_scale > 1, rho > 12, or
   another pixel's demand). It is now at most the pixel's own predicted
   texel. Tilted x4 L 0.2: 0.0120 -> 0.0040; at x8 (antialias off) 0.0123 ->
   0.0019, where before x8 measured the same as x4.

   What remains, and why (PVSM with every default above PCSS-4096: offset,
   close and tilted at L 0.1, overhead and low at every size):
   - The blocker's edge lands on the tile's texel grid, and the tile is as
     coarse as the paper's perceptual prediction allows: Eq. 5 gives a texel
     of (kernel width) / rho(n), rho_dynamic(n) = 4 to 12 texels across the
     kernel for kernels of 5 to 40 pixels, so an edge moves by up to half a
     texel, i.e. up to 1/(2 rho) of the penumbra in visibility. The printed
     per-edge shifts are the texel rounding's to within 0.1 cm + 0.1 texel
     (asserted): overhead L 0.4 moves the -x edge by 1.40 cm where rounding
     to its 3.36 cm texels (a 54-texel tile) predicts 1.46 cm. PCSS-4096's
     texels are 0.07-0.27 cm here and its edges stay within 0.3 cm
     (asserted); its error is the banding of its 12 taps per axis (steps of
     1/12). At resolution_scale 4 (the paper's quality knob, Sec. 7) PVSM
     is at or below PCSS-4096 in offset, close and tilted at every size and
     overhead at L 0.4 (asserted). The default is left as the paper's.
   - Anti-aliasing (Sec. 4.2) widens every kernel by the pixel's footprint
     and returns the pixel's average, where the truth (and the reference of
     DESIGN.md) samples the pixel's centre; for penumbrae of 0.4-8 pixels
     (overhead, low) that difference dominates: overhead L 0.1 at x4
     measures 0.0171 against the centre and 0.0089 against the pixel's
     box average. With disable_antialias at x8, PVSM is at or below PCSS-4096
     in overhead at every size and low at L 0.2 and 0.4 (asserted).
   - low L 0.1 (penumbra 0.4 cm, 0.4 pixel): at x8 without anti-aliasing
     PVSM's texel (0.15-0.18 cm) equals PCSS-4096's and rounding decides;
     PVSM's grid grows every edge by 0.04-0.07 cm (rounding predicts the
     same), PCSS-4096's less: 0.0098 against 0.0059. resolution_scale stops
     at 8; the paper's method, which asks rho(1) = 0.667 texels across a
     one-pixel kernel, does not aim at sub-pixel placement.
   Bias (test_bias): ten times every bias term changes no figure on the
   tilted ground at L 0.4 (PCSS-4096 0.0233, PVSM 0.0072, edges unmoved);
   without bias the lit ground is acne (lit mean 0.039 PCSS-4096, 0.012
   PVSM). The default neither displaces nor is idle here; on the flat scenes
   the plate is parallel to the maps (no slope for the slope-scaled offset)
   and 0.08-1 m above the receiver (the tolerance is 0.2% of 4-5 m).

   Can fail: with shadowkit_gl.h as before the fixes, 9 checks of
   test_closed_form fail (tilted L 0.4: PVSM 0.0479 over 0.0110, PCSS-4096
   0.0432 over 0.0350, PCSS-2048 0.0425 over 0.0340, x4 0.0420 over 0.0080,
   PVSM's lit max 0.053, PVSM above PCSS-4096; x4 close L 0.2 0.0139 over
   0.0075 and tilted L 0.2 0.0120 over 0.0060) and 2 of test_bias (PCSS-4096
   0.0432 -> 0.0410 with ten times the bias; PVSM's lit max 0.053); with
   the first fix only, the two x4 checks fail.
   Run time: 14-19 s wall here (10 s CPU, 2 cores shared). */

/* penumbra MAE bounds, 1.5x the measured figure (in the comment beside),
   [scene][light][run]; 0: not run */
static const double cf_bound[NSCENES][NLIGHTS][NRUNS] = {
    /*  pcss-2048 pcss-4096 pvsm     pvsm-x4  pvsm-x8-pt pvsm-x4-256 */
    /* offset */
    {{0.0195, 0.0175, 0.0240, 0.0100, 0, 0.0095},   /* L 0.1: 0.0127 0.0115 0.0159 0.0064 - 0.0061 */
     {0.0245, 0.0250, 0.0205, 0.0045, 0, 0.0060},   /* L 0.2: 0.0163 0.0166 0.0136 0.0027 - 0.0037 */
     {0.0300, 0.0310, 0.0225, 0.0065, 0, 0.0075}},  /* L 0.4: 0.0197 0.0206 0.0148 0.0043 - 0.0047 */
    /* overhead */
    {{0.0070, 0.0075, 0.0365, 0.0260, 0.0060, 0},   /* L 0.1: 0.0046 0.0049 0.0243 0.0171 0.0039 */
     {0.0110, 0.0115, 0.0400, 0.0145, 0.0040, 0},   /* L 0.2: 0.0071 0.0075 0.0264 0.0096 0.0025 */
     {0.0180, 0.0185, 0.0220, 0.0060, 0.0025, 0}},  /* L 0.4: 0.0118 0.0123 0.0145 0.0037 0.0015 */
    /* close */
    {{0.0300, 0.0305, 0.0320, 0.0110, 0, 0},        /* L 0.1: 0.0197 0.0203 0.0213 0.0071 */
     {0.0350, 0.0360, 0.0130, 0.0075, 0, 0},        /* L 0.2: 0.0233 0.0238 0.0085 0.0049 */
     {0.0390, 0.0395, 0.0110, 0.0105, 0, 0}},       /* L 0.4: 0.0257 0.0261 0.0071 0.0067 */
    /* tilted */
    {{0.0235, 0.0240, 0.0340, 0.0060, 0, 0},        /* L 0.1: 0.0155 0.0159 0.0225 0.0037 */
     {0.0285, 0.0305, 0.0270, 0.0060, 0, 0},        /* L 0.2: 0.0188 0.0201 0.0178 0.0040 */
     {0.0340, 0.0350, 0.0110, 0.0080, 0, 0}},       /* L 0.4: 0.0224 0.0233 0.0072 0.0052 */
    /* low */
    {{0.0285, 0.0090, 0.0725, 0, 0.0150, 0},        /* L 0.1: 0.0187 0.0059 0.0480 - 0.0098 */
     {0.0275, 0.0135, 0.0780, 0, 0.0095, 0},        /* L 0.2: 0.0182 0.0088 0.0518 - 0.0061 */
     {0.0225, 0.0085, 0.0440, 0, 0.0070, 0}},       /* L 0.4: 0.0149 0.0055 0.0291 - 0.0044 */
};

/* where PVSM with every default is at or below PCSS-4096 (bit k: light k) */
static const unsigned cf_pvsm_wins[NSCENES] = {6, 0, 6, 6, 0};
/* where PVSM at resolution_scale 4 is (the texel budget explains the rest) */
static const unsigned cf_x4_wins[NSCENES] = {7, 4, 7, 7, 0};
/* where PVSM at resolution_scale 8 without anti-aliasing is (the pixel
   average against the point-sampled truth explains the rest) */
static const unsigned cf_x8pt_wins[NSCENES] = {0, 7, 0, 0, 6};

static void test_closed_form(void) {
    int sc, k, r, q;
    cf_measure_all();
    for (sc = 0; sc < NSCENES; sc++)
        for (k = 0; k < NLIGHTS; k++) {
            const cf_scene *c = &cf_scenes[sc];
            const cf_err *p4 = &cf_results[sc][k][R_PCSS4096], *pv = &cf_results[sc][k][R_PVSM];
            double L = cf_halves[k];
            for (r = 0; r < NRUNS; r++) {
                const cf_err *s = &cf_results[sc][k][r];
                if (!(c->runs >> r & 1u)) continue;
                SK_CHECK_MSG(s->pen_mae >= 0.0 && s->pen_mae <= cf_bound[sc][k][r],
                             "%s L %.1f %s: penumbra %.4f over %.4f", c->name, L, cf_runs[r].name, s->pen_mae,
                             cf_bound[sc][k][r]);
                /* no acne, no light leaking: lit and umbra exact away from the
                   penumbra (the low plate's 1-pixel penumbrae: means only) */
                if (sc != 4)
                    SK_CHECK_MSG(s->lit_max <= 1e-3 && s->umb_max <= 1e-3, "%s L %.1f %s: lit max %.4f umbra max %.4f",
                                 c->name, L, cf_runs[r].name, s->lit_max, s->umb_max);
                else
                    SK_CHECK_MSG(s->lit_mae <= 1e-3 && s->umb_mae <= 6e-3, "%s L %.1f %s: lit %.5f umbra %.5f",
                                 c->name, L, cf_runs[r].name, s->lit_mae, s->umb_mae);
            }
            /* kernels across tiles merge as V = sum(V_i A_i) / sum(A_i)
               (Sec. 5.2): tiles of at most 256^2 (4 to 6 of them) measure
               as one tile does */
            if (c->runs >> R_PVSM_X4_256 & 1u)
                SK_CHECK_MSG(cf_results[sc][k][R_PVSM_X4_256].tiles >= 4, "%s L %.1f: %d tiles of 256^2", c->name, L,
                             cf_results[sc][k][R_PVSM_X4_256].tiles);
            if (cf_pvsm_wins[sc] >> k & 1u)
                SK_CHECK_MSG(pv->pen_mae <= p4->pen_mae, "%s L %.1f: PVSM %.4f over PCSS-4096 %.4f", c->name, L,
                             pv->pen_mae, p4->pen_mae);
            if (cf_x4_wins[sc] >> k & 1u)
                SK_CHECK_MSG(cf_results[sc][k][R_PVSM_X4].pen_mae <= p4->pen_mae, "%s L %.1f: PVSM x4 %.4f over %.4f",
                             c->name, L, cf_results[sc][k][R_PVSM_X4].pen_mae, p4->pen_mae);
            if (cf_x8pt_wins[sc] >> k & 1u)
                SK_CHECK_MSG(cf_results[sc][k][R_PVSM_X8_PT].pen_mae <= p4->pen_mae,
                             "%s L %.1f: PVSM x8 point-sampled %.4f over %.4f", c->name, L,
                             cf_results[sc][k][R_PVSM_X8_PT].pen_mae, p4->pen_mae);
            if (c->tilt != 0.0) continue;
            for (q = 0; q < 4; q++) {
                /* PCSS-4096 puts every edge within 0.3 cm (a bias that moved
                   shadows would show here, its texels being 0.07-0.27 cm) */
                if (p4->shift_n[q] >= 100)
                    SK_CHECK_MSG(fabs(p4->shift[q]) <= 0.003, "%s L %.1f PCSS-4096 edge %d: shift %.2f cm", c->name, L,
                                 q, 100 * p4->shift[q]);
                /* PVSM's edges are where its tile's texel grid puts the
                   plate's edges (penumbrae of 2 pixels and more) */
                if (sc != 4 && pv->shift_n[q] >= 100)
                    SK_CHECK_MSG(fabs(pv->shift[q] - pv->snap[q]) <= 0.001 + 0.1 * pv->texel[q],
                                 "%s L %.1f PVSM edge %d: shift %.2f cm, texel rounding %.2f cm (texel %.2f cm)",
                                 c->name, L, q, 100 * pv->shift[q], 100 * pv->snap[q], 100 * pv->texel[q]);
            }
        }
}

/* The default bias on the steepest receiver (tilted, L = 0.4): ten times
   every bias term moves nothing (the penumbra error stays within 0.0005,
   every edge within 0.05 cm: the plate is 1 m above the receiver, the
   tolerance 0.2% of 5 m); no bias at all is acne on the lit receiver.
   The bias neither displaces the penumbra nor is idle. */
static void test_bias(void) {
    static const cf_run base[2] = {{"pcss-4096", SKGL_SOFT_PCSS, 4096, 0.0f, 0, 0.0f, 0.0f, 0.0f},
                                   {"pvsm", SKGL_SOFT_PVSM, 0, 0.0f, 0, 0.0f, 0.0f, 0.0f}};
    const cf_scene *c = &cf_scenes[3];
    skgl_area_light l = cf_light(c, 0.4f);
    cf_ctx x;
    int t, q;
    if (cf_open(&x, c)) return;
    cf_fill_truth(&x.e, c, 0.4f, &x.tb);
    for (t = 0; t < 2; t++) {
        cf_run big = base[t], none = base[t];
        cf_err d, b, n;
        big.rel_bias = 0.02f; big.slope_bias = 15.0f; big.depth_bias = 10.0f;
        none.rel_bias = 1e-7f; none.slope_bias = -1.0f; none.depth_bias = -1.0f;
        d = cf_frame(&x.e, c, &base[t], &l, &x.tb, x.mask, NULL);
        b = cf_frame(&x.e, c, &big, &l, &x.tb, x.mask, NULL);
        n = cf_frame(&x.e, c, &none, &l, &x.tb, x.mask, NULL);
        printf("bias %s: default pen %.4f lit %.4f | x10 pen %.4f lit %.4f | none pen %.4f lit %.4f (max %.3f)\n",
               base[t].name, d.pen_mae, d.lit_mae, b.pen_mae, b.lit_mae, n.pen_mae, n.lit_mae, n.lit_max);
        SK_CHECK_MSG(fabs(b.pen_mae - d.pen_mae) <= 5e-4, "%s: bias x10 moves the penumbra error %.4f -> %.4f",
                     base[t].name, d.pen_mae, b.pen_mae);
        for (q = 0; q < 4; q++)
            if (d.shift_n[q] >= 100)
                SK_CHECK_MSG(fabs(b.shift[q] - d.shift[q]) <= 5e-4, "%s edge %d: bias x10 moves it %.2f -> %.2f cm",
                             base[t].name, q, 100 * d.shift[q], 100 * b.shift[q]);
        SK_CHECK_MSG(d.lit_max <= 1e-3 && b.lit_max <= 1e-3, "%s: lit max %.4f (default), %.4f (x10)", base[t].name,
                     d.lit_max, b.lit_max);
        SK_CHECK_MSG(n.lit_mae > 5e-3, "%s: no bias and still no acne (lit %.5f)", base[t].name, n.lit_mae);
    }
    cf_close(&x);
}

SK_TEST_MAIN(test_closed_form, test_bias)
