/* test_gl_caster_varyings.c - caster programs' varyings (desc.varyings)
   through every kind of caster pass, each interpolation qualifier, and
   what the hooks may declare.

   Scene: a 28 x 28 m ground and a row of 8 boxes of 1 m (instanced, one
   draw call; the vertex hook places instance i at x = -5.25 + 1.5 i,
   y = 2.5), 320 x 180. Each caster hands gl_InstanceID to its fragment
   hook through one varying, which discards the odd instances: the
   reference (Embree) has the 4 even boxes only. Casters, one per
   qualifier: plain `float v;`, smooth, `flat int v;`, noperspective,
   centroid, and "preproc": `flat ID_TYPE v;` inside #if, after a #define
   of its type, comments holding ';' and the macros k, c, p, b and s
   (names shadowkit's geometry shaders and forwarding function use, which
   the varyings' macros must not reach). Passes:
     STANDARD   sun, the depth pass
     PSSM-L     sun, PSSM 4 cascades, layered (the geometry shader of
                layered.geom; GL_ARB_gpu_shader5 invocations, or the GL 3.3
                loop in test_gl_caster_varyings_loop)
     cube       point light, a depth pass per face
     cube-L     point light, layered
     PVSM       area light: the conservative low-resolution pass
                (soft_cons.geom) and the depth tiles
     PVSM+G     the same with its own G-buffer (depth_tex 0): the camera's
                view through the hooks too
   Errors as in test_gl_casters: hard lights tb_metric_shadow (wrong
   pixels per shadowed pixel, %), PVSM penumbra + umbra mean |difference|.
   Checked: every render SK_OK with no skgl_use_caster failure; each
   qualifier's error within the bound; each qualifier's mask identical to
   the plain float's (a constant per instance interpolates to itself
   under any qualifier) within MASK_DIFF_MAX pixels; the control, the same
   caster without its fragment hook (all 8 boxes), at least 2 x worse.
   Then the "collide" caster: hooks that declare every name shadowkit's
   passes used before the skgl_ prefix (u_view_proj, u_model, u_texel,
   u_conservative, u_eye, u_layer_vp, u_layer_of, u_layer_count, v_world,
   g_box, g_edge, o_cons, o_true, o_cons_copy, o_normal) and macros named
   as shadowkit's locals and swizzles after the hooks (w, xy, z, p, n,
   inside; each hook's macros are #undef'd after it): links in every pass,
   its mask the control's. Then desc.varyings' contracts: lists,
   unterminated comments, unknown directives, in/out, integer without
   flat, reserved names, each refused naming its line; a type error and a
   name declared twice reported at line 20000 + its line; a link error's
   log intact.

   Can fail: against the header before these fixes (commit 4d91cf6) 40
   checks fail: the smooth, noperspective and centroid casters at
   skgl_caster_create ("0:4(1): error: storage qualifiers must come after
   ...", inside shadowkit's preamble), preproc refused by the old parser,
   `flat int v` in every geometry-shader pass ("unsized array index must
   be constant"), the collide caster ("redeclaration of `u_view_proj' has
   incorrect type"), `float a, b;` and the directives passed to the
   compiler instead of refused, the link log "caster 'unlinked':
   skgl_caster_create: caster 'unlinked': ..." (vsnprintf reading the log
   it writes). With the hooks' #undef lines left out, the collide caster
   fails under PVSM and PVSM+G (4 checks); with the varyings' left out,
   preproc fails in every geometry-shader pass (8). */
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "sk_test.h"
#include "gl_test_util.h"

#include <stdint.h>
#include <stdio.h>

#define W 320
#define H 180
#define BOXES 8
#define MASK_DIFF_MAX 0

typedef struct xgl {
    void (*DrawElementsInstanced)(unsigned, int, unsigned, const void *, int);
} xgl;

/* ---- the casters -------------------------------------------------------- */
enum { Q_PLAIN, Q_SMOOTH, Q_FLAT, Q_NOPERSPECTIVE, Q_CENTROID, Q_PREPROC, Q_COUNT };
static const char *const q_name[Q_COUNT] = {"plain", "smooth", "flat", "noperspective", "centroid", "preproc"};
static const char *const q_varyings[Q_COUNT] = {
    "float v;",
    "smooth float v;",
    "flat int v;",
    "noperspective float v;",
    "centroid float v;",
    "// the instance; this comment holds ';' and /* */\n"
    "#define ID_TYPE int\n"
    "#define k 3          // k, c, p, b, s: names of shadowkit's shaders\n"
    "#define c vec4\n"
    "#define p 1.0\n"
    "#define b 0.5\n"
    "#define s 2\n"
    "#if defined(SKGL_CASTER) && SKGL_CASTER_PASS >= 0   /* every stage; every pass */\n"
    "flat ID_TYPE v; /* a trailing; comment */\n"
    "#else\n"
    "vec4 never;\n"
    "#endif\n"};
static const int q_int[Q_COUNT] = {0, 0, 1, 0, 0, 1};

#define BOX_X0 -5.25f
#define BOX_DX 1.5f
#define BOX_Y 2.5f

static const char vs_float[] = "layout(location = 0) in vec3 a_pos;\n"
                               "vec4 skgl_caster_position()\n"
                               "{\n"
                               "    v = float(gl_InstanceID);\n"
                               "    return vec4(a_pos + vec3(-5.25 + 1.5 * float(gl_InstanceID), 2.5, 0.0), 1.0);\n"
                               "}\n";
static const char vs_int[] = "layout(location = 0) in vec3 a_pos;\n"
                             "vec4 skgl_caster_position()\n"
                             "{\n"
                             "    v = gl_InstanceID;\n"
                             "    return vec4(a_pos + vec3(-5.25 + 1.5 * float(gl_InstanceID), 2.5, 0.0), 1.0);\n"
                             "}\n";
/* the odd instances discarded: v is the instance's number */
static const char fs_float[] = "void skgl_caster_fragment() { if (mod(v + 0.5, 2.0) >= 1.0) discard; }\n";
static const char fs_int[] = "void skgl_caster_fragment() { if ((v & 1) == 1) discard; }\n";

/* every name shadowkit's passes declared before the skgl_ prefix, and
   macros named as their locals and swizzles (.w, .xy, .z) after the hooks */
static const char vs_collide[] = "#define w 4.0\n"
                                 "layout(location = 0) in vec3 a_pos;\n"
                                 "uniform vec4 u_view_proj;\n"
                                 "uniform vec4 u_model;\n"
                                 "uniform vec4 u_texel;\n"
                                 "uniform vec4 u_conservative;\n"
                                 "uniform vec4 u_layer_vp;\n"
                                 "uniform vec4 u_layer_of;\n"
                                 "uniform vec4 u_layer_count;\n"
                                 "vec4 skgl_caster_position()\n"
                                 "{\n"
                                 "    vec4 z = u_view_proj + u_model + u_texel + u_conservative + u_layer_vp +\n"
                                 "             u_layer_of + u_layer_count;\n"
                                 "    v_world = 0.0;\n"
                                 "    return vec4(a_pos + vec3(-5.25 + 1.5 * float(gl_InstanceID), 2.5, 0.0) +\n"
                                 "                0.0 * z.xyz, 1.0);\n"
                                 "}\n";
static const char fs_collide[] = "#define xy 0.0\n"
                                 "#define z 1.0\n"
                                 "#define p 1.0\n"
                                 "#define n 2.0\n"
                                 "#define inside 3\n"
                                 "uniform vec4 u_eye;\n"
                                 "float g_box, g_edge, o_cons, o_true, o_cons_copy, o_normal;\n"
                                 "void skgl_caster_fragment()\n"
                                 "{\n"
                                 "    g_box = g_edge = o_cons = o_true = o_cons_copy = o_normal = u_eye.x;\n"
                                 "    if (v_world + g_box > 1e30) discard;\n"
                                 "}\n";

/* ---- geometry ----------------------------------------------------------- */
static const float cube_pos[8 * 3] = {-.5f, -.5f, -.5f, .5f, -.5f, -.5f, .5f, .5f, -.5f, -.5f, .5f, -.5f,
                                      -.5f, -.5f, .5f,  .5f, -.5f, .5f,  .5f, .5f, .5f,  -.5f, .5f, .5f};
static const uint32_t cube_idx[36] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                      3, 6, 2, 3, 7, 6, 0, 4, 7, 0, 7, 3, 1, 2, 6, 1, 6, 5};

#define GL_ARRAY_BUFFER 0x8892
#define GL_ELEMENT_ARRAY_BUFFER 0x8893
#define GL_STATIC_DRAW 0x88E4
#define GL_FLOAT 0x1406
#define GL_UNSIGNED_INT 0x1405
#define GL_TRIANGLES 0x0004

typedef struct world {
    gt_env e;
    xgl x;
    tb_object ground;
    unsigned vao, vbo, ibo;
    skgl_caster *caster;   /* drawn by the callback */
    int calls_failed;
} world;

static void draw(void *user, const skgl_draw_info *info) {
    world *w = (world *)user;
    const tb_gl_funcs *gl = &w->e.gl;
    (void)info;
    tb_gl_mesh_draw(gl, &w->e.mesh, w->ground.first_index, w->ground.index_count);
    if (!skgl_use_caster(w->e.sk, w->caster)) { w->calls_failed++; return; }
    gl->BindVertexArray(w->vao);
    w->x.DrawElementsInstanced(GL_TRIANGLES, 36, GL_UNSIGNED_INT, 0, BOXES);
    skgl_use_caster(w->e.sk, NULL);
}

static int world_init(world *w) {
    tb_scene s;
    tb_gl_getproc_fn gp;
    const tb_gl_funcs *gl;
    void *fp;
    int i;
    memset(w, 0, sizeof *w);
    tb_scene_init(&s);
    tb_scene_add_ground(&s, "ground", 0, 0, 14, 14, 0, 8, 8);
    for (i = 0; i < BOXES; i += 2) {   /* the reference: the even instances */
        float x = BOX_X0 + BOX_DX * (float)i;
        tb_scene_add_box(&s, "box", gt_v3(x - 0.5f, BOX_Y - 0.5f, -0.5f), gt_v3(x + 0.5f, BOX_Y + 0.5f, 0.5f));
    }
    w->ground = s.objects[0];
    if (gt_env_init(&w->e, &s, W, H) != 0) return -1;
    gp = tb_gl_context_getproc(w->e.ctx);
    fp = gp("glDrawElementsInstanced");
    memcpy(&w->x.DrawElementsInstanced, &fp, sizeof fp);
    if (!w->x.DrawElementsInstanced) { SK_CHECK_MSG(0, "glDrawElementsInstanced missing"); return -1; }
    gl = &w->e.gl;
    gl->GenVertexArrays(1, &w->vao);
    gl->GenBuffers(1, &w->vbo);
    gl->GenBuffers(1, &w->ibo);
    gl->BindVertexArray(w->vao);
    gl->BindBuffer(GL_ARRAY_BUFFER, w->vbo);
    gl->BufferData(GL_ARRAY_BUFFER, sizeof cube_pos, cube_pos, GL_STATIC_DRAW);
    gl->VertexAttribPointer(0, 3, GL_FLOAT, 0, 12, (void *)0);
    gl->EnableVertexAttribArray(0);
    gl->BindBuffer(GL_ELEMENT_ARRAY_BUFFER, w->ibo);
    gl->BufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof cube_idx, cube_idx, GL_STATIC_DRAW);
    gl->BindVertexArray(0);
    return 0;
}

static void world_free(world *w) {
    if (w->e.ctx) {
        w->e.gl.DeleteVertexArrays(1, &w->vao);
        w->e.gl.DeleteBuffers(1, &w->vbo);
        w->e.gl.DeleteBuffers(1, &w->ibo);
    }
    gt_env_free(&w->e);
}

/* ---- one pass kind ------------------------------------------------------ */
enum { T_STANDARD, T_PSSM_LAYERED, T_CUBE, T_CUBE_LAYERED, T_PVSM, T_PVSM_GBUF, T_COUNT };
static const char *const tech_name[T_COUNT] = {"STANDARD", "PSSM-L", "cube", "cube-L", "PVSM", "PVSM+G"};

#define SUN_DIR GT_CASTER_SUN
#define POINT_POS GT_CASTER_LAMP

/* renders pass kind t with w->caster into res (background -1); SK_OK or
   the render's error (checked, named) */
static sk_result render(world *w, const skgl_camera *cam, int t, const char *what, float *res) {
    gt_env *e = &w->e;
    skgl_scene sc;
    sk_result r = SK_OK;
    int layered = -1;
    size_t i;
    sc.draw = draw;
    sc.user = w;
    sc.bounds = e->scene.bounds;
    w->calls_failed = 0;
    if (t == T_STANDARD || t == T_PSSM_LAYERED) {
        skgl_shadow_desc d;
        skgl_shadow *s;
        memset(&d, 0, sizeof d);
        d.technique = t == T_STANDARD ? SKGL_STANDARD : SKGL_PSSM;
        d.layered = t == T_PSSM_LAYERED;
        d.resolution = 1024;
        s = gt_shadow(e, &d);
        if (!s) return SK_ERR_GL;
        r = skgl_shadow_render(e->sk, s, cam, &sc, SUN_DIR);
        if (r == SK_OK && gt_mask_only(e, s, cam, res) != 0) r = SK_ERR_GL;
        if (r == SK_OK && d.layered) layered = skgl_shadow_stats(s)->layered;
        skgl_shadow_destroy(e->sk, s);
    } else if (t == T_CUBE || t == T_CUBE_LAYERED) {
        skgl_point_desc d;
        skgl_point *p = NULL;
        memset(&d, 0, sizeof d);
        d.technique = SKGL_POINT_CUBE;
        d.resolution = 1024;
        d.range = 40.0f;
        d.near_plane = 0.1f;
        d.layered = t == T_CUBE_LAYERED;
        gt_point_bias(&d);
        r = skgl_point_create(e->sk, &d, &p);
        if (r == SK_OK) r = skgl_point_render(e->sk, p, cam, &sc, POINT_POS);
        if (r == SK_OK) r = skgl_point_mask(e->sk, p, cam, e->gbuf.depth_tex, e->gbuf.color_tex, e->mask.color_tex);
        if (r == SK_OK && tb_gl_read_texture_red(&e->gl, e->mask.color_tex, e->w, e->h, res) != 0) r = SK_ERR_GL;
        if (r == SK_OK && d.layered) layered = skgl_point_stats(p)->layered;
        skgl_point_destroy(e->sk, p);
    } else {
        skgl_soft *s = gt_soft(e, SKGL_SOFT_PVSM, 1024);
        skgl_area_light l = gt_caster_area();
        if (!s) return SK_ERR_GL;
        r = skgl_soft_render(e->sk, s, cam, &sc, &l, t == T_PVSM_GBUF ? 0 : e->gbuf.depth_tex,
                             t == T_PVSM_GBUF ? 0 : e->gbuf.color_tex, e->mask.color_tex);
        if (r == SK_OK && tb_gl_read_texture_red(&e->gl, e->mask.color_tex, e->w, e->h, res) != 0) r = SK_ERR_GL;
        skgl_soft_destroy(e->sk, s);
    }
    SK_CHECK_MSG(r == SK_OK, "%s under %s: %s (%s)", what, tech_name[t], sk_result_string(r),
                 skgl_error_log(e->sk));
    SK_CHECK_MSG(w->calls_failed == 0, "%s under %s: skgl_use_caster failed %d times", what, tech_name[t],
                 w->calls_failed);
    /* stats.layered: 1 the loop, 2 an invocation per layer (llvmpipe has GL_ARB_gpu_shader5) */
#ifdef SKGL_LAYERED_LOOP
    SK_CHECK_MSG(layered == -1 || layered == 1, "%s under %s: stats.layered %d, the loop wanted", what,
                 tech_name[t], layered);
#else
    SK_CHECK_MSG(layered == -1 || layered >= 1, "%s under %s: the layers were not drawn in one pass", what,
                 tech_name[t]);
#endif
    SK_CHECK_MSG(e->gl.GetError() == 0, "%s under %s: GL error", what, tech_name[t]);
    for (i = 0; i < e->n; i++) if (!(e->depth[i] < 1.0f)) res[i] = -1.0f;
    return r;
}

static double error_of(const gt_env *e, int t, const float *ref, const float *res) {
    if (t >= T_PVSM) {
        tb_penumbra_error pe = tb_metric_penumbra(ref, res, e->w, e->h, 2);
        double n = (double)(pe.penumbra + pe.umbra);
        return n > 0 ? (pe.penumbra_mae * (double)pe.penumbra + pe.umbra_mae * (double)pe.umbra) / n : 0.0;
    }
    return tb_metric_shadow(ref, res, e->w, e->h).area_pct;
}

/* pixels where two masks differ by more than 1e-3 */
static int mask_diff(const gt_env *e, const float *a, const float *b) {
    size_t i;
    int n = 0;
    for (i = 0; i < e->n; i++) n += fabsf(a[i] - b[i]) > 1e-3f;
    return n;
}

static skgl_caster *make_caster(world *w, int q, int with_fragment) {
    skgl_caster_desc d;
    skgl_caster *c = NULL;
    sk_result r;
    memset(&d, 0, sizeof d);
    d.label = q_name[q];
    d.vertex = q_int[q] ? vs_int : vs_float;
    d.fragment = with_fragment ? (q_int[q] ? fs_int : fs_float) : NULL;
    d.varyings = q_varyings[q];
    r = skgl_caster_create(w->e.sk, &d, &c);
    SK_CHECK_MSG(r == SK_OK, "skgl_caster_create(%s): %s (%s)", q_name[q], sk_result_string(r),
                 skgl_error_log(w->e.sk));
    return c;
}

/* Measured (Mesa 22.3 llvmpipe, 320 x 180), every qualifier the same to
   the last digit (their masks identical), the control without the
   fragment hook after the slash:
     STANDARD 1.292 / 86.82   PSSM-L 0.7752 / 87.08   cube 0.6397 / 67.27
     cube-L 0.6397 / 67.27    PVSM 0.0232 / 0.1001    PVSM+G 0.0232 / 0.1001
   Bounds: 1.25 x the figure + 0.25 (hard, %) or + 0.003 (PVSM); the
   control at least 2 x the error. */
static const double measured[T_COUNT] = {1.292, 0.7752, 0.6397, 0.6397, 0.0232, 0.0232};

static void test_qualifier_matrix(void) {
    world w;
    skgl_camera cam = gt_camera(gt_v3(-10, 9, 13), gt_v3(0, 1.0f, 0), 0.9f, 0.5f, 60, W, H);
    float *ref[3], *res, *plain, *control;
    double err[Q_COUNT][T_COUNT], err_off[T_COUNT];
    skgl_caster *casters[Q_COUNT], *bare;
    int q, t, i;
    if (world_init(&w) != 0) { world_free(&w); return; }
    for (i = 0; i < 3; i++) ref[i] = gt_alloc(&w.e);
    res = gt_alloc(&w.e); plain = gt_alloc(&w.e); control = gt_alloc(&w.e);
    SK_CHECK(gt_gbuffer(&w.e, &cam) == 0);
    gt_caster_references(&w.e, ref[0], ref[1], ref[2]);
    for (q = 0; q < Q_COUNT; q++) casters[q] = make_caster(&w, q, 1);
    bare = make_caster(&w, Q_PLAIN, 0);
    for (t = 0; t < T_COUNT; t++) {
        const float *r = ref[t <= T_PSSM_LAYERED ? 0 : t <= T_CUBE_LAYERED ? 1 : 2];
        double bound = 1.25 * measured[t] + (t >= T_PVSM ? 0.003 : 0.25);
        char name[64];
        w.caster = bare;
        err_off[t] = render(&w, &cam, t, "control", control) == SK_OK ? error_of(&w.e, t, r, control) : -1.0;
        for (q = 0; q < Q_COUNT; q++) {
            int diff;
            err[q][t] = -1.0;
            w.caster = casters[q];
            if (!casters[q] || render(&w, &cam, t, q_name[q], q == Q_PLAIN ? plain : res) != SK_OK) continue;
            err[q][t] = error_of(&w.e, t, r, q == Q_PLAIN ? plain : res);
            snprintf(name, sizeof name, "caster_varyings_%s_%s", q_name[q], tech_name[t]);
            gt_images(&w.e, name, r, q == Q_PLAIN ? plain : res);
            SK_CHECK_MSG(err[q][t] <= bound, "%s under %s: error %.4f, bound %.4f", q_name[q], tech_name[t],
                         err[q][t], bound);
            SK_CHECK_MSG(err_off[t] >= 2.0 * err[q][t], "%s under %s: without the discard %.4f, with %.4f",
                         q_name[q], tech_name[t], err_off[t], err[q][t]);
            if (q == Q_PLAIN) continue;
            diff = mask_diff(&w.e, res, plain);
            SK_CHECK_MSG(diff <= MASK_DIFF_MAX, "%s under %s: %d pixels differ from the plain float's", q_name[q],
                         tech_name[t], diff);
        }
    }
    gt_print_names("varying", tech_name, T_COUNT);
    for (q = 0; q < Q_COUNT; q++) gt_print_values(q_name[q], err[q], T_COUNT);
    gt_print_values("no discard", err_off, T_COUNT);
    for (q = 0; q < Q_COUNT; q++) skgl_caster_destroy(w.e.sk, casters[q]);
    skgl_caster_destroy(w.e.sk, bare);
    for (i = 0; i < 3; i++) free(ref[i]);
    free(res); free(plain); free(control);
    world_free(&w);
}

/* hooks that declare the names shadowkit's passes used to declare: every
   pass links, and draws all 8 boxes as the control does */
static void test_reserved_names(void) {
    world w;
    skgl_camera cam = gt_camera(gt_v3(-10, 9, 13), gt_v3(0, 1.0f, 0), 0.9f, 0.5f, 60, W, H);
    float *res, *control;
    skgl_caster_desc d;
    skgl_caster *collide = NULL, *bare;
    sk_result r;
    int t;
    if (world_init(&w) != 0) { world_free(&w); return; }
    res = gt_alloc(&w.e); control = gt_alloc(&w.e);
    SK_CHECK(gt_gbuffer(&w.e, &cam) == 0);
    memset(&d, 0, sizeof d);
    d.label = "collide";
    d.vertex = vs_collide;
    d.fragment = fs_collide;
    d.varyings = "float v_world;";
    r = skgl_caster_create(w.e.sk, &d, &collide);
    SK_CHECK_MSG(r == SK_OK, "collide: %s (%s)", sk_result_string(r), skgl_error_log(w.e.sk));
    bare = make_caster(&w, Q_PLAIN, 0);
    for (t = 0; collide && bare && t < T_COUNT; t++) {
        int diff;
        w.caster = bare;
        if (render(&w, &cam, t, "control", control) != SK_OK) continue;
        w.caster = collide;
        if (render(&w, &cam, t, "collide", res) != SK_OK) continue;
        diff = mask_diff(&w.e, res, control);
        SK_CHECK_MSG(diff == 0, "collide under %s: %d pixels differ from the control", tech_name[t], diff);
    }
    skgl_caster_destroy(w.e.sk, collide);
    skgl_caster_destroy(w.e.sk, bare);
    free(res); free(control);
    world_free(&w);
}

static int log_has(skgl_context *sk, const char *what) { return strstr(skgl_error_log(sk), what) != NULL; }

static int count_of(const char *s, const char *what) {
    int n = 0;
    while ((s = strstr(s, what)) != NULL) { n++; s += strlen(what); }
    return n;
}

/* desc.varyings refused with its line named; a type error at 20000 + its
   line; a link error's log intact */
static void test_varyings_contracts(void) {
    static const struct { const char *varyings, *log1, *log2; } bad[] = {
        {"float a, b;", "line 1", "one varying per declaration"},
        {"float v;\nvec2 uv[2];", "line 2", "arrays"},
        {"float v; /* never closed\n", "line 1", "does not end"},
        {"#extension GL_ARB_gpu_shader5 : enable\nfloat v;", "line 1", "#extension"},
        {"#version 330\nfloat v;", "line 1", "#version"},
        {"float v;\n\nout vec2 uv;", "line 3", "\"out\""},
        {"int id;", "line 1", "must be flat"},
        {"flat smooth float v;", "line 1", "two interpolation"},
        {"float skgl_v;", "line 1", "reserved"},
        {"float v", "line 1", "does not end in ';'"},
        {"float v; #ifdef X\n", "line 1", "begin its line"},
        {"struct S { float a; } s;", "line 1", "structs"},
        {"uniform float v;", "line 1", "\"uniform\""},
        {"flat;", "line 1", "not a declaration"},
    };
    world w;
    skgl_caster_desc d;
    skgl_caster *c = NULL;
    skgl_context *sk;
    size_t k;
    int before;
    if (world_init(&w) != 0) { world_free(&w); return; }
    sk = w.e.sk;
    before = skgl_gl_object_count(sk);
    memset(&d, 0, sizeof d);
    d.label = "contract";
    d.vertex = vs_float;
    for (k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        d.varyings = bad[k].varyings;
        c = NULL;
        SK_CHECK_MSG(skgl_caster_create(sk, &d, &c) == SK_ERR_INVALID_ARG && c == NULL,
                     "accepted: \"%s\" (%s)", bad[k].varyings, skgl_error_log(sk));
        SK_CHECK_MSG(log_has(sk, "desc.varyings") && log_has(sk, bad[k].log1) && log_has(sk, bad[k].log2),
                     "\"%s\": log %s", bad[k].varyings, skgl_error_log(sk));
        skgl_caster_destroy(sk, c);
    }
    /* what is accepted: comments anywhere, directives between declarations,
       every qualifier with a precision, several per line */
    d.varyings = "/* a; b */ float v; // c; d\n"
                 "#ifdef GL_ES\n"
                 "flat centroid highp int e;\n"
                 "#else\n"
                 "flat centroid int e;\n"
                 "#endif\n"
                 "noperspective mediump vec2 f; smooth centroid lowp vec3 g;;\n";
    c = NULL;
    SK_CHECK_MSG(skgl_caster_create(sk, &d, &c) == SK_OK, "%s", skgl_error_log(sk));
    skgl_caster_destroy(sk, c);
    /* a type the compiler refuses, on desc.varyings' line 2; a name
       declared twice, on line 3 */
    d.varyings = "float v;\nvec5 u;";
    c = NULL;
    SK_CHECK(skgl_caster_create(sk, &d, &c) == SK_ERR_GL && c == NULL);
    SK_CHECK_MSG(log_has(sk, "20002") && log_has(sk, "'contract'"), "log: %s", skgl_error_log(sk));
    d.varyings = "float v;\n\nfloat v;";
    c = NULL;
    SK_CHECK(skgl_caster_create(sk, &d, &c) == SK_ERR_GL && c == NULL);
    SK_CHECK_MSG(log_has(sk, "20003"), "log: %s", skgl_error_log(sk));
    /* compiles but does not link (skgl_caster_position declared, never
       defined): the link log follows the caster's name once, intact */
    d.varyings = NULL;
    d.label = "unlinked";
    d.vertex = "vec4 skgl_caster_position();\n";
    c = NULL;
    SK_CHECK(skgl_caster_create(sk, &d, &c) == SK_ERR_GL && c == NULL);
    SK_CHECK_MSG(count_of(skgl_error_log(sk), "caster 'unlinked'") == 1 && log_has(sk, "program link failed: "),
                 "log: %s", skgl_error_log(sk));
    SK_CHECK(skgl_gl_object_count(sk) == before);
    world_free(&w);
}

SK_TEST_MAIN(test_qualifier_matrix, test_reserved_names, test_varyings_contracts)
