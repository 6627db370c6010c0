/* fuzz_estimate_resolution: sk_estimate_resolution(depth, w, h,
   cam_inv_view_proj, light_view_proj, max_res, out).
   Input: w (int 0..72: one strip of 64 columns and part of a second), h
   (int 0..6), or any int for either (w*h kept <= 4096), max_res (int 0..8192), a byte
   (bit 0: the camera matrix is inverted here first, as a caller does), the
   camera and light matrices (fz_mat4), a depth mode byte (0: one palette
   entry per pixel, 1: a plane a + b x + c y, 2: constant) and its data.
   Checks: SK_ERR_INVALID_ARG exactly on bad input (sizes, max_res,
   non-finite matrices), out untouched; else SK_OK with samples in
   [0, w*h]; no sample: width = height = 0, texel sizes 0, bounds [-1,1]^2,
   crop the identity; samples: width and height in [1, max_res], bounds
   finite, ordered and inside [-1,1]^2, texel sizes finite and >= 0, crop
   finite, the estimate the same when run again (no state). */
#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size};
    int w = fz_int(&in, 0, 72), h = fz_int(&in, 0, 6), max_res = fz_int(&in, 0, 8192);
    int invert = fz_u8(&in) & 1, mode, valid, i;
    sk_mat4 cam = fz_mat4(&in), light = fz_mat4(&in), inv;
    size_t n;
    float *depth;
    sk_res_estimate e, e2;
    sk_result r;
    valid = w >= 1 && h >= 1 && w <= 65536 && h <= 65536;
    /* valid, but small work: at most 4096 pixels (a wider image gets h = 0,
       refused; tests/test_resest.c runs the 65536-pixel limits) */
    if (valid && (long)w * h > 4096) {
        h = 4096 / w;
        valid = h >= 1;
    }
    inv = cam;
    if (invert && !sk_mat4_inverse(cam, &inv)) inv = cam;
    n = valid ? (size_t)w * h : 1;
    depth = (float *)malloc(n * sizeof(float));
    mode = fz_u8(&in) % 3;
    if (mode == 0) {
        float pal[8];
        for (i = 0; i < 8; i++) pal[i] = fz_float(&in);
        for (i = 0; i < (int)n; i++) depth[i] = pal[fz_u8(&in) & 7];
    } else if (mode == 1) {
        float a = fz_float(&in), b = fz_float(&in), c = fz_float(&in);
        for (i = 0; i < (int)n; i++) {
            int x = valid ? i % w : 0, y = valid ? i / w : 0;
            depth[i] = a + b * x + c * y;
        }
    } else {
        float a = fz_float(&in);
        for (i = 0; i < (int)n; i++) depth[i] = a;
    }
    valid = valid && max_res >= 1 && fz_mat_finite(&inv) && fz_mat_finite(&light);
    FZ_FILL(e);
    r = sk_estimate_resolution(depth, w, h, inv, light, max_res, &e);
    if (!valid) {
        FZ_CHECK(r == SK_ERR_INVALID_ARG, "r = %d on bad input (w %d h %d max_res %d)", (int)r, w, h, max_res);
        FZ_CHECK(FZ_UNTOUCHED(e), "out written on bad input");
    } else {
        FZ_CHECK(r == SK_OK, "r = %d", (int)r);
        FZ_CHECK(e.samples >= 0 && (long)e.samples <= (long)w * h, "samples %d of %d x %d", e.samples, w, h);
        if (e.samples == 0) {
            sk_mat4 id = sk_mat4_identity();
            FZ_CHECK(e.width == 0 && e.height == 0 && e.texel_w == 0.0f && e.texel_h == 0.0f, "empty: %d x %d, texel %g %g",
                     e.width, e.height, e.texel_w, e.texel_h);
            FZ_CHECK(e.bounds.x0 == -1.0f && e.bounds.y0 == -1.0f && e.bounds.x1 == 1.0f && e.bounds.y1 == 1.0f,
                     "empty: bounds (%g %g %g %g)", e.bounds.x0, e.bounds.y0, e.bounds.x1, e.bounds.y1);
            FZ_CHECK(memcmp(&e.crop, &id, sizeof id) == 0, "empty: crop not the identity");
        } else {
            FZ_CHECK(e.width >= 1 && e.width <= max_res && e.height >= 1 && e.height <= max_res, "%d x %d, max_res %d",
                     e.width, e.height, max_res);
            FZ_CHECK(fz_finite(e.bounds.x0) && fz_finite(e.bounds.y0) && fz_finite(e.bounds.x1) &&
                     fz_finite(e.bounds.y1) && e.bounds.x0 <= e.bounds.x1 && e.bounds.y0 <= e.bounds.y1 &&
                     e.bounds.x0 >= -1.0f && e.bounds.y0 >= -1.0f && e.bounds.x1 <= 1.0f && e.bounds.y1 <= 1.0f,
                     "bounds (%g %g %g %g)", e.bounds.x0, e.bounds.y0, e.bounds.x1, e.bounds.y1);
            FZ_CHECK(fz_finite(e.texel_w) && fz_finite(e.texel_h) && e.texel_w >= 0.0f && e.texel_h >= 0.0f,
                     "texel %g x %g", e.texel_w, e.texel_h);
            FZ_CHECK(fz_mat_finite(&e.crop), "crop not finite");
        }
        r = sk_estimate_resolution(depth, w, h, inv, light, max_res, &e2);
        FZ_CHECK(r == SK_OK && memcmp(&e, &e2, sizeof e) == 0, "second run differs");
    }
    free(depth);
    return 0;
}

#ifdef FZ_SEED_MAIN
static void fz_seeds(void)
{
    int k;
    /* 0: camera and light the same over a plane; 1: a light from above over
       a depth plane; 2: a palette of special depths; 3: an orthographic light */
    for (k = 0; k < 4; k++) {
        fz_out o = {{0}, 0};
        fz_put_int(&o, k == 2 ? 13 : 40);
        fz_put_int(&o, k == 2 ? 7 : 30);
        fz_put_int(&o, 2048);
        fz_put_u8(&o, 1);
        fz_put_persp(&o, 0, 5, 10, 0, 0, 0, 1.0f, 1.333f, 0.5f, 50.0f);
        if (k == 0) fz_put_persp(&o, 0, 5, 10, 0, 0, 0, 1.0f, 1.333f, 0.5f, 50.0f);
        else if (k == 3) fz_put_ortho(&o, 10, 20, 0, 0, 0, 0, -15, 15, -15, 15, 1, 60);
        else fz_put_persp(&o, 3, 20, 1, 0, 0, 0, 0.9f, 1.0f, 1.0f, 80.0f);
        if (k == 2) {
            const float pal[8] = {1.0f, 0.5f, 0.999f, NAN, 0.0f, -0.5f, 2.0f, 1e-30f};
            fz_put_u8(&o, 0);
            for (int j = 0; j < 8; j++) fz_put_float(&o, pal[j]);
            for (int j = 0; j < 13 * 7; j++) fz_put_u8(&o, (unsigned)(j * 5) % 8);
        } else {
            fz_put_u8(&o, 1);
            fz_put_float(&o, 0.9f);
            fz_put_float(&o, 0.0005f);
            fz_put_float(&o, 0.002f);
        }
        fz_seed(&o);
    }
}
#endif
