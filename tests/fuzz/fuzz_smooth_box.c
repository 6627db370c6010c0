/* fuzz_smooth_box: sk_smooth_box_visibility(x0, y0, x1, y1, lit, user).
   Input: the box (4 floats), a lit mode byte (0 all lit, 1 none, 2 a
   checkerboard, 3 a hash of (tx, ty) and a seed), the seed (4 bytes), a
   byte (bit 0: lit NULL).
   Checks: -1 exactly on bad input (NULL, non-finite, |coordinate| > 1e9) and
   for a box spanning more than 64 texels on an axis, with lit never called;
   an empty box (x1 <= x0 or y1 <= y0) calls lit once, at the texel holding
   its centre, and returns 0 or 1; otherwise lit is called only for texels
   the box overlaps (at most 64 x 64), each at most once, and the result is
   in [0, 1] and matches the lit texels' coverage summed here in double
   (1e-5): all lit gives 1, none 0. */
#include "fuzz_common.h"

typedef struct fz_lit {
    int mode;
    uint32_t seed;
    long calls;
    int tx0, ty0, tx1, ty1;         /* the texel range the box overlaps */
    int out_of_range;
    unsigned char seen[64 * 64];
} fz_lit;

static int fz_lit_value(const fz_lit *l, int tx, int ty)
{
    uint32_t h;
    switch (l->mode) {
    case 0: return 1;
    case 1: return 0;
    case 2: return ((tx ^ ty) & 1) == 0;
    default:
        h = (uint32_t)tx * 0x9E3779B1u ^ (uint32_t)ty * 0x85EBCA77u ^ l->seed;
        h ^= h >> 15; h *= 0x2C1B3C6Du; h ^= h >> 12;
        return (int)(h & 1u);
    }
}

static int fz_lit_cb(void *user, int tx, int ty)
{
    fz_lit *l = (fz_lit *)user;
    l->calls++;
    if (tx < l->tx0 || tx >= l->tx1 || ty < l->ty0 || ty >= l->ty1) l->out_of_range = 1;
    else {
        unsigned char *s = &l->seen[(ty - l->ty0) * 64 + (tx - l->tx0)];
        FZ_CHECK(!*s, "texel (%d, %d) asked twice", tx, ty);
        *s = 1;
    }
    return fz_lit_value(l, tx, ty);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size};
    float x0 = fz_float(&in), y0 = fz_float(&in), x1 = fz_float(&in), y1 = fz_float(&in);
    static fz_lit l;
    int null_cb, bad;
    float v;
    memset(&l, 0, sizeof l);
    l.mode = fz_u8(&in) & 3;
    l.seed = fz_u32(&in);
    null_cb = fz_u8(&in) & 1;
    bad = null_cb || !fz_finite(x0) || !fz_finite(y0) || !fz_finite(x1) || !fz_finite(y1) || fabsf(x0) > 1e9f ||
          fabsf(y0) > 1e9f || fabsf(x1) > 1e9f || fabsf(y1) > 1e9f;
    if (bad) {
        l.tx0 = l.ty0 = 1; l.tx1 = l.ty1 = 0;
        v = sk_smooth_box_visibility(x0, y0, x1, y1, null_cb ? NULL : fz_lit_cb, &l);
        FZ_CHECK(v == -1.0f && l.calls == 0, "bad input: %g after %ld calls", v, l.calls);
        return 0;
    }
    if (!(x1 > x0) || !(y1 > y0)) {
        int cx = (int)floor(0.5 * ((double)x0 + x1)), cy = (int)floor(0.5 * ((double)y0 + y1));
        l.tx0 = cx; l.ty0 = cy; l.tx1 = cx + 1; l.ty1 = cy + 1;
        v = sk_smooth_box_visibility(x0, y0, x1, y1, fz_lit_cb, &l);
        FZ_CHECK(l.calls == 1 && !l.out_of_range, "empty box: %ld calls, out of range %d", l.calls, l.out_of_range);
        FZ_CHECK(v == (float)fz_lit_value(&l, cx, cy), "empty box: %g, texel (%d, %d) lit %d", v, cx, cy,
                 fz_lit_value(&l, cx, cy));
        return 0;
    }
    l.tx0 = (int)floor(x0); l.tx1 = (int)ceil(x1);
    l.ty0 = (int)floor(y0); l.ty1 = (int)ceil(y1);
    v = sk_smooth_box_visibility(x0, y0, x1, y1, fz_lit_cb, &l);
    if (l.tx1 - l.tx0 > 64 || l.ty1 - l.ty0 > 64) {
        FZ_CHECK(v == -1.0f && l.calls == 0, "box of %d x %d texels: %g after %ld calls", l.tx1 - l.tx0, l.ty1 - l.ty0, v,
                 l.calls);
        return 0;
    }
    FZ_CHECK(!l.out_of_range && l.calls <= (long)(l.tx1 - l.tx0) * (l.ty1 - l.ty0), "%ld calls, out of range %d",
             l.calls, l.out_of_range);
    FZ_CHECK(v >= 0.0f && v <= 1.0f, "visibility %g for (%g %g %g %g)", v, x0, y0, x1, y1);
    {
        double sum = 0.0, area = ((double)x1 - x0) * ((double)y1 - y0), want;
        int tx, ty;
        for (ty = l.ty0; ty < l.ty1; ty++)
            for (tx = l.tx0; tx < l.tx1; tx++) {
                /* in double: past 2^24 a texel index converted to float is
                   not the index any more */
                double ax0 = x0 > (double)tx ? x0 : (double)tx, ax1 = x1 < tx + 1.0 ? x1 : tx + 1.0;
                double ay0 = y0 > (double)ty ? y0 : (double)ty, ay1 = y1 < ty + 1.0 ? y1 : ty + 1.0;
                if (ax1 > ax0 && ay1 > ay0 && fz_lit_value(&l, tx, ty)) sum += (ax1 - ax0) * (ay1 - ay0);
            }
        want = sum / area;
        if (want > 1.0) want = 1.0;
        FZ_CHECK(fabs(v - want) <= 1e-5, "visibility %.9g, coverage %.9g for (%.9g %.9g %.9g %.9g) mode %d", v, want, x0,
                 y0, x1, y1, l.mode);
    }
    return 0;
}

#ifdef FZ_SEED_MAIN
static void fz_seeds(void)
{
    static const float boxes[][5] = {{0.25f, 0.5f, 3.75f, 2.5f, 2}, {-10.5f, -3.2f, 40.0f, 12.0f, 3},
                                     {5.0f, 5.0f, 5.0f, 7.0f, 0}, {0.1f, 0.1f, 0.2f, 0.9f, 0},
                                     {-32.0f, -32.0f, 32.0f, 32.0f, 1}};
    size_t i;
    for (i = 0; i < sizeof boxes / sizeof boxes[0]; i++) {
        fz_out o = {{0}, 0};
        fz_put_float(&o, boxes[i][0]);
        fz_put_float(&o, boxes[i][1]);
        fz_put_float(&o, boxes[i][2]);
        fz_put_float(&o, boxes[i][3]);
        fz_put_u8(&o, (unsigned)boxes[i][4]);
        fz_put_u32(&o, 0x1234567u * (uint32_t)(i + 1));
        fz_put_u8(&o, 0);
        fz_seed(&o);
    }
}
#endif
