/* test_gl_layered.c - layered single-pass caster rendering (desc.layered):
   the same maps as a pass per layer, in one callback.

   For PSSM with 4 cascades, LSPSM (its partitions), LiSPSM with 3 cascades
   and a cube-map point light (all six faces, then with face culling), on
   "ground-boxes" at 400 x 225: the deferred mask with layered passes
   against the mask with a pass per layer, then the same with a caster
   program (a hook that moves the casters by a uniform, set to zero in the
   callback: its layered program must get every layer's matrix). Counted:
   callbacks and the draw calls the callback makes (one per object), and
   the render's time, layered over per layer, in this process (llvmpipe:
   a geometry shader costs more here than the vertex work it saves; the
   ratio on a GPU comes from the bench).

   Measured (Mesa 22.3 llvmpipe, GL_ARB_gpu_shader5 invocations; the
   _loop build, the GL 3.3 loop, the same): 0 of 60099 covered pixels
   differ between layered and per-layer maps for every light, with and
   without the hook; callbacks 4 -> 1 (PSSM), 4 -> 1 (LSPSM, 4
   partitions), 3 -> 1 (LiSPSM), 6 -> 1 (cube), the callback's draw calls
   24 -> 6, 24 -> 6, 18 -> 6, 36 -> 6 (16 -> 6 with face and caster
   culling, which the layered pass does per object over all its faces);
   render time layered / per layer 0.67 to 1.89 over 5 frames (llvmpipe's
   noise: no claim either way here). Bounds: at most 0.01% of the pixels
   differ, callbacks exactly 1 and per-layer as many as layers, draw calls
   divided by the layers, stats.layered 2 (1 in the _loop build). Can
   fail: layered.geom with gl_Layer fixed at 0 (a local copy of the header)
   puts every layer into layer 0: 1532 (PSSM), 13332 (LSPSM), 1518
   (LiSPSM) and 17547 (cube) of the 60099 pixels differ, all 10 bounds
   fail. */
#if !defined(_POSIX_C_SOURCE) || _POSIX_C_SOURCE < 199309L
#undef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 199309L   /* clock_gettime */
#endif
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "sk_test.h"
#include "gl_test_util.h"

#include <time.h>

#define W 400
#define H 225
#define FRAMES 5

typedef struct counted {
    gt_env *e;
    skgl_caster *hook;       /* NULL: shadowkit's own program */
    void (*Uniform3f)(int, float, float, float);
    int callbacks, draws, max_layers;
} counted;

/* one draw call per object, as an engine draws */
static void draw(void *user, const skgl_draw_info *info) {
    counted *c = (counted *)user;
    uint32_t i;
    c->callbacks++;
    if (info->layers > c->max_layers) c->max_layers = info->layers;
    if (c->hook) {
        const int *loc = skgl_use_caster(c->e->sk, c->hook);
        if (!loc) return;
        c->Uniform3f(loc[0], 0.0f, 0.0f, 0.0f);
    }
    for (i = 0; i < c->e->scene.object_count; i++) {
        const tb_object *o = &c->e->scene.objects[i];
        if (info->kind == SKGL_PASS_CUBE_FACE && !skgl_point_caster_visible(info, o->bounds)) continue;
        tb_gl_mesh_draw(&c->e->gl, &c->e->mesh, o->first_index, o->index_count);
        c->draws++;
    }
}

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

enum { L_PSSM, L_LSPSM, L_LISPSM, L_CUBE, L_CUBE_CULLED, L_COUNT };
static const char *const light_name[L_COUNT] = {"PSSM-4", "LSPSM", "LiSPSM-3", "cube", "cube, culled"};

typedef struct run_result {
    int ok, callbacks, draws, layers_seen, stats_layered;
    double seconds;
} run_result;

/* FRAMES renders of light kind k, layered or not, then its mask into vis */
static run_result run(gt_env *e, int k, int layered, skgl_caster *hook, const skgl_camera *cam, float *vis) {
    counted c;
    skgl_scene sc;
    run_result rr;
    sk_vec3 sun = gt_v3(-0.5f, -1.0f, -0.35f), lamp = gt_v3(-3.0f, 3.0f, 2.0f);
    int f;
    sk_result r = SK_OK;
    void *fp = tb_gl_context_getproc(e->ctx)("glUniform3f");
    memset(&rr, 0, sizeof rr);
    memset(&c, 0, sizeof c);
    c.e = e;
    c.hook = hook;
    memcpy(&c.Uniform3f, &fp, sizeof fp);
    sc = gt_scene(e);
    sc.draw = draw;
    sc.user = &c;
    if (k <= L_LISPSM) {
        skgl_shadow_desc d;
        skgl_shadow *s;
        memset(&d, 0, sizeof d);
        d.technique = k == L_PSSM ? SKGL_PSSM : k == L_LSPSM ? SKGL_LSPSM : SKGL_LISPSM;
        d.cascades = k == L_LISPSM ? 3 : 4;
        d.resolution = 1024;
        d.layered = layered;
        s = gt_shadow(e, &d);
        if (!s) return rr;
        rr.seconds = now();
        for (f = 0; f < FRAMES && r == SK_OK; f++) r = skgl_shadow_render(e->sk, s, cam, &sc, sun);
        e->gl.Finish();
        rr.seconds = now() - rr.seconds;
        rr.callbacks = c.callbacks / FRAMES;
        rr.draws = c.draws / FRAMES;
        rr.stats_layered = skgl_shadow_stats(s)->layered;
        if (r == SK_OK && gt_mask_only(e, s, cam, vis) != 0) r = SK_ERR_GL;
        skgl_shadow_destroy(e->sk, s);
    } else {
        skgl_point_desc d;
        skgl_point *p = NULL;
        size_t i;
        memset(&d, 0, sizeof d);
        d.resolution = 512;
        d.range = 25.0f;
        d.layered = layered;
        d.cull_faces = d.cull_casters = k == L_CUBE_CULLED;
        gt_point_bias(&d);
        r = skgl_point_create(e->sk, &d, &p);
        rr.seconds = now();
        for (f = 0; f < FRAMES && r == SK_OK; f++) r = skgl_point_render(e->sk, p, cam, &sc, lamp);
        e->gl.Finish();
        rr.seconds = now() - rr.seconds;
        rr.callbacks = c.callbacks / FRAMES;
        rr.draws = c.draws / FRAMES;
        if (p) rr.stats_layered = skgl_point_stats(p)->layered;
        if (r == SK_OK) r = skgl_point_mask(e->sk, p, cam, e->gbuf.depth_tex, e->gbuf.color_tex, e->mask.color_tex);
        if (r == SK_OK && tb_gl_read_texture_red(&e->gl, e->mask.color_tex, W, H, vis) != 0) r = SK_ERR_GL;
        for (i = 0; i < e->n; i++) if (!(e->depth[i] < 1.0f)) vis[i] = -1.0f;
        skgl_point_destroy(e->sk, p);
    }
    rr.layers_seen = c.max_layers;
    rr.ok = r == SK_OK;
    SK_CHECK_MSG(rr.ok, "%s, layered %d: %s (%s)", light_name[k], layered, sk_result_string(r),
                 skgl_error_log(e->sk));
    return rr;
}

static void compare(int k, const char *what, const float *a, const float *b, size_t n) {
    gt_agreement g = gt_agree(a, b, n);
    printf("%-13s %-9s: %zu of %zu pixels differ\n", light_name[k], what, g.differ, g.both);
    SK_CHECK(g.both > n / 2);
    SK_CHECK_MSG((double)g.differ <= 1e-4 * (double)g.both, "%s %s: %zu of %zu differ", light_name[k], what,
                 g.differ, g.both);
}

static void test_layered(void) {
    gt_env e;
    skgl_camera cam = gt_camera(gt_v3(-9, 7, 12), gt_v3(0, 1, 0), 0.9f, 0.5f, 100, W, H);
    skgl_caster *hook = NULL;
    float *per = NULL, *lay = NULL;
    int k;
#ifdef SKGL_LAYERED_LOOP
    const int want_state = 1;
#else
    const int want_state = 2;
#endif
    if (gt_env_init_named(&e, "ground-boxes", W, H) != 0) { gt_env_free(&e); return; }
    per = gt_alloc(&e);
    lay = gt_alloc(&e);
    SK_CHECK(gt_gbuffer(&e, &cam) == 0);
    hook = gt_offset_caster(&e);
    for (k = 0; k < L_COUNT; k++) {
        int layers = k == L_LISPSM ? 3 : k == L_CUBE ? 6 : 4, h;
        for (h = 0; h < 2; h++) {
            skgl_caster *use = h ? hook : NULL;
            run_result a = run(&e, k, 0, use, &cam, per), b = run(&e, k, 1, use, &cam, lay);
            if (!a.ok || !b.ok) continue;
            compare(k, h ? "hook" : "own", per, lay, e.n);
            printf("%-13s %-9s: callbacks %d -> %d, draw calls %d -> %d, render time layered / per layer %.2f "
                   "(stats.layered %d)\n",
                   light_name[k], h ? "hook" : "own", a.callbacks, b.callbacks, a.draws, b.draws,
                   a.seconds > 0 ? b.seconds / a.seconds : 0.0, b.stats_layered);
            SK_CHECK(b.callbacks == 1 && b.stats_layered == want_state && a.stats_layered == 0);
            SK_CHECK(a.layers_seen == 0);
            if (k != L_CUBE_CULLED) {
                SK_CHECK_MSG(a.callbacks == layers, "%s: %d callbacks per layer", light_name[k], a.callbacks);
                SK_CHECK(b.layers_seen == layers);
                SK_CHECK(a.draws == layers * b.draws);
            } else {
                /* culled faces: fewer callbacks, and the layered pass culls per object over its faces */
                SK_CHECK(a.callbacks >= 1 && a.callbacks <= 6 && b.layers_seen == a.callbacks);
                SK_CHECK(b.draws <= a.draws);
            }
        }
    }
    skgl_caster_destroy(e.sk, hook);
    free(per);
    free(lay);
    gt_env_free(&e);
}

/* desc.layered is 0 or 1, named when not */
static void test_layered_desc(void) {
    gt_env e;
    skgl_shadow_desc d;
    skgl_point_desc pd;
    skgl_shadow *s = NULL;
    skgl_point *p = NULL;
    if (gt_env_init_named(&e, "ground-boxes", 64, 36) != 0) { gt_env_free(&e); return; }
    memset(&d, 0, sizeof d);
    d.layered = 2;
    SK_CHECK(skgl_shadow_create(e.sk, &d, &s) == SK_ERR_INVALID_ARG && s == NULL &&
             strstr(skgl_error_log(e.sk), "layered") != NULL);
    memset(&pd, 0, sizeof pd);
    pd.layered = -1;
    SK_CHECK(skgl_point_create(e.sk, &pd, &p) == SK_ERR_INVALID_ARG && p == NULL &&
             strstr(skgl_error_log(e.sk), "layered") != NULL);
    gt_env_free(&e);
}

SK_TEST_MAIN(test_layered, test_layered_desc)
