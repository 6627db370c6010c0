/* tb_reference.c - see tb_reference.h */
#if !defined(_POSIX_C_SOURCE) || _POSIX_C_SOURCE < 200809L
#undef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L
#endif
#include "tb_reference.h"

#include <embree3/rtcore.h>
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#define TB_HAVE_MXCSR 1
#endif

#define TB_MAX_THREADS 64
#define TB_POINT_CHUNK 64   /* points per work item in tb_reference_trace_points */

struct tb_reference {
    RTCDevice device;
    RTCScene scene;
    double diagonal;
    float *pos;              /* copy of the vertex positions (exact method) */
    float *nrm;              /* copy of the vertex normals (the same-face test), NULL without */
    unsigned *idx;           /* copy of the triangle indices */
    unsigned tri_count;
    unsigned vertex_count;
    /* tb_reference_set_alpha: uv per vertex, the alpha-tested triangles, the texture */
    float *uv;
    unsigned alpha_first, alpha_count;
    unsigned char *alpha;
    int alpha_w, alpha_h;
    float cutoff;
    int alpha_primary;       /* tb_reference_alpha_primary */
};

static void tb_embree_error_(void *user, enum RTCError code, const char *msg) {
    (void)user;
    fprintf(stderr, "embree error %d: %s\n", (int)code, msg ? msg : "");
}

tb_reference *tb_reference_create(const tb_scene *s) {
    tb_reference *r;
    RTCGeometry g;
    float *vb;
    unsigned *ib;
    uint32_t k;
    if (!s || s->index_count < 3 || !s->positions || !s->indices) return NULL;
    for (k = 0; k < s->index_count; k++)
        if (s->indices[k] >= s->vertex_count) return NULL;
    r = (tb_reference *)calloc(1, sizeof *r);
    if (!r) return NULL;
    r->device = rtcNewDevice(NULL);
    if (!r->device) {
        fprintf(stderr, "embree: rtcNewDevice failed (%d)\n", (int)rtcGetDeviceError(NULL));
        free(r);
        return NULL;
    }
    rtcSetDeviceErrorFunction(r->device, tb_embree_error_, NULL);
    r->scene = rtcNewScene(r->device);
    /* the context filter is used only by the exact method's shadow rays; a
       context without one (the legacy calls) is not filtered */
    rtcSetSceneFlags(r->scene, RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
    rtcSetSceneBuildQuality(r->scene, RTC_BUILD_QUALITY_HIGH);
    g = rtcNewGeometry(r->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    vb = (float *)rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                          3 * sizeof(float), s->vertex_count);
    ib = (unsigned *)rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                             3 * sizeof(unsigned), s->index_count / 3);
    if (!vb || !ib) {
        rtcReleaseGeometry(g);
        tb_reference_destroy(r);
        return NULL;
    }
    memcpy(vb, s->positions, (size_t)s->vertex_count * 3 * sizeof(float));
    memcpy(ib, s->indices, (size_t)(s->index_count / 3) * 3 * sizeof(unsigned));
    r->tri_count = s->index_count / 3;
    r->vertex_count = s->vertex_count;
    r->pos = (float *)malloc((size_t)s->vertex_count * 3 * sizeof(float));
    r->idx = (unsigned *)malloc((size_t)r->tri_count * 3 * sizeof(unsigned));
    if (!r->pos || !r->idx) {
        rtcReleaseGeometry(g);
        tb_reference_destroy(r);
        return NULL;
    }
    memcpy(r->pos, s->positions, (size_t)s->vertex_count * 3 * sizeof(float));
    memcpy(r->idx, s->indices, (size_t)r->tri_count * 3 * sizeof(unsigned));
    if (s->normals) {
        r->nrm = (float *)malloc((size_t)s->vertex_count * 3 * sizeof(float));
        if (!r->nrm) {
            rtcReleaseGeometry(g);
            tb_reference_destroy(r);
            return NULL;
        }
        memcpy(r->nrm, s->normals, (size_t)s->vertex_count * 3 * sizeof(float));
    }
    rtcCommitGeometry(g);
    rtcAttachGeometry(r->scene, g);
    rtcReleaseGeometry(g);
    rtcCommitScene(r->scene);
    if (rtcGetDeviceError(r->device) != RTC_ERROR_NONE) {
        tb_reference_destroy(r);
        return NULL;
    }
    r->diagonal = tb_scene_diagonal(s);
    return r;
}

void tb_reference_destroy(tb_reference *r) {
    if (!r) return;
    if (r->scene) rtcReleaseScene(r->scene);
    if (r->device) rtcReleaseDevice(r->device);
    free(r->pos);
    free(r->nrm);
    free(r->idx);
    free(r->uv);
    free(r->alpha);
    free(r);
}

static double tb_eps_rel_(const tb_ref_options *opt) {
    return (opt && opt->eps_rel > 0) ? opt->eps_rel : TB_REF_EPS_REL;
}

double tb_reference_epsilon(const tb_reference *r, const tb_ref_options *opt) {
    return r ? tb_eps_rel_(opt) * r->diagonal : 0.0;
}

/* ---- math ---- */

static void tb_mul_m4_v4_(const sk_mat4 *m, const double v[4], double out[4]) {
    int row, col;
    for (row = 0; row < 4; row++) {
        double acc = 0;
        for (col = 0; col < 4; col++) acc += (double)m->m[col * 4 + row] * v[col];
        out[row] = acc;
    }
}

int tb_mat4_inverse_d(const double m[16], double inv[16]) {
    double a[4][8];
    int i, j, k;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 8; j++) a[i][j] = j < 4 ? m[j * 4 + i] : (double)(j - 4 == i);
    for (i = 0; i < 4; i++) {
        int p = i;
        double piv;
        for (k = i + 1; k < 4; k++)
            if (fabs(a[k][i]) > fabs(a[p][i])) p = k;
        if (fabs(a[p][i]) < 1e-300) return 0;
        for (j = 0; j < 8; j++) {
            double t = a[i][j];
            a[i][j] = a[p][j];
            a[p][j] = t;
        }
        piv = a[i][i];
        for (j = 0; j < 8; j++) a[i][j] /= piv;
        for (k = 0; k < 4; k++)
            if (k != i) {
                double f = a[k][i];
                for (j = 0; j < 8; j++) a[k][j] -= f * a[i][j];
            }
    }
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) inv[j * 4 + i] = a[i][j + 4];
    return 1;
}

int tb_unproject_pixel(const sk_mat4 *ivp, int width, int height, int x, int y, float depth,
                       double out[3]) {
    double ndc[4], w[4];
    ndc[0] = 2.0 * (x + 0.5) / width - 1.0;
    ndc[1] = 2.0 * (y + 0.5) / height - 1.0;
    ndc[2] = 2.0 * (double)depth - 1.0;
    ndc[3] = 1.0;
    tb_mul_m4_v4_(ivp, ndc, w);
    if (w[3] == 0 || !isfinite(w[3])) return -1;
    out[0] = w[0] / w[3];
    out[1] = w[1] / w[3];
    out[2] = w[2] / w[3];
    return (isfinite(out[0]) && isfinite(out[1]) && isfinite(out[2])) ? 0 : -1;
}

static double tb_dot_(const double a[3], const double b[3]) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static int tb_normalize_(double v[3]) {
    double l = sqrt(tb_dot_(v, v));
    if (!(l > 0) || !isfinite(l)) return 0;
    v[0] /= l; v[1] /= l; v[2] /= l;
    return 1;
}

/* PCG32 (O'Neill), seeded per pixel: deterministic regardless of threads */
typedef struct tb_pcg_ { uint64_t state, inc; } tb_pcg_;
static uint32_t tb_pcg_next_(tb_pcg_ *g) {
    uint64_t old = g->state;
    uint32_t xs, rot;
    g->state = old * 6364136223846793005ull + g->inc;
    xs = (uint32_t)(((old >> 18u) ^ old) >> 27u);
    rot = (uint32_t)(old >> 59u);
    return (xs >> rot) | (xs << ((32u - rot) & 31u));
}
static void tb_pcg_seed_(tb_pcg_ *g, uint64_t seed, uint64_t stream) {
    g->state = 0;
    g->inc = (stream << 1u) | 1u;
    tb_pcg_next_(g);
    g->state += seed;
    tb_pcg_next_(g);
}
static double tb_pcg_unit_(tb_pcg_ *g) { return tb_pcg_next_(g) * (1.0 / 4294967296.0); }

/* the jittered sample of stratum `cell` (of s x s) on a rect light centred
   at c: one uniform point inside the cell, two PCG draws */
static void tb_rect_sample_(const tb_light *L, const double c[3], tb_pcg_ *rng, int cell, int s, double q[3]) {
    int cx = cell % s, cy = cell / s;
    double a = 2.0 * (cx + tb_pcg_unit_(rng)) / s - 1.0;
    double b = 2.0 * (cy + tb_pcg_unit_(rng)) / s - 1.0;
    q[0] = c[0] + a * L->half_u.x + b * L->half_v.x;
    q[1] = c[1] + a * L->half_u.y + b * L->half_v.y;
    q[2] = c[2] + a * L->half_u.z + b * L->half_v.z;
}

/* lane i of a 16-ray packet: origin p, unit direction d, [tnear, tfar] */
static void tb_ray16_lane_(struct RTCRay16 *ray, int i, const double p[3], const double d[3], double tnear,
                           double tfar) {
    ray->org_x[i] = (float)p[0]; ray->org_y[i] = (float)p[1]; ray->org_z[i] = (float)p[2];
    ray->dir_x[i] = (float)d[0]; ray->dir_y[i] = (float)d[1]; ray->dir_z[i] = (float)d[2];
    ray->tnear[i] = (float)tnear;
    ray->tfar[i] = (float)tfar;
    ray->time[i] = 0;
    ray->mask[i] = 0xFFFFFFFFu;
    ray->id[i] = (unsigned)i;
    ray->flags[i] = 0;
}

/* ---- shading one point ---- */

typedef struct tb_job_ {
    const tb_reference *ref;
    const tb_light *light;
    double eps;
    int facing;
    /* pixel mode */
    const tb_view *view;
    const float *depth;
    const float *fnormals;
    /* point mode */
    const double *points;
    const double *dnormals;
    int count;
    /* normals mode (tb_reference_normals) */
    float *out_normals;
    /* exact mode (tb_reference_trace_exact) */
    int exact;
    const float *raster;     /* raster window depth or NULL */
    const float *raster_n;   /* raster normals (opt->raster_normals) or NULL */
    double vp[16];           /* double inverse of view->inv_view_proj (column-major) */
    int rows;            /* work items */
    int nthreads;
    float *vis;
} tb_job_;

static int tb_occluded1_(RTCScene scene, const double o[3], const double d[3], double tnear,
                         double tfar) {
    struct RTCIntersectContext ctx;
    struct RTCRay ray;
    rtcInitIntersectContext(&ctx);
    ray.org_x = (float)o[0]; ray.org_y = (float)o[1]; ray.org_z = (float)o[2];
    ray.dir_x = (float)d[0]; ray.dir_y = (float)d[1]; ray.dir_z = (float)d[2];
    ray.tnear = (float)tnear;
    ray.tfar = (float)tfar;
    ray.time = 0;
    ray.mask = 0xFFFFFFFFu;
    ray.id = 0;
    ray.flags = 0;
    rtcOccluded1(scene, &ctx, &ray);
    return ray.tfar < 0;   /* -inf when occluded */
}

/* visibility of world point p (normal n or NULL), sample stream `index` */
static float tb_shade_(const tb_job_ *j, const double p_in[3], const double *n_in, uint64_t index) {
    const tb_light *L = j->light;
    RTCScene scene = j->ref->scene;
    double p[3], n[3], eps = j->eps;
    int has_n = 0;
    p[0] = p_in[0]; p[1] = p_in[1]; p[2] = p_in[2];
    if (n_in) {
        n[0] = n_in[0]; n[1] = n_in[1]; n[2] = n_in[2];
        has_n = tb_normalize_(n);
        if (has_n) { p[0] += n[0] * eps; p[1] += n[1] * eps; p[2] += n[2] * eps; }
    }
    if (L->type == TB_LIGHT_DIRECTIONAL) {
        double d[3];
        d[0] = -(double)L->direction.x; d[1] = -(double)L->direction.y; d[2] = -(double)L->direction.z;
        if (!tb_normalize_(d)) return 0.0f;
        if (has_n && j->facing && tb_dot_(n, d) <= 0) return 0.0f;
        return tb_occluded1_(scene, p, d, eps, INFINITY) ? 0.0f : 1.0f;
    }
    if (L->type == TB_LIGHT_POINT) {
        double d[3], dist;
        d[0] = L->position.x - p_in[0]; d[1] = L->position.y - p_in[1]; d[2] = L->position.z - p_in[2];
        dist = sqrt(tb_dot_(d, d));
        if (L->range > 0 && dist > L->range) return TB_VIS_OUT_OF_RANGE;
        d[0] = L->position.x - p[0]; d[1] = L->position.y - p[1]; d[2] = L->position.z - p[2];
        dist = sqrt(tb_dot_(d, d));
        if (!tb_normalize_(d)) return 1.0f;   /* at the light */
        if (has_n && j->facing && tb_dot_(n, d) <= 0) return 0.0f;
        if (dist <= 2 * eps) return 1.0f;
        return tb_occluded1_(scene, p, d, eps, dist - eps) ? 0.0f : 1.0f;
    }
    {
        /* rect light: strata x strata jittered samples, 16-ray packets */
        int s = L->strata < TB_REF_MIN_STRATA ? TB_REF_MIN_STRATA : L->strata;
        int total = s * s, k = 0, unocc = 0, i;
        tb_pcg_ rng;
        struct RTCIntersectContext ctx;
        RTC_ALIGN(64) int valid[16];
        RTC_ALIGN(64) struct RTCRay16 ray;
        tb_pcg_seed_(&rng, ((uint64_t)L->seed << 32) ^ 0x9E3779B97F4A7C15ull, index);
        rtcInitIntersectContext(&ctx);
        memset(&ray, 0, sizeof ray);
        while (k < total) {
            int m = total - k < 16 ? total - k : 16, any = 0;
            for (i = 0; i < 16; i++) {
                valid[i] = 0;
                ray.tfar[i] = 0;
                if (i < m) {
                    double q[3], d[3], dist, centre[3];
                    centre[0] = L->position.x; centre[1] = L->position.y; centre[2] = L->position.z;
                    tb_rect_sample_(L, centre, &rng, k + i, s, q);
                    d[0] = q[0] - p[0]; d[1] = q[1] - p[1]; d[2] = q[2] - p[2];
                    dist = sqrt(tb_dot_(d, d));
                    if (!tb_normalize_(d)) { unocc++; continue; }
                    if (has_n && j->facing && tb_dot_(n, d) <= 0) continue;   /* occluded */
                    if (dist <= 2 * eps) { unocc++; continue; }
                    tb_ray16_lane_(&ray, i, p, d, eps, dist - eps);
                    valid[i] = -1;
                    any = 1;
                }
            }
            if (any) {
                rtcOccluded16(valid, scene, &ctx, &ray);
                for (i = 0; i < m; i++)
                    if (valid[i] && ray.tfar[i] >= 0) unocc++;
            }
            k += m;
        }
        return (float)((double)unocc / total);
    }
}

/* primary ray through pixel (x, y); 1 and the camera-facing unit normal
   when the hit lies within tol of the reconstructed point p */
static int tb_primary_normal_(const tb_job_ *j, int x, int y, const double p[3], float out[3]) {
    const tb_view *v = j->view;
    double a[3], b[3], d[3], len, tol = 0.01 * j->ref->diagonal, hit[3], e[3], ng[3];
    struct RTCIntersectContext ctx;
    struct RTCRayHit rh;
    if (tb_unproject_pixel(&v->inv_view_proj, v->width, v->height, x, y, 0.0f, a) ||
        tb_unproject_pixel(&v->inv_view_proj, v->width, v->height, x, y, 1.0f, b))
        return 0;
    d[0] = b[0] - a[0]; d[1] = b[1] - a[1]; d[2] = b[2] - a[2];
    len = sqrt(tb_dot_(d, d));
    if (!tb_normalize_(d)) return 0;
    rtcInitIntersectContext(&ctx);
    rh.ray.org_x = (float)a[0]; rh.ray.org_y = (float)a[1]; rh.ray.org_z = (float)a[2];
    rh.ray.dir_x = (float)d[0]; rh.ray.dir_y = (float)d[1]; rh.ray.dir_z = (float)d[2];
    rh.ray.tnear = 0;
    rh.ray.tfar = (float)(len * 1.001);
    rh.ray.time = 0;
    rh.ray.mask = 0xFFFFFFFFu;
    rh.ray.id = 0;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(j->ref->scene, &ctx, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return 0;
    hit[0] = a[0] + d[0] * rh.ray.tfar; hit[1] = a[1] + d[1] * rh.ray.tfar; hit[2] = a[2] + d[2] * rh.ray.tfar;
    e[0] = hit[0] - p[0]; e[1] = hit[1] - p[1]; e[2] = hit[2] - p[2];
    if (tb_dot_(e, e) > tol * tol) return 0;
    ng[0] = rh.hit.Ng_x; ng[1] = rh.hit.Ng_y; ng[2] = rh.hit.Ng_z;
    if (!tb_normalize_(ng)) return 0;
    if (tb_dot_(ng, d) > 0) { ng[0] = -ng[0]; ng[1] = -ng[1]; ng[2] = -ng[2]; }
    out[0] = (float)ng[0]; out[1] = (float)ng[1]; out[2] = (float)ng[2];
    return 1;
}


/* ---- the exact method (tb_reference_trace_exact) ---- */

/* one float ulp at magnitude m: 2^(e-24) for m in [2^(e-1), 2^e) */
static double tb_ulpf_(double m) {
    int ex;
    if (!(m > 0) || !isfinite(m)) return ldexp(1.0, -149);
    frexp(m, &ex);
    return ldexp(1.0, ex - 24);
}

static double tb_maxabs3_(const double p[3]) {
    double m = fabs(p[0]);
    if (fabs(p[1]) > m) m = fabs(p[1]);
    if (fabs(p[2]) > m) m = fabs(p[2]);
    return m;
}

/* the float error bound e of point 4 in the header, at point p */
static double tb_ulp_bound_(const double p[3]) { return TB_REF_ULP_BOUND * tb_ulpf_(tb_maxabs3_(p)); }

static void tb_tri_vertex_(const tb_reference *r, unsigned prim, int k, double v[3]) {
    const float *f = r->pos + 3 * (size_t)r->idx[3 * (size_t)prim + (size_t)k];
    v[0] = f[0]; v[1] = f[1]; v[2] = f[2];
}

/* unit geometric normal of triangle prim (double cross product of its float
   edges, the winding's orientation); 0 when degenerate */
static int tb_tri_normal_(const tb_reference *r, unsigned prim, double n[3]) {
    double v0[3], v1[3], v2[3], e1[3], e2[3];
    tb_tri_vertex_(r, prim, 0, v0);
    tb_tri_vertex_(r, prim, 1, v1);
    tb_tri_vertex_(r, prim, 2, v2);
    e1[0] = v1[0] - v0[0]; e1[1] = v1[1] - v0[1]; e1[2] = v1[2] - v0[2];
    e2[0] = v2[0] - v0[0]; e2[1] = v2[1] - v0[1]; e2[2] = v2[2] - v0[2];
    n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
    return tb_normalize_(n);
}

/* The extended intersection context of a shadow query: Embree passes the
   context pointer to the filter, which reads the receiver from it. */
typedef struct tb_xctx_ {
    struct RTCIntersectContext ctx;   /* first member */
    const tb_reference *ref;
    unsigned self;                    /* the receiver's triangle */
    double n[3], d;                   /* the receiver's plane: dot(n, x) = d, |n| = 1 */
    double tol;                       /* the ulp bound e at the receiver */
} tb_xctx_;

/* 1 when lane i of an Embree RTCHitN (N wide) on triangle prim lies in a
   hole of the alpha texture (tb_reference_set_alpha) */
static int tb_alpha_hole_(const tb_reference *r, unsigned prim, const struct RTCHitN *hitn, unsigned N, unsigned i) {
    /* u, v: the hit's barycentric weights of vertices 1 and 2 */
    const float *hit = (const float *)(const void *)hitn;
    double bu, bv, t[2];
    const float *uv0, *uv1, *uv2;
    long tx, ty;
    int k;
    if (!r->alpha || prim - r->alpha_first >= r->alpha_count) return 0;
    bu = hit[3 * N + i];
    bv = hit[4 * N + i];
    uv0 = r->uv + 2 * r->idx[3 * prim];
    uv1 = r->uv + 2 * r->idx[3 * prim + 1];
    uv2 = r->uv + 2 * r->idx[3 * prim + 2];
    for (k = 0; k < 2; k++) t[k] = (1.0 - bu - bv) * uv0[k] + bu * uv1[k] + bv * uv2[k];
    tx = (long)floor(t[0] * r->alpha_w) % r->alpha_w;
    ty = (long)floor(t[1] * r->alpha_h) % r->alpha_h;
    if (tx < 0) tx += r->alpha_w;
    if (ty < 0) ty += r->alpha_h;
    return r->alpha[ty * r->alpha_w + tx] < r->cutoff * 255.0f;
}

/* Embree 3 context filter (rtcOccluded1 / rtcOccluded16): rejects hits on
   the receiver's triangle and on any triangle lying in the receiver's plane
   (all three vertices within the ulp bound of it, at the larger of the
   receiver's and the vertex's magnitude). */
static void tb_receiver_filter_(const struct RTCFilterFunctionNArguments *args) {
    const tb_xctx_ *x = (const tb_xctx_ *)(const void *)args->context;
    unsigned i;
    for (i = 0; i < args->N; i++) {
        unsigned prim;
        int k, in_plane = 1;
        if (args->valid[i] != -1) continue;
        /* RTCHitN is SOA: Ng_x, Ng_y, Ng_z, u, v, primID, ... each N wide
           (rtcore_ray.h; its RTCHitN_primID accessor is C++ only) */
        prim = ((const unsigned *)(const void *)args->hit)[5 * args->N + i];
        if (prim == x->self) { args->valid[i] = 0; continue; }
        if (prim >= x->ref->tri_count) continue;
        for (k = 0; k < 3 && in_plane; k++) {
            double v[3], tol;
            tb_tri_vertex_(x->ref, prim, k, v);
            /* a vertex meant to lie in the plane is off it by its own
               rounding: the bound at the larger of |p| and |v| */
            tol = TB_REF_ULP_BOUND * tb_ulpf_(tb_maxabs3_(v));
            if (tol < x->tol) tol = x->tol;
            if (fabs(tb_dot_(x->n, v) - x->d) > tol) in_plane = 0;
        }
        if (in_plane) { args->valid[i] = 0; continue; }
        if (tb_alpha_hole_(x->ref, prim, args->hit, args->N, i)) args->valid[i] = 0;
    }
}

/* Embree 3 context filter of the exact method's primary rays
   (tb_reference_alpha_primary): rejects hits in an alpha hole */
static void tb_primary_alpha_filter_(const struct RTCFilterFunctionNArguments *args) {
    const tb_xctx_ *x = (const tb_xctx_ *)(const void *)args->context;
    unsigned i;
    for (i = 0; i < args->N; i++) {
        if (args->valid[i] != -1) continue;
        if (tb_alpha_hole_(x->ref, ((const unsigned *)(const void *)args->hit)[5 * args->N + i], args->hit, args->N, i))
            args->valid[i] = 0;
    }
}

int tb_reference_alpha_primary(tb_reference *r, int on) {
    if (!r || !r->alpha) return -1;
    r->alpha_primary = on != 0;
    return 0;
}

int tb_reference_set_alpha(tb_reference *r, const float *uv, unsigned first_tri, unsigned tri_count,
                           const unsigned char *alpha, int w, int h, float cutoff) {
    if (!r || !uv || !alpha || w <= 0 || h <= 0 || first_tri > r->tri_count || tri_count > r->tri_count - first_tri)
        return -1;
    free(r->uv);
    free(r->alpha);
    r->uv = (float *)malloc(sizeof(float) * 2 * r->vertex_count);
    r->alpha = (unsigned char *)malloc((size_t)w * (size_t)h);
    if (!r->uv || !r->alpha) {
        free(r->uv); free(r->alpha);
        r->uv = NULL; r->alpha = NULL;
        return -1;
    }
    memcpy(r->uv, uv, sizeof(float) * 2 * r->vertex_count);
    memcpy(r->alpha, alpha, (size_t)w * (size_t)h);
    r->alpha_first = first_tri;
    r->alpha_count = tri_count;
    r->alpha_w = w;
    r->alpha_h = h;
    r->cutoff = cutoff;
    return 0;
}

static void tb_ray_fill_(struct RTCRay *ray, const double o[3], const double d[3], double tnear, double tfar) {
    ray->org_x = (float)o[0]; ray->org_y = (float)o[1]; ray->org_z = (float)o[2];
    ray->dir_x = (float)d[0]; ray->dir_y = (float)d[1]; ray->dir_z = (float)d[2];
    ray->tnear = (float)tnear;
    ray->tfar = isfinite(tfar) ? (float)tfar : INFINITY;
    ray->time = 0;
    ray->mask = 0xFFFFFFFFu;
    ray->id = 0;
    ray->flags = 0;
}

/* visibility of the exact hit p (camera-facing unit normal n, triangle
   prim), or TB_VIS_BACKFACING / TB_VIS_OUT_OF_RANGE; sample stream `index` */
static float tb_shade_exact_(const tb_job_ *j, const double p[3], const double n[3], unsigned prim,
                             uint64_t index) {
    const tb_light *L = j->light;
    RTCScene scene = j->ref->scene;
    double e = tb_ulp_bound_(p);
    tb_xctx_ xc;
    rtcInitIntersectContext(&xc.ctx);
    xc.ctx.filter = tb_receiver_filter_;
    xc.ref = j->ref;
    xc.self = prim;
    xc.n[0] = n[0]; xc.n[1] = n[1]; xc.n[2] = n[2];
    xc.d = tb_dot_(n, p);
    xc.tol = e;
    if (L->type == TB_LIGHT_DIRECTIONAL) {
        double d[3], c;
        struct RTCRay ray;
        d[0] = -(double)L->direction.x; d[1] = -(double)L->direction.y; d[2] = -(double)L->direction.z;
        if (!tb_normalize_(d)) return 0.0f;
        c = tb_dot_(n, d);
        if (c <= 0) return TB_VIS_BACKFACING;
        tb_ray_fill_(&ray, p, d, e / c, INFINITY);
        rtcOccluded1(scene, &xc.ctx, &ray);
        return ray.tfar < 0 ? 0.0f : 1.0f;
    }
    if (L->type == TB_LIGHT_POINT) {
        double q[3], d[3], dist, c, tnear, tfar;
        struct RTCRay ray;
        q[0] = L->position.x; q[1] = L->position.y; q[2] = L->position.z;
        d[0] = q[0] - p[0]; d[1] = q[1] - p[1]; d[2] = q[2] - p[2];
        dist = sqrt(tb_dot_(d, d));
        if (L->range > 0 && dist > L->range) return TB_VIS_OUT_OF_RANGE;
        if (!tb_normalize_(d)) return 1.0f;   /* at the light */
        c = tb_dot_(n, d);
        if (c <= 0) return TB_VIS_BACKFACING;
        tnear = e / c;
        tfar = dist - tb_ulp_bound_(q);
        if (tfar <= tnear) return 1.0f;   /* nothing between, at float resolution */
        tb_ray_fill_(&ray, p, d, tnear, tfar);
        rtcOccluded1(scene, &xc.ctx, &ray);
        return ray.tfar < 0 ? 0.0f : 1.0f;
    }
    {
        /* rect light: strata x strata jittered samples, 16-ray packets */
        int s = L->strata <= 0 ? TB_REF_EXACT_STRATA : (L->strata < TB_REF_MIN_STRATA ? TB_REF_MIN_STRATA : L->strata);
        int total = s * s, k = 0, unocc = 0, i, front = 0;
        double nl[3], c0[3];
        tb_pcg_ rng;
        RTC_ALIGN(64) int valid[16];
        RTC_ALIGN(64) struct RTCRay16 ray;
        c0[0] = L->position.x; c0[1] = L->position.y; c0[2] = L->position.z;
        /* back-facing when all four corners lie behind the receiver's plane */
        for (i = 0; i < 4; i++) {
            double a = (i & 1) ? 1.0 : -1.0, b = (i & 2) ? 1.0 : -1.0, q[3];
            q[0] = c0[0] + a * L->half_u.x + b * L->half_v.x - p[0];
            q[1] = c0[1] + a * L->half_u.y + b * L->half_v.y - p[1];
            q[2] = c0[2] + a * L->half_u.z + b * L->half_v.z - p[2];
            if (tb_dot_(n, q) > 0) front = 1;
        }
        if (!front) return TB_VIS_BACKFACING;
        /* the light's plane, for the bound at its end */
        nl[0] = (double)L->half_u.y * L->half_v.z - (double)L->half_u.z * L->half_v.y;
        nl[1] = (double)L->half_u.z * L->half_v.x - (double)L->half_u.x * L->half_v.z;
        nl[2] = (double)L->half_u.x * L->half_v.y - (double)L->half_u.y * L->half_v.x;
        if (!tb_normalize_(nl)) nl[0] = nl[1] = nl[2] = 0;
        tb_pcg_seed_(&rng, ((uint64_t)L->seed << 32) ^ 0x9E3779B97F4A7C15ull, index);
        memset(&ray, 0, sizeof ray);
        while (k < total) {
            int m = total - k < 16 ? total - k : 16, any = 0;
            for (i = 0; i < 16; i++) {
                valid[i] = 0;
                ray.tfar[i] = 0;
                if (i < m) {
                    double q[3], d[3], dist, c, cl, tnear, tfar;
                    tb_rect_sample_(L, c0, &rng, k + i, s, q);
                    d[0] = q[0] - p[0]; d[1] = q[1] - p[1]; d[2] = q[2] - p[2];
                    dist = sqrt(tb_dot_(d, d));
                    if (!tb_normalize_(d)) { unocc++; continue; }
                    c = tb_dot_(n, d);
                    if (c <= 0) continue;   /* behind the receiver: occluded */
                    cl = fabs(tb_dot_(nl, d));
                    tnear = e / c;
                    tfar = dist - tb_ulp_bound_(q) / (cl > 0 ? cl : 1.0);
                    if (tfar <= tnear) { unocc++; continue; }
                    tb_ray16_lane_(&ray, i, p, d, tnear, tfar);
                    valid[i] = -1;
                    any = 1;
                }
            }
            if (any) {
                rtcOccluded16(valid, scene, &xc.ctx, &ray);
                for (i = 0; i < m; i++)
                    if (valid[i] && ray.tfar[i] >= 0) unocc++;
            }
            k += m;
        }
        return (float)((double)unocc / total);
    }
}

/* window depth of world point p under the double matrix vp; NaN if w <= 0 */
static double tb_window_depth_(const double vp[16], const double p[3]) {
    double z = vp[2] * p[0] + vp[6] * p[1] + vp[10] * p[2] + vp[14];
    double w = vp[3] * p[0] + vp[7] * p[1] + vp[11] * p[2] + vp[15];
    if (!(w > 0)) return NAN;
    return 0.5 * (z / w) + 0.5;
}

/* the rasterised normal g (any sign, any length; 0 or not finite: no test)
   and the traced unit normal t agree on the face: |cos| >=
   TB_REF_SAME_FACE_COS */
static int tb_normals_agree_(const float *g, const double t[3]) {
    double gn[3];
    gn[0] = g[0]; gn[1] = g[1]; gn[2] = g[2];
    if (!tb_normalize_(gn)) return 1;
    return fabs(tb_dot_(gn, t)) >= TB_REF_SAME_FACE_COS;
}

/* The same-face test (header, point 2): the G-buffer's normal g is the
   traced triangle prim's geometric normal n (a G-buffer of face normals,
   as the instanced scenes draw) or its vertex normals interpolated at
   Embree's barycentrics (u, v weigh vertices 1 and 2; a G-buffer of
   shading normals, smooth meshes included), within TB_REF_SAME_FACE_COS
   of either. */
static int tb_same_face_(const tb_reference *r, unsigned prim, float u, float v, const double n[3],
                         const float *g) {
    double w[3], m[3] = {0.0, 0.0, 0.0};
    int k;
    if (tb_normals_agree_(g, n)) return 1;
    if (!r->nrm) return 0;
    w[0] = 1.0 - (double)u - (double)v; w[1] = u; w[2] = v;
    for (k = 0; k < 3; k++) {
        const float *f = r->nrm + 3 * (size_t)r->idx[3 * (size_t)prim + (size_t)k];
        m[0] += w[k] * f[0]; m[1] += w[k] * f[1]; m[2] += w[k] * f[2];
    }
    return tb_normalize_(m) && tb_normals_agree_(g, m);
}

/* one pixel of the exact method (header, points 1-5) */
static float tb_exact_pixel_(const tb_job_ *j, int x, int y, size_t i) {
    const tb_view *v = j->view;
    double a[3], b[3], d[3], len, n[3], v0[3], p[3], den, t;
    tb_xctx_ pc;
    struct RTCRayHit rh;
    int raster_hit = 0, traced_hit = 0;
    unsigned prim = 0;
    float dr = 0.0f;
    if (j->raster) {
        dr = j->raster[i];
        raster_hit = dr < 1.0f && dr >= 0.0f;
    }
    if (tb_unproject_pixel(&v->inv_view_proj, v->width, v->height, x, y, 0.0f, a) == 0 &&
        tb_unproject_pixel(&v->inv_view_proj, v->width, v->height, x, y, 1.0f, b) == 0) {
        d[0] = b[0] - a[0]; d[1] = b[1] - a[1]; d[2] = b[2] - a[2];
        len = sqrt(tb_dot_(d, d));
        if (tb_normalize_(d)) {
            rtcInitIntersectContext(&pc.ctx);
            if (j->ref->alpha_primary) {
                pc.ctx.filter = tb_primary_alpha_filter_;
                pc.ref = j->ref;
            }
            tb_ray_fill_(&rh.ray, a, d, 0.0, len);
            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
            rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(j->ref->scene, &pc.ctx, &rh);
            if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID && rh.hit.primID < j->ref->tri_count &&
                tb_tri_normal_(j->ref, rh.hit.primID, n)) {
                /* the double ray against the hit triangle's plane */
                prim = rh.hit.primID;
                tb_tri_vertex_(j->ref, prim, 0, v0);
                den = tb_dot_(n, d);
                t = den != 0 ? (tb_dot_(n, v0) - tb_dot_(n, a)) / den : (double)rh.ray.tfar;
                if (!(t >= 0) || !(t <= len)) t = rh.ray.tfar;
                p[0] = a[0] + t * d[0]; p[1] = a[1] + t * d[1]; p[2] = a[2] + t * d[2];
                if (den > 0) { n[0] = -n[0]; n[1] = -n[1]; n[2] = -n[2]; }
                traced_hit = 1;
            }
        }
    }
    if (!j->raster) {
        if (!traced_hit) return TB_VIS_BACKGROUND;
    } else {
        if (!traced_hit && !raster_hit) return TB_VIS_BACKGROUND;
        if (traced_hit != raster_hit) return TB_VIS_SILHOUETTE;
        {
            double dt = tb_window_depth_(j->vp, p);
            if (!(fabs(dt - (double)dr) <= TB_REF_SAME_SURFACE_ULPS * ldexp(1.0, -24))) return TB_VIS_SILHOUETTE;
        }
        if (j->raster_n && !tb_same_face_(j->ref, prim, rh.hit.u, rh.hit.v, n, j->raster_n + 3 * i))
            return TB_VIS_SILHOUETTE;
    }
    return tb_shade_exact_(j, p, n, prim, (uint64_t)i);
}

typedef struct tb_worker_ { const tb_job_ *job; int tid; } tb_worker_;

static void *tb_worker_main_(void *arg) {
    const tb_worker_ *w = (const tb_worker_ *)arg;
    const tb_job_ *j = w->job;
    int row;
#ifdef TB_HAVE_MXCSR
    /* flush-to-zero and denormals-are-zero, as Embree recommends */
    _mm_setcsr(_mm_getcsr() | 0x8040);
#endif
    for (row = w->tid; row < j->rows; row += j->nthreads) {
        if (j->view) {
            const tb_view *v = j->view;
            int x;
            for (x = 0; x < v->width; x++) {
                size_t i = (size_t)row * (size_t)v->width + (size_t)x;
                double p[3], nd[3];
                const double *np = NULL;
                float dep;
                if (j->exact) {
                    j->vis[i] = tb_exact_pixel_(j, x, row, i);
                    continue;
                }
                dep = j->depth[i];
                if (j->out_normals) {
                    float *o = j->out_normals + 3 * i;
                    o[0] = o[1] = o[2] = 0.0f;
                    if (!(dep < 1.0f) || tb_unproject_pixel(&v->inv_view_proj, v->width, v->height,
                                                             x, row, dep, p))
                        continue;
                    tb_primary_normal_(j, x, row, p, o);
                    continue;
                }
                if (!(dep < 1.0f) || !(dep >= 0.0f) ||
                    tb_unproject_pixel(&v->inv_view_proj, v->width, v->height, x, row, dep, p)) {
                    j->vis[i] = TB_VIS_BACKGROUND;
                    continue;
                }
                if (j->fnormals) {
                    nd[0] = j->fnormals[3 * i];
                    nd[1] = j->fnormals[3 * i + 1];
                    nd[2] = j->fnormals[3 * i + 2];
                    np = nd;
                }
                j->vis[i] = tb_shade_(j, p, np, (uint64_t)i);
            }
        } else {
            int i0 = row * TB_POINT_CHUNK, i;
            for (i = i0; i < i0 + TB_POINT_CHUNK && i < j->count; i++)
                j->vis[i] = tb_shade_(j, j->points + 3 * (size_t)i,
                                      j->dnormals ? j->dnormals + 3 * (size_t)i : NULL, (uint64_t)i);
        }
    }
    return NULL;
}

static int tb_run_(tb_job_ *j, const tb_ref_options *opt) {
    pthread_t th[TB_MAX_THREADS];
    tb_worker_ w[TB_MAX_THREADS];
    int n = opt && opt->threads > 0 ? opt->threads : 0, i, started = 0;
    if (n <= 0) {
        long c = sysconf(_SC_NPROCESSORS_ONLN);
        n = c > 0 ? (int)c : 1;
    }
    if (n > TB_MAX_THREADS) n = TB_MAX_THREADS;
    if (n > j->rows) n = j->rows > 0 ? j->rows : 1;
    j->nthreads = n;
    for (i = 0; i < n; i++) {
        w[i].job = j;
        w[i].tid = i;
        if (pthread_create(&th[i], NULL, tb_worker_main_, &w[i]) != 0) break;
        started++;
    }
    if (started == 0) {
        /* no threads available: do it here */
        j->nthreads = 1;
        w[0].tid = 0;
        tb_worker_main_(&w[0]);
        return 0;
    }
    if (started < n) {
        /* the missing workers' rows: redo with the threads we have */
        for (i = 0; i < started; i++) pthread_join(th[i], NULL);
        j->nthreads = 1;
        w[0].tid = 0;
        tb_worker_main_(&w[0]);
        return 0;
    }
    for (i = 0; i < started; i++) pthread_join(th[i], NULL);
    return 0;
}

static int tb_light_ok_(const tb_light *L) {
    if (!L) return 0;
    return L->type == TB_LIGHT_DIRECTIONAL || L->type == TB_LIGHT_POINT || L->type == TB_LIGHT_RECT;
}

int tb_reference_trace(const tb_reference *ref, const tb_view *view, const float *depth,
                       const float *normals, const tb_light *light, const tb_ref_options *opt,
                       float *vis) {
    tb_job_ j;
    if (!ref || !view || !depth || !vis || !tb_light_ok_(light) || view->width <= 0 ||
        view->height <= 0)
        return -1;
    memset(&j, 0, sizeof j);
    j.ref = ref;
    j.light = light;
    j.eps = tb_reference_epsilon(ref, opt);
    j.facing = !(opt && opt->ignore_facing);
    j.view = view;
    j.depth = depth;
    j.fnormals = normals;
    j.rows = view->height;
    j.vis = vis;
    return tb_run_(&j, opt);
}

int tb_reference_trace_points(const tb_reference *ref, const double *points, const double *normals,
                              int count, const tb_light *light, const tb_ref_options *opt,
                              float *vis) {
    tb_job_ j;
    if (!ref || !points || !vis || count < 0 || !tb_light_ok_(light)) return -1;
    if (count == 0) return 0;
    memset(&j, 0, sizeof j);
    j.ref = ref;
    j.light = light;
    j.eps = tb_reference_epsilon(ref, opt);
    j.facing = !(opt && opt->ignore_facing);
    j.points = points;
    j.dnormals = normals;
    j.count = count;
    j.rows = (count + TB_POINT_CHUNK - 1) / TB_POINT_CHUNK;
    j.vis = vis;
    return tb_run_(&j, opt);
}

int tb_reference_normals(const tb_reference *ref, const tb_view *view, const float *depth,
                         const tb_ref_options *opt, float *normals) {
    tb_job_ j;
    if (!ref || !view || !depth || !normals || view->width <= 0 || view->height <= 0) return -1;
    memset(&j, 0, sizeof j);
    j.ref = ref;
    j.view = view;
    j.depth = depth;
    j.out_normals = normals;
    j.rows = view->height;
    return tb_run_(&j, opt);
}

static int tb_vec3_finite_(sk_vec3 v) { return isfinite(v.x) && isfinite(v.y) && isfinite(v.z); }

int tb_reference_trace_exact(const tb_reference *ref, const tb_view *view, const float *raster_depth,
                             const tb_light *light, const tb_ref_options *opt, float *vis,
                             tb_ref_stats *stats) {
    tb_job_ j;
    double ivp[16];
    size_t i, n;
    int k;
    if (stats) memset(stats, 0, sizeof *stats);
    if (!ref || !view || !vis || !tb_light_ok_(light) || view->width <= 0 || view->height <= 0)
        return -1;
    if ((light->type == TB_LIGHT_DIRECTIONAL &&
         (!tb_vec3_finite_(light->direction) ||
          !(light->direction.x != 0 || light->direction.y != 0 || light->direction.z != 0))) ||
        (light->type == TB_LIGHT_RECT && light->strata > TB_REF_MAX_STRATA) ||
        (light->type != TB_LIGHT_DIRECTIONAL && !tb_vec3_finite_(light->position)) ||
        (light->type == TB_LIGHT_RECT && (!tb_vec3_finite_(light->half_u) || !tb_vec3_finite_(light->half_v))) ||
        (light->type == TB_LIGHT_POINT && isnan(light->range)))
        return -1;
    if ((size_t)view->width > ((size_t)-1) / (size_t)view->height) return -1;
    memset(&j, 0, sizeof j);
    for (k = 0; k < 16; k++) {
        ivp[k] = view->inv_view_proj.m[k];
        if (!isfinite(ivp[k])) return -1;
    }
    if (!tb_mat4_inverse_d(ivp, j.vp)) return -1;
    j.ref = ref;
    j.light = light;
    j.view = view;
    j.exact = 1;
    j.raster = raster_depth;
    j.raster_n = raster_depth && opt ? opt->raster_normals : NULL;
    j.rows = view->height;
    j.vis = vis;
    if (tb_run_(&j, opt) != 0) return -1;
    if (stats) {
        n = (size_t)view->width * (size_t)view->height;
        stats->pixels = n;
        for (i = 0; i < n; i++) {
            float f = vis[i];
            if (f >= 0) stats->covered++;
            else if (f == TB_VIS_BACKGROUND) stats->background++;
            else if (f == TB_VIS_BACKFACING) stats->backfacing++;
            else if (f == TB_VIS_SILHOUETTE) stats->silhouette++;
            else if (f == TB_VIS_OUT_OF_RANGE) stats->out_of_range++;
        }
    }
    return 0;
}
