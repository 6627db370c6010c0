/* test_lspsm.c - Light Space Partitioned Shadow Maps (Tang et al. 2017).

   Tests sk_lspsm_default_params, sk_lspsm_partition, sk_lspsm_region_extract and
   sk_lspsm_crops. Every expected value is derived here independently, in double:
   - the partition from the paper's Eq. (1) and this library's documented rules
     (rows stacked from y = 0, at most h_max rows, the last one stretched to end at
     L with the trapezoid's full width there, transverse split into
     N_w = min(nw_max, ceil((W/H)/(1+sigma))) equal columns centred on x = 0);
   - the projective region from this file's own convex clip of the camera frustum
     against the receiver box (vertex enumeration over plane triples) and a
     brute-force minimum-area enclosing isosceles trapezoid;
   - the crops from the partition rects lifted back to world space. */
#define SHADOWKIT_IMPLEMENTATION
#include "shadowkit.h"
#include "tests/sk_test.h"
#include "tests/sk_ref.h"
#include <float.h>
#include <limits.h>

/* ---------------------------------------------------------------- helpers */
static int finite_rect(sk_rect r) { return finite_d(r.x0) && finite_d(r.y0) && finite_d(r.x1) && finite_d(r.y1); }
static int nan_rect(sk_rect r) { return r.x0 != r.x0 || r.y0 != r.y0 || r.x1 != r.x1 || r.y1 != r.y1; }

static sk_lspsm_params mkparams(float zeta, float sigma, int h_max, int nw_max) {
    sk_lspsm_params p; p.zeta = zeta; p.sigma = sigma; p.h_max = h_max; p.nw_max = nw_max; return p;
}

static dv3 mat_row(const sk_mat4 *m, int r) { return dv(m->m[r], m->m[4 + r], m->m[8 + r]); }
/* inverse of an affine (rigid) view: world point whose view coords are q */
static dv3 view_unproject(const sk_mat4 *m, dv3 q) {
    dv3 r0 = mat_row(m, 0), r1 = mat_row(m, 1), r2 = mat_row(m, 2);
    double det = ddot(r0, dcross(r1, r2));
    dv3 v = dv(q.x - m->m[12], q.y - m->m[13], q.z - m->m[14]);
    dv3 c0 = dmul(dcross(r1, r2), 1.0 / det), c1 = dmul(dcross(r2, r0), 1.0 / det),
        c2 = dmul(dcross(r0, r1), 1.0 / det);
    return dadd(dadd(dmul(c0, v.x), dmul(c1, v.y)), dmul(c2, v.z));
}

/* ------------------------------------------------ reference partition (Eq. 1) */
typedef struct drect { double x0, y0, x1, y1; int row; int stretched; double W, H; } drect;

/* Eq. (1) plus the documented rules, in double. Returns the count (or -1 if
   more than cap). */
static int ref_partition(double n, double L, double theta, double zeta, double sigma,
                         int h_max, int nw_max, drect *out, int cap) {
    double t = tan(theta), y = 0.0;
    int i, count = 0;
    for (i = 1; i <= h_max; i++) {
        double W, H, y1, ratio;
        int stretched = 0, nw, j;
        if (t < zeta) { W = n / pow(1.0 - 2.0 * t, i); H = W; }
        else { W = n / pow(1.0 - 2.0 * zeta, i); H = W * zeta / t; }
        y1 = y + H;
        if (i == h_max && y1 < L) { y1 = L; H = L - y; W = n + 2.0 * L * t; stretched = 1; }
        ratio = W / H;
        nw = 1;
        if (ratio > 1.0 + sigma) {
            double c = ceil(ratio / (1.0 + sigma));
            nw = c > (double)nw_max ? nw_max : (int)c;
        }
        for (j = 0; j < nw; j++) {
            if (count >= cap) return -1;
            out[count].x0 = -W / 2 + W * j / nw;
            out[count].x1 = -W / 2 + W * (j + 1) / nw;
            out[count].y0 = y;
            out[count].y1 = y1;
            out[count].row = i;
            out[count].stretched = stretched;
            out[count].W = W;
            out[count].H = H;
            count++;
        }
        y = y1;
        if (y >= L) break;
    }
    return count;
}

/* Full comparison of sk_lspsm_partition against the reference, plus the
   geometric properties of the paper's design. */
static void check_partition_case(float n, float L, float theta, sk_lspsm_params p, int expect_count) {
    sk_rect out[64];
    drect ref[64];
    int got, want, k;
    double t = tan((double)theta);
    memset(out, 0, sizeof out);
    got = sk_lspsm_partition(n, L, theta, &p, out, 64);
    want = ref_partition(n, L, theta, p.zeta, p.sigma, p.h_max, p.nw_max, ref, 64);
    SK_CHECK_MSG(got == want, "n=%g L=%g theta=%.9g: count %d, expected %d", n, L, theta, got, want);
    if (expect_count > 0)
        SK_CHECK_MSG(want == expect_count, "reference count %d, hand-derived %d (n=%g L=%g theta=%g)",
                     want, expect_count, n, L, theta);
    if (got != want || got <= 0) return;

    /* every rect, exactly as Eq. (1) */
    for (k = 0; k < got; k++) {
        double sc = (ref[k].W > ref[k].H ? ref[k].W : ref[k].H);
        double tol = 2e-4 * sc;
        SK_CHECK_MSG(finite_rect(out[k]), "rect %d not finite", k);
        SK_CHECK_MSG(fabs(out[k].x0 - ref[k].x0) <= tol + 2e-4 * fabs(ref[k].x0) &&
                     fabs(out[k].x1 - ref[k].x1) <= tol + 2e-4 * fabs(ref[k].x1) &&
                     fabs(out[k].y0 - ref[k].y0) <= tol + 2e-4 * fabs(ref[k].y0) &&
                     fabs(out[k].y1 - ref[k].y1) <= tol + 2e-4 * fabs(ref[k].y1),
                     "n=%g L=%g theta=%.9g rect %d = [%.9g,%.9g]x[%.9g,%.9g], expected [%.9g,%.9g]x[%.9g,%.9g]",
                     n, L, theta, k, out[k].x0, out[k].x1, out[k].y0, out[k].y1,
                     ref[k].x0, ref[k].x1, ref[k].y0, ref[k].y1);
    }

    /* rows: stacked from y = 0 without gaps, last reaches L; each row's full
       width equals the trapezoid's width at its far edge; columns equal,
       contiguous and centred; space-wasting factor <= zeta for Eq. (1) rows */
    {
        int row_start = 0;
        double prev_y1 = 0.0;
        double Ld = L, nd = n;
        while (row_start < got) {
            int row_end = row_start, j;
            double ry0 = out[row_start].y0, ry1 = out[row_start].y1;
            double xmin, xmax, W, H, scale;
            while (row_end + 1 < got && out[row_end + 1].y0 == ry0 && out[row_end + 1].y1 == ry1) row_end++;
            xmin = out[row_start].x0; xmax = out[row_end].x1;
            W = xmax - xmin; H = ry1 - ry0;
            scale = (W > H ? W : H) + fabs(ry1);
            SK_CHECK_MSG(fabs(ry0 - prev_y1) <= 2e-5 * scale, "row at %d starts at %.9g, previous ended at %.9g",
                         row_start, ry0, prev_y1);
            SK_CHECK_MSG(fabs(W - (nd + 2.0 * ry1 * t)) <= 2e-4 * W,
                         "row width %.9g != trapezoid width %.9g at its far edge y=%.9g",
                         W, nd + 2.0 * ry1 * t, ry1);
            SK_CHECK_MSG(fabs(xmin + xmax) <= 2e-4 * W, "row not centred: [%.9g, %.9g]", xmin, xmax);
            for (j = row_start; j <= row_end; j++) {
                double cw = out[j].x1 - out[j].x0;
                SK_CHECK_MSG(fabs(cw - W / (row_end - row_start + 1)) <= 2e-4 * W, "column %d width %.9g", j, cw);
                if (j > row_start)
                    SK_CHECK_MSG(fabs(out[j].x0 - out[j - 1].x1) <= 2e-5 * W, "column gap at %d", j);
            }
            if (!ref[row_start].stretched) {
                double rho = H * t / W;
                SK_CHECK_MSG(rho <= p.zeta * (1.0 + 1e-4) + 1e-7, "space wasting factor %.9g > zeta %g", rho, p.zeta);
                /* tan(theta) < zeta: squares */
                if (t < p.zeta)
                    SK_CHECK_MSG(fabs(W - H) <= 2e-4 * W, "tan(theta) < zeta but row %gx%g is not square", W, H);
            }
            prev_y1 = ry1;
            row_start = row_end + 1;
        }
        SK_CHECK_MSG(prev_y1 >= Ld * (1.0 - 1e-5), "rows end at %.9g < L = %.9g", prev_y1, Ld);
        SK_CHECK_MSG(fabs(out[0].y0) <= 1e-6 * Ld, "first row starts at %.9g, not 0", out[0].y0);
    }

    /* union of rects covers the trapezoid */
    {
        int iy, ix, missed = 0;
        double mx = 0, my = 0;
        for (iy = 0; iy <= 40; iy++) {
            double y = (double)L * iy / 40.0;
            double hw = (double)n / 2 + y * t;
            for (ix = 0; ix <= 20; ix++) {
                double x = -hw + 2.0 * hw * ix / 20.0;
                double tol = 1e-4 * (hw + (double)L);
                int inside = 0;
                for (k = 0; k < got && !inside; k++)
                    inside = x >= out[k].x0 - tol && x <= out[k].x1 + tol && y >= out[k].y0 - tol && y <= out[k].y1 + tol;
                if (!inside) { missed++; mx = x; my = y; }
            }
        }
        SK_CHECK_MSG(missed == 0, "n=%g L=%g theta=%g: %d trapezoid points in no rect, e.g. (%.9g, %.9g)",
                     n, L, theta, missed, mx, my);
    }
}

/* ------------------------------------------------------------ default params */
static void test_default_params(void) {
    sk_lspsm_params p = sk_lspsm_default_params();
    SK_CHECK(p.zeta == 0.25f);
    SK_CHECK(p.sigma == 0.5f);
    SK_CHECK(p.h_max == 4);
    SK_CHECK(p.nw_max == 2);
}

/* ---------------------------------------------------------------- partition */
static void test_partition_theta0_squares(void) {
    sk_lspsm_params p = sk_lspsm_default_params();
    sk_rect out[16];
    int c, k;
    /* theta = 0: W = H = n; 3 unit squares reach L = 2.5 (the last past L) */
    check_partition_case(1.0f, 2.5f, 0.0f, p, 3);
    c = sk_lspsm_partition(1.0f, 2.5f, 0.0f, &p, out, 16);
    SK_CHECK(c == 3);
    for (k = 0; k < c && k < 16; k++) {
        SK_CHECK_NEAR(out[k].x0, -0.5, 1e-6);
        SK_CHECK_NEAR(out[k].x1, 0.5, 1e-6);
        SK_CHECK_NEAR(out[k].y0, (double)k, 1e-6);
        SK_CHECK_NEAR(out[k].y1, (double)k + 1.0, 1e-6);
    }
    /* 4 squares do not reach L = 10: the 4th row is stretched to [3, 10], width n */
    check_partition_case(1.0f, 10.0f, 0.0f, p, 4);
    c = sk_lspsm_partition(1.0f, 10.0f, 0.0f, &p, out, 16);
    SK_CHECK(c == 4);
    if (c == 4) {
        SK_CHECK_NEAR(out[3].y0, 3.0, 1e-6);
        SK_CHECK_NEAR(out[3].y1, 10.0, 1e-5);
        SK_CHECK_NEAR(out[3].x1 - out[3].x0, 1.0, 1e-6);
    }
    /* theta = 0 with a wide near base: W/H = 1, never split */
    check_partition_case(7.0f, 20.0f, 0.0f, p, 3);
}

static void test_partition_small_theta(void) {
    sk_lspsm_params p = sk_lspsm_default_params();
    sk_rect out[16];
    int c;
    /* tan(0.1) = 0.1003 < zeta: squares growing by 1/(1-2t) = 1.2510;
       H1 = 2.502, H2 = 3.130: two rows reach L = 5 */
    check_partition_case(2.0f, 5.0f, 0.1f, p, 2);
    c = sk_lspsm_partition(2.0f, 5.0f, 0.1f, &p, out, 16);
    SK_CHECK(c == 2);
    if (c == 2) {
        double a = 1.0 / (1.0 - 2.0 * tan(0.1f));
        SK_CHECK_NEAR(out[0].x1 - out[0].x0, 2.0 * a, 1e-4);
        SK_CHECK_NEAR(out[0].y1, 2.0 * a, 1e-4);
        SK_CHECK_NEAR(out[1].x1 - out[1].x0, 2.0 * a * a, 1e-4);
        SK_CHECK_NEAR(out[1].y1, 2.0 * a + 2.0 * a * a, 1e-4);
    }
    /* more rows, stretched */
    check_partition_case(1.0f, 40.0f, 0.2f, p, 4);
    check_partition_case(1.0f, 3.0f, 0.05f, p, 3);
}

static void test_partition_large_theta(void) {
    sk_lspsm_params p = sk_lspsm_default_params();
    sk_lspsm_params p10 = mkparams(0.25f, 0.5f, 4, 10);
    sk_lspsm_params p6 = mkparams(0.1f, 0.3f, 6, 3);
    sk_rect out[64];
    int c;
    /* tan(0.6) = 0.684 > zeta: W = n 2^i, H = W zeta/t: 0.731, 1.462, 2.923 (sum 5.12),
       the 4th stretched to [5.117, 20] with width 1 + 40 t = 28.37; every row has
       W/H > 1.5 and is split in nw_max = 2 columns: 8 rects */
    check_partition_case(1.0f, 20.0f, 0.6f, p, 8);
    c = sk_lspsm_partition(1.0f, 20.0f, 0.6f, &p, out, 64);
    SK_CHECK(c == 8);
    if (c == 8) {
        double t = tan(0.6f);
        SK_CHECK_NEAR(out[0].x0, -1.0, 1e-5);
        SK_CHECK_NEAR(out[0].x1, 0.0, 1e-5);
        SK_CHECK_NEAR(out[1].x1, 1.0, 1e-5);
        SK_CHECK_NEAR(out[0].y1, 2.0 * 0.25 / t, 1e-5);
        SK_CHECK_NEAR(out[6].y0, (2.0 + 4.0 + 8.0) * 0.25 / t, 1e-4);
        SK_CHECK_NEAR(out[6].y1, 20.0, 1e-4);
        SK_CHECK_NEAR(out[7].x1, (1.0 + 40.0 * t) / 2.0, 1e-3);
    }
    /* tan(1.2) = 2.572: W/H = t/zeta = 10.29, N_w = ceil(10.29/1.5) = 7 when allowed */
    check_partition_case(1.0f, 1.0f, 1.2f, p10, 0);
    c = sk_lspsm_partition(1.0f, 1.0f, 1.2f, &p10, out, 64);
    SK_CHECK(c > 0 && c % 7 == 0);
    /* the same with nw_max = 2 */
    check_partition_case(1.0f, 1.0f, 1.2f, p, 0);
    /* other params */
    check_partition_case(3.0f, 500.0f, 0.7f, p6, 0);
    check_partition_case(3.0f, 2.0f, 0.7f, p6, 0);
    check_partition_case(0.5f, 30.0f, 0.45f, mkparams(0.4f, 0.2f, 8, 4), 0);
    check_partition_case(0.5f, 30.0f, 0.45f, mkparams(0.4f, 0.2f, 1, 1), 1);
    check_partition_case(2.0f, 30.0f, 1.0f, mkparams(0.3f, 2.0f, 1, 5), 0);
}

static void test_partition_tan_equals_zeta(void) {
    /* at tan(theta) == zeta both cases of Eq. (1) give W = H = n/(1-2 zeta)^i */
    sk_lspsm_params p = sk_lspsm_default_params();
    float th = (float)atan(0.25);
    sk_rect out[16];
    int c;
    check_partition_case(1.0f, 10.0f, th, p, 3);
    c = sk_lspsm_partition(1.0f, 10.0f, th, &p, out, 16);
    SK_CHECK(c == 3);
    if (c == 3) {
        SK_CHECK_NEAR(out[0].y1, 2.0, 1e-4);
        SK_CHECK_NEAR(out[1].y1, 6.0, 1e-4);
        SK_CHECK_NEAR(out[2].y1, 14.0, 1e-4);
        SK_CHECK_NEAR(out[2].x1 - out[2].x0, 8.0, 1e-4);
    }
    /* just either side */
    check_partition_case(1.0f, 10.0f, nextafterf(th, 0.0f), p, 3);
    check_partition_case(1.0f, 10.0f, nextafterf(th, 1.0f), p, 3);
}

static void test_partition_extremes(void) {
    sk_lspsm_params p = sk_lspsm_default_params();
    sk_rect out[64];
    int c, k;
    float below_half_pi = nextafterf((float)(T_PI / 2), 0.0f);
    if ((double)below_half_pi >= T_PI / 2) below_half_pi = nextafterf(below_half_pi, 0.0f);
    /* theta near pi/2 */
    check_partition_case(1.0f, 10.0f, 1.57f, p, 8);
    check_partition_case(1.0f, 10.0f, 1.5f, p, 8);
    /* the largest float below pi/2: tan = 8.7e6, still finite */
    c = sk_lspsm_partition(1.0f, 10.0f, below_half_pi, &p, out, 64);
    SK_CHECK_MSG(c > 0, "theta = %.9g (< pi/2) rejected: %d", below_half_pi, c);
    for (k = 0; k < c && k < 64; k++) SK_CHECK(finite_rect(out[k]) && out[k].x0 < out[k].x1 && out[k].y0 < out[k].y1);
    check_partition_case(1.0f, 10.0f, below_half_pi, p, 0);
    /* n -> 0 */
    check_partition_case(1e-6f, 1.0f, 0.5f, p, 7);
    check_partition_case(1e-6f, 1.0f, 0.0f, p, 4);
    check_partition_case(1e-6f, 1e-6f, 0.5f, p, 0);
    check_partition_case(1e-6f, 1000.0f, 1.3f, p, 0);
    /* tiny L: one row reaching far past L */
    check_partition_case(1.0f, 1e-6f, 0.3f, p, 1);   /* W/H = t/zeta = 1.24: no split */
    check_partition_case(1.0f, 1e-6f, 0.0f, p, 1);
    /* huge L */
    check_partition_case(1.0f, 1e6f, 0.3f, p, 0);
    check_partition_case(1.0f, 1e20f, 0.3f, p, 4);
    check_partition_case(1.0f, 1e20f, 1.5f, p, 8);
    check_partition_case(1e-3f, 1e30f, 0.0f, p, 4);
    /* overflow of the trapezoid's width in float: an error or a result without NaN */
    memset(out, 0, sizeof out);
    c = sk_lspsm_partition(1.0f, 3e38f, 1.5f, &p, out, 64);
    SK_CHECK_MSG(c != 0, "count 0");
    for (k = 0; k < c && k < 64; k++) SK_CHECK_MSG(!nan_rect(out[k]), "NaN in rect %d for L = 3e38", k);
    memset(out, 0, sizeof out);
    c = sk_lspsm_partition(3e38f, 3e38f, 1.5f, &p, out, 64);
    SK_CHECK_MSG(c != 0, "count 0");
    for (k = 0; k < c && k < 64; k++) SK_CHECK_MSG(!nan_rect(out[k]), "NaN in rect %d for n = L = 3e38", k);
}

static void test_partition_paper_count(void) {
    /* Sec. 4.1: with zeta 0.25, sigma 0.5, h_max 4, nw_max 2 at most 8 passes;
       theta mostly in [25, 30] degrees */
    sk_lspsm_params p = sk_lspsm_default_params();
    sk_rect out[64];
    int ideg, il, worst = 0, bad = 0;
    for (ideg = 0; ideg <= 10; ideg++) {
        float th = (float)((25.0 + 0.5 * ideg) * T_PI / 180.0);
        for (il = 0; il < 12; il++) {
            float L = (float)pow(10.0, -0.5 + 0.3 * il);   /* L/n from 0.3 to 1000 */
            int c = sk_lspsm_partition(1.0f, L, th, &p, out, 64);
            if (c < 1 || c > 8) bad++;
            if (c > worst) worst = c;
        }
    }
    SK_CHECK_MSG(bad == 0, "%d cases outside [1, 8] partitions (worst %d)", bad, worst);
    check_partition_case(1.0f, 3.0f, (float)(27.0 * T_PI / 180.0), p, 0);
    check_partition_case(2.0f, 60.0f, (float)(28.0 * T_PI / 180.0), p, 7);   /* stretched row W/H = 1.40: one column */
}

static void test_partition_capacity(void) {
    sk_lspsm_params p = sk_lspsm_default_params();
    sk_rect out[16];
    int k, c;
    /* 8 partitions (see test_partition_large_theta) into 7 slots + guard */
    for (k = 0; k < 16; k++) { out[k].x0 = out[k].y0 = out[k].x1 = out[k].y1 = 12345.0f; }
    c = sk_lspsm_partition(1.0f, 20.0f, 0.6f, &p, out, 7);
    SK_CHECK_MSG(c == -(int)SK_ERR_CAPACITY, "got %d", c);
    for (k = 7; k < 16; k++) SK_CHECK_MSG(out[k].x0 == 12345.0f && out[k].y1 == 12345.0f, "wrote past cap at %d", k);
    /* exactly enough */
    c = sk_lspsm_partition(1.0f, 20.0f, 0.6f, &p, out, 8);
    SK_CHECK(c == 8);
    SK_CHECK(out[8].x0 == 12345.0f);
    /* cap 1 */
    for (k = 0; k < 16; k++) { out[k].x0 = out[k].y0 = out[k].x1 = out[k].y1 = 12345.0f; }
    c = sk_lspsm_partition(1.0f, 20.0f, 0.6f, &p, out, 1);
    SK_CHECK(c == -(int)SK_ERR_CAPACITY);
    SK_CHECK(out[1].x0 == 12345.0f);
    /* cap 0 or negative: an error, nothing written */
    c = sk_lspsm_partition(1.0f, 20.0f, 0.6f, &p, out, 0);
    SK_CHECK_MSG(c == -(int)SK_ERR_CAPACITY || c == -(int)SK_ERR_INVALID_ARG, "cap 0: %d", c);
    SK_CHECK(out[0].x0 == 12345.0f);
    c = sk_lspsm_partition(1.0f, 20.0f, 0.6f, &p, out, -5);
    SK_CHECK_MSG(c == -(int)SK_ERR_CAPACITY || c == -(int)SK_ERR_INVALID_ARG, "cap -5: %d", c);
    SK_CHECK(out[0].x0 == 12345.0f);
    /* enormous h_max and nw_max: must return CAPACITY promptly, no overflow */
    {
        sk_lspsm_params big = mkparams(0.25f, 0.5f, INT_MAX, INT_MAX);
        c = sk_lspsm_partition(1.0f, 1e30f, 0.0f, &big, out, 16);
        SK_CHECK_MSG(c == -(int)SK_ERR_CAPACITY, "h_max INT_MAX, theta 0: %d", c);
        c = sk_lspsm_partition(1.0f, 1e30f, 1.5f, &big, out, 16);
        SK_CHECK_MSG(c == -(int)SK_ERR_CAPACITY, "h_max = nw_max = INT_MAX: %d", c);
        c = sk_lspsm_partition(1e-6f, 1.0f, 1.5707f, &big, out, 16);
        SK_CHECK_MSG(c == -(int)SK_ERR_CAPACITY, "h_max = nw_max = INT_MAX, theta ~ pi/2: %d", c);
    }
}

static void test_partition_bad_input(void) {
    sk_lspsm_params p = sk_lspsm_default_params();
    sk_rect out[16];
    const float half_pi_f = (float)(T_PI / 2);
    int k, c, i;
    struct { float n, L, theta; } bad[] = {
        { 1.0f, 10.0f, -0.1f }, { 1.0f, 10.0f, -1e-30f }, { 1.0f, 10.0f, 1.5707964f }, { 1.0f, 10.0f, 2.0f },
        { 1.0f, 10.0f, 3.0f }, { 1.0f, 10.0f, 4.0f },
        { 0.0f, 10.0f, 0.5f }, { -1.0f, 10.0f, 0.5f }, { 1.0f, 0.0f, 0.5f }, { 1.0f, -3.0f, 0.5f },
        { NAN, 10.0f, 0.5f }, { 1.0f, NAN, 0.5f }, { 1.0f, 10.0f, NAN },
        { INFINITY, 10.0f, 0.5f }, { 1.0f, INFINITY, 0.5f }, { 1.0f, 10.0f, INFINITY },
        { -INFINITY, 10.0f, 0.5f }, { 1.0f, -INFINITY, 0.5f }, { 1.0f, 10.0f, -INFINITY }
    };
    for (i = 0; i < (int)(sizeof bad / sizeof bad[0]); i++) {
        for (k = 0; k < 16; k++) { out[k].x0 = out[k].y0 = out[k].x1 = out[k].y1 = 777.0f; }
        c = sk_lspsm_partition(bad[i].n, bad[i].L, bad[i].theta, &p, out, 16);
        SK_CHECK_MSG(c == -(int)SK_ERR_INVALID_ARG, "case %d (n=%g L=%g theta=%.9g): got %d", i,
                     bad[i].n, bad[i].L, bad[i].theta, c);
        for (k = 0; k < 16; k++) SK_CHECK_MSG(out[k].x0 == 777.0f && out[k].y1 == 777.0f, "case %d wrote rect %d", i, k);
    }
    /* theta == (float)(pi/2) rounds above pi/2 */
    c = sk_lspsm_partition(1.0f, 10.0f, half_pi_f, &p, out, 16);
    SK_CHECK_MSG(c == -(int)SK_ERR_INVALID_ARG, "theta = (float)(pi/2): %d", c);
    /* bad params */
    {
        sk_lspsm_params bp[14];
        bp[0] = mkparams(0.0f, 0.5f, 4, 2);
        bp[1] = mkparams(0.5f, 0.5f, 4, 2);
        bp[2] = mkparams(-0.1f, 0.5f, 4, 2);
        bp[3] = mkparams(0.7f, 0.5f, 4, 2);
        bp[4] = mkparams(NAN, 0.5f, 4, 2);
        bp[5] = mkparams(0.25f, 0.0f, 4, 2);
        bp[6] = mkparams(0.25f, -1.0f, 4, 2);
        bp[7] = mkparams(0.25f, NAN, 4, 2);
        bp[8] = mkparams(0.25f, 0.5f, 0, 2);
        bp[9] = mkparams(0.25f, 0.5f, -3, 2);
        bp[10] = mkparams(0.25f, 0.5f, 4, 0);
        bp[11] = mkparams(0.25f, 0.5f, 4, -1);
        bp[12] = mkparams(INFINITY, 0.5f, 4, 2);
        bp[13] = mkparams(0.25f, INFINITY, 4, 2);
        for (i = 0; i < 14; i++) {
            for (k = 0; k < 16; k++) { out[k].x0 = out[k].y0 = out[k].x1 = out[k].y1 = 777.0f; }
            c = sk_lspsm_partition(1.0f, 10.0f, 0.5f, &bp[i], out, 16);
            SK_CHECK_MSG(c == -(int)SK_ERR_INVALID_ARG, "params %d (zeta %g sigma %g h %d nw %d): got %d", i,
                         bp[i].zeta, bp[i].sigma, bp[i].h_max, bp[i].nw_max, c);
            for (k = 0; k < 16; k++) SK_CHECK_MSG(out[k].x0 == 777.0f, "params %d wrote rect %d", i, k);
        }
    }
    /* NULL */
    c = sk_lspsm_partition(1.0f, 10.0f, 0.5f, NULL, out, 16);
    SK_CHECK(c == -(int)SK_ERR_INVALID_ARG);
    c = sk_lspsm_partition(1.0f, 10.0f, 0.5f, &p, NULL, 16);
    SK_CHECK(c == -(int)SK_ERR_INVALID_ARG);
}

/* ------------------------------------------------------ region: the oracle */
static cam make_cam(dv3 eye, dv3 target, dv3 up_hint, double fovy, double aspect, double zn, double zf) {
    cam c = cam_frame(eye, target, up_hint, fovy, aspect, zn, zf);
    int i;
    {
        sk_mat4 proj = sk_mat4_perspective((float)fovy, (float)aspect, (float)zn, (float)zf);
        sk_mat4 view = sk_mat4_look_at(tof(eye), tof(target), tof(up_hint));
        c.f = sk_frustum_from_matrix(sk_mat4_mul(proj, view));
    }
    if (zf / zn > 1e4) {
        /* a float projection matrix cannot carry far/near this large (its m[10]
           rounds): hand the library this file's own frustum instead */
        for (i = 0; i < 8; i++) c.f.corners[i] = tof(c.corners[i]);
        for (i = 0; i < 6; i++) { c.f.planes[i].n = tof(c.planes[i].n); c.f.planes[i].d = (float)c.planes[i].d; }
        return c;
    }
    /* cross-check the core-math frustum against this file's (core math, not LSPSM) */
    {
        double worst = 0;
        for (i = 0; i < 8; i++) {
            double e = dlen(dsub(tod(c.f.corners[i]), c.corners[i])) / (1.0 + dlen(dsub(c.corners[i], eye)));
            if (!(e <= worst)) worst = e;
        }
        SK_CHECK_MSG(worst < 1e-4, "sk_frustum_from_matrix corners differ from the camera's (rel %g): core math", worst);
    }
    return c;
}

/* Minimum area L*(n + L*t) of an isosceles trapezoid with axis along y that
   encloses the 2D points (x, y); the axis offset is optimal in closed form
   for each t, t = tan(theta) searched on a grid then refined. */
static double trap_area_for(const double *xs, const double *ys, int np, double y0, double L, double t) {
    double a = -1e300, b = -1e300, nn;
    int i;
    for (i = 0; i < np; i++) {
        double s = (ys[i] - y0) * t;
        if (xs[i] - s > a) a = xs[i] - s;
        if (-xs[i] - s > b) b = -xs[i] - s;
    }
    nn = a + b;
    if (nn < 0) nn = 0;
    return L * (nn + L * t);
}
static double min_trap_area(const double *xs, const double *ys, int np) {
    double y0 = 1e300, y1 = -1e300, L, best = 1e300, bt = 0, lo, hi;
    int i, k, bk = 0;
    const int N = 4000;
    for (i = 0; i < np; i++) { if (ys[i] < y0) y0 = ys[i]; if (ys[i] > y1) y1 = ys[i]; }
    L = y1 - y0;
    for (k = 0; k <= N; k++) {
        double t = tan((T_PI / 2 - 1e-4) * k / N);
        double a = trap_area_for(xs, ys, np, y0, L, t);
        if (a < best) { best = a; bt = t; bk = k; }
    }
    lo = tan((T_PI / 2 - 1e-4) * (bk > 0 ? bk - 1 : 0) / N);
    hi = tan((T_PI / 2 - 1e-4) * (bk < N ? bk + 1 : N) / N);
    for (k = 0; k < 200; k++) {   /* area is convex in t: ternary search */
        double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
        if (trap_area_for(xs, ys, np, y0, L, m1) < trap_area_for(xs, ys, np, y0, L, m2)) hi = m2; else lo = m1;
    }
    bt = (lo + hi) / 2;
    {
        double a = trap_area_for(xs, ys, np, y0, L, bt);
        if (a < best) best = a;
    }
    return best;
}

#define MAXB 256
typedef struct scene_case {
    const char *name;
    dv3 eye, target, up;
    sk_aabb receivers;
    int has_casters;
    sk_aabb casters;
    dv3 light;
    double zn;
} scene_case;

static int region_body(const scene_case *sc, cam *c, dv3 *body) {
    *c = make_cam(sc->eye, sc->target, sc->up, 60.0 * T_PI / 180.0, 1.33, sc->zn, 60.0);
    return clip_body(c, sc->receivers, body, MAXB);
}

/* Checks a non-fallback region against the oracle; returns 1 if the region is usable. */
static int check_region(const scene_case *sc, const sk_lspsm_region *r, const dv3 *body, int nb) {
    double xs[MAXB], ys[MAXB];
    dv3 l = dnorm(tod(tof(sc->light))), v = dnorm(dsub(sc->target, sc->eye));
    dv3 r0 = mat_row(&r->light_view, 0), r1 = mat_row(&r->light_view, 1), r2 = mat_row(&r->light_view, 2);
    dv3 axis = dnorm(dsub(v, dmul(l, ddot(v, l))));
    double t = tan((double)r->theta), far_w, scale, area, amin, zlo = 1e300, zhi = -1e300;
    int i, out_count = 0, worst_i = -1;
    double worst = 0;
    SK_CHECK_MSG(all_finite_mat(&r->light_view), "%s: light_view not finite", sc->name);
    SK_CHECK_MSG(finite_d(r->origin.x) && finite_d(r->origin.y) && finite_d(r->n) && finite_d(r->L) &&
                 finite_d(r->theta) && finite_d(r->zmin) && finite_d(r->zmax), "%s: region not finite", sc->name);
    SK_CHECK_MSG(r->n > 0 && r->L > 0 && r->theta >= 0 && (double)r->theta < T_PI / 2 && r->zmin <= r->zmax,
                 "%s: n %g L %g theta %g z [%g, %g]", sc->name, r->n, r->L, r->theta, r->zmin, r->zmax);
    /* the frame: orthonormal, right-handed, z towards the light, y = projected view direction */
    SK_CHECK_MSG(fabs(dlen(r0) - 1) < 1e-4 && fabs(dlen(r1) - 1) < 1e-4 && fabs(dlen(r2) - 1) < 1e-4 &&
                 fabs(ddot(r0, r1)) < 1e-4 && fabs(ddot(r1, r2)) < 1e-4 && fabs(ddot(r0, r2)) < 1e-4,
                 "%s: light_view rotation not orthonormal", sc->name);
    SK_CHECK_MSG(ddot(dcross(r0, r1), r2) > 0, "%s: light_view not right-handed", sc->name);
    SK_CHECK_MSG(ddot(r2, l) < -1 + 1e-5, "%s: light_view z is not towards the light (dot %g)", sc->name, ddot(r2, l));
    SK_CHECK_MSG(fabs(ddot(r1, l)) < 1e-5, "%s: trapezoid axis not perpendicular to the light (%g)", sc->name, ddot(r1, l));
    SK_CHECK_MSG(ddot(r1, axis) > 1 - 1e-5, "%s: trapezoid axis not the projected view direction (dot %.9g)",
                 sc->name, ddot(r1, axis));
    if (r->n <= 0 || r->L <= 0) return 0;
    far_w = (double)r->n + 2.0 * r->L * t;
    SK_CHECK_MSG(r->n >= 1e-4 * far_w * (1 - 1e-3), "%s: n %g < 1e-4 of the far base %g", sc->name, r->n, far_w);
    scale = (double)r->L + far_w;
    /* containment */
    for (i = 0; i < nb; i++) {
        double q[4], X, Y, ex;
        xform(&r->light_view, body[i], q);
        xs[i] = q[0]; ys[i] = q[1];
        if (q[2] < zlo) zlo = q[2];
        if (q[2] > zhi) zhi = q[2];
        X = q[0] - r->origin.x; Y = q[1] - r->origin.y;
        ex = 0;
        if (-Y > ex) ex = -Y;
        if (Y - r->L > ex) ex = Y - r->L;
        if (fabs(X) - (r->n / 2.0 + Y * t) > ex) ex = fabs(X) - (r->n / 2.0 + Y * t);
        if (ex > 1e-4 * scale) { out_count++; if (ex > worst) { worst = ex; worst_i = i; } }
    }
    SK_CHECK_MSG(out_count == 0, "%s: %d of %d body points outside the trapezoid (worst by %g, point %d)",
                 sc->name, out_count, nb, worst, worst_i);
    /* depth range holds the body and the casters */
    SK_CHECK_MSG(r->zmin <= zlo + 1e-4 * scale && r->zmax >= zhi - 1e-4 * scale,
                 "%s: z range [%g, %g] misses body z [%g, %g]", sc->name, r->zmin, r->zmax, zlo, zhi);
    if (sc->has_casters) {
        int k;
        for (k = 0; k < 8; k++) {
            dv3 p = dv((k & 1) ? sc->casters.max.x : sc->casters.min.x, (k & 2) ? sc->casters.max.y : sc->casters.min.y,
                       (k & 4) ? sc->casters.max.z : sc->casters.min.z);
            double q[4];
            xform(&r->light_view, p, q);
            SK_CHECK_MSG(q[2] >= r->zmin - 1e-4 * scale && q[2] <= r->zmax + 1e-4 * scale,
                         "%s: caster corner %d z %g outside [%g, %g]", sc->name, k, q[2], r->zmin, r->zmax);
        }
    }
    /* minimality: within 1% of the brute-force minimum */
    area = (double)r->L * ((double)r->n + (double)r->L * t);
    amin = min_trap_area(xs, ys, nb);
    /* the documented floor n >= 1e-2 of the far base may widen the optimum
       by at most L * n_floor */
    SK_CHECK_MSG(area <= amin * 1.01 + (double)r->L * 1.01e-2 * ((double)r->n + 2.0 * r->L * t) &&
                 area >= amin * (1 - 1e-3), "%s: area %.9g, brute-force minimum %.9g (ratio %.5f)",
                 sc->name, area, amin, area / amin);
    return 1;
}

/* crops for a region: count and rects match the partition, corners map to
   the NDC square, every body point is in some crop */
static void check_crops(const char *name, const sk_lspsm_region *r, const sk_lspsm_params *p,
                        const dv3 *body, int nb, int expect_fallback_one) {
    sk_mat4 vp[64];
    sk_rect rects[64], prect[64];
    int c, pc, k, i, missed = 0;
    double scale = (double)r->L + (double)r->n + 2.0 * r->L * tan((double)r->theta);
    c = sk_lspsm_crops(r, p, vp, rects, 64);
    if (expect_fallback_one) {
        SK_CHECK_MSG(c == 1, "%s: fallback region gave %d crops", name, c);
    } else {
        pc = sk_lspsm_partition(r->n, r->L, r->theta, p, prect, 64);
        SK_CHECK_MSG(c == pc && c > 0, "%s: %d crops, sk_lspsm_partition gives %d", name, c, pc);
        for (k = 0; k < c && k < pc; k++) {
            double tol = 2e-4 * scale;
            SK_CHECK_MSG(fabs(rects[k].x0 - (prect[k].x0 + r->origin.x)) <= tol &&
                         fabs(rects[k].x1 - (prect[k].x1 + r->origin.x)) <= tol &&
                         fabs(rects[k].y0 - (prect[k].y0 + r->origin.y)) <= tol &&
                         fabs(rects[k].y1 - (prect[k].y1 + r->origin.y)) <= tol,
                         "%s: crop rect %d is not the partition rect moved to the origin", name, k);
        }
    }
    if (c <= 0) return;
    if (c > 64) c = 64;
    for (k = 0; k < c; k++) {
        int zi, ci;
        /* NDC tolerance: 1e-3, plus what float coordinates of this size can
           resolve across a partition this small (the near rows of an n -> 0
           trapezoid are sub-millimetre partitions tens of units from the
           light-view origin) */
        double big = fabs(rects[k].x0), ext = rects[k].x1 - rects[k].x0, ntol;
        if (fabs(rects[k].x1) > big) big = fabs(rects[k].x1);
        if (fabs(rects[k].y0) > big) big = fabs(rects[k].y0);
        if (fabs(rects[k].y1) > big) big = fabs(rects[k].y1);
        for (ci = 12; ci < 15; ci++) if (fabs(r->light_view.m[ci]) > big) big = fabs(r->light_view.m[ci]);
        if (rects[k].y1 - rects[k].y0 < ext) ext = rects[k].y1 - rects[k].y0;
        ntol = 1e-3 + 16.0 * FLT_EPSILON * big / (ext > 0 ? ext : 1e-30);
        SK_CHECK_MSG(all_finite_mat(&vp[k]) && finite_rect(rects[k]), "%s: crop %d not finite", name, k);
        for (zi = 0; zi < 3; zi++) {
            double z = zi == 0 ? r->zmin : zi == 1 ? r->zmax : 0.5 * ((double)r->zmin + r->zmax);
            for (ci = 0; ci < 4; ci++) {
                double x = (ci & 1) ? rects[k].x1 : rects[k].x0, y = (ci & 2) ? rects[k].y1 : rects[k].y0;
                dv3 w = view_unproject(&r->light_view, dv(x, y, z));
                double q[4], nx, ny, nz;
                xform(&vp[k], w, q);
                nx = q[0] / q[3]; ny = q[1] / q[3]; nz = q[2] / q[3];
                SK_CHECK_MSG(q[3] > 0 && fabs(nx - ((ci & 1) ? 1.0 : -1.0)) < ntol && fabs(ny - ((ci & 2) ? 1.0 : -1.0)) < ntol &&
                             nz >= -1 - 1e-3 && nz <= 1 + 1e-3,
                             "%s: crop %d corner %d at z %g maps to (%g, %g, %g, w %g), tol %g", name, k, ci, z, nx, ny, nz,
                             q[3], ntol);
            }
        }
    }
    for (i = 0; i < nb; i++) {
        int found = 0;
        for (k = 0; k < c && !found; k++) {
            double q[4];
            xform(&vp[k], body[i], q);
            found = q[3] > 0 && fabs(q[0]) <= q[3] * (1 + 1e-3) && fabs(q[1]) <= q[3] * (1 + 1e-3) &&
                    fabs(q[2]) <= q[3] * (1 + 1e-3);
        }
        if (!found) missed++;
    }
    SK_CHECK_MSG(missed == 0, "%s: %d of %d body points in no crop", name, missed, nb);
    /* out_rects may be NULL */
    {
        sk_mat4 vp2[64];
        int c2 = sk_lspsm_crops(r, p, vp2, NULL, 64);
        SK_CHECK_MSG(c2 == c, "%s: out_rects NULL gives %d, not %d", name, c2, c);
    }
}

static scene_case mkscene(const char *name, dv3 eye, dv3 target, dv3 up, sk_aabb rec, dv3 light) {
    scene_case s;
    s.name = name; s.eye = eye; s.target = target; s.up = up; s.receivers = rec;
    s.has_casters = 0; s.casters = rec; s.light = light; s.zn = 0.5;
    return s;
}

static void test_region_and_crops_general(void) {
    sk_aabb ground = box3(-50, -1, -50, 50, 0, 50);
    scene_case cases[10];
    int nc = 0, i;
    sk_lspsm_params pdef = sk_lspsm_default_params(), pother = mkparams(0.1f, 0.3f, 6, 3);
    cases[nc++] = mkscene("oblique", dv(0, 5, 10), dv(0, 0, -10), dv(0, 1, 0), ground, dv(0.4, -1, -0.3));
    cases[nc++] = mkscene("low sun from the side", dv(0, 5, 10), dv(0, 0, -10), dv(0, 1, 0), ground, dv(1, -0.2, 0.1));
    cases[nc++] = mkscene("light towards camera", dv(3, 4, 0), dv(-5, 1, -20), dv(0, 1, 0), ground, dv(0.2, -1, 1));
    cases[nc++] = mkscene("straight down, camera tilted", dv(0, 8, 0), dv(10, 0, -20), dv(0, 1, 0), ground, dv(0, -1, 0));
    cases[nc++] = mkscene("view nearly along the light", dv(0, 30, 0), dv(0.3, 0, -1), dv(0, 0, -1), ground, dv(0, -1, 0));
    cases[nc] = mkscene("with casters", dv(0, 5, 10), dv(0, 0, -10), dv(0, 1, 0), ground, dv(0.3, -1, -0.2));
    cases[nc].has_casters = 1;
    cases[nc].casters = box3(-3, 8, -12, 3, 12, -6);
    nc++;
    cases[nc++] = mkscene("camera inside the receivers", dv(0, 1, 0), dv(0, 0.5, -10), dv(0, 1, 0),
                          box3(-40, -1, -40, 40, 3, 40), dv(0.5, -1, 0.2));
    /* n -> 0: a near plane of 1e-4 inside the receivers, the trapezoid is nearly a triangle */
    cases[nc] = mkscene("tiny near plane", dv(0, 1, 0), dv(0, 0.2, -10), dv(0, 1, 0), box3(-40, -1, -40, 40, 3, 40),
                        dv(0, -1, 0));
    cases[nc++].zn = 1e-4;
    cases[nc] = mkscene("whole frustum, tiny near plane", dv(0, 0, 0), dv(0, 0, -1), dv(0, 1, 0),
                        box3(-100, -100, -100, 100, 100, 100), dv(0, -1, 0));
    cases[nc++].zn = 1e-4;
    for (i = 0; i < nc; i++) {
        cam c;
        dv3 body[MAXB];
        int nb = region_body(&cases[i], &c, body);
        sk_lspsm_region r;
        sk_result res;
        SK_CHECK_MSG(nb >= 4, "%s: oracle body has %d points", cases[i].name, nb);
        memset(&r, 0, sizeof r);
        res = sk_lspsm_region_extract(&c.f, tof(c.fwd), cases[i].receivers,
                                      cases[i].has_casters ? &cases[i].casters : NULL, tof(cases[i].light), &r);
        SK_CHECK_MSG(res == SK_OK, "%s: %s", cases[i].name, sk_result_string(res));
        if (res != SK_OK) continue;
        SK_CHECK_MSG(r.fallback == 0, "%s: unexpected fallback", cases[i].name);
        if (r.fallback) continue;
        if (check_region(&cases[i], &r, body, nb)) {
            check_crops(cases[i].name, &r, &pdef, body, nb, 0);
            check_crops(cases[i].name, &r, &pother, body, nb, 0);
        }
    }
}

static void check_fallback(const char *name, dv3 eye, dv3 target, dv3 up, sk_aabb rec, dv3 light) {
    scene_case sc = mkscene(name, eye, target, up, rec, light);
    cam c;
    dv3 body[MAXB];
    int nb = region_body(&sc, &c, body);
    sk_lspsm_region r;
    sk_result res;
    sk_lspsm_params p = sk_lspsm_default_params();
    SK_CHECK_MSG(nb >= 4, "%s: oracle body has %d points", name, nb);
    memset(&r, 0, sizeof r);
    res = sk_lspsm_region_extract(&c.f, tof(c.fwd), rec, NULL, tof(light), &r);
    SK_CHECK_MSG(res == SK_OK, "%s: %s", name, sk_result_string(res));
    if (res != SK_OK) return;
    SK_CHECK_MSG(r.fallback == 1, "%s: fallback %d", name, r.fallback);
    SK_CHECK_MSG(all_finite_mat(&r.light_view) && finite_d(r.origin.x) && finite_d(r.origin.y) && finite_d(r.n) &&
                 finite_d(r.L) && finite_d(r.theta) && finite_d(r.zmin) && finite_d(r.zmax),
                 "%s: fallback region not finite", name);
    SK_CHECK_MSG(r.zmin <= r.zmax, "%s: z range [%g, %g]", name, r.zmin, r.zmax);
    {   /* still a light view: z towards the light */
        dv3 r2 = mat_row(&r.light_view, 2);
        SK_CHECK_MSG(ddot(r2, dnorm(tod(tof(light)))) < -1 + 1e-5, "%s: light_view z not towards the light", name);
    }
    if (r.fallback == 1) check_crops(name, &r, &p, body, nb, 1);
}

static void test_region_fallback(void) {
    sk_aabb ground = box3(-50, -1, -50, 50, 0, 50);
    sk_aabb ceiling = box3(-40, 10, -40, 40, 11, 40);
    /* view direction parallel to the light: looking straight down, sun overhead */
    check_fallback("parallel", dv(0, 20, 0), dv(0, 0, 0), dv(0, 0, -1), ground, dv(0, -1, 0));
    check_fallback("parallel, oblique", dv(20, 20, 20), dv(0, 0, 0), dv(0, 1, 0), box3(-60, -1, -60, 60, 0, 60),
                   dv(-1, -1, -1));
    /* anti-parallel: looking up at a ceiling lit from above */
    check_fallback("anti-parallel", dv(0, 0, 0), dv(0, 1, 0), dv(0, 0, -1), ceiling, dv(0, -1, 0));
}

static void test_region_errors(void) {
    sk_aabb ground = box3(-50, -1, -50, 50, 0, 50);
    scene_case sc = mkscene("miss", dv(0, 5, 0), dv(0, 10, 0), dv(0, 0, -1), ground, dv(0.3, -1, 0.1));
    cam c;
    dv3 body[MAXB];
    sk_lspsm_region r, sentinel;
    sk_result res;
    int nb = region_body(&sc, &c, body);
    SK_CHECK(nb == 0);
    /* frustum above the ground, looking up: misses the receivers */
    res = sk_lspsm_region_extract(&c.f, tof(c.fwd), ground, NULL, tof(sc.light), &r);
    SK_CHECK_MSG(res == SK_ERR_DEGENERATE, "miss: %s", sk_result_string(res));
    /* bad input: INVALID_ARG, out untouched */
    {
        scene_case g = mkscene("ok", dv(0, 5, 10), dv(0, 0, -10), dv(0, 1, 0), ground, dv(0.4, -1, -0.3));
        cam gc;
        sk_vec3 vd, ld = v3(0.4f, -1.0f, -0.3f);
        sk_frustum badf;
        sk_aabb badcast;
        int i;
        region_body(&g, &gc, body);
        vd = tof(gc.fwd);
        memset(&sentinel, 0x5a, sizeof sentinel);
        for (i = 0; i < 17; i++) {
            sk_vec3 v = vd, l = ld;
            sk_aabb rec = ground;
            const sk_frustum *fp = &gc.f;
            const sk_aabb *cp = NULL;
            sk_lspsm_region *op = &r;
            badf = gc.f;
            badcast = box3(-1, 5, -1, 1, 6, 1);
            switch (i) {
            case 0: fp = NULL; break;
            case 1: op = NULL; break;
            case 2: v = v3(0, 0, 0); break;
            case 3: v.x = NAN; break;
            case 4: v.y = INFINITY; break;
            case 5: l = v3(0, 0, 0); break;
            case 6: l.z = NAN; break;
            case 7: l.x = -INFINITY; break;
            case 8: rec.min.x = NAN; break;
            case 9: rec.max.y = INFINITY; break;
            case 10: rec.min.z = -INFINITY; break;
            case 11: rec.min.x = 60; break;                      /* min > max */
            case 12: badf.corners[3].y = NAN; fp = &badf; break;
            case 13: badf.planes[2].d = INFINITY; fp = &badf; break;
            case 14: badcast.max.x = NAN; cp = &badcast; break;
            case 15: badcast.min.y = -INFINITY; cp = &badcast; break;
            case 16: badcast.min.x = 5; cp = &badcast; break;   /* min > max */
            }
            memcpy(&r, &sentinel, sizeof r);
            res = sk_lspsm_region_extract(fp, v, rec, cp, l, op);
            SK_CHECK_MSG(res == SK_ERR_INVALID_ARG, "bad input %d: %s", i, sk_result_string(res));
            SK_CHECK_MSG(memcmp(&r, &sentinel, sizeof r) == 0, "bad input %d: out was written", i);
        }
        /* all-zero frustum (what sk_frustum_from_matrix returns for a singular matrix) */
        memset(&badf, 0, sizeof badf);
        res = sk_lspsm_region_extract(&badf, vd, ground, NULL, ld, &r);
        SK_CHECK_MSG(res != SK_OK, "all-zero frustum accepted");
    }
}

static void test_crops_bad_input(void) {
    sk_aabb ground = box3(-50, -1, -50, 50, 0, 50);
    scene_case g = mkscene("ok", dv(0, 5, 10), dv(0, 0, -10), dv(0, 1, 0), ground, dv(0.4, -1, -0.3));
    cam gc;
    dv3 body[MAXB];
    sk_lspsm_region r, br;
    sk_lspsm_params p = sk_lspsm_default_params(), bp = mkparams(0.0f, 0.5f, 4, 2);
    sk_mat4 vp[64];
    sk_rect rects[64];
    int c, full, k;
    region_body(&g, &gc, body);
    memset(&r, 0, sizeof r);
    if (sk_lspsm_region_extract(&gc.f, tof(gc.fwd), ground, NULL, v3(0.4f, -1.0f, -0.3f), &r) != SK_OK) {
        SK_CHECK_MSG(0, "region extraction failed; crop bad-input tests skipped");
        return;
    }
    full = sk_lspsm_crops(&r, &p, vp, rects, 64);
    SK_CHECK(full > 1);
    if (full <= 1) return;
    /* capacity: one short, guard untouched */
    for (k = 0; k < 64; k++) { vp[k].m[0] = 4242.0f; rects[k].x0 = 4242.0f; }
    c = sk_lspsm_crops(&r, &p, vp, rects, full - 1);
    SK_CHECK_MSG(c == -(int)SK_ERR_CAPACITY, "cap %d of %d: got %d", full - 1, full, c);
    for (k = full - 1; k < 64; k++) SK_CHECK_MSG(vp[k].m[0] == 4242.0f && rects[k].x0 == 4242.0f, "wrote past cap at %d", k);
    /* NULL */
    SK_CHECK(sk_lspsm_crops(NULL, &p, vp, rects, 64) == -(int)SK_ERR_INVALID_ARG);
    SK_CHECK(sk_lspsm_crops(&r, NULL, vp, rects, 64) == -(int)SK_ERR_INVALID_ARG);
    SK_CHECK(sk_lspsm_crops(&r, &p, NULL, rects, 64) == -(int)SK_ERR_INVALID_ARG);
    SK_CHECK(sk_lspsm_crops(&r, &bp, vp, rects, 64) == -(int)SK_ERR_INVALID_ARG);
    /* a corrupted region */
    for (k = 0; k < 9; k++) {
        br = r;
        switch (k) {
        case 0: br.n = NAN; break;
        case 1: br.L = -1.0f; break;
        case 2: br.theta = 2.0f; break;
        case 3: br.theta = -0.5f; break;
        case 4: br.n = 0.0f; break;
        case 5: br.zmin = NAN; break;
        case 6: br.zmax = INFINITY; break;
        case 7: br.light_view.m[5] = NAN; break;
        case 8: br.origin.y = -INFINITY; break;
        }
        vp[0].m[0] = 4242.0f;
        c = sk_lspsm_crops(&br, &p, vp, rects, 64);
        SK_CHECK_MSG(c == -(int)SK_ERR_INVALID_ARG, "corrupted region %d: got %d", k, c);
    }
}

SK_TEST_MAIN(test_default_params, test_partition_theta0_squares, test_partition_small_theta,
             test_partition_large_theta, test_partition_tan_equals_zeta, test_partition_extremes,
             test_partition_paper_count, test_partition_capacity, test_partition_bad_input,
             test_region_and_crops_general, test_region_fallback, test_region_errors, test_crops_bad_input)
