/* fuzz_pssm_splits: sk_pssm_splits(zn, zf, m, lambda, out).
   Input: zn, zf (float), m (int, -2..20), lambda (float).
   Checks: SK_ERR_INVALID_ARG exactly when the header says (non-finite, m
   outside [1, SK_MAX_SPLITS], lambda outside [0,1], zn < 0, zf <= zn, zn = 0
   with lambda > 0), and then nothing written; otherwise SK_OK with m+1
   finite entries, out[0] = zn, out[m] = zf, non-decreasing, inside [zn, zf],
   each between the uniform and the logarithmic split; nothing written past
   out[m]. */
#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size};
    float zn = fz_float(&in), zf = fz_float(&in);
    int m = fz_int(&in, -2, 20);
    float lambda = fz_float(&in);
    int valid = fz_finite(zn) && fz_finite(zf) && fz_finite(lambda) && m >= 1 && m <= SK_MAX_SPLITS &&
                lambda >= 0.0f && lambda <= 1.0f && zn >= 0.0f && zf > zn && !(lambda > 0.0f && zn == 0.0f);
    /* out holds m+1 entries when m is in range, else one (nothing may be written) */
    size_t cap = (valid ? (size_t)m + 1 : 1) * sizeof(float);
    float *out = (float *)fz_alloc(cap);
    sk_result r = sk_pssm_splits(zn, zf, m, lambda, out);
    if (!valid) {
        FZ_CHECK(r == SK_ERR_INVALID_ARG, "r = %d for zn %g zf %g m %d lambda %g", (int)r, zn, zf, m, lambda);
        FZ_CHECK(fz_untouched(out, cap), "written on error");
    } else {
        int i;
        FZ_CHECK(r == SK_OK, "r = %d for zn %g zf %g m %d lambda %g", (int)r, zn, zf, m, lambda);
        FZ_CHECK(fz_guard_ok(out, cap), "written past out[m]");
        FZ_CHECK(out[0] == zn && out[m] == zf, "ends %g %g, want %g %g", out[0], out[m], zn, zf);
        for (i = 0; i <= m; i++) {
            double f = (double)i / m, uni = zn + ((double)zf - zn) * f;
            double lg = zn > 0.0f ? zn * pow((double)zf / zn, f) : uni;
            double lo = uni < lg ? uni : lg, hi = uni < lg ? lg : uni;
            FZ_CHECK(fz_finite(out[i]), "out[%d] = %g", i, out[i]);
            FZ_CHECK(out[i] >= zn && out[i] <= zf, "out[%d] = %g outside [%g, %g]", i, out[i], zn, zf);
            FZ_CHECK(i == 0 || out[i] >= out[i - 1], "out[%d] = %g < out[%d] = %g", i, out[i], i - 1, out[i - 1]);
            /* a convex combination of the two schemes (float rounding aside) */
            FZ_CHECK(out[i] >= (float)lo * (1.0f - 1e-6f) && out[i] <= (float)hi * (1.0f + 1e-6f),
                     "out[%d] = %g outside [%g, %g]", i, out[i], lo, hi);
        }
    }
    free(out);
    return 0;
}

#ifdef FZ_SEED_MAIN
static void fz_seeds(void)
{
    static const float cases[][4] = {
        {0.1f, 100.0f, 4, 0.5f}, {1.0f, 1000.0f, 8, 1.0f}, {0.0f, 50.0f, 3, 0.0f},
        {0.01f, 1e4f, 16, 0.75f}, {1e-3f, 1e3f, 1, 0.5f}, {0.5f, 0.5f, 4, 0.5f}
    };
    size_t i;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        fz_out o = {{0}, 0};
        fz_put_float(&o, cases[i][0]);
        fz_put_float(&o, cases[i][1]);
        fz_put_int(&o, (int)cases[i][2]);
        fz_put_float(&o, cases[i][3]);
        fz_seed(&o);
    }
}
#endif
