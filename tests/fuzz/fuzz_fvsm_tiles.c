/* fuzz_fvsm_tiles: sk_fvsm_tiles(grid, gw, gh, max_res, out, cap).
   Input: gw, gh (int 0..48), max_res (int 0..4096), cap (int -1..256), a
   palette of 8 floats, then one byte per cell: its two channels' palette
   entries (low and high nibble, & 7).
   Checks: -SK_ERR_INVALID_ARG exactly on bad sizes, nothing written;
   -SK_ERR_CAPACITY writes nothing past cap; a count: tiles inside the grid,
   non-empty, disjoint, each holding a sampled cell, covering every sampled
   cell (one not +INFINITY or NaN on both channels), res in [1, max_res],
   res >= span / smallest texel size of its cells (or max_res, clamped); a
   cell with a demand <= 0 ends in a 1x1 tile at max_res along that axis;
   the same call with one slot less gives -SK_ERR_CAPACITY. */
#include "fuzz_common.h"

#define FZ_GMAX 48

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size};
    int gw = fz_int(&in, 0, FZ_GMAX), gh = fz_int(&in, 0, FZ_GMAX);
    int max_res = fz_int(&in, 0, 4096), cap = fz_int(&in, -1, 256);
    int valid = gw >= 1 && gh >= 1 && gw <= 4096 && gh <= 4096 && max_res >= 1 && cap >= 0;
    float pal[8], *grid;
    size_t cells, obytes;
    sk_tile *out;
    int i, r;
    for (i = 0; i < 8; i++) pal[i] = fz_float(&in);
    if (cap > 4096) cap = 4096;
    /* grids past FZ_GMAX cost time and find nothing new: the sizes stay
       valid, the work small */
    if (valid && (gw > FZ_GMAX || gh > FZ_GMAX)) {
        if ((long)gw * gh > 4096) { if (gw > gh) gw = 4096 / gh > 0 ? 4096 / gh : 1; else gh = 4096 / gw > 0 ? 4096 / gw : 1; }
    }
    cells = valid ? (size_t)gw * gh : 1;
    grid = (float *)malloc(cells * 2 * sizeof(float));
    for (i = 0; i < (int)cells; i++) {
        uint8_t b = fz_u8(&in);
        grid[2 * i] = pal[b & 7];
        grid[2 * i + 1] = pal[(b >> 4) & 7];
    }
    obytes = (size_t)(cap > 0 ? cap : 0) * sizeof(sk_tile);
    out = (sk_tile *)fz_alloc(obytes);
    r = sk_fvsm_tiles(grid, gw, gh, max_res, out, cap);
    if (!valid) {
        FZ_CHECK(r == -(int)SK_ERR_INVALID_ARG, "r = %d for gw %d gh %d max_res %d cap %d", r, gw, gh, max_res, cap);
        FZ_CHECK(fz_untouched(out, obytes), "written on bad input");
    } else if (r < 0) {
        FZ_CHECK(r == -(int)SK_ERR_CAPACITY, "r = %d", r);
        FZ_CHECK(fz_guard_ok(out, obytes), "written past cap %d", cap);
    } else {
        int *owner = (int *)malloc(cells * sizeof(int));
        int x, y, t;
        FZ_CHECK(r <= cap, "count %d > cap %d", r, cap);
        FZ_CHECK(fz_guard_ok(out, (size_t)r * sizeof(sk_tile)), "written past the %d tiles", r);
        for (i = 0; i < (int)cells; i++) owner[i] = -1;
        for (t = 0; t < r; t++) {
            const sk_tile *q = &out[t];
            double mx = INFINITY, my = INFINITY, need_x, need_y;
            int sampled = 0, unbounded_x = 0, unbounded_y = 0;
            FZ_CHECK(q->x0 >= 0 && q->y0 >= 0 && q->x1 <= gw && q->y1 <= gh && q->x0 < q->x1 && q->y0 < q->y1,
                     "tile %d = [%d,%d) x [%d,%d) in %d x %d", t, q->x0, q->x1, q->y0, q->y1, gw, gh);
            FZ_CHECK(q->res_x >= 1 && q->res_x <= max_res && q->res_y >= 1 && q->res_y <= max_res,
                     "tile %d res %d x %d, max_res %d", t, q->res_x, q->res_y, max_res);
            for (y = q->y0; y < q->y1; y++)
                for (x = q->x0; x < q->x1; x++) {
                    float a = grid[(y * gw + x) * 2], b = grid[(y * gw + x) * 2 + 1];
                    FZ_CHECK(owner[y * gw + x] < 0, "cell (%d,%d) in tiles %d and %d", x, y, owner[y * gw + x], t);
                    owner[y * gw + x] = t;
                    if (a != a) a = INFINITY;
                    if (b != b) b = INFINITY;
                    if (a == INFINITY && b == INFINITY) continue;
                    sampled = 1;
                    if (a <= 0.0f) unbounded_x = 1;
                    if (b <= 0.0f) unbounded_y = 1;
                    if (a < mx) mx = a;
                    if (b < my) my = b;
                }
            FZ_CHECK(sampled, "tile %d holds no sampled cell", t);
            if (unbounded_x || unbounded_y)
                FZ_CHECK(q->x1 - q->x0 == 1 && q->y1 - q->y0 == 1 && (!unbounded_x || q->res_x == max_res) &&
                         (!unbounded_y || q->res_y == max_res),
                         "unbounded demand in tile %d = [%d,%d) x [%d,%d) res %d x %d", t, q->x0, q->x1, q->y0, q->y1,
                         q->res_x, q->res_y);
            need_x = mx == INFINITY ? 1.0 : mx <= 0.0 ? INFINITY : 2.0 * (q->x1 - q->x0) / gw / mx;
            need_y = my == INFINITY ? 1.0 : my <= 0.0 ? INFINITY : 2.0 * (q->y1 - q->y0) / gh / my;
            FZ_CHECK(q->res_x == max_res || q->res_x >= need_x * (1.0 - 1e-9),
                     "tile %d res_x %d < need %.9g", t, q->res_x, need_x);
            FZ_CHECK(q->res_y == max_res || q->res_y >= need_y * (1.0 - 1e-9),
                     "tile %d res_y %d < need %.9g", t, q->res_y, need_y);
        }
        for (i = 0; i < (int)cells; i++) {
            float a = grid[2 * i], b = grid[2 * i + 1];
            int s = !((a != a || a == INFINITY) && (b != b || b == INFINITY));
            FZ_CHECK(!s || owner[i] >= 0, "sampled cell (%d,%d) = (%g %g) in no tile", i % gw, i / gw, a, b);
        }
        free(owner);
        if (r >= 1) {
            int r2 = sk_fvsm_tiles(grid, gw, gh, max_res, out, r - 1);
            FZ_CHECK(r2 == -(int)SK_ERR_CAPACITY, "cap %d - 1 gives %d", r, r2);
        }
    }
    free(grid);
    free(out);
    return 0;
}

#ifdef FZ_SEED_MAIN
static void fz_seeds(void)
{
    /* gw, gh, max_res, cap; palette; the cell pattern: 0 all entry 1,
       1 a disc of entries 1..3 in entry 0 (+INFINITY), 2 stripes */
    static const int dims[][5] = {{16, 16, 1024, 256, 0}, {32, 8, 256, 256, 1}, {7, 13, 64, 64, 2},
                                  {48, 48, 2048, 256, 1}, {1, 1, 16, 4, 0}};
    size_t i;
    int k, x, y;
    for (i = 0; i < sizeof dims / sizeof dims[0]; i++) {
        fz_out o = {{0}, 0};
        const float pal[8] = {INFINITY, 0.01f, 0.002f, 0.05f, 0.0f, NAN, 1e-6f, 2.0f};
        for (k = 0; k < 4; k++) fz_put_int(&o, dims[i][k]);
        for (k = 0; k < 8; k++) fz_put_float(&o, pal[k]);
        for (y = 0; y < dims[i][1]; y++)
            for (x = 0; x < dims[i][0]; x++) {
                int cx = x - dims[i][0] / 2, cy = y - dims[i][1] / 2, e;
                if (dims[i][4] == 0) e = 1;
                else if (dims[i][4] == 1) e = cx * cx + cy * cy < dims[i][0] * dims[i][0] / 5 ? 1 + (x + y) % 3 : 0;
                else e = (x % 3 == 0) ? 4 + y % 4 : 1;
                fz_put_u8(&o, (unsigned)(e | e << 4));
            }
        fz_seed(&o);
    }
}
#endif
