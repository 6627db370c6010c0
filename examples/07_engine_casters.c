/* 07_engine_casters.c - shadowkit tutorial 7: casters drawn the way an
   engine draws them. Trees and ferns are instanced, alpha-tested and sway
   in the wind, all in their own vertex and fragment code, and they cast
   the same shadows under a PSSM sun and a point light as they show on the
   screen.

   Run (from any directory, after `make examples`):
     build/examples/07_engine_casters              a window; Esc quits
     build/examples/07_engine_casters --headless   writes out/07_engine_casters.png
   Options: --frames N, --out FILE, --debug, --timing (as in tutorial 01);
   --scene FILE puts the trees and ferns on the ground laid under your model
   (scaled to it), the camera and the lamp with them.

   The foliage textures are Minetest Game's (examples/assets/minetest/,
   CC BY-SA 3.0, from Debian's minetest-data package; LICENSE.txt there):
   default_leaves.png on leaf cubes, default_fern_3.png on crossed quads.
   Their transparent texels are holes, in the picture and in the shadows.

   One GLSL hook describes where a foliage vertex is: its model vertex, the
   instance's place (a per-instance attribute) and the wind. It is given
   to shadowkit once (skgl_caster_create) together with the alpha test,
   and the draw callback selects it (skgl_use_caster) before drawing the
   instances: shadowkit links it into every shadow pass it needs (here the
   cascades and the six cube faces) and puts its own matrices around it.
   The example's own G-buffer and lighting programs are built from the very
   same hook, so the camera sees exactly the geometry that casts.

   Each frame:
     1. skgl_shadow_render (PSSM, 4 cascades) and skgl_point_render (a cube
        map), both through draw_casters: the ground and trunks with
        shadowkit's program, the foliage with the hook;
     2. the camera's G-buffer: the scene (common.c), then the foliage with
        our G-buffer program (alpha-tested, instanced, swaying);
     3. the two masks: skgl_shadow_mask and skgl_point_mask;
     4. lighting: the scene and the foliage, each pixel lit by the sun and
        the lamp times their masks. */

#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"

#include "common.h"

#include <stb/stb_image.h>   /* Debian's libstb, as the testbed links it */

#include <math.h>
#include <stdio.h>
#include <string.h>

/* ---- the foliage's code: one hook for shadowkit and for our passes ---- */
static const char foliage_vertex[] =
    "layout(location = 0) in vec3 a_pos;\n"
    "layout(location = 1) in vec3 a_normal;\n"
    "layout(location = 2) in vec2 a_uv;\n"
    "layout(location = 3) in vec4 a_instance;   /* where, and the phase of its sway */\n"
    "uniform float u_time;\n"
    "uniform float u_sway;                     /* metres at one metre above the base */\n"
    "vec4 skgl_caster_position()\n"
    "{\n"
    "    v_uv = a_uv;\n"
    "    float bend = u_sway * (a_pos.y + 0.5) * sin(1.3 * u_time + a_instance.w);\n"
    "    return vec4(a_instance.xyz + a_pos + vec3(bend, 0.0, 0.6 * bend), 1.0);\n"
    "}\n";
static const char foliage_fragment[] =
    "uniform sampler2D u_albedo;\n"
    "void skgl_caster_fragment()\n"
    "{\n"
    "    if (texture(u_albedo, v_uv).a < 0.5) discard;\n"
    "}\n";

/* our own passes around the hook: G-buffer (world normals) and lighting */
static const char vs_foliage_main[] =
    "uniform mat4 u_view_proj;\n"
    "out vec3 v_world;\n"
    "out vec3 v_normal;\n"
    "void main() {\n"
    "    vec4 w = skgl_caster_position();\n"
    "    v_world = w.xyz;\n"
    "    v_normal = a_normal;\n"
    "    gl_Position = u_view_proj * w;\n"
    "}\n";
static const char fs_gbuffer_main[] =
    "in vec3 v_world;\n"
    "in vec3 v_normal;\n"
    "uniform vec3 u_eye;\n"
    "out vec4 o_normal;\n"
    "void main() {\n"
    "    skgl_caster_fragment();\n"
    "    vec3 n = normalize(v_normal);\n"
    "    if (dot(n, u_eye - v_world) < 0.0) n = -n;\n"
    "    o_normal = vec4(n, 1.0);\n"
    "}\n";
/* the lighting both kinds of object share */
static const char fs_shade[] =
    "uniform sampler2D u_sun_mask;\n"
    "uniform sampler2D u_lamp_mask;\n"
    "uniform vec3 u_sun_dir;                   /* travel direction */\n"
    "uniform vec3 u_lamp_pos;\n"
    "uniform float u_range;\n"
    "out vec4 o_color;\n"
    "vec3 shade(vec3 albedo, vec3 p, vec3 n) {\n"
    "    ivec2 px = ivec2(gl_FragCoord.xy);\n"
    "    float vs = texelFetch(u_sun_mask, px, 0).r, vl = texelFetch(u_lamp_mask, px, 0).r;\n"
    "    if (!gl_FrontFacing) n = -n;\n"
    "    float sun = max(dot(n, -normalize(u_sun_dir)), 0.0);\n"
    "    vec3 l = u_lamp_pos - p;\n"
    "    float d = length(l), fall = clamp(1.0 - d / u_range, 0.0, 1.0);\n"
    "    float lamp = max(dot(n, l / max(d, 1e-6)), 0.0) * fall * fall;\n"
    "    return albedo * (0.14 + 0.85 * sun * vs * vec3(1.0, 0.96, 0.88) + 2.2 * lamp * vl * vec3(1.0, 0.62, 0.3));\n"
    "}\n";
static const char fs_foliage_main[] =
    "in vec3 v_world;\n"
    "in vec3 v_normal;\n"
    "void main() {\n"
    "    skgl_caster_fragment();\n"
    "    vec3 albedo = 1.6 * texture(u_albedo, v_uv).rgb;   /* the textures are dark */\n"
    "    o_color = vec4(shade(albedo, v_world, normalize(v_normal)), 1.0);\n"
    "}\n";
/* the ground and the trunks: ex_world_vs (common.c), fs_shade, then this */
static const char fs_scene_main[] =
    "in vec3 v_world;\n"
    "in vec3 v_normal;\n"
    "void main() {\n"
    "    vec3 albedo = v_world.y < 0.01 ? vec3(0.42, 0.5, 0.3) : vec3(0.45, 0.33, 0.22);\n"
    "    o_color = vec4(shade(albedo, v_world, normalize(v_normal)), 1.0);\n"
    "}\n";

/* ---- the scene ---------------------------------------------------------- */
#define TREES 5
static const float tree_xz[TREES][2] = {{-4.5f, -3.0f}, {3.5f, -4.5f}, {5.5f, 2.5f}, {-2.0f, 4.5f}, {-7.5f, 3.0f}};
#define TRUNK_TOP 3.2f

/* ground and trunks: plain geometry, drawn by common.c's callback */
static int build_scene(tb_scene *s) {
    int i;
    if (tb_scene_add_ground(s, "ground", 0, 0, 14, 14, 0, 8, 8) < 0) return -1;
    for (i = 0; i < TREES; i++)
        if (tb_scene_add_pole(s, "trunk", tree_xz[i][0], 0, tree_xz[i][1], 0.22f, TRUNK_TOP + 0.5f) < 0) return -1;
    return 0;
}

/* a unit cube with a face's uv on each face (24 vertices), and two crossed
   unit quads standing on y = -0.5 (8 vertices): position, normal, uv */
static const float leaf_vertices[24 * 8] = {
#define F(px, py, pz, nx, ny, nz, u, v) px, py, pz, nx, ny, nz, u, v
    F(-.5f, -.5f, .5f, 0, 0, 1, 0, 0),   F(.5f, -.5f, .5f, 0, 0, 1, 1, 0),   F(.5f, .5f, .5f, 0, 0, 1, 1, 1),
    F(-.5f, .5f, .5f, 0, 0, 1, 0, 1),    F(.5f, -.5f, -.5f, 0, 0, -1, 0, 0), F(-.5f, -.5f, -.5f, 0, 0, -1, 1, 0),
    F(-.5f, .5f, -.5f, 0, 0, -1, 1, 1),  F(.5f, .5f, -.5f, 0, 0, -1, 0, 1),  F(.5f, -.5f, .5f, 1, 0, 0, 0, 0),
    F(.5f, -.5f, -.5f, 1, 0, 0, 1, 0),   F(.5f, .5f, -.5f, 1, 0, 0, 1, 1),   F(.5f, .5f, .5f, 1, 0, 0, 0, 1),
    F(-.5f, -.5f, -.5f, -1, 0, 0, 0, 0), F(-.5f, -.5f, .5f, -1, 0, 0, 1, 0), F(-.5f, .5f, .5f, -1, 0, 0, 1, 1),
    F(-.5f, .5f, -.5f, -1, 0, 0, 0, 1),  F(-.5f, .5f, .5f, 0, 1, 0, 0, 0),   F(.5f, .5f, .5f, 0, 1, 0, 1, 0),
    F(.5f, .5f, -.5f, 0, 1, 0, 1, 1),    F(-.5f, .5f, -.5f, 0, 1, 0, 0, 1),  F(-.5f, -.5f, -.5f, 0, -1, 0, 0, 0),
    F(.5f, -.5f, -.5f, 0, -1, 0, 1, 0),  F(.5f, -.5f, .5f, 0, -1, 0, 1, 1),  F(-.5f, -.5f, .5f, 0, -1, 0, 0, 1)};
static const float fern_vertices[8 * 8] = {
    F(-.45f, -.5f, -.45f, .7071f, 0, -.7071f, 0, 1), F(.45f, -.5f, .45f, .7071f, 0, -.7071f, 1, 1),
    F(.45f, .5f, .45f, .7071f, 0, -.7071f, 1, 0),    F(-.45f, .5f, -.45f, .7071f, 0, -.7071f, 0, 0),
    F(-.45f, -.5f, .45f, .7071f, 0, .7071f, 0, 1),   F(.45f, -.5f, -.45f, .7071f, 0, .7071f, 1, 1),
    F(.45f, .5f, -.45f, .7071f, 0, .7071f, 1, 0),    F(-.45f, .5f, .45f, .7071f, 0, .7071f, 0, 0)
#undef F
};
static const unsigned short quad_indices[36] = {0,  1,  2,  0,  2,  3,  4,  5,  6,  4,  6,  7,  8,  9,  10, 8,  10, 11,
                                                12, 13, 14, 12, 14, 15, 16, 17, 18, 16, 18, 19, 20, 21, 22, 20, 22, 23};

/* the foliage: a vertex array per kind (mesh + instance buffer) and its texture */
typedef struct foliage {
    unsigned vao, vbo, ibo, inst, tex;
    int indices, instances, unit;
    float sway;
} foliage;

typedef struct world {
    ex_app app;
    skgl_context *sk;
    skgl_caster *hook;
    foliage kinds[2];       /* leaves, ferns */
    unsigned gbuf_prog, foliage_prog, scene_prog;
    tb_gl_fbo lamp_mask;
    void (TB_GLAPI *VertexAttribDivisor)(unsigned, unsigned);
    void (TB_GLAPI *DrawElementsInstanced)(unsigned, int, unsigned, const void *, int);
    void (TB_GLAPI *Uniform1f)(int, float);
} world;

/* a deterministic scatter (the same picture every run) */
static float scatter(unsigned *state) {
    *state = *state * 1664525u + 1013904223u;
    return (float)(*state >> 8) / 16777216.0f;
}

/* Where the example's 28 m square of ground (its own, or the one
   common.c lays under a --scene model) lies in the world: origin o (the
   ground's centre, at its height) and scale k; the trees, ferns, camera and
   lamp are laid out on the square and carried there. */
typedef struct placement {
    sk_vec3 o;
    float k;
} placement;
static sk_vec3 place(const placement *pl, float x, float y, float z) {
    return ex_v3(pl->o.x + pl->k * x, pl->o.y + pl->k * y, pl->o.z + pl->k * z);
}

/* --scene: the ground common.c laid under the model (centred below it,
   1.2 times its larger side each way from the centre) */
static placement user_ground(sk_aabb model) {
    placement pl;
    float hx = model.max.x - model.min.x, hz = model.max.z - model.min.z, h = hx > hz ? hx : hz;
    pl.o = ex_v3(0.5f * (model.min.x + model.max.x), model.min.y, 0.5f * (model.min.z + model.max.z));
    pl.k = h > 0.0f ? 1.2f * h / 14.0f : 1.0f;
    return pl;
}

/* the trunks on the user's ground: the mesh uploaded again with them */
static int add_trunks(world *w, const placement *pl) {
    int i;
    for (i = 0; i < TREES; i++) {
        sk_vec3 b = place(pl, tree_xz[i][0], 0.0f, tree_xz[i][1]);
        if (tb_scene_add_pole(&w->app.scene, "trunk", b.x, b.y, b.z, 0.22f * pl->k, (TRUNK_TOP + 0.5f) * pl->k) < 0)
            return -1;
    }
    tb_gl_mesh_destroy(&w->app.gl, &w->app.mesh);
    return tb_gl_mesh_create(&w->app.gl, &w->app.mesh, &w->app.scene);
}

/* the instances carried onto the placement (xyz; the phase stays) */
static void place_all(const placement *pl, float *inst, int n) {
    int i;
    for (i = 0; i < n; i++) {
        sk_vec3 p = place(pl, inst[4 * i], inst[4 * i + 1], inst[4 * i + 2]);
        inst[4 * i] = p.x;
        inst[4 * i + 1] = p.y;
        inst[4 * i + 2] = p.z;
    }
}

/* the instances: leaf cubes in a ball above each trunk, ferns on the ground */
static int place_instances(float *leaves, float *ferns, int max_ferns) {
    unsigned seed = 7;
    int t, x, y, z, n = 0, f;
    for (t = 0; t < TREES; t++)
        for (y = 0; y <= 3; y++)
            for (z = -2; z <= 2; z++)
                for (x = -2; x <= 2; x++) {
                    float r2 = (float)(x * x + z * z) + 1.6f * (float)((y - 1) * (y - 1));
                    if (r2 > 5.2f || (x == 0 && z == 0 && y == 0)) continue;
                    leaves[4 * n] = tree_xz[t][0] + (float)x;
                    leaves[4 * n + 1] = TRUNK_TOP + (float)y;
                    leaves[4 * n + 2] = tree_xz[t][1] + (float)z;
                    leaves[4 * n + 3] = 0.9f * (float)t + 0.3f * (float)y;
                    n++;
                }
    for (f = 0; f < max_ferns; f++) {
        ferns[4 * f] = -11.0f + 22.0f * scatter(&seed);
        ferns[4 * f + 2] = -11.0f + 22.0f * scatter(&seed);
        ferns[4 * f + 1] = 0.5f;
        ferns[4 * f + 3] = 6.28f * scatter(&seed);
    }
    return n;
}

static unsigned load_texture(world *w, const char *asset, int unit) {
    const tb_gl_funcs *gl = &w->app.gl;
    int tw, th, comp;
    unsigned tex = 0;
    unsigned char *px;
    char path[1200];
    (void)ex_asset_path(asset, path, sizeof path);   /* from any working directory */
    px = stbi_load(path, &tw, &th, &comp, 4);
    if (!px) {
        fprintf(stderr, "%s: %s\n", path, stbi_failure_reason());
        return 0;
    }
    gl->GenTextures(1, &tex);
    gl->ActiveTexture(GL_TEXTURE0 + (unsigned)unit);
    gl->BindTexture(GL_TEXTURE_2D, tex);
    /* stb gives the top row first; uv (0, 0) is the bottom left here, as in GL */
    gl->PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    {
        int row;
        unsigned char *flip = (unsigned char *)malloc((size_t)tw * (size_t)th * 4);
        if (flip) {
            for (row = 0; row < th; row++)
                memcpy(flip + (size_t)row * tw * 4, px + (size_t)(th - 1 - row) * tw * 4, (size_t)tw * 4);
            gl->TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, tw, th, 0, GL_RGBA, GL_UNSIGNED_BYTE, flip);
            free(flip);
        }
    }
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);   /* pixel art */
    gl->TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl->ActiveTexture(GL_TEXTURE0);
    stbi_image_free(px);
    return tex;
}

static void foliage_upload(world *w, foliage *f, const float *vertices, int nv, int indices, const float *inst,
                           int instances, float scale) {
    const tb_gl_funcs *gl = &w->app.gl;
    float scaled[24 * 8];
    int i;
    /* the model scaled about its centre (positions only) */
    memcpy(scaled, vertices, sizeof(float) * 8 * (size_t)nv);
    for (i = 0; i < nv; i++) {
        scaled[8 * i] *= scale;
        scaled[8 * i + 1] *= scale;
        scaled[8 * i + 2] *= scale;
    }
    gl->GenVertexArrays(1, &f->vao);
    gl->GenBuffers(1, &f->vbo);
    gl->GenBuffers(1, &f->ibo);
    gl->GenBuffers(1, &f->inst);
    gl->BindVertexArray(f->vao);
    gl->BindBuffer(GL_ARRAY_BUFFER, f->vbo);
    gl->BufferData(GL_ARRAY_BUFFER, (long)sizeof(float) * 8 * nv, scaled, GL_STATIC_DRAW);
    gl->VertexAttribPointer(0, 3, GL_FLOAT, 0, 32, (void *)0);
    gl->VertexAttribPointer(1, 3, GL_FLOAT, 0, 32, (void *)12);
    gl->VertexAttribPointer(2, 2, GL_FLOAT, 0, 32, (void *)24);
    gl->EnableVertexAttribArray(0);
    gl->EnableVertexAttribArray(1);
    gl->EnableVertexAttribArray(2);
    gl->BindBuffer(GL_ARRAY_BUFFER, f->inst);
    gl->BufferData(GL_ARRAY_BUFFER, (long)sizeof(float) * 4 * instances, inst, GL_STATIC_DRAW);
    gl->VertexAttribPointer(3, 4, GL_FLOAT, 0, 16, (void *)0);
    gl->EnableVertexAttribArray(3);
    w->VertexAttribDivisor(3, 1);
    gl->BindBuffer(GL_ELEMENT_ARRAY_BUFFER, f->ibo);
    gl->BufferData(GL_ELEMENT_ARRAY_BUFFER, (long)sizeof quad_indices, quad_indices, GL_STATIC_DRAW);
    gl->BindVertexArray(0);
    f->indices = indices;
    f->instances = instances;
}

/* the foliage's instances, with whatever program is bound: its time, sway
   and texture unit at locations loc[0..2] */
static void foliage_draw(world *w, const int *loc) {
    int k;
    for (k = 0; k < 2; k++) {
        const foliage *f = &w->kinds[k];
        w->Uniform1f(loc[0], (float)w->app.time);
        w->Uniform1f(loc[1], f->sway);
        w->app.glx.Uniform1i(loc[2], f->unit);
        w->app.gl.BindVertexArray(f->vao);
        w->DrawElementsInstanced(GL_TRIANGLES, f->indices, GL_UNSIGNED_SHORT, 0, f->instances);
    }
}

/* shadowkit's draw callback: ground and trunks (common.c, shadowkit's own
   program), then the foliage through the hook */
static void draw_casters(void *user, const skgl_draw_info *info) {
    world *w = (world *)user;
    const int *loc;
    ex_draw_casters(&w->app, info);
    loc = skgl_use_caster(w->sk, w->hook);
    if (!loc) return;   /* the render returns the link error */
    foliage_draw(w, loc);
    skgl_use_caster(w->sk, NULL);
}

/* our program around the hook: "#version", the varyings, the hook, our main */
static unsigned foliage_program(world *w, const char *fs_main, const char *fs_extra, const char *what) {
    const char *vs[4] = {"#version 330 core\n", "out vec2 v_uv;\n", foliage_vertex, vs_foliage_main};
    const char *fs[5] = {"#version 330 core\n", "in vec2 v_uv;\n", foliage_fragment, fs_extra, fs_main};
    return ex_link_program(&w->app, ex_compile_shader(&w->app, GL_VERTEX_SHADER, 4, vs, what),
                           ex_compile_shader(&w->app, GL_FRAGMENT_SHADER, 5, fs, what), what);
}

static void set_shading(world *w, unsigned prog, sk_vec3 sun, sk_vec3 lamp, float range, unsigned sun_mask) {
    const tb_gl_funcs *gl = &w->app.gl;
    gl->Uniform3f(gl->GetUniformLocation(prog, "u_sun_dir"), sun.x, sun.y, sun.z);
    gl->Uniform3f(gl->GetUniformLocation(prog, "u_lamp_pos"), lamp.x, lamp.y, lamp.z);
    w->Uniform1f(gl->GetUniformLocation(prog, "u_range"), range);
    ex_bind_texture(&w->app, prog, "u_sun_mask", 0, sun_mask);
    ex_bind_texture(&w->app, prog, "u_lamp_mask", 1, w->lamp_mask.color_tex);
}

int main(int argc, char **argv) {
    static float leaves[TREES * 100 * 4], ferns[300 * 4];
    ex_options opt;
    world w;
    skgl_desc desc = {0};
    skgl_shadow_desc sdesc;
    skgl_point_desc pdesc;
    skgl_caster_desc cdesc;
    skgl_shadow *sun = NULL;
    skgl_point *lamp = NULL;
    skgl_scene scene;
    sk_vec3 eye = {-13.0f, 8.5f, 12.0f}, target = {0.0f, 1.5f, 0.0f}, up = {0, 1, 0};
    sk_vec3 sun_dir = ex_normalize(ex_v3(-0.55f, -1.0f, -0.35f));
    sk_result r = SK_OK;
    placement pl;
    float top, zn, zf;
    int status = 1, n_leaves, rc = ex_parse_args(argc, argv, "out/07_engine_casters.png", 0, &opt);
    if (rc != 0) return rc == 1 ? 0 : 2;
    memset(&w, 0, sizeof w);
    if (ex_app_open(&w.app, &opt, "shadowkit 07: engine casters") != 0) return 1;
    if (ex_app_load_scene(&w.app, build_scene) != 0) goto done;
    /* --scene: the trees and ferns on the ground laid under the user's model */
    pl.o = ex_v3(0, 0, 0);
    pl.k = 1.0f;
    if (opt.scene_path) {
        pl = user_ground(w.app.model_bounds);
        if (add_trunks(&w, &pl) != 0) goto done;
    }
    {
        /* object pointer to function pointer by copy (ISO C has no cast between them) */
        void *p[3];
        p[0] = w.app.getproc("glVertexAttribDivisor");
        p[1] = w.app.getproc("glDrawElementsInstanced");
        p[2] = w.app.getproc("glUniform1f");
        if (!p[0] || !p[1] || !p[2]) { fprintf(stderr, "07: GL 3.3 entry points missing\n"); goto done; }
        memcpy(&w.VertexAttribDivisor, &p[0], sizeof p[0]);
        memcpy(&w.DrawElementsInstanced, &p[1], sizeof p[1]);
        memcpy(&w.Uniform1f, &p[2], sizeof p[2]);
    }

    /* the foliage: textures on units 4 and 5 (shadowkit's passes keep to 0-3) */
    n_leaves = place_instances(leaves, ferns, 300);
    place_all(&pl, leaves, n_leaves);
    place_all(&pl, ferns, 300);
    /* leaf cubes 4 cm apart: no face of one lies in a neighbour's, where
       the two would fight for the pixel (differently from one rasteriser
       to the next) */
    foliage_upload(&w, &w.kinds[0], leaf_vertices, 24, 36, leaves, n_leaves, 0.96f * pl.k);
    foliage_upload(&w, &w.kinds[1], fern_vertices, 8, 12, ferns, 300, pl.k);
    w.kinds[0].unit = 4;
    w.kinds[0].sway = 0.06f;
    w.kinds[1].unit = 5;
    w.kinds[1].sway = 0.12f;
    if (!(w.kinds[0].tex = load_texture(&w, "examples/assets/minetest/default_leaves.png", 4))) goto done;
    if (!(w.kinds[1].tex = load_texture(&w, "examples/assets/minetest/default_fern_3.png", 5))) goto done;

    desc.getproc = w.app.getproc;
    desc.debug = opt.debug;
    desc.timing = opt.timing;
    if ((r = skgl_create(&desc, &w.sk)) != SK_OK) goto done;
    memset(&sdesc, 0, sizeof sdesc);
    sdesc.technique = SKGL_PSSM;       /* 4 cascades of 2048^2 */
    if ((r = skgl_shadow_create(w.sk, &sdesc, &sun)) != SK_OK) goto done;
    memset(&pdesc, 0, sizeof pdesc);
    pdesc.range = 9.0f * pl.k;
    pdesc.near_plane = 0.05f * pl.k;
    pdesc.resolution = 1024;
    if ((r = skgl_point_create(w.sk, &pdesc, &lamp)) != SK_OK) goto done;

    /* the hook, once: shadowkit links it into each pass that needs it */
    memset(&cdesc, 0, sizeof cdesc);
    cdesc.label = "foliage";
    cdesc.vertex = foliage_vertex;
    cdesc.fragment = foliage_fragment;
    cdesc.varyings = "vec2 v_uv;";
    cdesc.uniforms[0] = "u_time";
    cdesc.uniforms[1] = "u_sway";
    cdesc.uniforms[2] = "u_albedo";
    if ((r = skgl_caster_create(w.sk, &cdesc, &w.hook)) != SK_OK) goto done;

    /* our programs, from the same hook */
    w.gbuf_prog = foliage_program(&w, fs_gbuffer_main, "", "07 foliage G-buffer");
    w.foliage_prog = foliage_program(&w, fs_foliage_main, fs_shade, "07 foliage lighting");
    {
        const char *vs = ex_world_vs, *fs[3] = {"#version 330 core\n", fs_shade, fs_scene_main};
        w.scene_prog = ex_link_program(&w.app, ex_compile_shader(&w.app, GL_VERTEX_SHADER, 1, &vs, "07 scene"),
                                       ex_compile_shader(&w.app, GL_FRAGMENT_SHADER, 3, fs, "07 scene"),
                                       "07 scene");
    }
    if (!w.gbuf_prog || !w.foliage_prog || !w.scene_prog) goto done;

    scene.draw = draw_casters;
    scene.user = &w;
    scene.bounds = w.app.scene.bounds;
    top = pl.o.y + pl.k * (TRUNK_TOP + 4.0f);   /* the leaves above the trunks, and their sway */
    if (scene.bounds.max.y < top) scene.bounds.max.y = top;
    eye = place(&pl, eye.x, eye.y, eye.z);
    target = place(&pl, target.x, target.y, target.z);
    zn = 0.3f * pl.k;
    zf = 60.0f * pl.k;
    if (opt.scene_path) ex_camera_from_bounds(scene.bounds, &eye, &target, &zn, &zf);   /* the model and the trees */
    printf("07: %d leaf cubes and 300 ferns, instanced and alpha-tested, under PSSM and a point light\n", n_leaves);

    while (ex_app_begin_frame(&w.app)) {
        const tb_gl_funcs *gl = &w.app.gl;
        skgl_camera cam;
        sk_mat4 vp;
        unsigned sun_mask;
        int locs[3];
        float a = 0.4f * (float)w.app.time;
        sk_vec3 lamp_pos = place(&pl, 1.2f * cosf(a), 1.6f, 1.2f * sinf(a));
        cam.view = sk_mat4_look_at(eye, target, up);
        cam.proj = sk_mat4_perspective(0.9f, (float)w.app.width / (float)w.app.height, zn, zf);
        vp = sk_mat4_mul(cam.proj, cam.view);

        /* 1. the maps: cascades and cube faces, foliage through the hook */
        if ((r = skgl_shadow_render(w.sk, sun, &cam, &scene, sun_dir)) != SK_OK) break;
        if ((r = skgl_point_render(w.sk, lamp, &cam, &scene, lamp_pos)) != SK_OK) break;

        /* 2. the camera's G-buffer: the scene, then the foliage into it */
        if (ex_gbuffer_render(&w.app, w.sk, &cam) != 0) goto done;
        tb_gl_fbo_bind(gl, &w.app.gbuffer);
        gl->UseProgram(w.gbuf_prog);
        gl->UniformMatrix4fv(gl->GetUniformLocation(w.gbuf_prog, "u_view_proj"), 1, 0, vp.m);
        gl->Uniform3f(gl->GetUniformLocation(w.gbuf_prog, "u_eye"), eye.x, eye.y, eye.z);
        locs[0] = gl->GetUniformLocation(w.gbuf_prog, "u_time");
        locs[1] = gl->GetUniformLocation(w.gbuf_prog, "u_sway");
        locs[2] = gl->GetUniformLocation(w.gbuf_prog, "u_albedo");
        foliage_draw(&w, locs);
        gl->BindVertexArray(0);

        /* 3. the masks: the sun's, then the lamp's (our own R16F target) */
        if (!(sun_mask = ex_mask_texture(&w.app, w.sk, -1.0f))) goto done;
        if (!w.lamp_mask.fbo || w.lamp_mask.width != w.app.width || w.lamp_mask.height != w.app.height) {
            if (w.lamp_mask.fbo) {
                skgl_forget_texture(w.sk, w.lamp_mask.color_tex);
                tb_gl_fbo_destroy(gl, &w.lamp_mask);
            }
            if (tb_gl_fbo_create(gl, &w.lamp_mask, w.app.width, w.app.height, TB_GL_COLOR_R16F) != 0) goto done;
        }
        if ((r = skgl_shadow_mask(w.sk, sun, &cam, w.app.gbuffer.depth_tex, w.app.gbuffer.color_tex, sun_mask)) !=
            SK_OK)
            break;
        if ((r = skgl_point_mask(w.sk, lamp, &cam, w.app.gbuffer.depth_tex, w.app.gbuffer.color_tex,
                                 w.lamp_mask.color_tex)) != SK_OK)
            break;

        /* 4. lighting: the scene, then the foliage */
        ex_bind_frame(&w.app);
        gl->UseProgram(w.scene_prog);
        set_shading(&w, w.scene_prog, sun_dir, lamp_pos, pdesc.range, sun_mask);
        ex_draw_scene(&w.app, w.scene_prog, &cam);
        gl->UseProgram(w.foliage_prog);
        set_shading(&w, w.foliage_prog, sun_dir, lamp_pos, pdesc.range, sun_mask);
        gl->UniformMatrix4fv(gl->GetUniformLocation(w.foliage_prog, "u_view_proj"), 1, 0, vp.m);
        locs[0] = gl->GetUniformLocation(w.foliage_prog, "u_time");
        locs[1] = gl->GetUniformLocation(w.foliage_prog, "u_sway");
        locs[2] = gl->GetUniformLocation(w.foliage_prog, "u_albedo");
        foliage_draw(&w, locs);
        gl->BindVertexArray(0);
        gl->UseProgram(0);
        if (ex_app_end_frame(&w.app) != 0) goto done;
    }
    if (r == SK_OK) {
        const skgl_shadow_frame_stats *st = skgl_shadow_stats(sun);
        printf("07: sun %d cascades, lamp %d faces\n", st->maps, skgl_point_stats(lamp)->faces_rendered);
        if (opt.timing) {
            ex_print_ms("cascades", st->shadow_ms);
            ex_print_ms("cube faces", skgl_point_stats(lamp)->shadow_ms);
        }
        status = 0;
    }

done:
    if (r != SK_OK) fprintf(stderr, "shadowkit: %s %s\n", sk_result_string(r), w.sk ? skgl_error_log(w.sk) : "");
    {
        const tb_gl_funcs *gl = &w.app.gl;
        int k;
        if (gl->DeleteProgram) {
            if (w.gbuf_prog) gl->DeleteProgram(w.gbuf_prog);
            if (w.foliage_prog) gl->DeleteProgram(w.foliage_prog);
            if (w.scene_prog) gl->DeleteProgram(w.scene_prog);
            for (k = 0; k < 2; k++) {
                foliage *f = &w.kinds[k];
                if (f->vao) gl->DeleteVertexArrays(1, &f->vao);
                if (f->vbo) gl->DeleteBuffers(1, &f->vbo);
                if (f->ibo) gl->DeleteBuffers(1, &f->ibo);
                if (f->inst) gl->DeleteBuffers(1, &f->inst);
                if (f->tex) gl->DeleteTextures(1, &f->tex);
            }
            if (w.lamp_mask.fbo) tb_gl_fbo_destroy(gl, &w.lamp_mask);
        }
    }
    if (w.hook) skgl_caster_destroy(w.sk, w.hook);
    if (lamp) skgl_point_destroy(w.sk, lamp);
    if (sun) skgl_shadow_destroy(w.sk, sun);
    if (w.sk) skgl_destroy(w.sk);
    ex_app_close(&w.app);
    return status;
}
