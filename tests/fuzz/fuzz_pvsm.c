/* fuzz_pvsm: sk_convolve_parallelograms and sk_pvsm_predict (with
   sk_rho_dynamic / sk_rho_static through it).
   Input: four vec2 (u0, v0, u1, v1) for the convolution, four vec2 (u_h,
   v_h, u_phi, v_phi) and a byte (bit 0: dynamic scene, bit 1: r0 NULL,
   bit 2: r1 NULL) for the prediction.
   Checks: sk_convolve_parallelograms: outputs always finite, v_out.x = 0,
   u_out.x >= 0, v_out.y >= 0; non-finite input gives zero axes; for
   moderate input U U^T + V V^T equals the summed covariance
   u0 u0^T + v0 v0^T + u1 u1^T + v1 v1^T (relative 1e-5 of its trace).
   sk_pvsm_predict: non-finite input gives +INFINITY on both; finite input
   gives finite r0, r1 >= 0 equal to 2|u_h.x| / rho(n0) and 2|v_h.y| /
   rho(n1) with rho in [rho(1), rho(n_peak)]. */
#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size};
    sk_vec2 a[4], b[4];
    int i, flags, finite = 1;
    for (i = 0; i < 4; i++) { a[i] = fz_vec2(&in); finite &= fz_finite(a[i].x) && fz_finite(a[i].y); }
    {
        sk_vec2 u, v;
        u.x = u.y = v.x = v.y = 7.0f;
        sk_convolve_parallelograms(a[0], a[1], a[2], a[3], &u, &v);
        FZ_CHECK(fz_finite(u.x) && fz_finite(u.y) && fz_finite(v.x) && fz_finite(v.y), "u (%g %g) v (%g %g)", u.x, u.y,
                 v.x, v.y);
        FZ_CHECK(v.x == 0.0f && u.x >= 0.0f && v.y >= 0.0f, "u (%g %g) v (%g %g)", u.x, u.y, v.x, v.y);
        if (!finite) FZ_CHECK(u.x == 0.0f && u.y == 0.0f && v.y == 0.0f, "non-finite input: u (%g %g) v (%g %g)", u.x,
                              u.y, v.x, v.y);
        else {
            double m00 = 0, m10 = 0, m11 = 0, tr, lim = 1e15;
            int moderate = 1;
            for (i = 0; i < 4; i++) {
                moderate &= fabsf(a[i].x) <= lim && fabsf(a[i].y) <= lim;
                m00 += (double)a[i].x * a[i].x;
                m10 += (double)a[i].x * a[i].y;
                m11 += (double)a[i].y * a[i].y;
            }
            tr = m00 + m11;
            if (moderate && tr > 1e-30) {
                double e00 = (double)u.x * u.x - m00, e10 = (double)u.x * u.y - m10,
                       e11 = (double)u.y * u.y + (double)v.y * v.y - m11;
                FZ_CHECK(fabs(e00) <= 1e-5 * tr && fabs(e10) <= 1e-5 * tr && fabs(e11) <= 1e-5 * tr,
                         "covariance off by (%g %g %g), trace %g", e00, e10, e11, tr);
            }
        }
        sk_convolve_parallelograms(a[0], a[1], a[2], a[3], NULL, &v);   /* NULL: nothing, no crash */
        sk_convolve_parallelograms(a[0], a[1], a[2], a[3], &u, NULL);
    }
    finite = 1;
    for (i = 0; i < 4; i++) { b[i] = fz_vec2(&in); finite &= fz_finite(b[i].x) && fz_finite(b[i].y); }
    flags = fz_u8(&in);
    {
        float r0 = 7.0f, r1 = 7.0f;
        int dyn = flags & 1;
        sk_pvsm_predict(b[0], b[1], b[2], b[3], dyn, (flags & 2) ? NULL : &r0, (flags & 4) ? NULL : &r1);
        if (flags & 2) FZ_CHECK(r0 == 7.0f, "r0 written through NULL?");
        if (flags & 4) FZ_CHECK(r1 == 7.0f, "r1 written through NULL?");
        if (!finite) {
            FZ_CHECK(((flags & 2) || r0 == INFINITY) && ((flags & 4) || r1 == INFINITY), "non-finite input: %g %g", r0,
                     r1);
        } else {
            float rho_lo = dyn ? sk_rho_dynamic(1.0f) : sk_rho_static(1.0f);
            float rho_hi = dyn ? sk_rho_dynamic(1e30f) : sk_rho_static(1e30f);
            double a0 = 2.0 * fabs((double)b[0].x), a1 = 2.0 * fabs((double)b[1].y);
            FZ_CHECK(fz_finite(rho_lo) && fz_finite(rho_hi) && rho_lo > 0.0f && rho_hi >= rho_lo, "rho %g %g", rho_lo,
                     rho_hi);
            if (!(flags & 2)) {
                FZ_CHECK(fz_finite(r0) && r0 >= 0.0f, "r0 = %g for u_h.x %g", r0, b[0].x);
                if (a0 / rho_lo < 3e38)
                    FZ_CHECK(r0 >= (float)(a0 / rho_hi) * (1.0f - 1e-6f) && r0 <= (float)(a0 / rho_lo) * (1.0f + 1e-6f),
                             "r0 = %g outside [%g, %g]", r0, a0 / rho_hi, a0 / rho_lo);
            }
            if (!(flags & 4)) {
                FZ_CHECK(fz_finite(r1) && r1 >= 0.0f, "r1 = %g for v_h.y %g", r1, b[1].y);
                if (a1 / rho_lo < 3e38)
                    FZ_CHECK(r1 >= (float)(a1 / rho_hi) * (1.0f - 1e-6f) && r1 <= (float)(a1 / rho_lo) * (1.0f + 1e-6f),
                             "r1 = %g outside [%g, %g]", r1, a1 / rho_hi, a1 / rho_lo);
            }
        }
    }
    return 0;
}

#ifdef FZ_SEED_MAIN
static void fz_seeds(void)
{
    int k;
    for (k = 0; k < 4; k++) {
        fz_out o = {{0}, 0};
        float s = k == 3 ? 0.0f : 1.0f + (float)k;
        fz_put_vec2(&o, 0.5f * s, 0.1f);
        fz_put_vec2(&o, 0.0f, 0.3f * s);
        fz_put_vec2(&o, 0.2f, 0.2f);
        fz_put_vec2(&o, -0.1f, 0.4f);
        fz_put_vec2(&o, 0.01f * s, 0.002f);
        fz_put_vec2(&o, 0.001f, 0.02f);
        fz_put_vec2(&o, 0.004f, 0.0f);
        fz_put_vec2(&o, 0.0f, 0.004f * s);
        fz_put_u8(&o, (unsigned)k);
        fz_seed(&o);
    }
}
#endif
