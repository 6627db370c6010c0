/* loader_test.h - the body of the two loader tests (loader_glew.c,
   loader_glad.c). Each includes its loader's header, shadowkit_gl.h with
   the implementation and loader_render.h compiled against that loader
   (GL(name) = gl##name), then this file, and calls lt_run() with its
   context kind and the function that initialises its loader.

   One run: a testbed context of that kind, the loader initialised on it,
   skgl_create with the context's getproc, then lr_render twice: through
   the loader's entry points, and through the testbed's table
   (lr_render_testbed). Checks: the loader reports GL 3.3, both renders
   succeed, the image shows the scene with its shadows (5% to 50% of the
   pixels in the ambient-only colour of shadowed surfaces, under 50%
   background), the two renders differ in at most 0.1% of the pixels, no
   GL error. Writes out/tests/integration/loader-<name>.png and
   loader-<name>-testbed.png, which loaders.sh then compares across
   loaders. */
#ifndef LOADER_TEST_H
#define LOADER_TEST_H

#include <stdlib.h>

#include "image_diff.h"
#include "loader_tb.h"
#include "sk_test.h"
#include "tb_gl_context.h"
#include "tb_gl_funcs.h"
#include "tb_image.h"
#include "tb_scene.h"

typedef struct lt_loader {
    const char *name;               /* "glew", "glad": names the images */
    tb_gl_backend backend;          /* the context it runs on */
    /* initialises the loader on the current context; 0 ok, else a message in msg */
    int (*init)(tb_gl_context *ctx, char *msg, size_t n);
} lt_loader;

/* pixels in the colour lr_fs gives a surface without direct light
   (albedo (0.8, 0.75, 0.6) times the ambient 0.25), and background pixels */
static void lt_classify(const unsigned char *rgb, size_t px, size_t *shadowed, size_t *background) {
    size_t i;
    *shadowed = *background = 0;
    for (i = 0; i < px; i++) {
        const unsigned char *p = rgb + 3 * i;
        if (abs(p[0] - 51) <= 2 && abs(p[1] - 48) <= 2 && abs(p[2] - 38) <= 2) (*shadowed)++;
        if (abs(p[0] - 77) <= 1 && abs(p[1] - 102) <= 1 && abs(p[2] - 153) <= 1) (*background)++;
    }
}

static void lt_run(const lt_loader *L) {
    char err[512] = "", path[256];
    const size_t px = (size_t)LR_W * LR_H;
    tb_gl_context *ctx = tb_gl_context_create(L->backend, err, sizeof err);
    unsigned char *own = (unsigned char *)malloc(3 * px), *ref = (unsigned char *)malloc(3 * px);
    skgl_context *sk = NULL;
    tb_gl_funcs tbgl;
    tb_scene scene;
    skgl_desc d;
    sk_result r;
    tb_scene_init(&scene);
    SK_CHECK_MSG(ctx != NULL, "%s: no context: %s", L->name, err);
    SK_CHECK(own && ref && tb_scene_build_ground_boxes(&scene) == 0);
    if (!ctx || !own || !ref) goto done;
    printf("%s on %s: %s, %s\n", L->name, tb_gl_context_backend_name(ctx), tb_gl_context_renderer(ctx),
           tb_gl_context_version(ctx));
    if (L->init(ctx, err, sizeof err) != 0) {   /* nothing to render through */
        SK_CHECK_MSG(0, "%s: %s", L->name, err);
        goto done;
    }
    printf("%s: %s\n", L->name, err);

    memset(&d, 0, sizeof d);
    d.getproc = (skgl_getproc_fn)tb_gl_context_getproc(ctx);
    d.debug = 1;
    r = skgl_create(&d, &sk);
    SK_CHECK_MSG(r == SK_OK, "skgl_create: %s", sk_result_string(r));
    SK_CHECK(tb_gl_funcs_load(&tbgl, tb_gl_context_getproc(ctx)) == 0);
    if (r != SK_OK) goto done;

    SK_CHECK_MSG(lr_render(sk, &scene, own) == 0, "%s: the render through the loader failed", L->name);
    SK_CHECK_MSG(lr_render_testbed(&tbgl, sk, &scene, ref) == 0, "%s: the testbed render failed", L->name);
    SK_CHECK(tbgl.GetError() == 0);
    {
        size_t shadowed, background;
        image_diff dd = image_diff_rgb(own, ref, px, 3, 0, NULL);
        char what[64];
        lt_classify(own, px, &shadowed, &background);
        printf("%s: %.2f%% of the pixels shadowed, %.2f%% background\n", L->name, 100.0 * (double)shadowed / (double)px,
               100.0 * (double)background / (double)px);
        SK_CHECK_MSG(shadowed * 20 >= px && shadowed * 2 <= px, "%zu of %zu pixels shadowed", shadowed, px);
        SK_CHECK_MSG(background * 2 < px, "%zu of %zu pixels background", background, px);
        snprintf(what, sizeof what, "%s against the testbed's table", L->name);
        image_diff_print(what, dd, 0);
        SK_CHECK_MSG(dd.pct <= 0.1, "%s: %.4f%% of the pixels differ from the testbed render", L->name, dd.pct);
    }
    snprintf(path, sizeof path, "out/tests/integration/loader-%s.png", L->name);
    SK_CHECK_MSG(tb_image_write_rgb8(path, LR_W, LR_H, own) == 0, "cannot write %s", path);
    snprintf(path, sizeof path, "out/tests/integration/loader-%s-testbed.png", L->name);
    SK_CHECK_MSG(tb_image_write_rgb8(path, LR_W, LR_H, ref) == 0, "cannot write %s", path);

done:
    if (sk) skgl_destroy(sk);
    tb_gl_context_destroy(ctx);
    tb_scene_free(&scene);
    free(own);
    free(ref);
}

#endif /* LOADER_TEST_H */
