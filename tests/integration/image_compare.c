/* image_compare.c - compares pairs of PNG files, one check per pair: both
   load, have the same size, and at most --max-pct percent of their pixels
   differ (a channel more than --tol apart). Used by examples_window.sh and
   loaders.sh. Differing pixels are drawn red over a dim copy
   of the first image in <first without .png>-diff.png when any differ.

   usage: image_compare [--max-pct P] [--tol T] [--name PROG] NAME A.png B.png [NAME A.png B.png ...]
   Prints one line per pair with its figures, then the sk_test.h summary
   line under the name PROG (default: argv[0]). */
#include <stdlib.h>
#include <string.h>

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include "image_diff.h"
#include "sk_test.h"

static double max_pct = 0.5;
static int tol = 0;

static void compare_pair(const char *name, const char *pa, const char *pb) {
    int wa = 0, ha = 0, wb = 0, hb = 0, n = 0;
    unsigned char *a = stbi_load(pa, &wa, &ha, &n, 3);
    unsigned char *b = stbi_load(pb, &wb, &hb, &n, 3);
    SK_CHECK_MSG(a != NULL, "%s: cannot read %s", name, pa);
    SK_CHECK_MSG(b != NULL, "%s: cannot read %s", name, pb);
    if (a && b) {
        SK_CHECK_MSG(wa == wb && ha == hb, "%s: %dx%d against %dx%d", name, wa, ha, wb, hb);
        if (wa == wb && ha == hb) {
            size_t px = (size_t)wa * (size_t)ha;
            unsigned char *mark = (unsigned char *)malloc(3 * px);
            image_diff d = image_diff_rgb(a, b, px, 3, tol, mark);
            image_diff_print(name, d, tol);
            SK_CHECK_MSG(d.pct <= max_pct, "%s: %.4f%% of the pixels differ (at most %.2f%%)", name, d.pct,
                         max_pct);
            if (mark && d.differ > 0) {
                char path[4096];
                size_t k = strlen(pa);
                if (k > 4 && strcmp(pa + k - 4, ".png") == 0) k -= 4;
                if (k + 10 < sizeof path) {
                    memcpy(path, pa, k);
                    strcpy(path + k, "-diff.png");
                    stbi_write_png(path, wa, ha, 3, mark, 3 * wa);
                }
            }
            free(mark);
        }
    }
    stbi_image_free(a);
    stbi_image_free(b);
}

int main(int argc, char **argv) {
    const char *prog = argv[0];
    int i = 1;
    while (i + 1 < argc && strncmp(argv[i], "--", 2) == 0) {
        if (strcmp(argv[i], "--max-pct") == 0) max_pct = atof(argv[i + 1]);
        else if (strcmp(argv[i], "--tol") == 0) tol = atoi(argv[i + 1]);
        else if (strcmp(argv[i], "--name") == 0) prog = argv[i + 1];
        else break;
        i += 2;
    }
    if (i >= argc || (argc - i) % 3 != 0) {
        fprintf(stderr, "usage: %s [--max-pct P] [--tol T] [--name PROG] NAME A.png B.png [...]\n", argv[0]);
        return 2;
    }
    for (; i < argc; i += 3) compare_pair(argv[i], argv[i + 1], argv[i + 2]);
    return sk_test_run_(prog, NULL, 0);   /* the checks ran above: only the summary */
}
