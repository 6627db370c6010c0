/* shadowkit_web.c - the live demo page (make web): every technique of
   shadowkit_gl.h on WebGL2, built with Emscripten.

   - scenes: boxes, a fence and a street under a spot light made here (the
     street picks the "spot" technique: skgl_spot_render, a skgl_point
     with a cone), and the bunny, the Sponza ivy and
     curtains when make web found ../shared/scenes (baked by scene_bake.c and
     embedded);
   - a technique switcher, and two techniques side by side (the left and
     right halves of the view) at the same texel budget;
   - the camera on the left mouse button (orbit) and the wheel (distance),
     the light on the right button or shift + drag;
   - an overlay of the stats (maps, texels, passes, GPU ms where
     EXT_disjoint_timer_query_webgl2 exists, read late as the stats are);
   - cascades (PSSM, LiSPSM, LSPSM: by the view depths of the layers) and
     PVSM's tiles (their screen rectangles) tinted on demand.
   The page (web/index.html) drives it through web_set() and reads
   web_stats(). Everything is embedded: the page works from disk, offline. */
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"

#include <emscripten.h>
#include <emscripten/html5.h>
#include <GLES3/gl3.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* the WebGL2 library's own entry point, left out of emscripten_webgl_get_proc_address */
extern void glGetBufferSubData(unsigned target, long offset, long size, void *data);
static void *web_getproc(const char *name)
{
    if (strcmp(name, "glGetBufferSubData") == 0) return (void *)glGetBufferSubData;
    return emscripten_webgl_get_proc_address(name);
}

/* ---- scenes -------------------------------------------------------------- */
typedef struct mesh {
    float *pos, *nrm;
    unsigned *idx;
    int nv, ni, cap_v, cap_i;
    sk_aabb bounds;
} mesh;

static void mesh_quad(mesh *m, const float p[4][3], const float n[3])
{
    int k, base = m->nv;
    if (m->nv + 4 > m->cap_v) {
        m->cap_v = 2 * m->cap_v + 64;
        m->pos = (float *)realloc(m->pos, sizeof(float) * 3 * (size_t)m->cap_v);
        m->nrm = (float *)realloc(m->nrm, sizeof(float) * 3 * (size_t)m->cap_v);
    }
    if (m->ni + 6 > m->cap_i) {
        m->cap_i = 2 * m->cap_i + 96;
        m->idx = (unsigned *)realloc(m->idx, sizeof(unsigned) * (size_t)m->cap_i);
    }
    for (k = 0; k < 4; k++) {
        memcpy(m->pos + 3 * (m->nv + k), p[k], sizeof(float) * 3);
        memcpy(m->nrm + 3 * (m->nv + k), n, sizeof(float) * 3);
    }
    m->nv += 4;
    m->idx[m->ni++] = (unsigned)base; m->idx[m->ni++] = (unsigned)base + 1; m->idx[m->ni++] = (unsigned)base + 2;
    m->idx[m->ni++] = (unsigned)base; m->idx[m->ni++] = (unsigned)base + 2; m->idx[m->ni++] = (unsigned)base + 3;
}

static void mesh_box(mesh *m, float x0, float y0, float z0, float x1, float y1, float z1)
{
    const float q[6][4][3] = {
        {{x1, y0, z0}, {x1, y1, z0}, {x1, y1, z1}, {x1, y0, z1}}, {{x0, y0, z1}, {x0, y1, z1}, {x0, y1, z0}, {x0, y0, z0}},
        {{x0, y1, z0}, {x0, y1, z1}, {x1, y1, z1}, {x1, y1, z0}}, {{x0, y0, z1}, {x0, y0, z0}, {x1, y0, z0}, {x1, y0, z1}},
        {{x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1}, {x0, y0, z1}}, {{x0, y0, z0}, {x0, y1, z0}, {x1, y1, z0}, {x1, y0, z0}}};
    const float n[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    int f;
    for (f = 0; f < 6; f++) mesh_quad(m, q[f], n[f]);
}

static void mesh_bounds(mesh *m)
{
    int i;
    m->bounds.min.x = m->bounds.min.y = m->bounds.min.z = 1e30f;
    m->bounds.max.x = m->bounds.max.y = m->bounds.max.z = -1e30f;
    for (i = 0; i < m->nv; i++) {
        const float *p = m->pos + 3 * i;
        m->bounds.min.x = fminf(m->bounds.min.x, p[0]); m->bounds.max.x = fmaxf(m->bounds.max.x, p[0]);
        m->bounds.min.y = fminf(m->bounds.min.y, p[1]); m->bounds.max.y = fmaxf(m->bounds.max.y, p[1]);
        m->bounds.min.z = fminf(m->bounds.min.z, p[2]); m->bounds.max.z = fmaxf(m->bounds.max.z, p[2]);
    }
}

static void scene_boxes(mesh *m)
{
    mesh_box(m, -20, -0.1f, -20, 20, 0, 20);
    mesh_box(m, -1, 0, -1, 1, 2, 1);
    mesh_box(m, 3, 0, -4, 5, 4, -2);
    mesh_box(m, -6, 0, 2, -3, 1, 5);
    mesh_box(m, -2, 3, 4, 0, 3.5f, 6);
    mesh_box(m, 6, 0, 5, 6.5f, 6, 5.5f);
}

static void scene_fence(mesh *m)
{
    int i;
    mesh_box(m, -15, -0.1f, -15, 15, 0, 15);
    for (i = 0; i <= 20; i++) mesh_box(m, -10.0f + i - 0.02f, 0, -0.02f, -10.0f + i + 0.02f, 2, 0.02f);
    for (i = 1; i <= 9; i++) mesh_box(m, -10, 0.2f * i - 0.01f, -0.01f, 10, 0.2f * i + 0.01f, 0.01f);
    for (i = 0; i <= 40; i++) mesh_box(m, -10.0f + 0.5f * i - 0.01f, 0, -0.01f, -10.0f + 0.5f * i + 0.01f, 2, 0.01f);
    for (i = 0; i < 8; i++) mesh_box(m, -7.0f + 2 * i - 0.05f, 0, 3.95f, -7.0f + 2 * i + 0.05f, 3, 4.05f);
}

/* a street for the spot light: houses on both sides, lamp posts, crates
   and a bench on the road */
static void scene_street(mesh *m)
{
    int i;
    mesh_box(m, -15, -0.1f, -15, 15, 0, 15);
    for (i = 0; i < 5; i++) {
        float x = -12.0f + 6.0f * (float)i;
        mesh_box(m, x, 0, -11, x + 4, 3.0f + (float)(i % 3), -7);
        mesh_box(m, x + 1, 0, 7, x + 5, 4.0f - (float)(i % 2), 11);
        mesh_box(m, x + 2.95f, 0, -5.05f, x + 3.05f, 3.2f, -4.95f);   /* a post, its arm over the road */
        mesh_box(m, x + 2.95f, 3.1f, -5.05f, x + 3.05f, 3.2f, -3.5f);
    }
    mesh_box(m, -2, 0, -1, -1, 1, 0);
    mesh_box(m, -0.6f, 0, 0.4f, 0.2f, 0.8f, 1.2f);
    mesh_box(m, 2, 0.45f, -2, 4.5f, 0.55f, -1.6f);                  /* a bench: seat and legs */
    mesh_box(m, 2.1f, 0, -1.95f, 2.2f, 0.45f, -1.65f);
    mesh_box(m, 4.3f, 0, -1.95f, 4.4f, 0.45f, -1.65f);
}

/* a scene baked by scene_bake.c; 0 ok */
static int scene_file(mesh *m, const char *path)
{
    FILE *f = fopen(path, "rb");
    unsigned h[3];
    float b[6];
    int ok;
    if (!f) return -1;
    ok = fread(h, 4, 3, f) == 3 && h[0] == 0x53574B53u && fread(b, 4, 6, f) == 6;
    if (ok) {
        m->nv = m->cap_v = (int)h[1];
        m->ni = m->cap_i = (int)h[2];
        m->pos = (float *)malloc(12u * h[1]);
        m->nrm = (float *)malloc(12u * h[1]);
        m->idx = (unsigned *)malloc(4u * h[2]);
        ok = m->pos && m->nrm && m->idx && fread(m->pos, 12, h[1], f) == h[1] && fread(m->nrm, 12, h[1], f) == h[1] &&
             fread(m->idx, 4, h[2], f) == h[2];
    }
    fclose(f);
    return ok ? 0 : -1;
}

/* ---- techniques ------------------------------------------------------------ */
enum { K_DIR, K_POINT, K_SOFT, K_SPOT };
typedef struct tech {
    const char *name;
    int kind, technique, maps;   /* maps: layers the texel budget is shared by */
} tech;
static const tech g_techs[] = {
    {"STANDARD", K_DIR, SKGL_STANDARD, 1}, {"PSSM", K_DIR, SKGL_PSSM, 4},         {"PSM", K_DIR, SKGL_PSM, 1},
    {"LiSPSM", K_DIR, SKGL_LISPSM, 4},     {"LSPSM", K_DIR, SKGL_LSPSM, 4},       {"FERKO", K_DIR, SKGL_FERKO, 1},
    {"RMSM", K_DIR, SKGL_RMSM, 1},         {"cube", K_POINT, SKGL_POINT_CUBE, 6}, {"VSDCT", K_POINT, SKGL_POINT_VSDCT, 6},
    {"PCSS", K_SOFT, SKGL_SOFT_PCSS, 1},   {"PVSM", K_SOFT, SKGL_SOFT_PVSM, 1},   {"spot", K_SPOT, SKGL_POINT_VSDCT, 1}};
#define TECHS ((int)(sizeof g_techs / sizeof g_techs[0]))

typedef struct light {
    int tech;
    void *obj;                   /* skgl_shadow / skgl_point / skgl_soft */
    unsigned mask;               /* R8, the canvas' size */
    char stats[256];
} light;

/* ---- the page's state ---------------------------------------------------- */
static struct {
    skgl_context *sk;
    int w, h;
    mesh scenes[6];
    const char *scene_names[6];
    int nscenes, scene, side, tint, budget;
    unsigned vao, vbo[3];
    unsigned prog_g, prog_c, depth, normal, fb_g, fb_m;
    light l[2];
    float yaw, pitch, dist;        /* the camera's orbit */
    float sun_az, sun_el;          /* the light: azimuth, elevation */
    int drag, drag_light, lx, ly;
    char info[1024];
} S;

static unsigned shader(unsigned type, const char *src)
{
    const char *s[2] = {"#version 300 es\nprecision highp float;\n", src};
    unsigned sh = glCreateShader(type);
    int ok = 0;
    glShaderSource(sh, 2, s, NULL);
    glCompileShader(sh);
    glGetShaderiv(sh, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[512];
        glGetShaderInfoLog(sh, sizeof log, NULL, log);
        printf("shader: %s\n", log);
    }
    return sh;
}
static unsigned program(const char *vs, const char *fs)
{
    unsigned p = glCreateProgram(), a = shader(GL_VERTEX_SHADER, vs), b = shader(GL_FRAGMENT_SHADER, fs);
    glAttachShader(p, a);
    glAttachShader(p, b);
    glLinkProgram(p);
    glDeleteShader(a);
    glDeleteShader(b);
    return p;
}

static const char vs_g[] = "layout(location = 0) in vec3 a_pos;\nlayout(location = 1) in vec3 a_nrm;\n"
                           "uniform mat4 u_vp;\nout vec3 v_n;\n"
                           "void main() { v_n = a_nrm; gl_Position = u_vp * vec4(a_pos, 1.0); }\n";
static const char fs_g[] = "in vec3 v_n;\nout vec4 o_n;\n"
                           "void main() { vec3 n = normalize(v_n); o_n = vec4(gl_FrontFacing ? n : -n, 1.0); }\n";
/* the lit view: the masks of A (left) and B (right), the cascades tinted
   by view depth (u_splits), PVSM's tiles outlined (u_rects) */
static const char vs_c[] = "out vec2 v_uv;\nvoid main() { vec2 p = vec2(float((gl_VertexID << 1) & 2), "
                           "float(gl_VertexID & 2)); v_uv = p; gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0); }\n";
static const char fs_c[] =
    "in vec2 v_uv;\nout vec4 o;\n"
    "uniform sampler2D u_depth, u_normal, u_mask0, u_mask1;\n"
    "uniform mat4 u_inv_vp;\nuniform vec3 u_light, u_eye;\nuniform int u_side, u_tint0, u_tint1, u_rects0, u_rects1;\n"
    "uniform vec4 u_splits0[2], u_splits1[2];\nuniform vec4 u_rect0[16], u_rect1[16];\n"
    "vec3 tint(int i) { return i == 0 ? vec3(1.0, 0.7, 0.7) : i == 1 ? vec3(0.7, 1.0, 0.7) : i == 2 ? vec3(0.7, 0.8, 1.0)"
    " : i == 3 ? vec3(1.0, 1.0, 0.6) : vec3(1.0, 0.7, 1.0); }\n"
    "void main() {\n"
    "  ivec2 px = ivec2(gl_FragCoord.xy);\n"
    "  float d = texelFetch(u_depth, px, 0).r;\n"
    "  if (d >= 1.0) { o = vec4(0.62, 0.72, 0.85, 1.0); return; }\n"
    "  vec4 w = u_inv_vp * vec4(v_uv * 2.0 - 1.0, d * 2.0 - 1.0, 1.0);\n"
    "  vec3 p = w.xyz / w.w, n = normalize(texelFetch(u_normal, px, 0).xyz);\n"
    "  bool right = u_side != 0 && v_uv.x > 0.5;\n"
    "  float vis = right ? texelFetch(u_mask1, px, 0).r : texelFetch(u_mask0, px, 0).r;\n"
    "  vec3 l = normalize(u_light - p * float(u_light != u_light));\n"
    "  vec3 albedo = vec3(0.82, 0.8, 0.76);\n"
    "  vec3 c = albedo * (0.22 + 0.78 * max(dot(n, l), 0.0) * vis);\n"
    "  float vd = distance(p, u_eye);\n"
    "  if (right ? u_tint1 != 0 : u_tint0 != 0) {\n"
    "    vec4 s0 = right ? u_splits1[0] : u_splits0[0], s1 = right ? u_splits1[1] : u_splits0[1];\n"
    "    int k = vd < s0.y ? 0 : vd < s0.z ? 1 : vd < s0.w ? 2 : vd < s1.x ? 3 : 4;\n"
    "    c *= tint(k);\n"
    "  }\n"
    "  int nr = right ? u_rects1 : u_rects0;\n"
    "  for (int i = 0; i < 16; i++) {\n"
    "    if (i >= nr) break;\n"
    "    vec4 r = right ? u_rect1[i] : u_rect0[i];\n"
    "    vec2 q = gl_FragCoord.xy;\n"
    "    bool inside = all(greaterThanEqual(q, r.xy)) && all(lessThanEqual(q, r.zw));\n"
    "    bool edge = inside && (q.x < r.x + 2.0 || q.y < r.y + 2.0 || q.x > r.z - 2.0 || q.y > r.w - 2.0);\n"
    "    if (edge) c = mix(c, tint(i % 5) * 0.9, 0.8);\n"
    "  }\n"
    "  if (u_side != 0 && abs(gl_FragCoord.x - 0.5 * float(textureSize(u_depth, 0).x)) < 1.0) c = vec3(1.0);\n"
    "  o = vec4(pow(c, vec3(1.0 / 2.2)), 1.0);\n"
    "}\n";

static skgl_camera camera(void)
{
    skgl_camera c;
    sk_aabb b = S.scenes[S.scene].bounds;
    float cx = 0.5f * (b.min.x + b.max.x), cz = 0.5f * (b.min.z + b.max.z);
    sk_vec3 eye, at, up = {0.0f, 1.0f, 0.0f};
    at.x = cx; at.y = 1.0f; at.z = cz;
    eye.x = cx + S.dist * cosf(S.pitch) * sinf(S.yaw);
    eye.y = 1.0f + S.dist * sinf(S.pitch);
    eye.z = cz + S.dist * cosf(S.pitch) * cosf(S.yaw);
    c.view = sk_mat4_look_at(eye, at, up);
    c.proj = sk_mat4_perspective(0.9f, (float)S.w / (float)S.h, 0.2f, 120.0f);
    return c;
}
static sk_vec3 eye_of(void)
{
    skgl_camera c = camera();
    sk_mat4 inv;
    sk_vec3 e = {0, 0, 0};
    sk_mat4_inverse(c.view, &inv);
    return sk_mat4_transform_point(inv, e);
}
static sk_vec3 sun_dir(void)
{
    sk_vec3 d;
    d.x = -cosf(S.sun_el) * sinf(S.sun_az);
    d.y = -sinf(S.sun_el);
    d.z = -cosf(S.sun_el) * cosf(S.sun_az);
    return d;
}
/* the lamp (cube, VSDCT) and the area light: on a dome over the scene,
   sized by it, at the sun's azimuth and elevation */
static sk_vec3 lamp_pos(float above)
{
    sk_aabb b = S.scenes[S.scene].bounds;
    float ext = 0.5f * fmaxf(b.max.x - b.min.x, b.max.z - b.min.z), r = 0.45f * ext * cosf(S.sun_el);
    sk_vec3 p;
    p.x = 0.5f * (b.min.x + b.max.x) + r * sinf(S.sun_az);
    p.y = b.max.y * above + 0.25f * ext * sinf(S.sun_el);
    p.z = 0.5f * (b.min.z + b.max.z) + r * cosf(S.sun_az);
    return p;
}
static skgl_area_light area_light(void)
{
    skgl_area_light a;
    sk_aabb b = S.scenes[S.scene].bounds;
    memset(&a, 0, sizeof a);
    a.position = lamp_pos(1.3f);
    a.direction.x = 0.5f * (b.min.x + b.max.x) - a.position.x;
    a.direction.y = -a.position.y;
    a.direction.z = 0.5f * (b.min.z + b.max.z) - a.position.z;
    a.half_width = a.half_height = 0.03f * fmaxf(b.max.x - b.min.x, b.max.z - b.min.z);
    return a;
}

/* the spot (the "spot" technique): at the lamp, aimed at the middle of the
   scene's floor, a 35 degree cone */
static sk_vec3 spot_dir(void)
{
    sk_aabb b = S.scenes[S.scene].bounds;
    sk_vec3 p = lamp_pos(0.9f), d;
    d.x = 0.5f * (b.min.x + b.max.x) - p.x;
    d.y = b.min.y - p.y;
    d.z = 0.5f * (b.min.z + b.max.z) - p.z;
    return d;
}

static void draw(void *user, const skgl_draw_info *info)
{
    (void)user; (void)info;
    glBindVertexArray(S.vao);
    glDrawElements(GL_TRIANGLES, S.scenes[S.scene].ni, GL_UNSIGNED_INT, NULL);
    glBindVertexArray(0);
}

static void upload_scene(void)
{
    mesh *m = &S.scenes[S.scene];
    glBindVertexArray(S.vao);
    glBindBuffer(GL_ARRAY_BUFFER, S.vbo[0]);
    glBufferData(GL_ARRAY_BUFFER, 12 * m->nv, m->pos, GL_STATIC_DRAW);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 12, 0);
    glEnableVertexAttribArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, S.vbo[1]);
    glBufferData(GL_ARRAY_BUFFER, 12 * m->nv, m->nrm, GL_STATIC_DRAW);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 12, 0);
    glEnableVertexAttribArray(1);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, S.vbo[2]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, 4 * m->ni, m->idx, GL_STATIC_DRAW);
    glBindVertexArray(0);
}

static void free_light(light *l)
{
    if (!l->obj) return;
    if (g_techs[l->tech].kind == K_DIR) skgl_shadow_destroy(S.sk, (skgl_shadow *)l->obj);
    else if (g_techs[l->tech].kind == K_POINT || g_techs[l->tech].kind == K_SPOT)
        skgl_point_destroy(S.sk, (skgl_point *)l->obj);
    else skgl_soft_destroy(S.sk, (skgl_soft *)l->obj);
    l->obj = NULL;
}

/* the light of technique t at the budget's resolution (texels shared by its maps) */
static void make_light(light *l, int t)
{
    const tech *e = &g_techs[t];
    int res = (int)sqrtf((float)S.budget / (float)e->maps), p2 = 64;
    sk_result r;
    while (p2 * 2 <= res) p2 *= 2;
    free_light(l);
    l->tech = t;
    if (e->kind == K_DIR) {
        skgl_shadow_desc d;
        memset(&d, 0, sizeof d);
        d.technique = (skgl_technique)e->technique;
        d.resolution = res;
        d.cascades = e->technique == SKGL_LISPSM ? 4 : 0;
        r = skgl_shadow_create(S.sk, &d, (skgl_shadow **)&l->obj);
    } else if (e->kind == K_POINT || e->kind == K_SPOT) {
        skgl_point_desc d;
        memset(&d, 0, sizeof d);
        d.technique = (skgl_point_technique)e->technique;
        d.resolution = p2;
        d.range = 60.0f;
        if (e->kind == K_SPOT) d.spot_angle = 35.0f;
        d.bias = SKGL_BIAS_NORMAL_OFFSET;   /* see the manual's OpenGL ES section: SwiftShader */
        r = skgl_point_create(S.sk, &d, (skgl_point **)&l->obj);
    } else {
        skgl_soft_desc d;
        memset(&d, 0, sizeof d);
        d.technique = (skgl_soft_technique)e->technique;
        d.resolution = e->technique == SKGL_SOFT_PVSM ? p2 * 2 : res;
        r = skgl_soft_create(S.sk, &d, (skgl_soft **)&l->obj);
    }
    if (r != SK_OK) {
        snprintf(l->stats, sizeof l->stats, "%s: %s", e->name, skgl_error_log(S.sk));
        l->obj = NULL;
    }
}

static void ms(char *out, size_t n, const char *what, float v)
{
    if (v >= 0.0f) snprintf(out, n, " %s %.2f ms", what, v);
    else snprintf(out, n, " %s -", what);
}

/* one light's frame into its mask; the uniforms of its tint */
static void render_light(light *l, int slot, unsigned prog, const skgl_camera *cam, const skgl_scene *sc)
{
    const tech *e = &g_techs[l->tech];
    char a[40], b[40];
    float splits[8] = {0, 1e30f, 1e30f, 1e30f, 1e30f, 1e30f, 1e30f, 1e30f}, rects[64];
    int nr = 0, i, tint = 0;
    if (!l->obj) return;
    if (e->kind == K_DIR) {
        skgl_shadow *s = (skgl_shadow *)l->obj;
        const skgl_shadow_frame_stats *st;
        if (e->technique == SKGL_FERKO || e->technique == SKGL_RMSM) skgl_shadow_analyze(S.sk, s, cam, sc, sun_dir(), S.depth);
        skgl_shadow_render(S.sk, s, cam, sc, sun_dir());
        skgl_shadow_mask(S.sk, s, cam, S.depth, S.normal, l->mask);
        st = skgl_shadow_stats(s);
        ms(a, sizeof a, "shadow", st->shadow_ms);
        ms(b, sizeof b, "mask", st->mask_ms);
        snprintf(l->stats, sizeof l->stats, "%s: %d maps of %dx%d, %.2f Mtexels, %d passes;%s;%s", e->name, st->maps,
                 st->map_width, st->map_height, st->texels * 1e-6, st->passes, a, b);
        if (st->maps > 1 && e->technique != SKGL_RMSM) {
            tint = 1;
            for (i = 0; i <= st->maps && i < 8; i++) splits[i] = st->splits[i];
            for (; i < 8; i++) splits[i] = 1e30f;
        }
    } else if (e->kind == K_POINT || e->kind == K_SPOT) {
        skgl_point *p = (skgl_point *)l->obj;
        const skgl_point_frame_stats *st;
        if (e->kind == K_SPOT) skgl_spot_render(S.sk, p, cam, sc, lamp_pos(0.9f), spot_dir());
        else skgl_point_render(S.sk, p, cam, sc, lamp_pos(0.9f));
        skgl_point_mask(S.sk, p, cam, S.depth, S.normal, l->mask);
        st = skgl_point_stats(p);
        ms(a, sizeof a, "shadow", st->shadow_ms);
        ms(b, sizeof b, "mask", st->mask_ms);
        snprintf(l->stats, sizeof l->stats, "%s: %d faces, %.2f Mtexels, %d passes;%s;%s", e->name, st->faces_rendered,
                 st->texels * 1e-6, st->passes, a, b);
    } else {
        skgl_soft *s = (skgl_soft *)l->obj;
        const skgl_soft_frame_stats *st;
        skgl_area_light al = area_light();
        sk_rect r[16];
        skgl_soft_render(S.sk, s, cam, sc, &al, S.depth, S.normal, l->mask);
        st = skgl_soft_stats(s);
        ms(a, sizeof a, "shadow", st->shadow_ms);
        ms(b, sizeof b, "rest", st->mask_ms);
        snprintf(l->stats, sizeof l->stats, "%s: %d tiles, %.2f Mtexels, %d passes;%s;%s", e->name, st->tiles,
                 st->texels * 1e-6, st->passes, a, b);
        if (e->technique == SKGL_SOFT_PVSM) {
            nr = skgl_soft_tile_rects(s, r, 16);
            if (nr > 16) nr = 16;
            for (i = 0; i < nr; i++) {
                rects[4 * i] = r[i].x0; rects[4 * i + 1] = r[i].y0;
                rects[4 * i + 2] = r[i].x1; rects[4 * i + 3] = r[i].y1;
            }
        }
    }
    glUseProgram(prog);
    glUniform4fv(glGetUniformLocation(prog, slot ? "u_splits1" : "u_splits0"), 2, splits);
    glUniform1i(glGetUniformLocation(prog, slot ? "u_tint1" : "u_tint0"), S.tint && tint);
    glUniform1i(glGetUniformLocation(prog, slot ? "u_rects1" : "u_rects0"), S.tint ? nr : 0);
    if (nr) glUniform4fv(glGetUniformLocation(prog, slot ? "u_rect1" : "u_rect0"), nr, rects);
}

static unsigned texture(unsigned ifmt, unsigned fmt, unsigned type)
{
    unsigned t;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glTexImage2D(GL_TEXTURE_2D, 0, (int)ifmt, S.w, S.h, 0, fmt, type, NULL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    skgl_remember_texture(S.sk, t, S.w, S.h);   /* WebGL2 cannot be asked a texture's size */
    return t;
}

static EM_BOOL frame(double time, void *user)
{
    skgl_camera cam = camera();
    sk_mat4 vp = sk_mat4_mul(cam.proj, cam.view), inv;
    skgl_scene sc;
    sk_vec3 eye = eye_of(), lp;
    float zero[4] = {0, 0, 0, 0}, one = 1.0f, lv[3];
    int k, n = S.side ? 2 : 1;
    (void)time; (void)user;
    sc.draw = draw;
    sc.user = NULL;
    sc.bounds = S.scenes[S.scene].bounds;
    /* the G-buffer */
    glBindFramebuffer(GL_FRAMEBUFFER, S.fb_g);
    glViewport(0, 0, S.w, S.h);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glClearBufferfv(GL_COLOR, 0, zero);
    glClearBufferfv(GL_DEPTH, 0, &one);
    glUseProgram(S.prog_g);
    glUniformMatrix4fv(glGetUniformLocation(S.prog_g, "u_vp"), 1, GL_FALSE, vp.m);
    draw(NULL, NULL);
    glDisable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    /* the lights */
    for (k = 0; k < n; k++) render_light(&S.l[k], k, S.prog_c, &cam, &sc);
    /* the lit view */
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, S.w, S.h);
    glUseProgram(S.prog_c);
    sk_mat4_inverse(vp, &inv);
    glUniformMatrix4fv(glGetUniformLocation(S.prog_c, "u_inv_vp"), 1, GL_FALSE, inv.m);
    lp = g_techs[S.l[0].tech].kind == K_DIR ? sun_dir() : lamp_pos(0.9f);
    if (g_techs[S.l[0].tech].kind == K_DIR) { lv[0] = -lp.x * 1e4f; lv[1] = -lp.y * 1e4f; lv[2] = -lp.z * 1e4f; }
    else if (g_techs[S.l[0].tech].kind == K_SOFT) { skgl_area_light a = area_light(); lv[0] = a.position.x; lv[1] = a.position.y; lv[2] = a.position.z; }
    else { lv[0] = lp.x; lv[1] = lp.y; lv[2] = lp.z; }
    glUniform3fv(glGetUniformLocation(S.prog_c, "u_light"), 1, lv);
    glUniform3f(glGetUniformLocation(S.prog_c, "u_eye"), eye.x, eye.y, eye.z);
    glUniform1i(glGetUniformLocation(S.prog_c, "u_side"), S.side);
    glActiveTexture(GL_TEXTURE0); glBindTexture(GL_TEXTURE_2D, S.depth);
    glActiveTexture(GL_TEXTURE1); glBindTexture(GL_TEXTURE_2D, S.normal);
    glActiveTexture(GL_TEXTURE2); glBindTexture(GL_TEXTURE_2D, S.l[0].mask);
    glActiveTexture(GL_TEXTURE3); glBindTexture(GL_TEXTURE_2D, S.l[1].mask);
    glActiveTexture(GL_TEXTURE0);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    snprintf(S.info, sizeof S.info, "%s | %s%s%s", S.scene_names[S.scene], S.l[0].stats, S.side ? " || " : "",
             S.side ? S.l[1].stats : "");
    return EM_TRUE;
}

/* ---- the page's controls ------------------------------------------------- */
EMSCRIPTEN_KEEPALIVE void web_set(int a, int b, int side, int tint, int scene, int budget)
{
    if (a < 0 || a >= TECHS) a = 0;
    if (b < 0 || b >= TECHS) b = 0;
    if (scene < 0 || scene >= S.nscenes) scene = 0;
    if (budget < 65536) budget = 65536;
    if (budget > 16777216) budget = 16777216;
    if (scene != S.scene) { S.scene = scene; upload_scene(); }
    if (!S.l[0].obj || a != S.l[0].tech || budget != S.budget || !S.l[1].obj || b != S.l[1].tech) {
        S.budget = budget;
        make_light(&S.l[0], a);
        make_light(&S.l[1], b);
    }
    S.side = side != 0;
    S.tint = tint != 0;
}
EMSCRIPTEN_KEEPALIVE const char *web_stats(void) { return S.info; }
EMSCRIPTEN_KEEPALIVE int web_scenes(void) { return S.nscenes; }
EMSCRIPTEN_KEEPALIVE const char *web_scene_name(int i) { return i >= 0 && i < S.nscenes ? S.scene_names[i] : ""; }
EMSCRIPTEN_KEEPALIVE int web_techs(void) { return TECHS; }
EMSCRIPTEN_KEEPALIVE const char *web_tech_name(int i) { return i >= 0 && i < TECHS ? g_techs[i].name : ""; }

static EM_BOOL on_mouse(int type, const EmscriptenMouseEvent *e, void *user)
{
    (void)user;
    if (type == EMSCRIPTEN_EVENT_MOUSEDOWN) {
        S.drag = 1;
        S.drag_light = e->button == 2 || e->shiftKey;
        S.lx = (int)e->targetX;
        S.ly = (int)e->targetY;
    } else if (type == EMSCRIPTEN_EVENT_MOUSEUP) {
        S.drag = 0;
    } else if (S.drag) {
        float dx = (float)((int)e->targetX - S.lx), dy = (float)((int)e->targetY - S.ly);
        if (S.drag_light) {
            S.sun_az += 0.005f * dx;
            S.sun_el = fminf(fmaxf(S.sun_el - 0.005f * dy, 0.15f), 1.5f);
        } else {
            S.yaw -= 0.005f * dx;
            S.pitch = fminf(fmaxf(S.pitch + 0.005f * dy, 0.05f), 1.45f);
        }
        S.lx = (int)e->targetX;
        S.ly = (int)e->targetY;
    }
    return EM_TRUE;
}
static EM_BOOL on_wheel(int type, const EmscriptenWheelEvent *e, void *user)
{
    (void)type; (void)user;
    S.dist = fminf(fmaxf(S.dist * (e->deltaY > 0 ? 1.1f : 1.0f / 1.1f), 3.0f), 80.0f);
    return EM_TRUE;
}

int main(void)
{
    EmscriptenWebGLContextAttributes attr;
    EMSCRIPTEN_WEBGL_CONTEXT_HANDLE gl;
    skgl_desc desc;
    static const char *files[3][2] = {{"/scenes/bunny.bin", "bunny"}, {"/scenes/ivy.bin", "Sponza ivy"},
                                      {"/scenes/curtains.bin", "Sponza curtains"}};
    unsigned bufs[1] = {GL_COLOR_ATTACHMENT0};
    int i;
    emscripten_get_canvas_element_size("#canvas", &S.w, &S.h);
    emscripten_webgl_init_context_attributes(&attr);
    attr.majorVersion = 2;
    attr.antialias = 0;
    attr.preserveDrawingBuffer = 1;   /* for the screenshot */
    gl = emscripten_webgl_create_context("#canvas", &attr);
    if (gl <= 0) { printf("no WebGL2\n"); return 1; }
    emscripten_webgl_make_context_current(gl);
    emscripten_webgl_enable_extension(gl, "EXT_color_buffer_float");
    emscripten_webgl_enable_extension(gl, "EXT_float_blend");
    emscripten_webgl_enable_extension(gl, "EXT_disjoint_timer_query_webgl2");
    memset(&desc, 0, sizeof desc);
    desc.getproc = web_getproc;
    desc.timing = 1;
    if (skgl_create(&desc, &S.sk) != SK_OK) { printf("skgl_create failed\n"); return 1; }
    scene_boxes(&S.scenes[0]); S.scene_names[0] = "boxes";
    scene_fence(&S.scenes[1]); S.scene_names[1] = "fence";
    scene_street(&S.scenes[2]); S.scene_names[2] = "spot street";
    S.nscenes = 3;
    for (i = 0; i < 3; i++)
        if (scene_file(&S.scenes[S.nscenes], files[i][0]) == 0) S.scene_names[S.nscenes++] = files[i][1];
    for (i = 0; i < S.nscenes; i++) mesh_bounds(&S.scenes[i]);
    glGenVertexArrays(1, &S.vao);
    glGenBuffers(3, S.vbo);
    S.prog_g = program(vs_g, fs_g);
    S.prog_c = program(vs_c, fs_c);
    glUseProgram(S.prog_c);
    glUniform1i(glGetUniformLocation(S.prog_c, "u_depth"), 0);
    glUniform1i(glGetUniformLocation(S.prog_c, "u_normal"), 1);
    glUniform1i(glGetUniformLocation(S.prog_c, "u_mask0"), 2);
    glUniform1i(glGetUniformLocation(S.prog_c, "u_mask1"), 3);
    S.depth = texture(GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT);
    S.normal = texture(GL_RGBA16F, GL_RGBA, GL_HALF_FLOAT);
    S.l[0].mask = texture(GL_R8, GL_RED, GL_UNSIGNED_BYTE);
    S.l[1].mask = texture(GL_R8, GL_RED, GL_UNSIGNED_BYTE);
    glGenFramebuffers(1, &S.fb_g);
    glBindFramebuffer(GL_FRAMEBUFFER, S.fb_g);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, S.depth, 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, S.normal, 0);
    glDrawBuffers(1, bufs);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    S.yaw = 0.7f; S.pitch = 0.5f; S.dist = 22.0f;
    S.sun_az = 2.4f; S.sun_el = 0.9f;
    S.scene = 0;
    upload_scene();
    web_set(1, 6, 1, 1, 0, 4194304);   /* PSSM beside RMSM, 4 Mtexels each, cascades tinted */
    emscripten_set_mousedown_callback("#canvas", NULL, EM_TRUE, on_mouse);
    emscripten_set_mousemove_callback("#canvas", NULL, EM_TRUE, on_mouse);
    emscripten_set_mouseup_callback("#canvas", NULL, EM_TRUE, on_mouse);
    emscripten_set_wheel_callback("#canvas", NULL, EM_TRUE, on_wheel);
    emscripten_request_animation_frame_loop(frame, NULL);
    EM_ASM(if (Module.ready) Module.ready(););   /* the page fills its menus */
    return 0;
}
