/* fuzz_lispsm: sk_lispsm_matrices(desc, out).
   Input: eye, view_dir (vec3), zn (float), light_dir (vec3), body_count
   (int -1..200, past SK_CLIP_MAX_POINTS the body is read twice) and that
   many points (vec3), a byte (bit 0: a caster box given), the box (aabb),
   n_override (float).
   Checks: SK_ERR_INVALID_ARG exactly on the documented bad input, out
   untouched; SK_OK or SK_ERR_DEGENERATE otherwise; SK_OK gives a finite
   matrix, sin_gamma in [0, 1], warped 0 or 1, n > 0 (+INFINITY exactly when
   not warped); for moderate values (and a warp no stronger than n >= 1e-3
   of the body's size) every body point lands in the light's clip cube (the
   focus body is what the map covers). */
#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size};
    sk_lispsm_desc d;
    sk_lispsm_result res;
    sk_vec3 *body;
    sk_aabb box;
    int nb, i, bad, moderate;
    sk_result r;
    memset(&d, 0, sizeof d);
    d.eye = fz_vec3(&in);
    d.view_dir = fz_vec3(&in);
    d.zn = fz_float(&in);
    d.light_dir = fz_vec3(&in);
    nb = fz_int(&in, -1, 200);
    if (nb > 512) nb = 512;
    body = (sk_vec3 *)malloc((size_t)(nb > 0 ? nb : 1) * sizeof(sk_vec3));
    for (i = 0; i < nb; i++) body[i] = fz_vec3(&in);
    d.body = nb > 0 || (fz_u8(&in) & 1) ? body : NULL;
    d.body_count = nb;
    box = fz_aabb(&in);
    d.casters = fz_u8(&in) & 1 ? &box : NULL;
    d.n_override = fz_float(&in);
    bad = !fz_v3_finite(d.eye) || !fz_v3_finite(d.view_dir) || !fz_v3_finite(d.light_dir) ||
          (d.view_dir.x == 0.0f && d.view_dir.y == 0.0f && d.view_dir.z == 0.0f) ||
          (d.light_dir.x == 0.0f && d.light_dir.y == 0.0f && d.light_dir.z == 0.0f) || !fz_finite(d.zn) ||
          !(d.zn > 0.0f) || !d.body || nb < 1 || !fz_finite(d.n_override);
    if (d.casters && !(fz_v3_finite(box.min) && fz_v3_finite(box.max) && box.min.x <= box.max.x &&
                       box.min.y <= box.max.y && box.min.z <= box.max.z))
        bad = 1;
    for (i = 0; i < nb; i++) if (!fz_v3_finite(body[i])) bad = 1;
    FZ_FILL(res);
    r = sk_lispsm_matrices(&d, &res);
    if (bad) {
        FZ_CHECK(r == SK_ERR_INVALID_ARG, "r = %d on bad input", (int)r);
        FZ_CHECK(FZ_UNTOUCHED(res), "written on bad input");
    } else {
        FZ_CHECK(r == SK_OK || r == SK_ERR_DEGENERATE, "r = %d", (int)r);
    }
    if (r == SK_OK) {
        FZ_CHECK(fz_mat_finite(&res.light_view_proj), "matrix not finite");
        FZ_CHECK(fz_finite(res.sin_gamma) && res.sin_gamma >= 0.0f && res.sin_gamma <= 1.0f, "sin_gamma %g",
                 res.sin_gamma);
        FZ_CHECK((res.warped == 1 && fz_finite(res.n) && res.n > 0.0f) || (res.warped == 0 && res.n == INFINITY),
                 "warped %d n %g", res.warped, res.n);
        moderate = fz_v3_moderate(d.eye, 1e3f) && d.zn >= 1e-3f && d.zn <= 1e3f &&
                   (d.n_override <= 0.0f || (d.n_override >= 1e-2f && d.n_override <= 1e4f));
        for (i = 0; i < nb && moderate; i++) moderate = fz_v3_moderate(body[i], 1e3f);
        if (moderate) {
            /* spread of the body: a body far smaller than its distance to the
               origin is below float resolution */
            double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300}, ext = 0.0;
            int k;
            for (i = 0; i < nb; i++)
                for (k = 0; k < 3; k++) {
                    double v = (&body[i].x)[k];
                    if (v < lo[k]) lo[k] = v;
                    if (v > hi[k]) hi[k] = v;
                }
            for (k = 0; k < 3; k++) if (hi[k] - lo[k] > ext) ext = hi[k] - lo[k];
            /* (a warp whose projection centre sits closer than 1e-3 of the
               body's size is a far/near of 1e3 and more: float cannot keep
               the body's edges there) */
            if (ext > 1e-2 && (!res.warped || res.n >= 1e-3 * ext))
                for (i = 0; i < nb; i++) {
                    double q[3], w = fz_xform(&res.light_view_proj, body[i], q), tol = 1e-2;
                    FZ_CHECK(w > 0.0 && fabs(q[0] / w) <= 1.0 + tol && fabs(q[1] / w) <= 1.0 + tol &&
                             fabs(q[2] / w) <= 1.0 + tol,
                             "body point %d (%g %g %g) maps to (%g %g %g; w %g), warped %d n %g", i, body[i].x,
                             body[i].y, body[i].z, q[0] / w, q[1] / w, q[2] / w, w, res.warped, res.n);
                }
        }
    }
    free(body);
    return 0;
}

#ifdef FZ_SEED_MAIN
static void fz_seeds(void)
{
    static const float lights[][3] = {{0.3f, -1, 0.2f}, {0, -1, 0.001f}, {0, 0, 1}, {1, -1, 0}, {0, -0.2f, -1}};
    size_t i;
    int k;
    for (i = 0; i < sizeof lights / sizeof lights[0]; i++) {
        fz_out o = {{0}, 0};
        fz_put_vec3(&o, 0, 3, 10);
        fz_put_vec3(&o, 0, -0.2f, -1);
        fz_put_float(&o, 0.5f);
        fz_put_vec3(&o, lights[i][0], lights[i][1], lights[i][2]);
        fz_put_int(&o, 8);
        for (k = 0; k < 8; k++) fz_put_vec3(&o, (k & 1) ? 8.0f : -8.0f, (k & 2) ? 2.0f : 0.0f, (k & 4) ? 9.0f : -40.0f);
        fz_put_aabb(&o, -20, 0, -50, 20, 6, 10);
        fz_put_u8(&o, (unsigned)(i & 1));
        fz_put_float(&o, i == 3 ? 5.0f : 0.0f);
        fz_seed(&o);
    }
}
#endif
