/* bench/bench_common.c - see bench_common.h */
#define _POSIX_C_SOURCE 200809L
#include "bench_common.h"

#include "tb_image.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

/* ------------------------------------------------------------------ utils */
double now_s(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

void fmt_duration(double s, char *buf, size_t n) {
    if (s < 0) s = 0;
    if (s < 60) snprintf(buf, n, "%.0fs", s);
    else if (s < 3600) snprintf(buf, n, "%dm%02ds", (int)(s / 60), (int)s % 60);
    else snprintf(buf, n, "%dh%02dm", (int)(s / 3600), ((int)s % 3600) / 60);
}

sk_vec3 v3(float x, float y, float z) {
    sk_vec3 r;
    r.x = x; r.y = y; r.z = z;
    return r;
}
sk_vec3 v3_add(sk_vec3 a, sk_vec3 b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
sk_vec3 v3_sub(sk_vec3 a, sk_vec3 b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
sk_vec3 v3_scale(sk_vec3 a, float s) { return v3(a.x * s, a.y * s, a.z * s); }
float v3_len(sk_vec3 a) { return sqrtf(a.x * a.x + a.y * a.y + a.z * a.z); }
sk_vec3 v3_norm(sk_vec3 a) {
    float l = v3_len(a);
    return l > 0.0f ? v3_scale(a, 1.0f / l) : a;
}
sk_aabb aabb_union(sk_aabb a, sk_aabb b) {
    sk_aabb r;
    r.min = v3(fminf(a.min.x, b.min.x), fminf(a.min.y, b.min.y), fminf(a.min.z, b.min.z));
    r.max = v3(fmaxf(a.max.x, b.max.x), fmaxf(a.max.y, b.max.y), fmaxf(a.max.z, b.max.z));
    return r;
}

static int cmp_float(const void *a, const void *b) {
    float x = *(const float *)a, y = *(const float *)b;
    return x < y ? -1 : x > y;
}
static int cmp_double(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}
float median(float *v, int n) {
    if (n <= 0) return -1.0f;
    qsort(v, (size_t)n, sizeof *v, cmp_float);
    return n & 1 ? v[n / 2] : 0.5f * (v[n / 2 - 1] + v[n / 2]);
}
double median_d(double *v, int n) {
    if (n <= 0) return -1.0;
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return n & 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

int file_exists(const char *p) {
    struct stat st;
    return stat(p, &st) == 0 && S_ISREG(st.st_mode);
}
int dir_exists(const char *p) {
    struct stat st;
    return stat(p, &st) == 0 && S_ISDIR(st.st_mode);
}
/* through the testbed's helper, which makes a path's parents */
int mkdir_p(const char *dir) {
    char buf[1100];
    snprintf(buf, sizeof buf, "%.1000s/x", dir);
    return tb_image_make_parent_dirs(buf);
}

int software_renderer(const char *renderer) {
    return renderer && (strstr(renderer, "llvmpipe") != NULL || strstr(renderer, "softpipe") != NULL);
}
const char *timing_label(const char *renderer) {
    return software_renderer(renderer) ? "relative (CPU rasteriser: compare within this run only, not absolute ms)"
                                       : "absolute (GPU ms, GL timer queries)";
}

static void quoted(FILE *f, const char *s, char q) {
    fputc(q, f);
    for (; *s; s++) {
        if (*s == q) fputc(q, f);
        fputc(*s, f);
    }
    fputc(q, f);
}
void csv_field(FILE *f, const char *s) {
    if (strpbrk(s, ",\"\n\r")) quoted(f, s, '"');
    else fputs(s, f);
}
void gp_string(FILE *f, const char *s) { quoted(f, s, '\''); }

int gnuplot_ready(const char *prog, const char *gp) {
    if (system("command -v gnuplot >/dev/null 2>&1") != 0) {
        fprintf(stderr, "%s: gnuplot not found (Debian: gnuplot-nox; `make deps-demo` installs it): no charts\n", prog);
        return 0;
    }
    if (!file_exists(gp)) {
        fprintf(stderr, "%s: gnuplot script %s not found (run from the repository root or pass --gp)\n", prog, gp);
        return 0;
    }
    return 1;
}

void bench_paths_init(bench_paths *p, const char *gp) {
    p->scenes_dir = BENCH_SCENES_DIR;
    p->out_dir = BENCH_OUT_DIR;
    p->only = NULL;
    p->gp = gp;
}

int bench_path_option(bench_paths *p, int argc, char **argv, int *i) {
    static const char *const names[4] = {"--scenes", "--out", "--only", "--gp"};
    const char **dst[4];
    int k;
    dst[0] = &p->scenes_dir;
    dst[1] = &p->out_dir;
    dst[2] = &p->only;
    dst[3] = &p->gp;
    if (*i + 1 >= argc) return 0;
    for (k = 0; k < 4; k++)
        if (strcmp(argv[*i], names[k]) == 0) {
            *dst[k] = argv[++*i];
            return 1;
        }
    return 0;
}

int scene_selected(const char *only, const char *name) {
    const char *p = only;
    size_t n = strlen(name);
    if (!p || !*p) return 1;
    while (*p) {
        const char *e = strchr(p, ',');
        size_t len = e ? (size_t)(e - p) : strlen(p);
        if (len == n && strncmp(p, name, n) == 0) return 1;
        if (!e) break;
        p = e + 1;
    }
    return 0;
}

/* ---------------------------------------------------------------- scenes */
/* Every scene of the benches, in the order they run. A new scene is one
   entry: a file under the shared scenes folder (a model, set on a ground
   plane) or a tb_scene_build name, and the benches that run it. */
const bench_scene_entry bench_scene_table[] = {
    {"stanford-bunny", "stanford-bunny.obj", BENCH_IN_SWEEP | BENCH_IN_CACHE},
    {"sponza-ivy", "sponza-ivy/sponza_ivy.gltf", BENCH_IN_SWEEP | BENCH_IN_CACHE},
    {"sponza-curtains", "sponza-curtains/sponza_curtains.gltf", BENCH_IN_SWEEP | BENCH_IN_CACHE},
    {"ground-boxes", NULL, BENCH_IN_SWEEP | BENCH_IN_CACHE},
    {"fence", NULL, BENCH_IN_SWEEP | BENCH_IN_CACHE},
    {"terrace", NULL, BENCH_IN_SWEEP | BENCH_IN_CACHE},
    {"open-world", NULL, BENCH_IN_SWEEP | BENCH_OPEN_WORLD},
    {"forest", NULL, BENCH_IN_SWEEP | BENCH_FOREST},
};
const int bench_scene_count = (int)(sizeof bench_scene_table / sizeof bench_scene_table[0]);

int bench_scenes(const char *prog, unsigned in, const char *scenes_dir, const char *only, bench_scene_def *defs,
                 int cap, int *shared) {
    int i, n = 0, have_dir = scenes_dir && dir_exists(scenes_dir);
    *shared = have_dir;
    if (!have_dir && scenes_dir)
        fprintf(stderr, "%s: %s not found: PROCEDURAL SCENES ONLY; --scenes DIR points elsewhere\n", prog,
                scenes_dir);
    for (i = 0; i < bench_scene_count && n < cap; i++) {
        const bench_scene_entry *e = &bench_scene_table[i];
        bench_scene_def *d = &defs[n];
        if (!(e->flags & in) || !scene_selected(only, e->name)) continue;
        if (e->file && !have_dir) continue;
        memset(d, 0, sizeof *d);
        snprintf(d->name, sizeof d->name, "%s", e->name);
        if (e->file) snprintf(d->path, sizeof d->path, "%.900s/%s", scenes_dir, e->file);
        d->flags = e->flags;
        d->light_dir = v3_norm(v3(-0.45f, -1.0f, -0.35f));
        if (e->flags & BENCH_OPEN_WORLD) tb_open_world_sun(0, 2, &d->light_dir);
        if (e->flags & BENCH_FOREST) tb_forest_sun(0, 2, &d->light_dir);
        if (e->file && !file_exists(d->path)) {
            fprintf(stderr, "%s: %s is missing: scene %s skipped\n", prog, d->path, d->name);
            continue;
        }
        n++;
    }
    return n;
}

/* the ground plane under a loaded model: 3x its horizontal extent */
static int add_ground_under(tb_scene *s) {
    sk_aabb b = s->bounds;
    float cx = 0.5f * (b.min.x + b.max.x), cz = 0.5f * (b.min.z + b.max.z);
    float hx = 0.5f * (b.max.x - b.min.x), hz = 0.5f * (b.max.z - b.min.z);
    float h = 3.0f * (hx > hz ? hx : hz);
    return tb_scene_add_ground(s, "ground", cx, cz, h, h, b.min.y, 8, 8) < 0 ? -1 : 0;
}

int load_scene(const bench_scene_def *def, tb_scene *s) {
    tb_scene_init(s);
    if (def->path[0]) {
        if (tb_scene_load(s, def->path) != 0 || s->index_count == 0) return -1;
        return add_ground_under(s);
    }
    return tb_scene_build(s, def->name);
}

sk_aabb content_bounds(const tb_scene *s) {
    sk_aabb r = s->bounds;
    unsigned i;
    int any = 0;
    for (i = 0; i < s->object_count; i++) {
        const tb_object *o = &s->objects[i];
        if (strstr(o->name, "ground")) continue;
        r = any ? aabb_union(r, o->bounds) : o->bounds;
        any = 1;
    }
    return any ? r : s->bounds;
}

/* ----------------------------------------------------------------- views */
void finish_view(bench_view *v, const sk_aabb *all) {
    float zf = 0.0f, d = v3_len(v3_sub(v->target, v->eye));
    int i;
    for (i = 0; i < 8; i++) {
        sk_vec3 c = v3(i & 1 ? all->max.x : all->min.x, i & 2 ? all->max.y : all->min.y,
                       i & 4 ? all->max.z : all->min.z);
        float l = v3_len(v3_sub(c, v->eye));
        if (l > zf) zf = l;
    }
    v->zf = zf * 1.01f;
    v->zn = 0.002f * d;
    if (v->zn < v->zf * 1e-5f) v->zn = v->zf * 1e-5f;
    v->cam.view = sk_mat4_look_at(v->eye, v->target, v3(0, 1, 0));
    v->cam.proj = sk_mat4_perspective(BENCH_FOVY, (float)BENCH_W / (float)BENCH_H, v->zn, v->zf);
    v->view_proj = sk_mat4_mul(v->cam.proj, v->cam.view);
}

void make_open_world_views(bench_view *v) {
    static const char *names[3] = {"head", "street", "square"};
    int i;
    memset(v, 0, 3 * sizeof *v);
    for (i = 0; i < 3; i++) {
        snprintf(v[i].name, sizeof v[i].name, "%s", names[i]);
        tb_open_world_view(i, &v[i].eye, &v[i].target);
        v[i].zn = 0.5f;
        v[i].zf = 1000.0f;
        v[i].cam.view = sk_mat4_look_at(v[i].eye, v[i].target, v3(0, 1, 0));
        v[i].cam.proj = sk_mat4_perspective(BENCH_FOVY, (float)BENCH_W / (float)BENCH_H, v[i].zn, v[i].zf);
        v[i].view_proj = sk_mat4_mul(v[i].cam.proj, v[i].cam.view);
    }
}

void make_forest_views(bench_view *v) {
    static const char *names[3] = {"trail0", "trail1", "trail2"};
    int i;
    memset(v, 0, 3 * sizeof *v);
    for (i = 0; i < 3; i++) {
        snprintf(v[i].name, sizeof v[i].name, "%s", names[i]);
        tb_forest_view(i, &v[i].eye, &v[i].target);
        v[i].zn = 0.3f;
        v[i].zf = TB_FOREST_FAR;
        v[i].cam.view = sk_mat4_look_at(v[i].eye, v[i].target, v3(0, 1, 0));
        v[i].cam.proj = sk_mat4_perspective(BENCH_FOVY, (float)BENCH_W / (float)BENCH_H, v[i].zn, v[i].zf);
        v[i].view_proj = sk_mat4_mul(v[i].cam.proj, v[i].cam.view);
    }
}

/* direction from azimuth (about +y, 0 = +z) and elevation, in radians */
static sk_vec3 dir_az_el(float az, float el) {
    return v3(cosf(el) * sinf(az), sinf(el), cosf(el) * cosf(az));
}
static float azimuth_of(sk_vec3 h) { return atan2f(h.x, h.z); }

/* the distance along u (unit, target -> eye) at which every corner of box
   lies in front of the camera and within +-lim of the frame in NDC (lim > 1:
   the box overflows the frame, a close-up) */
static float fit_distance(sk_vec3 target, sk_vec3 u, const sk_aabb *box, float lim) {
    float lo = 0.0f, hi, rad;
    sk_mat4 proj = sk_mat4_perspective(BENCH_FOVY, (float)BENCH_W / (float)BENCH_H, 1e-3f, 1e6f);
    int it, k;
    rad = v3_len(v3_sub(box->max, box->min));
    hi = 100.0f * (rad > 0.0f ? rad : 1.0f);
    for (it = 0; it < 48; it++) {
        float d = 0.5f * (lo + hi);
        sk_mat4 vp = sk_mat4_mul(proj, sk_mat4_look_at(v3_add(target, v3_scale(u, d)), target, v3(0, 1, 0)));
        int ok = 1;
        for (k = 0; k < 8 && ok; k++) {
            sk_vec4 p, c;
            p.x = k & 1 ? box->max.x : box->min.x;
            p.y = k & 2 ? box->max.y : box->min.y;
            p.z = k & 4 ? box->max.z : box->min.z;
            p.w = 1.0f;
            c = sk_mat4_transform_vec4(vp, p);
            if (!(c.w > 0.0f) || fabsf(c.x) > lim * c.w || fabsf(c.y) > lim * c.w) ok = 0;
        }
        if (ok) hi = d; else lo = d;
    }
    return hi;
}

int make_views(const tb_scene *s, bench_view *v) {
    sk_aabb cb = content_bounds(s), all = s->bounds, local;
    sk_vec3 c = v3(0.5f * (cb.min.x + cb.max.x), 0.5f * (cb.min.y + cb.max.y), 0.5f * (cb.min.z + cb.max.z));
    sk_vec3 ex = v3(0.5f * (cb.max.x - cb.min.x), 0.5f * (cb.max.y - cb.min.y), 0.5f * (cb.max.z - cb.min.z));
    float H = 2.0f * ex.y, L, S, m, az0, el, d;
    sk_vec3 axis, side, u;
    if (ex.x >= ex.z) { axis = v3(1, 0, 0); side = v3(0, 0, 1); L = ex.x; S = ex.z; }
    else { axis = v3(0, 0, 1); side = v3(1, 0, 0); L = ex.z; S = ex.x; }
    if (H < 0.02f * L) H = 0.02f * L;
    memset(v, 0, 3 * sizeof *v);

    snprintf(v[0].name, sizeof v[0].name, "overview");
    az0 = azimuth_of(v3_add(v3_scale(axis, 0.94f), v3_scale(side, 0.34f)));   /* 20 degrees off the axis */
    u = dir_az_el(az0, 0.61f);
    v[0].target = c;
    v[0].eye = v3_add(c, v3_scale(u, fit_distance(c, u, &cb, 1.0f)));
    finish_view(&v[0], &all);

    snprintf(v[1].name, sizeof v[1].name, "low");
    v[1].target = v3_add(c, v3_scale(axis, -0.25f * L));
    v[1].target.y = cb.min.y + 0.15f * H;
    el = atan2f(0.6f * H, L);
    if (el < 0.05f) el = 0.05f;
    if (el > 0.35f) el = 0.35f;
    m = 0.5f * S / L;   /* off the axis by about the content's half width */
    if (m < 0.05f) m = 0.05f;
    if (m > 0.3f) m = 0.3f;
    u = dir_az_el(azimuth_of(v3_add(axis, v3_scale(side, m))), el);
    local = cb;   /* the half of the content nearer the eye must be in the frame */
    if (axis.x > 0.0f) local.min.x = c.x; else local.min.z = c.z;
    v[1].eye = v3_add(v[1].target, v3_scale(u, fit_distance(v[1].target, u, &local, 1.0f)));
    finish_view(&v[1], &all);

    snprintf(v[2].name, sizeof v[2].name, "close");
    m = S > H ? S : H;
    local = cb;
    if (ex.x > m) { local.min.x = c.x - m; local.max.x = c.x + m; }
    if (ex.z > m) { local.min.z = c.z - m; local.max.z = c.z + m; }
    u = dir_az_el(az0 - 1.9f, 0.87f);
    v[2].target = v3(c.x, cb.min.y + 0.3f * H, c.z);
    d = fit_distance(v[2].target, u, &local, 1.5f);
    v[2].eye = v3_add(v[2].target, v3_scale(u, d));
    finish_view(&v[2], &all);
    return 3;
}

void scene_views(const bench_scene_def *def, const tb_scene *s, bench_view *v) {
    if (def->flags & BENCH_OPEN_WORLD) make_open_world_views(v);
    else if (def->flags & BENCH_FOREST) make_forest_views(v);
    else make_views(s, v);
}

/* -------------------------------------------------------------------- GL */
int bench_gl_open(bench_gl *B, const char *prog, int timing) {
    char err[1024] = "";
    const char *failed = NULL;
    skgl_desc sd;
    sk_result r = SK_OK;
    memset(B, 0, sizeof *B);
    B->ctx = tb_gl_context_create(TB_GL_AUTO, err, sizeof err);
    if (!B->ctx) failed = "no GL context";
    else if (tb_gl_funcs_load(&B->gl, tb_gl_context_getproc(B->ctx)) != 0) failed = "GL entry points missing";
    if (!failed) {
        B->renderer = tb_gl_context_renderer(B->ctx);
        fprintf(stderr, "%s: GL %s on %s (%s)\n", prog, tb_gl_context_version(B->ctx), B->renderer,
                tb_gl_context_backend_name(B->ctx));
        memset(&sd, 0, sizeof sd);
        sd.getproc = tb_gl_context_getproc(B->ctx);
        sd.timing = timing != BENCH_TIMING_GPU_ONLY ? timing : software_renderer(B->renderer) ? 0 : SKGL_TIMING_SYNC;
        r = skgl_create(&sd, &B->sk);
        if (r != SK_OK) failed = "skgl_create";
        else if (tb_gl_gbuffer_create(&B->gl, &B->gb, err, sizeof err) != 0 ||
                 tb_gl_fbo_create(&B->gl, &B->mask, BENCH_W, BENCH_H, TB_GL_COLOR_R16F) != 0)
            failed = "G-buffer / mask target";
    }
    if (!failed) return 0;
    fprintf(stderr, "%s: %s: %s %s\n", prog, failed, r != SK_OK ? sk_result_string(r) : err,
            B->sk ? skgl_error_log(B->sk) : "");
    bench_gl_close(B);
    return -1;
}

void bench_gl_close(bench_gl *B) {
    if (B->mask.fbo) tb_gl_fbo_destroy(&B->gl, &B->mask);
    if (B->gb.program) tb_gl_gbuffer_destroy(&B->gl, &B->gb);
    skgl_destroy(B->sk);
    tb_gl_context_destroy(B->ctx);
    memset(B, 0, sizeof *B);
}

int bench_trace(const tb_reference *ref, const sk_mat4 *view_proj, const float *depth, const float *normals,
                const tb_light *light, float *vis) {
    double d[16], inv[16];
    tb_view tv;
    tb_ref_options opt;
    int k;
    for (k = 0; k < 16; k++) d[k] = view_proj->m[k];
    if (!tb_mat4_inverse_d(d, inv)) return -1;
    memset(&tv, 0, sizeof tv);
    for (k = 0; k < 16; k++) tv.inv_view_proj.m[k] = (float)inv[k];
    tv.width = BENCH_W;
    tv.height = BENCH_H;
    memset(&opt, 0, sizeof opt);
    opt.raster_normals = normals;
    return tb_reference_trace_exact(ref, &tv, depth, light, &opt, vis, NULL) != 0 ? -1 : 0;
}

/* ---------------------------------------------------------------- forest */
#define BENCH_GL_TEXTURE_2D 0x0DE1
#define BENCH_GL_TEXTURE0 0x84C0

int bench_forest_open(bench_gl *B, bench_forest *f, const tb_scene *s, tb_reference *ref) {
    tb_scene ground, tree;
    float *uv = NULL, *tree_uv = NULL, inst[TB_FOREST_TREES * TB_FOREST_INSTANCE_FLOATS];
    unsigned char alpha[TB_FOREST_ALPHA_SIZE * TB_FOREST_ALPHA_SIZE];
    unsigned first = 0, count = 0;
    char err[1024] = "";
    skgl_caster_desc d;
    int ok;
    memset(f, 0, sizeof *f);
    tb_scene_init(&ground);
    tb_scene_init(&tree);
    tb_forest_alpha(alpha);
    tb_forest_instances(inst);
    ok = tb_forest_build_ground(&ground) == 0 && tb_forest_tree(&tree, &tree_uv) == 0 &&
         tb_forest_uv(s, &uv, &first, &count) == 0;
    if (ok)
        ok = tb_reference_set_alpha(ref, uv, first, count, alpha, TB_FOREST_ALPHA_SIZE, TB_FOREST_ALPHA_SIZE, 0.5f) ==
                 0 &&
             tb_reference_alpha_primary(ref, 1) == 0;
    if (ok)
        ok = tb_gl_mesh_create(&B->gl, &f->ground, &ground) == 0 &&
             tb_gl_instanced_create(&B->gl, &f->trees, &tree, tree_uv, inst, TB_FOREST_TREES, alpha,
                                    TB_FOREST_ALPHA_SIZE, TB_FOREST_ALPHA_SIZE) == 0 &&
             tb_gl_gbuffer_create_instanced(&B->gl, &f->gb_trees, 1, err, sizeof err) == 0;
    if (ok) {
        /* bound once: shadowkit leaves the casters' units alone */
        B->gl.ActiveTexture(BENCH_GL_TEXTURE0 + BENCH_FOREST_ALPHA_UNIT);
        B->gl.BindTexture(BENCH_GL_TEXTURE_2D, f->trees.alpha_tex);
        B->gl.ActiveTexture(BENCH_GL_TEXTURE0);
        memset(&d, 0, sizeof d);
        d.vertex = tb_gl_instanced_vertex_hook;
        d.fragment = tb_gl_instanced_fragment_hook;
        d.varyings = TB_GL_INSTANCED_VARYINGS;
        d.uniforms[0] = "u_alpha";
        d.label = "bench forest, alpha-tested";
        ok = skgl_caster_create(B->sk, &d, &f->caster) == SK_OK;
        if (!ok) snprintf(err, sizeof err, "skgl_caster_create: %s", skgl_error_log(B->sk));
    }
    if (!ok) {
        fprintf(stderr, "bench: forest setup failed: %s\n", err);
        bench_forest_close(B, f);
    }
    tb_scene_free(&ground);
    tb_scene_free(&tree);
    free(uv);
    free(tree_uv);
    return ok ? 0 : -1;
}

void bench_forest_close(bench_gl *B, bench_forest *f) {
    if (f->caster) skgl_caster_destroy(B->sk, f->caster);
    if (f->gb_trees.program) tb_gl_gbuffer_destroy(&B->gl, &f->gb_trees);
    if (f->trees.vao) tb_gl_instanced_destroy(&B->gl, &f->trees);
    if (f->ground.vao) tb_gl_mesh_destroy(&B->gl, &f->ground);
    memset(f, 0, sizeof *f);
}

/* the ground with shadowkit's own program, the trees instanced through the
   caster program (every tree: the instances are not culled per pass) */
void bench_forest_draw(void *user, const skgl_draw_info *info) {
    const bench_forest_draw_user *u = (const bench_forest_draw_user *)user;
    const int *loc;
    (void)info;
    tb_gl_mesh_draw(u->gl, &u->f->ground, 0, 0);
    loc = skgl_use_caster(u->sk, u->f->caster);
    if (!loc) {
        u->f->failed_calls++;
        return;
    }
    u->gl->Uniform1i(loc[0], BENCH_FOREST_ALPHA_UNIT);
    tb_gl_instanced_draw(u->gl, &u->f->trees);
}

int bench_forest_gbuffer(bench_gl *B, const bench_forest *f, const tb_gl_fbo *fbo, const sk_mat4 *view_proj) {
    return tb_gl_gbuffer_render_instanced(&B->gl, &B->gb, &f->ground, &f->gb_trees, &f->trees, fbo, view_proj);
}
