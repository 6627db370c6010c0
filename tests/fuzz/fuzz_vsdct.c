/* fuzz_vsdct: sk_vsdct_layout_make, sk_vsdct_lookup, sk_vsdct_indirection_fill.
   Input: a mode byte (bit 0: the layout from sk_vsdct_layout_make(face_res),
   else filled field by field), face_res (int 0..4096) or the 15 ints of a
   layout (0..4096), 8 directions (vec3), ni (int 0..12).
   Checks: sk_vsdct_layout_make: SK_OK and the 3 x 2 layout exactly for
   face_res in [1, SK_VSDCT_MAX_FACE_RES], else SK_ERR_INVALID_ARG and out
   untouched. sk_vsdct_lookup: -1 (u, v untouched) for a zero or non-finite
   direction or an invalid layout (face_res outside [1,
   SK_VSDCT_MAX_FACE_RES], an atlas side above SK_VSDCT_MAX_ATLAS, a face
   outside the atlas), else the face of the direction's major
   axis (x before y before z on ties, its sign picking + or -), u, v finite
   in [0,1], at least half a texel (float rounding of u, v aside) inside
   that face's sub-rect. sk_vsdct_indirection_fill: SK_ERR_INVALID_ARG for
   ni outside [1, 65536] or an invalid layout (nothing written), else every
   texel holds, to 1/65535, the lookup of the direction through its centre
   (GL's cube-map face table) and lies half a texel inside its face up to
   the RG16 rounding, nothing written past 6*ni*ni*2 shorts. */
#include "fuzz_common.h"

/* GL cube-map faces +X,-X,+Y,-Y,+Z,-Z: major axis, and the directions s and
   t run along (OpenGL 4.6, Table 8.19: s = (sc/|ma| + 1)/2, t likewise) */
static const int fz_face_axes[6][3][3] = {
    {{1, 0, 0}, {0, 0, -1}, {0, -1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, -1, 0}},
    {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},   {{0, -1, 0}, {1, 0, 0}, {0, 0, -1}},
    {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, -1, 0}}
};

static int fz_layout_valid(const sk_vsdct_layout *l)
{
    int f;
    if (l->face_res < 1 || l->face_res > SK_VSDCT_MAX_FACE_RES || l->atlas_w < l->face_res ||
        l->atlas_h < l->face_res || l->atlas_w > SK_VSDCT_MAX_ATLAS || l->atlas_h > SK_VSDCT_MAX_ATLAS)
        return 0;
    for (f = 0; f < 6; f++)
        if (l->face_x[f] < 0 || l->face_y[f] < 0 || (long)l->face_x[f] + l->face_res > l->atlas_w ||
            (long)l->face_y[f] + l->face_res > l->atlas_h)
            return 0;
    return 1;
}

/* u, v of face f lie at least half a texel inside its sub-rect; float u, v
   carry a rounding error of up to an ulp of 1 times the atlas size, and
   `quant` more (in units of u, v: 0.5/65535 for the RG16 texels) */
static void fz_check_inside(const sk_vsdct_layout *l, int f, float u, float v, double quant, const char *what)
{
    double px = (double)u * l->atlas_w, py = (double)v * l->atlas_h;
    double tx = 0.5 - l->atlas_w * (1.2e-7 + quant), ty = 0.5 - l->atlas_h * (1.2e-7 + quant);
    FZ_CHECK(fz_finite(u) && fz_finite(v) && u >= 0.0f && u <= 1.0f && v >= 0.0f && v <= 1.0f, "%s: u %g v %g", what,
             u, v);
    FZ_CHECK(px >= l->face_x[f] + tx && px <= l->face_x[f] + l->face_res - tx && py >= l->face_y[f] + ty &&
             py <= l->face_y[f] + l->face_res - ty,
             "%s: face %d texel (%.6f, %.6f) outside [%d+.5, %d-.5] x [%d+.5, %d-.5]", what, f, px, py, l->face_x[f],
             l->face_x[f] + l->face_res, l->face_y[f], l->face_y[f] + l->face_res);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size};
    sk_vsdct_layout l;
    int made = fz_u8(&in) & 1, valid, i, ni;
    if (made) {
        int res = fz_int(&in, 0, 4096);
        sk_result r;
        FZ_FILL(l);
        r = sk_vsdct_layout_make(res, &l);
        if (res >= 1 && res <= SK_VSDCT_MAX_FACE_RES) {
            FZ_CHECK(r == SK_OK, "layout_make(%d) = %d", res, (int)r);
            FZ_CHECK(l.face_res == res && l.atlas_w == 3 * res && l.atlas_h == 2 * res, "layout %d: %d x %d", l.face_res,
                     l.atlas_w, l.atlas_h);
            for (i = 0; i < 6; i++)
                FZ_CHECK(l.face_x[i] == (i % 3) * res && l.face_y[i] == (i / 3) * res, "face %d at (%d, %d)", i,
                         l.face_x[i], l.face_y[i]);
        } else {
            FZ_CHECK(r == SK_ERR_INVALID_ARG, "layout_make(%d) = %d", res, (int)r);
            FZ_CHECK(FZ_UNTOUCHED(l), "layout written on error");
            memset(&l, 0, sizeof l);
        }
    } else {
        l.face_res = fz_int(&in, 0, 4096);
        l.atlas_w = fz_int(&in, 0, 4096);
        l.atlas_h = fz_int(&in, 0, 4096);
        for (i = 0; i < 6; i++) { l.face_x[i] = fz_int(&in, 0, 4096); l.face_y[i] = fz_int(&in, 0, 4096); }
    }
    valid = fz_layout_valid(&l);
    for (i = 0; i < 8; i++) {
        sk_vec3 d = fz_vec3(&in);
        float u = 12345.0f, v = 54321.0f;
        int f = sk_vsdct_lookup(&l, d, &u, &v);
        int zero = d.x == 0.0f && d.y == 0.0f && d.z == 0.0f;
        if (!valid || !fz_v3_finite(d) || zero) {
            FZ_CHECK(f == -1, "lookup (%g %g %g) = %d on bad input", d.x, d.y, d.z, f);
            FZ_CHECK(u == 12345.0f && v == 54321.0f, "u, v written on bad input");
        } else {
            float ax = fabsf(d.x), ay = fabsf(d.y), az = fabsf(d.z);
            int want = (ax >= ay && ax >= az) ? (d.x >= 0.0f ? 0 : 1) : ay >= az ? (d.y >= 0.0f ? 2 : 3)
                                                                             : (d.z >= 0.0f ? 4 : 5);
            FZ_CHECK(f == want, "lookup (%g %g %g) = face %d, want %d", d.x, d.y, d.z, f, want);
            fz_check_inside(&l, f, u, v, 0.0, "lookup");
        }
    }
    FZ_CHECK(sk_vsdct_lookup(NULL, sk_mat4_transform_point(sk_mat4_identity(), fz_vec3(&in)), NULL, NULL) == -1,
             "lookup with NULL");
    ni = fz_int(&in, 0, 12);
    {
        int ok_ni = ni >= 1 && ni <= 65536;
        /* large valid ni are refused by the buffer size here, not the call */
        size_t n = ok_ni && valid && ni <= 64 ? (size_t)6 * ni * ni * 2 : 1;
        unsigned short *out;
        sk_result r;
        if (ok_ni && valid && ni > 64) return 0;
        out = (unsigned short *)fz_alloc(n * sizeof *out);
        r = sk_vsdct_indirection_fill(&l, ni, out);
        if (!ok_ni || !valid) {
            FZ_CHECK(r == SK_ERR_INVALID_ARG, "fill(ni %d) = %d on bad input", ni, (int)r);
            FZ_CHECK(fz_untouched(out, n * sizeof *out), "written on bad input");
        } else {
            int f, s, t;
            FZ_CHECK(r == SK_OK, "fill(ni %d) = %d", ni, (int)r);
            FZ_CHECK(fz_guard_ok(out, n * sizeof *out), "written past 6*ni*ni*2");
            for (f = 0; f < 6; f++)
                for (t = 0; t < ni; t++)
                    for (s = 0; s < ni; s++) {
                        const unsigned short *o = out + ((f * ni + t) * ni + s) * 2;
                        double sc = 2.0 * (s + 0.5) / ni - 1.0, tc = 2.0 * (t + 0.5) / ni - 1.0;
                        sk_vec3 d;
                        float u, v;
                        int got;
                        d.x = (float)(fz_face_axes[f][0][0] + sc * fz_face_axes[f][1][0] + tc * fz_face_axes[f][2][0]);
                        d.y = (float)(fz_face_axes[f][0][1] + sc * fz_face_axes[f][1][1] + tc * fz_face_axes[f][2][1]);
                        d.z = (float)(fz_face_axes[f][0][2] + sc * fz_face_axes[f][1][2] + tc * fz_face_axes[f][2][2]);
                        got = sk_vsdct_lookup(&l, d, &u, &v);
                        FZ_CHECK(got == f, "texel %d (%d,%d) looks up face %d", f, s, t, got);
                        FZ_CHECK(fabs(o[0] - u * 65535.0) <= 1.0 && fabs(o[1] - v * 65535.0) <= 1.0,
                                 "texel %d (%d,%d) = (%u %u), lookup (%.1f %.1f)", f, s, t, o[0], o[1], u * 65535.0,
                                 v * 65535.0);
                        fz_check_inside(&l, f, (float)(o[0] / 65535.0), (float)(o[1] / 65535.0), 0.5 / 65535.0, "fill");
                    }
        }
        free(out);
    }
    return 0;
}

#ifdef FZ_SEED_MAIN
static void fz_seeds(void)
{
    static const int res[] = {1, 2, 64, 512, 65536};
    size_t i;
    int k;
    for (i = 0; i < sizeof res / sizeof res[0]; i++) {
        fz_out o = {{0}, 0};
        fz_put_u8(&o, 1);
        fz_put_int(&o, res[i]);
        for (k = 0; k < 8; k++)
            fz_put_vec3(&o, (k & 1) ? 1.0f : -0.5f, (k & 2) ? 0.7f : -1.0f, (k & 4) ? 0.3f : -2.0f);
        fz_put_vec3(&o, 1, 0, 0);
        fz_put_int(&o, 1 + (int)i * 3);
        fz_seed(&o);
    }
    {
        /* a layout as shadowkit_gl.h packs it: faces of 100 in a bigger atlas */
        fz_out o = {{0}, 0};
        fz_put_u8(&o, 0);
        fz_put_int(&o, 100);
        fz_put_int(&o, 512);
        fz_put_int(&o, 256);
        for (k = 0; k < 6; k++) { fz_put_int(&o, (k % 3) * 100); fz_put_int(&o, (k / 3) * 100); }
        for (k = 0; k < 8; k++) fz_put_vec3(&o, (float)k - 3.5f, 1.0f, (float)(k * k) - 20.0f);
        fz_put_vec3(&o, 0, 0, 1);
        fz_put_int(&o, 8);
        fz_seed(&o);
    }
}
#endif
