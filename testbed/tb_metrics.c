/* tb_metrics.c - see tb_metrics.h */
#include "tb_metrics.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

int tb_visibility_class(float v) {
    if (v < 0) return -1;
    return v >= TB_LIT_THRESHOLD ? 1 : 0;
}

static int tb_finite_(float v) { return isfinite(v) ? 1 : 0; }

tb_hard_error tb_metric_hard(const float *ref, const float *res, size_t n) {
    tb_hard_error e;
    size_t i;
    memset(&e, 0, sizeof e);
    for (i = 0; i < n; i++) {
        int rc = tb_visibility_class(ref[i]);
        if (rc < 0 || !tb_finite_(ref[i])) continue;
        e.covered++;
        if (!tb_finite_(res[i])) { e.invalid++; continue; }
        if (res[i] >= TB_LIT_THRESHOLD) { if (rc == 0) e.false_lit++; }
        else if (rc == 1) e.false_shadow++;
    }
    e.wrong = e.false_lit + e.false_shadow + e.invalid;
    e.pct = e.covered ? 100.0 * (double)e.wrong / (double)e.covered : 0.0;
    return e;
}

tb_soft_error tb_metric_soft(const float *ref, const float *res, size_t n) {
    tb_soft_error e;
    double sum = 0;
    size_t i;
    memset(&e, 0, sizeof e);
    for (i = 0; i < n; i++) {
        double d;
        if (!(ref[i] >= 0) || !tb_finite_(ref[i])) continue;
        e.covered++;
        if (!tb_finite_(res[i])) { e.invalid++; d = 1.0; }
        else d = fabs((double)res[i] - (double)ref[i]);
        sum += d;
        if (d > e.max_abs) e.max_abs = d;
    }
    e.mae = e.covered ? sum / (double)e.covered : 0.0;
    return e;
}

/* class of a result value: non-finite is its own class (2) */
static int tb_res_class_(float v) {
    if (!tb_finite_(v)) return 2;
    return v >= TB_LIT_THRESHOLD ? 1 : 0;
}

tb_flip_rate tb_metric_flip(const float *ref0, const float *ref1, const float *res0,
                            const float *res1, size_t n) {
    tb_flip_rate f;
    size_t i;
    memset(&f, 0, sizeof f);
    for (i = 0; i < n; i++) {
        int a = tb_visibility_class(ref0[i]), b = tb_visibility_class(ref1[i]);
        if (a < 0 || b < 0 || !tb_finite_(ref0[i]) || !tb_finite_(ref1[i])) continue;
        f.covered++;
        if (a != b) { f.ref_flips++; continue; }
        if (tb_res_class_(res0[i]) != tb_res_class_(res1[i]) || tb_res_class_(res0[i]) == 2)
            f.flips++;
    }
    f.pct = f.covered ? 100.0 * (double)f.flips / (double)f.covered : 0.0;
    return f;
}

static int tb_cmp_float_(const void *a, const void *b) {
    float x = *(const float *)a, y = *(const float *)b;
    return (x > y) - (x < y);
}

double tb_quantile_sorted(const float *x, size_t n, double p) {
    double h, fl;
    size_t k;
    if (n == 0) return 0.0;
    if (p <= 0) return x[0];
    if (p >= 1) return x[n - 1];
    h = (double)(n - 1) * p;
    fl = floor(h);
    k = (size_t)fl;
    if (k + 1 >= n) return x[n - 1];
    return x[k] + (h - fl) * ((double)x[k + 1] - (double)x[k]);
}

/* % of the n ascending values above t */
static double tb_share_above_(const float *sorted, size_t n, float t) {
    size_t lo = 0, hi = n;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (sorted[mid] > t) hi = mid;
        else lo = mid + 1;
    }
    return 100.0 * (double)(n - lo) / (double)n;
}

tb_footprint_stats tb_metric_footprint(const float *fp, size_t n) {
    tb_footprint_stats s;
    float *c;
    size_t i, m = 0;
    double sum = 0;
    memset(&s, 0, sizeof s);
    if (n == 0) return s;
    c = (float *)malloc(n * sizeof *c);
    if (!c) return s;
    for (i = 0; i < n; i++)
        if (tb_finite_(fp[i]) && fp[i] >= 0) {
            c[m++] = fp[i];
            sum += fp[i];
        }
    if (m > 0) {
        qsort(c, m, sizeof *c, tb_cmp_float_);
        s.count = m;
        s.min = c[0];
        s.max = c[m - 1];
        s.mean = sum / (double)m;
        s.median = tb_quantile_sorted(c, m, 0.5);
        s.p95 = tb_quantile_sorted(c, m, 0.95);
        s.over1_pct = tb_share_above_(c, m, 1.0f);
        s.over2_pct = tb_share_above_(c, m, 2.0f);
        s.over4_pct = tb_share_above_(c, m, 4.0f);
    }
    free(c);
    return s;
}

/* the change of pixel i's texel coordinates to its neighbour j (j - i
   steps of +1 along the axis when sign is 1, -1 when it is -1) into d;
   0 when j samples another map */
static int tb_texel_step_(const double *texel, const int *key, size_t i, size_t j, double sign, double d[2]) {
    if (key[j] != key[i] || !isfinite(texel[2 * j]) || !isfinite(texel[2 * j + 1])) return 0;
    d[0] = sign * (texel[2 * j] - texel[2 * i]);
    d[1] = sign * (texel[2 * j + 1] - texel[2 * i + 1]);
    return 1;
}

/* the shorter of the changes to the neighbours before (i - stride, if
   has_lo) and after (i + stride, if has_hi); 0 when neither samples the
   same map */
static int tb_texel_axis_(const double *texel, const int *key, size_t i, size_t stride, int has_lo, int has_hi,
                          double d[2]) {
    double lo[2], hi[2];
    int a = has_lo && tb_texel_step_(texel, key, i, i - stride, -1.0, lo);
    int b = has_hi && tb_texel_step_(texel, key, i, i + stride, 1.0, hi);
    if (!a && !b) return 0;
    if (a && (!b || lo[0] * lo[0] + lo[1] * lo[1] < hi[0] * hi[0] + hi[1] * hi[1])) { d[0] = lo[0]; d[1] = lo[1]; }
    else { d[0] = hi[0]; d[1] = hi[1]; }
    return 1;
}

int tb_texel_footprint(const double *texel, const int *key, int w, int h, float *footprint, float *deriv) {
    int x, y;
    if (!texel || !key || !footprint || w <= 0 || h <= 0) return -1;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            size_t i = (size_t)y * (size_t)w + (size_t)x;
            double dx[2], dy[2], ex, ey, f;
            int ok = key[i] >= 0 && isfinite(texel[2 * i]) && isfinite(texel[2 * i + 1]) &&
                     tb_texel_axis_(texel, key, i, 1, x > 0, x + 1 < w, dx) &&
                     tb_texel_axis_(texel, key, i, (size_t)w, y > 0, y + 1 < h, dy);
            if (!ok) {
                footprint[i] = -1.0f;
                if (deriv) deriv[4 * i] = deriv[4 * i + 1] = deriv[4 * i + 2] = deriv[4 * i + 3] = (float)NAN;
                continue;
            }
            /* the patch's bounding box in the map: ex by ey texels; a texel
               spans 1/ex pixels along the map's x, 1/ey along its y */
            ex = fabs(dx[0]) + fabs(dy[0]);
            ey = fabs(dx[1]) + fabs(dy[1]);
            f = 1.0 / (ex < ey ? ex : ey);
            footprint[i] = f < (double)FLT_MAX ? (float)f : FLT_MAX;
            if (deriv) {
                deriv[4 * i] = (float)dx[0];
                deriv[4 * i + 1] = (float)dx[1];
                deriv[4 * i + 2] = (float)dy[0];
                deriv[4 * i + 3] = (float)dy[1];
            }
        }
    return 0;
}

int tb_metric_shadow_bands(const float *ref, const float *res, const int *band, size_t n, int nbands,
                           uint64_t *shadow, uint64_t *wrong) {
    size_t i;
    int b;
    if (!ref || !res || !band || !shadow || !wrong || nbands <= 0) return -1;
    for (b = 0; b < nbands; b++) shadow[b] = wrong[b] = 0;
    for (i = 0; i < n; i++) {
        int rc = tb_visibility_class(ref[i]);
        b = band[i];
        if (rc < 0 || !tb_finite_(ref[i]) || b < 0 || b >= nbands) continue;
        shadow[b] += rc == 0;
        wrong[b] += !tb_finite_(res[i]) || tb_visibility_class(res[i]) != rc;
    }
    return 0;
}

/* ---------------------------------------------- exact distance transform */
/* Squared Euclidean distance transform after Felzenszwalb and Huttenlocher,
   "Distance Transforms of Sampled Functions", Theory of Computing 8 (2012):
   D(p) = min_q (|p - q|^2 + f(q)) is separable, so it runs as a 1-D
   transform along every column, then along every row of the result.
   Here f is 0 at sites and +infinity elsewhere. For such a function the
   column transform is the squared distance to the nearest site in the
   column, which two sweeps over the rows find (contiguous in memory); the
   row transform is the paper's lower envelope of the parabolas
   (x - q)^2 + f(q), built left to right in one pass and read off in a
   second: O(n). Infinite samples (columns without a site) are left out of
   the envelope instead of standing in as a large number, so every output
   is exact (sums of squares of integers, far below 2^53) or +infinity
   when the frame holds no site. */

/* 1-D transform of the n samples of f into d (f == d allowed); v (n ints),
   z (n + 1 doubles) and tmp (n doubles) are scratch */
static void tb_dt1d_(const double *f, double *d, int n, int *v, double *z, double *tmp) {
    int q, k = -1, j;
    for (q = 0; q < n; q++) {
        double s;
        if (isinf(f[q])) continue;
        if (k < 0) {
            k = 0;
            v[0] = q;
            z[0] = -INFINITY;
            z[1] = INFINITY;
            continue;
        }
        /* where the parabola from q overtakes the rightmost one kept;
           z[0] = -inf ends the loop with k >= 0 */
        for (;;) {
            s = ((f[q] + (double)q * q) - (f[v[k]] + (double)v[k] * v[k])) / (2.0 * (double)(q - v[k]));
            if (s > z[k]) break;
            k--;
        }
        k++;
        v[k] = q;
        z[k] = s;
        z[k + 1] = INFINITY;
    }
    if (k < 0) {
        for (q = 0; q < n; q++) tmp[q] = INFINITY;
    } else {
        j = 0;
        for (q = 0; q < n; q++) {
            double dq;
            while (z[j + 1] < (double)q) j++;
            dq = (double)(q - v[j]);
            tmp[q] = dq * dq + f[v[j]];
        }
    }
    memcpy(d, tmp, sizeof(double) * (size_t)n);
}

/* in place: grid (w x h, row-major) holds 0 at sites and +infinity
   elsewhere on entry, the squared distance to the nearest site on return
   (+infinity everywhere when there is none). -1 when out of memory. */
static int tb_edt_sq_(double *grid, int w, int h) {
    int x, y;
    int *v = (int *)malloc(sizeof(int) * (size_t)w);
    double *z = (double *)malloc(sizeof(double) * ((size_t)w + 1));
    double *tmp = (double *)malloc(sizeof(double) * (size_t)w);
    if (!v || !z || !tmp) {
        free(v); free(z); free(tmp);
        return -1;
    }
    /* columns: distance in rows to the nearest site below, then above */
    for (y = 1; y < h; y++) {
        double *row = grid + (size_t)y * w;
        const double *below = row - w;
        for (x = 0; x < w; x++)
            if (row[x] != 0.0 && below[x] + 1.0 < row[x]) row[x] = below[x] + 1.0;
    }
    for (y = h - 2; y >= 0; y--) {
        double *row = grid + (size_t)y * w;
        const double *above = row + w;
        for (x = 0; x < w; x++)
            if (above[x] + 1.0 < row[x]) row[x] = above[x] + 1.0;
    }
    /* rows: the envelope over the squared column distances */
    for (y = 0; y < h; y++) {
        double *row = grid + (size_t)y * w;
        for (x = 0; x < w; x++) row[x] *= row[x];
        tb_dt1d_(row, row, w, v, z, tmp);
    }
    free(v); free(z); free(tmp);
    return 0;
}

/* covered: reference finite and >= 0 */
static int tb_covered_(float r) { return tb_finite_(r) && r >= 0.0f; }

static int tb_frame_ok_(const void *ref, const void *res, int w, int h) {
    if (!ref || !res || w <= 0 || h <= 0) return 0;
    /* w * h and (w * h + 1) doubles must fit a size_t */
    return (size_t)w <= ((size_t)-1 / sizeof(double) - 1) / (size_t)h;
}

static int tb_cmp_double_(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* tb_quantile_sorted's definition on doubles */
static double tb_quantile_sorted_d_(const double *x, size_t n, double p) {
    double hp, fl;
    size_t k;
    if (n == 0) return 0.0;
    if (p <= 0) return x[0];
    if (p >= 1) return x[n - 1];
    hp = (double)(n - 1) * p;
    fl = floor(hp);
    k = (size_t)fl;
    if (k + 1 >= n) return x[n - 1];
    return x[k] + (hp - fl) * (x[k + 1] - x[k]);
}

tb_shadow_error tb_metric_shadow(const float *ref, const float *res, int w, int h) {
    tb_shadow_error e;
    size_t n, i, m = 0;
    double *grid = NULL, *dist = NULL, sum = 0.0;
    uint64_t wrong_in[2] = {0, 0};   /* wrong pixels by reference class */
    int cls;
    memset(&e, 0, sizeof e);
    if (!tb_frame_ok_(ref, res, w, h)) return e;
    n = (size_t)w * (size_t)h;
    for (i = 0; i < n; i++) {
        int rc;
        if (!tb_covered_(ref[i])) continue;
        rc = tb_visibility_class(ref[i]);
        e.covered++;
        if (rc == 1) e.lit++;
        else e.shadow++;
        if (!tb_finite_(res[i])) e.invalid++;
        else if (res[i] >= TB_LIT_THRESHOLD) { if (rc == 0) e.false_light++; else continue; }
        else if (rc == 1) e.false_shadow++;
        else continue;
        wrong_in[rc]++;
    }
    e.wrong = e.false_shadow + e.false_light + e.invalid;
    e.covered_pct = e.covered ? 100.0 * (double)e.wrong / (double)e.covered : 0.0;
    if (e.shadow) {
        e.area_pct = 100.0 * (double)e.wrong / (double)e.shadow;
        e.false_shadow_pct = 100.0 * (double)e.false_shadow / (double)e.shadow;
        e.false_light_pct = 100.0 * (double)e.false_light / (double)e.shadow;
    }
    e.ok = 1;
    /* edges exist only when the reference has covered pixels of both classes */
    if (e.wrong == 0 || e.shadow == 0 || e.lit == 0) return e;
    grid = (double *)malloc(sizeof(double) * n);
    dist = (double *)malloc(sizeof(double) * (size_t)e.wrong);
    if (!grid || !dist) goto oom;
    /* wrong pixels of reference class cls measure to the sites of class 1 - cls */
    for (cls = 0; cls < 2; cls++) {
        if (wrong_in[cls] == 0) continue;
        for (i = 0; i < n; i++)
            grid[i] = tb_covered_(ref[i]) && tb_visibility_class(ref[i]) == 1 - cls ? 0.0 : INFINITY;
        if (tb_edt_sq_(grid, w, h) != 0) goto oom;
        for (i = 0; i < n; i++) {
            double d;
            if (!tb_covered_(ref[i]) || tb_visibility_class(ref[i]) != cls) continue;
            if (tb_finite_(res[i]) && (res[i] >= TB_LIT_THRESHOLD) == (cls == 1)) continue;   /* right */
            d = sqrt(grid[i]) - 0.5;
            dist[m++] = d > 0.0 ? d : 0.0;
            sum += dist[m - 1];
        }
    }
    qsort(dist, m, sizeof *dist, tb_cmp_double_);
    e.edge_count = m;
    e.edge_mean_px = m ? sum / (double)m : 0.0;
    e.edge_p95_px = tb_quantile_sorted_d_(dist, m, 0.95);
    free(grid);
    free(dist);
    return e;
oom:
    free(grid);
    free(dist);
    memset(&e, 0, sizeof e);
    return e;
}

tb_penumbra_error tb_metric_penumbra(const float *ref, const float *res, int w, int h, int grow_px) {
    tb_penumbra_error e;
    size_t n, i;
    double *grid, sum_p = 0.0, sum_u = 0.0, sum_l = 0.0, sum_all = 0.0;
    const double reach = (double)grow_px * (double)grow_px;
    memset(&e, 0, sizeof e);
    if (!tb_frame_ok_(ref, res, w, h) || grow_px < 0) return e;
    n = (size_t)w * (size_t)h;
    grid = (double *)malloc(sizeof(double) * n);
    if (!grid) return e;
    for (i = 0; i < n; i++) {
        int core = tb_covered_(ref[i]) && ref[i] > 0.0f && ref[i] < 1.0f;
        grid[i] = core ? 0.0 : INFINITY;
        e.penumbra_core += (uint64_t)core;
    }
    if (grow_px > 0 && e.penumbra_core > 0 && tb_edt_sq_(grid, w, h) != 0) {
        free(grid);
        return e;
    }
    for (i = 0; i < n; i++) {
        double d;
        if (!tb_covered_(ref[i])) continue;
        e.covered++;
        if (!tb_finite_(res[i])) { e.invalid++; d = 1.0; }
        else d = fabs((double)res[i] - (double)ref[i]);
        sum_all += d;
        if (grid[i] <= reach) {
            e.penumbra++;
            sum_p += d;
            if (d > e.penumbra_max) e.penumbra_max = d;
        } else if (ref[i] <= 0.0f) {
            e.umbra++;
            sum_u += d;
            if (d > e.umbra_max) e.umbra_max = d;
        } else {
            e.lit++;
            sum_l += d;
            if (d > e.lit_max) e.lit_max = d;
        }
    }
    free(grid);
    e.penumbra_mae = e.penumbra ? sum_p / (double)e.penumbra : 0.0;
    e.umbra_mae = e.umbra ? sum_u / (double)e.umbra : 0.0;
    e.lit_mae = e.lit ? sum_l / (double)e.lit : 0.0;
    e.covered_mae = e.covered ? sum_all / (double)e.covered : 0.0;
    e.ok = 1;
    return e;
}
