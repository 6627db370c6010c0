/* 03_warping.c - shadowkit tutorial 3: perspective warping (PSM, LiSPSM).

   Run (from any directory, after `make examples`):
     build/examples/03_warping                       a window, LiSPSM; Esc quits
     build/examples/03_warping --technique psm       perspective shadow map
     build/examples/03_warping --technique standard  the unwarped map, to compare
     build/examples/03_warping --headless            writes out/03_warping.png
   Options: --scene FILE, --frames N, --out FILE, --debug, --timing.

   Why warp: tutorial 02 fought perspective aliasing (near texels too big)
   with several maps. Warping does it with one: the map is rendered after a
   perspective transform, so that texels near the camera come out small and
   far ones large, as the camera's own pixels do.
   - PSM (Stamminger & Drettakis 2002) renders the map in the camera's
     post-perspective space, where the sun becomes a point light. Its
     special cases are handled for you: a sun behind the viewer turns into
     a "sink" (the depth order flips; shadowkit negates the map's depth so
     the test stays LESS), casters behind the camera slide a virtual camera
     back. psm_slide (default 0.5) slides it further, by 0.5 sqrt(near*far):
     the raw PSM spends nearly all texels on the first metre.
   - LiSPSM (Wimmer et al. 2004) puts the warp's perspective axis across the
     light direction, with its centre at the optimal distance
     n_opt = (z_n + sqrt(z_n z_f')) / sin(gamma). As the sun turns parallel
     to the view direction (gamma -> 0) the warp fades into the plain map.
     With .cascades > 1 each PSSM cascade gets its own warp.
   The frame loop is the same two calls as in tutorials 01 and 02. */

#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"

#include "common.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* the terrace of tutorial 02: a 200 m strip with posts and boxes */
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
    sk_vec3 eye = {0.0f, 2.0f, 1.0f}, target = {0.0f, 0.5f, -30.0f}, up = {0, 1, 0};
    /* the sun from behind the viewer and to the side, 40 degrees to the view */
    sk_vec3 light = ex_normalize(ex_v3(0.35f, -0.55f, -1.0f));
    float zn = 0.1f, zf = 250.0f;
    sk_result r = SK_OK;
    int status = 1, rc = ex_parse_args(argc, argv, "out/03_warping.png", 0, &opt);
    if (rc != 0) return rc == 1 ? 0 : 2;

    /* Only the technique differs between the three maps; all are one
       1024^2 texture: the same memory, spent differently. */
    sdesc.technique = SKGL_LISPSM;
    if (opt.technique && strcmp(opt.technique, "psm") == 0) sdesc.technique = SKGL_PSM;
    else if (opt.technique && strcmp(opt.technique, "standard") == 0) sdesc.technique = SKGL_STANDARD;
    else if (opt.technique && strcmp(opt.technique, "lispsm") != 0) {
        fprintf(stderr, "--technique: standard, psm or lispsm\n");
        return 2;
    }
    sdesc.resolution = 1024;

    if (ex_app_open(&app, &opt, "shadowkit 03: warped shadow maps") != 0) return 1;
    if (ex_app_load_scene(&app, build_scene) != 0) goto done;
    if (opt.scene_path) ex_camera_from_bounds(app.model_bounds, &eye, &target, &zn, &zf);

    /* debug and timing only when asked for (tutorial 01 says what they cost) */
    desc.getproc = app.getproc;
    desc.debug = opt.debug;
    desc.timing = opt.timing;
    if ((r = skgl_create(&desc, &sk)) != SK_OK) goto done;
    if ((r = skgl_shadow_create(sk, &sdesc, &sun)) != SK_OK) goto done;
    /* the snippet is the same for every technique: the warp is in the matrix */
    if (ex_forward_create(&app, skgl_glsl_snippet()) != 0) goto done;

    scene.draw = ex_draw_casters;
    scene.user = &app;
    scene.bounds = app.scene.bounds;

    while (ex_app_begin_frame(&app)) {
        skgl_camera cam;
        /* in a window the sun circles slowly: watch the warp follow it and
           fade out when the sun is straight behind the camera (the saved
           images, --headless or a window with --out, keep the fixed sun) */
        float a = 0.2f * (float)app.time;
        int fixed_sun = opt.headless || opt.save_window;
        sk_vec3 l = fixed_sun ? light : ex_normalize(ex_v3(0.6f * sinf(a), -0.55f, -cosf(a)));
        cam.view = sk_mat4_look_at(eye, target, up);
        cam.proj = sk_mat4_perspective(1.0f, (float)app.width / (float)app.height, zn, zf);
        if ((r = skgl_shadow_render(sk, sun, &cam, &scene, l)) != SK_OK) break;
        app.gl.UseProgram(app.program);
        if ((r = skgl_shadow_bind(sk, sun, app.program, 0)) != SK_OK) break;
        ex_forward_draw(&app, &cam, l, skgl_shadow_stats(sun)->splits, 0);
        if (ex_app_end_frame(&app) != 0) goto done;
    }
    if (r == SK_OK) {
        /* what the warp did this frame */
        const skgl_shadow_frame_stats *st = skgl_shadow_stats(sun);
        printf("%s: one %d^2 map, receivers at view depth %.2f .. %.2f m\n",
               sdesc.technique == SKGL_PSM ? "psm" : sdesc.technique == SKGL_LISPSM ? "lispsm" : "standard",
               st->resolution, st->splits[0], st->splits[1]);
        if (sdesc.technique == SKGL_PSM)
            printf("  sun %s the viewer%s; virtual camera slid back %.2f m\n",
                   st->depth_reversed ? "behind" : "in front of",
                   st->depth_reversed ? " (depth order reversed, handled)" : "", st->psm_slide);
        if (sdesc.technique == SKGL_LISPSM)
            printf("  warp %s, n = %.2f m\n", st->warped[0] ? "on" : "off (uniform map)", st->warp_n[0]);
        /* the timer's result of 2-3 frames back (-1 until one arrives) */
        if (opt.timing) ex_print_ms("depth pass", st->shadow_ms);
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
