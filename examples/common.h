/* examples/common.h - the plumbing the shadowkit examples share, so that each
   example file shows only what it teaches: the shadowkit_gl.h calls.

   What lives here (none of it is shadowkit):
   - command line: --headless, --scene FILE, --frames N, --out FILE,
     --technique NAME, --debug, --timing, --show-cascades (02 only),
     --forward (05 only), --help;
   - a window (GLFW, GL 3.3 core) or, with --headless, an off-screen GL 3.3
     core context from the testbed (OSMesa or EGL) rendering into a 1280x720
     framebuffer object that is saved as a PNG at the end; a window given
     --out saves its last frame the same way (the integration tests compare
     the two);
   - the scene: a procedural one built by the example, or any glTF/OBJ file
     through the testbed's assimp loader, uploaded as one mesh;
   - shader compiling and linking (ex_compile_shader, ex_link_program), the
     forward shader: lambert lighting times sk_shadow() from the GLSL
     snippet of shadowkit_gl.h, with an optional colour per cascade, and
     the vertex shader of the examples' own lighting passes (ex_world_vs);
   - the camera's G-buffer (depth and normals) and a visibility-mask texture
     for the deferred examples;
   - the draw callback shadowkit calls for each shadow pass.

   The examples depend on shadowkit_gl.h and on the testbed (the tb_*.h headers),
   never the other way round. */
#ifndef EXAMPLES_COMMON_H
#define EXAMPLES_COMMON_H

#include "shadowkit_gl.h"
#include "tb_gl_context.h"
#include "tb_gl_funcs.h"
#include "tb_gl_fbo.h"
#include "tb_gl_scene.h"
#include "tb_scene.h"

/* The GL enums by their GL names, from Khronos's core-profile header (in
   Debian's libgl-dev, which libglfw3-dev pulls in). It declares no GL
   function without GL_GLEXT_PROTOTYPES, so GL is still called only through
   the tables loaded by the same getproc shadowkit gets. */
#include <GL/glcorearb.h>

#define EX_WIDTH 1280    /* headless image and initial window size */
#define EX_HEIGHT 720

/* options an example may accept besides the common ones (ex_parse_args) */
#define EX_ARG_CASCADES 1        /* --show-cascades */
#define EX_ARG_FORWARD 2         /* --forward */

typedef struct ex_options {
    int headless;              /* --headless: no window, write a PNG */
    const char *scene_path;    /* --scene FILE (NULL: procedural scene) */
    int frames;                /* --frames N: quit after N frames (0: until closed; headless
                                  or a window with --out: 1) */
    const char *out_path;      /* --out FILE: PNG of the last frame (headless: always written) */
    int save_window;           /* a window given --out: the clock steps 1/60 s a frame, as
                                  headless, and the last frame's back buffer is saved */
    int show_cascades;         /* --show-cascades: colour pixels by cascade */
    const char *technique;     /* --technique NAME (NULL: the example's default) */
    int debug;                 /* --debug: skgl_desc.debug (glGetError after every pass) */
    int timing;                /* --timing: skgl_desc.timing (GPU timer queries) */
    int forward;               /* --forward: 05's forward path instead of the deferred mask */
} ex_options;

/* GL entry points the examples call: the testbed's table, plus the few
   uniform setters it lacks. Loaded through the same getproc shadowkit gets. */
typedef struct ex_gl_extra {
    void (TB_GLAPI *Uniform1i)(int loc, int v);
    void (TB_GLAPI *Uniform1fv)(int loc, int count, const float *v);
} ex_gl_extra;

typedef struct ex_app {
    ex_options opt;
    skgl_getproc_fn getproc;   /* hand this to skgl_create() */
    tb_gl_funcs gl;            /* call GL as app.gl.Clear(...) */
    ex_gl_extra glx;
    int width, height;         /* current framebuffer size in pixels */
    int frame;                 /* frames started so far */
    double time;               /* seconds (headless: frame / 60) */

    /* the scene, on the CPU (bounds, objects) and on the GPU */
    tb_scene scene;
    tb_gl_mesh mesh;
    sk_aabb model_bounds;      /* of the file or procedural scene, before the added ground */

    /* the forward program (ex_forward_create) */
    unsigned program;
    int u_view_proj, u_view, u_light_dir, u_albedo, u_cascades, u_splits;

    /* the deferred examples' textures, the size of the framebuffer:
       the camera's G-buffer (ex_gbuffer_render) and a mask (ex_mask_texture) */
    tb_gl_gbuffer gpass;
    tb_gl_fbo gbuffer;         /* depth_tex: window depth; color_tex: world normals (RGBA16F) */
    tb_gl_fbo mask;            /* color_tex: R16F */

    /* the window, or the headless context and its render target */
    void *window;              /* GLFWwindow * */
    tb_gl_context *headless;
    tb_gl_fbo target;
} ex_app;

/* Parses argv into o. `default_out` is the headless PNG path when --out is
   not given; `extra` (EX_ARG_* bits) enables the example's own options.
   Returns 0 to go on, 1 when the program should exit with status 0
   (--help), 2 on a usage error. */
int ex_parse_args(int argc, char **argv, const char *default_out, int extra, ex_options *o);

/* Opens the window or the headless context and loads the GL tables.
   0 on success, -1 (message on stderr). */
int ex_app_open(ex_app *app, const ex_options *o, const char *title);
void ex_app_close(ex_app *app);

/* Loads opt.scene_path if set (and adds a ground plane under it, so that
   its shadow has somewhere to fall), otherwise calls build(scene); then
   uploads the mesh. 0 ok, -1 (message on stderr). */
int ex_app_load_scene(ex_app *app, int (*build)(tb_scene *s));
/* An asset shipped with the examples (rel: "examples/assets/..."), found
   from any working directory: next to the executable or up to two
   directories above it (build/examples/NAME: the repository; Linux, through
   /proc/self/exe), else in the current directory. Writes the path into out;
   0 when the file is there, -1 when not (out then holds rel). */
int ex_asset_path(const char *rel, char *out, size_t cap);

/* A camera looking at the scene's bounds from above one corner, for scenes
   loaded from files: eye, target and near/far planes scaled to the bounds. */
void ex_camera_from_bounds(sk_aabb b, sk_vec3 *eye, sk_vec3 *target, float *zn, float *zf);

/* Frame loop: ex_app_begin_frame returns 0 when it is time to quit (window
   closed, Esc, --frames reached); otherwise it binds the window or the
   off-screen framebuffer, sets the viewport and clears colour and depth.
   ex_app_end_frame shows the frame (window) or, after the last headless
   frame, reads it back and writes opt.out_path; a window with save_window
   reads its back buffer before showing the last frame. 0 ok, -1 on failure. */
int ex_app_begin_frame(ex_app *app);
int ex_app_end_frame(ex_app *app);
/* binds the frame's framebuffer again (after a pass of the example's own
   into another one) and sets the viewport to its size */
void ex_bind_frame(ex_app *app);

/* Shader objects and programs. ex_compile_shader joins count source
   strings (e.g. "#version", a shadowkit snippet, your code) into one
   shader of `type` (GL_VERTEX_SHADER, GL_FRAGMENT_SHADER); on failure
   it prints the info log under `what` and returns 0. ex_link_program links
   the two into a program and deletes them (they are no longer needed once
   linked); it returns 0, after printing the log, when either is 0 or the
   link fails. */
unsigned ex_compile_shader(const ex_app *app, unsigned type, int count, const char *const *src,
                           const char *what);
unsigned ex_link_program(const ex_app *app, unsigned vs, unsigned fs, const char *what);

/* Draws the whole scene with `program`, which must be current, with depth
   test LESS and no face culling; sets its mat4 u_view_proj from cam. */
void ex_draw_scene(ex_app *app, unsigned program, const skgl_camera *cam);

/* Binds the 2D texture tex to texture unit `unit` and points the sampler
   uniform `name` of the current program at it. */
void ex_bind_texture(ex_app *app, unsigned program, const char *name, int unit, unsigned tex);

/* The camera's G-buffer, for the deferred passes: renders the scene's
   window depth (app->gbuffer.depth_tex) and world-space normals
   (app->gbuffer.color_tex) for cam, in textures the size of the
   framebuffer. When the framebuffer changes size they are made again, and
   sk (may be NULL) is told to forget the old ones (skgl_forget_texture).
   0 ok, -1 (message on stderr). */
int ex_gbuffer_render(ex_app *app, skgl_context *sk, const skgl_camera *cam);

/* An R16F texture the size of the framebuffer, for a visibility mask (made
   again, and forgotten by sk, as the G-buffer's); `clear` >= 0 clears it
   to that value first. Returns the texture, 0 on failure. */
unsigned ex_mask_texture(ex_app *app, skgl_context *sk, float clear);

/* Prints "  <what>: N.NNN ms" for a GPU time from the stats, or says it
   is not measured yet (-1: timer results arrive frames late). */
void ex_print_ms(const char *what, float ms);

/* Builds the forward program: our vertex shader, and a fragment shader made
   of "#version 330 core", shadowkit's GLSL snippet (it declares
   sk_shadow()), and our lighting code that calls sk_shadow(). 0 or -1. */
int ex_forward_create(ex_app *app, const char *shadow_snippet);

/* The vertex shader of the examples' own lighting passes (05, 06, 07):
   the testbed's world-space a_position and a_normal (locations 0 and 1)
   passed on as v_world and v_normal, u_view_proj to clip space. */
extern const char ex_world_vs[];

/* Draws the whole scene with the forward program, which must be current
   (the example binds it and calls skgl_shadow_bind first). light_dir is the
   light's travel direction. splits/cascades feed the --show-cascades view
   (cascades 0: off). */
void ex_forward_draw(ex_app *app, const skgl_camera *cam, sk_vec3 light_dir,
                     const float *splits, int cascades);

/* The skgl_scene draw callback (user = the ex_app): draws each object whose
   bounds meet the pass's frustum, with whatever program shadowkit bound. */
void ex_draw_casters(void *user, const skgl_draw_info *info);

/* World size (metres) of one texel of a map of res x res texels whose
   world -> light clip matrix is light_vp (orthographic): 2 / (res * |row 0|). */
float ex_texel_size(sk_mat4 light_vp, int res);

/* small vector helpers */
sk_vec3 ex_v3(float x, float y, float z);
sk_vec3 ex_normalize(sk_vec3 v);

#endif /* EXAMPLES_COMMON_H */
