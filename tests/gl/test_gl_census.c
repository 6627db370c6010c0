/* test_gl_census.c - what shadowkit_gl.h creates, it releases: GL objects
   per object type and host memory, for every technique, counted apart.

   Each case of gl_exercise.h (every directional technique, FERKO and RMSM
   through skgl_shadow_analyze at two G-buffer sizes, cube and VSDCT point
   lights naive and with every optimization, three VSDCT lights in one
   shared atlas, area lights PCSS and PVSM, a caster program with varyings
   and a fragment hook through layered PSSM, a layered cube and PVSM with
   its own G-buffer ("engine": 13 programs besides the context's 2: the
   point mask's, PVSM's 7, the layered depth program and the hook's 4 for
   the depth, layered, low-resolution and G-buffer passes), and a bare
   context) runs on a
   context of its own, loaded through a getproc of this test that wraps
   every entry point which makes or frees a GL object: glGen* / glDelete* of textures, framebuffers,
   renderbuffers, samplers, vertex arrays, buffers, queries, transform
   feedbacks and program pipelines, the GL 4.5 glCreate* of each, and
   glCreateProgram, glCreateShader, glCreateShaderProgramv, glDeleteProgram,
   glDeleteShader, glFenceSync, glDeleteSync. shadowkit may ask for no other
   glGen*, glCreate*, glDelete* or glFenceSync: one it asked for that this
   test does not count fails the test (a new kind of object is not missed).
   Host memory goes through SKGL_MALLOC / SKGL_FREE, defined here to count.

   Per case, after skgl_destroy: created == deleted for every type, nothing
   live, no name deleted that shadowkit did not create (or deleted twice),
   every host allocation freed. While the context lives,
   skgl_gl_object_count() equals the live objects (shaders apart: they are
   flagged for deletion once linked). desc.timing is on, so the timer query
   is counted too; desc.debug is on, so every pass checks glGetError.
   The table printed is the census (created/deleted per type).

   Failure paths, the same census after each: skgl_create when the k-th
   shader fails to compile or the k-th program to link (k = 1 .. every one
   it builds), and when glGetError reports GL_OUT_OF_MEMORY at its final
   check; skgl_shadow_create of every directional technique, skgl_point_create
   (cube, VSDCT) and skgl_point_atlas_create when glGetError reports it
   after their allocations; a point light whose mask program fails to link;
   and every host allocation of every case made to fail in turn (the n-th
   SKGL_MALLOC returns NULL, n = 1 .. until the case runs through): each
   failing call returns an error, nothing leaks, nothing crashes.

   Programs on demand: a bare skgl_create links 2 programs and holds 6 GL
   objects (BARE_*, with the figures before); the first FERKO, AUTO or
   .fit_to_depth light adds FERKO's 3 analysis programs, the first RMSM
   light RMSM's 2, later lights none; each link or compile of them made to
   fail in turn gives SK_ERR_GL from skgl_shadow_create with the driver's
   message in skgl_error_log, the next create builds them, nothing leaks.
   Can fail: with FERKO's and RMSM's programs built by skgl_create again
   (the header before this change), "bare skgl_create: 7 links, 7 programs
   live, 2 expected", "11 GL objects, 6 expected" and "the first FERKO light
   added 0 programs, 3 expected" (and the failure injections missed).

   Measured (the table): every case 1 framebuffer (the masks' target), 2
   samplers, 1 vertex array and 2 programs (4 shaders) of the context; a
   directional light +1 texture and +1 framebuffer per layer, +9 timer
   queries (three per timed pass: render, mask, analysis); FERKO +3
   programs (its analysis, made with the light), 8
   textures and 9 framebuffers (its map, the final 2x1 pair, and the
   analysis and reduction levels each time the G-buffer size changes:
   three times over the frames) and 3 pixel buffers (the read-back ring),
   ferko-late 2 fences (the ring's); RMSM +2 programs, 6 textures (map, request atlas,
   page table, the samples made once per G-buffer size), 3 pixel buffers
   and 2 fences; a cube light +1 program, +1 texture, +6 framebuffers (its
   faces), +6 timer queries; a VSDCT light +1 program, +2 textures, +1
   framebuffer, +1 sampler; the atlas case 4 textures, 3 programs, 3
   samplers, 1 framebuffer; PCSS +3 textures (its map, the G-buffer it
   renders itself), +2 framebuffers, +2 programs, 24 timer queries (three
   frame sets of 8); PVSM +8 textures (map, low-res pyramid and plain map,
   SMTG, screen array, accumulation, G-buffer), +14 framebuffers (one per
   target and per pyramid level at lowres 256), +3 pixel buffers (the
   prediction's ring), +7 programs, 56 timer queries (sets grown to the
   tiles' passes). Nothing is left: this version of shadowkit_gl.h releases
   everything, on the failure paths too (7 of skgl_create, 84 host
   allocation failures, a failed timer-set growth reported by
   skgl_soft_render as SK_ERR_CAPACITY).
   Can fail: in local copies of the header with skgl__ring_free's fence
   delete removed, ferko-late and rmsm reported "1 sync(s) live (2 created,
   1 deleted)" (the fence still in flight at destroy), also on their
   allocation-failure paths; in an earlier version, with skgl__ferko_free's
   pixel buffer delete removed, ferko and ferko-late reported "3 buffer(s)
   live";
   with skgl__release's query delete removed, every case reported "1
   query(s) live"; with skgl_point_create's SKGL_FREE(p) after a failed
   link removed, the link-failure cases of point-cube and point-vsdct
   reported one host allocation more than frees. */
#if !defined(_POSIX_C_SOURCE) || _POSIX_C_SOURCE < 199309L
#undef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 199309L   /* clock_gettime */
#endif
#include <stdlib.h>
#include <string.h>
#include <time.h>

static long census_allocs, census_frees, census_fail_at;   /* fail_at: the n-th allocation returns NULL (0: none) */
static long census_alloc_seen;
static void *census_malloc(size_t n) {
    census_alloc_seen++;
    if (census_fail_at > 0 && census_alloc_seen == census_fail_at) return NULL;
    census_allocs++;
    return malloc(n);
}
static void census_free(void *p) {
    if (!p) return;
    census_frees++;
    free(p);
}
#define SKGL_MALLOC(n) census_malloc(n)
#define SKGL_FREE(p) census_free(p)

#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "sk_test.h"
#include "gl_test_util.h"
#include "gl_exercise.h"

/* A bare skgl_create builds what every directional light needs: the depth
   program and the directional mask (measured: 2 links, 4 compiles, 6 GL
   objects with the masks' framebuffer, the 2 samplers and the empty vertex
   array; it built 7 programs, 11 objects, before FERKO's and RMSM's were
   made on demand). FERKO's analysis (FERKO, AUTO, .fit_to_depth) adds its
   3 programs with the first light that uses it, RMSM its 2; later lights
   add none, and skgl_destroy frees them. */
#define BARE_PROGRAMS 2
#define BARE_OBJECTS 6
#define FERKO_PROGRAMS 3
#define RMSM_PROGRAMS 2

/* ---- object kinds and the wrapped entry points ---- */
enum { K_TEXTURE, K_FRAMEBUFFER, K_RENDERBUFFER, K_SAMPLER, K_VAO, K_BUFFER, K_QUERY, K_XFB, K_PIPELINE,
       K_PROGRAM, K_SHADER, K_SYNC, K_KINDS };
static const char *const kind_names[K_KINDS] = {"texture", "framebuffer", "renderbuffer", "sampler",
                                                "vertex array", "buffer", "query", "transform feedback",
                                                "program pipeline", "program", "shader", "sync"};
#define MAX_LIVE 512
static uintptr_t live[K_KINDS][MAX_LIVE];
static int live_n[K_KINDS], created[K_KINDS], deleted[K_KINDS];
static int foreign_deletes, overflow, uncounted;
static char uncounted_names[512];

static void track_new(int k, uintptr_t name) {
    if (!name) return;
    created[k]++;
    if (live_n[k] < MAX_LIVE) live[k][live_n[k]++] = name; else overflow = 1;
}
static void track_del(int k, uintptr_t name) {
    int i;
    if (!name) return;
    for (i = 0; i < live_n[k]; i++)
        if (live[k][i] == name) { live[k][i] = live[k][--live_n[k]]; deleted[k]++; return; }
    foreign_deletes++;
    printf("shadowkit deleted %s %lu, which it did not create (or deleted twice)\n", kind_names[k],
           (unsigned long)name);
}

typedef void (*gen_fn)(int, unsigned *);
typedef void (*create_t_fn)(unsigned, int, unsigned *);   /* glCreateTextures, glCreateQueries */
typedef void (*del_fn)(int, const unsigned *);
typedef unsigned (*u0_fn)(void);
typedef unsigned (*u1_fn)(unsigned);
typedef unsigned (*csp_fn)(unsigned, int, const char *const *);
typedef void (*v1_fn)(unsigned);
typedef void *(*fence_fn)(unsigned, unsigned);
typedef void (*delsync_fn)(void *);
typedef void (*getiv_fn)(unsigned, unsigned, int *);
static gen_fn real_gen[K_PIPELINE + 1], real_create[K_PIPELINE + 1];
static create_t_fn real_create_t[K_PIPELINE + 1];
static del_fn real_del[K_PIPELINE + 1];
static unsigned (*real_create_program)(void);
static unsigned (*real_create_shader)(unsigned);
static unsigned (*real_create_shader_programv)(unsigned, int, const char *const *);
static void (*real_delete_program)(unsigned), (*real_delete_shader)(unsigned);
static void *(*real_fence_sync)(unsigned, unsigned);
static void (*real_delete_sync)(void *);
static unsigned (*real_get_error)(void);
static void (*real_get_shaderiv)(unsigned, unsigned, int *);
static void (*real_get_programiv)(unsigned, unsigned, int *);
static tb_gl_getproc_fn real_getproc;

/* failure injection: the n-th compile / link reports failure; the next
   glGetError reports GL_OUT_OF_MEMORY once */
static int fail_compile_at, fail_link_at, compiles_seen, links_seen, error_armed;

#define GEN_WRAP(k, gname, cname, ctname, dname) \
    static void gname(int n, unsigned *ids) { int i; real_gen[k](n, ids); for (i = 0; i < n; i++) track_new(k, ids[i]); } \
    static void cname(int n, unsigned *ids) { int i; real_create[k](n, ids); for (i = 0; i < n; i++) track_new(k, ids[i]); } \
    static void ctname(unsigned t, int n, unsigned *ids) { int i; real_create_t[k](t, n, ids); for (i = 0; i < n; i++) track_new(k, ids[i]); } \
    static void dname(int n, const unsigned *ids) { int i; for (i = 0; i < n; i++) track_del(k, ids[i]); real_del[k](n, ids); }
GEN_WRAP(K_TEXTURE, w_gen_tex, w_cr_tex, w_crt_tex, w_del_tex)
GEN_WRAP(K_FRAMEBUFFER, w_gen_fb, w_cr_fb, w_crt_fb, w_del_fb)
GEN_WRAP(K_RENDERBUFFER, w_gen_rb, w_cr_rb, w_crt_rb, w_del_rb)
GEN_WRAP(K_SAMPLER, w_gen_smp, w_cr_smp, w_crt_smp, w_del_smp)
GEN_WRAP(K_VAO, w_gen_vao, w_cr_vao, w_crt_vao, w_del_vao)
GEN_WRAP(K_BUFFER, w_gen_buf, w_cr_buf, w_crt_buf, w_del_buf)
GEN_WRAP(K_QUERY, w_gen_q, w_cr_q, w_crt_q, w_del_q)
GEN_WRAP(K_XFB, w_gen_xfb, w_cr_xfb, w_crt_xfb, w_del_xfb)
GEN_WRAP(K_PIPELINE, w_gen_pp, w_cr_pp, w_crt_pp, w_del_pp)

static unsigned w_create_program(void) { unsigned p = real_create_program(); track_new(K_PROGRAM, p); return p; }
static void w_delete_program(unsigned p) { track_del(K_PROGRAM, p); real_delete_program(p); }
static unsigned w_create_shader(unsigned t) { unsigned s = real_create_shader(t); track_new(K_SHADER, s); return s; }
static void w_delete_shader(unsigned s) { track_del(K_SHADER, s); real_delete_shader(s); }
static unsigned w_create_shader_programv(unsigned t, int n, const char *const *src) {
    unsigned p = real_create_shader_programv(t, n, src);
    track_new(K_PROGRAM, p);
    return p;
}
static void *w_fence_sync(unsigned cond, unsigned flags) {
    void *s = real_fence_sync(cond, flags);
    track_new(K_SYNC, (uintptr_t)s);
    return s;
}
static void w_delete_sync(void *s) { track_del(K_SYNC, (uintptr_t)s); real_delete_sync(s); }
static unsigned w_get_error(void) {
    unsigned e = real_get_error();
    /* armed: the call's second glGetError answers GL_OUT_OF_MEMORY (its first
       clears what the application left pending, not shadowkit's) */
    if (error_armed && e == 0 && --error_armed == 0) return 0x0505; /* GL_OUT_OF_MEMORY */
    return e;
}
static void w_get_shaderiv(unsigned sh, unsigned pname, int *v) {
    real_get_shaderiv(sh, pname, v);
    if (pname == 0x8B81 /* COMPILE_STATUS */ && ++compiles_seen == fail_compile_at) *v = 0;
}
static void w_get_programiv(unsigned p, unsigned pname, int *v) {
    real_get_programiv(p, pname, v);
    if (pname == 0x8B82 /* LINK_STATUS */ && ++links_seen == fail_link_at) *v = 0;
}

/* name, the wrapper (as an object pointer), where the real entry point goes */
typedef struct wrap_entry {
    const char *name;
    void *wrapper;
    void *slot;             /* address of a function pointer variable */
} wrap_entry;
static wrap_entry wraps[48];
static int nwraps;
#define WRAP(nm, type, fn, slotp) do { type f_ = fn; wraps[nwraps].name = nm; \
        memcpy(&wraps[nwraps].wrapper, &f_, sizeof f_); wraps[nwraps].slot = (void *)(slotp); nwraps++; } while (0)
#define WRAP_KIND(k, suffix, g, c, ct, d) do { \
        WRAP("glGen" suffix, gen_fn, g, &real_gen[k]); \
        if ((k) == K_TEXTURE || (k) == K_QUERY) WRAP("glCreate" suffix, create_t_fn, ct, &real_create_t[k]); \
        else WRAP("glCreate" suffix, gen_fn, c, &real_create[k]); \
        WRAP("glDelete" suffix, del_fn, d, &real_del[k]); } while (0)

static void tracking_init(tb_gl_getproc_fn gp) {
    int i;
    real_getproc = gp;
    nwraps = 0;
    WRAP_KIND(K_TEXTURE, "Textures", w_gen_tex, w_cr_tex, w_crt_tex, w_del_tex);
    WRAP_KIND(K_FRAMEBUFFER, "Framebuffers", w_gen_fb, w_cr_fb, w_crt_fb, w_del_fb);
    WRAP_KIND(K_RENDERBUFFER, "Renderbuffers", w_gen_rb, w_cr_rb, w_crt_rb, w_del_rb);
    WRAP_KIND(K_SAMPLER, "Samplers", w_gen_smp, w_cr_smp, w_crt_smp, w_del_smp);
    WRAP_KIND(K_VAO, "VertexArrays", w_gen_vao, w_cr_vao, w_crt_vao, w_del_vao);
    WRAP_KIND(K_BUFFER, "Buffers", w_gen_buf, w_cr_buf, w_crt_buf, w_del_buf);
    WRAP_KIND(K_QUERY, "Queries", w_gen_q, w_cr_q, w_crt_q, w_del_q);
    WRAP_KIND(K_XFB, "TransformFeedbacks", w_gen_xfb, w_cr_xfb, w_crt_xfb, w_del_xfb);
    WRAP_KIND(K_PIPELINE, "ProgramPipelines", w_gen_pp, w_cr_pp, w_crt_pp, w_del_pp);
    WRAP("glCreateProgram", u0_fn, w_create_program, &real_create_program);
    WRAP("glCreateShader", u1_fn, w_create_shader, &real_create_shader);
    WRAP("glCreateShaderProgramv", csp_fn, w_create_shader_programv,
         &real_create_shader_programv);
    WRAP("glDeleteProgram", v1_fn, w_delete_program, &real_delete_program);
    WRAP("glDeleteShader", v1_fn, w_delete_shader, &real_delete_shader);
    WRAP("glFenceSync", fence_fn, w_fence_sync, &real_fence_sync);
    WRAP("glDeleteSync", delsync_fn, w_delete_sync, &real_delete_sync);
    WRAP("glGetError", u0_fn, w_get_error, &real_get_error);
    WRAP("glGetShaderiv", getiv_fn, w_get_shaderiv, &real_get_shaderiv);
    WRAP("glGetProgramiv", getiv_fn, w_get_programiv, &real_get_programiv);
    for (i = 0; i < nwraps; i++) {
        void *r = gp(wraps[i].name);
        memcpy(wraps[i].slot, &r, sizeof r);
    }
}

static int has_prefix(const char *s, const char *p) { return strncmp(s, p, strlen(p)) == 0; }

static void *tracking_getproc(const char *name) {
    int i;
    void *r;
    for (i = 0; i < nwraps; i++)
        if (!strcmp(name, wraps[i].name)) {
            memcpy(&r, wraps[i].slot, sizeof r);
            return r ? wraps[i].wrapper : NULL;
        }
    if (has_prefix(name, "glGen") || has_prefix(name, "glCreate") || has_prefix(name, "glDelete") ||
        has_prefix(name, "glFenceSync")) {
        uncounted++;
        if (strlen(uncounted_names) + strlen(name) + 2 < sizeof uncounted_names) {
            strcat(uncounted_names, " ");
            strcat(uncounted_names, name);
        }
    }
    return real_getproc(name);
}

/* ---- one census ---- */
static void census_reset(void) {
    memset(live_n, 0, sizeof live_n);
    memset(created, 0, sizeof created);
    memset(deleted, 0, sizeof deleted);
    foreign_deletes = overflow = 0;
    census_allocs = census_frees = census_alloc_seen = 0;
    census_fail_at = 0;
    fail_compile_at = fail_link_at = compiles_seen = links_seen = error_armed = 0;
}

static int live_objects(void) {
    int k, n = 0;
    for (k = 0; k < K_KINDS; k++) if (k != K_SHADER) n += live_n[k];
    return n;
}

static skgl_context *census_context(sk_result *res) {
    skgl_desc d;
    skgl_context *sk = NULL;
    memset(&d, 0, sizeof d);
    d.getproc = tracking_getproc;
    d.debug = 1;
    d.timing = 1;
    *res = skgl_create(&d, &sk);
    return sk;
}

/* after the case's skgl_destroy (or failed skgl_create): everything
   released; returns the number of problems */
static int census_check(const char *what) {
    int k, bad = 0;
    for (k = 0; k < K_KINDS; k++)
        if (live_n[k] || created[k] != deleted[k]) {
            bad++;
            SK_CHECK_MSG(0, "%s: %d %s(s) live (%d created, %d deleted)", what, live_n[k], kind_names[k],
                         created[k], deleted[k]);
        }
    if (foreign_deletes || overflow) {
        bad++;
        SK_CHECK_MSG(0, "%s: %d foreign deletes%s", what, foreign_deletes, overflow ? ", tracking overflow" : "");
    }
    if (census_allocs != census_frees) {
        bad++;
        SK_CHECK_MSG(0, "%s: %ld host allocations, %ld frees", what, census_allocs, census_frees);
    }
    if (!bad) SK_CHECK(1);
    return bad;
}

static void print_row(const char *name) {
    int k;
    printf("%-22s", name);
    for (k = 0; k < K_KINDS; k++)
        if (k == K_TEXTURE || k == K_FRAMEBUFFER || k == K_SAMPLER || k == K_VAO || k == K_BUFFER ||
            k == K_QUERY || k == K_PROGRAM || k == K_SHADER)
            printf(" %5d/%-5d", created[k], deleted[k]);
    for (k = 0; k < K_KINDS; k++)
        if ((k == K_RENDERBUFFER || k == K_XFB || k == K_PIPELINE || k == K_SYNC) && created[k])
            printf(" +%s %d/%d", kind_names[k], created[k], deleted[k]);
    printf(" %6ld/%-6ld\n", census_allocs, census_frees);
}

static gx_env X;
static int env_ok;

static void test_census(void) {
    int c;
    env_ok = gx_env_init(&X) == 0;
    if (!env_ok) return;
    tracking_init(tb_gl_context_getproc(X.e.ctx));
    printf("census, created/deleted per type, after skgl_destroy\n");
    printf("%-22s %11s %11s %11s %11s %11s %11s %11s %11s %13s\n", "case", "texture", "framebuffer", "sampler",
           "vertex arr.", "buffer", "query", "program", "shader", "host alloc");
    for (c = 0; c < GX_NCASES; c++) {
        sk_result r;
        skgl_context *sk;
        int calls;
        census_reset();
        uncounted = 0;
        uncounted_names[0] = 0;
        sk = census_context(&r);
        SK_CHECK_MSG(r == SK_OK && sk, "%s: skgl_create: %s", gx_cases[c].name, sk_result_string(r));
        if (!sk) continue;
        SK_CHECK_MSG(skgl_gl_object_count(sk) == live_objects(), "%s: count %d, tracked %d", gx_cases[c].name,
                     skgl_gl_object_count(sk), live_objects());
        calls = gx_run(&X, sk, &gx_cases[c]);
        SK_CHECK_MSG(calls >= 0, "%s did not run", gx_cases[c].name);
        SK_CHECK_MSG(skgl_gl_object_count(sk) == live_objects(), "%s: after the case: count %d, tracked %d",
                     gx_cases[c].name, skgl_gl_object_count(sk), live_objects());
        skgl_destroy(sk);
        print_row(gx_cases[c].name);
        census_check(gx_cases[c].name);
        SK_CHECK_MSG(uncounted == 0, "shadowkit loads object entry points this census does not count:%s",
                     uncounted_names);
        SK_CHECK(created[K_PROGRAM] >= BARE_PROGRAMS && created[K_TEXTURE] + created[K_PROGRAM] > 0);
    }
    SK_CHECK(X.e.gl.GetError() == 0);
}

/* skgl_create when its k-th shader compile or program link fails, or when
   glGetError reports an error at its last check */
static void test_create_failures(void) {
    int k, mode, ran = 0;
    if (!env_ok) return;
    for (mode = 0; mode < 2; mode++)
        for (k = 1; k < 64; k++) {
            sk_result r;
            skgl_context *sk;
            char what[64];
            census_reset();
            if (mode == 0) fail_compile_at = k; else fail_link_at = k;
            sk = census_context(&r);
            if (sk) {   /* k is past the last one: it ran through */
                SK_CHECK(r == SK_OK);
                skgl_destroy(sk);
                census_check(mode ? "skgl_create, all links" : "skgl_create, all compiles");
                break;
            }
            ran++;
            SK_CHECK_MSG(r == SK_ERR_GL, "compile/link failure %d: %s", k, sk_result_string(r));
            snprintf(what, sizeof what, "skgl_create, %s %d fails", mode ? "link" : "compile", k);
            census_check(what);
        }
    SK_CHECK_MSG(ran == 3 * BARE_PROGRAMS, "%d failure points", ran);   /* each program's link and 2 compiles */
    {
        sk_result r;
        skgl_context *sk;
        census_reset();
        error_armed = 2;
        /* the second glGetError of skgl_create is its final check */
        sk = census_context(&r);
        SK_CHECK_MSG(!sk && r == SK_ERR_GL, "skgl_create with a GL error: %s", sk_result_string(r));
        skgl_destroy(sk);
        census_check("skgl_create, GL error");
    }
    printf("skgl_create failure paths: %d, each released everything\n", ran + 1);
}

/* the create calls of every technique when glGetError reports an error
   right after their allocations; a point light whose program fails to link */
static void test_object_failures(void) {
    int c;
    if (!env_ok) return;
    for (c = 0; c < GX_NCASES; c++) {
        const gx_case *gc = &gx_cases[c];
        sk_result r;
        skgl_context *sk;
        char what[96];
        if (gc->kind == GX_CONTEXT) continue;
        census_reset();
        sk = census_context(&r);
        if (!sk) { SK_CHECK(0); continue; }
        error_armed = 2;
        if (gc->kind == GX_DIRECTIONAL) {
            skgl_shadow_desc d;
            skgl_shadow *s = NULL;
            memset(&d, 0, sizeof d);
            d.technique = gc->technique;
            d.resolution = gc->resolution;
            d.cascades = gc->cascades;
            r = skgl_shadow_create(sk, &d, &s);
            SK_CHECK_MSG(r == SK_ERR_GL && !s, "%s: skgl_shadow_create with a GL error: %s", gc->name,
                         sk_result_string(r));
            skgl_shadow_destroy(sk, s);
        } else if (gc->kind == GX_POINT) {
            skgl_point_desc d;
            skgl_point *p = NULL;
            gx_point_desc(gc, &d);
            r = skgl_point_create(sk, &d, &p);
            SK_CHECK_MSG(r == SK_ERR_GL && !p, "%s: skgl_point_create with a GL error: %s", gc->name,
                         sk_result_string(r));
            skgl_point_destroy(sk, p);
            if (!gc->optimized) {
                /* its mask program: the next link fails */
                error_armed = 0;
                fail_link_at = links_seen + 1;
                r = skgl_point_create(sk, &d, &p);
                SK_CHECK_MSG(r == SK_ERR_GL && !p, "%s: skgl_point_create, link failure: %s", gc->name,
                             sk_result_string(r));
                skgl_point_destroy(sk, p);
            }
        } else if (gc->kind == GX_SOFT) {
            skgl_soft_desc d;
            skgl_soft *so = NULL;
            memset(&d, 0, sizeof d);
            d.technique = gc->soft;
            d.resolution = gc->resolution;
            r = skgl_soft_create(sk, &d, &so);
            SK_CHECK_MSG(r == SK_ERR_GL && !so, "%s: skgl_soft_create with a GL error: %s", gc->name,
                         sk_result_string(r));
            skgl_soft_destroy(sk, so);
        } else {
            skgl_point_atlas *a = NULL;
            r = skgl_point_atlas_create(sk, 512, 512, &a);
            SK_CHECK_MSG(r == SK_ERR_GL && !a, "atlas create with a GL error: %s", sk_result_string(r));
            skgl_point_atlas_destroy(sk, a);
        }
        error_armed = 0;
        SK_CHECK_MSG(skgl_gl_object_count(sk) == live_objects(), "%s: count %d, tracked %d", gc->name,
                     skgl_gl_object_count(sk), live_objects());
        skgl_destroy(sk);
        snprintf(what, sizeof what, "%s: create failing on a GL error", gc->name);
        census_check(what);
    }
}

/* every host allocation of every case made to fail in turn */
static void test_allocation_failures(void) {
    int c, total = 0;
    if (!env_ok) return;
    for (c = 0; c < GX_NCASES; c++) {
        long n;
        for (n = 1; n < 1000; n++) {
            sk_result r;
            skgl_context *sk;
            char what[96];
            int failed = 0;
            census_reset();
            census_fail_at = n;
            sk = census_context(&r);
            if (!sk) {
                SK_CHECK_MSG(r == SK_ERR_CAPACITY, "%s: skgl_create, allocation %ld: %s", gx_cases[c].name, n,
                             sk_result_string(r));
                failed = 1;
            } else {
                /* a failing call is the point here: counted, not reported */
                gx_expect_failures = 1;
                gx_failed_calls = 0;
                gx_run(&X, sk, &gx_cases[c]);
                gx_expect_failures = 0;
                failed = gx_failed_calls > 0;
                skgl_destroy(sk);
            }
            snprintf(what, sizeof what, "%s, allocation %ld failing", gx_cases[c].name, n);
            census_check(what);
            if (census_alloc_seen < n) break;   /* the n-th allocation never happened: done */
            total++;
            if (!failed) SK_CHECK_MSG(0, "%s: allocation %ld failed and no call reported it", gx_cases[c].name, n);
        }
    }
    printf("allocation failure paths: %d, each released everything\n", total);
    SK_CHECK(total > GX_NCASES);
}

/* ---- programs built on demand ---- */

static double census_now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int cmp_double(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* a light of technique t; the programs it added (-1: its create failed) */
static int programs_added(skgl_context *sk, skgl_technique t, int fit_to_depth, skgl_shadow **out) {
    skgl_shadow_desc d;
    int before = created[K_PROGRAM];
    sk_result r;
    memset(&d, 0, sizeof d);
    d.technique = t;
    d.resolution = t == SKGL_RMSM ? 4096 : 512;
    d.cascades = t == SKGL_FERKO || t == SKGL_RMSM ? 1 : 2;
    d.fit_to_depth = fit_to_depth;
    *out = NULL;
    r = skgl_shadow_create(sk, &d, out);
    return r == SK_OK ? created[K_PROGRAM] - before : -1;
}

static void test_lazy_programs(void) {
    double ms[7];
    int i, n;
    sk_result r;
    skgl_context *sk;
    skgl_shadow *s[6];
    if (!env_ok) return;
    /* the bare create: its links and objects, and its time (median of 7) */
    for (i = 0; i < 7; i++) {
        double t0;
        census_reset();
        t0 = census_now();
        sk = census_context(&r);
        ms[i] = 1e3 * (census_now() - t0);
        if (!sk) { SK_CHECK_MSG(0, "skgl_create: %s", sk_result_string(r)); return; }
        SK_CHECK_MSG(links_seen == BARE_PROGRAMS && live_n[K_PROGRAM] == BARE_PROGRAMS,
                     "bare skgl_create: %d links, %d programs live, %d expected", links_seen, live_n[K_PROGRAM],
                     BARE_PROGRAMS);
        SK_CHECK_MSG(skgl_gl_object_count(sk) == BARE_OBJECTS, "bare skgl_create: %d GL objects, %d expected",
                     skgl_gl_object_count(sk), BARE_OBJECTS);
        if (i == 0)
            printf("bare skgl_create: %d GL objects, %d programs linked, %d shaders compiled\n",
                   skgl_gl_object_count(sk), links_seen, compiles_seen);
        skgl_destroy(sk);
        census_check("bare skgl_create");
    }
    qsort(ms, 7, sizeof ms[0], cmp_double);
    printf("bare skgl_create: %.1f ms (median of 7; %.1f .. %.1f)\n", ms[3], ms[0], ms[6]);
    /* FERKO's programs once, with the first light that analyses; RMSM's once */
    census_reset();
    sk = census_context(&r);
    if (!sk) { SK_CHECK(0); return; }
    n = programs_added(sk, SKGL_PSSM, 0, &s[0]);
    SK_CHECK_MSG(n == 0, "a PSSM light added %d programs", n);
    n = programs_added(sk, SKGL_FERKO, 0, &s[1]);
    SK_CHECK_MSG(n == FERKO_PROGRAMS, "the first FERKO light added %d programs, %d expected", n, FERKO_PROGRAMS);
    n = programs_added(sk, SKGL_FERKO, 0, &s[2]);
    SK_CHECK_MSG(n == 0, "a second FERKO light added %d programs", n);
    n = programs_added(sk, SKGL_AUTO, 0, &s[3]);
    SK_CHECK_MSG(n == 0, "an AUTO light after FERKO added %d programs", n);
#ifndef SKGL_NO_RMSM
    n = programs_added(sk, SKGL_RMSM, 0, &s[4]);
    SK_CHECK_MSG(n == RMSM_PROGRAMS, "the first RMSM light added %d programs, %d expected", n, RMSM_PROGRAMS);
    n = programs_added(sk, SKGL_RMSM, 0, &s[5]);
    SK_CHECK_MSG(n == 0, "a second RMSM light added %d programs", n);
#else
    s[4] = s[5] = NULL;
#endif
    for (i = 0; i < 6; i++) skgl_shadow_destroy(sk, s[i]);
    SK_CHECK_MSG(live_n[K_PROGRAM] == BARE_PROGRAMS + FERKO_PROGRAMS + RMSM_PROGRAMS,
                 "%d programs live after the lights (kept with the context)", live_n[K_PROGRAM]);
    SK_CHECK(skgl_gl_object_count(sk) == live_objects());
    skgl_destroy(sk);
    census_check("FERKO and RMSM lights");
    /* .fit_to_depth alone builds FERKO's analysis too */
    census_reset();
    sk = census_context(&r);
    if (!sk) { SK_CHECK(0); return; }
    n = programs_added(sk, SKGL_PSSM, 1, &s[0]);
    SK_CHECK_MSG(n == FERKO_PROGRAMS, "a .fit_to_depth light added %d programs, %d expected", n, FERKO_PROGRAMS);
    skgl_shadow_destroy(sk, s[0]);
    skgl_destroy(sk);
    census_check(".fit_to_depth light");
}

/* the k-th link or compile of FERKO's and RMSM's programs failing: the
   light's create says SK_ERR_GL with the driver's log, the context stays
   usable (the next create builds them), nothing leaks */
static void test_lazy_failures(void) {
    int mode, k, ran = 0;
    if (!env_ok) return;
    for (mode = 0; mode < 4; mode++) {
        skgl_technique t = mode < 2 ? SKGL_FERKO : SKGL_RMSM;
        int count = t == SKGL_FERKO ? FERKO_PROGRAMS : RMSM_PROGRAMS;
#ifdef SKGL_NO_RMSM
        if (t == SKGL_RMSM) continue;
#endif
        for (k = 1; k <= (mode & 1 ? count : 2 * count); k++) {
            sk_result r;
            skgl_context *sk;
            skgl_shadow *s;
            char what[96];
            const char *log;
            int n;
            census_reset();
            sk = census_context(&r);
            if (!sk) { SK_CHECK(0); return; }
            if (mode & 1) fail_link_at = links_seen + k; else fail_compile_at = compiles_seen + k;
            n = programs_added(sk, t, 0, &s);
            log = skgl_error_log(sk);
            SK_CHECK_MSG(n == -1 && !s, "%s, %s %d failing: the light was made", t == SKGL_FERKO ? "FERKO" : "RMSM",
                         mode & 1 ? "link" : "compile", k);
            SK_CHECK_MSG(strstr(log, "skgl_shadow_create") && strstr(log, t == SKGL_FERKO ? "FERKO" : "RMSM") &&
                             strstr(log, mode & 1 ? "link failed" : "compile failed"),
                         "the log: \"%s\"", log);
            SK_CHECK_MSG(skgl_gl_object_count(sk) == live_objects(), "count %d, tracked %d",
                         skgl_gl_object_count(sk), live_objects());
            skgl_shadow_destroy(sk, s);
            n = programs_added(sk, t, 0, &s);   /* the driver recovers: built now */
            SK_CHECK_MSG(n >= 1 && s, "the light after a failed one: %d programs added", n);
            skgl_shadow_destroy(sk, s);
            skgl_destroy(sk);
            snprintf(what, sizeof what, "%s, %s %d failing", t == SKGL_FERKO ? "FERKO" : "RMSM",
                     mode & 1 ? "link" : "compile", k);
            census_check(what);
            ran++;
        }
    }
    printf("FERKO and RMSM program failures: %d, each reported and released\n", ran);
}

static void test_teardown(void) {
    if (env_ok) SK_CHECK(X.e.gl.GetError() == 0);
    gx_env_free(&X);
}

SK_TEST_MAIN(test_census, test_create_failures, test_object_failures, test_allocation_failures, test_lazy_programs,
             test_lazy_failures, test_teardown)
