/* fuzz_lspsm_partition: sk_lspsm_partition(n, L, theta, params, out, cap).
   Input: n, L, theta (float), zeta, sigma (float), h_max, nw_max (int, 0..12),
   cap (int, -1..64), then a byte: bit 0 passes NULL params.
   Checks: -SK_ERR_INVALID_ARG exactly on the documented bad input, and then
   nothing written; -SK_ERR_CAPACITY and -SK_ERR_DEGENERATE (a rect float
   cannot hold) write nothing; a count is in [1, min(cap, h_max*nw_max)],
   every rect finite with sides of non-zero length (x0 < x1, y0 < y1), the
   first row starts at y = 0, rows go from near to far and the last reaches
   L; nothing written past the count; the same call with one slot less
   reports -SK_ERR_CAPACITY. */
#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size};
    float n = fz_float(&in), L = fz_float(&in), theta = fz_float(&in);
    sk_lspsm_params p;
    const sk_lspsm_params *pp = &p;
    int cap, r, i, valid;
    size_t bytes;
    sk_rect *out;
    p.zeta = fz_float(&in);
    p.sigma = fz_float(&in);
    p.h_max = fz_int(&in, 0, 12);
    p.nw_max = fz_int(&in, 0, 12);
    cap = fz_int(&in, -1, 64);
    if (cap > 4096) cap = 4096;        /* the buffer is real: cap bounds the work */
    if (fz_u8(&in) & 1) pp = NULL;
    valid = pp && fz_finite(p.zeta) && fz_finite(p.sigma) && p.zeta > 0.0f && p.zeta < 0.5f && p.sigma > 0.0f &&
            p.h_max >= 1 && p.nw_max >= 1 && fz_finite(n) && fz_finite(L) && fz_finite(theta) && n > 0.0f &&
            L > 0.0f && theta >= 0.0f && (double)theta < 0.5 * 3.14159265358979323846 && cap >= 0;
    bytes = (size_t)(cap > 0 ? cap : 0) * sizeof(sk_rect);
    out = (sk_rect *)fz_alloc(bytes);
    r = sk_lspsm_partition(n, L, theta, pp, out, cap);
    if (!valid) {
        FZ_CHECK(r == -(int)SK_ERR_INVALID_ARG, "r = %d on bad input", r);
        FZ_CHECK(fz_untouched(out, bytes), "written on bad input");
    } else if (r < 0) {
        FZ_CHECK(r == -(int)SK_ERR_CAPACITY || r == -(int)SK_ERR_DEGENERATE,
                 "r = %d for n %g L %g theta %.9g zeta %g sigma %g h %d nw %d cap %d",
                 r, n, L, theta, p.zeta, p.sigma, p.h_max, p.nw_max, cap);
        FZ_CHECK(fz_untouched(out, bytes), "written on error %d", r);
    } else {
        float ymax = 0.0f;
        FZ_CHECK(r >= 1 && r <= cap, "count %d, cap %d", r, cap);
        FZ_CHECK((long)r <= (long)p.h_max * p.nw_max, "count %d > h_max %d * nw_max %d", r, p.h_max, p.nw_max);
        FZ_CHECK(fz_guard_ok(out, (size_t)r * sizeof(sk_rect)), "written past the %d rects", r);
        FZ_CHECK(out[0].y0 == 0.0f, "first row starts at %g", out[0].y0);
        for (i = 0; i < r; i++) {
            const sk_rect *q = &out[i];
            FZ_CHECK(fz_finite(q->x0) && fz_finite(q->y0) && fz_finite(q->x1) && fz_finite(q->y1),
                     "rect %d = (%g %g %g %g) for n %g L %g theta %.9g", i, q->x0, q->y0, q->x1, q->y1, n, L, theta);
            FZ_CHECK(q->x0 < q->x1 && q->y0 < q->y1, "rect %d = (%g %g %g %g)", i, q->x0, q->y0, q->x1, q->y1);
            FZ_CHECK(i == 0 || q->y0 >= out[i - 1].y0, "rect %d starts at %g before rect %d at %g", i, q->y0, i - 1,
                     out[i - 1].y0);
            if (q->y1 > ymax) ymax = q->y1;
        }
        FZ_CHECK(ymax >= L, "rows end at %g < L = %g", ymax, L);
        if (r >= 1) {
            int r2 = sk_lspsm_partition(n, L, theta, pp, out, r - 1);
            FZ_CHECK(r2 == -(int)SK_ERR_CAPACITY, "cap %d - 1 gives %d", r, r2);
        }
    }
    free(out);
    return 0;
}

#ifdef FZ_SEED_MAIN
static void fz_seeds(void)
{
    /* n, L, theta, zeta, sigma, h_max, nw_max, cap */
    static const float cases[][8] = {
        {1.0f, 10.0f, 0.3f, 0.25f, 0.5f, 4, 2, 16}, {0.5f, 100.0f, 1.2f, 0.25f, 0.5f, 4, 2, 8},
        {2.0f, 1.0f, 0.0f, 0.25f, 0.5f, 4, 2, 8},   {1e-3f, 1e3f, 1.5f, 0.1f, 0.2f, 8, 4, 64},
        {1.0f, 5.0f, 0.7f, 0.25f, 0.5f, 4, 2, 2}
    };
    size_t i;
    int k;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        fz_out o = {{0}, 0};
        for (k = 0; k < 5; k++) fz_put_float(&o, cases[i][k]);
        for (k = 5; k < 8; k++) fz_put_int(&o, (int)cases[i][k]);
        fz_put_u8(&o, 0);
        fz_seed(&o);
    }
}
#endif
