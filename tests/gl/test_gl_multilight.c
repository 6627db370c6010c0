/* test_gl_multilight.c - several lights in one forward program: two
   directional lights (a focused map and 4 PSSM cascades) and four point
   lights (two cube maps, two VSDCT) sampled by one fragment shader built
   from prefixed snippets (skgl_glsl_snippet_prefixed,
   skgl_point_glsl_snippet_prefixed) and bound with skgl_shadow_bind_named /
   skgl_point_bind_named on twelve texture units. Each light's visibility,
   chosen by a uniform, must agree with its own deferred mask over the
   G-buffer of the same view ("ground-boxes", 400 x 225).

   Measured (Mesa 22.3 llvmpipe): for each of the six lights 0 of the 60099
   covered pixels differ in class, mean |difference| 0.00001 (suns) and
   0.000001 (lamps): R16F rounding. Bounds: at most 0.05% differ in class,
   mean |difference| below 0.002, as test_gl_forward. (A lamp placed on a
   box's edge, (3, 2.5, -2), made 1.1% differ: the forward and deferred
   point paths part at such a degenerate light, test_gl_omni's 99% bound;
   the lamps here stand clear of the boxes.) Can fail: with each light's
   map bound under its neighbour's prefix (SK_GL_TEST_SWAP=1) 8240 (suns),
   7125 (cube lamps) and 12940 (VSDCT lamps) of the pixels differ, mean
   |difference| 0.12 to 0.22: all 12 bounds fail. */
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "sk_test.h"
#include "gl_test_util.h"

#include <stdlib.h>

#define W 400
#define H 225
#define SUNS 2
#define LAMPS 4
#define LIGHTS (SUNS + LAMPS)

static const char *const sun_prefix[SUNS] = {"sun0_", "sun1_"};
static const char *const lamp_prefix[LAMPS] = {"lamp0_", "lamp1_", "lamp2_", "lamp3_"};

static const char fs_main[] =
    "in vec3 v_world;\n"
    "in vec3 v_normal;\n"
    "in float v_view_depth;\n"
    "uniform int u_which;\n"
    "out float o_visibility;\n"
    "void main() {\n"
    "    vec3 n = normalize(v_normal);\n"
    "    n = gl_FrontFacing ? n : -n;\n"
    "    /* every light's lookup runs in uniform control flow (the snippets' rule) */\n"
    "    float v[6];\n"
    "    v[0] = sun0_shadow(v_world, n, v_view_depth);\n"
    "    v[1] = sun1_shadow(v_world, n, v_view_depth);\n"
    "    v[2] = lamp0_point_shadow(v_world, n);\n"
    "    v[3] = lamp1_point_shadow(v_world, n);\n"
    "    v[4] = lamp2_point_shadow(v_world, n);\n"
    "    v[5] = lamp3_point_shadow(v_world, n);\n"
    "    o_visibility = v[u_which];\n"
    "}\n";

static char *snippet(int point, const char *prefix) {
    int n = point ? skgl_point_glsl_snippet_prefixed(prefix, NULL, 0) : skgl_glsl_snippet_prefixed(prefix, NULL, 0);
    char *s = n > 0 ? (char *)malloc((size_t)n + 1) : NULL;
    int m;
    if (!s) return NULL;
    m = point ? skgl_point_glsl_snippet_prefixed(prefix, s, n + 1) : skgl_glsl_snippet_prefixed(prefix, s, n + 1);
    if (m != n) { free(s); return NULL; }
    return s;
}

/* the program: #version, the VSDCT lamps' defines, six snippets, main */
static unsigned make_program(gt_env *e) {
    const tb_gl_funcs *gl = &e->gl;
    const char *vs[1], *fs[3 + LIGHTS];
    char *sn[LIGHTS];
    unsigned v, f, p = 0;
    int i, ok = 0;
    for (i = 0; i < LIGHTS; i++) sn[i] = i < SUNS ? snippet(0, sun_prefix[i]) : snippet(1, lamp_prefix[i - SUNS]);
    for (i = 0; i < LIGHTS; i++) if (!sn[i]) { SK_CHECK_MSG(0, "snippet %d", i); goto out; }
    vs[0] = gt_forward_vs;
    fs[0] = "#version 330 core\n";
    fs[1] = "#define LAMP2_POINT_VSDCT 1\n#define LAMP3_POINT_VSDCT 1\n";
    for (i = 0; i < LIGHTS; i++) fs[2 + i] = sn[i];
    fs[2 + LIGHTS] = fs_main;
    v = gt_compile(gl, 0x8B31, 1, vs);
    f = gt_compile(gl, 0x8B30, 3 + LIGHTS, fs);
    if (!v || !f) goto out;
    p = gl->CreateProgram();
    gl->AttachShader(p, v);
    gl->AttachShader(p, f);
    gl->LinkProgram(p);
    gl->DeleteShader(v);
    gl->DeleteShader(f);
    gl->GetProgramiv(p, 0x8B82, &ok);
    if (!ok) {
        char log[2048] = "";
        gl->GetProgramInfoLog(p, (int)sizeof log, NULL, log);
        SK_CHECK_MSG(0, "six-light program: %s", log);
        gl->DeleteProgram(p);
        p = 0;
    }
out:
    for (i = 0; i < LIGHTS; i++) free(sn[i]);
    return p;
}

static void test_six_lights(void) {
    gt_env e;
    skgl_camera cam = gt_camera(gt_v3(-9, 7, 12), gt_v3(0, 1, 0), 0.9f, 0.5f, 100, W, H);
    sk_vec3 sun_dir[SUNS] = {{-0.5f, -1.0f, -0.35f}, {0.6f, -1.0f, 0.2f}};
    sk_vec3 lamp_pos[LAMPS] = {{-3.0f, 3.0f, 2.0f}, {2.0f, 4.5f, 2.0f}, {-4.0f, 2.5f, -3.0f}, {0.5f, 5.0f, -5.0f}};
    skgl_shadow *sun[SUNS] = {NULL, NULL};
    skgl_point *lamp[LAMPS] = {NULL, NULL, NULL, NULL};
    skgl_scene sc;
    tb_gl_fbo fw;
    float *deferred, *forward, *fdepth;
    unsigned prog;
    int i, swap = getenv("SK_GL_TEST_SWAP") && atoi(getenv("SK_GL_TEST_SWAP")) == 1;
    if (gt_env_init_named(&e, "ground-boxes", W, H) != 0) { gt_env_free(&e); return; }
    sc = gt_scene(&e);
    deferred = gt_alloc(&e); forward = gt_alloc(&e); fdepth = gt_alloc(&e);
    SK_CHECK(tb_gl_fbo_create(&e.gl, &fw, W, H, TB_GL_COLOR_R16F) == 0);
    SK_CHECK(gt_gbuffer(&e, &cam) == 0);
    prog = make_program(&e);
    SK_CHECK(prog != 0);
    for (i = 0; i < SUNS; i++) {
        skgl_shadow_desc d;
        memset(&d, 0, sizeof d);
        d.technique = i == 0 ? SKGL_STANDARD : SKGL_PSSM;
        d.resolution = 1024;
        sun[i] = gt_shadow(&e, &d);
        SK_CHECK(sun[i] && skgl_shadow_render(e.sk, sun[i], &cam, &sc, sun_dir[i]) == SK_OK);
    }
    for (i = 0; i < LAMPS; i++) {
        skgl_point_desc d;
        memset(&d, 0, sizeof d);
        d.technique = i < 2 ? SKGL_POINT_CUBE : SKGL_POINT_VSDCT;
        d.resolution = 512;
        d.range = 25.0f;
        gt_point_bias(&d);
        SK_CHECK(skgl_point_create(e.sk, &d, &lamp[i]) == SK_OK);
        SK_CHECK(lamp[i] && skgl_point_render(e.sk, lamp[i], &cam, &sc, lamp_pos[i]) == SK_OK);
    }
    for (i = 0; prog && i < LIGHTS; i++) {
        const tb_gl_funcs *gl = &e.gl;
        sk_mat4 vp = sk_mat4_mul(cam.proj, cam.view);
        int k, bound = 1;
        size_t j, both = 0, differ = 0;
        double sum = 0;
        sk_result r;
        /* deferred: this light's own mask */
        if (i < SUNS) r = skgl_shadow_mask(e.sk, sun[i], &cam, e.gbuf.depth_tex, e.gbuf.color_tex, e.mask.color_tex);
        else r = skgl_point_mask(e.sk, lamp[i - SUNS], &cam, e.gbuf.depth_tex, e.gbuf.color_tex, e.mask.color_tex);
        SK_CHECK_MSG(r == SK_OK, "mask %d: %s", i, skgl_error_log(e.sk));
        SK_CHECK(tb_gl_read_texture_red(&e.gl, e.mask.color_tex, W, H, deferred) == 0);
        /* forward: all six bound, light i selected */
        tb_gl_fbo_bind(gl, &fw);
        gl->ClearColor(-1.0f, 0, 0, 0);
        gl->ClearDepth(1.0);
        gl->Clear(0x00004000u | 0x00000100u);
        gl->Enable(0x0B71);
        gl->DepthFunc(0x0201);
        gl->UseProgram(prog);
        gl->UniformMatrix4fv(gl->GetUniformLocation(prog, "u_view_proj"), 1, 0, vp.m);
        gl->UniformMatrix4fv(gl->GetUniformLocation(prog, "u_view"), 1, 0, cam.view.m);
        {
            int loc = gl->GetUniformLocation(prog, "u_which");
            void (*u1i)(int, int);
            void *fp = tb_gl_context_getproc(e.ctx)("glUniform1i");
            memcpy(&u1i, &fp, sizeof fp);
            u1i(loc, i);
        }
        for (k = 0; k < SUNS; k++) {
            /* the swap experiment binds sun 0's map under sun 1's names and back */
            const skgl_shadow *s = swap ? sun[1 - k] : sun[k];
            bound &= skgl_shadow_bind_named(e.sk, s, prog, 2 * k, sun_prefix[k], NULL) == SK_OK;
        }
        for (k = 0; k < LAMPS; k++) {
            const skgl_point *p = swap ? lamp[k ^ 1] : lamp[k];
            bound &= skgl_point_bind_named(e.sk, p, prog, 4 + 2 * k, lamp_prefix[k]) == SK_OK;
        }
        SK_CHECK_MSG(bound, "binds: %s", skgl_error_log(e.sk));
        tb_gl_mesh_draw(gl, &e.mesh, 0, 0);
        gl->UseProgram(0);
        tb_gl_fbo_bind(gl, NULL);
        SK_CHECK(tb_gl_read_red(gl, fw.fbo, W, H, forward) == 0);
        SK_CHECK(tb_gl_read_depth(gl, fw.fbo, W, H, fdepth) == 0);
        for (j = 0; j < e.n; j++) {
            if (!(e.depth[j] < 1.0f) || !(fdepth[j] < 1.0f)) continue;
            both++;
            differ += (deferred[j] >= 0.5f) != (forward[j] >= 0.5f);
            sum += fabs((double)deferred[j] - (double)forward[j]);
        }
        printf("light %d (%s): %zu of %zu pixels differ in class, mean |difference| %.6f\n", i,
               i < SUNS ? sun_prefix[i] : lamp_prefix[i - SUNS], differ, both, both ? sum / (double)both : 0.0);
        SK_CHECK(both > e.n / 2);
        SK_CHECK_MSG((double)differ <= 0.0005 * (double)both, "light %d: %zu of %zu differ", i, differ, both);
        SK_CHECK_MSG(both && sum / (double)both < 0.002, "light %d: mean |difference| %.6f", i, sum / (double)both);
    }
    for (i = 0; i < 12; i += 2) SK_CHECK(skgl_unbind(e.sk, i) == SK_OK);
    if (prog) e.gl.DeleteProgram(prog);
    skgl_forget_program(e.sk, prog);
    for (i = 0; i < SUNS; i++) skgl_shadow_destroy(e.sk, sun[i]);
    for (i = 0; i < LAMPS; i++) skgl_point_destroy(e.sk, lamp[i]);
    tb_gl_fbo_destroy(&e.gl, &fw);
    free(deferred); free(forward); free(fdepth);
    gt_env_free(&e);
}

/* The prefixed text and its rules. */
static void test_prefixes(void) {
    char small[8], *full;
    const char *plain = skgl_glsl_snippet();
    int n = skgl_glsl_snippet_prefixed("sun0_", NULL, 0);
    SK_CHECK(n > 0);
    full = (char *)malloc((size_t)n + 1);
    SK_CHECK(full && skgl_glsl_snippet_prefixed("sun0_", full, n + 1) == n && (int)strlen(full) == n);
    if (full) {
        SK_CHECK(strstr(full, "float sun0_shadow(vec3 world_pos") != NULL);
        SK_CHECK(strstr(full, "uniform mat4 sun0_light_vp[8]") != NULL);
        SK_CHECK(strstr(full, "SUN0_PLANE_MAX_TAN") != NULL);
        SK_CHECK(strstr(full, "sk_") == NULL && strstr(full, "SK_") == NULL);
        /* "sk_" becomes "sun0_": two characters more per name */
        SK_CHECK(n > (int)strlen(plain));
    }
    free(full);
    /* cut short like snprintf, NUL-terminated */
    SK_CHECK(skgl_glsl_snippet_prefixed("sun0_", small, (int)sizeof small) == n && strlen(small) == 7);
    SK_CHECK(skgl_point_glsl_snippet_prefixed("lamp0_", small, (int)sizeof small) > 0 && strlen(small) == 7);
    /* bad prefixes */
    SK_CHECK(skgl_glsl_snippet_prefixed(NULL, small, 8) == -1);
    SK_CHECK(skgl_glsl_snippet_prefixed("", small, 8) == -1);
    SK_CHECK(skgl_glsl_snippet_prefixed("0sun", small, 8) == -1);
    SK_CHECK(skgl_glsl_snippet_prefixed("gl_sun", small, 8) == -1);
    SK_CHECK(skgl_glsl_snippet_prefixed("sun__a", small, 8) == -1);
    SK_CHECK(skgl_glsl_snippet_prefixed("sun-a", small, 8) == -1);
    SK_CHECK(skgl_glsl_snippet_prefixed("a_prefix_longer_than_24ch", small, 8) == -1);
    SK_CHECK(skgl_glsl_snippet_prefixed("sun0_", small, -1) == -1);
    {
        gt_env e;
        skgl_shadow_desc d;
        skgl_shadow *s;
        if (gt_env_init_named(&e, "ground-boxes", 64, 36) != 0) { gt_env_free(&e); return; }
        memset(&d, 0, sizeof d);
        d.resolution = 256;
        s = gt_shadow(&e, &d);
        SK_CHECK(skgl_shadow_bind_named(e.sk, s, 1, 0, "bad prefix", NULL) == SK_ERR_INVALID_ARG &&
                 strstr(skgl_error_log(e.sk), "prefix = \"bad prefix\"") != NULL);
        skgl_shadow_destroy(e.sk, s);
        gt_env_free(&e);
    }
}

SK_TEST_MAIN(test_six_lights, test_prefixes)
