/* tests/test_pvsm.c - Predicted Virtual Soft Shadow Maps (Shen Li
   et al. 2011): perceptual rho(n), the appendix's parallelogram convolution,
   smooth texel-as-quad coverage (Sec. 4.1), resolution prediction
   (Eqs. 4-5), the V*A/A merge (Sec. 5.2), the SMTG min-pyramid and the
   kd-tree tiles (after Giegl & Wimmer).

   Every expected value is computed in this file in double precision from the
   seed's formulas, by hand, or by brute force; none is copied from the
   implementation's output. */
#define SHADOWKIT_IMPLEMENTATION
#include "shadowkit.h"
#include "tests/sk_test.h"
#include <float.h>
#include <limits.h>
#include <stdlib.h>

static sk_vec2 v2(float x, float y) { sk_vec2 r; r.x = x; r.y = y; return r; }

static unsigned rng_state = 2011u;
static double rnd(void) {
    rng_state = rng_state * 1664525u + 1013904223u;
    return (double)(rng_state >> 8) / 16777216.0;          /* [0,1) */
}
static double rnd_range(double a, double b) { return a + (b - a) * rnd(); }
static double dmax(double a, double b) { return a > b ? a : b; }
static double dmin(double a, double b) { return a < b ? a : b; }
static double rel_tol(double v, double r) { return r * dmax(1.0, fabs(v)); }

/* ================================================================ rho(n) */
/* the seed's cubic fits in x = log2(n) */
static double pd(double x) { return 0.667 + 0.7794 * x + 0.3967 * x * x - 0.02716 * x * x * x; }
static double ps(double x) { return 0.5477 + 1.406 * x - 0.04687 * x * x - 0.003944 * x * x * x; }
/* peaks: the positive roots of the derivatives, solved here */
static double peak_d(void) {   /* -3*0.02716 x^2 + 2*0.3967 x + 0.7794 = 0 */
    double a = 3 * 0.02716, b = 2 * 0.3967, c = 0.7794;
    return (b + sqrt(b * b + 4 * a * c)) / (2 * a);
}
static double peak_s(void) {   /* -3*0.003944 x^2 - 2*0.04687 x + 1.406 = 0 */
    double a = 3 * 0.003944, b = 2 * 0.04687, c = 1.406;
    return (-b + sqrt(b * b + 4 * a * c)) / (2 * a);
}
static double rho_ref(double n, int dynamic) {
    double x, pk = dynamic ? peak_d() : peak_s();
    if (!(n >= 1.0)) n = 1.0;                     /* NaN and n < 1 -> 1 */
    x = log2(n);                                  /* +Inf -> +Inf -> clamped */
    if (x > pk) x = pk;
    return dynamic ? pd(x) : ps(x);
}

static void test_rho_peaks(void) {
    /* sanity of this file's own algebra: the derivative vanishes at the peak,
       near the values the header quotes (10.64 and 7.64) */
    double xd = peak_d(), xs = peak_s();
    SK_CHECK_NEAR(xd, 10.64, 0.01);
    SK_CHECK_NEAR(xs, 7.64, 0.01);
    SK_CHECK_NEAR(0.7794 + 2 * 0.3967 * xd - 3 * 0.02716 * xd * xd, 0.0, 1e-12);
    SK_CHECK_NEAR(1.406 - 2 * 0.04687 * xs - 3 * 0.003944 * xs * xs, 0.0, 1e-12);
    SK_CHECK(pd(xd) > pd(xd - 0.1) && pd(xd) > pd(xd + 0.1));
    SK_CHECK(ps(xs) > ps(xs - 0.1) && ps(xs) > ps(xs + 0.1));
}

static void test_rho_values(void) {
    static const float ns[] = { 1.0f, 1.5f, 2.0f, 3.0f, 4.0f, 8.0f, 16.0f, 33.3f, 64.0f, 100.0f,
                                150.0f, 190.0f, 199.0f, 200.0f, 256.0f, 512.0f, 1000.0f,
                                1500.0f, 1580.0f, 1600.0f, 2048.0f, 4096.0f, 1e6f, 1e30f, FLT_MAX };
    int i;
    for (i = 0; i < (int)(sizeof ns / sizeof ns[0]); i++) {
        double rd = rho_ref(ns[i], 1), rs = rho_ref(ns[i], 0);
        SK_CHECK_NEAR(sk_rho_dynamic(ns[i]), rd, rel_tol(rd, 1e-4));
        SK_CHECK_NEAR(sk_rho_static(ns[i]), rs, rel_tol(rs, 1e-4));
    }
    /* hand values: n = 1 -> P(0); n = 2 -> P(1); n = 4 -> P(2) */
    SK_CHECK_NEAR(sk_rho_dynamic(1.0f), 0.667, 1e-5);
    SK_CHECK_NEAR(sk_rho_static(1.0f), 0.5477, 1e-5);
    SK_CHECK_NEAR(sk_rho_dynamic(2.0f), 0.667 + 0.7794 + 0.3967 - 0.02716, 1e-5);
    SK_CHECK_NEAR(sk_rho_static(2.0f), 0.5477 + 1.406 - 0.04687 - 0.003944, 1e-5);
    SK_CHECK_NEAR(sk_rho_dynamic(4.0f), 0.667 + 2 * 0.7794 + 4 * 0.3967 - 8 * 0.02716, 1e-5);
    SK_CHECK_NEAR(sk_rho_static(4.0f), 0.5477 + 2 * 1.406 - 4 * 0.04687 - 8 * 0.003944, 1e-5);
}

static void test_rho_clamps(void) {
    double d1 = pd(0.0), s1 = ps(0.0), dpk = pd(peak_d()), spk = ps(peak_s());
    /* n < 1, NaN, -Inf: the value at n = 1 */
    SK_CHECK_NEAR(sk_rho_dynamic(0.5f), d1, 1e-5);
    SK_CHECK_NEAR(sk_rho_dynamic(0.0f), d1, 1e-5);
    SK_CHECK_NEAR(sk_rho_dynamic(-3.0f), d1, 1e-5);
    SK_CHECK_NEAR(sk_rho_dynamic(NAN), d1, 1e-5);
    SK_CHECK_NEAR(sk_rho_dynamic(-INFINITY), d1, 1e-5);
    SK_CHECK_NEAR(sk_rho_dynamic(FLT_MIN), d1, 1e-5);
    SK_CHECK_NEAR(sk_rho_static(0.5f), s1, 1e-5);
    SK_CHECK_NEAR(sk_rho_static(0.0f), s1, 1e-5);
    SK_CHECK_NEAR(sk_rho_static(-3.0f), s1, 1e-5);
    SK_CHECK_NEAR(sk_rho_static(NAN), s1, 1e-5);
    SK_CHECK_NEAR(sk_rho_static(-INFINITY), s1, 1e-5);
    /* beyond the peak and +Inf: the peak value */
    SK_CHECK_NEAR(sk_rho_dynamic((float)pow(2.0, 10.7)), dpk, rel_tol(dpk, 1e-4));
    SK_CHECK_NEAR(sk_rho_dynamic(1e5f), dpk, rel_tol(dpk, 1e-4));
    SK_CHECK_NEAR(sk_rho_dynamic(INFINITY), dpk, rel_tol(dpk, 1e-4));
    SK_CHECK_NEAR(sk_rho_static((float)pow(2.0, 7.7)), spk, rel_tol(spk, 1e-4));
    SK_CHECK_NEAR(sk_rho_static(1e5f), spk, rel_tol(spk, 1e-4));
    SK_CHECK_NEAR(sk_rho_static(INFINITY), spk, rel_tol(spk, 1e-4));
    /* where the unclamped cubics would fall: well below the peak */
    SK_CHECK(pd(14.0) < dpk - 1.0 && ps(12.0) < spk - 1.0);
    SK_CHECK(sk_rho_dynamic(16384.0f) > (float)(dpk - 1e-3 * dpk));
    SK_CHECK(sk_rho_static(4096.0f) > (float)(spk - 1e-3 * spk));
}

static void test_rho_monotone(void) {
    double n;
    float pd_prev = sk_rho_dynamic(0.25f), ps_prev = sk_rho_static(0.25f);
    int bad_d = 0, bad_s = 0;
    for (n = 0.25; n < 1e8; n *= 1.003) {
        float a = sk_rho_dynamic((float)n), b = sk_rho_static((float)n);
        /* non-decreasing; a few ulps of float noise on the flat top allowed */
        if (!(a >= pd_prev - 4e-6f * pd_prev)) bad_d++;
        if (!(b >= ps_prev - 4e-6f * ps_prev)) bad_s++;
        if (!isfinite(a) || !isfinite(b) || a <= 0 || b <= 0) { bad_d++; bad_s++; }
        pd_prev = a;
        ps_prev = b;
    }
    SK_CHECK_MSG(bad_d == 0, "rho_dynamic decreased %d times", bad_d);
    SK_CHECK_MSG(bad_s == 0, "rho_static decreased %d times", bad_s);
}

/* ================================================================ convolution */
/* the appendix, in double */
static void conv_ref(const double in[8], double out[4]) {
    double m00 = in[0] * in[0] + in[2] * in[2] + in[4] * in[4] + in[6] * in[6];
    double m10 = in[0] * in[1] + in[2] * in[3] + in[4] * in[5] + in[6] * in[7];
    double m11 = in[1] * in[1] + in[3] * in[3] + in[5] * in[5] + in[7] * in[7];
    out[0] = sqrt(m00);
    out[1] = m10 / out[0];
    out[2] = 0.0;
    out[3] = sqrt(m11 - out[1] * out[1]);
}

/* u u^T + v v^T must reproduce the summed variance matrix */
static void check_variance(const float in[8], sk_vec2 u, sk_vec2 v, double tol_rel, const char *what) {
    double m00 = 0, m10 = 0, m11 = 0, scale;
    int k;
    for (k = 0; k < 4; k++) {
        double x = in[2 * k], y = in[2 * k + 1];
        m00 += x * x; m10 += x * y; m11 += y * y;
    }
    scale = dmax(dmax(m00, m11), 1e-30);
    SK_CHECK_MSG(fabs((double)u.x * u.x + (double)v.x * v.x - m00) <= tol_rel * scale,
                 "%s: m00 %g vs %g", what, (double)u.x * u.x + (double)v.x * v.x, m00);
    SK_CHECK_MSG(fabs((double)u.x * u.y + (double)v.x * v.y - m10) <= tol_rel * scale,
                 "%s: m10 %g vs %g", what, (double)u.x * u.y + (double)v.x * v.y, m10);
    SK_CHECK_MSG(fabs((double)u.y * u.y + (double)v.y * v.y - m11) <= tol_rel * scale,
                 "%s: m11 %g vs %g", what, (double)u.y * u.y + (double)v.y * v.y, m11);
}

static void run_conv(const float in[8], sk_vec2 *u, sk_vec2 *v) {
    u->x = u->y = v->x = v->y = -999.0f;
    sk_convolve_parallelograms(v2(in[0], in[1]), v2(in[2], in[3]), v2(in[4], in[5]), v2(in[6], in[7]), u, v);
}

static void test_convolve_formula(void) {
    /* a worked case: axis-aligned boxes, half-axes (2,0),(0,1) and (1,0),(0,3):
       V = diag(4+1, 1+9) -> u = (sqrt5, 0), v = (0, sqrt10) */
    float in0[8] = { 2, 0, 0, 1, 1, 0, 0, 3 };
    sk_vec2 u, v;
    int t;
    run_conv(in0, &u, &v);
    SK_CHECK_NEAR(u.x, sqrt(5.0), 1e-5);
    SK_CHECK_NEAR(u.y, 0.0, 1e-6);
    SK_CHECK(v.x == 0.0f);
    SK_CHECK_NEAR(v.y, sqrt(10.0), 1e-5);
    /* random parallelograms against the appendix in double */
    for (t = 0; t < 300; t++) {
        float in[8];
        double din[8], ref[4], S, scale = pow(10.0, rnd_range(-3, 3));
        int k;
        for (k = 0; k < 8; k++) { in[k] = (float)(rnd_range(-1, 1) * scale); din[k] = in[k]; }
        conv_ref(din, ref);
        run_conv(in, &u, &v);
        /* S: the size of the kernel; float rounding is relative to it, and v.y
           (a square root of a difference) loses up to half the digits */
        S = sqrt(ref[0] * ref[0] + ref[1] * ref[1] + ref[3] * ref[3]);
        SK_CHECK_NEAR(u.x, ref[0], 1e-4 * S);
        SK_CHECK_NEAR(u.y, ref[1], 1e-4 * S);
        SK_CHECK(v.x == 0.0f);
        SK_CHECK_NEAR(v.y, ref[3], 2e-3 * S);
        SK_CHECK(u.x >= 0.0f && v.y >= 0.0f);
        check_variance(in, u, v, 1e-4, "random");
    }
}

static void test_convolve_degenerate(void) {
    /* zero area inputs: finite axes and still the summed variance */
    static const float cases[][8] = {
        { 0, 0, 0, 0, 0, 0, 0, 0 },          /* nothing at all */
        { 1, 1, 2, 2, 0, 0, 0, 0 },          /* parallel axes: m11 - u.y^2 == 0 */
        { 1, 1, 2, 2, -3, -3, 0.5f, 0.5f },  /* all along one diagonal */
        { 0, 1, 0, 0.5f, 0, 0, 0, 0 },       /* vertical segment: m00 == 0 */
        { 0, 1, 0, 2, 0, -1, 0, 0 },
        { 3, 0, 0, 0, 0, 0, 0, 0 },          /* horizontal segment */
        { 1e-20f, 1e-20f, 0, 0, 0, 0, 0, 0 },/* underflowing squares */
        { 0.1f, 0.3f, 0.2f, 0.6f, 0.3f, 0.9f, 0.7f, 2.1f },
    };
    int i;
    for (i = 0; i < (int)(sizeof cases / sizeof cases[0]); i++) {
        sk_vec2 u, v;
        char what[128];
        run_conv(cases[i], &u, &v);
        SK_CHECK_MSG(isfinite(u.x) && isfinite(u.y) && isfinite(v.x) && isfinite(v.y),
                     "case %d: u (%g,%g) v (%g,%g)", i, u.x, u.y, v.x, v.y);
        SK_CHECK(v.x == 0.0f);
        sprintf(what, "degenerate %d", i);
        check_variance(cases[i], u, v, 1e-3, what);
    }
}

static void test_convolve_bad_input(void) {
    static const float bad[] = { NAN, INFINITY, -INFINITY };
    int b, k;
    sk_vec2 u, v;
    for (b = 0; b < 3; b++)
        for (k = 0; k < 8; k++) {
            float in[8] = { 1, 0.5f, -0.25f, 2, 0.75f, 0.1f, 0.3f, -1 };
            in[k] = bad[b];
            run_conv(in, &u, &v);
            SK_CHECK_MSG(u.x == 0 && u.y == 0 && v.x == 0 && v.y == 0,
                         "input %d = %g: u (%g,%g) v (%g,%g)", k, (double)bad[b], u.x, u.y, v.x, v.y);
        }
    /* finite but huge: no NaN (library-wide rule) */
    {
        float in[8] = { 3e30f, 1e30f, -2e30f, 3e30f, 1e30f, 1e30f, 0, 2e30f };
        run_conv(in, &u, &v);
        SK_CHECK_MSG(!isnan(u.x) && !isnan(u.y) && !isnan(v.x) && !isnan(v.y),
                     "huge: u (%g,%g) v (%g,%g)", u.x, u.y, v.x, v.y);
    }
    /* NULL outputs: no crash */
    sk_convolve_parallelograms(v2(1, 0), v2(0, 1), v2(0, 0), v2(0, 0), &u, NULL);
    sk_convolve_parallelograms(v2(1, 0), v2(0, 1), v2(0, 0), v2(0, 0), NULL, &v);
    sk_convolve_parallelograms(v2(1, 0), v2(0, 1), v2(0, 0), v2(0, 0), NULL, NULL);
    SK_CHECK(1);
}

/* ================================================================ coverage */
static double cov_ref(double x0, double y0, double x1, double y1, int tx, int ty) {
    double w = dmin(x1, tx + 1.0) - dmax(x0, (double)tx);
    double h = dmin(y1, ty + 1.0) - dmax(y0, (double)ty);
    if (!(w > 0 && h > 0)) return 0.0;
    return w * h;
}

static void test_coverage_hand(void) {
    /* box [0.5,1.5]x[0.25,0.75]: half in texel (0,0), half in (1,0) */
    SK_CHECK_NEAR(sk_texel_box_coverage(0.5f, 0.25f, 1.5f, 0.75f, 0, 0), 0.25, 1e-6);
    SK_CHECK_NEAR(sk_texel_box_coverage(0.5f, 0.25f, 1.5f, 0.75f, 1, 0), 0.25, 1e-6);
    SK_CHECK_NEAR(sk_texel_box_coverage(0.5f, 0.25f, 1.5f, 0.75f, 0, 1), 0.0, 1e-7);
    SK_CHECK_NEAR(sk_texel_box_coverage(0.5f, 0.25f, 1.5f, 0.75f, 2, 0), 0.0, 1e-7);
    SK_CHECK_NEAR(sk_texel_box_coverage(0.5f, 0.25f, 1.5f, 0.75f, -1, 0), 0.0, 1e-7);
    /* box containing the texel entirely */
    SK_CHECK_NEAR(sk_texel_box_coverage(-2.0f, -3.0f, 5.0f, 4.0f, 1, 2), 1.0, 1e-6);
    /* box inside one texel */
    SK_CHECK_NEAR(sk_texel_box_coverage(3.1f, 4.2f, 3.6f, 4.9f, 3, 4), 0.5 * 0.7, 1e-6);
    /* negative coordinates: box [-1.75,-0.5] x [-2.5,-1.25] (area 1.5625):
       texel (-2,-2) = [-2,-1]x[-2,-1]: 0.75 * 0.75; (-1,-2): 0.5 * 0.75;
       (-2,-3): 0.75 * 0.5; (-1,-3): 0.5 * 0.5 */
    SK_CHECK_NEAR(sk_texel_box_coverage(-1.75f, -2.5f, -0.5f, -1.25f, -2, -2), 0.75 * 0.75, 1e-6);
    SK_CHECK_NEAR(sk_texel_box_coverage(-1.75f, -2.5f, -0.5f, -1.25f, -1, -2), 0.5 * 0.75, 1e-6);
    SK_CHECK_NEAR(sk_texel_box_coverage(-1.75f, -2.5f, -0.5f, -1.25f, -2, -3), 0.75 * 0.5, 1e-6);
    SK_CHECK_NEAR(sk_texel_box_coverage(-1.75f, -2.5f, -0.5f, -1.25f, -1, -3), 0.5 * 0.5, 1e-6);
    /* touching at an edge only: zero */
    SK_CHECK_NEAR(sk_texel_box_coverage(1.0f, 0.0f, 2.0f, 1.0f, 0, 0), 0.0, 1e-7);
}

static void test_coverage_sum(void) {
    int t;
    for (t = 0; t < 100; t++) {
        double x0 = rnd_range(-6, 6), y0 = rnd_range(-6, 6);
        double x1 = x0 + rnd_range(0.01, 5), y1 = y0 + rnd_range(0.01, 5);
        float fx0 = (float)x0, fy0 = (float)y0, fx1 = (float)x1, fy1 = (float)y1;
        double sum = 0, area = ((double)fx1 - fx0) * ((double)fy1 - fy0);
        int tx, ty, ok = 1;
        for (ty = -8; ty <= 12; ty++)
            for (tx = -8; tx <= 12; tx++) {
                float c = sk_texel_box_coverage(fx0, fy0, fx1, fy1, tx, ty);
                double r = cov_ref(fx0, fy0, fx1, fy1, tx, ty);
                if (!(fabs(c - r) <= 1e-5)) ok = 0;
                sum += c;
            }
        SK_CHECK_MSG(ok, "coverage differs from the overlap area for box %d", t);
        SK_CHECK_NEAR(sum, area, 1e-4 * dmax(1.0, area));
    }
}

static void test_coverage_bad_input(void) {
    float r;
    SK_CHECK(sk_texel_box_coverage(0.5f, 0.5f, 0.5f, 0.9f, 0, 0) == 0.0f);   /* zero width */
    SK_CHECK(sk_texel_box_coverage(0.2f, 0.5f, 0.9f, 0.5f, 0, 0) == 0.0f);   /* zero height */
    SK_CHECK(sk_texel_box_coverage(0.9f, 0.1f, 0.2f, 0.8f, 0, 0) == 0.0f);   /* reversed x */
    SK_CHECK(sk_texel_box_coverage(0.1f, 0.8f, 0.9f, 0.2f, 0, 0) == 0.0f);   /* reversed y */
    SK_CHECK(sk_texel_box_coverage(NAN, 0.1f, 0.9f, 0.8f, 0, 0) == 0.0f);
    SK_CHECK(sk_texel_box_coverage(0.1f, NAN, 0.9f, 0.8f, 0, 0) == 0.0f);
    SK_CHECK(sk_texel_box_coverage(0.1f, 0.1f, NAN, 0.8f, 0, 0) == 0.0f);
    SK_CHECK(sk_texel_box_coverage(0.1f, 0.1f, 0.9f, NAN, 0, 0) == 0.0f);
    /* infinite boxes: a finite area within the texel, never NaN */
    r = sk_texel_box_coverage(-INFINITY, 0.25f, INFINITY, 0.75f, 0, 0);
    SK_CHECK_MSG(isfinite(r) && r >= 0 && r <= 1, "r = %g", (double)r);
    r = sk_texel_box_coverage(-INFINITY, -INFINITY, INFINITY, INFINITY, 3, -4);
    SK_CHECK_MSG(isfinite(r) && r >= 0 && r <= 1, "r = %g", (double)r);
    r = sk_texel_box_coverage(INFINITY, 0.0f, -INFINITY, 1.0f, 0, 0);
    SK_CHECK(r == 0.0f);
    /* texel indices at the ends of int: no overflow (UBSan watches) */
    SK_CHECK(sk_texel_box_coverage(0.0f, 0.0f, 1.0f, 1.0f, INT_MAX, 0) == 0.0f);
    SK_CHECK(sk_texel_box_coverage(0.0f, 0.0f, 1.0f, 1.0f, 0, INT_MAX) == 0.0f);
    SK_CHECK(sk_texel_box_coverage(0.0f, 0.0f, 1.0f, 1.0f, INT_MIN, INT_MIN) == 0.0f);
    r = sk_texel_box_coverage(-INFINITY, -INFINITY, INFINITY, INFINITY, INT_MAX, INT_MIN);
    SK_CHECK_MSG(isfinite(r) && r >= 0 && r <= 1, "r = %g", (double)r);
}

/* ================================================================ smooth visibility */
static int lit_half(void *user, int tx, int ty) { (void)ty; return tx < *(const int *)user; }
static int lit_checker(void *user, int tx, int ty) { (void)user; return (((tx + ty) % 2) + 2) % 2 == 0; }
static int calls_outside;   /* counts callback calls for texels the box does not touch */
static double cb_box[4];
static int lit_counting(void *user, int tx, int ty) {
    (void)user;
    if (tx + 1 <= cb_box[0] - 1 || tx >= cb_box[2] + 1 || ty + 1 <= cb_box[1] - 1 || ty >= cb_box[3] + 1) calls_outside++;
    return 1;
}

static double half_ref(double x0, double x1, int k) {
    double lit = dmin(x1, (double)k) - x0;
    if (lit < 0) lit = 0;
    if (lit > x1 - x0) lit = x1 - x0;
    return lit / (x1 - x0);
}

static double checker_ref(double x0, double y0, double x1, double y1) {
    int tx, ty;
    double s = 0;
    for (ty = (int)floor(y0) - 1; ty <= (int)floor(y1) + 1; ty++)
        for (tx = (int)floor(x0) - 1; tx <= (int)floor(x1) + 1; tx++)
            if (lit_checker(NULL, tx, ty)) s += cov_ref(x0, y0, x1, y1, tx, ty);
    return s / ((x1 - x0) * (y1 - y0));
}

static void test_smooth_visibility_values(void) {
    int k = 3, t;
    /* hand: [2.5,4.5] x [0,1] with texels tx < 3 lit: 0.5 of 2 -> 0.25 */
    SK_CHECK_NEAR(sk_smooth_box_visibility(2.5f, 0.0f, 4.5f, 1.0f, lit_half, &k), 0.25, 1e-5);
    SK_CHECK_NEAR(sk_smooth_box_visibility(0.0f, 0.0f, 2.0f, 3.0f, lit_half, &k), 1.0, 1e-5);
    SK_CHECK_NEAR(sk_smooth_box_visibility(3.0f, -2.0f, 9.0f, 3.0f, lit_half, &k), 0.0, 1e-5);
    SK_CHECK_NEAR(sk_smooth_box_visibility(1.0f, 5.25f, 5.0f, 7.75f, lit_half, &k), 0.5, 1e-5);
    SK_CHECK_NEAR(sk_smooth_box_visibility(-1.3f, 0.1f, 3.2f, 0.2f, lit_half, &k), 4.3 / 4.5, 1e-5);
    /* random boxes against the hand formula and a 2D checkerboard */
    for (t = 0; t < 200; t++) {
        double x0 = rnd_range(-10, 10), y0 = rnd_range(-10, 10);
        double x1 = x0 + rnd_range(0.05, 20), y1 = y0 + rnd_range(0.05, 20);
        float fx0 = (float)x0, fy0 = (float)y0, fx1 = (float)x1, fy1 = (float)y1;
        k = (int)floor(rnd_range(-12, 12));
        SK_CHECK_NEAR(sk_smooth_box_visibility(fx0, fy0, fx1, fy1, lit_half, &k),
                      half_ref(fx0, fx1, k), 1e-4);
        SK_CHECK_NEAR(sk_smooth_box_visibility(fx0, fy0, fx1, fy1, lit_checker, NULL),
                      checker_ref(fx0, fy0, fx1, fy1), 1e-4);
    }
    /* a box inside one texel sees only that texel */
    SK_CHECK_NEAR(sk_smooth_box_visibility(0.2f, 0.3f, 0.7f, 0.6f, lit_checker, NULL), 1.0, 1e-6);
    SK_CHECK_NEAR(sk_smooth_box_visibility(1.2f, 0.3f, 1.7f, 0.6f, lit_checker, NULL), 0.0, 1e-6);
    /* a box of exactly 64 x 64 texels is allowed; 63.5 wide touching 64 texels too */
    k = 32;
    SK_CHECK_NEAR(sk_smooth_box_visibility(0.0f, 0.0f, 64.0f, 64.0f, lit_half, &k), 0.5, 1e-5);
    SK_CHECK_NEAR(sk_smooth_box_visibility(0.25f, 0.25f, 63.75f, 63.75f, lit_half, &k),
                  31.75 / 63.5, 1e-5);
}

static void test_smooth_visibility_continuity(void) {
    /* PVSM's point (Sec. 4.1, Fig. 4): sliding the kernel by small steps changes
       the result by small steps (classic PCF jumps by whole texels). Box 2.37
       texels wide, shifted by 0.01 texel: at most 0.01 / 2.37 per step. */
    int k = 0, i, jumps = 0;
    double w = 2.37, prev = -1, maxstep = 0;
    for (i = 0; i <= 600; i++) {
        double x0 = -4.0 + 0.01 * i;
        float v = sk_smooth_box_visibility((float)x0, 0.3f, (float)(x0 + w), 1.9f, lit_half, &k);
        double ref = half_ref((float)x0, (float)(x0 + w), k);
        if (!(fabs(v - ref) <= 1e-4)) jumps++;
        if (prev >= 0 && fabs(v - prev) > maxstep) maxstep = fabs(v - prev);
        prev = v;
    }
    SK_CHECK_MSG(jumps == 0, "%d positions off the lit fraction", jumps);
    SK_CHECK_MSG(maxstep <= 0.01 / w + 1e-4, "largest step %g", maxstep);
    /* same with a 2D pattern and diagonal motion: Lipschitz in the shift */
    prev = -1; maxstep = 0;
    for (i = 0; i <= 600; i++) {
        double x0 = -3.0 + 0.01 * i, y0 = -1.0 + 0.007 * i;
        float v = sk_smooth_box_visibility((float)x0, (float)y0, (float)(x0 + 1.7), (float)(y0 + 2.9),
                                           lit_checker, NULL);
        if (prev >= 0 && fabs(v - prev) > maxstep) maxstep = fabs(v - prev);
        prev = v;
    }
    /* |dV| <= (perimeter-ish change) / area: (0.01*2.9 + 0.007*1.7) / (1.7*2.9) */
    SK_CHECK_MSG(maxstep <= (0.01 * 2.9 + 0.007 * 1.7) / (1.7 * 2.9) + 1e-4, "largest step %g", maxstep);
}

static void test_smooth_visibility_edges(void) {
    int k = 3;
    float r;
    /* larger than 64 x 64 texels: -1 */
    SK_CHECK(sk_smooth_box_visibility(0.0f, 0.0f, 100.0f, 1.0f, lit_half, &k) == -1.0f);
    SK_CHECK(sk_smooth_box_visibility(0.0f, 0.0f, 1.0f, 100.0f, lit_half, &k) == -1.0f);
    SK_CHECK(sk_smooth_box_visibility(-1e6f, -1e6f, 1e6f, 1e6f, lit_half, &k) == -1.0f);
    /* empty box: the lit value of the texel holding its centre */
    SK_CHECK(sk_smooth_box_visibility(2.5f, 7.5f, 2.5f, 7.5f, lit_half, &k) == 1.0f);
    SK_CHECK(sk_smooth_box_visibility(3.5f, 7.5f, 3.5f, 7.5f, lit_half, &k) == 0.0f);
    SK_CHECK(sk_smooth_box_visibility(-0.5f, -0.5f, -0.5f, -0.5f, lit_checker, NULL) == 1.0f);
    SK_CHECK(sk_smooth_box_visibility(0.5f, -0.5f, 0.5f, -0.5f, lit_checker, NULL) == 0.0f);
    /* only texels the box touches are asked (one texel of slack for edges) */
    calls_outside = 0;
    cb_box[0] = 5.3; cb_box[1] = -2.2; cb_box[2] = 9.1; cb_box[3] = 1.4;
    r = sk_smooth_box_visibility(5.3f, -2.2f, 9.1f, 1.4f, lit_counting, NULL);
    SK_CHECK_NEAR(r, 1.0, 1e-5);
    SK_CHECK(calls_outside == 0);
    /* bad input: never NaN, a valid visibility or -1 */
    r = sk_smooth_box_visibility(NAN, 0.0f, 1.0f, 1.0f, lit_half, &k);
    SK_CHECK_MSG(r == -1.0f || (r >= 0 && r <= 1), "NaN box -> %g", (double)r);
    r = sk_smooth_box_visibility(0.0f, 0.0f, INFINITY, 1.0f, lit_half, &k);
    SK_CHECK_MSG(r == -1.0f || (r >= 0 && r <= 1), "Inf box -> %g", (double)r);
    r = sk_smooth_box_visibility(-INFINITY, -INFINITY, INFINITY, INFINITY, lit_half, &k);
    SK_CHECK_MSG(r == -1.0f || (r >= 0 && r <= 1), "Inf box -> %g", (double)r);
    r = sk_smooth_box_visibility(0.0f, 0.0f, 2.0f, 2.0f, NULL, NULL);
    SK_CHECK_MSG(r == -1.0f || (r >= 0 && r <= 1), "NULL lit -> %g", (double)r);
    r = sk_smooth_box_visibility(4.0f, 0.0f, 2.0f, 1.0f, lit_half, &k);   /* reversed */
    SK_CHECK_MSG(r == -1.0f || (r >= 0 && r <= 1), "reversed box -> %g", (double)r);
    /* coordinates beyond int range: no overflowing conversion (UBSan watches) */
    r = sk_smooth_box_visibility(3e9f, 0.0f, 3e9f + 256.0f, 1.0f, lit_half, &k);
    SK_CHECK_MSG(r == -1.0f || (r >= 0 && r <= 1), "far box -> %g", (double)r);
    r = sk_smooth_box_visibility(-3e9f, -3e9f, -3e9f, -3e9f, lit_half, &k);   /* empty, far */
    SK_CHECK_MSG(r == -1.0f || (r >= 0 && r <= 1), "far empty box -> %g", (double)r);
    r = sk_smooth_box_visibility(1e30f, 1e30f, 1e30f, 1e30f, lit_half, &k);
    SK_CHECK_MSG(r == -1.0f || (r >= 0 && r <= 1), "far empty box -> %g", (double)r);
}

/* ================================================================ prediction */
/* Eq. (4)-(5) in double. M = [u_phi v_phi]; n0 = ||M^-1 (u_h.x, 0)||,
   n1 = ||M^-1 (0, v_h.y)||; r0 = 2|u_h.x| / rho(n0), r1 = 2|v_h.y| / rho(n1).
   Singular M: n taken as huge (rho at its peak). */
static void predict_ref(const double h[4], const double p[4], int dynamic, double *r0, double *r1) {
    double det = p[0] * p[3] - p[2] * p[1];
    double n0, n1;
    if (det == 0.0) {
        n0 = n1 = INFINITY;
    } else {
        /* M^-1 = 1/det [[v.y, -v.x], [-u.y, u.x]] */
        n0 = fabs(h[0]) / fabs(det) * sqrt(p[3] * p[3] + p[1] * p[1]);
        n1 = fabs(h[3]) / fabs(det) * sqrt(p[2] * p[2] + p[0] * p[0]);
    }
    *r0 = 2.0 * fabs(h[0]) / rho_ref(n0, dynamic);
    *r1 = 2.0 * fabs(h[3]) / rho_ref(n1, dynamic);
}

static void run_predict(const float h[4], const float p[4], int dynamic, float *r0, float *r1) {
    *r0 = *r1 = -999.0f;
    sk_pvsm_predict(v2(h[0], h[1]), v2(h[2], h[3]), v2(p[0], p[1]), v2(p[2], p[3]), dynamic, r0, r1);
}

static void test_predict_hand(void) {
    /* footprint: axis-aligned pixel of half-size 0.01 x 0.02 shadow-map units;
       kernel h half-axes (0.08, 0) and (0, 0.16): n0 = 0.08/0.01 = 8,
       n1 = 0.16/0.02 = 8 pixels; r0 = 0.16 / rho(8), r1 = 0.32 / rho(8) */
    float h[4] = { 0.08f, 0.0f, 0.0f, 0.16f }, p[4] = { 0.01f, 0.0f, 0.0f, 0.02f };
    float r0, r1;
    double rd8 = pd(3.0), rs8 = ps(3.0);
    run_predict(h, p, 1, &r0, &r1);
    SK_CHECK_NEAR(r0, 0.16 / rd8, 1e-5 * 0.16 / rd8 + 1e-9);
    SK_CHECK_NEAR(r1, 0.32 / rd8, 1e-5 * 0.32 / rd8 + 1e-9);
    run_predict(h, p, 0, &r0, &r1);
    SK_CHECK_NEAR(r0, 0.16 / rs8, 1e-5 * 0.16 / rs8 + 1e-9);
    SK_CHECK_NEAR(r1, 0.32 / rs8, 1e-5 * 0.32 / rs8 + 1e-9);
    /* dynamic needs smaller texels than static at the same n (conservative) */
    {
        float d0, d1, s0, s1;
        run_predict(h, p, 1, &d0, &d1);
        run_predict(h, p, 0, &s0, &s1);
        SK_CHECK(d0 < s0 && d1 < s1);
    }
    /* kernel == footprint: n = 1 pixel, rho(1) = P(0); r = 2 h / P(0) */
    {
        float hh[4] = { 0.01f, 0.0f, 0.0f, 0.02f };
        run_predict(hh, p, 1, &r0, &r1);
        SK_CHECK_NEAR(r0, 0.02 / 0.667, 1e-6);
        SK_CHECK_NEAR(r1, 0.04 / 0.667, 1e-6);
    }
    /* n below 1 (sub-pixel kernel) is taken as 1 */
    {
        float hh[4] = { 0.004f, 0.0f, 0.0f, 0.001f };
        run_predict(hh, p, 0, &r0, &r1);
        SK_CHECK_NEAR(r0, 0.008 / 0.5477, 1e-6);
        SK_CHECK_NEAR(r1, 0.002 / 0.5477, 1e-6);
    }
    /* a negative axis gives the same (positive) size */
    {
        float hn[4] = { -0.08f, 0.0f, 0.0f, -0.16f };
        float pn[4] = { -0.01f, 0.0f, 0.0f, 0.02f };
        run_predict(hn, pn, 1, &r0, &r1);
        SK_CHECK_NEAR(r0, 0.16 / rd8, 1e-5 * 0.16 / rd8 + 1e-9);
        SK_CHECK_NEAR(r1, 0.32 / rd8, 1e-5 * 0.32 / rd8 + 1e-9);
    }
}

static void test_predict_random(void) {
    int t;
    for (t = 0; t < 400; t++) {
        float h[4], p[4], r0, r1;
        double dh[4], dp[4], e0, e1, s = pow(10.0, rnd_range(-2.5, 0));
        int k, dyn = t & 1;
        /* footprint: a random well-conditioned parallelogram */
        for (k = 0; k < 4; k++) { p[k] = (float)(rnd_range(-1, 1) * s * 0.05); dp[k] = p[k]; }
        if (fabs(dp[0] * dp[3] - dp[2] * dp[1]) < 0.05 * (dp[0] * dp[0] + dp[1] * dp[1] + dp[2] * dp[2] + dp[3] * dp[3]))
            continue;
        /* kernel: from 0.3 to 3000 footprints wide, semi-axis aligned */
        {
            double m = pow(10.0, rnd_range(-0.5, 3.5));
            h[0] = (float)(fabs(rnd_range(0.2, 1)) * s * 0.05 * m);
            h[1] = (float)(rnd_range(-1, 1) * s * 0.05 * m);
            h[2] = 0.0f;
            h[3] = (float)(rnd_range(0.2, 1) * s * 0.05 * m);
        }
        for (k = 0; k < 4; k++) dh[k] = h[k];
        predict_ref(dh, dp, dyn, &e0, &e1);
        run_predict(h, p, dyn, &r0, &r1);
        SK_CHECK_NEAR(r0, e0, 2e-4 * e0);
        SK_CHECK_NEAR(r1, e1, 2e-4 * e1);
    }
}

static void test_predict_singular(void) {
    /* singular footprints: n huge, rho at its peak, r finite */
    static const float ps_[][4] = {
        { 0.01f, 0.0f, 0.02f, 0.0f },     /* parallel axes */
        { 0.01f, 0.01f, -0.03f, -0.03f },
        { 0.0f, 0.0f, 0.0f, 0.0f },       /* no footprint at all */
        { 0.02f, 0.0f, 0.0f, 0.0f },
    };
    float h[4] = { 0.08f, 0.01f, 0.0f, 0.16f };
    int i, dyn;
    for (i = 0; i < 4; i++)
        for (dyn = 0; dyn <= 1; dyn++) {
            float r0, r1;
            double pk = dyn ? pd(peak_d()) : ps(peak_s());
            run_predict(h, ps_[i], dyn, &r0, &r1);
            SK_CHECK_MSG(isfinite(r0) && isfinite(r1), "footprint %d: r0 %g r1 %g", i, (double)r0, (double)r1);
            SK_CHECK_NEAR(r0, 0.16 / pk, 1e-4 * 0.16 / pk);
            SK_CHECK_NEAR(r1, 0.32 / pk, 1e-4 * 0.32 / pk);
        }
}

static void test_predict_bad_input(void) {
    static const float bad[] = { NAN, INFINITY, -INFINITY };
    int b, k;
    for (b = 0; b < 3; b++)
        for (k = 0; k < 8; k++) {
            float v[8] = { 0.08f, 0.01f, 0.0f, 0.16f, 0.01f, 0.0f, 0.0f, 0.02f };
            float r0 = -999.0f, r1 = -999.0f;
            v[k] = bad[b];
            sk_pvsm_predict(v2(v[0], v[1]), v2(v[2], v[3]), v2(v[4], v[5]), v2(v[6], v[7]), 1, &r0, &r1);
            SK_CHECK_MSG(isinf(r0) && r0 > 0 && isinf(r1) && r1 > 0,
                         "input %d = %g: r0 %g r1 %g", k, (double)bad[b], (double)r0, (double)r1);
        }
    /* NULL outputs: no crash, the other one still written */
    {
        float r = -999.0f;
        sk_pvsm_predict(v2(0.08f, 0), v2(0, 0.16f), v2(0.01f, 0), v2(0, 0.02f), 1, &r, NULL);
        SK_CHECK_NEAR(r, 0.16 / pd(3.0), 1e-5);
        r = -999.0f;
        sk_pvsm_predict(v2(0.08f, 0), v2(0, 0.16f), v2(0.01f, 0), v2(0, 0.02f), 1, NULL, &r);
        SK_CHECK_NEAR(r, 0.32 / pd(3.0), 1e-5);
        sk_pvsm_predict(v2(0.08f, 0), v2(0, 0.16f), v2(0.01f, 0), v2(0, 0.02f), 1, NULL, NULL);
    }
}

/* ================================================================ merge */
static void test_merge(void) {
    float v = 0.3f, a = 2.0f;
    int t;
    /* (0.3*2 + 0.8*6) / 8 = 0.675 */
    sk_pvsm_merge(&v, &a, 0.8f, 6.0f);
    SK_CHECK_NEAR(v, 0.675, 1e-6);
    SK_CHECK_NEAR(a, 8.0, 1e-6);
    /* starting from nothing (a = 0), whatever v holds, the first tile wins */
    v = 0.9f; a = 0.0f;
    sk_pvsm_merge(&v, &a, 0.4f, 3.0f);
    SK_CHECK_NEAR(v, 0.4, 1e-6);
    SK_CHECK_NEAR(a, 3.0, 1e-6);
    /* a zero-area tile changes nothing */
    sk_pvsm_merge(&v, &a, 1.0f, 0.0f);
    SK_CHECK_NEAR(v, 0.4, 1e-6);
    SK_CHECK_NEAR(a, 3.0, 1e-6);
    /* nothing merged into nothing: finite, area 0 */
    v = 0.0f; a = 0.0f;
    sk_pvsm_merge(&v, &a, 0.5f, 0.0f);
    SK_CHECK_FINITE(v);
    SK_CHECK_NEAR(a, 0.0, 0.0);
    /* many tiles: the area-weighted mean */
    for (t = 0; t < 50; t++) {
        int n = 1 + (int)(rnd() * 8), i;
        double sva = 0, sa = 0;
        v = 0.0f; a = 0.0f;
        for (i = 0; i < n; i++) {
            float vi = (float)rnd(), ai = (float)rnd_range(0.01, 40);
            sk_pvsm_merge(&v, &a, vi, ai);
            sva += (double)vi * ai;
            sa += ai;
        }
        SK_CHECK_NEAR(v, sva / sa, 1e-5);
        SK_CHECK_NEAR(a, sa, 1e-5 * sa);
    }
    /* the order of the tiles does not matter */
    {
        float va = 0, aa = 0, vb = 0, ab = 0;
        sk_pvsm_merge(&va, &aa, 0.1f, 1.0f); sk_pvsm_merge(&va, &aa, 0.7f, 2.5f); sk_pvsm_merge(&va, &aa, 1.0f, 0.5f);
        sk_pvsm_merge(&vb, &ab, 1.0f, 0.5f); sk_pvsm_merge(&vb, &ab, 0.1f, 1.0f); sk_pvsm_merge(&vb, &ab, 0.7f, 2.5f);
        SK_CHECK_NEAR(va, vb, 1e-6);
        SK_CHECK_NEAR(aa, ab, 1e-6);
        SK_CHECK_NEAR(va, (0.1 + 0.7 * 2.5 + 0.5) / 4.0, 1e-6);
    }
    /* bad input: never NaN; NULL: no crash */
    v = 0.5f; a = 1.0f;
    sk_pvsm_merge(&v, &a, NAN, 1.0f);
    SK_CHECK_MSG(!isnan(v) && !isnan(a), "v %g a %g", (double)v, (double)a);
    v = 0.5f; a = 1.0f;
    sk_pvsm_merge(&v, &a, 0.5f, NAN);
    SK_CHECK_MSG(!isnan(v) && !isnan(a), "v %g a %g", (double)v, (double)a);
    v = 0.5f; a = 1.0f;
    sk_pvsm_merge(&v, &a, 0.5f, INFINITY);
    SK_CHECK_MSG(!isnan(v) && !isnan(a), "v %g a %g", (double)v, (double)a);
    sk_pvsm_merge(NULL, &a, 0.5f, 1.0f);
    sk_pvsm_merge(&v, NULL, 0.5f, 1.0f);
    sk_pvsm_merge(NULL, NULL, 0.5f, 1.0f);
    SK_CHECK(1);
}

/* ================================================================ SMTG pyramid */
static int pyr_size_ref(int gw, int gh) {
    long long s = 0;
    for (;;) {
        s += (long long)gw * gh * 2;
        if (gw == 1 && gh == 1) break;
        gw = (gw + 1) / 2;
        gh = (gh + 1) / 2;
    }
    return (int)s;
}

static void test_smtg_size(void) {
    static const int dims[][2] = { { 1, 1 }, { 2, 2 }, { 5, 3 }, { 8, 8 }, { 7, 1 }, { 1, 9 },
                                   { 13, 6 }, { 64, 64 }, { 100, 37 }, { 4096, 4096 } };
    int i;
    /* by hand: 5x3 -> 3x2 -> 2x1 -> 1x1: (15 + 6 + 2 + 1) * 2 = 48 */
    SK_CHECK(sk_smtg_pyramid_size(5, 3) == 48);
    SK_CHECK(sk_smtg_pyramid_size(1, 1) == 2);
    /* 8x1 -> 4x1 -> 2x1 -> 1x1: 15 cells */
    SK_CHECK(sk_smtg_pyramid_size(8, 1) == 30);
    /* 64x64: 4096+1024+256+64+16+4+1 = 5461 cells */
    SK_CHECK(sk_smtg_pyramid_size(64, 64) == 2 * 5461);
    for (i = 0; i < (int)(sizeof dims / sizeof dims[0]); i++)
        SK_CHECK_MSG(sk_smtg_pyramid_size(dims[i][0], dims[i][1]) == pyr_size_ref(dims[i][0], dims[i][1]),
                     "%dx%d: %d vs %d", dims[i][0], dims[i][1],
                     sk_smtg_pyramid_size(dims[i][0], dims[i][1]), pyr_size_ref(dims[i][0], dims[i][1]));
    /* bad input: 0 */
    SK_CHECK(sk_smtg_pyramid_size(0, 4) == 0);
    SK_CHECK(sk_smtg_pyramid_size(4, 0) == 0);
    SK_CHECK(sk_smtg_pyramid_size(-3, 4) == 0);
    SK_CHECK(sk_smtg_pyramid_size(4, -3) == 0);
    /* more floats than an int can count: 0, not an overflowed value */
    SK_CHECK(sk_smtg_pyramid_size(100000, 100000) == 0);
    SK_CHECK(sk_smtg_pyramid_size(2147483647, 2147483647) == 0);
}

/* brute-force check of a built pyramid */
static int check_pyramid(const float *grid, int gw, int gh, const float *pyr, int levels) {
    int lw = gw, lh = gh, l = 0, off = 0, prev_off = 0, pw = 0, ph = 0, x, y, c, bad = 0;
    for (;;) {
        for (y = 0; y < lh; y++)
            for (x = 0; x < lw; x++)
                for (c = 0; c < 2; c++) {
                    float want;
                    if (l == 0) {
                        want = grid[(y * gw + x) * 2 + c];
                    } else {
                        int dx, dy;
                        want = INFINITY;
                        for (dy = 0; dy < 2; dy++)
                            for (dx = 0; dx < 2; dx++) {
                                int cx = 2 * x + dx, cy = 2 * y + dy;
                                if (cx < pw && cy < ph) {
                                    float cv = pyr[prev_off + (cy * pw + cx) * 2 + c];
                                    if (cv < want) want = cv;
                                }
                            }
                    }
                    if (!(pyr[off + (y * lw + x) * 2 + c] == want)) bad++;
                }
        l++;
        if (lw == 1 && lh == 1) break;
        prev_off = off; pw = lw; ph = lh;
        off += lw * lh * 2;
        lw = (lw + 1) / 2;
        lh = (lh + 1) / 2;
    }
    if (l != levels) bad++;
    return bad;
}

static void test_smtg_pyramid(void) {
    static const int dims[][2] = { { 1, 1 }, { 2, 1 }, { 1, 2 }, { 5, 3 }, { 8, 8 }, { 7, 1 },
                                   { 1, 9 }, { 13, 6 }, { 33, 17 } };
    int d;
    for (d = 0; d < (int)(sizeof dims / sizeof dims[0]); d++) {
        int gw = dims[d][0], gh = dims[d][1], size = pyr_size_ref(gw, gh), i, n, levels = 1;
        float *grid = (float *)malloc(sizeof(float) * (size_t)(gw * gh * 2));
        float *pyr = (float *)malloc(sizeof(float) * (size_t)(size + 4));
        { int a = gw, b = gh; while (a > 1 || b > 1) { a = (a + 1) / 2; b = (b + 1) / 2; levels++; } }
        for (i = 0; i < gw * gh * 2; i++)
            grid[i] = rnd() < 0.3 ? INFINITY : (float)rnd_range(0.0001, 1.0);
        for (i = 0; i < size + 4; i++) pyr[i] = -5.0f;
        n = sk_smtg_pyramid(grid, gw, gh, pyr, size);
        SK_CHECK_MSG(n == levels, "%dx%d: %d levels, expected %d", gw, gh, n, levels);
        if (n == levels)
            SK_CHECK_MSG(check_pyramid(grid, gw, gh, pyr, n) == 0, "%dx%d pyramid differs", gw, gh);
        /* writes nothing past the size */
        SK_CHECK(pyr[size] == -5.0f && pyr[size + 3] == -5.0f);
        /* too small: capacity error */
        SK_CHECK(sk_smtg_pyramid(grid, gw, gh, pyr, size - 1) == -SK_ERR_CAPACITY);
        free(grid);
        free(pyr);
    }
    /* an all-INF grid gives an all-INF pyramid */
    {
        float grid[6 * 2], pyr[64];
        int i, n, ok = 1;
        for (i = 0; i < 12; i++) grid[i] = INFINITY;
        n = sk_smtg_pyramid(grid, 3, 2, pyr, 64);
        SK_CHECK(n == 3);
        for (i = 0; i < pyr_size_ref(3, 2); i++) if (!(isinf(pyr[i]) && pyr[i] > 0)) ok = 0;
        SK_CHECK(ok);
    }
    /* hand case 3x2 (x then y components):
         row 0: (4,1) (2,9) (7,3)      level 1 (2x1): (min 4,2,5,8 ; min 1,9,6,0) = (2,0)
         row 1: (5,6) (8,0) (1,2)                     (min 7,1   ; min 3,2)     = (1,2)
       level 2 (1x1): (1, 0) */
    {
        float grid[12] = { 4, 1, 2, 9, 7, 3, 5, 6, 8, 0, 1, 2 }, pyr[32];
        int n = sk_smtg_pyramid(grid, 3, 2, pyr, 32);
        SK_CHECK(n == 3);
        if (n == 3) {
            SK_CHECK(pyr[12] == 2 && pyr[13] == 0 && pyr[14] == 1 && pyr[15] == 2);
            SK_CHECK(pyr[16] == 1 && pyr[17] == 0);
        }
    }
}

static void test_smtg_bad_input(void) {
    float grid[8] = { 1, 1, 1, 1, 1, 1, 1, 1 }, pyr[16];
    int i, r, untouched;
#define BADP(call) do { for (i = 0; i < 16; i++) pyr[i] = -5.0f; r = (call); \
        SK_CHECK_MSG(r == -SK_ERR_INVALID_ARG, "%s -> %d", #call, r); \
        for (untouched = 1, i = 0; i < 16; i++) if (pyr[i] != -5.0f) untouched = 0; \
        SK_CHECK_MSG(untouched, "%s wrote to out", #call); } while (0)
    BADP(sk_smtg_pyramid(NULL, 2, 2, pyr, 16));
    BADP(sk_smtg_pyramid(grid, 0, 2, pyr, 16));
    BADP(sk_smtg_pyramid(grid, 2, 0, pyr, 16));
    BADP(sk_smtg_pyramid(grid, -2, 2, pyr, 16));
    BADP(sk_smtg_pyramid(grid, 2, -2, pyr, 16));
    BADP(sk_smtg_pyramid(grid, 2, 2, NULL, 16));
    BADP(sk_smtg_pyramid(grid, 2, 2, pyr, -1));
#undef BADP
    r = sk_smtg_pyramid(grid, 2, 2, pyr, 0);
    SK_CHECK_MSG(r == -SK_ERR_CAPACITY || r == -SK_ERR_INVALID_ARG, "cap 0 -> %d", r);
    r = sk_smtg_pyramid(grid, 100000, 100000, pyr, 16);   /* size beyond int */
    SK_CHECK_MSG(r == -SK_ERR_CAPACITY || r == -SK_ERR_INVALID_ARG, "huge grid -> %d", r);
}

/* ================================================================ kd-tree tiles */
static int sampled(const float *g, int gw, int x, int y) {
    float a = g[(y * gw + x) * 2], b = g[(y * gw + x) * 2 + 1];
    return !(isnan(a) || isnan(b) || (isinf(a) && a > 0) || (isinf(b) && b > 0));
}

/* Checks the whole documented contract of one sk_fvsm_tiles result. */
static int check_tiles(const float *g, int gw, int gh, int max_res, const sk_tile *t, int n, const char *what) {
    int *cover = (int *)calloc((size_t)(gw * gh), sizeof(int));
    int *owner = (int *)calloc((size_t)(gw * gh), sizeof(int));
    int i, x, y, bad = 0, nsampled = 0;
    for (i = 0; i < n; i++) {
        double minx = INFINITY, miny = INFINITY, span_x, span_y, need_x, need_y;
        int any = 0, zero_x = 0, zero_y = 0;
        if (!(t[i].x0 >= 0 && t[i].x0 < t[i].x1 && t[i].x1 <= gw &&
              t[i].y0 >= 0 && t[i].y0 < t[i].y1 && t[i].y1 <= gh)) {
            printf("  %s: tile %d [%d,%d)x[%d,%d) outside the grid\n", what, i, t[i].x0, t[i].x1, t[i].y0, t[i].y1);
            bad++;
            continue;
        }
        if (!(t[i].res_x >= 1 && t[i].res_x <= max_res && t[i].res_y >= 1 && t[i].res_y <= max_res)) {
            printf("  %s: tile %d res %dx%d outside [1,%d]\n", what, i, t[i].res_x, t[i].res_y, max_res);
            bad++;
        }
        for (y = t[i].y0; y < t[i].y1; y++)
            for (x = t[i].x0; x < t[i].x1; x++) {
                cover[y * gw + x]++;
                owner[y * gw + x] = i;
                if (!sampled(g, gw, x, y)) continue;
                any = 1;
                if (g[(y * gw + x) * 2] <= 0) zero_x = 1; else minx = dmin(minx, g[(y * gw + x) * 2]);
                if (g[(y * gw + x) * 2 + 1] <= 0) zero_y = 1; else miny = dmin(miny, g[(y * gw + x) * 2 + 1]);
            }
        if (!any) {
            printf("  %s: tile %d [%d,%d)x[%d,%d) holds no sampled cell\n", what, i, t[i].x0, t[i].x1, t[i].y0, t[i].y1);
            bad++;
            continue;
        }
        span_x = (t[i].x1 - t[i].x0) * 2.0 / gw;
        span_y = (t[i].y1 - t[i].y0) * 2.0 / gh;
        need_x = zero_x ? (double)max_res : span_x / minx;
        need_y = zero_y ? (double)max_res : span_y / miny;
        /* res >= span / min texel size, unless the need exceeds max_res: then
           max_res. One rule for both: res >= min(need, max_res) (float slack 1e-5) */
        if (t[i].res_x < dmin(need_x * (1 - 1e-5), (double)max_res)) {
            printf("  %s: tile %d [%d,%d)x[%d,%d) res_x %d, needs %g (max %d)\n", what, i,
                   t[i].x0, t[i].x1, t[i].y0, t[i].y1, t[i].res_x, need_x, max_res);
            bad++;
        }
        if (t[i].res_y < dmin(need_y * (1 - 1e-5), (double)max_res)) {
            printf("  %s: tile %d [%d,%d)x[%d,%d) res_y %d, needs %g (max %d)\n", what, i,
                   t[i].x0, t[i].x1, t[i].y0, t[i].y1, t[i].res_y, need_y, max_res);
            bad++;
        }
    }
    for (y = 0; y < gh; y++)
        for (x = 0; x < gw; x++) {
            int s = sampled(g, gw, x, y);
            nsampled += s;
            if (s && cover[y * gw + x] != 1) {
                printf("  %s: sampled cell (%d,%d) covered %d times\n", what, x, y, cover[y * gw + x]);
                bad++;
            } else if (!s && cover[y * gw + x] > 1) {
                printf("  %s: cell (%d,%d) covered %d times (tiles overlap)\n", what, x, y, cover[y * gw + x]);
                bad++;
            }
            /* a cell whose own need exceeds max_res gets a tile of its own at max_res */
            if (s) {
                double vx = g[(y * gw + x) * 2], vy = g[(y * gw + x) * 2 + 1];
                int over_x = vx > 0 && (2.0 / gw) / vx > max_res * (1 + 1e-5);
                int over_y = vy > 0 && (2.0 / gh) / vy > max_res * (1 + 1e-5);
                i = owner[y * gw + x];
                if ((over_x || over_y) && cover[y * gw + x] == 1 &&
                    (t[i].x1 - t[i].x0 != 1 || t[i].y1 - t[i].y0 != 1 ||
                     (over_x && t[i].res_x != max_res) || (over_y && t[i].res_y != max_res))) {
                    printf("  %s: over-demanding cell (%d,%d) in tile [%d,%d)x[%d,%d) res %dx%d\n", what,
                           x, y, t[i].x0, t[i].x1, t[i].y0, t[i].y1, t[i].res_x, t[i].res_y);
                    bad++;
                }
            }
        }
    if (nsampled == 0 && n != 0) bad++;
    free(cover);
    free(owner);
    return bad;
}

static void test_tiles_simple(void) {
    /* 8x8 grid, every cell needs 4 texels per cell span along x and y:
       the whole grid needs 32 x 32 <= 64: the root is one tile */
    float g[8 * 8 * 2];
    sk_tile t[64];
    int i, n;
    for (i = 0; i < 64; i++) { g[2 * i] = 0.25f / 4.0f; g[2 * i + 1] = 0.25f / 4.0f; }
    n = sk_fvsm_tiles(g, 8, 8, 64, t, 64);
    SK_CHECK(n == 1);
    if (n == 1) {
        SK_CHECK(t[0].x0 == 0 && t[0].y0 == 0 && t[0].x1 == 8 && t[0].y1 == 8);
        SK_CHECK(t[0].res_x >= 32 && t[0].res_y >= 32 && t[0].res_x <= 64 && t[0].res_y <= 64);
    }
    SK_CHECK(check_tiles(g, 8, 8, 64, t, n > 0 ? n : 0, "uniform") == 0);
    /* only cells [2,5)x[3,4) sampled: the node shrinks to exactly them */
    for (i = 0; i < 128; i++) g[i] = INFINITY;
    for (i = 2; i < 5; i++) { g[(3 * 8 + i) * 2] = 0.25f / 4.0f; g[(3 * 8 + i) * 2 + 1] = 0.25f / 4.0f; }
    n = sk_fvsm_tiles(g, 8, 8, 64, t, 64);
    SK_CHECK(n == 1);
    if (n == 1) {
        SK_CHECK(t[0].x0 == 2 && t[0].x1 == 5 && t[0].y0 == 3 && t[0].y1 == 4);
        SK_CHECK(t[0].res_x >= 12 && t[0].res_y >= 4);
    }
    SK_CHECK(check_tiles(g, 8, 8, 64, t, n > 0 ? n : 0, "shrunk") == 0);
    /* uniform need of 16 texels per cell, max 64: 128 x 128 needed -> split
       into at least 4 tiles, each within max_res */
    for (i = 0; i < 64; i++) { g[2 * i] = 0.25f / 16.0f; g[2 * i + 1] = 0.25f / 16.0f; }
    n = sk_fvsm_tiles(g, 8, 8, 64, t, 64);
    SK_CHECK(n >= 4);
    SK_CHECK(check_tiles(g, 8, 8, 64, t, n > 0 ? n : 0, "split") == 0);
    /* single cell needing exactly max_res: one tile at max_res (not clamped) */
    g[0] = 2.0f / 256.0f; g[1] = 2.0f / 256.0f;
    n = sk_fvsm_tiles(g, 1, 1, 256, t, 4);
    SK_CHECK(n == 1);
    if (n == 1) SK_CHECK(t[0].x0 == 0 && t[0].y0 == 0 && t[0].x1 == 1 && t[0].y1 == 1 &&
                         t[0].res_x == 256 && t[0].res_y == 256);
    /* single cell needing more than max_res: its own tile, clamped */
    g[0] = 2.0f / 100000.0f; g[1] = 2.0f / 300.0f;
    n = sk_fvsm_tiles(g, 1, 1, 256, t, 4);
    SK_CHECK(n == 1);
    if (n == 1) SK_CHECK(t[0].res_x == 256 && t[0].res_y == 256);
    /* a value <= 0 demands max_res */
    g[0] = 0.0f; g[1] = 2.0f / 10.0f;
    n = sk_fvsm_tiles(g, 1, 1, 256, t, 4);
    SK_CHECK(n == 1);
    if (n == 1) SK_CHECK(t[0].res_x == 256 && t[0].res_y >= 10 && t[0].res_y <= 256);
    g[0] = 2.0f / 10.0f; g[1] = -1.0f;
    n = sk_fvsm_tiles(g, 1, 1, 256, t, 4);
    SK_CHECK(n == 1);
    if (n == 1) SK_CHECK(t[0].res_y == 256 && t[0].res_x >= 10 && t[0].res_x <= 256);
}

static void test_tiles_empty(void) {
    float g[6 * 5 * 2];
    sk_tile t[4];
    int i;
    for (i = 0; i < 60; i++) g[i] = INFINITY;
    SK_CHECK(sk_fvsm_tiles(g, 6, 5, 1024, t, 4) == 0);
    for (i = 0; i < 60; i++) g[i] = NAN;
    SK_CHECK(sk_fvsm_tiles(g, 6, 5, 1024, t, 4) == 0);
    for (i = 0; i < 60; i++) g[i] = (i / 2) % 2 ? NAN : INFINITY;
    SK_CHECK(sk_fvsm_tiles(g, 6, 5, 1024, t, 4) == 0);
}

static void test_tiles_random(void) {
    static const int max_res_set[] = { 1, 16, 64, 256, 1024, 4096 };
    int trial;
    for (trial = 0; trial < 150; trial++) {
        int gw = 1 + (int)(rnd() * 24), gh = 1 + (int)(rnd() * 24);
        int max_res = max_res_set[(int)(rnd() * 6)];
        double p_inf = rnd() * 0.8, p_over = rnd() < 0.5 ? 0.0 : 0.05;
        int cells = gw * gh, cap = cells + 8, i, n, bad;
        float *g = (float *)malloc(sizeof(float) * (size_t)(cells * 2));
        sk_tile *t = (sk_tile *)malloc(sizeof(sk_tile) * (size_t)cap);
        char what[128];
        for (i = 0; i < cells; i++) {
            double u = rnd();
            if (u < p_inf) {
                g[2 * i] = g[2 * i + 1] = (rnd() < 0.8) ? INFINITY : NAN;
            } else if (u < p_inf + p_over) {
                /* needs more than max_res in one axis, or a <= 0 demand */
                double w = rnd();
                g[2 * i] = w < 0.4 ? (float)((2.0 / gw) / (max_res * rnd_range(1.5, 100)))
                         : (w < 0.5 ? 0.0f : (float)((2.0 / gw) / rnd_range(1, max_res)));
                g[2 * i + 1] = w >= 0.4 && w < 0.8 ? (float)((2.0 / gh) / (max_res * rnd_range(1.5, 100)))
                             : (float)((2.0 / gh) / rnd_range(1, max_res));
            } else {
                /* between 1/8 and 200 texels per cell span, skewed towards small */
                double tx = pow(2.0, rnd_range(-3, log2(dmin(200.0, max_res))));
                double ty = pow(2.0, rnd_range(-3, log2(dmin(200.0, max_res))));
                g[2 * i] = (float)((2.0 / gw) / tx);
                g[2 * i + 1] = (float)((2.0 / gh) / ty);
            }
        }
        n = sk_fvsm_tiles(g, gw, gh, max_res, t, cap);
        sprintf(what, "trial %d (%dx%d, max %d)", trial, gw, gh, max_res);
        SK_CHECK_MSG(n >= 0, "%s: returned %d", what, n);
        if (n >= 0) {
            bad = check_tiles(g, gw, gh, max_res, t, n, what);
            SK_CHECK_MSG(bad == 0, "%s: %d contract violations", what, bad);
            if (n > 1) {
                /* one less than needed: a capacity error, nothing dropped silently */
                SK_CHECK_MSG(sk_fvsm_tiles(g, gw, gh, max_res, t, n - 1) == -SK_ERR_CAPACITY,
                             "%s: cap %d", what, n - 1);
            }
        }
        free(g);
        free(t);
    }
}

static void test_tiles_large(void) {
    /* the largest grids allowed along one axis, every cell needing max_res:
       one tile per cell, the deepest kd-tree */
    static const int dims[][2] = { { 4096, 1 }, { 1, 4096 }, { 64, 64 } };
    int d;
    for (d = 0; d < 3; d++) {
        int gw = dims[d][0], gh = dims[d][1], cells = gw * gh, i, n;
        float *g = (float *)malloc(sizeof(float) * (size_t)(cells * 2));
        sk_tile *t = (sk_tile *)malloc(sizeof(sk_tile) * (size_t)cells);
        char what[128];
        for (i = 0; i < cells; i++) { g[2 * i] = (float)(2.0 / gw / 256.0); g[2 * i + 1] = (float)(2.0 / gh / 256.0); }
        n = sk_fvsm_tiles(g, gw, gh, 256, t, cells);
        sprintf(what, "%dx%d at max_res", gw, gh);
        SK_CHECK_MSG(n == cells, "%s: %d tiles", what, n);
        if (n > 0) SK_CHECK(check_tiles(g, gw, gh, 256, t, n, what) == 0);
        /* random needs, a few cells far over the limit */
        for (i = 0; i < cells; i++) {
            double u = rnd();
            g[2 * i] = u < 0.3 ? INFINITY : (float)(2.0 / gw / (u < 0.31 ? 1e6 : rnd_range(0.1, 300)));
            g[2 * i + 1] = u < 0.3 ? INFINITY : (float)(2.0 / gh / rnd_range(0.1, 300));
        }
        n = sk_fvsm_tiles(g, gw, gh, 256, t, cells);
        sprintf(what, "%dx%d random", gw, gh);
        SK_CHECK_MSG(n > 0, "%s: %d tiles", what, n);
        if (n > 0) SK_CHECK(check_tiles(g, gw, gh, 256, t, n, what) == 0);
        free(g);
        free(t);
    }
}

static int tiles_untouched(const sk_tile *t, int n) {
    int i;
    for (i = 0; i < n; i++)
        if (t[i].x0 != -7 || t[i].y0 != -7 || t[i].x1 != -7 || t[i].y1 != -7 || t[i].res_x != -7 || t[i].res_y != -7)
            return 0;
    return 1;
}

static void test_tiles_bad_input(void) {
    float g[4 * 4 * 2];
    sk_tile t[8];
    int i, r;
    for (i = 0; i < 32; i++) g[i] = 0.5f / 8.0f;
#define BADT(call) do { for (i = 0; i < 8; i++) t[i].x0 = t[i].y0 = t[i].x1 = t[i].y1 = t[i].res_x = t[i].res_y = -7; \
        r = (call); SK_CHECK_MSG(r == -SK_ERR_INVALID_ARG, "%s -> %d", #call, r); \
        SK_CHECK_MSG(tiles_untouched(t, 8), "%s wrote to out", #call); } while (0)
    BADT(sk_fvsm_tiles(NULL, 4, 4, 64, t, 8));
    BADT(sk_fvsm_tiles(g, 0, 4, 64, t, 8));
    BADT(sk_fvsm_tiles(g, 4, 0, 64, t, 8));
    BADT(sk_fvsm_tiles(g, -4, 4, 64, t, 8));
    BADT(sk_fvsm_tiles(g, 4, -4, 64, t, 8));
    BADT(sk_fvsm_tiles(g, 4097, 1, 64, t, 8));
    BADT(sk_fvsm_tiles(g, 1, 4097, 64, t, 8));
    BADT(sk_fvsm_tiles(g, 4, 4, 0, t, 8));
    BADT(sk_fvsm_tiles(g, 4, 4, -64, t, 8));
    BADT(sk_fvsm_tiles(g, 4, 4, 64, NULL, 8));
    BADT(sk_fvsm_tiles(g, 4, 4, 64, t, -1));
#undef BADT
    /* needs many tiles, room for one: capacity error */
    for (i = 0; i < 32; i++) g[i] = 0.5f / 64.0f;   /* 64 texels per cell, max 64 -> 16 tiles */
    r = sk_fvsm_tiles(g, 4, 4, 64, t, 1);
    SK_CHECK_MSG(r == -SK_ERR_CAPACITY, "cap 1 -> %d", r);
    r = sk_fvsm_tiles(g, 4, 4, 64, t, 0);
    SK_CHECK_MSG(r == -SK_ERR_CAPACITY || r == -SK_ERR_INVALID_ARG, "cap 0 -> %d", r);
}

SK_TEST_MAIN(test_rho_peaks, test_rho_values, test_rho_clamps, test_rho_monotone,
             test_convolve_formula, test_convolve_degenerate, test_convolve_bad_input,
             test_coverage_hand, test_coverage_sum, test_coverage_bad_input,
             test_smooth_visibility_values, test_smooth_visibility_continuity, test_smooth_visibility_edges,
             test_predict_hand, test_predict_random, test_predict_singular, test_predict_bad_input,
             test_merge, test_smtg_size, test_smtg_pyramid, test_smtg_bad_input,
             test_tiles_simple, test_tiles_empty, test_tiles_random, test_tiles_large, test_tiles_bad_input)
