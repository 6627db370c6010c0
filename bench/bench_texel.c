/* bench/bench_texel.c - see bench_texel.h */
#include "bench_texel.h"

#include "tb_reference.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

int bench_receivers_init(bench_receivers *r, int w, int h, const sk_mat4 *view_proj, const sk_mat4 *view,
                         const float *depth) {
    double vp[16], inv[16];
    size_t n = (size_t)w * (size_t)h, i;
    int k;
    memset(r, 0, sizeof *r);
    for (k = 0; k < 16; k++) vp[k] = view_proj->m[k];
    if (!tb_mat4_inverse_d(vp, inv)) return -1;
    r->world = (double *)malloc(sizeof(double) * 3 * n);
    r->view_depth = (float *)malloc(sizeof(float) * n);
    if (!r->world || !r->view_depth) { bench_receivers_free(r); return -1; }
    r->w = w;
    r->h = h;
    for (i = 0; i < n; i++) {
        double ndc[4], p[4];
        int row, col;
        r->world[3 * i] = r->world[3 * i + 1] = r->world[3 * i + 2] = NAN;
        r->view_depth[i] = NAN;
        if (!(depth[i] < 1.0f)) continue;   /* background (cleared depth) */
        ndc[0] = 2.0 * ((double)(i % (size_t)w) + 0.5) / w - 1.0;
        ndc[1] = 2.0 * ((double)(i / (size_t)w) + 0.5) / h - 1.0;
        ndc[2] = 2.0 * depth[i] - 1.0;
        ndc[3] = 1.0;
        for (row = 0; row < 4; row++) {
            p[row] = 0.0;
            for (col = 0; col < 4; col++) p[row] += inv[col * 4 + row] * ndc[col];
        }
        if (!(p[3] != 0.0)) continue;
        for (k = 0; k < 3; k++) r->world[3 * i + k] = p[k] / p[3];
        r->view_depth[i] = -(float)(view->m[2] * r->world[3 * i] + view->m[6] * r->world[3 * i + 1] +
                                    view->m[10] * r->world[3 * i + 2] + view->m[14]);
    }
    return 0;
}

void bench_receivers_free(bench_receivers *r) {
    free(r->world);
    free(r->view_depth);
    memset(r, 0, sizeof *r);
}

int bench_texel_scratch_init(bench_texel_scratch *t, int w, int h) {
    size_t n = (size_t)w * (size_t)h;
    memset(t, 0, sizeof *t);
    t->texel = (double *)malloc(sizeof(double) * 2 * n);
    t->key = (int *)malloc(sizeof(int) * n);
    t->footprint = (float *)malloc(sizeof(float) * n);
    t->deriv = (float *)malloc(sizeof(float) * 4 * n);
    if (!t->texel || !t->key || !t->footprint || !t->deriv) { bench_texel_scratch_free(t); return -1; }
    return 0;
}

void bench_texel_scratch_free(bench_texel_scratch *t) {
    free(t->texel);
    free(t->key);
    free(t->footprint);
    free(t->deriv);
    free(t->resident);
    memset(t, 0, sizeof *t);
}

/* light clip of world point p by the float matrix m, in double */
static void clip_of(const sk_mat4 *m, const double p[3], double c[4]) {
    int r;
    for (r = 0; r < 4; r++) c[r] = m->m[r] * p[0] + m->m[4 + r] * p[1] + m->m[8 + r] * p[2] + m->m[12 + r];
}

/* the layer shadow_sample.glsl's sk_shadow picks for a point at view depth
   d: the last whose split it has passed; -1 outside the split range */
static int layer_by_depth(const skgl_shadow_frame_stats *st, float d) {
    int i, layer = 0;
    if (!(d >= st->splits[0]) || !(d < st->splits[st->maps])) return -1;
    for (i = 1; i < st->maps; i++)
        if (d >= st->splits[i]) layer = i;
    return layer;
}

/* LSPSM: the first partition whose rect holds p (sk_select_by_map) */
static int layer_by_map(const skgl_shadow *s, const skgl_shadow_frame_stats *st, const double p[3], float d) {
    float e = skgl_shadow_select_extent(s);
    int i;
    if (!(d >= st->splits[0]) || !(d < st->splits[1])) return -1;
    for (i = 0; i < st->maps; i++) {
        sk_mat4 m = skgl_shadow_matrix(s, i);
        double c[4];
        clip_of(&m, p, c);
        if (fabs(c[0]) <= e * c[3] && fabs(c[1]) <= e * c[3]) return i;
    }
    return -1;
}

/* one layered map's texel coordinates (layer as key), as sk_shadow_layer
   looks them up: uv = NDC / 2 + 1/2 within the rendered extent, in
   texels of the res x res layer */
static void layered_texels(const skgl_shadow *s, const bench_receivers *rc, const float *ref,
                           bench_texel_scratch *t) {
    const skgl_shadow_frame_stats *st = skgl_shadow_stats(s);
    skgl_shadow_desc d = skgl_shadow_get_desc(s);
    double res = d.resolution;
    double ext_x = d.technique == SKGL_FERKO ? st->map_width / res : 1.0;
    double ext_y = d.technique == SKGL_FERKO ? st->map_height / res : 1.0;
    sk_mat4 m[SKGL_MAX_CASCADES];
    size_t i, n = (size_t)rc->w * (size_t)rc->h;
    int l;
    for (l = 0; l < st->maps && l < SKGL_MAX_CASCADES; l++) m[l] = skgl_shadow_matrix(s, l);
    for (i = 0; i < n; i++) {
        const double *p = rc->world + 3 * i;
        double c[4], u, v, z;
        t->key[i] = -1;
        if (!(ref[i] >= 0.0f) || isnan(p[0])) continue;
        l = d.technique == SKGL_LSPSM ? layer_by_map(s, st, p, rc->view_depth[i])
                                      : layer_by_depth(st, rc->view_depth[i]);
        if (l < 0 || l >= SKGL_MAX_CASCADES) continue;
        clip_of(&m[l], p, c);
        if (!(c[3] > 0.0)) continue;
        u = c[0] / c[3] * 0.5 + 0.5;
        v = c[1] / c[3] * 0.5 + 0.5;
        z = c[2] / c[3] * 0.5 + 0.5;
        if (u < 0.0 || v < 0.0 || u > ext_x || v > ext_y || z > 1.0) continue;
        t->texel[2 * i] = u * res;
        t->texel[2 * i + 1] = v * res;
        t->key[i] = l;
    }
}

/* RMSM: the pages resident after the last render, a byte per page of every
   level (level l's (pages0 >> l)^2 pages after the finer levels'); NULL on
   failure */
static const unsigned char *rmsm_resident(const skgl_shadow *s, int pages0, int levels, bench_texel_scratch *t) {
    size_t total = 0, off[32];
    int l, k, np = skgl_shadow_pages(s, NULL, 0);
    sk_page *pages;
    for (l = 0; l < levels && l < 32; l++) {
        off[l] = total;
        total += (size_t)(pages0 >> l) * (size_t)(pages0 >> l);
    }
    if (total > t->resident_cap) {
        unsigned char *r = (unsigned char *)realloc(t->resident, total);
        if (!r) return NULL;
        t->resident = r;
        t->resident_cap = total;
    }
    memset(t->resident, 0, total);
    pages = (sk_page *)malloc(sizeof *pages * (size_t)(np > 0 ? np : 1));
    if (!pages) return NULL;
    np = skgl_shadow_pages(s, pages, np);
    for (k = 0; k < np; k++) {
        const sk_page *p = &pages[k];
        int side = p->level >= 0 && p->level < levels ? pages0 >> p->level : 0;
        if (p->px >= 0 && p->py >= 0 && p->px < side && p->py < side)
            t->resident[off[p->level] + (size_t)p->py * (size_t)side + (size_t)p->px] = 1;
    }
    free(pages);
    return t->resident;
}

/* the smallest singular value of the 2x2 [a b; c d] (columns: the change
   per pixel along screen x, y) */
static double smallest_singular(double a, double b, double c, double d) {
    double tr = a * a + b * b + c * c + d * d, det = fabs(a * d - b * c);
    double smax = sqrt(0.5 * (tr + sqrt(fmax(tr * tr - 4.0 * det * det, 0.0))));
    return smax > 0.0 ? det / smax : 0.0;
}

/* RMSM: level-0 virtual texels first (one key) for the level of detail,
   then each pixel's texel coordinates at the level it samples (level as
   key), as sk_shadow_rmsm walks the page table. 0 ok. */
static int rmsm_texels(const skgl_shadow *s, const bench_receivers *rc, const float *ref, bench_texel_scratch *t) {
    const skgl_shadow_frame_stats *st = skgl_shadow_stats(s);
    skgl_shadow_desc d = skgl_shadow_get_desc(s);
    sk_mat4 m = skgl_shadow_matrix(s, 0);
    int pages0 = d.resolution / d.rmsm_page_size, levels = 1, w = rc->w;
    size_t i, n = (size_t)rc->w * (size_t)rc->h, off[32];
    const unsigned char *res;
    while ((pages0 >> levels) >= 1 && levels < 32) levels++;
    if (!(res = rmsm_resident(s, pages0, levels, t))) return -1;
    off[0] = 0;
    for (i = 1; i < (size_t)levels; i++) off[i] = off[i - 1] + (size_t)(pages0 >> (i - 1)) * (size_t)(pages0 >> (i - 1));
    for (i = 0; i < n; i++) {
        const double *p = rc->world + 3 * i;
        double c[4], u, v;
        t->key[i] = -1;
        if (!(ref[i] >= 0.0f) || isnan(p[0])) continue;
        clip_of(&m, p, c);
        if (!(c[3] > 0.0)) continue;
        u = c[0] / c[3] * 0.5 + 0.5;
        v = c[1] / c[3] * 0.5 + 0.5;
        if (u < 0.0 || v < 0.0 || u >= 1.0 || v >= 1.0) continue;
        t->texel[2 * i] = u * d.resolution;
        t->texel[2 * i + 1] = v * d.resolution;
        t->key[i] = 0;
    }
    if (tb_texel_footprint(t->texel, t->key, w, rc->h, t->footprint, t->deriv) != 0) return -1;
    for (i = 0; i < n; i++) {
        const float *j = t->deriv + 4 * i;
        double sv, lres;
        int level, found = 0;
        if (t->key[i] < 0) continue;
        t->key[i] = -1;
        if (t->footprint[i] < 0.0f) continue;
        sv = smallest_singular(j[0], j[2], j[1], j[3]);
        /* as the shader takes it (sk_shadow_rmsm, its sk_rmsm_min_level =
           -stats.rmsm_band, else stats.rmsm_min_level): request band b
           starts b levels finer than the pixel's */
        {
            int u = st->rmsm_band > 0 ? -st->rmsm_band : st->rmsm_min_level;
            level = (sv > 0.0 ? (int)floor(log2(sv)) : 0) - (u < 0 ? -u : 0);
            if (level < (u > 0 ? u : 0)) level = u > 0 ? u : 0;
        }
        if (level > levels - 1) level = levels - 1;
        for (; level < levels; level++) {
            int side = pages0 >> level;
            int px = (int)(t->texel[2 * i] / d.resolution * side), py = (int)(t->texel[2 * i + 1] / d.resolution * side);
            if (px > side - 1) px = side - 1;
            if (py > side - 1) py = side - 1;
            if (res[off[level] + (size_t)py * (size_t)side + (size_t)px]) { found = 1; break; }
        }
        if (!found) continue;   /* no page: the mask says lit without a lookup */
        lres = ldexp(1.0, -level);
        t->texel[2 * i] *= lres;
        t->texel[2 * i + 1] *= lres;
        t->key[i] = level;
    }
    return 0;
}

tb_footprint_stats bench_texel_stats(const skgl_shadow *s, const bench_receivers *rc, const float *ref,
                                     bench_texel_scratch *t) {
    tb_footprint_stats none;
    size_t n = (size_t)rc->w * (size_t)rc->h;
    memset(&none, 0, sizeof none);
    if (!s || !rc->world) return none;
    if (skgl_shadow_get_desc(s).technique == SKGL_RMSM) {
        if (rmsm_texels(s, rc, ref, t) != 0) return none;
    } else {
        layered_texels(s, rc, ref, t);
    }
    if (tb_texel_footprint(t->texel, t->key, rc->w, rc->h, t->footprint, NULL) != 0) return none;
    return tb_metric_footprint(t->footprint, n);
}
