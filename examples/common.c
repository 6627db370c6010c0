/* examples/common.c - see common.h. Window/headless setup, scene loading,
   shaders, the G-buffer and mask textures, and the caster draw callback. */
#if defined(__linux__) && !defined(_DEFAULT_SOURCE)
#define _DEFAULT_SOURCE            /* readlink under -std=c99 */
#endif
#include "common.h"
#include "tb_image.h"

#define GLFW_INCLUDE_NONE          /* we load GL ourselves: no GL header from GLFW */
#include <GLFW/glfw3.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#ifdef __linux__
#include <unistd.h>
#endif

/* ------------------------------------------------------------ files */
static int ex_readable(const char *path) {
    FILE *f = fopen(path, "rb");
    if (!f) return 0;
    fclose(f);
    return 1;
}

int ex_asset_path(const char *rel, char *out, size_t cap) {
#ifdef __linux__
    /* the executable's directory, then its parents: build/examples/NAME
       finds the repository's examples/assets two levels up */
    static const char *const up[3] = {"", "../", "../../"};
    char exe[1024];
    ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n > 0) {
        char *slash;
        int k;
        exe[n] = 0;
        slash = strrchr(exe, '/');
        if (slash) slash[1] = 0;
        for (k = 0; k < 3; k++) {
            snprintf(out, cap, "%s%s%s", exe, up[k], rel);
            if (ex_readable(out)) return 0;
        }
    }
#endif
    snprintf(out, cap, "%s", rel);   /* the current directory */
    return ex_readable(out) ? 0 : -1;
}


sk_vec3 ex_v3(float x, float y, float z) {
    sk_vec3 r;
    r.x = x; r.y = y; r.z = z;
    return r;
}

sk_vec3 ex_normalize(sk_vec3 v) {
    float l = sqrtf(v.x * v.x + v.y * v.y + v.z * v.z);
    return l > 0.0f ? ex_v3(v.x / l, v.y / l, v.z / l) : v;
}

float ex_texel_size(sk_mat4 m, int res) {
    float r = sqrtf(m.m[0] * m.m[0] + m.m[4] * m.m[4] + m.m[8] * m.m[8]);   /* column-major row 0 */
    return r > 0.0f && res > 0 ? 2.0f / ((float)res * r) : 0.0f;
}

/* ------------------------------------------------------------ command line */
int ex_parse_args(int argc, char **argv, const char *default_out, int extra, ex_options *o) {
    int i, out_given = 0;
    memset(o, 0, sizeof *o);
    o->out_path = default_out;
    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "--headless") == 0) {
            o->headless = 1;
        } else if (strcmp(a, "--scene") == 0 && i + 1 < argc) {
            o->scene_path = argv[++i];
        } else if (strcmp(a, "--frames") == 0 && i + 1 < argc) {
            o->frames = atoi(argv[++i]);
        } else if (strcmp(a, "--out") == 0 && i + 1 < argc) {
            o->out_path = argv[++i];
            out_given = 1;
        } else if (strcmp(a, "--technique") == 0 && i + 1 < argc) {
            o->technique = argv[++i];
        } else if (strcmp(a, "--debug") == 0) {
            o->debug = 1;
        } else if (strcmp(a, "--timing") == 0) {
            o->timing = 1;
        } else if ((extra & EX_ARG_CASCADES) && strcmp(a, "--show-cascades") == 0) {
            o->show_cascades = 1;
        } else if ((extra & EX_ARG_FORWARD) && strcmp(a, "--forward") == 0) {
            o->forward = 1;
        } else {
            int help = strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0;
            FILE *f = help ? stdout : stderr;
            if (!help) fprintf(stderr, "unknown or incomplete option: %s\n", a);
            fprintf(f,
                    "usage: %s [--headless] [--scene FILE] [--frames N] [--out FILE] [--technique NAME]\n"
                    "          [--debug] [--timing]%s%s\n"
                    "  --headless        render off-screen and write a PNG (default %s)\n"
                    "  --scene FILE      load a glTF/OBJ scene (on a ground plane) instead of the procedural one\n"
                    "  --frames N        quit after N frames\n"
                    "  --out FILE        PNG path for --headless; in a window: save the last frame there\n"
                    "  --technique NAME  the shadow technique, where the example offers a choice\n"
                    "  --debug           skgl_desc.debug: glGetError after every shadowkit pass, GL errors\n"
                    "                    reported as SK_ERR_GL (each check waits for the driver: for development)\n"
                    "  --timing          skgl_desc.timing: GPU timer queries around every pass, printed at the\n"
                    "                    end (directional and point lights read them 2-3 frames late: use\n"
                    "                    --frames 5 or more; area lights at once, waiting for the GPU)\n",
                    argv[0], (extra & EX_ARG_CASCADES) ? " [--show-cascades]" : "",
                    (extra & EX_ARG_FORWARD) ? " [--forward]" : "", default_out);
            if (extra & EX_ARG_CASCADES) fprintf(f, "  --show-cascades   colour each pixel by its cascade\n");
            if (extra & EX_ARG_FORWARD)
                fprintf(f, "  --forward         shadows in the forward shader instead of the deferred mask\n");
            return help ? 1 : 2;
        }
    }
    /* a window asked for a PNG renders like --headless (a fixed 60 Hz
       clock, a set number of frames) so that the two images can be compared */
    o->save_window = out_given && !o->headless;
    if ((o->headless || o->save_window) && o->frames <= 0) o->frames = 1;
    return 0;
}

/* --------------------------------------------------------------- GL tables */
/* glfwGetProcAddress returns a function pointer; shadowkit and the testbed
   take void *(*)(const char *). Convert without the cast ISO C forbids. */
static void *ex_glfw_getproc(const char *name) {
    GLFWglproc f = glfwGetProcAddress(name);
    void *p = NULL;
    memcpy(&p, &f, sizeof p < sizeof f ? sizeof p : sizeof f);
    return p;
}

static int ex_load_extra(ex_gl_extra *x, skgl_getproc_fn getproc) {
    void *a = getproc("glUniform1i"), *b = getproc("glUniform1fv");
    if (!a || !b) { fprintf(stderr, "examples: glUniform1i/glUniform1fv missing\n"); return -1; }
    memcpy(&x->Uniform1i, &a, sizeof a);
    memcpy(&x->Uniform1fv, &b, sizeof b);
    return 0;
}

static void ex_glfw_error(int code, const char *msg) {
    fprintf(stderr, "GLFW error %d: %s\n", code, msg);
}

int ex_app_open(ex_app *app, const ex_options *o, const char *title) {
    memset(app, 0, sizeof *app);
    app->opt = *o;
    app->width = EX_WIDTH;
    app->height = EX_HEIGHT;
    tb_scene_init(&app->scene);
    if (o->headless) {
        char err[256] = "";
        /* OSMesa (llvmpipe) or EGL; SK_GL=osmesa|egl picks one */
        app->headless = tb_gl_context_create(TB_GL_AUTO, err, sizeof err);
        if (!app->headless) { fprintf(stderr, "headless GL context: %s\n", err); return -1; }
        app->getproc = tb_gl_context_getproc(app->headless);
        printf("headless GL: %s (%s)\n", tb_gl_context_renderer(app->headless),
               tb_gl_context_backend_name(app->headless));
    } else {
        GLFWwindow *w;
        glfwSetErrorCallback(ex_glfw_error);
        if (!glfwInit()) {
            fprintf(stderr, "cannot start GLFW; --headless needs no display\n");
            return -1;
        }
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);   /* macOS wants it */
        w = glfwCreateWindow(EX_WIDTH, EX_HEIGHT, title, NULL, NULL);
        if (!w) {
            fprintf(stderr, "no window with a GL 3.3 core context; --headless needs no display\n");
            glfwTerminate();
            return -1;
        }
        glfwMakeContextCurrent(w);
        glfwSwapInterval(1);
        app->window = w;
        app->getproc = ex_glfw_getproc;
    }
    if (tb_gl_funcs_load(&app->gl, app->getproc) != 0 || ex_load_extra(&app->glx, app->getproc) != 0) {
        ex_app_close(app);
        return -1;
    }
    if (app->headless &&
        tb_gl_fbo_create(&app->gl, &app->target, EX_WIDTH, EX_HEIGHT, TB_GL_COLOR_RGBA8) != 0) {
        fprintf(stderr, "cannot create the %dx%d render target\n", EX_WIDTH, EX_HEIGHT);
        ex_app_close(app);
        return -1;
    }
    return 0;
}

void ex_app_close(ex_app *app) {
    if (app->program) app->gl.DeleteProgram(app->program);
    if (app->gpass.program) tb_gl_gbuffer_destroy(&app->gl, &app->gpass);
    if (app->gbuffer.fbo) tb_gl_fbo_destroy(&app->gl, &app->gbuffer);
    if (app->mask.fbo) tb_gl_fbo_destroy(&app->gl, &app->mask);
    if (app->mesh.vao) tb_gl_mesh_destroy(&app->gl, &app->mesh);
    if (app->target.fbo) tb_gl_fbo_destroy(&app->gl, &app->target);
    tb_scene_free(&app->scene);
    if (app->headless) tb_gl_context_destroy(app->headless);
    if (app->window) {
        glfwDestroyWindow((GLFWwindow *)app->window);
        glfwTerminate();
    }
    memset(app, 0, sizeof *app);
}

/* ------------------------------------------------------------------ scene */
int ex_app_load_scene(ex_app *app, int (*build)(tb_scene *s)) {
    const char *what = app->opt.scene_path ? app->opt.scene_path : "procedural scene";
    int r = app->opt.scene_path ? tb_scene_load(&app->scene, app->opt.scene_path) : build(&app->scene);
    if (r != 0 || app->scene.index_count == 0) {
        fprintf(stderr, "cannot load %s\n", what);
        return -1;
    }
    app->model_bounds = app->scene.bounds;
    if (app->opt.scene_path) {
        /* a ground plane under the loaded model, so that it has somewhere to
           cast its shadow: centred below it, a little over twice its size */
        sk_aabb b = app->scene.bounds;
        float hx = b.max.x - b.min.x, hz = b.max.z - b.min.z, h = hx > hz ? hx : hz;
        if (tb_scene_add_ground(&app->scene, "ground", 0.5f * (b.min.x + b.max.x),
                                0.5f * (b.min.z + b.max.z), 1.2f * h, 1.2f * h, b.min.y, 1, 1) < 0)
            return -1;
    }
    if (tb_gl_mesh_create(&app->gl, &app->mesh, &app->scene) != 0) {
        fprintf(stderr, "cannot upload %s to the GPU\n", what);
        return -1;
    }
    printf("scene: %s, %u triangles, %u objects\n", what, tb_scene_triangle_count(&app->scene),
           app->scene.object_count);
    return 0;
}

void ex_camera_from_bounds(sk_aabb b, sk_vec3 *eye, sk_vec3 *target, float *zn, float *zf) {
    sk_vec3 c = ex_v3(0.5f * (b.min.x + b.max.x), 0.5f * (b.min.y + b.max.y), 0.5f * (b.min.z + b.max.z));
    sk_vec3 e = ex_v3(b.max.x - b.min.x, b.max.y - b.min.y, b.max.z - b.min.z);
    float d = sqrtf(e.x * e.x + e.y * e.y + e.z * e.z);
    if (!(d > 0.0f)) d = 1.0f;
    /* from above the +x +z side, far enough to see the whole box */
    *eye = ex_v3(c.x + 0.55f * d, c.y + 0.45f * d, c.z + 0.75f * d);
    *target = c;
    *zn = 0.01f * d;
    *zf = 3.0f * d;
}

/* ------------------------------------------------------------ frame loop */
/* binds the framebuffer the frame is drawn into: the window's, or the
   headless render target; sets the viewport to its size */
static void ex_bind_target(ex_app *app) {
    if (app->window) {
        app->gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
        app->gl.Viewport(0, 0, app->width, app->height);
    } else {
        tb_gl_fbo_bind(&app->gl, &app->target);
    }
}

void ex_bind_frame(ex_app *app) { ex_bind_target(app); }

int ex_app_begin_frame(ex_app *app) {
    if (app->opt.frames > 0 && app->frame >= app->opt.frames) return 0;
    if (app->window) {
        GLFWwindow *w = (GLFWwindow *)app->window;
        glfwPollEvents();
        if (glfwWindowShouldClose(w) || glfwGetKey(w, GLFW_KEY_ESCAPE) == GLFW_PRESS) return 0;
        glfwGetFramebufferSize(w, &app->width, &app->height);
        if (app->width <= 0 || app->height <= 0) { app->width = 1; app->height = 1; }  /* minimised */
        app->time = app->opt.save_window ? app->frame / 60.0 : glfwGetTime();
    } else {
        app->time = app->frame / 60.0;
    }
    ex_bind_target(app);
    app->frame++;
    app->gl.ClearColor(0.55f, 0.68f, 0.85f, 1.0f);   /* sky */
    app->gl.ClearDepth(1.0);
    app->gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    return 1;
}

/* reads the framebuffer being drawn (the window's back buffer, or the
   headless target) and writes it to opt.out_path */
static int ex_save_frame(ex_app *app) {
    int w = app->width, h = app->height, r;
    unsigned char *rgb = (unsigned char *)malloc((size_t)w * (size_t)h * 3);
    if (!rgb) return -1;
    if (app->window) app->gl.ReadBuffer(GL_BACK);   /* the frame before the swap shows it */
    r = tb_gl_read_rgb8(&app->gl, app->window ? 0 : app->target.fbo, w, h, rgb);
    if (r == 0) r = tb_image_write_rgb8(app->opt.out_path, w, h, rgb);
    free(rgb);
    if (r != 0) { fprintf(stderr, "cannot write %s\n", app->opt.out_path); return -1; }
    printf("wrote %s (%dx%d)\n", app->opt.out_path, w, h);
    return 0;
}

int ex_app_end_frame(ex_app *app) {
    int last = app->opt.frames > 0 && app->frame >= app->opt.frames;   /* only the last frame is saved */
    if (app->window) {
        if (app->opt.save_window && last && ex_save_frame(app) != 0) return -1;
        glfwSwapBuffers((GLFWwindow *)app->window);
        return 0;
    }
    return last ? ex_save_frame(app) : 0;
}

/* --------------------------------------------------------- forward shader */
static const char *ex_vs =
    "#version 330 core\n"
    "layout(location = 0) in vec3 a_position;   /* world space: the testbed pre-transforms */\n"
    "layout(location = 1) in vec3 a_normal;\n"
    "uniform mat4 u_view_proj;\n"
    "uniform mat4 u_view;\n"
    "out vec3 v_world_pos;\n"
    "out vec3 v_world_normal;\n"
    "out float v_view_depth;                      /* distance along the view axis */\n"
    "void main() {\n"
    "    v_world_pos = a_position;\n"
    "    v_world_normal = a_normal;\n"
    "    v_view_depth = -(u_view * vec4(a_position, 1.0)).z;\n"
    "    gl_Position = u_view_proj * vec4(a_position, 1.0);\n"
    "}\n";

const char ex_world_vs[] =
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

/* goes after "#version 330 core" and shadowkit's snippet */
static const char *ex_fs_body =
    "in vec3 v_world_pos;\n"
    "in vec3 v_world_normal;\n"
    "in float v_view_depth;\n"
    "uniform vec3 u_light_dir;                    /* travel direction of the light */\n"
    "uniform vec3 u_albedo;\n"
    "uniform int u_cascades;                      /* --show-cascades: their count; else 0 */\n"
    "uniform float u_splits[9];                   /* view depths bounding each cascade */\n"
    "out vec4 o_color;\n"
    "const vec3 ex_tint[8] = vec3[8](vec3(1.0, 0.35, 0.35), vec3(0.35, 1.0, 0.35),\n"
    "    vec3(0.4, 0.5, 1.0), vec3(1.0, 1.0, 0.3), vec3(1.0, 0.4, 1.0), vec3(0.3, 1.0, 1.0),\n"
    "    vec3(1.0, 0.65, 0.2), vec3(0.6, 0.4, 1.0));\n"
    "void main() {\n"
    "    vec3 n = normalize(v_world_normal);\n"
    "    if (!gl_FrontFacing) n = -n;             /* single-sided ground, foliage */\n"
    "    float lambert = max(dot(n, -u_light_dir), 0.0);\n"
    "    float vis = sk_shadow(v_world_pos, n, v_view_depth);   /* 1 lit .. 0 shadowed */\n"
    "    vec3 albedo = u_albedo;\n"
    "    if (u_cascades > 0) {\n"
    "        int c = -1;\n"
    "        for (int i = 0; i < u_cascades; i++)\n"
    "            if (v_view_depth >= u_splits[i] && v_view_depth <= u_splits[i + 1]) { c = i; break; }\n"
    "        albedo = c >= 0 ? albedo * ex_tint[c] : albedo * 0.5;\n"
    "    }\n"
    "    float ambient = 0.22 + 0.08 * n.y;\n"
    "    vec3 c = albedo * (ambient + (1.0 - ambient) * lambert * vis);\n"
    "    o_color = vec4(pow(c, vec3(1.0 / 2.2)), 1.0);   /* to sRGB, roughly */\n"
    "}\n";

unsigned ex_compile_shader(const ex_app *app, unsigned type, int count, const char *const *src,
                           const char *what) {
    const tb_gl_funcs *gl = &app->gl;
    unsigned sh = gl->CreateShader(type);
    int ok = 0;
    gl->ShaderSource(sh, count, src, NULL);
    gl->CompileShader(sh);
    gl->GetShaderiv(sh, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[4096] = "";
        gl->GetShaderInfoLog(sh, (int)sizeof log, NULL, log);
        fprintf(stderr, "%s: the %s shader does not compile:\n%s\n", what,
                type == GL_VERTEX_SHADER ? "vertex" : "fragment", log);
        gl->DeleteShader(sh);
        return 0;
    }
    return sh;
}

unsigned ex_link_program(const ex_app *app, unsigned vs, unsigned fs, const char *what) {
    const tb_gl_funcs *gl = &app->gl;
    unsigned p;
    int ok = 0;
    if (!vs || !fs) {
        if (vs) gl->DeleteShader(vs);
        if (fs) gl->DeleteShader(fs);
        return 0;
    }
    p = gl->CreateProgram();
    gl->AttachShader(p, vs);
    gl->AttachShader(p, fs);
    gl->LinkProgram(p);
    gl->DeleteShader(vs);      /* freed with the program */
    gl->DeleteShader(fs);
    gl->GetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[4096] = "";
        gl->GetProgramInfoLog(p, (int)sizeof log, NULL, log);
        fprintf(stderr, "%s: the program does not link:\n%s\n", what, log);
        gl->DeleteProgram(p);
        return 0;
    }
    return p;
}

int ex_forward_create(ex_app *app, const char *shadow_snippet) {
    const char *fs_src[3];
    fs_src[0] = "#version 330 core\n";
    fs_src[1] = shadow_snippet;
    fs_src[2] = ex_fs_body;
    app->program = ex_link_program(app, ex_compile_shader(app, GL_VERTEX_SHADER, 1, &ex_vs, "forward"),
                                   ex_compile_shader(app, GL_FRAGMENT_SHADER, 3, fs_src, "forward"),
                                   "forward");
    if (!app->program) return -1;
#define EX_U(field, name) app->field = app->gl.GetUniformLocation(app->program, name)
    EX_U(u_view_proj, "u_view_proj");
    EX_U(u_view, "u_view");
    EX_U(u_light_dir, "u_light_dir");
    EX_U(u_albedo, "u_albedo");
    EX_U(u_cascades, "u_cascades");
    EX_U(u_splits, "u_splits");
#undef EX_U
    return 0;
}

/* A colour per kind of object: the ground light grey; the rest from a
   palette by name without its trailing digits ("pole3" -> "pole"), so a
   fence's slats share one colour; unnamed objects by index. */
static void ex_object_albedo(const tb_object *o, unsigned i, float rgb[3]) {
    static const float pal[6][3] = {{0.85f, 0.45f, 0.30f}, {0.35f, 0.60f, 0.85f}, {0.90f, 0.75f, 0.35f},
                                    {0.50f, 0.75f, 0.45f}, {0.75f, 0.50f, 0.80f}, {0.80f, 0.80f, 0.80f}};
    size_t n = strlen(o->name), k;
    unsigned h = 5381u;
    if (strstr(o->name, "ground") || strstr(o->name, "floor")) {
        rgb[0] = rgb[1] = rgb[2] = 0.78f;
        return;
    }
    while (n > 0 && o->name[n - 1] >= '0' && o->name[n - 1] <= '9') n--;
    for (k = 0; k < n; k++) h = h * 33u + (unsigned char)o->name[k];
    memcpy(rgb, pal[(n > 0 ? h : i) % 6u], sizeof pal[0]);
}

void ex_forward_draw(ex_app *app, const skgl_camera *cam, sk_vec3 light_dir,
                     const float *splits, int cascades) {
    const tb_gl_funcs *gl = &app->gl;
    sk_mat4 vp = sk_mat4_mul(cam->proj, cam->view);
    float sp[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    unsigned i;
    if (cascades < 0) cascades = 0;
    if (cascades > 8) cascades = 8;
    if (splits && cascades > 0) memcpy(sp, splits, sizeof(float) * (size_t)(cascades + 1));
    gl->Enable(GL_DEPTH_TEST);
    gl->DepthFunc(GL_LESS);
    gl->DepthMask(1);
    gl->Disable(GL_CULL_FACE);      /* single-sided ground and foliage */
    gl->UniformMatrix4fv(app->u_view_proj, 1, 0, vp.m);
    gl->UniformMatrix4fv(app->u_view, 1, 0, cam->view.m);
    gl->Uniform3f(app->u_light_dir, light_dir.x, light_dir.y, light_dir.z);
    app->glx.Uniform1i(app->u_cascades, cascades);
    app->glx.Uniform1fv(app->u_splits, 9, sp);
    for (i = 0; i < app->scene.object_count; i++) {
        const tb_object *o = &app->scene.objects[i];
        float rgb[3];
        ex_object_albedo(o, i, rgb);
        gl->Uniform3f(app->u_albedo, rgb[0], rgb[1], rgb[2]);
        tb_gl_mesh_draw(gl, &app->mesh, o->first_index, o->index_count);
    }
}

void ex_draw_scene(ex_app *app, unsigned program, const skgl_camera *cam) {
    const tb_gl_funcs *gl = &app->gl;
    sk_mat4 vp = sk_mat4_mul(cam->proj, cam->view);
    gl->Enable(GL_DEPTH_TEST);
    gl->DepthFunc(GL_LESS);
    gl->DepthMask(1);
    gl->Disable(GL_CULL_FACE);      /* single-sided ground, room and foliage */
    gl->UniformMatrix4fv(gl->GetUniformLocation(program, "u_view_proj"), 1, 0, vp.m);
    tb_gl_mesh_draw(gl, &app->mesh, 0, 0);
}

void ex_bind_texture(ex_app *app, unsigned program, const char *name, int unit, unsigned tex) {
    app->glx.Uniform1i(app->gl.GetUniformLocation(program, name), unit);
    app->gl.ActiveTexture(GL_TEXTURE0 + (unsigned)unit);
    app->gl.BindTexture(GL_TEXTURE_2D, tex);
}

/* ------------------------------------------------- G-buffer and mask */
/* (Re)makes f at the framebuffer's size. shadowkit remembers a texture's
   size by its name, and a new texture may get the old one's name: it is
   told to forget the old textures (skgl_forget_texture) before they go.
   Making an FBO binds it: the frame's framebuffer is bound again after. */
static int ex_fit_fbo(ex_app *app, skgl_context *sk, tb_gl_fbo *f, tb_gl_color_format format) {
    if (f->fbo && f->width == app->width && f->height == app->height) return 0;
    if (f->fbo) {
        if (sk) {
            skgl_forget_texture(sk, f->depth_tex);
            if (f->color_tex) skgl_forget_texture(sk, f->color_tex);
        }
        tb_gl_fbo_destroy(&app->gl, f);
    }
    if (tb_gl_fbo_create(&app->gl, f, app->width, app->height, format) != 0) {
        fprintf(stderr, "cannot create a %dx%d render target\n", app->width, app->height);
        memset(f, 0, sizeof *f);
        return -1;
    }
    ex_bind_target(app);
    return 0;
}

int ex_gbuffer_render(ex_app *app, skgl_context *sk, const skgl_camera *cam) {
    const tb_gl_funcs *gl = &app->gl;
    sk_mat4 vp = sk_mat4_mul(cam->proj, cam->view);
    if (!app->gpass.program) {
        char err[1024] = "";
        if (tb_gl_gbuffer_create(&app->gl, &app->gpass, err, sizeof err) != 0) {
            fprintf(stderr, "G-buffer program: %s\n", err);
            return -1;
        }
    }
    if (ex_fit_fbo(app, sk, &app->gbuffer, TB_GL_COLOR_RGBA16F) != 0) return -1;
    /* the testbed's G-buffer program (window depth, and world normals
       turned toward the camera, alpha 1 where covered); the pass is ours,
       as an engine's would be: no state read back, no glGetError */
    tb_gl_fbo_bind(gl, &app->gbuffer);
    gl->Enable(GL_DEPTH_TEST);
    gl->DepthFunc(GL_LESS);
    gl->DepthMask(1);
    gl->Disable(GL_CULL_FACE);
    gl->ClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    gl->ClearDepth(1.0);
    gl->Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl->UseProgram(app->gpass.program);
    gl->UniformMatrix4fv(app->gpass.u_view_proj, 1, 0, vp.m);
    tb_gl_mesh_draw(gl, &app->mesh, 0, 0);
    gl->UseProgram(0);
    ex_bind_target(app);
    return 0;
}

unsigned ex_mask_texture(ex_app *app, skgl_context *sk, float clear) {
    if (ex_fit_fbo(app, sk, &app->mask, TB_GL_COLOR_R16F) != 0) return 0;
    if (clear >= 0.0f) {
        tb_gl_fbo_bind(&app->gl, &app->mask);
        app->gl.ClearColor(clear, clear, clear, clear);
        app->gl.Clear(GL_COLOR_BUFFER_BIT);
        ex_bind_target(app);
    }
    return app->mask.color_tex;
}

void ex_print_ms(const char *what, float ms) {
    if (ms >= 0.0f) printf("  %s: %.3f ms on the GPU\n", what, ms);
    else printf("  %s: no GPU time yet (timer results arrive 2-3 frames late: run more --frames)\n", what);
}

/* ------------------------------------------------------ shadow-pass callback */
void ex_draw_casters(void *user, const skgl_draw_info *info) {
    ex_app *app = (ex_app *)user;
    unsigned i;
    /* shadowkit has bound its depth program and the pass's framebuffer;
       all we do is draw. Objects whose box misses this pass's frustum (a
       cascade's light volume) are skipped. Our positions are already in
       world space; an engine with model matrices would call
       skgl_set_model(ctx, model) before each object. */
    for (i = 0; i < app->scene.object_count; i++) {
        const tb_object *o = &app->scene.objects[i];
        sk_frustum box;
        if (sk_frustum_from_aabb(o->bounds, &box) == SK_OK && !sk_frustum_intersects(&info->frustum, &box))
            continue;
        tb_gl_mesh_draw(&app->gl, &app->mesh, o->first_index, o->index_count);
    }
}
