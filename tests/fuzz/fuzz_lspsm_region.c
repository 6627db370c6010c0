/* fuzz_lspsm_region: sk_lspsm_region_extract(view, view_dir, receivers,
   casters, light_dir, out), then sk_lspsm_crops on the region it made.
   Input: view (fz_frustum), view_dir (vec3), receivers (aabb), a byte (bit
   0: casters given), casters (aabb), light_dir (vec3), then h_max, nw_max
   (int 1..8) and cap (int 0..64) for sk_lspsm_crops with the paper's zeta
   and sigma.
   Checks: SK_OK, SK_ERR_INVALID_ARG (only on bad input: non-finite or zero
   directions, an invalid view or box) or SK_ERR_DEGENERATE (only when the
   view misses the receivers), out untouched on error; a region has finite
   fields, n > 0, L > 0, theta in [0, pi/2), zmin <= zmax, fallback 0 or 1;
   for moderate geometry every vertex of the view clipped to the receivers
   lies in the trapezoid (or the fallback's rectangle) and in [zmin, zmax];
   sk_lspsm_crops accepts the region: a count or -SK_ERR_CAPACITY (for
   moderate geometry; -SK_ERR_DEGENERATE allowed beyond), finite matrices. */
#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size};
    int fmode, mmode, has_casters, cap, i, moderate;
    sk_frustum view = fz_frustum_mode(&in, &fmode, &mmode);
    sk_vec3 view_dir = fz_vec3(&in);
    sk_aabb receivers = fz_aabb(&in), casters;
    sk_vec3 light_dir;
    sk_lspsm_region reg;
    sk_lspsm_params p = sk_lspsm_default_params();
    sk_result r;
    sk_vec3 pts[SK_CLIP_MAX_POINTS];
    int npts;
    has_casters = fz_u8(&in) & 1;
    casters = fz_aabb(&in);
    light_dir = fz_vec3(&in);
    p.h_max = fz_int(&in, 1, 8);
    p.nw_max = fz_int(&in, 1, 8);
    cap = fz_int(&in, 0, 64);
    if (p.h_max < 1 || p.h_max > 64) p.h_max = 4;
    if (p.nw_max < 1 || p.nw_max > 64) p.nw_max = 2;
    if (cap < 0 || cap > 4096) cap = 64;
    FZ_FILL(reg);
    r = sk_lspsm_region_extract(&view, view_dir, receivers, has_casters ? &casters : NULL, light_dir, &reg);
    npts = sk_clip_frustum_aabb(&view, receivers, pts, SK_CLIP_MAX_POINTS);
    {
        int bad = !fz_v3_finite(view_dir) || !fz_v3_finite(light_dir) ||
                  (view_dir.x == 0.0f && view_dir.y == 0.0f && view_dir.z == 0.0f) ||
                  (light_dir.x == 0.0f && light_dir.y == 0.0f && light_dir.z == 0.0f) || npts < 0;
        if (has_casters && !(fz_v3_finite(casters.min) && fz_v3_finite(casters.max) && casters.min.x <= casters.max.x &&
                             casters.min.y <= casters.max.y && casters.min.z <= casters.max.z))
            bad = 1;
        if (bad) FZ_CHECK(r == SK_ERR_INVALID_ARG, "r = %d on bad input", (int)r);
        else if (npts == 0) FZ_CHECK(r == SK_ERR_DEGENERATE, "r = %d with no receiver in view", (int)r);
        else FZ_CHECK(r == SK_OK || r == SK_ERR_DEGENERATE, "r = %d with %d clipped points", (int)r, npts);
    }
    if (r != SK_OK) {
        FZ_CHECK(FZ_UNTOUCHED(reg), "region written on error %d", (int)r);
        return 0;
    }
    FZ_CHECK(fz_mat_finite(&reg.light_view), "light_view not finite");
    FZ_CHECK(fz_finite(reg.origin.x) && fz_finite(reg.origin.y) && fz_finite(reg.n) && fz_finite(reg.L) &&
             fz_finite(reg.theta) && fz_finite(reg.zmin) && fz_finite(reg.zmax),
             "region (%g %g) n %g L %g theta %g z [%g %g]", reg.origin.x, reg.origin.y, reg.n, reg.L, reg.theta,
             reg.zmin, reg.zmax);
    FZ_CHECK(reg.n > 0.0f && reg.L > 0.0f && reg.theta >= 0.0f && (double)reg.theta < 0.5 * 3.14159265358979323846 &&
             reg.zmin <= reg.zmax && (reg.fallback == 0 || reg.fallback == 1),
             "region n %g L %g theta %.9g z [%g %g] fallback %d", reg.n, reg.L, reg.theta, reg.zmin, reg.zmax,
             reg.fallback);
    /* the trapezoid holds the clipped view body */
    moderate = fz_frustum_moderate(&view, 1e4f) && fz_v3_moderate(receivers.min, 1e4f) &&
               fz_v3_moderate(receivers.max, 1e4f) &&
               (!has_casters || (fz_v3_moderate(casters.min, 1e4f) && fz_v3_moderate(casters.max, 1e4f)));
    if (fmode == FZ_F_MATRIX || fmode == FZ_F_AABB) {
        if (moderate) {
            double t = tan((double)reg.theta), ext = reg.L + reg.n + 2.0 * reg.L * t, mag = 0.0;
            /* the library places the points in float: an error relative to
               their world coordinates and the view's translation */
            for (i = 0; i < 3; i++) if (fabs(reg.light_view.m[12 + i]) > mag) mag = fabs(reg.light_view.m[12 + i]);
            for (i = 0; i < npts; i++) if (fz_maxabs3(pts[i]) > mag) mag = fz_maxabs3(pts[i]);
            for (i = 0; i < npts; i++) {
                double q[3], y, hw, tol;
                fz_xform(&reg.light_view, pts[i], q);
                tol = 1e-4 * (1.0 + ext + fabs(q[0]) + fabs(q[1]) + fabs(q[2])) + 1e-5 * mag;
                y = q[1] - reg.origin.y;
                hw = 0.5 * reg.n + (reg.fallback ? 0.0 : y * t);
                FZ_CHECK(y >= -tol && y <= reg.L + tol, "point %d: y %g outside [0, L = %g] (tol %g)", i, y, reg.L, tol);
                FZ_CHECK(fabs(q[0] - reg.origin.x) <= hw + tol, "point %d: |x - ox| = %g > half width %g (tol %g)", i,
                         fabs(q[0] - reg.origin.x), hw, tol);
                FZ_CHECK(q[2] >= reg.zmin - tol && q[2] <= reg.zmax + tol, "point %d: z %g outside [%g, %g]", i, q[2],
                         reg.zmin, reg.zmax);
            }
        }
    }
    /* sk_lspsm_crops takes every region sk_lspsm_region_extract makes of
       moderate geometry (far out, where the clip's relative tolerance
       admits points float cannot place, the region may be degenerate) */
    {
        size_t vbytes = (size_t)cap * sizeof(sk_mat4);
        sk_mat4 *vps = (sk_mat4 *)fz_alloc(vbytes);
        int c = sk_lspsm_crops(&reg, &p, vps, NULL, cap);
        FZ_CHECK(c > 0 || c == -(int)SK_ERR_CAPACITY || (!moderate && c == -(int)SK_ERR_DEGENERATE),
                 "sk_lspsm_crops = %d on region n %g L %g theta %.9g", c, reg.n, reg.L, reg.theta);
        if (c > 0) {
            FZ_CHECK(c <= cap && fz_guard_ok(vps, (size_t)c * sizeof(sk_mat4)), "count %d cap %d", c, cap);
            for (i = 0; i < c; i++) FZ_CHECK(fz_mat_finite(&vps[i]), "matrix %d not finite", i);
        } else {
            FZ_CHECK(fz_untouched(vps, vbytes), "written on -SK_ERR_CAPACITY");
        }
        free(vps);
    }
    return 0;
}

#ifdef FZ_SEED_MAIN
static void fz_seeds(void)
{
    /* camera eye, target; light direction */
    static const float cases[][9] = {
        {0, 5, 0, 10, 4, 10, -0.3f, -1.0f, 0.2f}, {0, 2, 0, 0, 2, 10, 0.0f, -1.0f, 0.0f},
        {0, 5, 0, 0, 0, 10, 0.0f, -1.0f, 1.0f},   {-10, 20, -10, 0, 0, 0, 1.0f, -0.5f, 0.0f},
        {0, 3, 0, 10, 3, 0, 0.0f, 0.0f, 1.0f}
    };
    size_t i;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const float *c = cases[i];
        fz_out o = {{0}, 0};
        fz_put_frustum_persp(&o, c[0], c[1], c[2], c[3], c[4], c[5], 1.0f, 1.5f, 0.1f, 60.0f);
        fz_put_vec3(&o, c[3] - c[0], c[4] - c[1], c[5] - c[2]);
        fz_put_aabb(&o, -30, -1, -30, 30, 4, 30);
        fz_put_u8(&o, (unsigned)(i & 1));
        fz_put_aabb(&o, -30, -1, -30, 30, 8, 30);
        fz_put_vec3(&o, c[6], c[7], c[8]);
        fz_put_int(&o, 4);
        fz_put_int(&o, 2);
        fz_put_int(&o, 16);
        fz_seed(&o);
    }
}
#endif
