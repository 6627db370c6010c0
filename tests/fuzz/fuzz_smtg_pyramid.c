/* fuzz_smtg_pyramid: sk_smtg_pyramid_size(gw, gh) and
   sk_smtg_pyramid(grid, gw, gh, out, cap_floats).
   Input: gw, gh (int 0..40), a cap mode byte (0: exactly the size, 1: one
   float short, 2: larger, 3: an int from the input), that int (-4..4096), a
   palette of 8 floats, then one byte per cell (two nibbles & 7: the
   channels' palette entries).
   Checks: the size is 0 for sizes outside [1, 4096], else the sum over the
   levels (computed here); -SK_ERR_INVALID_ARG for bad sizes or a negative
   cap, -SK_ERR_CAPACITY when cap is below the size, nothing written either
   way; on success the level count is 1 + ceil(log2(max(gw, gh))), level 0
   is the grid with NaN as +INFINITY, each further texel the minimum of its
   2x2 block (odd sizes rounding up), no NaN, nothing written past the size. */
#include "fuzz_common.h"

static float fz_min_nan(float a, float b) { return (b < a || a != a) ? b : a; }

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size};
    int gw = fz_int(&in, 0, 40), gh = fz_int(&in, 0, 40);
    int cap_mode = fz_u8(&in) & 3, cap_in = fz_int(&in, -4, 4096);
    int valid = gw >= 1 && gh >= 1 && gw <= 4096 && gh <= 4096;
    long want = 0;
    int levels = 0, need, cap, i, r;
    float pal[8], *grid, *out;
    size_t cells, obytes;
    for (i = 0; i < 8; i++) pal[i] = fz_float(&in);
    if (valid && (long)gw * gh > 4096) {           /* valid, but small work */
        if (gw > gh) gw = 4096 / gh > 0 ? 4096 / gh : 1; else gh = 4096 / gw > 0 ? 4096 / gw : 1;
    }
    if (valid) {
        int w = gw, h = gh;
        for (;;) {
            want += (long)w * h * 2;
            levels++;
            if (w == 1 && h == 1) break;
            w = (w + 1) / 2; h = (h + 1) / 2;
        }
    }
    need = sk_smtg_pyramid_size(gw, gh);
    FZ_CHECK(need == (valid ? want : 0), "size(%d, %d) = %d, want %ld", gw, gh, need, valid ? want : 0L);
    cap = cap_mode == 0 ? need : cap_mode == 1 ? need - 1 : cap_mode == 2 ? need + 7 : cap_in;
    cells = valid ? (size_t)gw * gh : 1;
    grid = (float *)malloc(cells * 2 * sizeof(float));
    for (i = 0; i < (int)cells; i++) {
        uint8_t b = fz_u8(&in);
        grid[2 * i] = pal[b & 7];
        grid[2 * i + 1] = pal[(b >> 4) & 7];
    }
    /* the buffer holds what the call may write: at most min(cap, need) floats */
    obytes = (size_t)(cap < 0 ? 0 : cap < need ? cap : need) * sizeof(float);
    out = (float *)fz_alloc(obytes);
    r = sk_smtg_pyramid(grid, gw, gh, out, cap);
    if (!valid || cap < 0) {
        FZ_CHECK(r == -(int)SK_ERR_INVALID_ARG, "r = %d for %d x %d cap %d", r, gw, gh, cap);
        FZ_CHECK(fz_untouched(out, obytes), "written on bad input");
    } else if (cap < need) {
        FZ_CHECK(r == -(int)SK_ERR_CAPACITY, "r = %d for cap %d < %d", r, cap, need);
        FZ_CHECK(fz_untouched(out, obytes), "written on -SK_ERR_CAPACITY");
    } else {
        const float *src = out;
        int w = gw, h = gh, lv;
        FZ_CHECK(r == levels, "%d levels, want %d", r, levels);
        FZ_CHECK(fz_guard_ok(out, (size_t)need * sizeof(float)), "written past %d floats", need);
        for (i = 0; i < gw * gh * 2; i++) {
            float g = grid[i] != grid[i] ? INFINITY : grid[i];
            FZ_CHECK(memcmp(&out[i], &g, sizeof g) == 0 || out[i] == g, "level 0 [%d] = %g, grid %g", i, out[i], grid[i]);
        }
        for (lv = 1; lv < levels; lv++) {
            int nw = (w + 1) / 2, nh = (h + 1) / 2, x, y, c;
            const float *dst = src + (size_t)w * h * 2;
            for (y = 0; y < nh; y++)
                for (x = 0; x < nw; x++)
                    for (c = 0; c < 2; c++) {
                        float m = src[((2 * y) * w + 2 * x) * 2 + c], got = dst[(y * nw + x) * 2 + c];
                        if (2 * x + 1 < w) m = fz_min_nan(m, src[((2 * y) * w + 2 * x + 1) * 2 + c]);
                        if (2 * y + 1 < h) m = fz_min_nan(m, src[((2 * y + 1) * w + 2 * x) * 2 + c]);
                        if (2 * x + 1 < w && 2 * y + 1 < h) m = fz_min_nan(m, src[((2 * y + 1) * w + 2 * x + 1) * 2 + c]);
                        FZ_CHECK(got == got, "NaN at level %d (%d,%d)", lv, x, y);
                        FZ_CHECK(got == m, "level %d (%d,%d).%d = %g, min of the block %g", lv, x, y, c, got, m);
                    }
            src = dst;
            w = nw; h = nh;
        }
    }
    free(grid);
    free(out);
    return 0;
}

#ifdef FZ_SEED_MAIN
static void fz_seeds(void)
{
    static const int dims[][2] = {{8, 8}, {5, 3}, {1, 1}, {40, 17}, {1, 33}};
    size_t i;
    int k, c;
    for (i = 0; i < sizeof dims / sizeof dims[0]; i++) {
        fz_out o = {{0}, 0};
        const float pal[8] = {INFINITY, 0.5f, 0.01f, NAN, 0.0f, -1.0f, 1e-30f, 3.0f};
        fz_put_int(&o, dims[i][0]);
        fz_put_int(&o, dims[i][1]);
        fz_put_u8(&o, (unsigned)i % 3);
        fz_put_int(&o, 0);
        for (k = 0; k < 8; k++) fz_put_float(&o, pal[k]);
        for (c = 0; c < dims[i][0] * dims[i][1]; c++) fz_put_u8(&o, (unsigned)((c * 7) % 8 | ((c * 3) % 8) << 4));
        fz_seed(&o);
    }
}
#endif
