/* glsl_dump.c - every GLSL program composition shadowkit_gl.h compiles,
   written out for glslangValidator (make check-glsl, mk/glsl.mk), in both
   dialects: desktop OpenGL 3.3 (OSMesa), OpenGL ES 3.2 and OpenGL ES 3.0
   as WebGL2 has it (Mesa's ES context, the ES 3.0 capabilities only through
   skgl_desc.disable_caps). Each dialect runs every technique of es_core.h,
   layered passes where there are geometry shaders, and a caster program
   with varyings and an alpha test through every pass kind; a getproc
   wrapper keeps what glShaderSource receives. Then the snippets, plain and
   prefixed, pasted into a minimal shader of the user's in each dialect.

   usage: glsl_dump OUTDIR   (files OUTDIR/<dialect>-<n>.<vert|frag|geom>)
   Exit status 0 when every dialect ran; a dialect whose context cannot be
   made is reported and skipped. */
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "tb_gl_context.h"
#include "tb_scene.h"
#include "es/es_core.h"

typedef unsigned (*create_shader_fn)(unsigned);
typedef void (*shader_source_fn)(unsigned, int, const char *const *, const int *);
static tb_gl_getproc_fn g_real;
static create_shader_fn g_create;
static shader_source_fn g_source;
static const char *g_dir, *g_dialect;
static int g_count;
static int g_quiet;   /* 1: a shader meant to fail, not written out */
static unsigned g_type[65536];

static unsigned w_create_shader(unsigned type)
{
    unsigned sh = g_create(type);
    if (sh < 65536) g_type[sh] = type;
    return sh;
}

static void w_shader_source(unsigned sh, int n, const char *const *src, const int *len)
{
    char path[512];
    unsigned type = sh < 65536 ? g_type[sh] : 0;
    FILE *f;
    int i;
    if (g_quiet) {
        g_source(sh, n, src, len);
        return;
    }
    snprintf(path, sizeof path, "%s/%s-%03d.%s", g_dir, g_dialect, g_count++,
             type == 0x8B31 ? "vert" : type == 0x8DD9 ? "geom" : "frag");
    f = fopen(path, "w");
    if (f) {
        for (i = 0; i < n; i++) {
            if (len && len[i] >= 0) fwrite(src[i], 1, (size_t)len[i], f);
            else fputs(src[i], f);
        }
        fclose(f);
    }
    g_source(sh, n, src, len);
}

static void *w_getproc(const char *name)
{
    create_shader_fn c = w_create_shader;
    shader_source_fn s = w_shader_source;
    void *p = NULL;
    /* function pointer -> void* through memcpy: ISO C has no direct cast */
    if (strcmp(name, "glCreateShader") == 0) memcpy(&p, &c, sizeof p);
    else if (strcmp(name, "glShaderSource") == 0) memcpy(&p, &s, sizeof p);
    else p = g_real(name);
    return p;
}

/* a caster program of the kind engines write: its own attribute,
   varyings of every qualifier the dialect has (declared by shadowkit from
   desc.varyings, comments and directives among them), an alpha test */
static const char caster_vs[] =
    "layout(location = 0) in vec3 a_pos;\n"
    "vec4 skgl_caster_position()\n"
    "{\n"
    "    uv = a_pos.xz; id = gl_VertexID; c = a_pos.y; sm = a_pos.x;\n"
    "#ifndef GL_ES\n"
    "    np = a_pos.z;\n"
    "#endif\n"
    "    return vec4(a_pos, 1.0);\n"
    "}\n";
static const char caster_fs[] =
    "void skgl_caster_fragment()\n"
    "{\n"
    "    float np_or_0 = 0.0;\n"
    "#ifndef GL_ES\n"
    "    np_or_0 = np;\n"
    "#endif\n"
    "    if (fract(uv.x * 0.5) > 0.99 || id < 0 || c + sm + np_or_0 > 1e9) discard;\n"
    "}\n";
static const char caster_varyings[] =
    "vec2 uv;   // the alpha test's; a comment with ;\n"
    "flat highp int id; /* ; */ centroid float c; smooth float sm;\n"
    "#ifndef GL_ES\n"
    "noperspective float np;\n"
    "#endif\n";

static skgl_caster *g_caster;
static void caster_draw(void *user, const skgl_draw_info *info)
{
    esx_run *r = (esx_run *)user;
    skgl_use_caster(r->sk, g_caster);
    esx_draw(r, info);
    skgl_use_caster(r->sk, NULL);
}

/* the passes a caster program can be linked into */
static int caster_passes(esx_run *r)
{
    skgl_caster_desc cd;
    skgl_scene sc;
    skgl_camera cam = esx_camera();
    skgl_caps caps = skgl_get_caps(r->sk);
    skgl_shadow_desc sd;
    skgl_soft_desc fd;
    skgl_point_desc pd;
    skgl_shadow *s = NULL;
    skgl_soft *f = NULL;
    skgl_point *p = NULL;
    skgl_area_light a = esx_area_light();
    int bad = 0;
    memset(&cd, 0, sizeof cd);
    cd.vertex = caster_vs;
    cd.fragment = caster_fs;
    cd.varyings = caster_varyings;
    cd.label = "dump";
    if (skgl_caster_create(r->sk, &cd, &g_caster) != SK_OK) {
        fprintf(stderr, "glsl_dump %s: caster: %s\n", g_dialect, skgl_error_log(r->sk));
        return -1;
    }
    if (strncmp(g_dialect, "es", 2) == 0) {
        /* GLSL ES has no noperspective: the compiler refuses it at create,
           at desc.varyings' line 2 (20002) */
        skgl_caster *np = NULL;
        skgl_caster_desc nd = cd;
        sk_result nr;
        nd.varyings = "vec2 uv; flat int id; centroid float c; smooth float sm;\nnoperspective float np;";
        g_quiet = 1;
        nr = skgl_caster_create(r->sk, &nd, &np);
        g_quiet = 0;
        if (nr != SK_ERR_GL || !strstr(skgl_error_log(r->sk), "20002")) {
            fprintf(stderr, "glsl_dump %s: noperspective not refused: %s\n", g_dialect, skgl_error_log(r->sk));
            skgl_caster_destroy(r->sk, np);
            bad = 1;
        }
    }
    sc.draw = caster_draw;
    sc.user = r;
    sc.bounds = r->scene.bounds;
    esx_gbuffer(r, &cam);
    memset(&sd, 0, sizeof sd);
    sd.technique = SKGL_PSSM;
    sd.resolution = 256;
    sd.layered = caps.geometry_shader;
    bad |= skgl_shadow_create(r->sk, &sd, &s) != SK_OK || skgl_shadow_render(r->sk, s, &cam, &sc, esx_sun_dir()) != SK_OK;
    skgl_shadow_destroy(r->sk, s);
    s = NULL;
    /* EVSM's moments passes (made with the first EVSM light), where the context can */
    sd.filter = SKGL_FILTER_EVSM;
    if (skgl_shadow_create(r->sk, &sd, &s) == SK_OK) bad |= skgl_shadow_render(r->sk, s, &cam, &sc, esx_sun_dir()) != SK_OK;
    skgl_shadow_destroy(r->sk, s);
    memset(&pd, 0, sizeof pd);
    pd.resolution = 128;
    pd.range = esx_point_range();
    pd.layered = caps.geometry_shader;
    bad |= skgl_point_create(r->sk, &pd, &p) != SK_OK || skgl_point_render(r->sk, p, &cam, &sc, esx_point_pos()) != SK_OK;
    skgl_point_destroy(r->sk, p);
    memset(&fd, 0, sizeof fd);
    fd.technique = SKGL_SOFT_PVSM;
    fd.resolution = 512;
    fd.sync_readback = 1;
    bad |= skgl_soft_create(r->sk, &fd, &f) != SK_OK ||
           skgl_soft_render(r->sk, f, &cam, &sc, &a, 0, 0, r->mask_tex) != SK_OK;
    skgl_soft_destroy(r->sk, f);
    if (bad) fprintf(stderr, "glsl_dump %s: caster passes: %s\n", g_dialect, skgl_error_log(r->sk));
    skgl_caster_destroy(r->sk, g_caster);
    return bad ? -1 : 0;
}

/* the snippets in a minimal fragment shader of the user's, each dialect */
static void snippet_files(void)
{
    static const char *heads[2] = {"#version 330 core\n", "#version 300 es\nprecision highp float;\n"};
    static const char *names[2] = {"user-gl33", "user-es300"};
    char buf[65536], pre[65536], path[512];
    int d, k;
    for (d = 0; d < 2; d++)
        for (k = 0; k < 9; k++) {
            const char *body = "";
            FILE *f;
            pre[0] = 0;
            switch (k) {
            case 0: snprintf(pre, sizeof pre, "%s", skgl_glsl_snippet()); break;
            case 1: skgl_glsl_snippet_prefixed("sun_", pre, (int)sizeof pre); break;
            case 2: snprintf(pre, sizeof pre, "%s", skgl_point_glsl_snippet()); break;
            case 3: snprintf(pre, sizeof pre, "#define SK_POINT_VSDCT 1\n%s", skgl_point_glsl_snippet()); break;
            case 4:
                snprintf(pre, sizeof pre, "#define SK_POINT_VSDCT 1\n#define SK_POINT_VSDCT_ANALYTIC 1\n%s",
                         skgl_point_glsl_snippet());
                break;
            case 6: snprintf(pre, sizeof pre, "#define SK_POINT_SPOT 1\n%s", skgl_point_glsl_snippet()); break;
            case 7: snprintf(pre, sizeof pre, "#define SK_SHADOW_CONTACT 1\n%s", skgl_glsl_snippet()); break;
            case 8: snprintf(pre, sizeof pre, "#define SK_SHADOW_EVSM 1\n%s", skgl_glsl_snippet()); break;
            default: skgl_point_glsl_snippet_prefixed("lamp_", pre, (int)sizeof pre); break;
            }
            body = k == 0 || k >= 7 ? "void main() { o = vec4(sk_shadow(p, vec3(0.0, 1.0, 0.0), 1.0)); }\n"
                   : k == 1 ? "void main() { o = vec4(sun_shadow(p, vec3(0.0, 1.0, 0.0), 1.0)); }\n"
                   : k == 5 ? "void main() { o = vec4(lamp_point_shadow(p, vec3(0.0, 1.0, 0.0))); }\n"
                            : "void main() { o = vec4(sk_point_shadow(p, vec3(0.0, 1.0, 0.0))); }\n";
            snprintf(buf, sizeof buf, "%s%s\nin vec3 p;\nout vec4 o;\n%s", heads[d], pre, body);
            snprintf(path, sizeof path, "%s/%s-%d.frag", g_dir, names[d], k);
            f = fopen(path, "w");
            if (f) { fputs(buf, f); fclose(f); }
        }
}

static esx_run g_run;

static int dialect(const char *name, int flags, unsigned disable_caps, const esx_scene *sc)
{
    char err[512];
    tb_gl_context *c = tb_gl_context_create_flags(TB_GL_AUTO, flags, err, sizeof err);
    int bad = 0, t;
    void *p;
    if (!c) { printf("glsl_dump: %s: no context (%s), skipped\n", name, err); return 0; }
    g_dialect = name;
    g_count = 0;
    g_real = tb_gl_context_getproc(c);
    p = g_real("glCreateShader"); memcpy(&g_create, &p, sizeof p);
    p = g_real("glShaderSource"); memcpy(&g_source, &p, sizeof p);
    if (esx_begin(&g_run, w_getproc, sc, disable_caps) != 0) {
        fprintf(stderr, "glsl_dump %s: %s\n", name, g_run.log);
        bad = 1;
    } else {
        while (!esx_step(&g_run)) {}
        for (t = 0; t < ESX_TECHS; t++)
            if (g_run.result[t] != SK_OK) {
                fprintf(stderr, "glsl_dump %s: %s: %s\n", name, esx_techs[t].name, g_run.why[t]);
                bad = 1;
            }
        bad |= caster_passes(&g_run) != 0;
    }
    esx_end(&g_run);
    tb_gl_context_destroy(c);
    printf("glsl_dump: %s: %d shaders\n", name, g_count);
    return bad;
}

int main(int argc, char **argv)
{
    tb_scene scene;
    esx_scene sc;
    int bad = 0;
    if (argc != 2) { fprintf(stderr, "usage: glsl_dump OUTDIR\n"); return 2; }
    g_dir = argv[1];
    tb_scene_init(&scene);
    if (tb_scene_build_ground_boxes(&scene) != 0) return 1;
    sc.pos = scene.positions;
    sc.nrm = scene.normals;
    sc.idx = scene.indices;
    sc.vertices = (int)scene.vertex_count;
    sc.indices = (int)scene.index_count;
    sc.bounds = scene.bounds;
    bad |= dialect("gl33", 0, 0, &sc);
    bad |= dialect("es320", TB_GL_CONTEXT_ES3, 0, &sc);
    bad |= dialect("es300", TB_GL_CONTEXT_ES3,
                   SKGL_CAP_GEOMETRY_SHADER | SKGL_CAP_GPU_SHADER5 | SKGL_CAP_NORM16 | SKGL_CAP_DEPTH_CLAMP |
                       SKGL_CAP_TEXTURE_SIZE | SKGL_CAP_BUFFER_READ | SKGL_CAP_MIP_RENDER_LEVEL,
                   &sc);
    snippet_files();
    tb_scene_free(&scene);
    return bad;
}
