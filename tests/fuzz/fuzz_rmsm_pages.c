/* fuzz_rmsm_pages: sk_rmsm_page_requests(samples, count, virtual_res,
   page_size, out, cap).
   Input: count (int -1..300), the log2 of virtual_res and page_size (int
   0..31, or a raw int: any size), cap (int -1..300), a byte (bit 0: samples
   NULL, bit 1: out NULL), then count samples (s, t: fz_unit; lod: float).
   Checks: -SK_ERR_INVALID_ARG exactly on bad input (counts < 0, NULL with a
   count, sizes not powers of two, page_size > virtual_res), nothing
   written; otherwise the unique pages of the valid samples (s, t in [0,1),
   level clamp(floor(lod), 0, log2(virtual_res/page_size)), NaN lod as 0),
   computed here by brute force: -SK_ERR_CAPACITY exactly when they are more
   than cap (nothing written past cap), else all of them, sorted by (level,
   py, px), nothing written past them. */
#include "fuzz_common.h"

static int fz_page_cmp(const void *pa, const void *pb)
{
    const sk_page *a = (const sk_page *)pa, *b = (const sk_page *)pb;
    if (a->level != b->level) return a->level < b->level ? -1 : 1;
    if (a->py != b->py) return a->py < b->py ? -1 : 1;
    if (a->px != b->px) return a->px < b->px ? -1 : 1;
    return 0;
}

/* a power of two 2^e for e in [0,30], else the raw value */
static int fz_pow2(fz_in *in)
{
    int e = fz_int(in, 0, 31);
    return e >= 0 && e <= 30 ? 1 << e : e;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size};
    int count = fz_int(&in, -1, 300), vres = fz_pow2(&in), psize = fz_pow2(&in), cap = fz_int(&in, -1, 300);
    int flags = fz_u8(&in), i, r, valid, max_level = 0, nref = 0;
    sk_vec3 *samples;
    sk_page *out, *ref;
    size_t obytes;
    if (count > 4096) count = 4096;
    if (cap > 4096) cap = 4096;
    samples = (sk_vec3 *)malloc((size_t)(count > 0 ? count : 1) * sizeof(sk_vec3));
    for (i = 0; i < count; i++) {
        samples[i].x = fz_unit(&in);
        samples[i].y = fz_unit(&in);
        samples[i].z = fz_float(&in);
    }
    valid = count >= 0 && cap >= 0 && !((flags & 1) && count > 0) && !((flags & 2) && cap > 0) && vres > 0 &&
            (vres & (vres - 1)) == 0 && psize > 0 && (psize & (psize - 1)) == 0 && psize <= vres;
    obytes = (size_t)(cap > 0 ? cap : 0) * sizeof(sk_page);
    out = (sk_page *)fz_alloc(obytes);
    r = sk_rmsm_page_requests((flags & 1) ? NULL : samples, count, vres, psize, (flags & 2) ? NULL : out, cap);
    if (!valid) {
        FZ_CHECK(r == -(int)SK_ERR_INVALID_ARG, "r = %d on bad input (count %d res %d page %d cap %d)", r, count, vres,
                 psize, cap);
        FZ_CHECK(fz_untouched(out, obytes), "written on bad input");
        goto done;
    }
    while ((long)psize << max_level < vres) max_level++;
    ref = (sk_page *)malloc((size_t)(count > 0 ? count : 1) * sizeof(sk_page));
    for (i = 0; i < count; i++) {
        float s = samples[i].x, t = samples[i].y, lod = samples[i].z;
        double pages;
        sk_page p;
        if (!(s >= 0.0f && s < 1.0f && t >= 0.0f && t < 1.0f)) continue;
        p.level = lod != lod || lod < 0.0f ? 0 : lod >= (float)max_level ? max_level : (int)floorf(lod);
        pages = (double)((vres >> p.level) / psize);
        p.px = (int)(s * pages);
        p.py = (int)(t * pages);
        FZ_CHECK(p.px >= 0 && p.px < pages && p.py >= 0 && p.py < pages, "reference page out of range");
        ref[nref++] = p;
    }
    qsort(ref, (size_t)nref, sizeof *ref, fz_page_cmp);
    {
        int m = 0;
        for (i = 0; i < nref; i++) if (m == 0 || fz_page_cmp(&ref[m - 1], &ref[i]) != 0) ref[m++] = ref[i];
        nref = m;
    }
    if (nref > cap) {
        FZ_CHECK(r == -(int)SK_ERR_CAPACITY, "r = %d with %d pages for cap %d", r, nref, cap);
        FZ_CHECK(fz_guard_ok(out, obytes), "written past cap %d", cap);
    } else {
        FZ_CHECK(r == nref, "r = %d, %d unique pages", r, nref);
        FZ_CHECK(fz_guard_ok(out, (size_t)nref * sizeof(sk_page)), "written past %d pages", nref);
        for (i = 0; i < nref; i++)
            FZ_CHECK(fz_page_cmp(&out[i], &ref[i]) == 0, "page %d = (%d %d %d), want (%d %d %d)", i, out[i].level,
                     out[i].px, out[i].py, ref[i].level, ref[i].px, ref[i].py);
    }
    free(ref);
done:
    free(samples);
    free(out);
    return 0;
}

#ifdef FZ_SEED_MAIN
static void fz_seeds(void)
{
    static const int cfg[][4] = {{64, 12, 7, 256}, {200, 14, 8, 300}, {16, 10, 10, 4}, {100, 30, 0, 300}, {3, 3, 1, 1}};
    size_t i;
    int k;
    for (i = 0; i < sizeof cfg / sizeof cfg[0]; i++) {
        fz_out o = {{0}, 0};
        fz_put_int(&o, cfg[i][0]);
        fz_put_int(&o, cfg[i][1]);
        fz_put_int(&o, cfg[i][2]);
        fz_put_int(&o, cfg[i][3]);
        fz_put_u8(&o, 0);
        for (k = 0; k < cfg[i][0]; k++) {
            fz_put_unit(&o, (float)((k * 37) % 100) / 100.0f);
            fz_put_unit(&o, (float)((k * 53) % 100) / 100.0f);
            fz_put_float(&o, (float)(k % 9) - 1.5f);
        }
        fz_seed(&o);
    }
}
#endif
