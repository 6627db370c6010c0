/* test_gl_contact.c - contact shadows (skgl_shadow_desc.contact_length: a
   short march toward the light through the camera's depth buffer in
   skgl_shadow_mask) on the closed-form pole and box scenes
   (tb_closed_form.h) against their exact truth, 400 x 225 on OSMesa.

   A sun at elevations 8, 20 and 45 degrees, each at azimuths 30, 150 and
   260, seen by gt_cf_sun_camera; SKGL_STANDARD and SKGL_PSSM with 512^2
   maps (at 2048^2 the receiver plane leaves 4-8 false-light pixels near
   the contact line per elevation, all PCF-blended lateral edge pixels: too
   few to measure a halving), under both bias schemes (receiver plane, the
   default, and the 1.5-texel normal offset), each without contact shadows
   and with CONTACT_LENGTH, CONTACT_STEPS, CONTACT_THICKNESS. Per bias and
   elevation, pooled over scenes, azimuths and techniques:
   - false light near the contact line: truth-shadowed pixels the mask
     calls lit within 5 px (Chebyshev) of a contact pixel, a ground pixel
     with a 4-neighbour on a caster less than 0.1 above the ground (the
     caster's foot, seen);
   - new open false shadow: pixels lit in the truth, lit without contact
     shadows, shadowed with them, and more than 1 px from the exact edge
     (no truth pixel of the other class in their 5 x 5, gt_open_false_shadow
     as in test_gl_bias_cf.c).
   Asserted: at every elevation and bias at least FALSE_LIGHT_MIN false-light
   pixels without contact shadows, and at most half as many with them; no
   new open false shadow in any configuration. The mask's cost is printed
   (wall time with glFinish, the same frame, this process, the fastest of
   six alternated batches).

   Measured (Mesa llvmpipe, OSMesa; false light near the contact line
   without -> with, of the truth-shadowed pixels there: 684 at 8 deg, 1180
   at 20, 1598 at 45):
     receiver plane   8 deg 31 -> 12,  20 deg 57 -> 24,  45 deg 62 -> 24
     normal offset    8 deg 26 -> 12,  20 deg 46 -> 23,  45 deg 61 -> 29
   new open false shadow 0 everywhere. Without normals (receiver plane,
   standard; the march's depth tolerance of two receiver pixel steps) the
   march is nearly inert: 22 -> 22, 56 -> 56, 56 -> 51, no new open false
   shadow; asserted: no new open false shadow and no more false light.
   Before the two plane tests (depth alone, with a tolerance of two
   receiver pixel depth steps; 0.3 m, 8 steps) the false light barely fell
   (31 -> 30 at 8 deg); with the receiver's plane alone (these settings) the
   foot pixels of a lit wall shadowed themselves: 12 new open false-shadow
   pixels at 8 deg (box, azimuths 30 and 150). Mask cost, box at 20 deg,
   400 x 225, standard: 10.9 -> 16.7 ms and 16.4 -> 25.1 ms in two runs
   (1.5x, a shared 2-core machine). About 10 s.

   The forward snippet (SK_SHADOW_CONTACT before skgl_glsl_snippet(); the
   march reads the G-buffer's depth, named by skgl_shadow_contact_depth,
   the buffer's normals taken from its depth) is judged the same way on the
   same frames: its forward pass draws the scene with the light without
   and with contact shadows in one program (so the bind that turns the
   march off is tested too). Measured, without -> with:
     receiver plane   8 deg 30 -> 10,  20 deg 57 -> 23,  45 deg 62 -> 24
     normal offset    8 deg 26 -> 11,  20 deg 46 -> 22,  45 deg 61 -> 29
   new open false shadow 0. With the buffer's normals from the one-sided
   difference of the smaller depth step (instead of the side whose second
   difference is smaller), 1 pixel at a lit wall's foot (box, 8/30, all
   four lights) shadowed itself: 4 checks failed. Forward cost (the scene
   drawn with overdraw, bind and draw, 400 x 225): 54.5 -> 150.7 ms (x2.8;
   the mask's x1.6 in the same run), llvmpipe on a shared machine.

   CAN FAIL (record): with contact_visibility() returning 1.0 at once in
   shadow_mask.frag (the march disabled), all six halving checks fail
   (31 -> 31, 57 -> 57, ...); with sk_contact_visibility() returning 1.0
   in shadow_sample.glsl, the forward path's six fail (30 -> 30, 57 -> 57,
   62 -> 62, 26 -> 26, 46 -> 46, 61 -> 61). */
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "sk_test.h"
#include "gl_test_util.h"

#include <time.h>

#define W 400
#define H 225
#define N_ELEV 3
#define N_AZIM 3
#define N_TECH 2
#define N_SCENE 2
#define N_BIAS 2
#define RESOLUTION 512
#define CONTACT_LENGTH 0.4f
#define CONTACT_STEPS 12
#define CONTACT_THICKNESS 0.15f
/* the fewest false-light pixels per elevation without contact shadows, for a
   halving to mean something (measured 26 to 62) */
#define FALSE_LIGHT_MIN 20

static const double elevations[N_ELEV] = {8, 20, 45};
static const double azimuths[N_AZIM] = {30, 150, 260};
static const skgl_technique techs[N_TECH] = {SKGL_STANDARD, SKGL_PSSM};
static const char *const tech_names[N_TECH] = {"standard", "pssm"};
static const char *const scene_names[N_SCENE] = {"pole", "box"};
static const float scene_heights[N_SCENE] = {3.0f, 1.5f};
static const skgl_bias biases[N_BIAS] = {SKGL_BIAS_RECEIVER_PLANE, SKGL_BIAS_NORMAL_OFFSET};
static const char *const bias_names[N_BIAS] = {"receiver plane", "normal offset"};

static double now_ms(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

typedef struct totals {
    uint64_t false_light[N_BIAS][2][N_ELEV];   /* [bias][contact][elevation] */
    uint64_t near_shadow[N_BIAS][N_ELEV];      /* truth-shadowed pixels near the contact line */
    uint64_t new_open_fs[N_BIAS][N_ELEV];
    uint64_t contact_px[N_ELEV];
    uint64_t nn_false_light[2][N_ELEV], nn_open_fs[N_ELEV];   /* without normals: receiver plane, standard */
    double ms[2];                      /* mask wall time, [contact] */
    double fwd_ms[2];                  /* the forward pass's wall time, [contact] */
    int timed;
} totals;

/* the forward path: gt_forward's program with the contact march on
   (SK_SHADOW_CONTACT before the snippet); 0 ok */
static int forward_create(gt_env *e, gt_forward *f) {
    const tb_gl_funcs *gl = &e->gl;
    const char *vs[1], *fs[4];
    int ok = 0;
    memset(f, 0, sizeof *f);
    vs[0] = gt_forward_vs;
    fs[0] = "#version 330 core\n";
    fs[1] = "#define SK_SHADOW_CONTACT 1\n";
    fs[2] = skgl_glsl_snippet();
    fs[3] = gt_forward_fs;
    f->program = gt_program(gl, 1, vs, 4, fs, &ok);
    if (!f->program || !ok) { SK_CHECK_MSG(0, "forward program with SK_SHADOW_CONTACT"); return -1; }
    f->u_view_proj = gl->GetUniformLocation(f->program, "u_view_proj");
    f->u_view = gl->GetUniformLocation(f->program, "u_view");
    return tb_gl_fbo_create(gl, &f->fbo, e->w, e->h, TB_GL_COLOR_R16F);
}

/* the mean wall time of one forward draw of the scene (bind and draw,
   finished) over reps */
static double forward_ms(gt_env *e, gt_forward *f, skgl_shadow *s, const skgl_camera *cam, int reps) {
    const tb_gl_funcs *gl = &e->gl;
    double t0;
    int i;
    gt_forward_begin(e, f, cam);
    gl->Finish();
    t0 = now_ms();
    for (i = 0; i < reps; i++) {
        gl->Clear(0x00004000u | 0x00000100u);
        if (skgl_shadow_bind(e->sk, s, f->program, 0) != SK_OK) { t0 = -1e30; break; }
        tb_gl_mesh_draw(gl, &e->mesh, 0, 0);
    }
    gl->Finish();
    gt_forward_unbind(e);
    return t0 < 0 ? -1.0 : (now_ms() - t0) / reps;
}


/* 1 for a ground pixel whose 4-neighbour is a caster's foot */
static int contact_pixel(const gt_env *e, int x, int y) {
    static const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
    double p[3];
    int k;
    if (gt_world(e, (size_t)y * (size_t)e->w + (size_t)x, p) || fabs(p[1]) > 1e-3) return 0;
    for (k = 0; k < 4; k++) {
        int u = x + dx[k], v = y + dy[k];
        if (u < 0 || v < 0 || u >= e->w || v >= e->h) continue;
        if (gt_world(e, (size_t)v * (size_t)e->w + (size_t)u, p)) continue;
        if (p[1] > 1e-3 && p[1] < 0.1) return 1;
    }
    return 0;
}

/* near[i] = 1 within 5 px (Chebyshev) of a contact pixel; returns the contact pixels */
static uint64_t contact_zone(const gt_env *e, unsigned char *near) {
    uint64_t n = 0;
    int x, y, u, v;
    memset(near, 0, e->n);
    for (y = 0; y < e->h; y++)
        for (x = 0; x < e->w; x++) {
            if (!contact_pixel(e, x, y)) continue;
            n++;
            for (v = y - 5; v <= y + 5; v++)
                for (u = x - 5; u <= x + 5; u++)
                    if (u >= 0 && v >= 0 && u < e->w && v < e->h) near[(size_t)v * (size_t)e->w + (size_t)u] = 1;
        }
    return n;
}

/* the mean wall time of one skgl_shadow_mask over reps, finished */
static double mask_ms(gt_env *e, skgl_shadow *s, const skgl_camera *cam, int reps) {
    double t0;
    int i;
    e->gl.Finish();
    t0 = now_ms();
    for (i = 0; i < reps; i++)
        if (skgl_shadow_mask(e->sk, s, cam, e->gbuf.depth_tex, e->gbuf.color_tex, e->mask.color_tex) != SK_OK)
            return -1.0;
    e->gl.Finish();
    return (now_ms() - t0) / reps;
}

/* Two masks of a frame, res[0] without contact shadows and res[1] with
   them, against the truth: the truth-shadowed pixels near the contact line
   (near), those of them each mask calls lit, and the new open false
   shadow (gt_open_false_shadow in res[1], lit in res[0]). */
typedef struct contact_count {
    uint64_t near_shadow, false_light[2], new_open_fs;
} contact_count;

static contact_count count_contact(const gt_env *e, const float *truth, float *const res[2],
                                   const unsigned char *near) {
    contact_count k;
    size_t p;
    memset(&k, 0, sizeof k);
    for (p = 0; p < e->n; p++) {
        if (tb_visibility_class(truth[p]) == 0 && near[p]) {
            k.near_shadow++;
            k.false_light[0] += res[0][p] >= 0.5f;
            k.false_light[1] += res[1][p] >= 0.5f;
        }
        if (res[0][p] >= 0.5f && gt_open_false_shadow(e, truth, res[1], p)) k.new_open_fs++;
    }
    return k;
}

static void score(const gt_env *e, const float *truth, float *const res[2], const unsigned char *near, int b,
                  int i, totals *T, const char *what) {
    contact_count k = count_contact(e, truth, res, near);
    T->near_shadow[b][i] += k.near_shadow;
    T->false_light[b][0][i] += k.false_light[0];
    T->false_light[b][1][i] += k.false_light[1];
    T->new_open_fs[b][i] += k.new_open_fs;
    SK_CHECK_MSG(k.new_open_fs == 0, "%s: %llu new open false-shadow pixels", what,
                 (unsigned long long)k.new_open_fs);
}

/* the mask without normals (depth alone: the receiver's plane from screen
   derivatives, the march's tolerance from its depth steps), after gt_mask
   rendered both lights */
static void score_without_normals(gt_env *e, skgl_shadow *s, skgl_shadow *c, const skgl_camera *cam,
                                  const float *truth, float *const res[2], const unsigned char *near, int i,
                                  totals *T, const char *what) {
    skgl_shadow *l[2];
    contact_count k;
    int m;
    l[0] = s;
    l[1] = c;
    for (m = 0; m < 2; m++)
        if (skgl_shadow_mask(e->sk, l[m], cam, e->gbuf.depth_tex, 0, e->mask.color_tex) != SK_OK ||
            tb_gl_read_texture_red(&e->gl, e->mask.color_tex, e->w, e->h, res[m]) != 0) {
            SK_CHECK_MSG(0, "%s: mask without normals", what);
            return;
        }
    k = count_contact(e, truth, res, near);
    T->nn_false_light[0][i] += k.false_light[0];
    T->nn_false_light[1][i] += k.false_light[1];
    T->nn_open_fs[i] += k.new_open_fs;
}

/* T: the mask's totals, F: the forward snippet's (SK_SHADOW_CONTACT) */
static void run_scene(int sc, totals *T, totals *F) {
    gt_env e;
    tb_cf_scene cf;
    skgl_shadow *sh[N_BIAS][2][N_TECH];
    float *ref, *truth, *res[2], *fres[2], *fdepth;
    unsigned char *near;
    gt_forward fw;
    int m, t, i, a, b;
    memset(sh, 0, sizeof sh);
    memset(&fw, 0, sizeof fw);
    if (gt_env_init_cf(&e, &cf, scene_names[sc], W, H) != 0) { gt_env_free(&e); return; }
    ref = gt_alloc(&e); truth = gt_alloc(&e); res[0] = gt_alloc(&e); res[1] = gt_alloc(&e);
    fres[0] = gt_alloc(&e); fres[1] = gt_alloc(&e); fdepth = gt_alloc(&e);
    near = (unsigned char *)malloc(e.n);
    if (forward_create(&e, &fw) != 0) goto done;
    for (b = 0; b < N_BIAS; b++)
        for (m = 0; m < 2; m++)
            for (t = 0; t < N_TECH; t++) {
                skgl_shadow_desc d;
                memset(&d, 0, sizeof d);
                d.technique = techs[t];
                d.resolution = RESOLUTION;
                d.bias = biases[b];
                d.contact_length = m ? CONTACT_LENGTH : 0.0f;
                d.contact_steps = CONTACT_STEPS;
                d.contact_thickness = CONTACT_THICKNESS;
                sh[b][m][t] = gt_shadow(&e, &d);
            }
    if (!ref || !truth || !res[0] || !res[1] || !fres[0] || !fres[1] || !fdepth || !near) {
        SK_CHECK_MSG(0, "out of memory");
        goto done;
    }
    for (i = 0; i < N_ELEV; i++)
        for (a = 0; a < N_AZIM; a++) {
            sk_vec3 dir;
            skgl_camera cam;
            if (gt_cf_sun_frame(&e, &cf, scene_heights[sc], elevations[i], azimuths[a], ref, truth, &dir, &cam) != 0)
                continue;
            T->contact_px[i] += contact_zone(&e, near);
            for (b = 0; b < N_BIAS; b++)
                for (t = 0; t < N_TECH; t++) {
                    char what[128];
                    skgl_shadow **s = sh[b][0] + t, **c = sh[b][1] + t;
                    snprintf(what, sizeof what, "%s sun %g/%g %s, %s", scene_names[sc], elevations[i], azimuths[a],
                             tech_names[t], bias_names[b]);
                    if (!*s || !*c || gt_mask(&e, *s, &cam, dir, res[0]) != 0 || gt_mask(&e, *c, &cam, dir, res[1]) != 0) {
                        SK_CHECK_MSG(0, "%s: mask", what);
                        continue;
                    }
                    score(&e, truth, res, near, b, i, T, what);
                    /* the forward snippet, its march reading the G-buffer's depth (the
                       lights rendered by gt_mask for this camera) */
                    {
                        char fwhat[160];
                        snprintf(fwhat, sizeof fwhat, "forward: %s", what);
                        if (skgl_shadow_contact_depth(e.sk, *c, &cam, e.gbuf.depth_tex) != SK_OK ||
                            gt_forward_render(&e, &fw, *s, &cam, 0, fres[0], fdepth) != 0 ||
                            gt_forward_render(&e, &fw, *c, &cam, 0, fres[1], fdepth) != 0) {
                            SK_CHECK_MSG(0, "%s: %s", fwhat, skgl_error_log(e.sk));
                            continue;
                        }
                        score(&e, truth, fres, near, b, i, F, fwhat);
                        if (sc == 1 && t == 0 && b == 0 && a == 0 && i == 0) {
                            gt_images(&e, "contact-box-8-forward-off", truth, fres[0]);
                            gt_images(&e, "contact-box-8-forward-on", truth, fres[1]);
                        }
                    }
                    if (b == 0 && t == 0) score_without_normals(&e, *s, *c, &cam, truth, res, near, i, T, what);
                    if (sc == 1 && t == 0 && b == 1 && a == 0 && i == 0) {
                        gt_images(&e, "contact-box-8-normal-off", truth, res[0]);
                        gt_images(&e, "contact-box-8-normal-on", truth, res[1]);
                    }
                    if (sc == 1 && t == 0 && b == 0 && a == 0 && i == 1 && !T->timed) {
                        /* the cost: the same frame, both lights already rendered */
                        int k;
                        T->ms[0] = T->ms[1] = 1e30;
                        F->fwd_ms[0] = F->fwd_ms[1] = 1e30;
                        for (k = 0; k < 6; k++) {   /* alternated, the fastest batch: a shared CPU */
                            double t0 = mask_ms(&e, *s, &cam, 5), t1 = mask_ms(&e, *c, &cam, 5);
                            double f0 = forward_ms(&e, &fw, *s, &cam, 5), f1 = forward_ms(&e, &fw, *c, &cam, 5);
                            if (t0 >= 0 && t0 < T->ms[0]) T->ms[0] = t0;
                            if (t1 >= 0 && t1 < T->ms[1]) T->ms[1] = t1;
                            if (f0 >= 0 && f0 < F->fwd_ms[0]) F->fwd_ms[0] = f0;
                            if (f1 >= 0 && f1 < F->fwd_ms[1]) F->fwd_ms[1] = f1;
                        }
                        T->timed = 1;
                    }
                }
        }
    SK_CHECK(e.gl.GetError() == 0);
done:
    for (b = 0; b < N_BIAS; b++)
        for (m = 0; m < 2; m++)
            for (t = 0; t < N_TECH; t++) skgl_shadow_destroy(e.sk, sh[b][m][t]);
    gt_forward_destroy(&e, &fw);
    free(ref); free(truth); free(res[0]); free(res[1]); free(fres[0]); free(fres[1]); free(fdepth); free(near);
    gt_env_free(&e);
}

/* the desc's rules name the contact fields */
static void test_contact_validation(void) {
    gt_env e;
    tb_cf_scene cf;
    skgl_shadow_desc d;
    skgl_shadow *s = NULL;
    if (gt_env_init_cf(&e, &cf, "pole", 64, 64) != 0) { gt_env_free(&e); return; }
    memset(&d, 0, sizeof d);
    d.contact_length = -0.1f;
    SK_CHECK(skgl_shadow_create(e.sk, &d, &s) == SK_ERR_INVALID_ARG && !s);
    SK_CHECK(strstr(skgl_error_log(e.sk), "contact_length") != NULL);
    d.contact_length = NAN;
    SK_CHECK(skgl_shadow_create(e.sk, &d, &s) == SK_ERR_INVALID_ARG && !s);
    SK_CHECK(strstr(skgl_error_log(e.sk), "contact_length") != NULL);
    d.contact_length = 0.2f;
    d.contact_steps = 65;
    SK_CHECK(skgl_shadow_create(e.sk, &d, &s) == SK_ERR_INVALID_ARG && !s);
    SK_CHECK(strstr(skgl_error_log(e.sk), "contact_steps") != NULL);
    d.contact_steps = 0;
    d.contact_thickness = -1.0f;
    SK_CHECK(skgl_shadow_create(e.sk, &d, &s) == SK_ERR_INVALID_ARG && !s);
    SK_CHECK(strstr(skgl_error_log(e.sk), "contact_thickness") != NULL);
    d.contact_thickness = 0.0f;
    SK_CHECK(skgl_shadow_create(e.sk, &d, &s) == SK_OK && s);
    if (s) {
        skgl_shadow_desc g = skgl_shadow_get_desc(s);
        SK_CHECK(g.contact_steps == 8 && g.contact_thickness == 0.2f);
    }
    if (s) {
        /* skgl_shadow_contact_depth: the light, the camera and the texture named */
        skgl_camera cam = gt_camera(gt_v3(3, 2, 3), gt_v3(0, 0, 0), 0.9f, 0.1f, 50, 64, 64), bad = cam;
        SK_CHECK(skgl_shadow_contact_depth(e.sk, NULL, &cam, 0) == SK_ERR_INVALID_ARG);
        SK_CHECK(strstr(skgl_error_log(e.sk), "s") != NULL);
        bad.view.m[0] = NAN;
        SK_CHECK(skgl_shadow_contact_depth(e.sk, s, &bad, 0) == SK_ERR_INVALID_ARG);
        SK_CHECK(strstr(skgl_error_log(e.sk), "cam") != NULL);
        SK_CHECK(skgl_shadow_contact_depth(e.sk, s, &cam, 123456u) == SK_ERR_INVALID_ARG);
        SK_CHECK(strstr(skgl_error_log(e.sk), "depth_tex") != NULL);
        SK_CHECK(skgl_shadow_contact_depth(e.sk, s, &cam, 0) == SK_OK);
        SK_CHECK(skgl_shadow_contact_depth(NULL, s, &cam, 0) == SK_ERR_INVALID_ARG);
    }
    skgl_shadow_destroy(e.sk, s);
    gt_env_free(&e);
}

/* the halving and false-shadow checks of one path's totals */
static void check_halving(const totals *T, const char *path) {
    int i, b;
    for (b = 0; b < N_BIAS; b++)
        for (i = 0; i < N_ELEV; i++) {
            uint64_t off = T->false_light[b][0][i], on = T->false_light[b][1][i];
            printf("  %-8s %-14s %4g deg: %5llu -> %5llu of %6llu (contact px %llu); new open false shadow %llu\n",
                   path, bias_names[b], elevations[i], (unsigned long long)off, (unsigned long long)on,
                   (unsigned long long)T->near_shadow[b][i], (unsigned long long)T->contact_px[i],
                   (unsigned long long)T->new_open_fs[b][i]);
            SK_CHECK_MSG(T->contact_px[i] > 50, "%s %g deg: %llu contact pixels", path, elevations[i],
                         (unsigned long long)T->contact_px[i]);
            SK_CHECK_MSG(on <= off, "%s %s, %g deg: false light %llu -> %llu", path, bias_names[b], elevations[i],
                         (unsigned long long)off, (unsigned long long)on);
            SK_CHECK_MSG(off >= FALSE_LIGHT_MIN && 2 * on <= off, "%s %s, %g deg: false light %llu -> %llu, not halved",
                         path, bias_names[b], elevations[i], (unsigned long long)off, (unsigned long long)on);
        }
}

static void test_contact_closed_form(void) {
    static totals T, F;
    int i, sc;
    memset(&T, 0, sizeof T);
    memset(&F, 0, sizeof F);
    for (sc = 0; sc < N_SCENE; sc++) run_scene(sc, &T, &F);
    memcpy(F.contact_px, T.contact_px, sizeof F.contact_px);
    printf("false light within 5 px of the contact line (of truth-shadowed px there), without -> with contact "
           "shadows (%.2f m, %d steps, thickness %.2f m); new open false shadow\n", CONTACT_LENGTH, CONTACT_STEPS,
           CONTACT_THICKNESS);
    check_halving(&T, "mask");
    check_halving(&F, "forward");
    for (i = 0; i < N_ELEV; i++) {
        printf("  no normals, receiver plane, standard %4g deg: %5llu -> %5llu; new open false shadow %llu\n",
               elevations[i], (unsigned long long)T.nn_false_light[0][i], (unsigned long long)T.nn_false_light[1][i],
               (unsigned long long)T.nn_open_fs[i]);
        SK_CHECK_MSG(T.nn_open_fs[i] == 0, "no normals, %g deg: %llu new open false-shadow pixels", elevations[i],
                     (unsigned long long)T.nn_open_fs[i]);
        SK_CHECK(T.nn_false_light[1][i] <= T.nn_false_light[0][i]);
    }
    printf("mask cost (box, 20 deg, standard, %dx%d, wall with glFinish, fastest of 6 alternated batches of 5): %.3f ms -> %.3f ms (x%.2f)\n",
           W, H, T.ms[0], T.ms[1], T.ms[0] > 0 ? T.ms[1] / T.ms[0] : 0.0);
    SK_CHECK(T.timed && T.ms[0] > 0 && T.ms[1] > 0);
    printf("forward cost (the same frame: bind and draw of the scene, %dx%d, wall with glFinish, fastest of 6 "
           "alternated batches of 5): %.3f ms -> %.3f ms (x%.2f)\n",
           W, H, F.fwd_ms[0], F.fwd_ms[1], F.fwd_ms[0] > 0 ? F.fwd_ms[1] / F.fwd_ms[0] : 0.0);
    SK_CHECK(F.fwd_ms[0] > 0 && F.fwd_ms[1] > 0);
}

SK_TEST_MAIN(test_contact_validation, test_contact_closed_form)
