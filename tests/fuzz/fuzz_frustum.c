/* fuzz_frustum: sk_frustum_from_matrix, sk_frustum_from_corners,
   sk_frustum_from_aabb and sk_clip_frustum_aabb.
   Input: a matrix (fz_mat4), 8 corners (vec3), a box (aabb), then for the
   clip a frustum (fz_frustum), a box (aabb) and cap (int -1..144).
   Checks: from_matrix gives the all-zero frustum exactly when the matrix is
   singular or not finite (sk_mat4_inverse fails), else either all zero
   (a volume through infinity, or beyond float) or finite corners and planes
   with unit normals, each corner inside every plane (tolerance relative to
   the frustum's size and the matrix's condition number); from_corners: SK_ERR_INVALID_ARG exactly
   for a non-finite corner, an error leaves out untouched, SK_OK copies the
   corners and gives finite unit-normal planes; from_aabb: SK_ERR_INVALID_ARG
   exactly for a bad box (out untouched), else the box's corners and planes.
   sk_clip_frustum_aabb: -SK_ERR_INVALID_ARG exactly for an unusable frustum,
   a bad box or cap < 0; -SK_ERR_CAPACITY only when the points do not fit
   (and never with cap = SK_CLIP_MAX_POINTS), nothing written on error; a
   count <= cap of finite points, nothing written past them; for a
   matrix or box frustum of moderate size every point lies in the box and in
   the frustum (within a tolerance relative to their size, plus as far as
   the frustum's own corners lie outside its planes). */
#include "fuzz_common.h"

/* largest |coordinate| of a frustum's corners (its scale) */
static double fz_frustum_scale(const sk_frustum *f)
{
    double s = 0.0;
    int i;
    for (i = 0; i < 8; i++) if (fz_maxabs3(f->corners[i]) > s) s = fz_maxabs3(f->corners[i]);
    return s;
}

static void fz_check_planes(const sk_frustum *f, const char *what)
{
    int k;
    for (k = 0; k < 6; k++) {
        const sk_plane *p = &f->planes[k];
        double l = sqrt((double)p->n.x * p->n.x + (double)p->n.y * p->n.y + (double)p->n.z * p->n.z);
        FZ_CHECK(fz_v3_finite(p->n) && fz_finite(p->d), "%s: plane %d (%g %g %g; %g)", what, k, p->n.x, p->n.y,
                 p->n.z, p->d);
        FZ_CHECK(fabs(l - 1.0) < 1e-5, "%s: plane %d normal length %.9g", what, k, l);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size};
    int i, k;
    /* sk_frustum_from_matrix */
    {
        sk_mat4 m = fz_mat4(&in), inv;
        sk_frustum f = sk_frustum_from_matrix(m), zero;
        memset(&zero, 0, sizeof zero);
        if (!sk_mat4_inverse(m, &inv)) {
            FZ_CHECK(memcmp(&f, &zero, sizeof f) == 0, "singular matrix: frustum not all zero");
        } else if (memcmp(&f, &zero, sizeof f) != 0) {
            double s = fz_frustum_scale(&f), ma = 0.0, mi = 0.0, cond;
            for (i = 0; i < 8; i++) FZ_CHECK(fz_v3_finite(f.corners[i]), "corner %d not finite", i);
            fz_check_planes(&f, "from_matrix");
            /* the corners are the unprojected NDC cube: inside every plane,
               up to float rounding amplified by the matrix's condition
               (corners from the inverse, planes from the matrix's rows) */
            for (i = 0; i < 16; i++) {
                if (fabs(m.m[i]) > ma) ma = fabs(m.m[i]);
                if (fabs(inv.m[i]) > mi) mi = fabs(inv.m[i]);
            }
            cond = 16.0 * ma * mi;
            /* and by the cancellation in each corner's w (far corners of a
               deep perspective have w near 0 out of terms near 1) */
            for (i = 0; i < 8; i++) {
                double w = 0.0, wa = 0.0;
                for (k = 0; k < 4; k++) {
                    double c = k == 3 ? 1.0 : ((i >> k) & 1) ? 1.0 : -1.0;
                    w += inv.m[k * 4 + 3] * c;
                    wa += fabs(inv.m[k * 4 + 3] * c);
                }
                if (wa > fabs(w) * cond / (16.0 * ma * mi)) cond = 16.0 * ma * mi * wa / fabs(w);
            }
            if (s < 1e6 && cond < 1e7)
                for (i = 0; i < 8; i++)
                    for (k = 0; k < 6; k++) {
                        double d = fz_plane_dist(&f.planes[k], f.corners[i]);
                        FZ_CHECK(d >= -(1e-3 + 1e-6 * cond) * (1.0 + s), "corner %d outside plane %d by %g (scale %g, cond %g)",
                                 i, k, d, s, cond);
                    }
        }
    }
    /* sk_frustum_from_corners */
    {
        sk_vec3 c[8];
        sk_frustum f;
        sk_result r;
        int finite = 1;
        for (i = 0; i < 8; i++) { c[i] = fz_vec3(&in); finite &= fz_v3_finite(c[i]); }
        FZ_FILL(f);
        r = sk_frustum_from_corners(c, &f);
        if (!finite) FZ_CHECK(r == SK_ERR_INVALID_ARG, "non-finite corner: %d", (int)r);
        else FZ_CHECK(r == SK_OK || r == SK_ERR_DEGENERATE, "r = %d", (int)r);
        if (r != SK_OK) {
            FZ_CHECK(FZ_UNTOUCHED(f), "written on error %d", (int)r);
        } else {
            FZ_CHECK(memcmp(f.corners, c, sizeof c) == 0, "corners not copied");
            fz_check_planes(&f, "from_corners");
        }
        FZ_CHECK(sk_frustum_from_corners(NULL, &f) == SK_ERR_INVALID_ARG && sk_frustum_from_corners(c, NULL) ==
                 SK_ERR_INVALID_ARG, "NULL accepted");
    }
    /* sk_frustum_from_aabb */
    {
        sk_aabb b = fz_aabb(&in);
        sk_frustum f;
        sk_result r;
        int ok = fz_v3_finite(b.min) && fz_v3_finite(b.max) && b.min.x <= b.max.x && b.min.y <= b.max.y &&
                 b.min.z <= b.max.z;
        FZ_FILL(f);
        r = sk_frustum_from_aabb(b, &f);
        if (!ok) {
            FZ_CHECK(r == SK_ERR_INVALID_ARG && FZ_UNTOUCHED(f), "bad box: r = %d", (int)r);
        } else {
            FZ_CHECK(r == SK_OK, "r = %d", (int)r);
            for (i = 0; i < 8; i++) {
                sk_vec3 p = f.corners[i];
                FZ_CHECK(p.x == ((i & 1) ? b.max.x : b.min.x) && p.y == ((i & 2) ? b.max.y : b.min.y) &&
                         p.z == ((i & 4) ? b.max.z : b.min.z), "corner %d", i);
                for (k = 0; k < 6; k++) FZ_CHECK(fz_plane_dist(&f.planes[k], p) >= 0.0, "corner %d outside plane %d", i, k);
            }
            fz_check_planes(&f, "from_aabb");
        }
    }
    /* sk_clip_frustum_aabb */
    {
        int fmode, mmode;
        sk_frustum f = fz_frustum_mode(&in, &fmode, &mmode);
        sk_aabb b = fz_aabb(&in);
        int cap = fz_int(&in, -1, SK_CLIP_MAX_POINTS), n, valid;
        size_t bytes;
        sk_vec3 *out;
        if (cap > 4096) cap = 4096;
        valid = fz_frustum_usable(&f) && cap >= 0 && fz_v3_finite(b.min) && fz_v3_finite(b.max) &&
                b.min.x <= b.max.x && b.min.y <= b.max.y && b.min.z <= b.max.z;
        bytes = (size_t)(cap > 0 ? cap : 0) * sizeof(sk_vec3);
        out = (sk_vec3 *)fz_alloc(bytes);
        n = sk_clip_frustum_aabb(&f, b, out, cap);
        if (!valid) {
            FZ_CHECK(n == -(int)SK_ERR_INVALID_ARG, "n = %d on bad input", n);
            FZ_CHECK(fz_untouched(out, bytes), "written on bad input");
        } else if (n < 0) {
            sk_vec3 all[SK_CLIP_MAX_POINTS];
            FZ_CHECK(n == -(int)SK_ERR_CAPACITY, "n = %d", n);
            FZ_CHECK(fz_untouched(out, bytes), "written on -SK_ERR_CAPACITY");
            k = sk_clip_frustum_aabb(&f, b, all, SK_CLIP_MAX_POINTS);
            FZ_CHECK(k > cap, "cap %d too small, yet SK_CLIP_MAX_POINTS gives %d", cap, k);
        } else {
            FZ_CHECK(n <= cap && n <= SK_CLIP_MAX_POINTS, "n = %d, cap %d", n, cap);
            FZ_CHECK(fz_guard_ok(out, (size_t)n * sizeof(sk_vec3)), "written past %d points", n);
            for (i = 0; i < n; i++) FZ_CHECK(fz_v3_finite(out[i]), "point %d (%g %g %g)", i, out[i].x, out[i].y, out[i].z);
            if ((fmode == FZ_F_MATRIX || fmode == FZ_F_AABB) && fz_frustum_moderate(&f, 1e5f) &&
                fz_frustum_solid(&f, 1e-3) &&
                fz_v3_moderate(b.min, 1e5f) && fz_v3_moderate(b.max, 1e5f)) {
                double s = fz_frustum_scale(&f), sb = fz_maxabs3(b.min) > fz_maxabs3(b.max) ? fz_maxabs3(b.min)
                                                                                           : fz_maxabs3(b.max);
                double tol = 1e-3 * (1.0 + (s > sb ? s : sb)), slack = 0.0;
                /* a matrix frustum's own corners may lie outside its planes
                   (rounding, more for an ill-conditioned matrix); a clipped
                   point on a corner or an edge may lie as far outside */
                for (i = 0; i < 8; i++)
                    for (k = 0; k < 6; k++)
                        if (-fz_plane_dist(&f.planes[k], f.corners[i]) > slack)
                            slack = -fz_plane_dist(&f.planes[k], f.corners[i]);
                for (i = 0; i < n; i++) {
                    sk_vec3 p = out[i];
                    FZ_CHECK(p.x >= b.min.x - tol && p.x <= b.max.x + tol && p.y >= b.min.y - tol &&
                             p.y <= b.max.y + tol && p.z >= b.min.z - tol && p.z <= b.max.z + tol,
                             "point %d (%g %g %g) outside the box (tol %g)", i, p.x, p.y, p.z, tol);
                    for (k = 0; k < 6; k++)
                        FZ_CHECK(fz_plane_dist(&f.planes[k], p) >= -tol - slack,
                                 "point %d outside plane %d by %g (tol %g, the corners' own %g)", i, k,
                                 fz_plane_dist(&f.planes[k], p), tol, slack);
                }
            }
        }
        free(out);
    }
    return 0;
}

#ifdef FZ_SEED_MAIN
static void fz_seeds(void)
{
    int k;
    for (k = 0; k < 5; k++) {
        fz_out o = {{0}, 0};
        int i;
        if (k & 1) fz_put_ortho(&o, 0, 0, 10, 0, 0, 0, -3, 3, -2, 2, 1, 30);
        else fz_put_persp(&o, 1, 2, 3, 0, 0, -10, 1.2f, 1.5f, 0.1f, 100.0f);
        for (i = 0; i < 8; i++)   /* a frustum's corners: near square 1, far square 4 */
            fz_put_vec3(&o, ((i & 1) ? 1.0f : -1.0f) * ((i & 4) ? 4.0f : 1.0f),
                        ((i & 2) ? 1.0f : -1.0f) * ((i & 4) ? 4.0f : 1.0f), (i & 4) ? -10.0f : -1.0f);
        fz_put_aabb(&o, -1, -2, -3, 4, 5, 6);
        if (k < 3) fz_put_frustum_persp(&o, 0, 2, 0, (float)k, 1, -10, 1.0f, 1.0f, 0.5f, 40.0f);
        else fz_put_frustum_aabb(&o, -1, -1, -1, 1, 1, 1);
        fz_put_aabb(&o, -5, 0, -20, 5, 3, -2 + (float)k);
        fz_put_int(&o, k == 4 ? 3 : SK_CLIP_MAX_POINTS);
        fz_seed(&o);
    }
}
#endif
