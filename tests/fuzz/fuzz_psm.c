/* fuzz_psm: sk_psm_matrices(desc, out).
   Input: cam_view (fz_mat4), fovy, aspect, zn, zf (float), light_dir (vec3),
   caster_count (int -1..40, a count past 32 takes the path that does not
   cache corners) and that many boxes (aabb), body_count (int -1..150) and
   that many points (vec3), extra_slide (float).
   Checks: SK_ERR_INVALID_ARG exactly on the documented bad input, out
   untouched; SK_OK or SK_ERR_DEGENERATE otherwise; SK_OK gives finite
   matrices, light_pp and slide (slide >= extra_slide), compare GREATER
   exactly when inverted; for a rigid camera, moderate values and a virtual
   camera with far/near at most 1e3, every body point inside the view
   frustum lands inside the light's clip square. */
#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size};
    sk_psm_desc d;
    sk_psm_result res;
    sk_aabb *casters;
    sk_vec3 *body;
    int cam_mode, nc, nb, i, bad;
    sk_result r;
    memset(&d, 0, sizeof d);
    d.cam_view = fz_mat4_mode(&in, &cam_mode);
    d.fovy = fz_float(&in);
    d.aspect = fz_float(&in);
    d.zn = fz_float(&in);
    d.zf = fz_float(&in);
    d.light_dir = fz_vec3(&in);
    nc = fz_int(&in, -1, 40);
    if (nc > 64) nc = 64;                    /* the array is real: no more than it holds */
    casters = (sk_aabb *)malloc((size_t)(nc > 0 ? nc : 1) * sizeof(sk_aabb));
    for (i = 0; i < nc; i++) casters[i] = fz_aabb(&in);
    nb = fz_int(&in, -1, 150);
    if (nb > 256) nb = 256;
    body = (sk_vec3 *)malloc((size_t)(nb > 0 ? nb : 1) * sizeof(sk_vec3));
    for (i = 0; i < nb; i++) body[i] = fz_vec3(&in);
    d.extra_slide = fz_float(&in);
    d.casters = nc > 0 || (fz_u8(&in) & 1) ? casters : NULL;
    d.caster_count = nc;
    d.body = nb > 0 || (fz_u8(&in) & 1) ? body : NULL;
    d.body_count = nb;
    bad = !fz_mat_finite(&d.cam_view) || !fz_v3_finite(d.light_dir) ||
          (d.light_dir.x == 0.0f && d.light_dir.y == 0.0f && d.light_dir.z == 0.0f) || !fz_finite(d.fovy) ||
          !fz_finite(d.aspect) || !fz_finite(d.zn) || !fz_finite(d.zf) || !(d.fovy > 0.0f) ||
          !((double)d.fovy < 3.14159265358979323846) || !(d.aspect > 0.0f) || !(d.zn > 0.0f) || !(d.zf > d.zn) ||
          nc < 0 || nb < 0 || nb > SK_CLIP_MAX_POINTS || !fz_finite(d.extra_slide) || d.extra_slide < 0.0f;
    for (i = 0; i < nc; i++)
        if (!(fz_v3_finite(casters[i].min) && fz_v3_finite(casters[i].max) && casters[i].min.x <= casters[i].max.x &&
              casters[i].min.y <= casters[i].max.y && casters[i].min.z <= casters[i].max.z))
            bad = 1;
    for (i = 0; i < nb && nb <= SK_CLIP_MAX_POINTS; i++) if (!fz_v3_finite(body[i])) bad = 1;
    /* a NULL light_dir vector cannot be expressed; a zero one can */
    FZ_FILL(res);
    r = sk_psm_matrices(&d, &res);
    if (bad) {
        FZ_CHECK(r == SK_ERR_INVALID_ARG, "r = %d on bad input", (int)r);
        FZ_CHECK(FZ_UNTOUCHED(res), "written on bad input");
    } else {
        FZ_CHECK(r == SK_OK || r == SK_ERR_DEGENERATE, "r = %d", (int)r);
    }
    if (r == SK_OK) {
        FZ_CHECK(fz_mat_finite(&res.light_view_proj) && fz_mat_finite(&res.virtual_cam_view_proj), "matrices not finite");
        FZ_CHECK(fz_v3_finite(res.light_pp) && fz_finite(res.slide) && res.slide >= d.extra_slide,
                 "light_pp (%g %g %g) slide %g (extra %g)", res.light_pp.x, res.light_pp.y, res.light_pp.z, res.slide,
                 d.extra_slide);
        FZ_CHECK((res.inverted == 0 || res.inverted == 1) && (res.orthographic == 0 || res.orthographic == 1) &&
                 (res.compare == SK_DEPTH_GREATER) == (res.inverted == 1), "inverted %d compare %d ortho %d",
                 res.inverted, (int)res.compare, res.orthographic);
        /* body points in the view frustum are covered by the map */
        if (cam_mode == FZ_M_VIEW && fz_is_rigid(&d.cam_view, 1e3f) && d.zn >= 1e-2f && d.zf <= 1e3f &&
            d.zf >= 2.0f * d.zn && d.fovy >= 0.1f && d.fovy <= 2.5f && d.aspect >= 0.1f && d.aspect <= 10.0f &&
            d.extra_slide <= 1e2f && ((double)res.slide + d.zf) / ((double)d.zn + d.extra_slide) <= 1e3) {
            /* (post-perspective depth resolves eye depth D to about
               3e-8 D / near: past far/near = 1e3 of the virtual camera, slid
               back for the casters, the fit loses the body to float) */
            sk_mat4 proj = sk_mat4_perspective(d.fovy, d.aspect, d.zn, d.zf), cvp = sk_mat4_mul(proj, d.cam_view);
            for (i = 0; i < nb; i++) {
                double c[3], w = fz_xform(&cvp, body[i], c), q[3], lw;
                if (!fz_v3_moderate(body[i], 1e3f) || !(w > 0.0) || fabs(c[0]) > 0.99 * w || fabs(c[1]) > 0.99 * w ||
                    fabs(c[2]) > 0.99 * w)
                    continue;
                lw = fz_xform(&res.light_view_proj, body[i], q);
                FZ_CHECK(lw != 0.0 && fabs(q[0] / lw) <= 1.0 + 1e-2 && fabs(q[1] / lw) <= 1.0 + 1e-2,
                         "body point %d (%g %g %g) in view maps to (%g %g) (w %g; inverted %d ortho %d)", i, body[i].x,
                         body[i].y, body[i].z, q[0] / lw, q[1] / lw, lw, res.inverted, res.orthographic);
            }
        }
    }
    free(casters);
    free(body);
    return 0;
}

#ifdef FZ_SEED_MAIN
static void fz_seeds(void)
{
    /* light directions: overhead, from behind the viewer, towards the
       viewer, perpendicular to the view, along the view */
    static const float lights[][3] = {{0.3f, -1, 0.2f}, {0, -0.5f, -1}, {0, -0.5f, 1}, {1, 0, 0}, {0, 0, -1}};
    size_t i;
    int k;
    for (i = 0; i < sizeof lights / sizeof lights[0]; i++) {
        fz_out o = {{0}, 0};
        fz_put_view(&o, 0, 3, 10, 0, 0, 0);
        fz_put_float(&o, 1.0f);
        fz_put_float(&o, 1.5f);
        fz_put_float(&o, 0.5f);
        fz_put_float(&o, 60.0f);
        fz_put_vec3(&o, lights[i][0], lights[i][1], lights[i][2]);
        fz_put_int(&o, (int)i);
        for (k = 0; k < (int)i; k++) fz_put_aabb(&o, -2.0f + k, 0, -2, 0.0f + k, 3, 12);
        fz_put_int(&o, 8);
        for (k = 0; k < 8; k++) fz_put_vec3(&o, (k & 1) ? 10.0f : -10.0f, (k & 2) ? 2.0f : 0.0f, (k & 4) ? 5.0f : -20.0f);
        fz_put_float(&o, i == 4 ? 2.0f : 0.0f);
        fz_seed(&o);
    }
}
#endif
