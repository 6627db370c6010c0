/* test_gl_conventions.c - the camera conventions engines use: reverse-Z
   (finite and infinite far), glClipControl's zero-to-one clip depth
   (skgl_desc.clip_zero_to_one) and OpenGL's infinite far plane, each read
   from the camera's own depth buffer.

   For each convention the test draws the G-buffer of one view of
   "ground-boxes" (320 x 180) with that convention's projection, depth
   function (GREATER and a clear to 0 for reverse-Z) and clip depth, leaves
   glClipControl in the convention's mode (as an engine does), and runs
   STANDARD, PSSM, FERKO and RMSM (each analysed from that depth buffer),
   a cube point light, PCSS and PVSM over it. Each mask is compared with the
   exact reference of the same view (tb_metric_shadow's area % for hard
   shadows, the mean |difference| for soft ones), and with the mask of
   OpenGL's own convention.

   Measured (Mesa 22.3 llvmpipe, DEPTH_COMPONENT32F): under every
   convention each technique's error equals OpenGL's (STANDARD 2.42%, PSSM
   1.51%, RMSM 3.03%, cube 0.83%, PCSS 0.0044, PVSM 0.0018), but FERKO's
   (1.92% against 2.02%: its estimate moves a texel with the depth's
   rounding); at most 2 of the 38459 covered pixels differ in class from
   OpenGL's masks. Bounds: the error at most OpenGL's + 1.0 (hard, %) or
   + 0.004 (soft), at most 0.1% of the pixels differing in class. Can
   fail: with the zero-to-one conventions run on a context left at
   clip_zero_to_one = 0 (SK_GL_TEST_CONV_LIE=1) their depth is read as
   OpenGL's and shadowkit's passes run under zero-to-one clipping: errors
   617% to 3585% (hard), 0.17 (soft), 6032 to 35527 pixels differ, 34
   checks fail; with reverse-Z not detected (a local copy of the header)
   the 18 runs of the three reverse-Z conventions that need near and far
   are refused. */
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "sk_test.h"
#include "gl_test_util.h"

#include <stdlib.h>

#define W 320
#define H 180
#define ZN 0.5
#define ZF 60.0

enum { C_GL, C_GL_REVERSE, C_GL_INFINITE, C_ZO, C_ZO_REVERSE, C_ZO_REVERSE_INFINITE, C_COUNT };
static const char *const conv_name[C_COUNT] = {"OpenGL", "OpenGL reverse-Z", "OpenGL infinite", "zero-to-one",
                                               "zero-to-one reverse-Z", "zero-to-one reverse-Z infinite"};
static const int conv_zo[C_COUNT] = {0, 0, 0, 1, 1, 1};
static const int conv_reverse[C_COUNT] = {0, 1, 0, 0, 1, 1};

enum { T_STANDARD, T_PSSM, T_FERKO, T_RMSM, T_CUBE, T_PCSS, T_PVSM, T_COUNT };
static const char *const tech_name[T_COUNT] = {"STANDARD", "PSSM", "FERKO", "RMSM", "cube", "PCSS", "PVSM"};

/* the convention's projection: OpenGL's perspective with its z row replaced */
static sk_mat4 projection(int c, float aspect) {
    sk_mat4 p = sk_mat4_perspective(0.9f, aspect, (float)ZN, (float)ZF);
    double n = ZN, f = ZF;
    switch (c) {
    case C_GL_REVERSE: p.m[10] = (float)((f + n) / (f - n)); p.m[14] = (float)(2.0 * n * f / (f - n)); break;
    case C_GL_INFINITE: p.m[10] = -1.0f; p.m[14] = (float)(-2.0 * n); break;
    case C_ZO: p.m[10] = (float)(f / (n - f)); p.m[14] = (float)(n * f / (n - f)); break;
    case C_ZO_REVERSE: p.m[10] = (float)(n / (f - n)); p.m[14] = (float)(n * f / (f - n)); break;
    case C_ZO_REVERSE_INFINITE: p.m[10] = 0.0f; p.m[14] = (float)n; break;
    default: break;
    }
    return p;
}

typedef struct xgl {
    void (*ClipControl)(unsigned, unsigned);
    void (*Uniform3f)(int, float, float, float);
} xgl;

static const char gb_vs[] = "#version 330 core\n"
                            "layout(location = 0) in vec3 a_position;\n"
                            "layout(location = 1) in vec3 a_normal;\n"
                            "uniform mat4 u_view_proj;\n"
                            "out vec3 v_world;\n"
                            "out vec3 v_normal;\n"
                            "void main() {\n"
                            "    v_world = a_position; v_normal = a_normal;\n"
                            "    gl_Position = u_view_proj * vec4(a_position, 1.0);\n"
                            "}\n";
static const char gb_fs[] = "#version 330 core\n"
                            "in vec3 v_world;\n"
                            "in vec3 v_normal;\n"
                            "uniform vec3 u_eye;\n"
                            "out vec4 o_normal;\n"
                            "void main() {\n"
                            "    vec3 n = normalize(v_normal);\n"
                            "    if (dot(n, u_eye - v_world) < 0.0) n = -n;\n"
                            "    o_normal = vec4(n, 1.0);\n"
                            "}\n";

/* the G-buffer of cam under convention c into e->gbuf; the clip depth is
   left in the convention's mode */
static void gbuffer(gt_env *e, const xgl *x, unsigned prog, const skgl_camera *cam, sk_vec3 eye, int c) {
    const tb_gl_funcs *gl = &e->gl;
    sk_mat4 vp = sk_mat4_mul(cam->proj, cam->view);
    static const float zero[4] = {0, 0, 0, 0};
    x->ClipControl(0x8CA1, conv_zo[c] ? 0x935F : 0x935E);
    tb_gl_fbo_bind(gl, &e->gbuf);
    gl->Enable(0x0B71);
    gl->DepthFunc(conv_reverse[c] ? 0x0204 /* GREATER */ : 0x0201 /* LESS */);
    gl->DepthMask(1);
    gl->ClearColor(zero[0], zero[1], zero[2], zero[3]);
    gl->ClearDepth(conv_reverse[c] ? 0.0 : 1.0);
    gl->Clear(0x4000 | 0x0100);
    gl->UseProgram(prog);
    gl->UniformMatrix4fv(gl->GetUniformLocation(prog, "u_view_proj"), 1, 0, vp.m);
    x->Uniform3f(gl->GetUniformLocation(prog, "u_eye"), eye.x, eye.y, eye.z);
    tb_gl_mesh_draw(gl, &e->mesh, 0, 0);
    gl->UseProgram(0);
    gl->DepthFunc(0x0201);
    gl->ClearDepth(1.0);
    tb_gl_fbo_bind(gl, NULL);
}

/* the mask of technique t over the G-buffer in e->gbuf, through sk */
static int mask(gt_env *e, skgl_context *sk, int t, const skgl_camera *cam, float *vis) {
    skgl_scene sc = gt_scene(e);
    sk_vec3 sun = gt_v3(-0.5f, -1.0f, -0.35f), lamp = gt_v3(-3.0f, 3.0f, 2.0f);
    sk_result r = SK_OK;
    size_t i;
    if (t <= T_RMSM) {
        static const skgl_technique map[] = {SKGL_STANDARD, SKGL_PSSM, SKGL_FERKO, SKGL_RMSM};
        skgl_shadow_desc d;
        skgl_shadow *s = NULL;
        memset(&d, 0, sizeof d);
        d.technique = map[t];
        d.resolution = t == T_RMSM ? 8192 : 1024;
        d.sync_readback = 1;
        r = skgl_shadow_create(sk, &d, &s);
        if (r == SK_OK && (t == T_FERKO || t == T_RMSM)) r = skgl_shadow_analyze(sk, s, cam, &sc, sun, e->gbuf.depth_tex);
        if (r == SK_OK) r = skgl_shadow_render(sk, s, cam, &sc, sun);
        if (r == SK_OK && t == T_RMSM) {
            r = skgl_shadow_analyze(sk, s, cam, &sc, sun, e->gbuf.depth_tex);
            if (r == SK_OK) r = skgl_shadow_render(sk, s, cam, &sc, sun);
        }
        if (r == SK_OK) r = skgl_shadow_mask(sk, s, cam, e->gbuf.depth_tex, e->gbuf.color_tex, e->mask.color_tex);
        skgl_shadow_destroy(sk, s);
    } else if (t == T_CUBE) {
        skgl_point_desc d;
        skgl_point *p = NULL;
        memset(&d, 0, sizeof d);
        d.resolution = 512;
        d.range = 25.0f;
        r = skgl_point_create(sk, &d, &p);
        if (r == SK_OK) r = skgl_point_render(sk, p, cam, &sc, lamp);
        if (r == SK_OK) r = skgl_point_mask(sk, p, cam, e->gbuf.depth_tex, e->gbuf.color_tex, e->mask.color_tex);
        skgl_point_destroy(sk, p);
    } else {
        skgl_soft_desc d;
        skgl_soft *s = NULL;
        skgl_area_light l;
        memset(&d, 0, sizeof d);
        d.technique = t == T_PCSS ? SKGL_SOFT_PCSS : SKGL_SOFT_PVSM;
        d.resolution = 1024;
        d.sync_readback = 1;
        memset(&l, 0, sizeof l);
        l.position = gt_v3(2.0f, 9.0f, 3.0f);
        l.direction = gt_v3(0, -1, 0);
        l.up = gt_v3(0, 0, 1);
        l.half_width = l.half_height = 0.3f;
        r = skgl_soft_create(sk, &d, &s);
        if (r == SK_OK)
            r = skgl_soft_render(sk, s, cam, &sc, &l, e->gbuf.depth_tex, e->gbuf.color_tex, e->mask.color_tex);
        skgl_soft_destroy(sk, s);
    }
    if (r != SK_OK) {
        SK_CHECK_MSG(0, "%s: %s (%s)", tech_name[t], sk_result_string(r), skgl_error_log(sk));
        return -1;
    }
    if (tb_gl_read_texture_red(&e->gl, e->mask.color_tex, W, H, vis) != 0) return -1;
    for (i = 0; i < e->n; i++) if (!(e->depth[i] < 1.0f)) vis[i] = -1.0f;
    return 0;
}

static double error_of(const gt_env *e, int t, const float *ref, const float *res) {
    if (t >= T_PCSS) {
        tb_soft_error se = tb_metric_soft(ref, res, e->n);
        return se.mae;
    }
    return tb_metric_shadow(ref, res, W, H).area_pct;
}

static void test_conventions(void) {
    gt_env e;
    xgl x;
    skgl_context *zo = NULL;
    skgl_desc d;
    sk_vec3 eye = gt_v3(-9, 7, 12);
    skgl_camera gl_cam = gt_camera(eye, gt_v3(0, 1, 0), 0.9f, (float)ZN, (float)ZF, W, H);
    float *ref_sun, *ref_lamp, *ref_area, *base[T_COUNT], *res;
    double base_err[T_COUNT];
    unsigned prog = 0;
    int c, t, lie = getenv("SK_GL_TEST_CONV_LIE") && atoi(getenv("SK_GL_TEST_CONV_LIE")) == 1;
    tb_light pl;
    skgl_area_light al;
    if (gt_env_init_named(&e, "ground-boxes", W, H) != 0) { gt_env_free(&e); return; }
    {
        void *fp[2];
        fp[0] = tb_gl_context_getproc(e.ctx)("glClipControl");
        fp[1] = tb_gl_context_getproc(e.ctx)("glUniform3f");
        memcpy(&x.ClipControl, &fp[0], sizeof fp[0]);
        memcpy(&x.Uniform3f, &fp[1], sizeof fp[1]);
        if (!fp[0] || !fp[1]) { printf("test_gl_conventions: no glClipControl (GL 4.5): skipped\n"); gt_env_free(&e); return; }
    }
    {
        const char *vs = gb_vs, *fs = gb_fs;
        unsigned v = gt_compile(&e.gl, 0x8B31, 1, &vs), f = gt_compile(&e.gl, 0x8B30, 1, &fs);
        int ok = 0;
        prog = e.gl.CreateProgram();
        e.gl.AttachShader(prog, v);
        e.gl.AttachShader(prog, f);
        e.gl.LinkProgram(prog);
        e.gl.GetProgramiv(prog, 0x8B82, &ok);
        e.gl.DeleteShader(v);
        e.gl.DeleteShader(f);
        SK_CHECK(ok);
    }
    memset(&d, 0, sizeof d);
    d.getproc = (skgl_getproc_fn)tb_gl_context_getproc(e.ctx);
    d.debug = 1;
    d.clip_zero_to_one = 1;
    SK_CHECK(skgl_create(&d, &zo) == SK_OK);
    /* the reference and OpenGL's own masks, over the testbed's G-buffer */
    ref_sun = gt_alloc(&e); ref_lamp = gt_alloc(&e); ref_area = gt_alloc(&e); res = gt_alloc(&e);
    SK_CHECK(gt_gbuffer(&e, &gl_cam) == 0);
    SK_CHECK(gt_reference(&e, gt_v3(-0.5f, -1.0f, -0.35f), ref_sun) == 0);
    memset(&pl, 0, sizeof pl);
    pl.type = TB_LIGHT_POINT;
    pl.position = gt_v3(-3.0f, 3.0f, 2.0f);
    pl.range = 25.0f;
    SK_CHECK(gt_reference_exact(&e, &pl, ref_lamp, NULL) == 0);
    memset(&al, 0, sizeof al);
    al.position = gt_v3(2.0f, 9.0f, 3.0f);
    al.direction = gt_v3(0, -1, 0);
    al.up = gt_v3(0, 0, 1);
    al.half_width = al.half_height = 0.3f;
    SK_CHECK(gt_area_reference(&e, &al, 16, ref_area) == 0);
    for (t = 0; t < T_COUNT; t++) {
        const float *ref = t <= T_RMSM ? ref_sun : t == T_CUBE ? ref_lamp : ref_area;
        base[t] = gt_alloc(&e);
        SK_CHECK(mask(&e, e.sk, t, &gl_cam, base[t]) == 0);
        base_err[t] = error_of(&e, t, ref, base[t]);
    }
    for (c = 0; c < C_COUNT; c++) {
        skgl_camera cam = gl_cam;
        skgl_context *sk = conv_zo[c] && !lie ? zo : e.sk;
        cam.proj = projection(c, (float)W / (float)H);
        gbuffer(&e, &x, prog, &cam, eye, c);
        for (t = 0; t < T_COUNT; t++) {
            const float *ref = t <= T_RMSM ? ref_sun : t == T_CUBE ? ref_lamp : ref_area;
            gt_agreement g;
            double err, bound;
            if (mask(&e, sk, t, &cam, res) != 0) continue;
            err = error_of(&e, t, ref, res);
            g = gt_agree(base[t], res, e.n);
            bound = base_err[t] + (t >= T_PCSS ? 0.004 : 1.0);
            printf("%-31s %-8s: error %.4f (OpenGL's %.4f), %zu of %zu pixels differ in class from OpenGL's\n",
                   conv_name[c], tech_name[t], err, base_err[t], g.differ, g.both);
            SK_CHECK_MSG(err <= bound, "%s %s: error %.4f, bound %.4f", conv_name[c], tech_name[t], err, bound);
            SK_CHECK_MSG(g.both > e.n / 2 && (double)g.differ <= 0.001 * (double)g.both,
                         "%s %s: %zu of %zu differ from OpenGL's", conv_name[c], tech_name[t], g.differ, g.both);
        }
        x.ClipControl(0x8CA1, 0x935E);
        SK_CHECK(e.gl.GetError() == 0);
    }
    for (t = 0; t < T_COUNT; t++) free(base[t]);
    free(ref_sun); free(ref_lamp); free(ref_area); free(res);
    e.gl.DeleteProgram(prog);
    skgl_destroy(zo);
    gt_env_free(&e);
}

/* bad conventions are refused, named */
static void test_convention_contracts(void) {
    gt_env e;
    skgl_desc d;
    skgl_context *zo = NULL, *bad = NULL;
    skgl_shadow_desc sd;
    skgl_shadow *s = NULL;
    skgl_camera cam;
    skgl_scene sc;
    if (gt_env_init_named(&e, "ground-boxes", 64, 36) != 0) { gt_env_free(&e); return; }
    memset(&d, 0, sizeof d);
    d.getproc = (skgl_getproc_fn)tb_gl_context_getproc(e.ctx);
    d.clip_zero_to_one = 2;
    SK_CHECK(skgl_create(&d, &bad) == SK_ERR_INVALID_ARG && bad == NULL);
    d.clip_zero_to_one = 1;
    SK_CHECK(skgl_create(&d, &zo) == SK_OK);
    memset(&sd, 0, sizeof sd);
    sd.resolution = 256;
    SK_CHECK(skgl_shadow_create(zo, &sd, &s) == SK_OK);
    /* under zero-to-one, a projection whose near/far cannot be read is refused */
    cam = gt_camera(gt_v3(-9, 7, 12), gt_v3(0, 1, 0), 0.9f, 0.5f, 60.0f, 64, 36);
    cam.proj.m[14] = 0.0f;
    sc = gt_scene(&e);
    SK_CHECK(skgl_shadow_render(zo, s, &cam, &sc, gt_v3(0, -1, 0)) == SK_ERR_INVALID_ARG &&
             strstr(skgl_error_log(zo), "clip_zero_to_one") != NULL);
    skgl_shadow_destroy(zo, s);
    skgl_destroy(zo);
    gt_env_free(&e);
}

SK_TEST_MAIN(test_conventions, test_convention_contracts)
