/* test_gl_large_world.c - the same scene and camera far from the world
   origin: hard-shadow error and stable-crop flip rate as at the origin.

   "ground-boxes" at 400 x 225, translated by d (0.6, 0.48, -0.64) for
   d = 0, 1e4 and 1e5 (one test each; the x offset is nudged by up to half
   a cell so that the camera path below crosses a boundary of
   shadowkit_gl.h's origin cells, SKGL_ORIGIN_CELL, half way). shadowkit
   gets what an application at that place holds: the vertices at the
   offset in float (the vertex buffer it draws), the scene bounds there,
   the camera's float world-space view matrix. The G-buffer and the Embree
   reference see the same float geometry and the same float camera, but
   relative to the offset (computed in double), so they are as exact as at
   the origin: what is measured is shadowkit's own precision.

   Per distance: the error of each directional technique (one frame; the
   camera of test_gl_stable.c), through the deferred mask and through a
   camera-relative forward pass (positions relative to the offset,
   skgl_shadow_bind_origin); and the stable path of test_gl_stable.c (24
   frames, steps of 0.37 texel) for standard and PSSM stable crops, 1024^2,
   max_distance 45 m, measured two ways: "flips" = pixels whose class
   changes between consecutive frames while the reference's does not, each
   frame with its own G-buffer (the temporal metric of DESIGN.md); and
   "shimmer" = flips of the first frame's world points under every frame's
   map (test_gl_stable.c's measure; 0 at the origin).

   Measured (Mesa 22.3 llvmpipe) against the exact reference with the
   default bias (receiver plane), covered error % (mask; the forward pass
   within 0.002 of it), and the path. "before" is shadowkit_gl.h without
   its camera-relative passes (this header built with
   -DSKGL_ORIGIN_CELL=0, which gives the figures of the header before that
   change); "after" is this header:
                     origin    1e4 before/after     1e5 before/after
     standard        0.0625    0.0764 / 0.0660      0.2553 / 0.0677
     standard-stable 0.1772    0.1945 / 0.1789      0.3804 / 0.1997
     pssm            0.0452    0.0677 / 0.0434      0.3196 / 0.0469
     pssm-stable     0.0886    0.0695 / 0.0712      0.2727 / 0.0677
     psm             0.0399    0.0538 / 0.0399      0.2536 / 0.0382
     lispsm          0.0417    0.0591 / 0.0417      0.3161 / 0.0469
     lspsm           0.0208    0.0365 / 0.0191      0.4203 / 0.0243
     ferko           0.0208    0.0399 / 0.0191      0.5210 / 0.0261
     rmsm            0.0677    0.0730 / 0.0660      0.3057 / 0.0712
     flips   standard-stable   0.0950   0.0928 / 0.0854   0.4404 / 0.0946
             pssm-stable       0.0695   0.0699 / 0.0589   1.2443 / 0.0569
     shimmer standard-stable   0        0.0009 / 0        0.0072 / 0
             pssm-stable       0        0.0022 / 0        0.0204 / 0
   The stable maps' errors move by a few hundredths at every distance
   because their texel grid is fixed in world light space and the scene
   sits elsewhere on it: the largest rise over the origin is
   standard-stable's at 1e5, +0.0225 point (+0.0208 through the forward
   pass); every other technique rises by at most 0.007 point.
   Asserted: error within ERR_MARGIN_PP (0.033, about 1.5x that rise)
   percentage point of the origin's for every technique, both paths
   (previously 0.2); flips within FLIP_FACTOR (2x) of the origin's (the
   largest ratio measured is 1.79, see FLIP_FACTOR); shimmer within that of
   the origin's (0) plus 0.001% (13 pixel pairs).
   Previously (old reference, normal-offset bias) the origin's errors were
   0.1647, 0.4143, 0.0715, 0.1730, 0.1198, 0.1464, 0.0815, 0.0349,
   0.1165% and its flips 0.1330 / 0.1030%; the largest rise after the
   change was 0.075 point (standard-stable, 1e5).
   Can fail: the header before the change fails 15 checks: at 1e4 the
   pssm shimmer (0.0022%: 29 pairs), at 1e5 the mask error of every
   technique (9; the smallest rise pssm-stable's, +0.18 point), lispsm's
   forward error (0.2032%, +0.16), both flip rates (4.6x and 17.9x) and
   both shimmers. The precise amount is chaotic:
   without the nudge (offset exactly (6e4, 4.8e4, -6.4e4)) that header
   gave 29.2% (standard), 47.0% (pssm), 50.2% (lspsm), 66.9% (ferko):
   bands of self-shadowing where the light depth of a receiver rounded
   past its caster's; this header gave 0.1680, 0.0715, 0.0848, 0.0266%
   there (both measured with the previous reference and bias). */
/* reads the implementation's SKGL_ORIGIN_CELL: its own copy of it (tests/shared_impl.h) */
#define SK_TEST_OWN_IMPLEMENTATION 1
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "sk_test.h"
#include "gl_test_util.h"

#define W 400
#define H 225
#define FRAMES 24
#define STEP_TEXELS 0.37f
#define MAX_DISTANCE 45.0f

/* the direction the scene is moved along (unit) */
static const double offset_dir[3] = {0.6, 0.48, -0.64};

typedef struct lw_env {
    gt_env e;             /* the scene relative to the offset: G-buffer and reference */
    tb_scene world;       /* the scene at the offset: what shadowkit draws and bounds */
    tb_gl_mesh wmesh;
    double off[3];
    skgl_caster *hook;    /* test_1e5_caster: the casters through a caster program */
} lw_env;

/* a copy of src, every position p replaced: world (relative = 0): the
   float nearest p + off; relative: that float minus off, in double, to the
   nearest float (the same points, near the origin) */
static int lw_translate(tb_scene *dst, const tb_scene *src, const double off[3], int relative) {
    size_t nv = (size_t)src->vertex_count * 3, i;
    uint32_t o, k;
    tb_scene_init(dst);
    dst->positions = (float *)malloc(sizeof(float) * nv);
    dst->normals = (float *)malloc(sizeof(float) * nv);
    dst->indices = (uint32_t *)malloc(sizeof(uint32_t) * src->index_count);
    dst->objects = (tb_object *)malloc(sizeof(tb_object) * src->object_count);
    if (!dst->positions || !dst->normals || !dst->indices || !dst->objects) return -1;
    for (i = 0; i < nv; i++) {
        float w = (float)((double)src->positions[i] + off[i % 3]);
        dst->positions[i] = relative ? (float)((double)w - off[i % 3]) : w;
    }
    memcpy(dst->normals, src->normals, sizeof(float) * nv);
    memcpy(dst->indices, src->indices, sizeof(uint32_t) * src->index_count);
    memcpy(dst->objects, src->objects, sizeof(tb_object) * src->object_count);
    dst->vertex_count = dst->vertex_cap_ = src->vertex_count;
    dst->index_count = dst->index_cap_ = src->index_count;
    dst->object_count = dst->object_cap_ = src->object_count;
    dst->bounds.min = gt_v3(3e38f, 3e38f, 3e38f);
    dst->bounds.max = gt_v3(-3e38f, -3e38f, -3e38f);
    for (o = 0; o < dst->object_count; o++) {
        tb_object *ob = &dst->objects[o];
        ob->bounds = dst->bounds;
        for (k = ob->first_index; k < ob->first_index + ob->index_count; k++) {
            const float *p = dst->positions + 3 * (size_t)dst->indices[k];
            int a;
            for (a = 0; a < 3; a++) {
                if (p[a] < (&ob->bounds.min.x)[a]) (&ob->bounds.min.x)[a] = p[a];
                if (p[a] > (&ob->bounds.max.x)[a]) (&ob->bounds.max.x)[a] = p[a];
            }
        }
        for (k = 0; k < 3; k++) {
            if ((&ob->bounds.min.x)[k] < (&dst->bounds.min.x)[k]) (&dst->bounds.min.x)[k] = (&ob->bounds.min.x)[k];
            if ((&ob->bounds.max.x)[k] > (&dst->bounds.max.x)[k]) (&dst->bounds.max.x)[k] = (&ob->bounds.max.x)[k];
        }
    }
    return 0;
}

static void lw_free(lw_env *w) {
    if (w->e.ctx) tb_gl_mesh_destroy(&w->e.gl, &w->wmesh);
    tb_scene_free(&w->world);
    gt_env_free(&w->e);
}

static float path_step;   /* set by the origin's run */

static int lw_init(lw_env *w, double dist) {
    tb_scene base, rel;
    int k;
    memset(w, 0, sizeof *w);
    for (k = 0; k < 3; k++) w->off[k] = dist * offset_dir[k];
    if (dist > 0.0) {
        /* nudged along x (by less than half a cell) so that the camera path
           crosses a boundary of shadowkit's origin cells (SKGL_ORIGIN_CELL)
           half way: the passes change origin mid-path */
        double cell = SKGL_ORIGIN_CELL > 0.0 ? SKGL_ORIGIN_CELL : 256.0, x0 = -9.0 + w->off[0];
        double run = 0.6 * path_step * (FRAMES - 1);
        double b = (floor(x0 / cell) + 0.5) * cell;
        w->off[0] += b - x0 - 0.5 * run;
    }
    tb_scene_init(&base);
    tb_scene_init(&rel);
    if (tb_scene_build(&base, "ground-boxes") != 0 || lw_translate(&w->world, &base, w->off, 0) != 0 ||
        lw_translate(&rel, &base, w->off, 1) != 0) {
        SK_CHECK_MSG(0, "scene");
        tb_scene_free(&base); tb_scene_free(&rel);
        return -1;
    }
    tb_scene_free(&base);
    if (gt_env_init(&w->e, &rel, W, H) != 0) { tb_scene_free(&rel); return -1; }
    if (tb_gl_mesh_create(&w->e.gl, &w->wmesh, &w->world) != 0) { SK_CHECK_MSG(0, "world mesh"); return -1; }
    return 0;
}

static void lw_draw(void *user, const skgl_draw_info *info) {
    lw_env *w = (lw_env *)user;
    (void)info;
    if (w->hook && !skgl_use_caster(w->e.sk, w->hook)) return;
    tb_gl_mesh_draw(&w->e.gl, &w->wmesh, 0, 0);
}

static skgl_scene lw_scene(lw_env *w) {
    skgl_scene sc;
    sc.draw = lw_draw;
    sc.user = w;
    sc.bounds = w->world.bounds;
    return sc;
}

/* The camera at eye_rel + off looking at target_rel + off, as a float
   world-space view (what an application holds: rotation, and a translation
   of the order of the offset, each rounded to float), and the same camera
   relative to the offset (that float matrix times T(off), in double: what
   the G-buffer and the reference use, so they see exactly the camera
   shadowkit is given). */
static void lw_cameras(const lw_env *w, sk_vec3 eye_rel, sk_vec3 target_rel, skgl_camera *world,
                       skgl_camera *rel) {
    sk_mat4 v = sk_mat4_look_at(eye_rel, target_rel, gt_v3(0, 1, 0));
    int r;
    world->view = v;
    rel->view = v;
    for (r = 0; r < 3; r++) {
        double t = (double)v.m[12 + r] - ((double)v.m[r] * w->off[0] + (double)v.m[4 + r] * w->off[1] +
                                         (double)v.m[8 + r] * w->off[2]);
        world->view.m[12 + r] = (float)t;
    }
    for (r = 0; r < 3; r++) {
        double t = (double)world->view.m[12 + r] + ((double)v.m[r] * w->off[0] + (double)v.m[4 + r] * w->off[1] +
                                                   (double)v.m[8 + r] * w->off[2]);
        rel->view.m[12 + r] = (float)t;
    }
    world->proj = rel->proj = sk_mat4_perspective(0.9f, (float)W / (float)H, 0.5f, 100.0f);
}

static const sk_vec3 *light_dir(void) {
    static sk_vec3 l = {-0.5f, -1.0f, -0.35f};
    return &l;
}

/* render (after analyze for FERKO and RMSM) for cw, mask over the last G-buffer */
static int lw_frame(lw_env *w, skgl_shadow *s, const skgl_camera *cw, float *mask) {
    skgl_scene sc = lw_scene(w);
    skgl_technique t = skgl_shadow_get_desc(s).technique;
    sk_result r;
    if (t == SKGL_FERKO || t == SKGL_RMSM) {
        r = skgl_shadow_analyze(w->e.sk, s, cw, &sc, *light_dir(), w->e.gbuf.depth_tex);
        if (r != SK_OK) { printf("analyze: %s\n", sk_result_string(r)); return -1; }
    }
    r = skgl_shadow_render(w->e.sk, s, cw, &sc, *light_dir());
    if (r != SK_OK) { printf("render: %s (%s)\n", sk_result_string(r), skgl_error_log(w->e.sk)); return -1; }
    return gt_mask_only(&w->e, s, cw, mask);
}

/* The forward path of a camera-relative renderer: the mesh relative to the
   offset (w->e.mesh), the relative camera, sk_shadow() given those
   positions through skgl_shadow_bind_origin(origin = the offset); the map
   already rendered for cw. Visibility read back as gt_forward_render does. */
static int lw_forward(lw_env *w, gt_forward *f, const skgl_shadow *s, const skgl_camera *cr, float *vis,
                      float *depth) {
    sk_result r;
    gt_forward_begin(&w->e, f, cr);
    r = skgl_shadow_bind_origin(w->e.sk, s, f->program, 4, w->off);
    if (r == SK_OK) tb_gl_mesh_draw(&w->e.gl, &w->e.mesh, 0, 0);
    gt_forward_unbind(&w->e);
    if (r != SK_OK) { printf("bind_origin: %s\n", sk_result_string(r)); return -1; }
    return gt_forward_read(&w->e, f, vis, depth);
}

/* ---- hard-shadow error, one frame per technique ---- */
typedef struct lw_tech {
    const char *name;
    skgl_technique technique;
    int resolution, cascades, stable;
} lw_tech;

static const lw_tech techs[] = {
    {"standard", SKGL_STANDARD, 1024, 1, 0},
    {"standard-stable", SKGL_STANDARD, 1024, 1, 1},
    {"pssm", SKGL_PSSM, 1024, 4, 0},
    {"pssm-stable", SKGL_PSSM, 1024, 4, 1},
    {"psm", SKGL_PSM, 1024, 1, 0},
    {"lispsm", SKGL_LISPSM, 1024, 1, 0},
    {"lspsm", SKGL_LSPSM, 1024, 0, 0},
    {"ferko", SKGL_FERKO, 2048, 1, 0},
    {"rmsm", SKGL_RMSM, 16384, 1, 0},
};
#define NTECH ((int)(sizeof techs / sizeof techs[0]))

static skgl_shadow *lw_shadow(lw_env *w, const lw_tech *t) {
    skgl_shadow_desc d = gt_shadow_desc(t->technique, t->resolution, t->cascades, t->stable);
    if (t->stable) d.max_distance = MAX_DISTANCE;
    return gt_shadow(&w->e, &d);
}

/* ---- the stable path ---- */
typedef struct path_result {
    double shimmer_pct;   /* flips of fixed world points (the first frame's G-buffer) between frames */
    double flip_pct;      /* flips where the reference does not flip, each frame its own G-buffer */
    uint64_t shimmer_flips, flips, covered;
} path_result;

static sk_vec3 path_dir(void) { return gt_v3(0.6f, 0.13f, 0.79f); }

static path_result lw_path(lw_env *w, const lw_tech *t, float step) {
    path_result pr;
    skgl_shadow *s = lw_shadow(w, t);
    float *ref0 = gt_alloc(&w->e), *refs[2], *fixed[2], *moving[2];
    sk_vec3 dir = path_dir();
    skgl_camera cw0, cr0;
    uint64_t covered_fixed = 0;
    int f, k;
    memset(&pr, 0, sizeof pr);
    for (k = 0; k < 2; k++) { refs[k] = gt_alloc(&w->e); fixed[k] = gt_alloc(&w->e); moving[k] = gt_alloc(&w->e); }
    lw_cameras(w, gt_v3(-9, 7, 12), gt_v3(0, 1, 0), &cw0, &cr0);
    if (!s || !ref0 || gt_gbuffer(&w->e, &cr0) != 0 || gt_reference(&w->e, *light_dir(), ref0) != 0) {
        SK_CHECK_MSG(0, "%s: path setup", t->name);
        goto done;
    }
    for (f = 0; f < FRAMES; f++) {
        float u = step * (float)f;
        skgl_camera cw, cr;
        int c = f & 1;
        lw_cameras(w, gt_v3(-9 + dir.x * u, 7 + dir.y * u, 12 + dir.z * u), gt_v3(dir.x * u, 1 + dir.y * u, dir.z * u),
                   &cw, &cr);
        /* the map of this frame's camera over the first frame's points */
        SK_CHECK(gt_gbuffer(&w->e, &cr0) == 0);
        {
            skgl_scene sc = lw_scene(w);
            SK_CHECK(skgl_shadow_render(w->e.sk, s, &cw, &sc, *light_dir()) == SK_OK);
        }
        SK_CHECK(gt_mask_only(&w->e, s, &cw0, fixed[c]) == 0);
        /* and over this frame's own points */
        SK_CHECK(gt_gbuffer(&w->e, &cr) == 0 && gt_reference(&w->e, *light_dir(), refs[c]) == 0);
        SK_CHECK(gt_mask_only(&w->e, s, &cw, moving[c]) == 0);
        if (f > 0) {
            tb_flip_rate a = tb_metric_flip(ref0, ref0, fixed[c ^ 1], fixed[c], w->e.n);
            tb_flip_rate b = tb_metric_flip(refs[c ^ 1], refs[c], moving[c ^ 1], moving[c], w->e.n);
            pr.shimmer_flips += a.flips;
            covered_fixed += a.covered;
            pr.flips += b.flips;
            pr.covered += b.covered;
        }
    }
    pr.shimmer_pct = covered_fixed ? 100.0 * (double)pr.shimmer_flips / (double)covered_fixed : 100.0;
    pr.flip_pct = pr.covered ? 100.0 * (double)pr.flips / (double)pr.covered : 100.0;
done:
    free(ref0);
    for (k = 0; k < 2; k++) { free(refs[k]); free(fixed[k]); free(moving[k]); }
    skgl_shadow_destroy(w->e.sk, s);
    return pr;
}

/* world size of one texel of layer 0 */
static float texel_world(const skgl_shadow *s) {
    sk_mat4 m = skgl_shadow_matrix(s, 0);
    float sx = sqrtf(m.m[0] * m.m[0] + m.m[4] * m.m[4] + m.m[8] * m.m[8]);
    return sx > 0 ? 2.0f / (sx * (float)skgl_shadow_get_desc(s).resolution) : 0;
}

/* ---- per distance ---- */
typedef struct lw_result {
    double err[NTECH], fwd_err[NTECH];   /* deferred mask; forward through skgl_shadow_bind_origin */
    path_result path[2];   /* standard-stable, pssm-stable */
    int ok;
} lw_result;

static lw_result at_origin;
static int lw_with_hook;   /* run_distance draws the casters through a caster program */

#define FWD_MASK_PP 0.01

static lw_result run_distance(double dist) {
    lw_env w;
    lw_result res;
    float *ref, *mask, *depth;
    skgl_camera cw, cr;
    gt_forward fw;
    int i;
    memset(&res, 0, sizeof res);
    memset(&fw, 0, sizeof fw);
    if (lw_init(&w, dist) != 0) { lw_free(&w); return res; }
    if (lw_with_hook) {
        skgl_caster_desc cd;
        memset(&cd, 0, sizeof cd);
        cd.vertex = "layout(location = 0) in vec3 a_pos;\nvec4 skgl_caster_position() { return vec4(a_pos, 1.0); }\n";
        SK_CHECK_MSG(skgl_caster_create(w.e.sk, &cd, &w.hook) == SK_OK, "%s", skgl_error_log(w.e.sk));
    }
    ref = gt_alloc(&w.e);
    mask = gt_alloc(&w.e);
    depth = gt_alloc(&w.e);
    SK_CHECK(depth && gt_forward_create(&w.e, &fw) == 0);
    lw_cameras(&w, gt_v3(-9, 7, 12), gt_v3(0, 1, 0), &cw, &cr);
    SK_CHECK(ref && mask && gt_gbuffer(&w.e, &cr) == 0 && gt_reference(&w.e, *light_dir(), ref) == 0);
    for (i = 0; i < NTECH; i++) {
        skgl_shadow *s = lw_shadow(&w, &techs[i]);
        res.err[i] = -1;
        if (s && lw_frame(&w, s, &cw, mask) == 0) {
            char name[64];
            res.err[i] = tb_metric_hard(ref, mask, w.e.n).pct;
            snprintf(name, sizeof name, "large-world-%g-%s", dist, techs[i].name);
            gt_images(&w.e, name, ref, mask);
            /* the forward path on the same map: the pixels the forward pass
               covers (its own rasterisation of the same camera) */
            res.fwd_err[i] = -1;
            if (lw_forward(&w, &fw, s, &cr, mask, depth) == 0) res.fwd_err[i] = tb_metric_hard(ref, mask, w.e.n).pct;
            SK_CHECK_MSG(res.fwd_err[i] >= 0, "%g: %s forward frame failed", dist, techs[i].name);
        }
        SK_CHECK_MSG(res.err[i] >= 0, "%g: %s frame failed", dist, techs[i].name);
        if (dist == 0.0 && techs[i].stable && techs[i].technique == SKGL_STANDARD) path_step = STEP_TEXELS * texel_world(s);
        skgl_shadow_destroy(w.e.sk, s);
    }
    res.path[0] = lw_path(&w, &techs[1], path_step);
    res.path[1] = lw_path(&w, &techs[3], path_step);
    printf("distance %g (offset %.1f %.1f %.1f):\n", dist, w.off[0], w.off[1], w.off[2]);
    for (i = 0; i < NTECH; i++) {
        printf("  %-16s error %.4f%% (forward, camera-relative %.4f%%)\n", techs[i].name, res.err[i], res.fwd_err[i]);
        /* the forward pass samples the map the mask sampled: within
           FWD_MASK_PP of the mask's error at every distance (measured at
           most 0.0018 point over the 36 technique-distance pairs); the
           comparisons with the origin alone would pass a forward pass wrong
           at every distance alike */
        SK_CHECK_MSG(fabs(res.fwd_err[i] - res.err[i]) <= FWD_MASK_PP, "%g: %s forward error %.4f%%, mask %.4f%%",
                     dist, techs[i].name, res.fwd_err[i], res.err[i]);
    }
    for (i = 0; i < 2; i++)
        printf("  %-16s path: shimmer %llu = %.4f%%, flips %llu of %llu = %.4f%% (step %.4f m)\n",
               i ? "pssm-stable" : "standard-stable", (unsigned long long)res.path[i].shimmer_flips,
               res.path[i].shimmer_pct, (unsigned long long)res.path[i].flips,
               (unsigned long long)res.path[i].covered, res.path[i].flip_pct, path_step);
    SK_CHECK(w.e.gl.GetError() == 0);
    res.ok = 1;
    free(ref);
    free(mask);
    free(depth);
    gt_forward_destroy(&w.e, &fw);
    skgl_caster_destroy(w.e.sk, w.hook);
    lw_free(&w);
    return res;
}

/* the bounds: error within ERR_MARGIN_PP percentage points of the origin's;
   flip rate within FLIP_FACTOR of it; fixed points shimmering at most
   FLIP_FACTOR times the origin's plus SHIMMER_SLACK_PCT (13 of the 1.32 M
   pixel pairs; the origin's is 0). Measured: a rise of at most 0.0225
   point, flips at most 1.00x the origin's (figures at the top) with the
   sphere-fitted stable crops. The stepped stable crops (the default
   since) flip 0.0215% at the origin and 0.0384% / 0.0382% at 1e4 / 1e5
   with every layer on the same ladder step at every distance (checked:
   widths and heights 2^(20/8) ... 2^(41/8) m alike): where the scene sits
   on the world-fixed texel grid moves which edge pixels cross a texel
   boundary, not precision. FLIP_FACTOR 2 allows that (1.79x) and still
   fails the header before the origin work (4.6x and 17.9x). */
#define ERR_MARGIN_PP 0.033
#define FLIP_FACTOR 2.0
#define SHIMMER_SLACK_PCT 0.001

static void compare(double dist) {
    lw_result r = run_distance(dist);
    int i;
    if (!r.ok || !at_origin.ok) { SK_CHECK_MSG(0, "%g: no result to compare", dist); return; }
    for (i = 0; i < NTECH; i++)
        SK_CHECK_MSG(r.fwd_err[i] >= 0 && r.fwd_err[i] <= at_origin.fwd_err[i] + ERR_MARGIN_PP,
                     "%g: %s forward error %.4f%%, at the origin %.4f%% (+%.3f allowed)", dist, techs[i].name,
                     r.fwd_err[i], at_origin.fwd_err[i], ERR_MARGIN_PP);
    for (i = 0; i < NTECH; i++)
        SK_CHECK_MSG(r.err[i] >= 0 && r.err[i] <= at_origin.err[i] + ERR_MARGIN_PP,
                     "%g: %s error %.4f%%, at the origin %.4f%% (+%.3f allowed)", dist, techs[i].name, r.err[i],
                     at_origin.err[i], ERR_MARGIN_PP);
    for (i = 0; i < 2; i++) {
        const char *n = i ? "pssm-stable" : "standard-stable";
        SK_CHECK(r.path[i].covered > (uint64_t)(FRAMES - 1) * (W * H / 2));
        SK_CHECK_MSG(r.path[i].flip_pct <= FLIP_FACTOR * at_origin.path[i].flip_pct,
                     "%g: %s flip rate %.4f%%, at the origin %.4f%%", dist, n, r.path[i].flip_pct,
                     at_origin.path[i].flip_pct);
        SK_CHECK_MSG(r.path[i].shimmer_pct <= FLIP_FACTOR * at_origin.path[i].shimmer_pct + SHIMMER_SLACK_PCT,
                     "%g: %s shimmer %.4f%%, at the origin %.4f%%", dist, n, r.path[i].shimmer_pct,
                     at_origin.path[i].shimmer_pct);
    }
}

static void test_origin(void) {
    at_origin = run_distance(0.0);
    SK_CHECK(at_origin.ok);
    SK_CHECK(path_step > 0.0f);
    /* the origin itself as test_gl_stable measures it: stable crops do not shimmer */
    SK_CHECK(at_origin.path[0].shimmer_pct < 0.005 && at_origin.path[1].shimmer_pct < 0.005);
}
static void test_1e4(void) { compare(1e4); }
static void test_1e5(void) { compare(1e5); }
/* the same at 1e5 with the casters drawn through a caster program: its
   program gets the origin-relative model and matrices from shadowkit as
   the default one does (measured: the same errors and flips as test_1e5,
   to the last digit). Can fail: skgl_use_caster setting a plain identity
   model instead of the one moved to the pass's origin (a local copy of the
   header) puts the casters 1e5 m off: 18 checks fail (errors 2.6%). */
static void test_1e5_caster(void) {
    lw_with_hook = 1;
    compare(1e5);
    lw_with_hook = 0;
}

SK_TEST_MAIN(test_origin, test_1e4, test_1e5, test_1e5_caster)
