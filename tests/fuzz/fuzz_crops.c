/* fuzz_crops: the focused and stable crop builders: sk_fit_ortho,
   sk_stable_crop, sk_crop_matrix, sk_frustum_slice, sk_cascade_sphere and
   sk_frustum_bounding_sphere. The first byte picks the function.
   sk_fit_ortho(pts, count, light_view, casters, out): input count (int
   -1..40) and the points, light_view (fz_mat4), a byte (casters given), a
   box. Checks: SK_ERR_INVALID_ARG exactly on bad input (out untouched),
   else SK_OK and a finite matrix, or SK_ERR_DEGENERATE (out untouched); for a rigid view and moderate values
   every point maps into the clip cube and no caster corner in front of the
   near plane.
   sk_stable_crop(sphere, light_view, res, casters, out): input the sphere,
   light_view, res (int -1..4096), casters. Checks: SK_ERR_INVALID_ARG
   exactly on bad input (out untouched), else SK_OK, a finite matrix; for a
   rigid view and moderate values the sphere's square and depth range map
   into the clip cube, the map is res texels of 2r/(res-1) across, and (res
   up to 16384) its origin sits on that texel grid.
   sk_crop_matrix(r, zmin, zmax): always finite; each axis with a finite,
   non-empty range whose scale 2/(hi-lo) fits a float maps its ends to -1
   and +1, each other axis is the identity.
   sk_frustum_slice(view, zn, zf, d0, d1, out): SK_ERR_INVALID_ARG exactly
   on bad input, out untouched on error; SK_OK: finite corners, each the
   lerp of the view's near and far corner at (d - zn) / (zf - zn).
   sk_cascade_sphere(cam_view, fovy, aspect, d0, d1): finite centre and
   radius; the zero sphere exactly on bad input; for a rigid view and
   moderate values it holds the slice's eight corners.
   sk_frustum_bounding_sphere(f): finite; for a usable frustum of moderate
   size it holds the corners. */
#include "fuzz_common.h"

static int fz_box_ok(const sk_aabb *b)
{
    return fz_v3_finite(b->min) && fz_v3_finite(b->max) && b->min.x <= b->max.x && b->min.y <= b->max.y &&
           b->min.z <= b->max.z;
}

static void fz_fit_ortho(fz_in *in)
{
    int count = fz_int(in, -1, 40), i, lv_mode, has_c, valid, c;
    sk_vec3 *pts;
    sk_mat4 lv, out;
    sk_aabb box;
    sk_result r;
    if (count > 256) count = 256;
    pts = (sk_vec3 *)malloc((size_t)(count > 0 ? count : 1) * sizeof(sk_vec3));
    for (i = 0; i < count; i++) pts[i] = fz_vec3(in);
    lv = fz_mat4_mode(in, &lv_mode);
    has_c = fz_u8(in) & 1;
    box = fz_aabb(in);
    valid = count >= 1 && fz_mat_finite(&lv) && (!has_c || fz_box_ok(&box));
    for (i = 0; i < count; i++) if (!fz_v3_finite(pts[i])) valid = 0;
    FZ_FILL(out);
    r = sk_fit_ortho(pts, count, lv, has_c ? &box : NULL, &out);
    if (!valid) {
        FZ_CHECK(r == SK_ERR_INVALID_ARG && FZ_UNTOUCHED(out), "r = %d on bad input", (int)r);
    } else {
        FZ_CHECK(r == SK_OK || r == SK_ERR_DEGENERATE, "r = %d", (int)r);
        if (r != SK_OK) { FZ_CHECK(FZ_UNTOUCHED(out), "written on error"); free(pts); return; }
        FZ_CHECK(fz_mat_finite(&out), "projection not finite");
        if (lv_mode == FZ_M_VIEW && fz_is_rigid(&lv, 1e4f)) {
            /* every point inside the clip cube. The library transforms in
               float: an error of a few ulps of the largest magnitude at hand,
               allowed relative to each light-view axis's extent (as widened
               by the library, 1e-4 of its magnitude at least) */
            sk_mat4 m = sk_mat4_mul(out, lv);
            int moderate = !has_c || (fz_v3_moderate(box.min, 1e4f) && fz_v3_moderate(box.max, 1e4f));
            double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300}, tol[3], mag = 0.0;
            int k;
            for (i = 0; i < count; i++) {
                double q[3];
                if (!fz_v3_moderate(pts[i], 1e4f)) moderate = 0;
                if (fz_maxabs3(pts[i]) > mag) mag = fz_maxabs3(pts[i]);
                fz_xform(&lv, pts[i], q);
                for (k = 0; k < 3; k++) {
                    if (q[k] < lo[k]) lo[k] = q[k];
                    if (q[k] > hi[k]) hi[k] = q[k];
                }
            }
            for (k = 0; k < 3; k++) {
                double ext = hi[k] - lo[k], wide = 1e-4 * (1.0 + fabs(lo[k]) + fabs(hi[k]));
                if (fabs(lo[k]) > mag) mag = fabs(lo[k]);
                if (fabs(hi[k]) > mag) mag = fabs(hi[k]);
                tol[k] = ext > wide ? ext : wide;
            }
            for (k = 0; k < 3; k++) tol[k] = 1e-4 + 1e-5 * (1.0 + mag) / tol[k];
            if (moderate) {
                for (i = 0; i < count; i++) {
                    double q[3];
                    fz_xform(&m, pts[i], q);
                    FZ_CHECK(fabs(q[0]) <= 1.0 + tol[0] && fabs(q[1]) <= 1.0 + tol[1] && fabs(q[2]) <= 1.0 + tol[2],
                             "point %d (%g %g %g) maps to (%g %g %g), tol %g %g %g", i, pts[i].x, pts[i].y, pts[i].z,
                             q[0], q[1], q[2], tol[0], tol[1], tol[2]);
                }
                for (c = 0; has_c && c < 8; c++) {
                    sk_vec3 p;
                    double q[3];
                    p.x = (c & 1) ? box.max.x : box.min.x;
                    p.y = (c & 2) ? box.max.y : box.min.y;
                    p.z = (c & 4) ? box.max.z : box.min.z;
                    fz_xform(&m, p, q);
                    FZ_CHECK(q[2] >= -1.0 - tol[2] - 1e-5 * (1.0 + fz_maxabs3(p)) / (hi[2] - lo[2] > 1e-3 ? hi[2] - lo[2] : 1e-3),
                             "caster corner %d in front of the near plane: depth %g", c, q[2]);
                }
            }
        }
    }
    FZ_CHECK(sk_fit_ortho(pts, count, lv, NULL, NULL) == SK_ERR_INVALID_ARG, "NULL out");
    free(pts);
}

static void fz_stable_crop(fz_in *in)
{
    sk_sphere s;
    sk_mat4 lv, out;
    sk_aabb box;
    int lv_mode, res, has_c, valid;
    sk_result r;
    s.c = fz_vec3(in);
    s.r = fz_float(in);
    lv = fz_mat4_mode(in, &lv_mode);
    res = fz_int(in, -1, 4096);
    has_c = fz_u8(in) & 1;
    box = fz_aabb(in);
    valid = res >= 2 && fz_v3_finite(s.c) && fz_finite(s.r) && s.r > 0.0f && fz_mat_finite(&lv) &&
            (!has_c || fz_box_ok(&box));
    FZ_FILL(out);
    r = sk_stable_crop(s, lv, res, has_c ? &box : NULL, &out);
    if (!valid) {
        FZ_CHECK(r == SK_ERR_INVALID_ARG && FZ_UNTOUCHED(out), "r = %d on bad input", (int)r);
        return;
    }
    FZ_CHECK(r == SK_OK || r == SK_ERR_DEGENERATE, "r = %d", (int)r);
    if (r != SK_OK) { FZ_CHECK(FZ_UNTOUCHED(out), "written on error"); return; }
    FZ_CHECK(fz_mat_finite(&out), "projection not finite for r %g res %d", s.r, res);
    if (lv_mode == FZ_M_VIEW && fz_is_rigid(&lv, 1e4f) && fz_v3_moderate(s.c, 1e4f) && s.r >= 1e-2f && s.r <= 1e4f &&
        (!has_c || (fz_v3_moderate(box.min, 1e4f) && fz_v3_moderate(box.max, 1e4f)))) {
        double c[3], texel = 2.0 * s.r / (res - 1), tol;
        double sx = out.m[0], sy = out.m[5], ox, oy;
        int k;
        fz_xform(&lv, s.c, c);
        /* the sphere's light-view position in float: an error relative to
           the magnitudes involved, against its radius */
        tol = 1e-4 + 1e-5 * (1.0 + fz_maxabs3(s.c) + fabs(c[0]) + fabs(c[1]) + fabs(c[2]) + fabs(lv.m[12]) +
                             fabs(lv.m[13]) + fabs(lv.m[14])) / s.r;
        for (k = 0; k < 4; k++) {
            double x = c[0] + ((k & 1) ? s.r : -s.r), y = c[1] + ((k & 2) ? s.r : -s.r);
            double px = out.m[0] * x + out.m[12], py = out.m[5] * y + out.m[13];
            FZ_CHECK(fabs(px) <= 1.0 + tol && fabs(py) <= 1.0 + tol, "sphere square corner maps to (%g %g), tol %g", px,
                     py, tol);
        }
        for (k = 0; k < 2; k++) {
            double z = c[2] + (k ? s.r : -s.r), pz = out.m[10] * z + out.m[14];
            FZ_CHECK(fabs(pz) <= 1.0 + tol, "sphere depth %g maps to %g", z, pz);
        }
        /* res texels of the documented size, the left edge on that grid;
           the float matrix holds the edges to a few ulps of their magnitude */
        ox = (-1.0 - out.m[12]) / sx;
        oy = (-1.0 - out.m[13]) / sy;
        {
            double ex = 1e-4 * texel * res + 1e-6 * (fabs(ox) + fabs(c[0]));
            double ey = 1e-4 * texel * res + 1e-6 * (fabs(oy) + fabs(c[1]));
            FZ_CHECK(fabs(2.0 / sx - texel * res) <= ex && fabs(2.0 / sy - texel * res) <= ey,
                     "map %g x %g across, want %d texels of %g", 2.0 / sx, 2.0 / sy, res, texel);
            /* (the float matrix places its edge to about 1e-7 of the map's
               width: a grid of 1/res is resolved for maps of real size) */
            if (res <= 16384)
                FZ_CHECK(fabs(ox / texel - floor(ox / texel + 0.5)) <= 1e-3 + 1e-6 * fabs(ox) / texel &&
                         fabs(oy / texel - floor(oy / texel + 0.5)) <= 1e-3 + 1e-6 * fabs(oy) / texel,
                         "origin (%g %g) off the texel grid %g", ox, oy, texel);
        }
    }
}

static void fz_crop_matrix(fz_in *in)
{
    sk_rect r;
    float z0, z1, lo[3], hi[3];
    sk_mat4 m;
    int k;
    r.x0 = fz_float(in); r.y0 = fz_float(in); r.x1 = fz_float(in); r.y1 = fz_float(in);
    z0 = fz_float(in); z1 = fz_float(in);
    m = sk_crop_matrix(r, z0, z1);
    lo[0] = r.x0; hi[0] = r.x1; lo[1] = r.y0; hi[1] = r.y1; lo[2] = z0; hi[2] = z1;
    FZ_CHECK(fz_mat_finite(&m), "crop not finite");
    for (k = 0; k < 3; k++) {
        float s = m.m[k * 5], t = m.m[12 + k];
        int j;
        for (j = 0; j < 3; j++) if (j != k) FZ_CHECK(m.m[j * 4 + k] == 0.0f, "off-diagonal m[%d]", j * 4 + k);
        FZ_CHECK(m.m[3 + 4 * k] == 0.0f, "row 3");
        if (fz_finite(lo[k]) && fz_finite(hi[k]) && hi[k] > lo[k] && fz_finite((float)(2.0 / ((double)hi[k] - lo[k])))) {
            double a = (double)s * lo[k] + t, b = (double)s * hi[k] + t;
            double tol = 1e-5 * (1.0 + (fabs(lo[k]) + fabs(hi[k])) / ((double)hi[k] - lo[k]));
            FZ_CHECK(fabs(a + 1.0) <= tol && fabs(b - 1.0) <= tol, "axis %d [%g, %g] maps to [%g, %g]", k, lo[k], hi[k],
                     a, b);
        } else {
            FZ_CHECK(s == 1.0f && t == 0.0f, "axis %d with range [%g, %g] not the identity: %g %g", k, lo[k], hi[k], s, t);
        }
    }
    FZ_CHECK(m.m[15] == 1.0f, "m[15] = %g", m.m[15]);
}

static void fz_frustum_slice(fz_in *in)
{
    int fmode, mmode, i, valid;
    sk_frustum view = fz_frustum_mode(in, &fmode, &mmode), out;
    float zn = fz_float(in), zf = fz_float(in), d0 = fz_float(in), d1 = fz_float(in);
    sk_result r;
    valid = fz_frustum_usable(&view) && fz_finite(zn) && fz_finite(zf) && fz_finite(d0) && fz_finite(d1) &&
            zn >= 0.0f && zf > zn && d0 >= zn && d1 > d0 && d1 <= zf;
    FZ_FILL(out);
    r = sk_frustum_slice(&view, zn, zf, d0, d1, &out);
    if (!valid) FZ_CHECK(r == SK_ERR_INVALID_ARG, "r = %d on bad input", (int)r);
    else FZ_CHECK(r == SK_OK || r == SK_ERR_DEGENERATE, "r = %d", (int)r);
    if (r != SK_OK) {
        FZ_CHECK(FZ_UNTOUCHED(out), "written on error %d", (int)r);
        return;
    }
    for (i = 0; i < 8; i++) {
        double t = (((i & 4) ? d1 : d0) - (double)zn) / ((double)zf - zn);
        const sk_vec3 *a = &view.corners[i & 3], *b = &view.corners[(i & 3) + 4];
        double w[3] = {a->x + (b->x - (double)a->x) * t, a->y + (b->y - (double)a->y) * t, a->z + (b->z - (double)a->z) * t};
        double tol = 1e-5 * (1.0 + fz_maxabs3(*a) + fz_maxabs3(*b));
        FZ_CHECK(fz_v3_finite(out.corners[i]), "corner %d not finite", i);
        FZ_CHECK(fabs(out.corners[i].x - w[0]) <= tol && fabs(out.corners[i].y - w[1]) <= tol &&
                 fabs(out.corners[i].z - w[2]) <= tol, "corner %d (%g %g %g), want (%g %g %g)", i, out.corners[i].x,
                 out.corners[i].y, out.corners[i].z, w[0], w[1], w[2]);
    }
    for (i = 0; i < 6; i++) FZ_CHECK(fz_v3_finite(out.planes[i].n) && fz_finite(out.planes[i].d), "plane %d", i);
}

static void fz_cascade_sphere(fz_in *in)
{
    int mode, k;
    sk_mat4 v = fz_mat4_mode(in, &mode);
    float fovy = fz_float(in), aspect = fz_float(in), d0 = fz_float(in), d1 = fz_float(in);
    sk_sphere s = sk_cascade_sphere(v, fovy, aspect, d0, d1);
    int bad = !fz_mat_finite(&v) || !fz_finite(fovy) || !fz_finite(aspect) || !fz_finite(d0) || !fz_finite(d1) ||
              !(fovy > 0.0f) || !((double)fovy < 3.14159265358979323846) || !(aspect > 0.0f) || !(d0 >= 0.0f) ||
              !(d1 > d0);
    FZ_CHECK(fz_v3_finite(s.c) && fz_finite(s.r) && s.r >= 0.0f, "sphere (%g %g %g) r %g for fovy %g aspect %g d %g %g",
             s.c.x, s.c.y, s.c.z, s.r, fovy, aspect, d0, d1);
    if (bad) {
        FZ_CHECK(s.r == 0.0f && s.c.x == 0.0f && s.c.y == 0.0f && s.c.z == 0.0f, "bad input: r %g", s.r);
        return;
    }
    FZ_CHECK(s.r > 0.0f || (s.r == 0.0f && s.c.x == 0.0f && s.c.y == 0.0f && s.c.z == 0.0f), "r %g", s.r);
    if (mode == FZ_M_VIEW && fz_is_rigid(&v, 1e4f) && d1 <= 1e4f && fovy <= 3.0f && aspect >= 1e-2f && aspect <= 1e2f &&
        s.r > 0.0f) {
        /* the slice's corners from the camera's axes (rows of the rotation) */
        double t = tan(0.5 * fovy), eye[3], r2max = 0.0;
        for (k = 0; k < 3; k++)
            eye[k] = -((double)v.m[k * 4] * v.m[12] + (double)v.m[k * 4 + 1] * v.m[13] + (double)v.m[k * 4 + 2] * v.m[14]);
        for (k = 0; k < 8; k++) {
            double d = (k & 4) ? d1 : d0, sx = ((k & 1) ? 1 : -1) * d * t * aspect, sy = ((k & 2) ? 1 : -1) * d * t;
            double p[3], r2 = 0.0;
            int j;
            for (j = 0; j < 3; j++) {
                p[j] = eye[j] + sx * v.m[j * 4] + sy * v.m[j * 4 + 1] - d * v.m[j * 4 + 2];
                r2 += (p[j] - (&s.c.x)[j]) * (p[j] - (&s.c.x)[j]);
            }
            if (r2 > r2max) r2max = r2;
        }
        FZ_CHECK(sqrt(r2max) <= s.r * (1.0 + 1e-5) + 1e-5 * (1.0 + fz_maxabs3(s.c)),
                 "corner %g from the centre, radius %g", sqrt(r2max), s.r);
    }
}

static void fz_bounding_sphere(fz_in *in)
{
    int fmode, mmode, i;
    sk_frustum f = fz_frustum_mode(in, &fmode, &mmode);
    sk_sphere s = sk_frustum_bounding_sphere(&f);
    FZ_CHECK(fz_v3_finite(s.c) && fz_finite(s.r) && s.r >= 0.0f, "sphere (%g %g %g) r %g", s.c.x, s.c.y, s.c.z, s.r);
    s = sk_frustum_bounding_sphere(NULL);
    FZ_CHECK(s.r == 0.0f, "NULL frustum: r %g", s.r);
    s = sk_frustum_bounding_sphere(&f);
    if (fz_frustum_usable(&f) && fz_frustum_moderate(&f, 1e6f))
        for (i = 0; i < 8; i++) {
            double dx = (double)f.corners[i].x - s.c.x, dy = (double)f.corners[i].y - s.c.y, dz = (double)f.corners[i].z - s.c.z;
            FZ_CHECK(sqrt(dx * dx + dy * dy + dz * dz) <= s.r * (1.0 + 1e-6) + 1e-6 * fz_maxabs3(s.c),
                     "corner %d %g from the centre, r %g", i, sqrt(dx * dx + dy * dy + dz * dz), s.r);
        }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size};
    switch (fz_u8(&in) % 6) {
    case 0: fz_fit_ortho(&in); break;
    case 1: fz_stable_crop(&in); break;
    case 2: fz_crop_matrix(&in); break;
    case 3: fz_frustum_slice(&in); break;
    case 4: fz_cascade_sphere(&in); break;
    default: fz_bounding_sphere(&in); break;
    }
    return 0;
}

#ifdef FZ_SEED_MAIN
static void fz_seeds(void)
{
    int k;
    for (k = 0; k < 2; k++) {                      /* sk_fit_ortho */
        fz_out o = {{0}, 0};
        int i;
        fz_put_u8(&o, 0);
        fz_put_int(&o, 8);
        for (i = 0; i < 8; i++) fz_put_vec3(&o, (i & 1) ? 5.0f : -5.0f, (i & 2) ? 3.0f : 0.0f, (i & 4) ? -1.0f : -30.0f);
        fz_put_view(&o, 0, 0, 0, 0.3f, -1, 0.2f);
        fz_put_u8(&o, (unsigned)k);
        fz_put_aabb(&o, -20, 0, -40, 20, 10, 5);
        fz_seed(&o);
    }
    for (k = 0; k < 2; k++) {                      /* sk_stable_crop */
        fz_out o = {{0}, 0};
        fz_put_u8(&o, 1);
        fz_put_vec3(&o, 3.25f, 1.0f, -12.5f);
        fz_put_float(&o, 9.5f);
        fz_put_view(&o, 0, 0, 0, -0.4f, -1, 0.3f);
        fz_put_int(&o, k ? 2048 : 2);
        fz_put_u8(&o, (unsigned)k);
        fz_put_aabb(&o, -20, 0, -40, 20, 10, 5);
        fz_seed(&o);
    }
    {                                              /* sk_crop_matrix */
        fz_out o = {{0}, 0};
        fz_put_u8(&o, 2);
        fz_put_vec2(&o, -0.5f, -0.25f);
        fz_put_vec2(&o, 0.75f, 1.0f);
        fz_put_vec2(&o, -1.0f, 0.5f);
        fz_seed(&o);
    }
    {                                              /* sk_frustum_slice */
        fz_out o = {{0}, 0};
        fz_put_u8(&o, 3);
        fz_put_frustum_persp(&o, 0, 2, 5, 0, 0, -10, 1.0f, 1.5f, 0.5f, 100.0f);
        fz_put_float(&o, 0.5f);
        fz_put_float(&o, 100.0f);
        fz_put_float(&o, 4.0f);
        fz_put_float(&o, 20.0f);
        fz_seed(&o);
    }
    for (k = 0; k < 2; k++) {                      /* sk_cascade_sphere */
        fz_out o = {{0}, 0};
        fz_put_u8(&o, 4);
        fz_put_view(&o, 1, 2, 3, 4, 1, -7);
        fz_put_float(&o, 1.0f);
        fz_put_float(&o, 1.777f);
        fz_put_float(&o, k ? 0.1f : 10.0f);
        fz_put_float(&o, k ? 5.0f : 200.0f);
        fz_seed(&o);
    }
    {                                              /* sk_frustum_bounding_sphere */
        fz_out o = {{0}, 0};
        fz_put_u8(&o, 5);
        fz_put_frustum_persp(&o, 0, 2, 5, 0, 0, -10, 1.0f, 1.5f, 0.5f, 10.0f);
        fz_seed(&o);
    }
}
#endif
