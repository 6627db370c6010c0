/* 01_hard_shadows.c - shadowkit tutorial 1: a sun and one focused shadow map.

   Run (from any directory, after `make examples`):
     build/examples/01_hard_shadows                  a window; Esc quits
     build/examples/01_hard_shadows --headless       writes out/01_hard_shadows.png
     build/examples/01_hard_shadows --scene FILE     any glTF/OBJ file instead
   Options: --frames N (quit after N frames), --out FILE (PNG of the last
   frame; a window given --out steps its clock like --headless), --debug
   (check GL errors after every shadowkit pass), --timing (GPU times).

   The steps, in the order you would write them in your engine:
     1. skgl_create         a shadowkit GL context, loading GL through your getproc
     2. skgl_shadow_create  one shadow map and its settings (skgl_shadow_desc)
     3. your forward shader pastes skgl_glsl_snippet() and calls sk_shadow()
     4. every frame:
          skgl_shadow_render  renders the light's depth map, focused on what
                              the camera sees, drawing through your callback
          skgl_shadow_bind    hands the map to your shader, then you draw
     5. skgl_shadow_destroy, skgl_destroy
   Everything that is not about shadows (window, scene, shader text, the draw
   callback) is in common.c, so this file holds only the shadowkit part. */

/* shadowkit is a single-header library: exactly one file of the program
   defines these two before including it, and gets the implementation. */
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"

#include "common.h"

#include <math.h>
#include <stdio.h>

/* The default scene: the testbed's ground with five boxes (one floating),
   plus a row of thin poles and a fence. Their 5 cm and 3 cm shadows show
   how much detail a 2048^2 map keeps once it is focused on the view. */
static int build_scene(tb_scene *s) {
    char name[32];
    int i;
    if (tb_scene_build_ground_boxes(s) != 0) return -1;
    for (i = 0; i < 8; i++) {                       /* poles 5 cm thick, 2.5 m tall */
        snprintf(name, sizeof name, "pole%d", i);
        if (tb_scene_add_pole(s, name, -9.0f + 1.5f * (float)i, 0, 8, 0.025f, 2.5f) < 0) return -1;
    }
    for (i = 0; i < 2; i++) {                       /* fence: two rails ... */
        float y = 0.4f + 0.6f * (float)i;
        snprintf(name, sizeof name, "rail%d", i);
        if (tb_scene_add_box(s, name, ex_v3(-10, y, -6.015f), ex_v3(-2, y + 0.06f, -5.985f)) < 0)
            return -1;
    }
    for (i = 0; i <= 32; i++) {                     /* ... and slats every 25 cm */
        float x = -10.0f + 0.25f * (float)i;
        snprintf(name, sizeof name, "slat%d", i);
        if (tb_scene_add_box(s, name, ex_v3(x - 0.015f, 0, -6.04f), ex_v3(x + 0.015f, 1.3f, -6.01f)) < 0)
            return -1;
    }
    return 0;
}

/* The direction the sunlight travels (from the sun toward the ground). In a
   window it circles slowly so you can watch the shadows move. */
static sk_vec3 sun_direction(double t) {
    float a = 2.5f + 0.2f * (float)t;               /* azimuth, radians */
    return ex_normalize(ex_v3(cosf(a), -1.1f, sinf(a)));
}

int main(int argc, char **argv) {
    ex_options opt;
    ex_app app;
    skgl_desc desc = {0};
    skgl_shadow_desc sdesc = {0};
    skgl_context *sk = NULL;
    skgl_shadow *sun = NULL;
    skgl_scene scene;
    sk_vec3 eye = {11.0f, 7.5f, 15.0f}, target = {-1.5f, 0.0f, 0.0f}, up = {0, 1, 0};
    float zn = 0.1f, zf = 100.0f;
    sk_result r = SK_OK;
    int status = 1, rc = ex_parse_args(argc, argv, "out/01_hard_shadows.png", 0, &opt);
    if (rc != 0) return rc == 1 ? 0 : 2;
    if (ex_app_open(&app, &opt, "shadowkit 01: hard shadows") != 0) return 1;
    if (ex_app_load_scene(&app, build_scene) != 0) goto done;
    if (opt.scene_path) ex_camera_from_bounds(app.model_bounds, &eye, &target, &zn, &zf);

    /* 1. The shadowkit context. It loads the GL entry points it needs
       through the same getproc you give your own loader (here
       glfwGetProcAddress, or the headless context's), into a private table.
       Both switches below cost time every frame, so they stay off unless
       asked for (as they should in the program you ship):
       debug (--debug): glGetError after every pass, reported as SK_ERR_GL,
         and extra checks of your textures and programs. Each glGetError
         is a round trip to the driver (with a driver that runs on its own
         thread, the CPU waits for it to catch up).
       timing (--timing): a GPU timer query around every pass, into
         skgl_shadow_stats(). Results are read only once the GPU has them,
         2-3 frames later, so the stats say -1 until then. */
    desc.getproc = app.getproc;
    desc.debug = opt.debug;
    desc.timing = opt.timing;
    if ((r = skgl_create(&desc, &sk)) != SK_OK) goto done;

    /* 2. One shadow map. Zeroed fields take the defaults (listed in
       shadowkit_gl.h); we spell out the ones that matter here.
       SKGL_STANDARD fits a single map, every frame, to the part of the view
       frustum that holds scene geometry, seen from the light: no texels are
       spent on empty space. With stable = 1 it fits a bounding sphere of
       the view instead and snaps it to whole texels, so that shadow edges
       do not shimmer while the camera moves; the sphere is looser (in this
       view a texel grows from 1.5 to 4.3 cm). Our camera stands still, so
       we keep the tight fit.
       Bias: casters are drawn with a slope-scaled depth offset, and
       receivers are pushed along their normal by normal_bias texels; both
       are in texel units, so they follow the resolution. pcf_radius 1 takes
       2x2 hardware comparisons (each one a bilinear 2x2 PCF): soft-ish edges. */
    sdesc.technique = SKGL_STANDARD;
    sdesc.resolution = 2048;
    sdesc.stable = 0;
    sdesc.pcf_radius = 1;
    if ((r = skgl_shadow_create(sk, &sdesc, &sun)) != SK_OK) goto done;

    /* 3. Our forward shader: "#version 330 core", then the snippet, which
       declares its uniforms and float sk_shadow(world_pos, world_normal,
       view_depth), then our lighting code calling sk_shadow() (common.c). */
    if (ex_forward_create(&app, skgl_glsl_snippet()) != 0) goto done;

    /* What shadowkit knows of the scene: a callback that draws the casters
       (ex_draw_casters, in common.c) and the bounds of everything. The
       bounds clip the view frustum for the fit, and pull the light's near
       plane back so casters outside the view still cast into it. */
    scene.draw = ex_draw_casters;
    scene.user = &app;
    scene.bounds = app.scene.bounds;

    /* 4. The frame loop. */
    while (ex_app_begin_frame(&app)) {
        skgl_camera cam;
        sk_vec3 light = sun_direction(app.time);
        cam.view = sk_mat4_look_at(eye, target, up);
        cam.proj = sk_mat4_perspective(50.0f * 3.14159265f / 180.0f,
                                       (float)app.width / (float)app.height, zn, zf);

        /* Render the depth map for this camera and light. It saves and
           restores every GL state it touches, so our framebuffer, viewport
           and depth state are as we left them afterwards. */
        if ((r = skgl_shadow_render(sk, sun, &cam, &scene, light)) != SK_OK) break;

        /* Draw the scene with our shader. skgl_shadow_bind puts the map on
           texture unit 0 and sets the snippet's uniforms (light matrix,
           bias, filter); the program must be current. */
        app.gl.UseProgram(app.program);
        if ((r = skgl_shadow_bind(sk, sun, app.program, 0)) != SK_OK) break;
        ex_forward_draw(&app, &cam, light, NULL, 0);

        if (ex_app_end_frame(&app) != 0) goto done;
    }
    if (r == SK_OK) {
        const skgl_shadow_frame_stats *st = skgl_shadow_stats(sun);
        /* skgl_shadow_matrix: the light's world -> clip matrix of the map;
           from it, how much ground one texel covers after the fit */
        printf("shadow map: %d x %d, one texel = %.3g cm, %d pass(es)\n", st->resolution, st->resolution,
               100.0f * ex_texel_size(skgl_shadow_matrix(sun, 0), st->resolution), st->passes);
        /* the depth pass's GPU time of a frame 2-3 frames back (-1 until one arrives) */
        if (opt.timing) ex_print_ms("depth pass", st->shadow_ms);
        status = 0;
    }

done:
    if (r != SK_OK)
        fprintf(stderr, "shadowkit: %s %s\n", sk_result_string(r), sk ? skgl_error_log(sk) : "");
    /* 5. Shutdown: every GL object shadowkit created is deleted here. */
    if (sun) skgl_shadow_destroy(sk, sun);
    if (sk) skgl_destroy(sk);
    ex_app_close(&app);
    return status;
}
