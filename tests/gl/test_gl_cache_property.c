/* test_gl_cache_property.c - cached maps (CACHED MAPS) against uncached
   ones under random frame sequences, and the drift of changes too small
   to see one frame at a time.

   Scene: "ground-boxes" plus a 0.8 m "mover" box, 192 x 108. Lights:
   STANDARD stable, STANDARD focused, PSSM-4 stable, LiSPSM (512 a
   layer), RMSM (2048 virtual, 64-texel pages, sync_readback, analysed
   every frame), point cube and VSDCT (128 a face, face and caster culling).
   Each cached light runs with .verify_cache = 1 beside an uncached one:
   for the directional lights its twin (the same desc,
   skgl_shadow_invalidate(NULL) before every render: every layer drawn
   whole with this frame's matrix; a .cache 0 stable crop takes another
   depth range, CACHED MAPS), for RMSM and the points a .cache 0 light.

   property  3 seeds x 80 frames per light. Each frame, at random: the
             camera walks (5-40 cm), jumps, creeps (0.1-0.9 mm) or stands;
             the light turns fast (0.005-0.05 rad; a point light moves
             2-30 cm), slowly (5e-7 rad; 1e-5 m) or not; box0 (drawn by
             scene.draw) moves with its old and new boxes invalidated;
             box3 disappears or comes back, invalidated; the mover (the
             dynamic casters) comes, goes, moves, with or without its
             bounds. Compared every frame: the masks (pixels whose shadow
             class differs, and pixels whose value differs at all), every
             render SK_OK (verify_cache accepts correct use), and for RMSM
             each page's texels in the cached light's slot against the
             uncached light's, bit for bit.
   drift     a sun turning 5e-7 rad a frame (144 fps) for 3000 frames:
             STANDARD and PSSM-4 stable, 256 a layer; and a focused
             STANDARD under a camera creeping 0.1 mm a frame. The masks
             compared every 250th frame; the layers must be redrawn as the
             change adds up (stats.cache_full).
   walk300   the walk with verify_cache: 300 frames of a camera
             walking 5 cm a frame, STANDARD and PSSM-4 stable, 512:
             every render SK_OK.

   Measured (Mesa 22.3 llvmpipe), 3 x 80 frames per light: pixels
   differing from the uncached mask by class 0, by value 0 (asserted 0:
   a layer is kept only while it is within 1e-3 texel and 1e-6 in depth
   of this frame's map, skgl__cache_shift, far under the rasterizer's
   1/256 texel subpixel grid), but RMSM's by value, 10848 of 4.1M by one
   R16F ulp (2^-11, asserted; why at the assertion); verify_cache failed
   0 frames; RMSM page texels differing from the uncached slots 0. Drift:
   the kept layer at most 1.8e-4 texel (sun) and 1.1e-3 texel (creep)
   from this frame's map (asserted <= 5e-3), layers drawn whole 214
   (STANDARD) and 821 (PSSM-4) of 3000 frames. walk300: 0 failures.
   Can fail: against the header before the fix (the cache compared with
   last frame's matrix, verify_cache at 1e-6 with no neighbour test, RMSM
   pages drawn in their slots): walk300 failed 211 / 126 of 300 frames
   (STANDARD / PSSM-4); drift: no layer drawn whole in 3000 frames, the
   kept layer 0.039 texel (sun) and 0.0062 texel (creep) from this
   frame's map, verify_cache failed 2998 / 2998 / 1060 frames; property:
   verify_cache failed 69 (STANDARD), 2 (focused), 70 (PSSM-4) frames of
   correct use; RMSM page texels differing 14,017,094. (The masks did
   not yet differ after 3000 frames at 256: 6000 frames at 1024 gave 85
   pixels by value for PSSM-4, too slow to keep.) Point lights had no
   .verify_cache (the test did not compile).

   HYGIENE. Under the sanitizers (build/hygiene/, __SANITIZE_ADDRESS__) the
   property runs 1 seed and the drift 600 frames: measured with gcov, both
   reach the same 2576 lines of shadowkit_gl.h as 3 seeds and 3000 frames
   (none fewer, none more), in 47 CPU s instead of 100-118; their checks
   (1667 there, 5013 here) are this file's, once per frame fewer. */
/* reads a light's cache internals (the kept layer's matrix): its own copy of the implementation */
#define SK_TEST_OWN_IMPLEMENTATION 1
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "sk_test.h"
#include "gl_test_util.h"

#define W 192
#define H 108
#define FRAMES 80
/* under the sanitizers, fewer frames over the same lines (HYGIENE above);
   the plain build keeps the figures' power to fail */
#ifdef __SANITIZE_ADDRESS__
#define SEEDS 1
#define DRIFT_FRAMES 600
#else
#define SEEDS 3
#define DRIFT_FRAMES 3000
#endif

typedef gt_movers world;

static world W_;

/* xorshift32: the same frames for a seed on every machine */
static unsigned rnd_state;
static float rnd(void) {
    rnd_state ^= rnd_state << 13;
    rnd_state ^= rnd_state >> 17;
    rnd_state ^= rnd_state << 5;
    return (float)(rnd_state >> 8) / 16777216.0f;
}
static float rnd_in(float a, float b) { return a + (b - a) * rnd(); }

typedef enum { L_STANDARD, L_FOCUSED, L_PSSM, L_LISPSM, L_RMSM, L_CUBE, L_VSDCT, N_LIGHTS } light_kind;
static const char *light_name[N_LIGHTS] = {"standard-stable", "standard-focused", "pssm4-stable", "lispsm",
                                           "rmsm", "point-cube", "point-vsdct"};

/* a cached light and its uncached counterpart */
typedef struct pair {
    light_kind kind;
    skgl_shadow *s[2];   /* [0] cached, [1] uncached */
    skgl_point *p[2];
} pair;

static int is_point(light_kind k) { return k == L_CUBE || k == L_VSDCT; }

static int pair_create(world *w, light_kind k, int res, pair *pr) {
    int i;
    memset(pr, 0, sizeof *pr);
    pr->kind = k;
    for (i = 0; i < 2; i++) {
        if (is_point(k)) {
            skgl_point_desc d;
            sk_result r;
            memset(&d, 0, sizeof d);
            d.technique = k == L_CUBE ? SKGL_POINT_CUBE : SKGL_POINT_VSDCT;
            d.resolution = res;
            d.range = 16;
            d.cull_faces = 1;
            d.cull_casters = 1;
            d.cache = i == 0;
            d.verify_cache = i == 0;
            gt_point_bias(&d);
            r = skgl_point_create(w->e.sk, &d, &pr->p[i]);
            SK_CHECK_MSG(r == SK_OK, "skgl_point_create: %s (%s)", sk_result_string(r), skgl_error_log(w->e.sk));
            if (r != SK_OK) return -1;
        } else {
            skgl_shadow_desc d;
            memset(&d, 0, sizeof d);
            d.technique = k == L_PSSM ? SKGL_PSSM : k == L_LISPSM ? SKGL_LISPSM : k == L_RMSM ? SKGL_RMSM
                                                                                        : SKGL_STANDARD;
            d.resolution = res;
            d.stable = k == L_STANDARD || k == L_PSSM;
            d.cascades = k == L_PSSM ? 4 : 1;
            d.max_distance = 40;
            d.cache = i == 0 || k != L_RMSM;   /* the directional twin is cached, invalidated every frame */
            d.verify_cache = i == 0;
            if (k == L_RMSM) {
                d.rmsm_page_size = 64;
                d.sync_readback = 1;
                /* the finer pages' slots set alike: by default a cached
                   light's band takes half the pool, an uncached one's all */
                d.rmsm_band_pages = 288;
            }
            pr->s[i] = gt_shadow(&w->e, &d);
            if (!pr->s[i]) return -1;
        }
    }
    return 0;
}

static void pair_destroy(world *w, pair *pr) {
    int i;
    for (i = 0; i < 2; i++) {
        if (pr->s[i]) skgl_shadow_destroy(w->e.sk, pr->s[i]);
        if (pr->p[i]) skgl_point_destroy(w->e.sk, pr->p[i]);
    }
}

static void pair_invalidate(world *w, pair *pr, const sk_aabb *b) {
    if (pr->s[0]) SK_CHECK(skgl_shadow_invalidate(w->e.sk, pr->s[0], b) == SK_OK);
    if (pr->p[0]) SK_CHECK(skgl_point_invalidate(w->e.sk, pr->p[0], b) == SK_OK);
}

/* light i of the pair rendered and its mask read back (-1 on background);
   the render's result into *rr. 0: a mask. */
static int pair_mask(world *w, pair *pr, int i, const skgl_camera *cam, const skgl_scene *sc, sk_vec3 dir,
                     sk_vec3 pos, float *out, sk_result *rr) {
    sk_result r;
    size_t k;
    if (is_point(pr->kind)) {
        r = skgl_point_render(w->e.sk, pr->p[i], cam, sc, pos);
        *rr = r;
        if (r != SK_OK) printf("  %s: %s\n", light_name[pr->kind], skgl_error_log(w->e.sk));
        if (r != SK_OK && r != SK_ERR_INVALID_ARG) return -1;
        if (skgl_point_mask(w->e.sk, pr->p[i], cam, w->e.gbuf.depth_tex, w->e.gbuf.color_tex,
                            w->e.mask.color_tex) != SK_OK)
            return -1;
        if (tb_gl_read_texture_red(&w->e.gl, w->e.mask.color_tex, w->e.w, w->e.h, out) != 0) return -1;
        for (k = 0; k < w->e.n; k++) if (!(w->e.depth[k] < 1.0f)) out[k] = -1.0f;
        return 0;
    }
    if (i == 1 && pr->kind != L_RMSM) SK_CHECK(skgl_shadow_invalidate(w->e.sk, pr->s[1], NULL) == SK_OK);
    r = pr->kind == L_RMSM ? skgl_shadow_analyze(w->e.sk, pr->s[i], cam, sc, dir, w->e.gbuf.depth_tex) : SK_OK;
    if (r == SK_OK) r = skgl_shadow_render(w->e.sk, pr->s[i], cam, sc, dir);
    *rr = r;
    if (r != SK_OK) printf("  %s: %s\n", light_name[pr->kind], skgl_error_log(w->e.sk));
    if (r != SK_OK && r != SK_ERR_INVALID_ARG) return -1;   /* verify_cache's failure still leaves the maps */
    return gt_mask_only(&w->e, pr->s[i], cam, out);
}

/* RMSM: texels of this frame's pages whose depth in the cached light's
   slot differs (bitwise) from the uncached light's; -1 when the two
   lights did not draw the same pages */
static long rmsm_page_texels(world *w, pair *pr) {
    skgl_shadow *a = pr->s[0], *b = pr->s[1];
    int i, slot = a->desc.rmsm_page_size + 2;
    size_t n = (size_t)slot * (size_t)slot, k;
    float *da = (float *)malloc(n * sizeof *da), *db = (float *)malloc(n * sizeof *db);
    long differ = 0;
    const tb_gl_funcs *gl = &w->e.gl;
    if (!da || !db || a->rmsm.npages != b->rmsm.npages) { free(da); free(db); return -1; }
    gl->PixelStorei(0x0D05 /* GL_PACK_ALIGNMENT */, 4);
    for (i = 0; i < a->rmsm.npages; i++) {
        int xa, ya, xb, yb;
        if (memcmp(&a->rmsm.pages[i], &b->rmsm.pages[i], sizeof(sk_page)) != 0) { differ = -1; break; }
        skgl__slot_xy(a, a->rmsm.slot_of[i], &xa, &ya);
        skgl__slot_xy(b, b->rmsm.slot_of[i], &xb, &yb);
        gl->BindFramebuffer(0x8CA8 /* GL_READ_FRAMEBUFFER */, a->fbo[0]);
        gl->ReadPixels(xa, ya, slot, slot, 0x1902 /* GL_DEPTH_COMPONENT */, 0x1406 /* GL_FLOAT */, da);
        gl->BindFramebuffer(0x8CA8, b->fbo[0]);
        gl->ReadPixels(xb, yb, slot, slot, 0x1902, 0x1406, db);
        for (k = 0; k < n; k++) differ += memcmp(&da[k], &db[k], sizeof(float)) != 0;
    }
    gl->BindFramebuffer(0x8CA8, 0);
    free(da);
    free(db);
    return differ;
}

typedef struct tally {
    uint64_t covered, differ_class, differ_value;
    int frames, render_failed, verify_failed;
    long page_texels;             /* RMSM: page texels differing, cached slot against uncached */
    int full, kept;               /* layers (faces) drawn whole / kept */
    float max_dv;                 /* the largest difference of a mask value */
} tally;

static void compare(world *w, const float *a, const float *b, tally *t) {
    size_t i;
    gt_agreement g = gt_agree(a, b, w->e.n);
    t->covered += g.both;
    t->differ_class += g.differ;
    for (i = 0; i < w->e.n; i++) {
        if (!(a[i] >= 0 && b[i] >= 0 && a[i] != b[i])) continue;
        t->differ_value++;
        if (fabsf(a[i] - b[i]) > t->max_dv) t->max_dv = fabsf(a[i] - b[i]);
    }
}

static void count_cache(pair *pr, tally *t) {
    if (pr->p[0]) {
        const skgl_point_frame_stats *ps = skgl_point_stats(pr->p[0]);
        t->kept += ps->faces_reused;
        t->full += ps->faces_rendered - ps->faces_reused;
    } else {
        const skgl_shadow_frame_stats *ss = skgl_shadow_stats(pr->s[0]);
        t->kept += ss->cache_scrolled + ss->cache_reused + ss->pages_reused;
        t->full += ss->cache_full + ss->pages_rendered;
    }
}

/* ---- property: random frames ---- */
static tally run_random(world *w, light_kind k, unsigned seed) {
    pair pr;
    tally t;
    float *a = gt_alloc(&w->e), *b = gt_alloc(&w->e);
    const sk_aabb box0 = w->e.scene.objects[w->box0].bounds, box3 = w->e.scene.objects[w->box3].bounds;
    sk_vec3 eye = gt_v3(-8, 5, 11), look = gt_v3(1, 0, -1), lpos = gt_v3(1.5f, 4.5f, 1.0f);
    float az = 0.6f, el = 0.9f;   /* the sun's azimuth and elevation */
    int f, mover = 0;             /* 0 none, 1 with bounds, 2 without */
    int res = k == L_RMSM ? 2048 : is_point(k) ? 128 : 512;
    skgl_scene sc;
    memset(&t, 0, sizeof t);
    rnd_state = seed * 2654435761u + 12345u;
    sc.draw = gt_movers_draw_static;
    sc.user = w;
    sc.bounds = w->e.scene.bounds;
    if (!a || !b || pair_create(w, k, res, &pr) != 0) goto done;
    for (f = 0; f < FRAMES; f++) {
        float u = rnd(), v = rnd();
        skgl_camera cam;
        sk_vec3 dir;
        sk_result r0, r1;
        if (f > 0) {
            if (u < 0.45f) {   /* walk */
                float d = rnd_in(0.05f, 0.4f), ang = rnd_in(0, 6.2832f);
                eye.x += d * cosf(ang); eye.z += d * sinf(ang);
                look.x += d * cosf(ang); look.z += d * sinf(ang);
            } else if (u < 0.55f) {   /* jump */
                eye = gt_v3(rnd_in(-10, 10), rnd_in(2, 8), rnd_in(-10, 12));
                look = gt_v3(rnd_in(-4, 4), 0, rnd_in(-4, 4));
            } else if (u < 0.8f) {   /* creep, under a millimetre */
                float d = rnd_in(1e-4f, 9e-4f);
                eye.x += d; look.x += d;
            }
            if (v < 0.15f) {   /* a fast turn (or move) */
                az += rnd_in(0.005f, 0.05f);
                el += rnd_in(-0.02f, 0.02f);
                lpos.x += rnd_in(0.02f, 0.3f);
            } else if (v < 0.4f) {   /* a slow one: a real sun at 144 fps */
                az += 5e-7f;
                lpos.x += 1e-5f;
            }
            if (rnd() < 0.1f) {   /* box0 moves, both boxes invalidated */
                sk_vec3 now = gt_v3(rnd_in(-1.5f, 1.5f), 0, rnd_in(-1.5f, 1.5f));
                sk_aabb ob = gt_moved(box0, w->box0_shift), nb = gt_moved(box0, now);
                pair_invalidate(w, &pr, &ob);
                pair_invalidate(w, &pr, &nb);
                w->box0_shift = now;
            }
            if (rnd() < 0.06f) {   /* box3 disappears or comes back */
                w->box3_hidden = !w->box3_hidden;
                pair_invalidate(w, &pr, &box3);
            }
            if (rnd() < 0.12f) mover = (int)(rnd() * 3.0f) % 3;
            if (mover) w->mover_at = gt_v3(rnd_in(-8, 8), 0, rnd_in(-8, 8));
        }
        if (mover) {
            skgl_dynamic dy;
            memset(&dy, 0, sizeof dy);
            dy.draw = gt_movers_draw_dynamic;
            dy.user = w;
            if (mover == 1) dy.bounds = gt_moved(w->e.scene.objects[w->mover].bounds, w->mover_at);
            SK_CHECK(skgl_set_dynamic(w->e.sk, &dy) == SK_OK);
        } else SK_CHECK(skgl_set_dynamic(w->e.sk, NULL) == SK_OK);
        dir = gt_v3(cosf(az) * cosf(el), -sinf(el), sinf(az) * cosf(el));
        cam = gt_camera(eye, look, 0.9f, 0.5f, 60, W, H);
        SK_CHECK(gt_gbuffer(&w->e, &cam) == 0);
        if (pair_mask(w, &pr, 0, &cam, &sc, dir, lpos, a, &r0) || pair_mask(w, &pr, 1, &cam, &sc, dir, lpos, b, &r1)) {
            t.render_failed++;
            break;
        }
        if (r0 != SK_OK && t.verify_failed++ == 0) printf("  (%s seed %u frame %d)\n", light_name[k], seed, f);
        if (r1 != SK_OK) t.render_failed++;
        compare(w, a, b, &t);
        if (k == L_RMSM) {
            long d = rmsm_page_texels(w, &pr);
            SK_CHECK_MSG(d >= 0, "rmsm: the cached and uncached lights drew other pages");
            if (d > 0) t.page_texels += d;
        }
        if (f > 0) count_cache(&pr, &t);
        t.frames++;
    }
done:
    SK_CHECK(skgl_set_dynamic(w->e.sk, NULL) == SK_OK);
    pair_destroy(w, &pr);
    free(a);
    free(b);
    w->box0_shift = gt_v3(0, 0, 0);
    w->box3_hidden = 0;
    w->mover_at = gt_v3(-6, 0, -6);
    return t;
}

static void test_property(void) {
    world *w = &W_;
    int k, seed;
    for (k = 0; k < N_LIGHTS; k++) {
        tally sum;
        memset(&sum, 0, sizeof sum);
        for (seed = 1; seed <= SEEDS; seed++) {
            tally t = run_random(w, (light_kind)k, (unsigned)seed);
            sum.covered += t.covered;
            sum.differ_class += t.differ_class;
            sum.differ_value += t.differ_value;
            sum.frames += t.frames;
            sum.render_failed += t.render_failed;
            sum.verify_failed += t.verify_failed;
            sum.page_texels += t.page_texels;
            sum.full += t.full;
            sum.kept += t.kept;
            if (t.max_dv > sum.max_dv) sum.max_dv = t.max_dv;
        }
        printf("%-17s %d frames: %llu of %llu pixels differ in class, %llu in value (by up to %g); verify_cache failed %d "
               "frames; %s drawn whole %d, kept %d",
               light_name[k], sum.frames, (unsigned long long)sum.differ_class, (unsigned long long)sum.covered,
               (unsigned long long)sum.differ_value, (double)sum.max_dv, sum.verify_failed,
               k == L_RMSM ? "pages" : is_point((light_kind)k) ? "faces" : "layers", sum.full, sum.kept);
        if (k == L_RMSM) printf("; page texels differing from the uncached slots %ld", sum.page_texels);
        printf("\n");
        SK_CHECK(sum.frames == SEEDS * FRAMES && sum.render_failed == 0);
        SK_CHECK(sum.covered > 0);
        /* 0 measured in every light and seed (the file's comment) */
        SK_CHECK_MSG(sum.differ_class == 0, "%s: %llu pixels differ in class from the uncached mask", light_name[k],
                     (unsigned long long)sum.differ_class);
        /* RMSM's pages are the same bit for bit (page_texels), but in
           other slots of the pool: the lookup's texture coordinates round
           otherwise there, and the filter's weights with them, by one
           ulp of the R16F mask (2^-11) at most, measured 2^-11 in 10848
           of 4.1M pixels, never across the lit threshold */
        if (k == L_RMSM)
            SK_CHECK_MSG(sum.max_dv <= 1.0f / 2048.0f, "rmsm: mask values differ by %g", (double)sum.max_dv);
        else
            SK_CHECK_MSG(sum.differ_value == 0, "%s: %llu pixels differ in value from the uncached mask",
                         light_name[k], (unsigned long long)sum.differ_value);
        SK_CHECK_MSG(sum.verify_failed == 0, "%s: verify_cache failed %d frames of correct use", light_name[k],
                     sum.verify_failed);
        SK_CHECK_MSG(sum.page_texels == 0, "%s: %ld page texels differ between the cached and uncached slots",
                     light_name[k], sum.page_texels);
        SK_CHECK_MSG(sum.kept > 0, "%s: the cache kept nothing", light_name[k]);
    }
}

/* ---- drift: 5e-7 rad a frame, 0.1 mm a frame ---- */
/* world -> light clip of light s's layer 0 this frame */
static void layer0_world(const skgl_shadow *s, double w[16]) {
    int k;
    for (k = 0; k < 12; k++) w[k] = s->render_vp[0].m[k];
    for (k = 0; k < 4; k++)
        w[12 + k] = (double)s->render_vp[0].m[12 + k] -
                    ((double)s->render_vp[0].m[k] * s->origin[0] + (double)s->render_vp[0].m[4 + k] * s->origin[1] +
                     (double)s->render_vp[0].m[8 + k] * s->origin[2]);
}

/* how far (texels of a res map, in x or y) any corner of box moves from
   orthographic map a to map b */
static double map_moved(const double *a, const double *b, sk_aabb box, int res) {
    double worst = 0;
    int i, k;
    for (i = 0; i < 8; i++) {
        double p[3] = {(i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
                       (i & 4) ? box.max.z : box.min.z};
        for (k = 0; k < 2; k++) {
            double d = (a[k] - b[k]) * p[0] + (a[4 + k] - b[4 + k]) * p[1] + (a[8 + k] - b[8 + k]) * p[2] +
                       (a[12 + k] - b[12 + k]);
            if (fabs(d) * 0.5 * res > worst) worst = fabs(d) * 0.5 * res;
        }
    }
    return worst;
}

static void test_drift(void) {
    static const light_kind kinds[3] = {L_STANDARD, L_PSSM, L_FOCUSED};
    world *w = &W_;
    float *a = gt_alloc(&w->e), *b = gt_alloc(&w->e);
    skgl_scene sc = gt_movers_scene(w);
    int ki;
    for (ki = 0; ki < 3 && a && b; ki++) {
        pair pr;
        tally t;
        int f, frames = DRIFT_FRAMES, every = 250, creep = kinds[ki] == L_FOCUSED;
        double az = 0.6, el = 0.9, drawn[16], now[16], stale = 0;
        memset(&t, 0, sizeof t);
        if (pair_create(w, kinds[ki], 256, &pr) != 0) { pair_destroy(w, &pr); break; }
        for (f = 0; f < frames; f++) {
            sk_vec3 eye = gt_v3(-6 + (creep ? 1e-4f * (float)f : 0.0f), 5, 9), dir;
            skgl_camera cam;
            sk_result r0, r1;
            if (!creep) az += 5e-7;
            dir = gt_v3((float)(cos(az) * cos(el)), (float)-sin(el), (float)(sin(az) * cos(el)));
            cam = gt_camera(eye, gt_v3(eye.x + 6, 0, -1), 0.9f, 0.5f, 60, W, H);
            if (f % every == every - 1) {
                SK_CHECK(gt_gbuffer(&w->e, &cam) == 0);
                if (pair_mask(w, &pr, 0, &cam, &sc, dir, gt_v3(0, 0, 0), a, &r0) ||
                    pair_mask(w, &pr, 1, &cam, &sc, dir, gt_v3(0, 0, 0), b, &r1))
                    break;
                t.verify_failed += r0 != SK_OK;
                compare(w, a, b, &t);
            } else {
                r0 = skgl_shadow_render(w->e.sk, pr.s[0], &cam, &sc, dir);
                t.verify_failed += r0 != SK_OK;
            }
            if (f > 0) count_cache(&pr, &t);
            /* one layer: how far the map it holds (drawn whole at the
               last cache_full) is from this frame's */
            if (kinds[ki] != L_PSSM) {
                layer0_world(pr.s[0], now);
                if (f == 0 || skgl_shadow_stats(pr.s[0])->cache_full) memcpy(drawn, now, sizeof now);
                if (map_moved(drawn, now, sc.bounds, 256) > stale) stale = map_moved(drawn, now, sc.bounds, 256);
            }
            t.frames++;
        }
        if (kinds[ki] != L_PSSM) {
            /* the cache keeps a layer while its entries are within 1e-3 / res
               of the largest linear one and 1e-3 texel of a whole shift
               (skgl__cache_shift): at the scene's corners that moves a
               point by up to ~2e-3 texel; measured 1.8e-4 (the sun), 1.1e-3
               (the creep) */
            printf("drift %-17s the kept layer at most %.2g texel from this frame's map\n", light_name[kinds[ki]],
                   stale);
            SK_CHECK_MSG(stale <= 5e-3, "drift %s: the kept layer is %g texel from this frame's map",
                         light_name[kinds[ki]], stale);
        }
        printf("drift %-17s %d frames (%s): %llu of %llu pixels differ in class, %llu in value, compared every "
               "%dth frame; layers drawn whole %d, kept %d; verify_cache failed %d\n",
               light_name[kinds[ki]], t.frames, creep ? "camera creeping 0.1 mm a frame" : "sun turning 5e-7 rad a frame",
               (unsigned long long)t.differ_class, (unsigned long long)t.covered,
               (unsigned long long)t.differ_value, every, t.full, t.kept, t.verify_failed);
        SK_CHECK(t.frames == frames && t.covered > 0);
        SK_CHECK_MSG(t.differ_class == 0, "drift %s: %llu pixels differ in class", light_name[kinds[ki]],
                     (unsigned long long)t.differ_class);
        SK_CHECK_MSG(t.differ_value == 0, "drift %s: %llu pixels differ in value", light_name[kinds[ki]],
                     (unsigned long long)t.differ_value);
        SK_CHECK(t.verify_failed == 0);
        /* the change adds up to a redraw now and then; the layers are kept between */
        SK_CHECK_MSG(t.full > 0 && t.kept > (creep ? 0 : t.full), "drift %s: drawn whole %d, kept %d",
                     light_name[kinds[ki]], t.full, t.kept);
        pair_destroy(w, &pr);
    }
    free(a);
    free(b);
}

/* ---- walk300: verify_cache along an ordinary walk ---- */
static void test_walk_verify(void) {
    static const light_kind kinds[2] = {L_STANDARD, L_PSSM};
    world *w = &W_;
    skgl_scene sc = gt_movers_scene(w);
    int ki;
    for (ki = 0; ki < 2; ki++) {
        pair pr;
        int f, failed = 0, scrolled = 0;
        if (pair_create(w, kinds[ki], 512, &pr) != 0) { pair_destroy(w, &pr); break; }
        for (f = 0; f < 300; f++) {
            float t = 0.05f * (float)f;
            skgl_camera cam = gt_camera(gt_v3(-9 + t, 6, 12 - 0.4f * t), gt_v3(t, 1, -0.4f * t), 0.9f, 0.5f, 60, W, H);
            sk_result r = skgl_shadow_render(w->e.sk, pr.s[0], &cam, &sc, gt_v3(-0.5f, -1, -0.35f));
            if (r != SK_OK && failed++ == 0) printf("  walk300 frame %d: %s\n", f, skgl_error_log(w->e.sk));
            scrolled += skgl_shadow_stats(pr.s[0])->cache_scrolled;
        }
        printf("walk300 %-17s verify_cache failed %d of 300 frames; layers scrolled %d\n", light_name[kinds[ki]],
               failed, scrolled);
        SK_CHECK_MSG(failed == 0, "walk300 %s: verify_cache failed %d of 300 frames", light_name[kinds[ki]], failed);
        SK_CHECK(scrolled > 0);
        pair_destroy(w, &pr);
    }
}

static void test_cache_property(void) {
    world *w = &W_;
    int objects;
    if (gt_movers_init(w, W, H) != 0) return;
    w->e.scene.bounds = gt_box(-12, 0, -12, 12, 7, 12);   /* the mover's and box0's room */
    w->mover_at = gt_v3(-6, 0, -6);
    gt_warm_programs(w->e.sk);
    objects = skgl_gl_object_count(w->e.sk);
    test_walk_verify();
    test_drift();
    test_property();
    SK_CHECK_MSG(skgl_gl_object_count(w->e.sk) == objects, "%d GL objects, %d before", skgl_gl_object_count(w->e.sk),
                 objects);
    SK_CHECK(w->e.gl.GetError() == 0);
    gt_env_free(&w->e);
}

SK_TEST_MAIN(test_cache_property)
