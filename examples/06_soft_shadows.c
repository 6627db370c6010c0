/* 06_soft_shadows.c - shadowkit tutorial 6: an area light, soft shadows
   with predicted virtual soft shadow maps (Shen et al. 2011)
   and with PCSS on one map.

   Run (from any directory, after `make examples`):
     build/examples/06_soft_shadows                       a window, PVSM; Esc quits
     build/examples/06_soft_shadows --technique pcss      PCSS on one 4096^2 map
     build/examples/06_soft_shadows --technique tiles     PVSM, its tiles drawn over
                                                          the picture (Fig. 10)
     build/examples/06_soft_shadows --headless            writes out/06_soft_shadows.png
   Options: --frames N, --out FILE, --scene FILE (default: the fence),
   --debug, --timing (each step's GPU time, read two or three frames late:
   a run of a single frame prints none).

   Soft shadows are a deferred effect here: skgl_soft_render takes the
   camera's depth and normals and writes visibility per pixel into a mask
   texture, which our lighting shader reads at its own pixel. With
   depth_tex = 0 (as below) shadowkit renders that G-buffer itself through
   the draw callback; an engine with a G-buffer hands its textures in.
   PVSM first renders a 1024^2 map with conservative rasterisation, finds
   per pixel how wide its penumbra is and how many texels that needs (the
   paper's perceptual rho(n)), collects the needs in a 64x64 grid on the
   light's plane, cuts the grid into tiles with a kd-tree, and renders one
   map per tile at just the resolution it asks for: soft shadows need few
   texels, sharp ones get many. --technique tiles tints each pixel by the
   tile that shadows it. */

#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"

#include "common.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define MAX_TILES 64

/* the fence of the tests: thin rails and slats, posts behind it */
static int build_scene(tb_scene *s) {
    return tb_scene_build_fence(s);
}

/* our lighting: lambert from the light's centre times the mask's visibility;
   with u_tiles > 0 each pixel is tinted by the PVSM tile it lies in */
static const char fs_src[] =
    "#version 330 core\n"
    "in vec3 v_world;\n"
    "in vec3 v_normal;\n"
    "out vec4 o_color;\n"
    "uniform sampler2D u_mask;\n"
    "uniform vec3 u_light_pos;\n"
    "uniform mat4 u_light_vp;\n"
    "uniform int u_tiles;\n"
    "uniform float u_rects[4 * 64];\n"
    "void main() {\n"
    "    vec3 n = normalize(v_normal);\n"
    "    if (!gl_FrontFacing) n = -n;\n"
    "    float lit = max(dot(n, normalize(u_light_pos - v_world)), 0.0);\n"
    "    float v = texelFetch(u_mask, ivec2(gl_FragCoord.xy), 0).r;\n"
    "    vec3 albedo = vec3(0.82, 0.8, 0.76);\n"
    "    for (int i = 0; i < u_tiles; i++) {\n"
    "        vec4 c = u_light_vp * vec4(v_world, 1.0);\n"
    "        vec2 p = c.xy / c.w;\n"
    "        if (c.w > 0.0 && p.x >= u_rects[4 * i] && p.y >= u_rects[4 * i + 1] &&\n"
    "            p.x < u_rects[4 * i + 2] && p.y < u_rects[4 * i + 3]) {\n"
    "            float h = fract(float(i) * 0.618034);\n"
    "            albedo = mix(albedo, clamp(abs(fract(h + vec3(0.0, 0.667, 0.333)) * 6.0 - 3.0) - 1.0, 0.0, 1.0), 0.45);\n"
    "            break;\n"
    "        }\n"
    "    }\n"
    "    o_color = vec4(albedo * (0.12 + 0.95 * lit * v), 1.0);\n"
    "}\n";

int main(int argc, char **argv) {
    ex_options opt;
    ex_app app;
    skgl_desc desc = {0};
    skgl_soft_desc sdesc;
    skgl_context *sk = NULL;
    skgl_soft *soft = NULL;
    skgl_scene scene;
    skgl_area_light light;
    sk_vec3 eye, target, up = {0, 1, 0}, c;
    float zn = 0.1f, zf = 80.0f, size;
    unsigned prog = 0;
    const char *vs = ex_world_vs, *fs = fs_src;
    sk_result r = SK_OK;
    int status = 1, show_tiles = 0;
    int rc = ex_parse_args(argc, argv, "out/06_soft_shadows.png", 0, &opt);
    if (rc != 0) return rc == 1 ? 0 : 2;
    memset(&sdesc, 0, sizeof sdesc);   /* zero fields take the defaults */
    sdesc.technique = SKGL_SOFT_PVSM;
    if (opt.technique && strcmp(opt.technique, "pcss") == 0) {
        sdesc.technique = SKGL_SOFT_PCSS;
        sdesc.resolution = 4096;
    } else if (opt.technique && strcmp(opt.technique, "tiles") == 0) show_tiles = 1;
    else if (opt.technique && strcmp(opt.technique, "pvsm") != 0) {
        fprintf(stderr, "--technique: pvsm, pcss or tiles\n");
        return 2;
    }

    if (ex_app_open(&app, &opt, "shadowkit 06: soft shadows") != 0) return 1;
    if (ex_app_load_scene(&app, build_scene) != 0) goto done;
    /* debug and timing only when asked for (tutorial 01 says what they cost) */
    desc.getproc = app.getproc;
    desc.debug = opt.debug;
    desc.timing = opt.timing;
    if ((r = skgl_create(&desc, &sk)) != SK_OK) goto done;
    if ((r = skgl_soft_create(sk, &sdesc, &soft)) != SK_OK) goto done;
    if (!(prog = ex_link_program(&app, ex_compile_shader(&app, GL_VERTEX_SHADER, 1, &vs, "06 lighting"),
                                 ex_compile_shader(&app, GL_FRAGMENT_SHADER, 1, &fs, "06 lighting"),
                                 "06 lighting")))
        goto done;

    scene.draw = ex_draw_casters;
    scene.user = &app;
    scene.bounds = app.scene.bounds;

    /* the camera, and a square light above the content, 1/12 of its size */
    if (opt.scene_path) ex_camera_from_bounds(app.model_bounds, &eye, &target, &zn, &zf);
    else { eye = ex_v3(6.5f, 3.2f, 7.5f); target = ex_v3(-1.5f, 0.4f, 0.5f); }
    c = ex_v3(0.5f * (app.model_bounds.min.x + app.model_bounds.max.x), app.model_bounds.max.y,
              0.5f * (app.model_bounds.min.z + app.model_bounds.max.z));
    size = 0.5f * (app.model_bounds.max.x - app.model_bounds.min.x);
    if (0.5f * (app.model_bounds.max.z - app.model_bounds.min.z) > size)
        size = 0.5f * (app.model_bounds.max.z - app.model_bounds.min.z);
    memset(&light, 0, sizeof light);
    light.up = ex_v3(0, 0, 1);
    light.half_width = light.half_height = size / 12.0f;

    while (ex_app_begin_frame(&app)) {
        skgl_camera cam;
        sk_mat4 lvp;
        unsigned mask;
        float rects[4 * MAX_TILES];
        sk_rect tiles[MAX_TILES];
        int nt = 0, i;
        /* the light swings slowly from side to side above the content */
        float a = 0.35f * sinf(0.4f * (float)app.time);
        light.position = ex_v3(c.x + 0.5f * size * sinf(a), c.y + 1.1f * size, c.z + 0.35f * size * cosf(a));
        light.direction = ex_v3(c.x - light.position.x, -light.position.y, c.z - light.position.z);
        cam.view = sk_mat4_look_at(eye, target, up);
        cam.proj = sk_mat4_perspective(0.9f, (float)app.width / (float)app.height, zn, zf);
        /* an R16F texture the size of the framebuffer (common.c); the soft
           shadows of this frame, G-buffer included, go into it: every pixel
           is written, so it needs no clearing (-1) */
        if (!(mask = ex_mask_texture(&app, sk, -1.0f))) goto done;
        if ((r = skgl_soft_render(sk, soft, &cam, &scene, &light, 0, 0, mask)) != SK_OK) break;
        lvp = skgl_soft_matrix(soft);
        if (show_tiles) {
            /* the tiles as this frame drew them, on its base frustum */
            nt = skgl_soft_tile_rects(soft, tiles, MAX_TILES);
            if (nt > MAX_TILES) nt = MAX_TILES;
            for (i = 0; i < nt; i++) {
                rects[4 * i] = tiles[i].x0;
                rects[4 * i + 1] = tiles[i].y0;
                rects[4 * i + 2] = tiles[i].x1;
                rects[4 * i + 3] = tiles[i].y1;
            }
        }
        /* our lighting pass: the scene drawn again, each pixel reading the
           mask at its own position */
        app.gl.UseProgram(prog);
        app.gl.UniformMatrix4fv(app.gl.GetUniformLocation(prog, "u_light_vp"), 1, 0, lvp.m);
        app.gl.Uniform3f(app.gl.GetUniformLocation(prog, "u_light_pos"), light.position.x, light.position.y,
                         light.position.z);
        app.glx.Uniform1i(app.gl.GetUniformLocation(prog, "u_tiles"), nt);
        if (nt > 0) app.glx.Uniform1fv(app.gl.GetUniformLocation(prog, "u_rects"), 4 * nt, rects);
        ex_bind_texture(&app, prog, "u_mask", 0, mask);
        ex_draw_scene(&app, prog, &cam);
        app.gl.BindTexture(GL_TEXTURE_2D, 0);
        app.gl.UseProgram(0);
        if (ex_app_end_frame(&app) != 0) goto done;
    }
    if (r == SK_OK) {
        const skgl_soft_frame_stats *st = skgl_soft_stats(soft);
        int k;
        /* GPU times only with --timing: read two or three frames late,
           never waited for */
        if (sdesc.technique == SKGL_SOFT_PVSM) {
            printf("pvsm: %d tiles (largest side %d), %.2f Mtexels (%.2fx one 4096^2 map), %.0f%% of the pixels "
                   "settled by the low-res map\n",
                   st->tiles, st->resolution, st->texels * 1e-6, st->texels / (4096.0 * 4096.0),
                   100.0 * st->lit_fraction);
            if (opt.timing) {
                printf("  ms per step:");
                for (k = 0; k < SKGL_SOFT_STEPS; k++) printf(" %.2f", st->step_ms[k]);
                printf("\n");
            }
        } else {
            printf("pcss: one %d^2 map\n", st->resolution);
            if (opt.timing) {
                ex_print_ms("depth pass", st->shadow_ms);
                ex_print_ms("mask", st->mask_ms);
            }
        }
        status = 0;
    }

done:
    if (r != SK_OK) fprintf(stderr, "shadowkit: %s %s\n", sk_result_string(r), sk ? skgl_error_log(sk) : "");
    if (prog) app.gl.DeleteProgram(prog);
    if (soft) skgl_soft_destroy(sk, soft);
    if (sk) skgl_destroy(sk);
    ex_app_close(&app);
    return status;
}
