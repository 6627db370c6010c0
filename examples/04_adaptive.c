/* 04_adaptive.c - shadowkit tutorial 4: maps that adapt to the view.

   Run (from any directory, after `make examples`):
     build/examples/04_adaptive                      a window, FERKO; Esc quits
     build/examples/04_adaptive --technique lspsm    light space partitions
     build/examples/04_adaptive --technique rmsm     a virtual map, page by page
     build/examples/04_adaptive --headless           writes out/04_adaptive.png
   Options: --scene FILE, --frames N, --out FILE, --debug, --timing.

   Tutorials 01 to 03 fit their maps to the view frustum. These three look
   at what the view holds:
   - LSPSM (Tang et al. 2017) projects the view onto the light plane, fits
     a trapezoid around it and cuts it into partitions (Eq. 1), one map
     each: as many as the view's perspective needs, at most 8.
   - FERKO (Ferko 2013) reads the camera's depth buffer, bounds the points
     the light sees (the crop) and finds the smallest texel any pixel
     needs: one map of exactly that size, up to .resolution.
   - RMSM (Lefohn et al. 2007) cuts a huge virtual map (.resolution =
     16384) into pages; each pixel asks for the page of its level of
     detail, and only those pages are rendered, into a pool, found again
     through a page table.
   FERKO and RMSM need the camera's depth first: a depth pass into a
   texture, then skgl_shadow_analyze(), then the usual render and draw.
   What the analysis finds comes back to the CPU without a stall, through
   a ring of read-back buffers: the render uses the result of an earlier
   frame (a frame late on a GPU that keeps up; the first frame reads at
   once). */

#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"

#include "common.h"

#include <stdio.h>
#include <string.h>

static int build_scene(tb_scene *s) {
    return tb_scene_build_terrace(s);
}

int main(int argc, char **argv) {
    ex_options opt;
    ex_app app;
    skgl_desc desc = {0};
    skgl_shadow_desc sdesc = {0};
    skgl_context *sk = NULL;
    skgl_shadow *sun = NULL;
    skgl_scene scene;
    sk_vec3 eye = {1.5f, 2.2f, 3.0f}, target = {0.0f, 0.6f, -30.0f}, up = {0, 1, 0};
    sk_vec3 light = ex_normalize(ex_v3(0.75f, -0.6f, -0.3f));
    float zn = 0.1f, zf = 200.0f;
    const char *name;
    sk_result r = SK_OK;
    int status = 1, rc = ex_parse_args(argc, argv, "out/04_adaptive.png", 0, &opt);
    if (rc != 0) return rc == 1 ? 0 : 2;
    name = opt.technique ? opt.technique : "ferko";
    if (strcmp(name, "ferko") == 0) {
        sdesc.technique = SKGL_FERKO;
        sdesc.resolution = 4096;          /* the largest map it may ask for */
    } else if (strcmp(name, "lspsm") == 0) {
        sdesc.technique = SKGL_LSPSM;
        sdesc.resolution = 1024;          /* per partition */
    } else if (strcmp(name, "rmsm") == 0) {
        sdesc.technique = SKGL_RMSM;      /* 16384^2 virtual, 128^2 pages, a pool of 24^2 pages */
    } else {
        fprintf(stderr, "--technique: ferko, lspsm or rmsm\n");
        return 2;
    }

    if (ex_app_open(&app, &opt, "shadowkit 04: maps that adapt to the view") != 0) return 1;
    if (ex_app_load_scene(&app, build_scene) != 0) goto done;
    if (opt.scene_path) ex_camera_from_bounds(app.model_bounds, &eye, &target, &zn, &zf);
    /* debug and timing only when asked for (tutorial 01 says what they cost) */
    desc.getproc = app.getproc;
    desc.debug = opt.debug;
    desc.timing = opt.timing;
    if ((r = skgl_create(&desc, &sk)) != SK_OK) goto done;
    if ((r = skgl_shadow_create(sk, &sdesc, &sun)) != SK_OK) goto done;
    if (ex_forward_create(&app, skgl_glsl_snippet()) != 0) goto done;
    scene.draw = ex_draw_casters;
    scene.user = &app;
    scene.bounds = app.scene.bounds;

    while (ex_app_begin_frame(&app)) {
        skgl_camera cam;
        cam.view = sk_mat4_look_at(eye, target, up);
        cam.proj = sk_mat4_perspective(1.0f, (float)app.width / (float)app.height, zn, zf);
        if (sdesc.technique != SKGL_LSPSM) {
            /* the camera's depth (common.c's G-buffer pass stands in for
               your engine's depth pre-pass), then the analysis of it.
               FERKO: crop and size of the map; RMSM: the pages it needs */
            if (ex_gbuffer_render(&app, sk, &cam) != 0) goto done;
            if ((r = skgl_shadow_analyze(sk, sun, &cam, &scene, light, app.gbuffer.depth_tex)) != SK_OK) break;
        }
        if ((r = skgl_shadow_render(sk, sun, &cam, &scene, light)) != SK_OK) break;
        app.gl.UseProgram(app.program);
        if ((r = skgl_shadow_bind(sk, sun, app.program, 0)) != SK_OK) break;
        ex_forward_draw(&app, &cam, light, skgl_shadow_stats(sun)->splits, 0);
        if (ex_app_end_frame(&app) != 0) goto done;
    }
    if (r == SK_OK) {
        const skgl_shadow_frame_stats *st = skgl_shadow_stats(sun);
        printf("%s: %d pass(es), %.0f texels rendered\n", name, st->passes, st->texels);
        if (sdesc.technique == SKGL_LSPSM)
            printf("  %d partitions of %d^2%s\n", st->maps, st->resolution, st->lspsm_fallback ? " (fallback)" : "");
        if (sdesc.technique == SKGL_FERKO)
            printf("  estimate %d x %d texels (map %d x %d with its border)\n", st->estimate.width,
                   st->estimate.height, st->map_width, st->map_height);
        if (sdesc.technique == SKGL_RMSM)
            printf("  %d pages requested, %d rendered, finest level %d\n", st->pages_requested, st->pages_rendered,
                   st->rmsm_min_level);
        /* GPU times of 2-3 frames back (-1 until they arrive) */
        if (opt.timing) {
            ex_print_ms("depth passes", st->shadow_ms);
            if (sdesc.technique != SKGL_LSPSM) ex_print_ms("analysis", st->analysis_ms);
        }
        status = 0;
    }

done:
    if (r != SK_OK)
        fprintf(stderr, "shadowkit: %s %s\n", sk_result_string(r), sk ? skgl_error_log(sk) : "");
    if (sun) skgl_shadow_destroy(sk, sun);
    if (sk) skgl_destroy(sk);
    ex_app_close(&app);
    return status;
}
