/* 02_cascades.c - shadowkit tutorial 2: cascaded shadow maps (PSSM) for a
   view that reaches far away.

   Run (from any directory, after `make examples`):
     build/examples/02_cascades                      a window; Esc quits
     build/examples/02_cascades --headless           writes out/02_cascades.png
     build/examples/02_cascades --show-cascades      tints each pixel by its cascade
     build/examples/02_cascades --scene FILE         any glTF/OBJ file instead
   Options: --frames N (quit after N frames), --out FILE (PNG of the last
   frame; a window given --out steps its clock like --headless), --debug,
   --timing (as in tutorial 01).

   Why cascades: with one map (tutorial 01) stretched over a 200 m long view,
   a texel near the camera covers many screen pixels (blocky shadows) while
   far away many texels fall into one pixel (wasted). Parallel-split shadow
   maps (PSSM, Zhang et al. 2006) cut the view frustum along its depth into slices,
   short near the camera and long far away, and give each slice its own map
   of the same resolution: texel density follows the perspective.

   The code differs from tutorial 01 only in the skgl_shadow_desc and in the
   optional cascade view; the frame loop is the same two calls. */

/* exactly one file defines these before including the header */
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"

#include "common.h"

#include <math.h>
#include <stdio.h>

/* The default scene: the testbed's terrace, a ground strip 12 m wide and
   200 m long with posts on both sides and a box in the middle every 5 m,
   receding to the horizon: the case cascades are for. */
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
    /* a low sun from the left: long shadows across the strip */
    sk_vec3 light = ex_normalize(ex_v3(0.75f, -0.5f, -0.3f));
    float zn = 0.1f, zf = 200.0f;
    sk_result r = SK_OK;
    int status = 1, rc = ex_parse_args(argc, argv, "out/02_cascades.png", EX_ARG_CASCADES, &opt);
    if (rc != 0) return rc == 1 ? 0 : 2;
    if (ex_app_open(&app, &opt, "shadowkit 02: cascaded shadow maps") != 0) return 1;
    if (ex_app_load_scene(&app, build_scene) != 0) goto done;
    if (opt.scene_path) ex_camera_from_bounds(app.model_bounds, &eye, &target, &zn, &zf);

    /* The shadowkit context, as in tutorial 01: debug and timing only
       when asked for (--debug, --timing), never in a shipped program. */
    desc.getproc = app.getproc;
    desc.debug = opt.debug;
    desc.timing = opt.timing;
    if ((r = skgl_create(&desc, &sk)) != SK_OK) goto done;

    /* The cascades. Each of the 4 gets its own 1024^2 layer of one depth
       texture array: 4 x 1024^2 texels, the same memory as tutorial 01's
       single 2048^2 map, spent where the camera needs it.
       lambda places the split distances between the uniform scheme (0:
       equal slices) and the logarithmic one (1: equal texel density in
       theory, but a tiny first slice); the "practical" 0.75 is a blend.
       Each cascade's map is fitted to its own slice (per-cascade crop), and
       the snippet picks the cascade for each pixel from its view depth.
       blend_band: the last 10% of each slice fades into the next cascade,
       so the change of resolution at a split does not show as a seam. */
    sdesc.technique = SKGL_PSSM;
    sdesc.cascades = 4;
    sdesc.resolution = 1024;
    sdesc.lambda = 0.75f;
    sdesc.blend_band = 0.1f;
    sdesc.stable = 1;                 /* texel-snapped crops: no shimmer while moving */
    sdesc.max_distance = zf;          /* shadows all the way to the far plane */
    if ((r = skgl_shadow_create(sk, &sdesc, &sun)) != SK_OK) goto done;

    /* the forward shader with the snippet: for PSSM the same sk_shadow()
       call; it needs the view depth to choose the cascade */
    if (ex_forward_create(&app, skgl_glsl_snippet()) != 0) goto done;

    scene.draw = ex_draw_casters;     /* called once per cascade; info->index is the cascade */
    scene.user = &app;
    scene.bounds = app.scene.bounds;

    while (ex_app_begin_frame(&app)) {
        skgl_camera cam;
        const skgl_shadow_frame_stats *st;
        /* in a window the camera walks slowly down the terrace and back */
        float walk = opt.scene_path ? 0.0f : 12.0f * (1.0f - cosf(0.25f * (float)app.time));
        sk_vec3 e = ex_v3(eye.x, eye.y, eye.z - walk), t = ex_v3(target.x, target.y, target.z - walk);
        cam.view = sk_mat4_look_at(e, t, up);
        cam.proj = sk_mat4_perspective(60.0f * 3.14159265f / 180.0f,
                                       (float)app.width / (float)app.height, zn, zf);

        /* Renders all four cascades: for each, the split distances of this
           camera, the slice's crop in light space, one depth pass through
           our callback into its layer. */
        if ((r = skgl_shadow_render(sk, sun, &cam, &scene, light)) != SK_OK) break;

        app.gl.UseProgram(app.program);
        if ((r = skgl_shadow_bind(sk, sun, app.program, 0)) != SK_OK) break;

        /* The stats hold this frame's split distances (view depths, near to
           far: splits[0] .. splits[cascades]). With --show-cascades our
           shader tints each pixel by the slice its view depth falls in. */
        st = skgl_shadow_stats(sun);
        ex_forward_draw(&app, &cam, light, st->splits, opt.show_cascades ? sdesc.cascades : 0);

        if (ex_app_end_frame(&app) != 0) goto done;
    }
    if (r == SK_OK) {
        const skgl_shadow_frame_stats *st = skgl_shadow_stats(sun);
        int i;
        printf("%d cascades of %d^2 texels, %d pass(es)\n", st->maps, st->resolution, st->passes);
        for (i = 0; i < st->maps && i < SKGL_MAX_CASCADES; i++)   /* texels grow with distance */
            printf("  cascade %d: view depth %7.3g .. %7.3g m, one texel = %.3g cm\n", i,
                   st->splits[i], st->splits[i + 1],
                   100.0f * ex_texel_size(skgl_shadow_matrix(sun, i), st->resolution));
        /* all cascades' depth passes, 2-3 frames back (-1 until measured) */
        if (opt.timing) ex_print_ms("depth passes", st->shadow_ms);
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
