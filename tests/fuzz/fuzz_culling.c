/* fuzz_culling: sk_frustum_intersects, sk_cube_visible_faces,
   sk_caster_shadow_frustum and sk_caster_visible.
   Input: two frusta a, b (fz_frustum), a point weight vector (8 bytes), a
   light position (vec3), zn, zf, light_range (float), a caster box (aabb),
   8 more weight bytes.
   Checks: sk_frustum_intersects is 0 or 1, symmetric, 1 when either frustum
   is unusable, 1 when a point inside both (a corner mix of a, inside b by a
   margin) exists; an aabb frustum intersects itself. sk_cube_visible_faces:
   within 0x3f, 0x3f for bad input, and the bit of the face holding a point
   of the view (inside it by a margin, and strictly inside that face's
   pyramid between zn and zf) set. sk_caster_shadow_frustum:
   SK_ERR_INVALID_ARG exactly on bad input, out untouched on error;
   SK_ERR_DEGENERATE only when no corner of the box is within range; SK_OK:
   finite planes, and every box corner within range inside the frustum.
   sk_caster_visible: 0 or 1, 1 on bad input, 0 only if the shadow frustum
   is degenerate or misses the view, and 1 when a box corner within range
   lies inside the view by a margin. */
#include "fuzz_common.h"

static double fz_scale2(const sk_frustum *a, const sk_frustum *b)
{
    double s = 0.0;
    int i;
    for (i = 0; i < 8; i++) {
        if (fz_maxabs3(a->corners[i]) > s) s = fz_maxabs3(a->corners[i]);
        if (fz_maxabs3(b->corners[i]) > s) s = fz_maxabs3(b->corners[i]);
    }
    return s;
}

/* a consistent (convex, planes matching corners) frustum of moderate size */
static int fz_convex(int mode, const sk_frustum *f)
{
    return (mode == FZ_F_MATRIX || mode == FZ_F_AABB) && fz_frustum_usable(f) && fz_frustum_moderate(f, 1e4f);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size};
    int ma, mb, mm, i;
    sk_frustum a = fz_frustum_mode(&in, &ma, &mm), b = fz_frustum_mode(&in, &mb, &mm);
    sk_vec3 p = fz_point_in(&in, &a);
    sk_vec3 light = fz_vec3(&in);
    float zn = fz_float(&in), zf = fz_float(&in), range = fz_float(&in);
    sk_aabb box = fz_aabb(&in);
    sk_vec3 q = fz_point_in(&in, &b);
    /* sk_frustum_intersects */
    {
        int ab = sk_frustum_intersects(&a, &b), ba = sk_frustum_intersects(&b, &a);
        FZ_CHECK(ab == 0 || ab == 1, "intersects = %d", ab);
        FZ_CHECK(ab == ba, "not symmetric: %d %d", ab, ba);
        if (!fz_frustum_usable(&a) || !fz_frustum_usable(&b)) FZ_CHECK(ab == 1, "unusable frustum culled");
        FZ_CHECK(sk_frustum_intersects(NULL, &b) == 1 && sk_frustum_intersects(&a, NULL) == 1, "NULL culled");
        if (fz_convex(ma, &a) && fz_convex(mb, &b)) {
            double s = fz_scale2(&a, &b);
            if (fz_inside_by(&b, p, 1e-3 * (1.0 + s)) && fz_inside_by(&a, p, 1e-3 * (1.0 + s)))
                FZ_CHECK(ab == 1, "point (%g %g %g) inside both, intersects = 0", p.x, p.y, p.z);
            if (fz_inside_by(&a, q, 1e-3 * (1.0 + s)) && fz_inside_by(&b, q, 1e-3 * (1.0 + s)))
                FZ_CHECK(ab == 1, "point (%g %g %g) inside both, intersects = 0", q.x, q.y, q.z);
        }
        if (ma == FZ_F_AABB && fz_frustum_usable(&a)) FZ_CHECK(sk_frustum_intersects(&a, &a) == 1, "box misses itself");
    }
    /* sk_cube_visible_faces: the view is b */
    {
        unsigned bits = sk_cube_visible_faces(light, zn, zf, &b);
        int bad = !fz_v3_finite(light) || !fz_finite(zn) || !fz_finite(zf) || !(zn > 0.0f) || !(zf > zn) ||
                  !fz_frustum_usable(&b);
        FZ_CHECK(bits <= 0x3fu, "bits %#x", bits);
        if (bad) FZ_CHECK(bits == 0x3fu, "bad input gives %#x", bits);
        FZ_CHECK(sk_cube_visible_faces(light, zn, zf, NULL) == 0x3fu, "NULL view");
        if (!bad && fz_convex(mb, &b) && fz_v3_moderate(light, 1e4f) && zf < 1e5f) {
            double s = fz_scale2(&b, &b) + fz_maxabs3(light) + zf;
            if (fz_inside_by(&b, q, 1e-3 * (1.0 + s))) {
                double d[3] = {(double)q.x - light.x, (double)q.y - light.y, (double)q.z - light.z};
                double ad[3] = {fabs(d[0]), fabs(d[1]), fabs(d[2])};
                int ax = (ad[0] >= ad[1] && ad[0] >= ad[2]) ? 0 : ad[1] >= ad[2] ? 1 : 2;
                int face = 2 * ax + (d[ax] < 0.0), o1 = (ax + 1) % 3, o2 = (ax + 2) % 3;
                double m = 1e-3 * (1.0 + s);
                if (ad[ax] > zn + m && ad[ax] < zf - m && ad[o1] < ad[ax] - m && ad[o2] < ad[ax] - m)
                    FZ_CHECK(bits >> face & 1u, "face %d holds (%g %g %g) of the view, bits %#x", face, q.x, q.y, q.z,
                             bits);
            }
        }
    }
    /* sk_caster_shadow_frustum, sk_caster_visible: the view is b */
    {
        sk_frustum f;
        sk_result r;
        int vis, bad, within = 0;
        int box_ok = fz_v3_finite(box.min) && fz_v3_finite(box.max) && box.min.x <= box.max.x &&
                     box.min.y <= box.max.y && box.min.z <= box.max.z;
        bad = !fz_v3_finite(light) || !fz_finite(range) || !(range > 0.0f) || !box_ok;
        FZ_FILL(f);
        r = sk_caster_shadow_frustum(light, range, box, &f);
        vis = sk_caster_visible(light, range, box, &b);
        FZ_CHECK(vis == 0 || vis == 1, "visible = %d", vis);
        FZ_CHECK(sk_caster_visible(light, range, box, NULL) == 1, "NULL view culled");
        if (bad) {
            FZ_CHECK(r == SK_ERR_INVALID_ARG, "r = %d on bad input", (int)r);
            FZ_CHECK(vis == 1, "bad input culled");
        }
        if (r != SK_OK) FZ_CHECK(FZ_UNTOUCHED(f), "written on error %d", (int)r);
        else FZ_CHECK(fz_frustum_usable(&f), "shadow frustum not usable");
        if (r == SK_OK && vis == 0) FZ_CHECK(sk_frustum_intersects(&f, &b) == 0, "culled, yet the frustum meets the view");
        if (!bad && fz_v3_moderate(light, 1e4f) && fz_v3_moderate(box.min, 1e4f) && fz_v3_moderate(box.max, 1e4f) &&
            range < 1e5f) {
            for (i = 0; i < 8; i++) {
                sk_vec3 c;
                double dx, dy, dz, dist;
                c.x = (i & 1) ? box.max.x : box.min.x;
                c.y = (i & 2) ? box.max.y : box.min.y;
                c.z = (i & 4) ? box.max.z : box.min.z;
                dx = (double)c.x - light.x; dy = (double)c.y - light.y; dz = (double)c.z - light.z;
                dist = sqrt(dx * dx + dy * dy + dz * dz);
                if (!(dist < range * (1.0 - 1e-4))) continue;
                within = 1;
                if (r == SK_OK) {
                    double s = fz_maxabs3(light) + range, m = -1e-4 * (1.0 + s);
                    int k;
                    for (k = 0; k < 6; k++)
                        FZ_CHECK(fz_plane_dist(&f.planes[k], c) >= m,
                                 "corner %d (%g %g %g), %g from the light (range %g), outside plane %d by %g", i, c.x,
                                 c.y, c.z, dist, range, k, fz_plane_dist(&f.planes[k], c));
                }
                if (fz_convex(mb, &b) && fz_inside_by(&b, c, 1e-3 * (1.0 + fz_scale2(&b, &b))))
                    FZ_CHECK(vis == 1, "corner %d (%g %g %g) in range and in the view, caster culled", i, c.x, c.y, c.z);
            }
            if (within) FZ_CHECK(r == SK_OK, "a corner within range, r = %d", (int)r);
        }
    }
    return 0;
}

#ifdef FZ_SEED_MAIN
static void fz_seeds(void)
{
    int k, i;
    for (k = 0; k < 6; k++) {
        fz_out o = {{0}, 0};
        fz_put_frustum_persp(&o, 0, 2, 0, 1, 1, -10, 1.0f, 1.3f, 0.1f, 30.0f);
        if (k & 1) fz_put_frustum_aabb(&o, -3, 0, -15, 3, 4, -5);
        else fz_put_frustum_persp(&o, 5, 5, -5, 0, 0, -8, 1.5f, 1.0f, 0.5f, 20.0f - 3 * k);
        for (i = 0; i < 8; i++) fz_put_u8(&o, (unsigned)(i * 37 + k));
        fz_put_vec3(&o, 2, 6 - k, -6);
        fz_put_float(&o, 0.05f);
        fz_put_float(&o, 25.0f);
        fz_put_float(&o, 25.0f);
        fz_put_aabb(&o, 0, 0, -9, 1 + k, 2, -7);
        for (i = 0; i < 8; i++) fz_put_u8(&o, (unsigned)(i * 11 + k * 5));
        fz_seed(&o);
    }
}
#endif
