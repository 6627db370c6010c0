/* test_gl_testbed.c - smoke test of the machinery every GL test stands on
   (no shadowkit_gl.h code runs here): an OSMesa GL 3.3 core context, the
   testbed's FBO and G-buffer, and tiny Embree reference cases whose answer
   is known in closed form: the legacy reference (tb_reference_trace_points,
   tb_reference_trace) and the exact one every GL test scores against
   (tb_reference_trace_exact: back-facing receivers and silhouette pixels
   left out, counted in tb_ref_stats). If this fails, the other GL tests'
   failures say nothing about shadowkit. */
#define SHADOWKIT_IMPLEMENTATION
#include "shadowkit.h"
#include "sk_test.h"

#include <stdlib.h>

#include "tb_gl_context.h"
#include "tb_gl_fbo.h"
#include "tb_gl_funcs.h"
#include "tb_gl_scene.h"
#include "tb_metrics.h"
#include "tb_reference.h"
#include "tb_scene.h"

static sk_vec3 v3(float x, float y, float z) { sk_vec3 r; r.x = x; r.y = y; r.z = z; return r; }

/* The context: OSMesa forced (what CI has), GL >= 3.3 core, the testbed's
   entry points load, an RGBA8 FBO clears and reads back. */
static void test_context(void) {
    char err[512] = "";
    tb_gl_context *ctx = tb_gl_context_create(TB_GL_OSMESA, err, sizeof err);
    tb_gl_funcs gl;
    tb_gl_fbo fbo;
    unsigned char rgba[4 * 4 * 4];
    int major = 0, minor = 0, core = 0;
    SK_CHECK_MSG(ctx != NULL, "OSMesa context: %s", err);
    if (!ctx) return;
    tb_gl_context_gl_version(ctx, &major, &minor, &core);
    printf("context: %s | %s | %s\n", tb_gl_context_backend_name(ctx), tb_gl_context_renderer(ctx),
           tb_gl_context_version(ctx));
    SK_CHECK_MSG(major > 3 || (major == 3 && minor >= 3), "GL %d.%d", major, minor);
    SK_CHECK(core);
    SK_CHECK(tb_gl_funcs_load(&gl, tb_gl_context_getproc(ctx)) == 0);
    SK_CHECK(tb_gl_context_getproc(ctx)("glGenQueries") != NULL);   /* timer queries, GL 3.3 */
    if (tb_gl_fbo_create(&gl, &fbo, 4, 4, TB_GL_COLOR_RGBA8) == 0) {
        tb_gl_fbo_bind(&gl, &fbo);
        gl.ClearColor(1.0f, 0.5f, 0.0f, 1.0f);
        gl.Clear(0x00004000u);
        SK_CHECK(tb_gl_read_rgba8(&gl, fbo.fbo, 4, 4, rgba) == 0);
        SK_CHECK(rgba[20] == 255 && abs(rgba[21] - 128) <= 1 && rgba[22] == 0 && rgba[23] == 255);
        tb_gl_fbo_bind(&gl, NULL);
        tb_gl_fbo_destroy(&gl, &fbo);
    } else {
        SK_CHECK_MSG(0, "FBO creation failed");
    }
    SK_CHECK(gl.GetError() == 0);
    tb_gl_context_destroy(ctx);
}

/* Embree on the "contact" scene (box [-1,0,-1]..[1,1,1] on the ground), sun
   straight down: points under the box's footprint are shadowed, points
   outside it lit, the box top is lit. */
static void test_reference_points(void) {
    tb_scene s;
    tb_reference *ref;
    tb_light sun;
    const double pts[5 * 3] = {0, 0, 0,  0.9, 0, -0.9,  1.1, 0, 0,  5, 0, 5,  0, 1, 0};
    const double nrm[5 * 3] = {0, 1, 0,  0, 1, 0,  0, 1, 0,  0, 1, 0,  0, 1, 0};
    const float want[5] = {0, 0, 1, 1, 1};
    float vis[5];
    int i;
    tb_scene_init(&s);
    SK_CHECK(tb_scene_build_contact(&s) == 0);
    ref = tb_reference_create(&s);
    SK_CHECK(ref != NULL);
    if (!ref) { tb_scene_free(&s); return; }
    memset(&sun, 0, sizeof sun);
    sun.type = TB_LIGHT_DIRECTIONAL;
    sun.direction = v3(0, -1, 0);
    SK_CHECK(tb_reference_trace_points(ref, pts, nrm, 5, &sun, NULL, vis) == 0);
    for (i = 0; i < 5; i++) SK_CHECK_MSG(vis[i] == want[i], "point %d: %g, expected %g", i, vis[i], want[i]);
    tb_reference_destroy(ref);
    tb_scene_free(&s);
}

/* The same-face test (tb_ref_options.raster_normals): with the G-buffer's
   own normals, or the same negated (the test ignores the sign), a pixel
   changes only by becoming TB_VIS_SILHOUETTE, on fewer than 0.5% of the
   image (measured 0 on this view); with the normals of the upward faces
   (ground, box top) turned to +z every such pixel is left out, the others
   are as before. vis: the trace without normals. */
static void same_face_rule(const tb_reference *ref, const tb_view *view, const float *depth, const float *nrm,
                           const tb_light *sun, const float *vis) {
    size_t n = (size_t)view->width * (size_t)view->height, i;
    float *vn = (float *)malloc(sizeof(float) * n), *turned = (float *)malloc(sizeof(float) * 3 * n);
    long changed = 0, other = 0, up = 0, up_kept = 0, rest_changed = 0;
    tb_ref_options opt;
    memset(&opt, 0, sizeof opt);
    if (!vn || !turned) { SK_CHECK(0); free(vn); free(turned); return; }
    opt.raster_normals = nrm;
    SK_CHECK(tb_reference_trace_exact(ref, view, depth, sun, &opt, vn, NULL) == 0);
    for (i = 0; i < n; i++)
        if (vn[i] != vis[i]) { changed++; other += vn[i] != TB_VIS_SILHOUETTE; }
    for (i = 0; i < 3 * n; i++) turned[i] = -nrm[i];
    opt.raster_normals = turned;
    SK_CHECK(tb_reference_trace_exact(ref, view, depth, sun, &opt, vn, NULL) == 0);
    for (i = 0; i < n; i++)
        if (vn[i] != vis[i]) { changed++; other += vn[i] != TB_VIS_SILHOUETTE; }
    memcpy(turned, nrm, sizeof(float) * 3 * n);
    for (i = 0; i < n; i++)
        if (nrm[3 * i + 1] > 0.9f) { turned[3 * i] = 0.0f; turned[3 * i + 1] = 0.0f; turned[3 * i + 2] = 1.0f; }
    opt.raster_normals = turned;
    SK_CHECK(tb_reference_trace_exact(ref, view, depth, sun, &opt, vn, NULL) == 0);
    for (i = 0; i < n; i++) {
        if (!(depth[i] < 1.0f)) continue;
        if (nrm[3 * i + 1] > 0.9f) { up++; up_kept += vn[i] != TB_VIS_SILHOUETTE; }
        else rest_changed += vn[i] != vis[i] && vn[i] != TB_VIS_SILHOUETTE;
    }
    printf("same-face test: %ld px left out with the G-buffer's normals and negated (%ld otherwise changed); upward faces "
           "turned: %ld of %ld kept, %ld others changed\n", changed, other, up_kept, up, rest_changed);
    SK_CHECK_MSG(other == 0 && changed * 200 < (long)n, "%ld changed, %ld not to silhouette", changed, other);
    SK_CHECK_MSG(up > 1000 && up_kept == 0 && rest_changed == 0, "upward %ld, kept %ld, others changed %ld", up,
                 up_kept, rest_changed);
    free(vn);
    free(turned);
}

/* G-buffer + reference together at 160 x 90 on the contact scene, seen
   from above at an angle, the sun 45 degrees from +x: the box's shadow on
   the ground is its footprint sheared 1 m toward +x. Ground pixels well
   inside that region are shadowed, ground on the far side of the box and
   the box top are lit, background pixels are "not covered". The box's +z
   side, the one the camera sees, is edge-on to the light (dot(n, to_light)
   = 0): the legacy reference (tb_reference_trace with the normals) calls
   it shadowed, the exact one (tb_reference_trace_exact with the raster
   depth) leaves it out as TB_VIS_BACKFACING. The exact trace's counts
   partition the image and match the pixels it returns; its silhouette
   pixels (raster and traced surfaces differ) lie on the box's outline and
   the ground's far edge only: fewer than 1% of the image. */
static void gbuffer_reference(int exact) {
    const int W = 160, H = 90;
    char err[512] = "";
    tb_gl_context *ctx = tb_gl_context_create(TB_GL_OSMESA, err, sizeof err);
    tb_gl_funcs gl;
    tb_gl_fbo fbo;
    tb_gl_mesh mesh;
    tb_gl_gbuffer gb;
    tb_scene s;
    tb_reference *ref = NULL;
    tb_view view;
    tb_light sun;
    sk_mat4 v, p, vp;
    float *depth = (float *)malloc(sizeof(float) * W * H);
    float *rgba = (float *)malloc(sizeof(float) * 4 * W * H);
    float *nrm = (float *)malloc(sizeof(float) * 3 * W * H);
    float *vis = (float *)malloc(sizeof(float) * W * H);
    long i, covered = 0, shadow_ground = 0, lit_top = 0, top = 0, bad = 0, far_ground = 0, side = 0, side_bad = 0;
    long counted[5] = {0, 0, 0, 0, 0};   /* vis >= 0, background, out of range, back-facing, silhouette */
    tb_ref_stats stats;
    const char *name = exact ? "exact" : "legacy";
    memset(&stats, 0, sizeof stats);
    tb_scene_init(&s);
    SK_CHECK_MSG(ctx != NULL, "OSMesa context: %s", err);
    if (!ctx || !depth || !rgba || !nrm || !vis) goto done;
    SK_CHECK(tb_gl_funcs_load(&gl, tb_gl_context_getproc(ctx)) == 0);
    SK_CHECK(tb_scene_build_contact(&s) == 0);
    SK_CHECK(tb_gl_fbo_create(&gl, &fbo, W, H, TB_GL_COLOR_RGBA16F) == 0);
    SK_CHECK(tb_gl_mesh_create(&gl, &mesh, &s) == 0);
    SK_CHECK_MSG(tb_gl_gbuffer_create(&gl, &gb, err, sizeof err) == 0, "gbuffer: %s", err);
    v = sk_mat4_look_at(v3(0, 6, 6), v3(0, 0, 0), v3(0, 1, 0));
    p = sk_mat4_perspective(0.9f, (float)W / (float)H, 0.5f, 50.0f);
    vp = sk_mat4_mul(p, v);
    memset(&view, 0, sizeof view);
    SK_CHECK(sk_mat4_inverse(vp, &view.inv_view_proj));
    view.width = W;
    view.height = H;
    SK_CHECK(tb_gl_gbuffer_render(&gl, &gb, &mesh, &fbo, &vp) == 0);
    SK_CHECK(tb_gl_read_depth(&gl, fbo.fbo, W, H, depth) == 0);
    SK_CHECK(tb_gl_read_rgba_float(&gl, fbo.fbo, W, H, rgba) == 0);
    for (i = 0; i < (long)W * H; i++) {
        nrm[3 * i] = rgba[4 * i]; nrm[3 * i + 1] = rgba[4 * i + 1]; nrm[3 * i + 2] = rgba[4 * i + 2];
        if (depth[i] < 1.0f) covered++;
    }
    SK_CHECK_MSG(covered > (long)W * H / 2, "covered %ld", covered);
    ref = tb_reference_create(&s);
    SK_CHECK(ref != NULL);
    if (!ref) goto done;
    memset(&sun, 0, sizeof sun);
    sun.type = TB_LIGHT_DIRECTIONAL;
    /* 45 degrees from +x: the shadow is the footprint sheared 1 m toward +x */
    sun.direction = v3(1, -1, 0);
    if (exact)
        SK_CHECK(tb_reference_trace_exact(ref, &view, depth, &sun, NULL, vis, &stats) == 0);
    else
        SK_CHECK(tb_reference_trace(ref, &view, depth, nrm, &sun, NULL, vis) == 0);
    for (i = 0; i < (long)W * H; i++) {
        double w[3];
        int k = vis[i] >= 0.0f ? 0 : vis[i] == TB_VIS_BACKGROUND ? 1 : vis[i] == TB_VIS_OUT_OF_RANGE ? 2
              : vis[i] == TB_VIS_BACKFACING ? 3 : vis[i] == TB_VIS_SILHOUETTE ? 4 : -1;
        if (k < 0) bad++; else counted[k]++;
        if (!(depth[i] < 1.0f)) { if (!(vis[i] < 0.0f)) bad++; continue; }
        if (exact && vis[i] == TB_VIS_SILHOUETTE) continue;      /* outline pixels: no closed-form class */
        if (tb_unproject_pixel(&view.inv_view_proj, W, H, (int)(i % W), (int)(i / W), depth[i], w)) continue;
        if (nrm[3 * i + 2] > 0.9f && w[1] > 0.05 && w[1] < 0.95 && fabs(w[0]) < 0.95) {   /* the +z side */
            side++;
            if (vis[i] != (exact ? TB_VIS_BACKFACING : 0.0f)) side_bad++;
        }
        if (nrm[3 * i + 1] < 0.9f) continue;                     /* box sides */
        if (w[1] > 0.95) { top++; if (vis[i] == 1.0f) lit_top++; }
        if (w[1] < 0.01 && w[0] > 1.05 && w[0] < 1.95 && fabs(w[2]) < 0.95) {
            shadow_ground++;
            if (vis[i] != 0.0f) bad++;
        }
        if (w[1] < 0.01 && w[0] < -1.05) { far_ground++; if (vis[i] != 1.0f) bad++; }
    }
    printf("gbuffer+reference (%s): %ld covered, box top %ld (lit %ld), ground in the shadow %ld, "
           "ground beyond the box %ld, +z side %ld (wrong %ld), wrong %ld; returned: %ld >= 0, %ld background, "
           "%ld back-facing, %ld silhouette\n", name, covered, top, lit_top, shadow_ground, far_ground, side,
           side_bad, bad, counted[0], counted[1], counted[3], counted[4]);
    SK_CHECK_MSG(top > 100 && lit_top == top, "%s: box top %ld, lit %ld", name, top, lit_top);
    SK_CHECK(shadow_ground > 100 && far_ground > 100);
    SK_CHECK_MSG(bad == 0, "%s: %ld pixels disagree with the closed-form answer", name, bad);
    SK_CHECK_MSG(side > 100 && side_bad == 0, "%s: %ld of %ld pixels of the +z side not %s", name, side_bad, side,
                 exact ? "back-facing" : "shadowed");
    SK_CHECK(gl.GetError() == 0);
    {
        tb_hard_error e = tb_metric_hard(vis, vis, (size_t)W * H);
        SK_CHECK(e.wrong == 0 && e.covered == (uint64_t)counted[0]);
        if (!exact) SK_CHECK(e.covered == (uint64_t)covered);
    }
    if (exact) {
        SK_CHECK(stats.pixels == (uint64_t)W * H &&
                 stats.covered + stats.background + stats.backfacing + stats.silhouette + stats.out_of_range ==
                     stats.pixels);
        SK_CHECK_MSG(stats.covered == (uint64_t)counted[0] && stats.background == (uint64_t)counted[1] &&
                         stats.out_of_range == 0 && counted[2] == 0 && stats.backfacing == (uint64_t)counted[3] &&
                         stats.silhouette == (uint64_t)counted[4],
                     "stats %llu %llu %llu %llu against the image's %ld %ld %ld %ld",
                     (unsigned long long)stats.covered, (unsigned long long)stats.background,
                     (unsigned long long)stats.backfacing, (unsigned long long)stats.silhouette, counted[0],
                     counted[1], counted[3], counted[4]);
        SK_CHECK_MSG(stats.silhouette * 100 < stats.pixels, "%llu silhouette pixels",
                     (unsigned long long)stats.silhouette);
        SK_CHECK(stats.backfacing >= (uint64_t)side);
        same_face_rule(ref, &view, depth, nrm, &sun, vis);
    }
done:
    tb_reference_destroy(ref);
    if (ctx) {
        tb_gl_gbuffer_destroy(&gl, &gb);
        tb_gl_mesh_destroy(&gl, &mesh);
        tb_gl_fbo_destroy(&gl, &fbo);
        tb_gl_context_destroy(ctx);
    }
    tb_scene_free(&s);
    free(depth); free(rgba); free(nrm); free(vis);
}

static void test_gbuffer_reference(void) { gbuffer_reference(0); }
static void test_gbuffer_reference_exact(void) { gbuffer_reference(1); }

SK_TEST_MAIN(test_context, test_reference_points, test_gbuffer_reference, test_gbuffer_reference_exact)
