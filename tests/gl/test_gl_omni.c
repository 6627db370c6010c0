/* test_gl_omni.c - point lights (King & Newhall, seed 004) through
   skgl_point_*: the native depth cube map and VSDCT against the Embree
   point-light reference, seams, culling against rendering everything, and
   the scissor. Room scene (tb_scene_build_room) with a 0.4 m box one metre
   from the light on each axis, and a "cage" (two boxes as one object) whose
   box holds a light position. 320 x 240, range 10, PCF radius 1.

   Measured (Mesa 22.3 llvmpipe, OSMesa):

   test_faces - one view per face, looking past that axis's box at its
   shadow on the wall, floor or ceiling (28-36% of the pixels shadowed in
   the reference), 512 texels per face, face and caster culling on:
       face        +X      -X      +Y      -Y      +Z      -Z
       error %   0.1302  0.1719  0.0000  0.1146  0.0977  0.1211  (cube = vsdct)
       found     0.9957  0.9967  1.0000  0.9968  0.9971  0.9961
     (found: the share of the reference's shadowed pixels the mask shadows).
     Asserted: error <= 0.25%, found >= 0.993, cube and VSDCT within 0.1
     percentage point, and the view sees > 20% shadow. Can fail: at 1/4
     resolution (SK_GL_TEST_RES_SCALE=0.25, 128 per face) errors 0.19,
     0.71, 0.00, 0.48, 0.38, 0.18% and found 0.994, 0.987, 1.0, 0.987,
     0.992, 0.994: faces -X, -Y and +Z fail; with the faces' views swapped
     in pairs (a local copy rendering face f with sk_cube_face_view(f ^ 1))
     errors 2.4, 4.9, 0.8, 32.0, 5.5, 3.6%: every face fails.

   test_seams - three overviews of the room, 256 per face: the pixels whose
   light vector lies within one texel (2/256 in face coordinates) of a face
   edge, where the pillars' shadows cross the seams: cube 99.21% of 2664
   agree with the reference (the other pixels 99.42%), VSDCT 99.14%
   (99.42%). Asserted: >= 98.9%, and at most 0.6 point below the other
   pixels. Can fail: with the swapped face views above 90.5% (the others
   78.9%): fails. Not seen by it: faces rendered 3% too narrow (seams 99.1%
   against 98.4%); at 1/4 resolution the band is four times wider and
   agrees 99.1% against 97.5%.

   test_culling_exhaustive - 16 random light positions (fixed seed, the
   first inside the cage's box), random eyes inside the room (so inside the
   light's range; every other one looking away from the light), random
   fields of view, 256 per face: face culling plus caster culling against
   rendering everything: 0 pixels differ (cube: 57 faces and 459
   (face, caster) pairs culled; VSDCT: 56 and 472). Asserted: no pixel
   differs, and something was culled. Can fail: the culling the seed warns
   against (caster box against the view frustum, in the test's callback)
   changes 361648 pixels on 16 such trials (asserted > 1000). Two fixes
   came from this test: VSDCT's RG16 coordinates are clamped again per face
   in the shader (without it 252 pixels of one trial differed by 0.002, a
   neighbouring sub-rect leaking into the 2x2 filter), and face culling is
   widened by the filter's reach (not needed by these trials: with the
   plain sk_cube_visible_faces the cube still matched).

   test_scissor - range 2 light seen from the room's end: rectangle
   87,9 194x172; every pixel outside it keeps the cleared value, every one
   inside equals the unscissored mask; eye inside the range box: the full
   viewport, every pixel written; the range box behind the eye: nothing
   written, rectangle 0.

   test_resolution_selection - range 1.5 light near a wall, 1024 at most:
   S = 8188 pixels, 6 faces, M = 64 = sk_cube_resolution(6, S, 2, 1024)
   (cube and VSDCT); 0 of 1576 covered pixels misclassified.

   test_forward - skgl_point_glsl_snippet() in a forward shader (VSDCT with
   its #define) bound by skgl_point_bind, the room drawn from an overview:
   100% of the 76800 pixels agree with the deferred mask (cube and VSDCT).
   Asserted: >= 99%. Can fail: without the skgl_point_bind call the cube
   agrees on 65.3% and VSDCT draws nothing; with the normal offset and the
   PCF step zeroed (sk_point_texel 0, a local copy of the header) both
   agree on 94.1% (and test_faces fails at 1.52%, test_seams at 96.1%).

   test_invalid - bad descs are SK_ERR_INVALID_ARG with nothing created;
   bad render / mask / bind arguments too; no GL error. */
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "sk_test.h"
#include "gl_test_util.h"

#include <math.h>

#define W 320
#define H 240
#define RANGE 10.0f

/* the room, one box on each axis around the light (the face culled toward
   each wall has a caster of its own), and a "cage": two boxes joined into
   one object whose box holds the point CAGE_LIGHT, for the light inside a
   caster's bounds */
static const float axis_light[3] = {0.3f, 2.1f, -0.2f};
static const float cage_light[3] = {-3.4f, 1.5f, 2.0f};

static int build_scene(tb_scene *s) {
    static const int axes[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    int a;
    tb_scene_init(s);
    if (tb_scene_build_room(s) != 0) return -1;
    for (a = 0; a < 6; a++) {
        char name[16];
        float c[3], hs = 0.2f;
        int k;
        for (k = 0; k < 3; k++) c[k] = axis_light[k] + 1.0f * (float)axes[a][k];
        snprintf(name, sizeof name, "axis%d", a);
        if (tb_scene_add_box(s, name, gt_v3(c[0] - hs, c[1] - hs, c[2] - hs), gt_v3(c[0] + hs, c[1] + hs, c[2] + hs)) < 0)
            return -1;
    }
    /* the cage: a slab below and a post beside cage_light, one object */
    if (tb_scene_add_box(s, "cage", gt_v3(-4.0f, 0.9f, 1.4f), gt_v3(-2.8f, 1.0f, 2.6f)) < 0 ||
        tb_scene_add_box(s, "cage_post", gt_v3(-2.9f, 1.0f, 1.4f), gt_v3(-2.8f, 2.2f, 1.5f)) < 0)
        return -1;
    {
        tb_object *o = &s->objects[s->object_count - 2], *q = &s->objects[s->object_count - 1];
        o->index_count += q->index_count;
        o->bounds.max.y = q->bounds.max.y > o->bounds.max.y ? q->bounds.max.y : o->bounds.max.y;
        s->object_count--;
    }
    return 0;
}

static int env_init(gt_env *e) {
    tb_scene s;
    if (build_scene(&s) != 0) { SK_CHECK_MSG(0, "scene"); tb_scene_free(&s); return -1; }
    return gt_env_init(e, &s, W, H);
}

/* per object: only the casters skgl_point_caster_visible passes; with
   wrong_cull set, instead the culling the seed warns against (Fig. 5.4.3:
   the caster's box against the view frustum, so off-screen casters lose
   their shadows), the negative control of test_culling_exhaustive */
static int wrong_cull;
static sk_frustum wrong_cull_view;
static void point_draw(void *user, const skgl_draw_info *info) {
    gt_env *e = (gt_env *)user;
    uint32_t i;
    for (i = 0; i < e->scene.object_count; i++) {
        const tb_object *o = &e->scene.objects[i];
        int vis;
        if (wrong_cull) {
            sk_frustum bf;
            vis = sk_frustum_from_aabb(o->bounds, &bf) != SK_OK || sk_frustum_intersects(&bf, &wrong_cull_view);
        } else vis = skgl_point_caster_visible(info, o->bounds);
        if (vis) tb_gl_mesh_draw(&e->gl, &e->mesh, o->first_index, o->index_count);
    }
}

static int point_reference(gt_env *e, sk_vec3 lp, float *vis) {
    tb_view v;
    tb_light l;
    memset(&l, 0, sizeof l);
    l.type = TB_LIGHT_POINT;
    l.position = lp;
    l.range = RANGE;
    v.inv_view_proj = e->inv_vp;
    v.width = e->w;
    v.height = e->h;
    return tb_reference_trace(e->ref, &v, e->depth, e->normals, &l, NULL, vis);
}

/* render + mask (the mask cleared to `clear` first), read back; background -1 */
static int point_mask_raw(gt_env *e, skgl_point *p, const skgl_camera *cam, sk_vec3 lp, float clear, float *vis, int raw) {
    skgl_scene sc = gt_scene(e);
    sk_result r;
    size_t i;
    sc.draw = point_draw;
    r = skgl_point_render(e->sk, p, cam, &sc, lp);
    if (r != SK_OK) { printf("skgl_point_render: %s (%s)\n", sk_result_string(r), skgl_error_log(e->sk)); return -1; }
    tb_gl_fbo_bind(&e->gl, &e->mask);
    e->gl.ClearColor(clear, 0, 0, 0);
    e->gl.Clear(0x00004000u);
    tb_gl_fbo_bind(&e->gl, NULL);
    r = skgl_point_mask(e->sk, p, cam, e->gbuf.depth_tex, e->gbuf.color_tex, e->mask.color_tex);
    if (r != SK_OK) { printf("skgl_point_mask: %s (%s)\n", sk_result_string(r), skgl_error_log(e->sk)); return -1; }
    if (tb_gl_read_texture_red(&e->gl, e->mask.color_tex, e->w, e->h, vis) != 0) return -1;
    if (!raw)
        for (i = 0; i < e->n; i++) if (!(e->depth[i] < 1.0f)) vis[i] = -1.0f;
    return 0;
}
static int point_mask(gt_env *e, skgl_point *p, const skgl_camera *cam, sk_vec3 lp, float clear, float *vis) {
    return point_mask_raw(e, p, cam, lp, clear, vis, 0);
}

static skgl_point *make_point(gt_env *e, skgl_point_technique t, int res, int culling) {
    skgl_point_desc d;
    skgl_point *p = NULL;
    sk_result r;
    memset(&d, 0, sizeof d);
    d.technique = t;
    d.resolution = res;
    d.range = RANGE;
    d.cull_faces = d.cull_casters = culling;
    r = skgl_point_create(e->sk, &d, &p);
    SK_CHECK_MSG(r == SK_OK, "skgl_point_create: %s (%s)", sk_result_string(r), skgl_error_log(e->sk));
    return p;
}

static const char *const tech_names[2] = {"cube", "vsdct"};
static int res_scaled(int r) { int s = (int)(r * gt_res_scale()); return s < 4 ? 4 : s; }

/* ---- every face orientation ---- */
static void test_faces(void) {
    static const int axes[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    static const int side[6][3] = {{0, 0, 1}, {0, 0, 1}, {1, 0, 0}, {1, 0, 0}, {1, 0, 0}, {1, 0, 0}};
    gt_env e;
    float *ref, *res;
    sk_vec3 lp = gt_v3(axis_light[0], axis_light[1], axis_light[2]);
    int t, a;
    double errs[2] = {0, 0};
    if (env_init(&e) != 0) { gt_env_free(&e); return; }
    ref = gt_alloc(&e); res = gt_alloc(&e);
    for (a = 0; a < 6; a++) {
        sk_vec3 eye, target;
        skgl_camera cam;
        size_t i, ref_shadow = 0, both = 0;
        eye = gt_v3(lp.x + 1.3f * side[a][0] - 0.6f * axes[a][0], lp.y + 1.3f * side[a][1] - 0.6f * axes[a][1],
                    lp.z + 1.3f * side[a][2] - 0.6f * axes[a][2]);
        target = gt_v3(lp.x + 3.0f * axes[a][0], lp.y + 3.0f * axes[a][1], lp.z + 3.0f * axes[a][2]);
        cam = gt_camera(eye, target, 1.2f, 0.05f, 30.0f, W, H);
        if (axes[a][1] != 0) cam.view = sk_mat4_look_at(eye, target, gt_v3(0, 0, 1));
        SK_CHECK(gt_gbuffer(&e, &cam) == 0);
        SK_CHECK(point_reference(&e, lp, ref) == 0);
        for (t = 0; t < 2; t++) {
            skgl_point *p = make_point(&e, (skgl_point_technique)t, res_scaled(512), 1);
            tb_hard_error err;
            char name[64];
            if (!p) continue;
            SK_CHECK(point_mask(&e, p, &cam, lp, 1.0f, res) == 0);
            err = tb_metric_hard(ref, res, e.n);
            ref_shadow = both = 0;
            for (i = 0; i < e.n; i++) {
                if (tb_visibility_class(ref[i]) == 0) {
                    ref_shadow++;
                    if (tb_visibility_class(res[i]) == 0) both++;
                }
            }
            printf("face %d %-5s err %.4f%% (lit %llu shadow %llu of %llu) ref shadow %.2f%% found %.4f faces %d culled %d casters %d/%d\n",
                   a, tech_names[t], err.pct, (unsigned long long)err.false_lit, (unsigned long long)err.false_shadow,
                   (unsigned long long)err.covered, 100.0 * ref_shadow / (double)err.covered,
                   ref_shadow ? (double)both / ref_shadow : 0.0, skgl_point_stats(p)->faces_rendered,
                   skgl_point_stats(p)->faces_culled, skgl_point_stats(p)->casters_drawn,
                   skgl_point_stats(p)->casters_culled);
            errs[t] = err.pct;
            SK_CHECK_MSG(100.0 * ref_shadow / (double)err.covered > 20.0, "face %d: the view sees too little shadow", a);
            SK_CHECK_MSG(err.pct <= 0.25, "face %d %s: %.4f%% misclassified", a, tech_names[t], err.pct);
            SK_CHECK_MSG(ref_shadow && (double)both / ref_shadow >= 0.993, "face %d %s: %.4f of the shadow found", a,
                         tech_names[t], ref_shadow ? (double)both / ref_shadow : 0.0);
            SK_CHECK_MSG(skgl_point_stats(p)->faces_rendered >= 1 && skgl_point_stats(p)->faces_culled >= 1,
                         "face %d %s: %d faces rendered", a, tech_names[t], skgl_point_stats(p)->faces_rendered);
            snprintf(name, sizeof name, "omni-face%d-%s", a, tech_names[t]);
            gt_images(&e, name, ref, res);
            skgl_point_destroy(e.sk, p);
        }
        SK_CHECK_MSG(fabs(errs[0] - errs[1]) <= 0.1, "face %d: cube %.4f%% against vsdct %.4f%%", a, errs[0], errs[1]);
    }
    SK_CHECK(e.gl.GetError() == 0);
    free(ref); free(res);
    gt_env_free(&e);
}

/* ---- seams: pixels whose light vector is within one texel of a face edge ---- */
static void test_seams(void) {
    static const float views[3][6] = {{4.2f, 3.6f, 4.2f, -2, 0.5f, -2}, {-4.2f, 0.6f, -4.0f, 2, 2.5f, 2},
                                      {4.0f, 1.0f, -4.2f, -3, 3.0f, 3}};
    gt_env e;
    float *ref, *res;
    sk_vec3 lp = gt_v3(-0.2f, 2.0f, 0.1f);
    int t, v, face_res = res_scaled(256);
    if (env_init(&e) != 0) { gt_env_free(&e); return; }
    ref = gt_alloc(&e); res = gt_alloc(&e);
    for (t = 0; t < 2; t++) {
        size_t seam = 0, seam_ok = 0, other = 0, other_ok = 0;
        skgl_point *p = make_point(&e, (skgl_point_technique)t, face_res, 1);
        if (!p) continue;
        for (v = 0; v < 3; v++) {
            skgl_camera cam = gt_camera(gt_v3(views[v][0], views[v][1], views[v][2]),
                                        gt_v3(views[v][3], views[v][4], views[v][5]), 1.3f, 0.05f, 30.0f, W, H);
            size_t i;
            SK_CHECK(gt_gbuffer(&e, &cam) == 0);
            SK_CHECK(point_reference(&e, lp, ref) == 0);
            SK_CHECK(point_mask(&e, p, &cam, lp, 1.0f, res) == 0);
            for (i = 0; i < e.n; i++) {
                double w[3], d[3], ma, lo;
                int c = tb_visibility_class(ref[i]), k, near_edge;
                if (c < 0 || gt_world(&e, i, w)) continue;
                for (k = 0; k < 3; k++) d[k] = fabs(w[k] - (k == 0 ? lp.x : k == 1 ? lp.y : lp.z));
                ma = d[0] > d[1] ? (d[0] > d[2] ? d[0] : d[2]) : (d[1] > d[2] ? d[1] : d[2]);
                /* the larger of the two minor components: the nearest face edge */
                lo = d[0] + d[1] + d[2] - ma - (d[0] < d[1] ? (d[0] < d[2] ? d[0] : d[2]) : (d[1] < d[2] ? d[1] : d[2]));
                near_edge = ma > 0.0 && 1.0 - lo / ma < 2.0 / face_res;
                if (near_edge) { seam++; seam_ok += tb_visibility_class(res[i]) == c; }
                else { other++; other_ok += tb_visibility_class(res[i]) == c; }
            }
            if (v == 0) {
                char name[64];
                snprintf(name, sizeof name, "omni-seam-%s", tech_names[t]);
                gt_images(&e, name, ref, res);
            }
        }
        printf("seams %-5s %d: %llu seam pixels agree %.4f%%, %llu others agree %.4f%%\n", tech_names[t], face_res,
               (unsigned long long)seam, 100.0 * seam_ok / (seam ? seam : 1), (unsigned long long)other,
               100.0 * other_ok / (other ? other : 1));
        SK_CHECK_MSG(seam > 1000, "%s: only %llu seam pixels", tech_names[t], (unsigned long long)seam);
        SK_CHECK_MSG(100.0 * seam_ok / (seam ? seam : 1) >= 98.9, "%s: seam pixels agree %.4f%%", tech_names[t],
                     100.0 * seam_ok / (seam ? seam : 1));
        SK_CHECK_MSG(100.0 * seam_ok / (seam ? seam : 1) >= 100.0 * other_ok / (other ? other : 1) - 0.6,
                     "%s: seam pixels agree %.4f%%, the others %.4f%%", tech_names[t],
                     100.0 * seam_ok / (seam ? seam : 1), 100.0 * other_ok / (other ? other : 1));
        skgl_point_destroy(e.sk, p);
    }
    SK_CHECK(e.gl.GetError() == 0);
    free(ref); free(res);
    gt_env_free(&e);
}

/* ---- culling never removes a visible shadow ---- */
static uint32_t rng_state = 12345u;
static float frand(float lo, float hi) {
    rng_state = rng_state * 1664525u + 1013904223u;
    return lo + (hi - lo) * (float)(rng_state >> 8) / 16777216.0f;
}

static void test_culling_exhaustive(void) {
    gt_env e;
    float *a, *b;
    int t, k, trials = 16;
    if (env_init(&e) != 0) { gt_env_free(&e); return; }
    a = gt_alloc(&e); b = gt_alloc(&e);
    for (t = 0; t < 2; t++) {
        skgl_point *naive = make_point(&e, (skgl_point_technique)t, 256, 0);
        skgl_point *culled = make_point(&e, (skgl_point_technique)t, 256, 1);
        int faces_culled = 0, casters_culled = 0, diff_total = 0;
        if (!naive || !culled) continue;
        for (k = 0; k < trials; k++) {
            sk_vec3 lp, eye, dir;
            skgl_camera cam;
            size_t i;
            int diff = 0;
            float fov;
            lp = gt_v3(frand(-4.5f, 4.5f), frand(0.3f, 3.7f), frand(-4.5f, 4.5f));
            if (k == 0) lp = gt_v3(cage_light[0], cage_light[1], cage_light[2]);   /* inside the cage's box */
            eye = gt_v3(frand(-4.6f, 4.6f), frand(0.2f, 3.8f), frand(-4.6f, 4.6f));
            dir = gt_v3(frand(-1, 1), frand(-0.7f, 0.7f), frand(-1, 1));
            if (k % 2 == 1) dir = gt_v3(eye.x - lp.x, 0.3f * (eye.y - lp.y), eye.z - lp.z);   /* looking away */
            fov = frand(0.5f, 1.4f);
            cam = gt_camera(eye, gt_v3(eye.x + dir.x, eye.y + dir.y, eye.z + dir.z), fov, 0.05f, 30.0f, W, H);
            SK_CHECK(gt_gbuffer(&e, &cam) == 0);
            SK_CHECK(point_mask(&e, naive, &cam, lp, 1.0f, a) == 0);
            SK_CHECK(point_mask(&e, culled, &cam, lp, 1.0f, b) == 0);
            for (i = 0; i < e.n; i++) if (fabs(a[i] - b[i]) > 1e-3) diff++;
            faces_culled += skgl_point_stats(culled)->faces_culled;
            casters_culled += skgl_point_stats(culled)->casters_culled;
            diff_total += diff;
            if (diff) printf("cull %-5s trial %d: %d pixels differ (light %.2f %.2f %.2f)\n", tech_names[t], k, diff,
                             lp.x, lp.y, lp.z);
            SK_CHECK_MSG(diff == 0, "%s trial %d: culling changed %d pixels", tech_names[t], k, diff);
        }
        printf("cull %-5s: %d trials, %d faces and %d (face, caster) pairs culled, %d pixels differ\n", tech_names[t],
               trials, faces_culled, casters_culled, diff_total);
        SK_CHECK(faces_culled > 0 && casters_culled > 0);
        if (t == 0) {
            /* negative control: the wrong caster culling on the same kind
               of trials must change pixels, or this test could not see it */
            int wrong = 0;
            for (k = 0; k < trials; k++) {
                sk_vec3 lp = gt_v3(frand(-4.5f, 4.5f), frand(0.3f, 3.7f), frand(-4.5f, 4.5f));
                sk_vec3 eye = gt_v3(frand(-4.6f, 4.6f), frand(0.2f, 3.8f), frand(-4.6f, 4.6f));
                skgl_camera cam = gt_camera(eye, gt_v3(2 * eye.x - lp.x, eye.y, 2 * eye.z - lp.z), 1.0f, 0.05f, 30.0f,
                                            W, H);
                size_t i;
                wrong_cull_view = sk_frustum_from_matrix(sk_mat4_mul(cam.proj, cam.view));
                SK_CHECK(gt_gbuffer(&e, &cam) == 0);
                SK_CHECK(point_mask(&e, naive, &cam, lp, 1.0f, a) == 0);
                wrong_cull = 1;
                SK_CHECK(point_mask(&e, culled, &cam, lp, 1.0f, b) == 0);
                wrong_cull = 0;
                for (i = 0; i < e.n; i++) if (fabs(a[i] - b[i]) > 1e-3) wrong++;
            }
            printf("cull %-5s: the box-against-view culling changes %d pixels over %d trials\n", tech_names[t], wrong,
                   trials);
            SK_CHECK_MSG(wrong > 1000, "the wrong culling changed only %d pixels", wrong);
        }
        skgl_point_destroy(e.sk, naive);
        skgl_point_destroy(e.sk, culled);
    }
    SK_CHECK(e.gl.GetError() == 0);
    free(a); free(b);
    gt_env_free(&e);
}

/* ---- scissor ---- */
static void test_scissor(void) {
    gt_env e;
    float *full, *sc;
    int t;
    if (env_init(&e) != 0) { gt_env_free(&e); return; }
    full = gt_alloc(&e); sc = gt_alloc(&e);
    for (t = 0; t < 2; t++) {
        skgl_point_desc d;
        skgl_point *p = NULL, *q = NULL;
        sk_vec3 lp = gt_v3(0.5f, 1.2f, -1.0f);
        skgl_camera cam = gt_camera(gt_v3(0, 2.5f, 4.8f), gt_v3(0, 1, -5), 1.2f, 0.05f, 30.0f, W, H);
        const skgl_stats *st;
        size_t i;
        int outside = 0, outside_bad = 0, inside_bad = 0, x, y;
        memset(&d, 0, sizeof d);
        d.technique = (skgl_point_technique)t;
        d.resolution = 256;
        d.range = 2.0f;
        SK_CHECK(skgl_point_create(e.sk, &d, &p) == SK_OK);
        d.scissor = 1;
        SK_CHECK(skgl_point_create(e.sk, &d, &q) == SK_OK);
        if (!p || !q) continue;
        SK_CHECK(gt_gbuffer(&e, &cam) == 0);
        SK_CHECK(point_mask_raw(&e, p, &cam, lp, -3.0f, full, 1) == 0);
        SK_CHECK(point_mask_raw(&e, q, &cam, lp, -3.0f, sc, 1) == 0);
        st = skgl_point_stats(q);
        printf("scissor %-5s rect %d %d %d %d\n", tech_names[t], st->scissor[0], st->scissor[1], st->scissor[2],
               st->scissor[3]);
        SK_CHECK(st->scissor[2] > 0 && st->scissor[3] > 0 && st->scissor[2] * st->scissor[3] < W * H / 2);
        for (y = 0; y < H; y++)
            for (x = 0; x < W; x++) {
                int in = x >= st->scissor[0] && x < st->scissor[0] + st->scissor[2] && y >= st->scissor[1] &&
                         y < st->scissor[1] + st->scissor[3];
                i = (size_t)y * W + (size_t)x;
                if (!in) { outside++; outside_bad += sc[i] != -3.0f; }
                else inside_bad += sc[i] != full[i];
            }
        SK_CHECK_MSG(outside > 0 && outside_bad == 0, "%d of %d pixels outside the rect written", outside_bad, outside);
        SK_CHECK_MSG(inside_bad == 0, "%d pixels inside the rect differ from the unscissored mask", inside_bad);
        /* eye inside the range box: the whole viewport */
        cam = gt_camera(gt_v3(lp.x + 0.6f, lp.y + 0.3f, lp.z + 0.9f), gt_v3(0, 0.5f, -5), 1.2f, 0.05f, 30.0f, W, H);
        SK_CHECK(gt_gbuffer(&e, &cam) == 0);
        SK_CHECK(point_mask_raw(&e, q, &cam, lp, -3.0f, sc, 1) == 0);
        SK_CHECK_MSG(st->scissor[0] == 0 && st->scissor[1] == 0 && st->scissor[2] == W && st->scissor[3] == H,
                     "eye inside: rect %d %d %d %d", st->scissor[0], st->scissor[1], st->scissor[2], st->scissor[3]);
        for (i = 0, outside_bad = 0; i < e.n; i++) outside_bad += sc[i] == -3.0f;
        SK_CHECK_MSG(outside_bad == 0, "eye inside: %d pixels not written", outside_bad);
        /* the light's range wholly behind the eye: nothing written */
        cam = gt_camera(gt_v3(0, 2, -3.5f), gt_v3(0, 2, -5), 1.0f, 0.05f, 30.0f, W, H);
        SK_CHECK(gt_gbuffer(&e, &cam) == 0);
        SK_CHECK(point_mask_raw(&e, q, &cam, lp, -3.0f, sc, 1) == 0);
        for (i = 0, outside_bad = 0; i < e.n; i++) outside_bad += sc[i] != -3.0f;
        SK_CHECK_MSG(outside_bad == 0 && st->scissor[2] == 0, "behind: %d pixels written", outside_bad);
        skgl_point_destroy(e.sk, p);
        skgl_point_destroy(e.sk, q);
    }
    SK_CHECK(e.gl.GetError() == 0);
    free(full); free(sc);
    gt_env_free(&e);
}

/* ---- resolution selection: N M^2 >= c S ---- */
static void test_resolution_selection(void) {
    gt_env e;
    float *ref, *res;
    int t;
    if (env_init(&e) != 0) { gt_env_free(&e); return; }
    ref = gt_alloc(&e); res = gt_alloc(&e);
    for (t = 0; t < 2; t++) {
        skgl_point_desc d;
        skgl_point *p = NULL;
        sk_vec3 lp = gt_v3(0.3f, 0.8f, -4.0f);
        skgl_camera cam = gt_camera(gt_v3(0, 2.5f, 4.8f), gt_v3(0, 1, -5), 1.0f, 0.05f, 30.0f, W, H);
        const skgl_stats *st;
        int rect[4], expect;
        float s_pixels;
        tb_hard_error err;
        size_t i, bad = 0;
        memset(&d, 0, sizeof d);
        d.technique = (skgl_point_technique)t;
        d.resolution = 1024;
        d.range = 1.5f;
        d.cull_faces = d.cull_casters = d.scissor = d.select_resolution = 1;
        d.screen_w = W;
        d.screen_h = H;
        SK_CHECK(skgl_point_create(e.sk, &d, &p) == SK_OK);
        if (!p) continue;
        SK_CHECK(gt_gbuffer(&e, &cam) == 0);
        SK_CHECK(point_mask(&e, p, &cam, lp, 1.0f, res) == 0);
        st = skgl_point_stats(p);
        SK_CHECK(sk_light_scissor(lp, d.range, sk_mat4_mul(cam.proj, cam.view), W, H, rect) == 1);
        s_pixels = (float)rect[2] * (float)rect[3];
        expect = sk_cube_resolution(st->faces_rendered, s_pixels, 2.0f, 1024);
        {
            tb_view v;
            tb_light l;
            memset(&l, 0, sizeof l);
            l.type = TB_LIGHT_POINT;
            l.position = lp;
            l.range = d.range;
            v.inv_view_proj = e.inv_vp; v.width = W; v.height = H;
            SK_CHECK(tb_reference_trace(e.ref, &v, e.depth, e.normals, &l, NULL, ref) == 0);
        }
        err = tb_metric_hard(ref, res, e.n);
        for (i = 0; i < e.n; i++) bad += !(res[i] >= -1.0f && res[i] <= 1.0f);
        printf("select %-5s S %.0f faces %d -> M %d (expected %d), texels %.0f, err %.3f%% of %llu\n", tech_names[t],
               s_pixels, st->faces_rendered, st->resolution, expect, st->texels, err.pct,
               (unsigned long long)err.covered);
        SK_CHECK(st->resolution == expect && expect < 1024);
        SK_CHECK((double)st->faces_rendered * st->resolution * st->resolution >= 2.0 * s_pixels);
        SK_CHECK(bad == 0);
        skgl_point_destroy(e.sk, p);
    }
    SK_CHECK(e.gl.GetError() == 0);
    free(ref); free(res);
    gt_env_free(&e);
}

/* ---- the forward path: skgl_point_glsl_snippet() in a forward shader ---- */
static const char fwd_fs[] =
    "in vec3 v_world;\n"
    "in vec3 v_normal;\n"
    "in float v_view_depth;\n"
    "out float o_visibility;\n"
    "void main() {\n"
    "    vec3 n = normalize(v_normal);\n"
    "    o_visibility = sk_point_shadow(v_world, gl_FrontFacing ? n : -n);\n"
    "}\n";

static void test_forward(void) {
    gt_env e;
    float *mask, *fwd, *fdepth;
    sk_vec3 lp = gt_v3(-0.2f, 2.0f, 0.1f);
    skgl_camera cam = gt_camera(gt_v3(4.2f, 3.6f, 4.2f), gt_v3(-2, 0.5f, -2), 1.3f, 0.05f, 30.0f, W, H);
    int t;
    if (env_init(&e) != 0) { gt_env_free(&e); return; }
    mask = gt_alloc(&e); fwd = gt_alloc(&e); fdepth = gt_alloc(&e);
    SK_CHECK(gt_gbuffer(&e, &cam) == 0);
    for (t = 0; t < 2; t++) {
        const tb_gl_funcs *gl = &e.gl;
        const char *vs[1], *fs[4];
        unsigned v, g, prog;
        int ok = 0;
        size_t i, both = 0, agree = 0;
        tb_gl_fbo fbo;
        sk_mat4 vp = sk_mat4_mul(cam.proj, cam.view);
        skgl_point *p = make_point(&e, (skgl_point_technique)t, 256, 1);
        sk_result r;
        if (!p) continue;
        SK_CHECK(point_mask(&e, p, &cam, lp, 1.0f, mask) == 0);
        vs[0] = gt_forward_vs;
        fs[0] = "#version 330 core\n";
        fs[1] = t ? "#define SK_POINT_VSDCT 1\n" : "";
        fs[2] = skgl_point_glsl_snippet();
        fs[3] = fwd_fs;
        v = gt_compile(gl, 0x8B31, 1, vs);
        g = gt_compile(gl, 0x8B30, 4, fs);
        SK_CHECK(v && g);
        prog = gl->CreateProgram();
        gl->AttachShader(prog, v);
        gl->AttachShader(prog, g);
        gl->LinkProgram(prog);
        gl->DeleteShader(v);
        gl->DeleteShader(g);
        gl->GetProgramiv(prog, 0x8B82, &ok);
        SK_CHECK(ok);
        SK_CHECK(tb_gl_fbo_create(gl, &fbo, W, H, TB_GL_COLOR_R16F) == 0);
        tb_gl_fbo_bind(gl, &fbo);
        gl->ClearColor(-1.0f, 0, 0, 0);
        gl->ClearDepth(1.0);
        gl->Clear(0x00004000u | 0x00000100u);
        gl->Enable(0x0B71);
        gl->DepthFunc(0x0201);
        /* as skgl_point_bind documents: seamless filtering on for the cube, off for VSDCT */
        if (t) gl->Disable(0x884F); else gl->Enable(0x884F);
        gl->UseProgram(prog);
        gl->UniformMatrix4fv(gl->GetUniformLocation(prog, "u_view_proj"), 1, 0, vp.m);
        gl->UniformMatrix4fv(gl->GetUniformLocation(prog, "u_view"), 1, 0, cam.view.m);
        r = skgl_point_bind(e.sk, p, prog, 4);
        SK_CHECK_MSG(r == SK_OK, "skgl_point_bind: %s (%s)", sk_result_string(r), skgl_error_log(e.sk));
        tb_gl_mesh_draw(gl, &e.mesh, 0, 0);
        gl->UseProgram(0);
        gl->Disable(0x884F);
        tb_gl_fbo_bind(gl, NULL);
        SK_CHECK(tb_gl_read_red(gl, fbo.fbo, W, H, fwd) == 0);
        SK_CHECK(tb_gl_read_depth(gl, fbo.fbo, W, H, fdepth) == 0);
        for (i = 0; i < e.n; i++) {
            if (!(fdepth[i] < 1.0f) || mask[i] < 0.0f) continue;
            both++;
            agree += tb_visibility_class(fwd[i]) == tb_visibility_class(mask[i]);
        }
        printf("forward %-5s: %llu pixels, %.4f%% agree with the mask\n", tech_names[t], (unsigned long long)both,
               100.0 * agree / (both ? both : 1));
        SK_CHECK_MSG(both > e.n / 2 && 100.0 * agree / (both ? both : 1) >= 99.0,
                     "%s: forward agrees with the mask on %.4f%%", tech_names[t], 100.0 * agree / (both ? both : 1));
        gl->DeleteProgram(prog);
        tb_gl_fbo_destroy(gl, &fbo);
        skgl_point_destroy(e.sk, p);
    }
    SK_CHECK(e.gl.GetError() == 0);
    free(mask); free(fwd); free(fdepth);
    gt_env_free(&e);
}

/* ---- bad input ---- */
static void test_invalid(void) {
    gt_env e;
    skgl_point_desc d, bad;
    skgl_point *p = NULL;
    skgl_scene sc;
    skgl_camera cam;
    int k, before;
    if (env_init(&e) != 0) { gt_env_free(&e); return; }
    before = skgl_gl_object_count(e.sk);
    memset(&d, 0, sizeof d);
    d.range = RANGE;
    for (k = 0; k < 9; k++) {
        bad = d;
        switch (k) {
        case 0: bad.technique = (skgl_point_technique)7; break;
        case 1: bad.resolution = -4; break;
        case 2: bad.near_plane = -1.0f; break;
        case 3: bad.range = 0.01f; break;
        case 4: bad.range = NAN; break;
        case 5: bad.pcf_radius = 9; break;
        case 6: bad.select_resolution = 1; bad.resolution = 300; break;
        case 7: bad.resolution = 1 << 20; break;
        default: bad.resolution_c = -2.0f; break;
        }
        p = NULL;
        SK_CHECK_MSG(skgl_point_create(e.sk, &bad, &p) == SK_ERR_INVALID_ARG && p == NULL, "case %d", k);
    }
    SK_CHECK(skgl_point_create(e.sk, NULL, &p) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_point_create(e.sk, &d, NULL) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_gl_object_count(e.sk) == before);
    SK_CHECK(skgl_point_create(e.sk, &d, &p) == SK_OK);
    cam = gt_camera(gt_v3(0, 2, 4), gt_v3(0, 1, 0), 1.0f, 0.05f, 30.0f, W, H);
    sc = gt_scene(&e);
    SK_CHECK(skgl_point_mask(e.sk, p, &cam, e.gbuf.depth_tex, 0, e.mask.color_tex) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_point_render(e.sk, p, &cam, &sc, gt_v3(NAN, 0, 0)) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_point_render(e.sk, p, NULL, &sc, gt_v3(0, 2, 0)) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_point_render(NULL, p, &cam, &sc, gt_v3(0, 2, 0)) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_point_caster_visible(NULL, gt_box(0, 0, 0, 1, 1, 1)) == 1);
    SK_CHECK(skgl_point_render(e.sk, p, &cam, &sc, gt_v3(0, 2, 0)) == SK_OK);
    SK_CHECK(skgl_point_mask(e.sk, p, &cam, 0, 0, e.mask.color_tex) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_point_bind(e.sk, p, 0, 0) == SK_ERR_INVALID_ARG);
    skgl_point_destroy(e.sk, p);
    SK_CHECK(skgl_gl_object_count(e.sk) == before);
    SK_CHECK(e.gl.GetError() == 0);
    gt_env_free(&e);
}

SK_TEST_MAIN(test_faces, test_seams, test_culling_exhaustive, test_scissor, test_resolution_selection, test_forward,
             test_invalid)
