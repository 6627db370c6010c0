/* 05_point_light.c - shadowkit tutorial 5: a point light (cube shadow maps
   and VSDCT, King & Newhall, seed 004).

   Run (from the repository root, after `make examples`):
     build/examples/05_point_light                    a window, cube map; Esc quits
     build/examples/05_point_light --technique vsdct  the virtual shadow depth cube texture
     build/examples/05_point_light --headless         writes out/05_point_light.png
   Options: --frames N, --out FILE (the scene is always the room).

   A point light sees all around it: six 90-degree maps, one per cube face.
   - SKGL_POINT_CUBE renders them into a GL depth cube map and looks it up
     with the light-to-point vector (samplerCubeShadow).
   - SKGL_POINT_VSDCT renders them as six rectangles of one 2D depth
     texture; a small RG16 cube map (the indirection) turns the direction
     into a place in that texture, kept away from the rectangles' edges so
     the filter never mixes two faces.
   Both store the depth of Eq. (5.4.6), so the comparison is the same.
   The seed's four savings are switches, all on here: faces whose frustum
   misses the view are not rendered, the draw callback skips the casters
   whose shadow cannot reach the view (skgl_point_caster_visible), the
   lighting touches only the light's rectangle on the screen, and the face
   resolution follows the light's size on the screen (N M^2 >= 2 S). */

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

/* our forward shader: lambert lighting from the point light, with a
   quadratic fall-off to zero at its range, times sk_point_shadow() */
static const char vs_src[] =
    "#version 330 core\n"
    "layout(location = 0) in vec3 a_position;\n"
    "layout(location = 1) in vec3 a_normal;\n"
    "uniform mat4 u_view_proj;\n"
    "out vec3 v_world;\n"
    "out vec3 v_normal;\n"
    "void main() {\n"
    "    v_world = a_position;\n"
    "    v_normal = a_normal;\n"
    "    gl_Position = u_view_proj * vec4(a_position, 1.0);\n"
    "}\n";
static const char fs_src[] =
    "in vec3 v_world;\n"
    "in vec3 v_normal;\n"
    "out vec4 o_color;\n"
    "void main() {\n"
    "    vec3 n = normalize(v_normal);\n"
    "    if (!gl_FrontFacing) n = -n;\n"
    "    vec3 l = sk_point_pos - v_world;\n"
    "    float d = length(l);\n"
    "    float fall = clamp(1.0 - d / sk_point_range, 0.0, 1.0);\n"
    "    float lit = max(dot(n, l / max(d, 1e-6)), 0.0) * fall * fall;\n"
    "    float v = sk_point_shadow(v_world, n);\n"
    "    vec3 albedo = vec3(0.85, 0.8, 0.72);\n"
    "    o_color = vec4(albedo * (0.06 + 1.6 * lit * v), 1.0);\n"
    "}\n";

static unsigned compile(const tb_gl_funcs *gl, unsigned type, int n, const char *const *src) {
    unsigned sh = gl->CreateShader(type);
    int ok = 0;
    gl->ShaderSource(sh, n, src, NULL);
    gl->CompileShader(sh);
    gl->GetShaderiv(sh, 0x8B81 /* GL_COMPILE_STATUS */, &ok);
    if (!ok) {
        char log[2048] = "";
        gl->GetShaderInfoLog(sh, (int)sizeof log, NULL, log);
        fprintf(stderr, "shader: %s\n", log);
        gl->DeleteShader(sh);
        return 0;
    }
    return sh;
}

/* "#version", the technique's define, shadowkit's snippet, our lighting */
static unsigned make_program(const tb_gl_funcs *gl, int vsdct) {
    const char *vs[1], *fs[4];
    unsigned v, f, p;
    int ok = 0;
    vs[0] = vs_src;
    fs[0] = "#version 330 core\n";
    fs[1] = vsdct ? "#define SK_POINT_VSDCT 1\n" : "";
    fs[2] = skgl_point_glsl_snippet();
    fs[3] = fs_src;
    v = compile(gl, 0x8B31 /* GL_VERTEX_SHADER */, 1, vs);
    f = compile(gl, 0x8B30 /* GL_FRAGMENT_SHADER */, 4, fs);
    if (!v || !f) return 0;
    p = gl->CreateProgram();
    gl->AttachShader(p, v);
    gl->AttachShader(p, f);
    gl->LinkProgram(p);
    gl->DeleteShader(v);
    gl->DeleteShader(f);
    gl->GetProgramiv(p, 0x8B82 /* GL_LINK_STATUS */, &ok);
    if (!ok) { gl->DeleteProgram(p); return 0; }
    return p;
}

int main(int argc, char **argv) {
    ex_options opt;
    ex_app app;
    skgl_desc desc = {0};
    skgl_point_desc pdesc;
    skgl_context *sk = NULL;
    skgl_point *lamp = NULL;
    skgl_scene scene;
    sk_vec3 eye = {4.6f, 3.4f, 0.8f}, target = {-2.0f, 0.6f, -0.6f}, up = {0, 1, 0};
    unsigned prog = 0;
    sk_result r = SK_OK;
    int status = 1, rc = ex_parse_args(argc, argv, "out/05_point_light.png", 0, &opt);
    if (rc != 0) return rc == 1 ? 0 : 2;
    memset(&pdesc, 0, sizeof pdesc);   /* zero fields take the defaults */
    if (opt.scene_path) { fprintf(stderr, "05_point_light: the scene is the room (no --scene)\n"); return 2; }
    if (opt.technique && strcmp(opt.technique, "vsdct") == 0) pdesc.technique = SKGL_POINT_VSDCT;
    else if (opt.technique && strcmp(opt.technique, "cube") != 0) {
        fprintf(stderr, "--technique: cube or vsdct\n");
        return 2;
    }
    pdesc.resolution = 512;          /* per face, the most */
    pdesc.range = 9.0f;
    pdesc.cull_faces = pdesc.cull_casters = pdesc.scissor = pdesc.select_resolution = 1;

    if (ex_app_open(&app, &opt, "shadowkit 05: point light") != 0) return 1;
    if (ex_app_load_scene(&app, build_scene) != 0) goto done;
    desc.getproc = app.getproc;
    desc.debug = 1;
    desc.timing = 1;
    if ((r = skgl_create(&desc, &sk)) != SK_OK) goto done;
    if ((r = skgl_point_create(sk, &pdesc, &lamp)) != SK_OK) goto done;
    if (!(prog = make_program(&app.gl, pdesc.technique == SKGL_POINT_VSDCT))) goto done;

    scene.draw = draw_casters;
    scene.user = &app;
    scene.bounds = app.scene.bounds;

    while (ex_app_begin_frame(&app)) {
        skgl_camera cam;
        sk_mat4 vp;
        /* the light circles between the pillars, bobbing up and down */
        float a = 0.5f * (float)app.time + 0.6f;
        sk_vec3 lp = ex_v3(1.6f * cosf(a), 1.9f + 0.6f * sinf(1.7f * a), 1.6f * sinf(a));
        cam.view = sk_mat4_look_at(eye, target, up);
        cam.proj = sk_mat4_perspective(1.0f, (float)app.width / (float)app.height, 0.05f, 30.0f);
        vp = sk_mat4_mul(cam.proj, cam.view);
        if ((r = skgl_point_render(sk, lamp, &cam, &scene, lp)) != SK_OK) break;
        app.gl.Enable(0x0B71 /* GL_DEPTH_TEST */);
        app.gl.DepthFunc(0x0201 /* GL_LESS */);
        app.gl.DepthMask(1);
        app.gl.UseProgram(prog);
        app.gl.UniformMatrix4fv(app.gl.GetUniformLocation(prog, "u_view_proj"), 1, 0, vp.m);
        if ((r = skgl_point_bind(sk, lamp, prog, 0)) != SK_OK) break;
        /* the cube map filters across its faces with seamless filtering;
           VSDCT's indirection must not */
        if (pdesc.technique == SKGL_POINT_CUBE) app.gl.Enable(0x884F /* GL_TEXTURE_CUBE_MAP_SEAMLESS */);
        else app.gl.Disable(0x884F);
        tb_gl_mesh_draw(&app.gl, &app.mesh, 0, 0);
        app.gl.UseProgram(0);
        if (ex_app_end_frame(&app) != 0) goto done;
    }
    if (r == SK_OK) {
        const skgl_stats *st = skgl_point_stats(lamp);
        printf("%s: %d faces rendered (%d culled) at %d^2, %d (face, caster) pairs culled, %.3f ms on the GPU\n",
               pdesc.technique == SKGL_POINT_VSDCT ? "vsdct" : "cube", st->faces_rendered, st->faces_culled,
               st->resolution, st->casters_culled, st->shadow_ms);
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
