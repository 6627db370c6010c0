/* tb_metrics.c - see tb_metrics.h */
#include "tb_metrics.h"

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
    }
    free(c);
    return s;
}
