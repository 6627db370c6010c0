/* 08_spot_lights.c - shadowkit tutorial 8: a night street lit by 16 shadowed
   street lamps (spot lights) and 2 shop lanterns (point lights), all their
   shadow maps in one atlas.

   Run (from any directory, after `make examples`):
     build/examples/08_spot_lights              a window; Esc quits
     build/examples/08_spot_lights --headless   writes out/08_spot_lights.png
   Options: --frames N, --out FILE, --debug, --timing (as in tutorial 01).

   A spot light is a skgl_point with desc.spot_angle, the half-angle of its
   cone, > 0. Instead of six cube faces it renders one perspective map down
   its direction (skgl_spot_render), fitted to the part of the cone the
   camera can see and snapped to a texel grid that stays put as the camera
   moves. It keeps the point light's machinery: the same mask
   (skgl_point_mask, 0 outside the cone), the same forward snippet (with
   "#define SK_POINT_SPOT 1"), caster culling (skgl_point_caster_visible
   now also tests the cone), the scissored mask and King & Newhall's
   resolution selection.

   All 18 lights share one depth atlas (skgl_point_atlas): every frame
   skgl_point_atlas_pack gives each lamp a side from its size on the screen
   (a lamp far down the street gets a small map) and places the spots' one
   face and the lanterns' six on shelves of the atlas.

   Each frame:
     1. skgl_point_atlas_pack, then skgl_spot_render / skgl_point_render
        per light, through our culling callback;
     2. the camera's G-buffer (common.c);
     3. an ambient pass, then per light: its mask (cleared to 0, written
        inside the light's scissor rectangle), and an additive lighting
        pass that multiplies the lamp's light by its mask. */

#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"

#include "common.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define N_SPOTS 16
#define N_POINTS 2
#define N_LIGHTS (N_SPOTS + N_POINTS)

/* the street's lamps: 8 a side, 7 m apart, 5 m high, leaning over the road */
static sk_vec3 spot_pos(int i) {
    float side = i < N_SPOTS / 2 ? -1.0f : 1.0f;
    int k = i % (N_SPOTS / 2);
    return ex_v3(-24.5f + 7.0f * (float)k + (side > 0 ? 3.5f : 0.0f), 5.0f, side * 4.3f);
}
static sk_vec3 spot_dir(int i) {
    return ex_v3(0.0f, -1.0f, i < N_SPOTS / 2 ? 0.35f : -0.35f);
}
/* the lanterns in two shop fronts */
static sk_vec3 point_pos(int i) {
    return i == 0 ? ex_v3(-8.0f, 2.6f, -7.3f) : ex_v3(11.0f, 2.6f, 7.3f);
}

static sk_vec3 v3(float x, float y, float z) { return ex_v3(x, y, z); }

/* the street: road, kerbs, houses of several heights, lamp posts with
   their arms, parked cars, benches */
static int build_scene(tb_scene *s) {
    int i, ok = 1;
    ok &= tb_scene_add_ground(s, "road", 0, 0, 34, 20, 0, 17, 10) >= 0;
    for (i = 0; i < 2; i++) {
        float z = i ? 1.0f : -1.0f;
        int k;
        ok &= tb_scene_add_box(s, "kerb", v3(-34, 0, z > 0 ? 5.0f : -8.0f), v3(34, 0.15f, z > 0 ? 8.0f : -5.0f)) >= 0;
        for (k = 0; k < 11; k++) {
            float x0 = -33.0f + 6.0f * (float)k, h = 4.0f + 3.0f * (float)((k * 7 + i * 3) % 4);
            ok &= tb_scene_add_box(s, "house", v3(x0, 0, z > 0 ? 8.0f : -16.0f), v3(x0 + 5.6f, h, z > 0 ? 16.0f : -8.0f)) >= 0;
        }
    }
    for (i = 0; i < N_SPOTS; i++) {
        sk_vec3 p = spot_pos(i);
        float side = p.z > 0 ? 1.0f : -1.0f;
        ok &= tb_scene_add_pole(s, "post", p.x, 0.15f, side * 5.6f, 0.07f, 5.25f) >= 0;
        ok &= tb_scene_add_box(s, "arm", v3(p.x - 0.05f, 5.25f, side > 0 ? 4.1f : -5.6f),
                               v3(p.x + 0.05f, 5.35f, side > 0 ? 5.6f : -4.1f)) >= 0;
    }
    for (i = 0; i < 6; i++) {   /* parked cars */
        float x = -20.0f + 7.5f * (float)i, z = (i & 1) ? 3.0f : -4.2f;
        ok &= tb_scene_add_box(s, "car", v3(x, 0.25f, z), v3(x + 4.2f, 1.0f, z + 1.8f)) >= 0;
        ok &= tb_scene_add_box(s, "car roof", v3(x + 1.0f, 1.0f, z + 0.15f), v3(x + 3.0f, 1.5f, z + 1.65f)) >= 0;
    }
    for (i = 0; i < 4; i++) {   /* benches */
        float x = -14.0f + 9.0f * (float)i, z = (i & 1) ? 6.6f : -7.2f;
        ok &= tb_scene_add_box(s, "bench", v3(x, 0.55f, z), v3(x + 1.8f, 0.65f, z + 0.6f)) >= 0;
    }
    return ok ? 0 : -1;
}

/* the draw callback: each object whose shadow this map can show */
static void draw_casters(void *user, const skgl_draw_info *info) {
    ex_app *app = (ex_app *)user;
    uint32_t i;
    for (i = 0; i < app->scene.object_count; i++) {
        const tb_object *o = &app->scene.objects[i];
        if (skgl_point_caster_visible(info, o->bounds))
            tb_gl_mesh_draw(&app->gl, &app->mesh, o->first_index, o->index_count);
    }
}

/* One lamp's light (u_cos_outer < -1: a lantern, no cone), with a soft
   edge to the cone and a quadratic fall-off to zero at its range, times
   the lamp's mask at this pixel; u_ambient: the dim sky alone. */
static const char fs_lighting[] =
    "#version 330 core\n"
    "in vec3 v_world;\n"
    "in vec3 v_normal;\n"
    "uniform vec3 u_light_pos, u_light_dir, u_color;\n"
    "uniform float u_range, u_cos_outer, u_cos_inner;\n"
    "uniform int u_ambient;\n"
    "uniform sampler2D u_mask;\n"
    "out vec4 o_color;\n"
    "void main() {\n"
    "    vec3 n = normalize(v_normal);\n"
    "    if (!gl_FrontFacing) n = -n;\n"
    "    vec3 albedo = n.y > 0.5 ? (v_world.y < 0.1 ? vec3(0.32, 0.32, 0.34) : vec3(0.55, 0.53, 0.5))\n"
    "                            : vec3(0.62, 0.5, 0.42);\n"
    "    if (u_ambient != 0) { o_color = vec4(albedo * vec3(0.025, 0.03, 0.05), 1.0); return; }\n"
    "    vec3 l = u_light_pos - v_world;\n"
    "    float d = length(l);\n"
    "    vec3 ld = l / max(d, 1e-6);\n"
    "    float fall = clamp(1.0 - d / u_range, 0.0, 1.0);\n"
    "    float cone = u_cos_outer < -1.0 ? 1.0 : smoothstep(u_cos_outer, u_cos_inner, dot(-ld, u_light_dir));\n"
    "    float v = texelFetch(u_mask, ivec2(gl_FragCoord.xy), 0).r;\n"
    "    o_color = vec4(albedo * u_color * (max(dot(n, ld), 0.0) * fall * fall * cone * v), 1.0);\n"
    "}\n";

typedef void (TB_GLAPI *blend_func_fn)(unsigned sfactor, unsigned dfactor);

int main(int argc, char **argv) {
    ex_options opt;
    ex_app app;
    skgl_desc desc = {0};
    skgl_context *sk = NULL;
    skgl_point_atlas *atlas = NULL;
    skgl_point *lights[N_LIGHTS];
    sk_vec3 pos[N_LIGHTS];
    skgl_scene scene;
    blend_func_fn blend_func;
    unsigned prog = 0, mask = 0;
    const char *vs = ex_world_vs, *fs = fs_lighting;
    sk_result r = SK_OK;
    const float spot_angle = 42.0f, spot_range = 10.0f, point_range = 7.0f;
    int i, status = 1, rc = ex_parse_args(argc, argv, "out/08_spot_lights.png", 0, &opt);
    if (rc != 0) return rc == 1 ? 0 : 2;
    memset(lights, 0, sizeof lights);

    if (ex_app_open(&app, &opt, "shadowkit 08: spot lights") != 0) return 1;
    if (ex_app_load_scene(&app, build_scene) != 0) goto done;
    {
        /* the one GL entry point the lighting needs beyond common.c's (a
           function pointer through memcpy: ISO C has no cast from void *) */
        void *f = app.getproc("glBlendFunc");
        if (!f) { fprintf(stderr, "glBlendFunc missing\n"); goto done; }
        memcpy(&blend_func, &f, sizeof f);
    }

    desc.getproc = app.getproc;
    desc.debug = opt.debug;
    desc.timing = opt.timing;
    if ((r = skgl_create(&desc, &sk)) != SK_OK) goto done;
    /* one atlas for every light's maps */
    if ((r = skgl_point_atlas_create(sk, 4096, 2048, &atlas)) != SK_OK) goto done;
    for (i = 0; i < N_LIGHTS; i++) {
        skgl_point_desc d;
        memset(&d, 0, sizeof d);          /* zero fields take the defaults */
        d.technique = SKGL_POINT_VSDCT;   /* the atlas's storage */
        d.atlas = atlas;
        d.spot_angle = i < N_SPOTS ? spot_angle : 0.0f;
        d.range = i < N_SPOTS ? spot_range : point_range;
        d.resolution = i < N_SPOTS ? 1024 : 512;   /* the most; the screen size selects less */
        d.select_resolution = d.cull_casters = d.scissor = 1;
        d.cull_faces = i >= N_SPOTS;
        if ((r = skgl_point_create(sk, &d, &lights[i])) != SK_OK) goto done;
        pos[i] = i < N_SPOTS ? spot_pos(i) : point_pos(i - N_SPOTS);
    }
    prog = ex_link_program(&app, ex_compile_shader(&app, GL_VERTEX_SHADER, 1, &vs, "08 lighting"),
                           ex_compile_shader(&app, GL_FRAGMENT_SHADER, 1, &fs, "08 lighting"), "08 lighting");
    if (!prog) goto done;

    scene.draw = draw_casters;
    scene.user = &app;
    scene.bounds = app.scene.bounds;

    while (ex_app_begin_frame(&app)) {
        skgl_camera cam;
        /* the camera walks down the street and back */
        float walk = 6.0f * sinf(0.15f * (float)app.time);
        sk_vec3 eye = v3(-21.0f + walk, 5.5f, 1.2f), target = v3(2.0f + walk, 0.8f, -0.5f);
        cam.view = sk_mat4_look_at(eye, target, v3(0, 1, 0));
        cam.proj = sk_mat4_perspective(1.0f, (float)app.width / (float)app.height, 0.1f, 80.0f);

        /* 1. every light's side from its size on the screen, packed; then the maps */
        if ((r = skgl_point_atlas_pack(sk, atlas, lights, N_LIGHTS, &cam, pos)) != SK_OK) break;
        for (i = 0; i < N_LIGHTS && r == SK_OK; i++)
            r = i < N_SPOTS ? skgl_spot_render(sk, lights[i], &cam, &scene, pos[i], spot_dir(i))
                            : skgl_point_render(sk, lights[i], &cam, &scene, pos[i]);
        if (r != SK_OK) break;

        /* 2. the camera's depth and normals */
        if (ex_gbuffer_render(&app, sk, &cam) != 0) goto done;

        /* 3. the sky's dim light, then each lamp added */
        app.gl.UseProgram(prog);
        app.glx.Uniform1i(app.gl.GetUniformLocation(prog, "u_ambient"), 1);
        ex_draw_scene(&app, prog, &cam);
        for (i = 0; i < N_LIGHTS; i++) {
            float cos_outer = i < N_SPOTS ? cosf(spot_angle * 3.14159265f / 180.0f) : -2.0f;
            float cos_inner = i < N_SPOTS ? cosf(0.8f * spot_angle * 3.14159265f / 180.0f) : -1.5f;
            float range = i < N_SPOTS ? spot_range : point_range;
            sk_vec3 dir = i < N_SPOTS ? ex_normalize(spot_dir(i)) : v3(0, -1, 0);
            /* the mask: 0, then the lamp's visibility inside its scissor */
            if (!(mask = ex_mask_texture(&app, sk, 0.0f))) goto done;
            if ((r = skgl_point_mask(sk, lights[i], &cam, app.gbuffer.depth_tex, app.gbuffer.color_tex, mask)) !=
                SK_OK)
                break;
            app.gl.UseProgram(prog);
            app.glx.Uniform1i(app.gl.GetUniformLocation(prog, "u_ambient"), 0);
            app.gl.Uniform3f(app.gl.GetUniformLocation(prog, "u_light_pos"), pos[i].x, pos[i].y, pos[i].z);
            app.gl.Uniform3f(app.gl.GetUniformLocation(prog, "u_light_dir"), dir.x, dir.y, dir.z);
            if (i < N_SPOTS) app.gl.Uniform3f(app.gl.GetUniformLocation(prog, "u_color"), 3.4f, 2.6f, 1.5f);
            else app.gl.Uniform3f(app.gl.GetUniformLocation(prog, "u_color"), 1.2f, 2.2f, 3.2f);
            app.glx.Uniform1fv(app.gl.GetUniformLocation(prog, "u_range"), 1, &range);
            app.glx.Uniform1fv(app.gl.GetUniformLocation(prog, "u_cos_outer"), 1, &cos_outer);
            app.glx.Uniform1fv(app.gl.GetUniformLocation(prog, "u_cos_inner"), 1, &cos_inner);
            ex_bind_texture(&app, prog, "u_mask", 0, mask);
            /* added over the ambient pass: same geometry, depth equal, no depth writes */
            {
                sk_mat4 vp = sk_mat4_mul(cam.proj, cam.view);
                app.gl.Enable(GL_BLEND);
                blend_func(GL_ONE, GL_ONE);
                app.gl.Enable(GL_DEPTH_TEST);
                app.gl.DepthFunc(GL_LEQUAL);
                app.gl.DepthMask(0);
                app.gl.UniformMatrix4fv(app.gl.GetUniformLocation(prog, "u_view_proj"), 1, 0, vp.m);
                tb_gl_mesh_draw(&app.gl, &app.mesh, 0, 0);
                app.gl.DepthMask(1);
                app.gl.Disable(GL_BLEND);
            }
        }
        app.gl.UseProgram(0);
        if (r != SK_OK) break;
        if (ex_app_end_frame(&app) != 0) goto done;
    }
    if (r == SK_OK) {
        int w = 0, h = 0, smallest = 1 << 30, largest = 0, culled = 0;
        double texels = 0.0;
        skgl_point_atlas_size(atlas, &w, &h);
        for (i = 0; i < N_LIGHTS; i++) {
            const skgl_point_frame_stats *st = skgl_point_stats(lights[i]);
            int faces = i < N_SPOTS ? 1 : 6;
            texels += (double)faces * st->resolution * st->resolution;
            culled += st->casters_culled;
            if (i < N_SPOTS && st->resolution < smallest) smallest = st->resolution;
            if (i < N_SPOTS && st->resolution > largest) largest = st->resolution;
        }
        printf("%d spots and %d point lights in one %d x %d atlas: spot maps %d^2 to %d^2, %.1f%% of the atlas "
               "used, %d (map, caster) pairs culled\n",
               N_SPOTS, N_POINTS, w, h, smallest, largest, 100.0 * texels / ((double)w * h), culled);
        if (opt.timing) {
            float ms = 0.0f;
            for (i = 0; i < N_LIGHTS; i++) ms += skgl_point_stats(lights[i])->shadow_ms;
            ex_print_ms("all shadow maps", ms);
        }
        status = 0;
    }

done:
    if (r != SK_OK) fprintf(stderr, "shadowkit: %s %s\n", sk_result_string(r), sk ? skgl_error_log(sk) : "");
    if (prog) app.gl.DeleteProgram(prog);
    for (i = 0; i < N_LIGHTS; i++)
        if (lights[i]) skgl_point_destroy(sk, lights[i]);
    if (atlas) skgl_point_atlas_destroy(sk, atlas);
    if (sk) skgl_destroy(sk);
    ex_app_close(&app);
    return status;
}
