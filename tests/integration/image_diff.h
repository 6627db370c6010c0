/* image_diff.h - pixel comparison shared by the integration tests.

   A pixel differs when any of its channels differs by more than `tol`
   (0..255); the tests bound the share of pixels that differ. Images are
   8-bit, `comp` channels per pixel, tightly packed, in any row order (both
   the same). Static inline functions, C99 and C++. */
#ifndef IMAGE_DIFF_H
#define IMAGE_DIFF_H

#include <stddef.h>
#include <stdio.h>

typedef struct image_diff {
    size_t pixels;          /* compared */
    size_t differ;          /* with a channel more than tol apart */
    int max_channel;        /* largest channel difference seen */
    double pct;             /* 100 * differ / pixels */
} image_diff;

static inline image_diff image_diff_rgb(const unsigned char *a, const unsigned char *b, size_t pixels, int comp,
                                 int tol, unsigned char *mark /* NULL, or 3 bytes per pixel */) {
    image_diff d;
    size_t i;
    int c;
    d.pixels = pixels;
    d.differ = 0;
    d.max_channel = 0;
    for (i = 0; i < pixels; i++) {
        int worst = 0;
        for (c = 0; c < comp; c++) {
            int k = (int)a[i * (size_t)comp + (size_t)c] - (int)b[i * (size_t)comp + (size_t)c];
            if (k < 0) k = -k;
            if (k > worst) worst = k;
        }
        if (worst > d.max_channel) d.max_channel = worst;
        if (worst > tol) d.differ++;
        if (mark) {   /* differing pixels red, the rest a dim copy of a */
            unsigned char g = (unsigned char)(a[i * (size_t)comp] / 3);
            mark[3 * i] = worst > tol ? 255 : g;
            mark[3 * i + 1] = worst > tol ? 0 : g;
            mark[3 * i + 2] = worst > tol ? 0 : g;
        }
    }
    d.pct = pixels ? 100.0 * (double)d.differ / (double)pixels : 0.0;
    return d;
}

static inline void image_diff_print(const char *what, image_diff d, int tol) {
    printf("%s: %zu of %zu pixels differ by more than %d (%.4f%%), largest channel difference %d\n", what,
           d.differ, d.pixels, tol, d.pct, d.max_channel);
}

#endif /* IMAGE_DIFF_H */
