/* 05_point_light.c - shadowkit tutorial 5: a point light, with cube shadow
   maps and VSDCT (King & Newhall 2004, "Efficient Omnidirectional Shadow
   Maps"), shadowed through a scissored deferred mask.

   Run (from any directory, after `make examples`):
     build/examples/05_point_light                    a window, cube map; Esc quits
     build/examples/05_point_light --technique vsdct  the virtual shadow depth cube texture
     build/examples/05_point_light --forward          the shadow looked up in the forward shader
     build/examples/05_point_light --headless         writes out/05_point_light.png
     build/examples/05_point_light --scene FILE       any glTF/OBJ file instead of the room
   Options: --frames N, --out FILE, --debug, --timing (as in tutorial 01).

   A point light sees all around it: six 90-degree maps, one per cube face.
   - SKGL_POINT_CUBE renders them into a GL depth cube map and looks it up
     with the light-to-point vector (samplerCubeShadow).
   - SKGL_POINT_VSDCT renders them as six rectangles of one 2D depth
     texture; a small RG16 cube map (the indirection) turns the direction
     into a place in that texture, kept away from the rectangles' edges so
     the filter never mixes two faces.
   Both store the depth of the paper's Eq. (5.4.6), so the comparison is
   the same. The paper's four savings are switches of skgl_point_desc, all
   on here:
   - cull_faces: a face whose frustum misses the view frustum is not rendered;
   - cull_casters: the draw callback skips the casters whose shadow cannot
     reach the view (skgl_point_caster_visible);
   - select_resolution: the face side follows the light's size on the
     screen (N M^2 >= 2 S);
   - scissor: the mask pass (skgl_point_mask) writes only the light's
     rectangle on the screen, the bounds of its range box (sk_light_scissor).
     Every pixel outside it is beyond the light's range.

   Each frame, by default (deferred):
     1. skgl_point_render  the faces the view needs, through our callback;
     2. the camera's G-buffer: window depth and world normals (common.c);
     3. the mask cleared to 1 (lit), then skgl_point_mask writes the
        visibility of the pixels inside the light's rectangle;
     4. our lighting pass draws the scene again; each pixel multiplies the
        light by the mask at its own position.
   With --forward, steps 2 and 3 go: skgl_point_bind hands the map to our
   shader, which calls sk_point_shadow() from skgl_point_glsl_snippet() for
   every fragment it draws. There is no mask there, so .scissor changes
   nothing on that path (a forward renderer would scissor its own light
   pass to the rectangle sk_light_scissor gives). The two paths light the
   scene with the same code and give the same picture (to the precision of
   the 16-bit float mask). */

#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"

#include "common.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* the room of the tests: floor, walls, ceiling, four pillars and a crate */
static int build_scene(tb_scene *s) {
    return tb_scene_build_room(s);
}

/* the draw callback: each object whose shadow this face can show */
static void draw_casters(void *user, const skgl_draw_info *info) {
    ex_app *app = (ex_app *)user;
    uint32_t i;
    for (i = 0; i < app->scene.object_count; i++) {
        const tb_object *o = &app->scene.objects[i];
        if (skgl_point_caster_visible(info, o->bounds))
            tb_gl_mesh_draw(&app->gl, &app->mesh, o->first_index, o->index_count);
    }
}

/* Our lighting: lambert from the point light with a quadratic fall-off to
   zero at its range, times the light's visibility, which each path defines
   as light_visibility() (see make_program). */
static const char fs_lighting[] =
    "in vec3 v_world;\n"
    "in vec3 v_normal;\n"
    "uniform vec3 u_light_pos;\n"
    "uniform float u_range;\n"
    "out vec4 o_color;\n"
    "void main() {\n"
    "    vec3 n = normalize(v_normal);\n"
    "    if (!gl_FrontFacing) n = -n;\n"
    "    vec3 l = u_light_pos - v_world;\n"
    "    float d = length(l);\n"
    "    float fall = clamp(1.0 - d / u_range, 0.0, 1.0);\n"
    "    float lit = max(dot(n, l / max(d, 1e-6)), 0.0) * fall * fall;\n"
    "    float v = light_visibility(v_world, n);\n"
    "    vec3 albedo = vec3(0.85, 0.8, 0.72);\n"
    "    o_color = vec4(albedo * (0.06 + 1.6 * lit * v), 1.0);\n"
    "}\n";
/* deferred: the mask skgl_point_mask wrote, read at this pixel */
static const char fs_deferred[] =
    "uniform sampler2D u_mask;\n"
    "float light_visibility(vec3 p, vec3 n) { return texelFetch(u_mask, ivec2(gl_FragCoord.xy), 0).r; }\n";
/* forward: shadowkit's lookup, from the snippet pasted before this */
static const char fs_forward[] =
    "float light_visibility(vec3 p, vec3 n) { return sk_point_shadow(p, n); }\n";

/* "#version"; forward: the technique's define and shadowkit's snippet;
   the path's light_visibility(); our lighting */
static unsigned make_program(const ex_app *app, int forward, int vsdct) {
    const char *vs = ex_world_vs, *fs[5];
    fs[0] = "#version 330 core\n";
    fs[1] = forward && vsdct ? "#define SK_POINT_VSDCT 1\n" : "";
    fs[2] = forward ? skgl_point_glsl_snippet() : "";
    fs[3] = forward ? fs_forward : fs_deferred;
    fs[4] = fs_lighting;
    return ex_link_program(app, ex_compile_shader(app, GL_VERTEX_SHADER, 1, &vs, "05 lighting"),
                           ex_compile_shader(app, GL_FRAGMENT_SHADER, 5, fs, "05 lighting"), "05 lighting");
}

int main(int argc, char **argv) {
    ex_options opt;
    ex_app app;
    skgl_desc desc = {0};
    skgl_point_desc pdesc;
    skgl_context *sk = NULL;
    skgl_point *lamp = NULL;
    skgl_scene scene;
    sk_vec3 eye = {4.6f, 3.4f, 0.8f}, target = {-2.0f, 0.6f, -0.6f}, up = {0, 1, 0}, centre;
    float zn = 0.05f, zf = 30.0f, orbit, height, lift;
    sk_aabb b;
    unsigned prog = 0, mask = 0;
    sk_result r = SK_OK;
    int status = 1, rc = ex_parse_args(argc, argv, "out/05_point_light.png", EX_ARG_FORWARD, &opt);
    if (rc != 0) return rc == 1 ? 0 : 2;
    memset(&pdesc, 0, sizeof pdesc);   /* zero fields take the defaults */
    if (opt.technique && strcmp(opt.technique, "vsdct") == 0) pdesc.technique = SKGL_POINT_VSDCT;
    else if (opt.technique && strcmp(opt.technique, "cube") != 0) {
        fprintf(stderr, "--technique: cube or vsdct\n");
        return 2;
    }

    if (ex_app_open(&app, &opt, "shadowkit 05: point light") != 0) return 1;
    if (ex_app_load_scene(&app, build_scene) != 0) goto done;
    if (opt.scene_path) ex_camera_from_bounds(app.model_bounds, &eye, &target, &zn, &zf);

    /* The light circles a centre, bobbing up and down by 0.15 of the
       scene's height. In the room (10 x 4 x 10 m, closed) it stays inside:
       a 1.6 m circle 1.9 m above the floor, 9 m of range. A model from a
       file stands on its ground plane, and the light's path comes from the
       model's bounds: it circles above the top of the box, where it cannot
       be inside the model (the bunny's body fills the middle of its box),
       half the half-width from the centre, and reaches 1.25 diagonals of
       the box, so that the ground around the model is lit too. */
    b = app.model_bounds;
    height = b.max.y - b.min.y;
    centre = ex_v3(0.5f * (b.min.x + b.max.x), b.min.y, 0.5f * (b.min.z + b.max.z));
    if (opt.scene_path) {
        float dx = b.max.x - b.min.x, dz = b.max.z - b.min.z;
        orbit = 0.25f * fmaxf(dx, dz);
        lift = 1.2f * height;
        pdesc.range = 1.25f * sqrtf(dx * dx + height * height + dz * dz);
        pdesc.near_plane = 0.005f * pdesc.range;   /* the default 5 cm would clip a small model */
    } else {
        orbit = 1.6f;
        lift = 1.9f;
        pdesc.range = 9.0f;
    }
    pdesc.resolution = 512;              /* per face, the most */
    pdesc.cull_faces = pdesc.cull_casters = pdesc.select_resolution = 1;
    pdesc.scissor = 1;                   /* for skgl_point_mask: the deferred path only */

    /* debug and timing only when asked for (tutorial 01 says what they cost) */
    desc.getproc = app.getproc;
    desc.debug = opt.debug;
    desc.timing = opt.timing;
    if ((r = skgl_create(&desc, &sk)) != SK_OK) goto done;
    if ((r = skgl_point_create(sk, &pdesc, &lamp)) != SK_OK) goto done;
    if (!(prog = make_program(&app, opt.forward, pdesc.technique == SKGL_POINT_VSDCT))) goto done;

    scene.draw = draw_casters;
    scene.user = &app;
    scene.bounds = app.scene.bounds;
    printf("light: range %.3g, circling x = %.3g, z = %.3g at a radius of %.3g, %.3g above y = %.3g\n",
           pdesc.range, centre.x, centre.z, orbit, lift, centre.y);

    while (ex_app_begin_frame(&app)) {
        skgl_camera cam;
        /* the light circles the centre, bobbing up and down */
        float a = 0.5f * (float)app.time + 0.6f;
        sk_vec3 lp = ex_v3(centre.x + orbit * cosf(a), centre.y + lift + 0.15f * height * sinf(1.7f * a),
                           centre.z + orbit * sinf(a));
        cam.view = sk_mat4_look_at(eye, target, up);
        cam.proj = sk_mat4_perspective(1.0f, (float)app.width / (float)app.height, zn, zf);

        /* 1. the faces this view needs */
        if ((r = skgl_point_render(sk, lamp, &cam, &scene, lp)) != SK_OK) break;

        if (!opt.forward) {
            /* 2. the camera's depth and normals */
            if (ex_gbuffer_render(&app, sk, &cam) != 0) goto done;
            /* 3. the mask: 1 everywhere, then the light's visibility inside
               its scissor rectangle (outside it the light reaches nothing) */
            if (!(mask = ex_mask_texture(&app, sk, 1.0f))) goto done;
            if ((r = skgl_point_mask(sk, lamp, &cam, app.gbuffer.depth_tex, app.gbuffer.color_tex, mask)) !=
                SK_OK)
                break;
        }

        /* 4. the lighting pass */
        app.gl.UseProgram(prog);
        app.gl.Uniform3f(app.gl.GetUniformLocation(prog, "u_light_pos"), lp.x, lp.y, lp.z);
        app.glx.Uniform1fv(app.gl.GetUniformLocation(prog, "u_range"), 1, &pdesc.range);
        if (opt.forward) {
            if ((r = skgl_point_bind(sk, lamp, prog, 0)) != SK_OK) break;
            /* the cube map filters across its faces with seamless
               filtering; VSDCT's indirection must not */
            if (pdesc.technique == SKGL_POINT_CUBE) app.gl.Enable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
            else app.gl.Disable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
        } else {
            ex_bind_texture(&app, prog, "u_mask", 0, mask);
        }
        ex_draw_scene(&app, prog, &cam);
        app.gl.UseProgram(0);
        if (ex_app_end_frame(&app) != 0) goto done;
    }
    if (r == SK_OK) {
        const skgl_point_frame_stats *st = skgl_point_stats(lamp);
        printf("%s, %s: %d faces rendered (%d culled) at %d^2, %d (face, caster) pairs culled\n",
               pdesc.technique == SKGL_POINT_VSDCT ? "vsdct" : "cube", opt.forward ? "forward" : "deferred",
               st->faces_rendered, st->faces_culled, st->resolution, st->casters_culled);
        /* the rectangle the last mask pass wrote (x, y from the bottom left;
           all 0: the light's range is off the screen, nothing written) */
        if (!opt.forward) {
            double covered = (double)st->scissor[2] * st->scissor[3] / ((double)app.width * app.height);
            printf("  mask scissor: %d x %d pixels at (%d, %d), %.1f%% of the %d x %d screen%s\n", st->scissor[2],
                   st->scissor[3], st->scissor[0], st->scissor[1], 100.0 * covered, app.width, app.height,
                   covered >= 1.0 ? " (the light's range box covers the whole view: nothing to skip)" : "");
        }
        /* GPU times of 2-3 frames back (-1 until they arrive) */
        if (opt.timing) {
            ex_print_ms("cube faces", st->shadow_ms);
            if (!opt.forward) ex_print_ms("mask", st->mask_ms);
        }
        status = 0;
    }

done:
    if (r != SK_OK) fprintf(stderr, "shadowkit: %s %s\n", sk_result_string(r), sk ? skgl_error_log(sk) : "");
    if (prog) app.gl.DeleteProgram(prog);
    if (lamp) skgl_point_destroy(sk, lamp);
    if (sk) skgl_destroy(sk);
    ex_app_close(&app);
    return status;
}
