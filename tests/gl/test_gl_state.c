/* test_gl_state.c - shadowkit_gl.h leaves the caller's GL state alone and
   frees what it creates.

   State: every piece of state shadowkit touches (the list in the header's
   "GL STATE" section, plus the texture/sampler bindings of units 0..7) is
   set to unusual values, in two complementary sets A and B (every enable
   flips between them, so a pass that forces a cap on and one that forces it
   off are both caught); each technique runs render, mask and bind under
   each set; everything is read back with the test's own glGet calls and
   must be unchanged (skgl_shadow_bind may change only what it documents:
   the 2D-array texture and the sampler of its unit, and for RMSM the 2D
   texture and sampler of the next unit, the page table). No GL error; every
   call returns SK_OK with desc.debug on.

   Objects: shadowkit loads its entry points through a getproc we supply,
   which wraps every glGen / glCreate / glDelete it asks for: the names it
   creates are tracked, it must delete only names it created, and none may
   be live after skgl_destroy(). skgl_gl_object_count() must agree with the
   tally while the context lives, and return to its value after
   skgl_create once the shadows are destroyed (measured: 13 = 7 programs,
   2 framebuffers, 1 vertex array, 1 query, 2 samplers; +1 texture and +1
   framebuffer per layer and +9 timer queries per shadow; after
   skgl_destroy every one of them, and the shaders, deleted). "ferko" runs
   with sync_readback, "ferko-late" with the ring.
   Can fail: in local copies of the header with one restore line removed
   (scissor enable, polygon offset, sampler bindings, active texture in
   skgl_shadow_bind) or the query not deleted, this test failed each time
   with the state named.
   Point lights (skgl_point_*: cube and VSDCT, naive and with face and
   caster culling, scissor and resolution selection on) run create, render,
   mask and bind under both sets the same way; the sets also differ in the
   cube-map bindings of every unit and GL_TEXTURE_CUBE_MAP_SEAMLESS.
   skgl_point_bind may change only the map's binding and sampler on its unit
   and, for VSDCT, the indirection cube map's and sampler on the next unit.
   Measured: +1 program and +1 texture per cube light, +1 program, +2
   textures and +1 sampler per VSDCT light, all deleted by
   skgl_point_destroy. Can fail: with the restore of the cube-map bindings
   and of the seamless enable removed from skgl__restore, 27 checks failed
   (create, render, mask, bind of the point lights).
   A fifth point light, VSDCT with every optimization on, lives in a
   shared atlas (skgl_point_atlas_create, 512 x 512): atlas create and
   skgl_point_atlas_pack (before each render) leave the state alone too;
   measured: the atlas +1 texture, its light +1 program, +1 texture (the
   indirection) and +1 sampler; the count returns to its value after
   skgl_create once the light and the atlas are destroyed. */
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "sk_test.h"
#include "gl_test_util.h"

#define W 320
#define H 180
#define UNITS 8

/* ---- GL enums ---- */
#define E_TEXTURE_2D 0x0DE1
#define E_TEXTURE_2D_ARRAY 0x8C1A
#define E_TEXTURE0 0x84C0
#define E_DEPTH_TEST 0x0B71
#define E_CULL_FACE 0x0B44
#define E_BLEND 0x0BE2
#define E_SCISSOR_TEST 0x0C11
#define E_POLYGON_OFFSET_FILL 0x8037
#define E_FRONT 0x0404
#define E_BACK 0x0405
#define E_FRONT_AND_BACK 0x0408
#define E_GEQUAL 0x0206
#define E_NOTEQUAL 0x0205
#define E_DRAW_FRAMEBUFFER 0x8CA9
#define E_READ_FRAMEBUFFER 0x8CA8
#define E_DRAW_FRAMEBUFFER_BINDING 0x8CA6
#define E_READ_FRAMEBUFFER_BINDING 0x8CAA
#define E_VIEWPORT 0x0BA2
#define E_SCISSOR_BOX 0x0C10
#define E_CURRENT_PROGRAM 0x8B8D
#define E_VERTEX_ARRAY_BINDING 0x85B5
#define E_ACTIVE_TEXTURE 0x84E0
#define E_TEXTURE_BINDING_2D 0x8069
#define E_TEXTURE_BINDING_2D_ARRAY 0x8C1D
#define E_SAMPLER_BINDING 0x8919
#define E_DEPTH_FUNC 0x0B74
#define E_DEPTH_WRITEMASK 0x0B72
#define E_CULL_FACE_MODE 0x0B45
#define E_COLOR_WRITEMASK 0x0C23
#define E_POLYGON_OFFSET_FACTOR 0x8038
#define E_POLYGON_OFFSET_UNITS 0x2A00
#define E_DEPTH_CLEAR_VALUE 0x0B73
#define E_RGBA8 0x8058
#define E_RGBA 0x1908
#define E_UNSIGNED_BYTE 0x1401
#define E_ARRAY_BUFFER_BINDING 0x8894
#define E_BLEND_SRC_RGB 0x80C9
#define E_CLEAR_COLOR 0x0C22
#define E_TEXTURE_CUBE_MAP 0x8513
#define E_TEXTURE_BINDING_CUBE_MAP 0x8514
#define E_TEXTURE_CUBE_MAP_POSITIVE_X 0x8515
#define E_TEXTURE_CUBE_MAP_SEAMLESS 0x884F

/* ---- entry points the testbed table lacks ---- */
typedef struct ext_funcs {
    void (*GetFloatv)(unsigned, float *);
    void (*GetDoublev)(unsigned, double *);
    void (*GetBooleanv)(unsigned, unsigned char *);
    void (*Scissor)(int, int, int, int);
    void (*CullFace)(unsigned);
    void (*PolygonOffset)(float, float);
    void (*ColorMask)(unsigned char, unsigned char, unsigned char, unsigned char);
    void (*GenSamplers)(int, unsigned *);
    void (*DeleteSamplers)(int, const unsigned *);
    void (*BindSampler)(unsigned, unsigned);
    void (*TexImage3D)(unsigned, int, int, int, int, int, int, unsigned, unsigned, const void *);
} ext_funcs;

static void load(void *dst, tb_gl_getproc_fn gp, const char *name) {
    void *p = gp(name);
    SK_CHECK_MSG(p != NULL, "%s", name);
    memcpy(dst, &p, sizeof p);
}

static void ext_load(ext_funcs *x, tb_gl_getproc_fn gp) {
    load(&x->GetFloatv, gp, "glGetFloatv");
    load(&x->GetDoublev, gp, "glGetDoublev");
    load(&x->GetBooleanv, gp, "glGetBooleanv");
    load(&x->Scissor, gp, "glScissor");
    load(&x->CullFace, gp, "glCullFace");
    load(&x->PolygonOffset, gp, "glPolygonOffset");
    load(&x->ColorMask, gp, "glColorMask");
    load(&x->GenSamplers, gp, "glGenSamplers");
    load(&x->DeleteSamplers, gp, "glDeleteSamplers");
    load(&x->BindSampler, gp, "glBindSampler");
    load(&x->TexImage3D, gp, "glTexImage3D");
}

/* ---- object tracking: getproc wrapper ---- */
enum { K_TEXTURE, K_FRAMEBUFFER, K_RENDERBUFFER, K_SAMPLER, K_VAO, K_BUFFER, K_QUERY, K_PROGRAM,
       K_SHADER, K_KINDS };
static const char *const kind_names[K_KINDS] = {"texture", "framebuffer", "renderbuffer", "sampler",
                                                "vertex array", "buffer", "query", "program", "shader"};
#define MAX_LIVE 256
static unsigned live[K_KINDS][MAX_LIVE];
static int live_n[K_KINDS];
static int created[K_KINDS], deleted[K_KINDS], foreign_deletes, overflow;

typedef void (*gen_fn)(int, unsigned *);
typedef void (*del_fn)(int, const unsigned *);
typedef unsigned (*create_fn)(void);
typedef unsigned (*create_sh_fn)(unsigned);
typedef void (*del1_fn)(unsigned);
static gen_fn real_gen[K_KINDS];
static del_fn real_del[K_KINDS];
static create_fn real_create_program;
static create_sh_fn real_create_shader;
static del1_fn real_delete_program, real_delete_shader;
static tb_gl_getproc_fn real_getproc;

static void track_new(int k, unsigned name) {
    if (!name) return;
    created[k]++;
    if (live_n[k] < MAX_LIVE) live[k][live_n[k]++] = name; else overflow = 1;
}
static void track_del(int k, unsigned name) {
    int i;
    if (!name) return;
    for (i = 0; i < live_n[k]; i++)
        if (live[k][i] == name) { live[k][i] = live[k][--live_n[k]]; deleted[k]++; return; }
    foreign_deletes++;
    printf("shadowkit deleted %s %u, which it did not create\n", kind_names[k], name);
}
#define GEN_WRAP(k, gname, dname) \
    static void gname(int n, unsigned *ids) { int i; real_gen[k](n, ids); for (i = 0; i < n; i++) track_new(k, ids[i]); } \
    static void dname(int n, const unsigned *ids) { int i; for (i = 0; i < n; i++) track_del(k, ids[i]); real_del[k](n, ids); }
GEN_WRAP(K_TEXTURE, w_gen_textures, w_del_textures)
GEN_WRAP(K_FRAMEBUFFER, w_gen_framebuffers, w_del_framebuffers)
GEN_WRAP(K_RENDERBUFFER, w_gen_renderbuffers, w_del_renderbuffers)
GEN_WRAP(K_SAMPLER, w_gen_samplers, w_del_samplers)
GEN_WRAP(K_VAO, w_gen_vaos, w_del_vaos)
GEN_WRAP(K_BUFFER, w_gen_buffers, w_del_buffers)
GEN_WRAP(K_QUERY, w_gen_queries, w_del_queries)
static unsigned w_create_program(void) { unsigned p = real_create_program(); track_new(K_PROGRAM, p); return p; }
static void w_delete_program(unsigned p) { track_del(K_PROGRAM, p); real_delete_program(p); }
static unsigned w_create_shader(unsigned t) { unsigned s = real_create_shader(t); track_new(K_SHADER, s); return s; }
static void w_delete_shader(unsigned s) { track_del(K_SHADER, s); real_delete_shader(s); }

static const struct { const char *gen, *del; int kind; gen_fn wgen; del_fn wdel; } gen_table[] = {
    {"glGenTextures", "glDeleteTextures", K_TEXTURE, w_gen_textures, w_del_textures},
    {"glGenFramebuffers", "glDeleteFramebuffers", K_FRAMEBUFFER, w_gen_framebuffers, w_del_framebuffers},
    {"glGenRenderbuffers", "glDeleteRenderbuffers", K_RENDERBUFFER, w_gen_renderbuffers, w_del_renderbuffers},
    {"glGenSamplers", "glDeleteSamplers", K_SAMPLER, w_gen_samplers, w_del_samplers},
    {"glGenVertexArrays", "glDeleteVertexArrays", K_VAO, w_gen_vaos, w_del_vaos},
    {"glGenBuffers", "glDeleteBuffers", K_BUFFER, w_gen_buffers, w_del_buffers},
    {"glGenQueries", "glDeleteQueries", K_QUERY, w_gen_queries, w_del_queries},
};

static void *as_ptr_gen(gen_fn f) { void *p; memcpy(&p, &f, sizeof p); return p; }
static void *as_ptr_del(del_fn f) { void *p; memcpy(&p, &f, sizeof p); return p; }

static void *tracking_getproc(const char *name) {
    size_t i;
    void *p;
    for (i = 0; i < sizeof gen_table / sizeof gen_table[0]; i++) {
        if (!strcmp(name, gen_table[i].gen)) return as_ptr_gen(gen_table[i].wgen);
        if (!strcmp(name, gen_table[i].del)) return as_ptr_del(gen_table[i].wdel);
    }
    if (!strcmp(name, "glCreateProgram")) { create_fn f = w_create_program; memcpy(&p, &f, sizeof p); return p; }
    if (!strcmp(name, "glDeleteProgram")) { del1_fn f = w_delete_program; memcpy(&p, &f, sizeof p); return p; }
    if (!strcmp(name, "glCreateShader")) { create_sh_fn f = w_create_shader; memcpy(&p, &f, sizeof p); return p; }
    if (!strcmp(name, "glDeleteShader")) { del1_fn f = w_delete_shader; memcpy(&p, &f, sizeof p); return p; }
    return real_getproc(name);
}

static void tracking_init(tb_gl_getproc_fn gp) {
    size_t i;
    void *p;
    real_getproc = gp;
    for (i = 0; i < sizeof gen_table / sizeof gen_table[0]; i++) {
        p = gp(gen_table[i].gen); memcpy(&real_gen[gen_table[i].kind], &p, sizeof p);
        p = gp(gen_table[i].del); memcpy(&real_del[gen_table[i].kind], &p, sizeof p);
    }
    p = gp("glCreateProgram"); memcpy(&real_create_program, &p, sizeof p);
    p = gp("glDeleteProgram"); memcpy(&real_delete_program, &p, sizeof p);
    p = gp("glCreateShader"); memcpy(&real_create_shader, &p, sizeof p);
    p = gp("glDeleteShader"); memcpy(&real_delete_shader, &p, sizeof p);
}

/* live objects that count as "GL objects" (shaders are flagged for deletion
   once linked; they are tracked separately) */
static int live_objects(int with_shaders) {
    int k, n = 0;
    for (k = 0; k < K_KINDS; k++) if (with_shaders || k != K_SHADER) n += live_n[k];
    return n;
}

/* ---- the state ---- */
typedef struct gl_state {
    int draw_fb, read_fb, viewport[4], scissor_box[4], program, vao, active, array_buffer, pack_buffer;
    int read_buffer, draw_buffer;   /* state of the caller's bound framebuffer objects themselves */
    int tex2d[UNITS], tex2da[UNITS], sampler[UNITS], texcube[UNITS];
    int depth_func, cull_mode;
    unsigned char seamless, depth_test, depth_mask, cull, blend, scissor, poly_fill, color_mask[4];
    float poly_factor, poly_units, clear_color[4];
    double clear_depth;
} gl_state;

typedef struct objs {
    tb_gl_fbo draw_fbo, read_fbo;
    unsigned tex2d[UNITS], tex2da[UNITS], sampler[UNITS], texcube[UNITS], vao, pack_buffer;
} objs;

static void read_state(const tb_gl_funcs *gl, const ext_funcs *x, gl_state *s) {
    int u;
    memset(s, 0, sizeof *s);
    gl->GetIntegerv(E_DRAW_FRAMEBUFFER_BINDING, &s->draw_fb);
    gl->GetIntegerv(E_READ_FRAMEBUFFER_BINDING, &s->read_fb);
    gl->GetIntegerv(E_VIEWPORT, s->viewport);
    gl->GetIntegerv(E_SCISSOR_BOX, s->scissor_box);
    gl->GetIntegerv(E_CURRENT_PROGRAM, &s->program);
    gl->GetIntegerv(E_VERTEX_ARRAY_BINDING, &s->vao);
    gl->GetIntegerv(E_ARRAY_BUFFER_BINDING, &s->array_buffer);
    gl->GetIntegerv(0x88ED, &s->pack_buffer);   /* GL_PIXEL_PACK_BUFFER_BINDING */
    gl->GetIntegerv(0x0C02, &s->read_buffer);   /* GL_READ_BUFFER of the read framebuffer */
    gl->GetIntegerv(0x8825, &s->draw_buffer);   /* GL_DRAW_BUFFER0 of the draw framebuffer */
    gl->GetIntegerv(E_ACTIVE_TEXTURE, &s->active);
    for (u = 0; u < UNITS; u++) {
        gl->ActiveTexture(E_TEXTURE0 + (unsigned)u);
        gl->GetIntegerv(E_TEXTURE_BINDING_2D, &s->tex2d[u]);
        gl->GetIntegerv(E_TEXTURE_BINDING_2D_ARRAY, &s->tex2da[u]);
        gl->GetIntegerv(E_SAMPLER_BINDING, &s->sampler[u]);
        gl->GetIntegerv(E_TEXTURE_BINDING_CUBE_MAP, &s->texcube[u]);
    }
    s->seamless = gl->IsEnabled(E_TEXTURE_CUBE_MAP_SEAMLESS);
    gl->ActiveTexture((unsigned)s->active);
    gl->GetIntegerv(E_DEPTH_FUNC, &s->depth_func);
    gl->GetIntegerv(E_CULL_FACE_MODE, &s->cull_mode);
    s->depth_test = gl->IsEnabled(E_DEPTH_TEST);
    x->GetBooleanv(E_DEPTH_WRITEMASK, &s->depth_mask);
    s->cull = gl->IsEnabled(E_CULL_FACE);
    s->blend = gl->IsEnabled(E_BLEND);
    s->scissor = gl->IsEnabled(E_SCISSOR_TEST);
    s->poly_fill = gl->IsEnabled(E_POLYGON_OFFSET_FILL);
    x->GetBooleanv(E_COLOR_WRITEMASK, s->color_mask);
    x->GetFloatv(E_POLYGON_OFFSET_FACTOR, &s->poly_factor);
    x->GetFloatv(E_POLYGON_OFFSET_UNITS, &s->poly_units);
    x->GetFloatv(E_CLEAR_COLOR, s->clear_color);
    x->GetDoublev(E_DEPTH_CLEAR_VALUE, &s->clear_depth);
}

/* set A (variant 0) or B (variant 1): every enable differs between them */
static void set_state(const tb_gl_funcs *gl, const ext_funcs *x, const objs *o, unsigned program, int v) {
    int u;
    gl->BindFramebuffer(E_DRAW_FRAMEBUFFER, v ? o->read_fbo.fbo : o->draw_fbo.fbo);
    gl->BindFramebuffer(E_READ_FRAMEBUFFER, v ? o->draw_fbo.fbo : o->read_fbo.fbo);
    if (v) gl->Viewport(3, 1, 211, 97); else gl->Viewport(7, 9, 101, 53);
    if (v) x->Scissor(11, 2, 5, 301); else x->Scissor(3, 5, 17, 11);
    gl->UseProgram(program);
    gl->BindVertexArray(o->vao);
    gl->BindBuffer(0x88EB, v ? 0 : o->pack_buffer);   /* GL_PIXEL_PACK_BUFFER: A bound, B none */
    for (u = 0; u < UNITS; u++) {
        int j = v ? UNITS - 1 - u : u;      /* B: the names in reverse order */
        gl->ActiveTexture(E_TEXTURE0 + (unsigned)u);
        gl->BindTexture(E_TEXTURE_2D, o->tex2d[j]);
        gl->BindTexture(E_TEXTURE_2D_ARRAY, o->tex2da[j]);
        x->BindSampler((unsigned)u, o->sampler[j]);
        gl->BindTexture(E_TEXTURE_CUBE_MAP, o->texcube[j]);
    }
    if (v) gl->Disable(E_TEXTURE_CUBE_MAP_SEAMLESS); else gl->Enable(E_TEXTURE_CUBE_MAP_SEAMLESS);
    gl->ActiveTexture(E_TEXTURE0 + (v ? 2u : 5u));
    gl->DepthFunc(v ? E_NOTEQUAL : E_GEQUAL);
    gl->DepthMask(v ? 1 : 0);
    if (v) gl->Disable(E_DEPTH_TEST); else gl->Enable(E_DEPTH_TEST);
    x->CullFace(v ? E_FRONT_AND_BACK : E_FRONT);
    if (v) gl->Disable(E_CULL_FACE); else gl->Enable(E_CULL_FACE);
    if (v) gl->Disable(E_BLEND); else gl->Enable(E_BLEND);
    if (v) gl->Disable(E_SCISSOR_TEST); else gl->Enable(E_SCISSOR_TEST);
    if (v) gl->Disable(E_POLYGON_OFFSET_FILL); else gl->Enable(E_POLYGON_OFFSET_FILL);
    if (v) x->PolygonOffset(-1.5f, 11.0f); else x->PolygonOffset(3.25f, -7.5f);
    if (v) x->ColorMask(0, 1, 0, 1); else x->ColorMask(1, 0, 1, 0);
    gl->ClearDepth(v ? 0.625 : 0.25);
    gl->ClearColor(0.125f, 0.25f, 0.375f, 0.5f);
}

/* compares; `except_unit` (>= 0): its 2D-array and sampler bindings are
   allowed to differ (skgl_shadow_bind's documented effect) */
static int compare_state(const gl_state *a, const gl_state *b, const char *what, int except_unit, int except_table) {
    int bad = 0, u, k;
#define SAME(field) do { if (a->field != b->field) { bad++; \
    printf("%s: %s changed: %g -> %g\n", what, #field, (double)a->field, (double)b->field); } } while (0)
#define SAME_I(field, i) do { if (a->field[i] != b->field[i]) { bad++; \
    printf("%s: %s[%d] changed: %g -> %g\n", what, #field, i, (double)a->field[i], (double)b->field[i]); } } while (0)
    SAME(draw_fb); SAME(read_fb); SAME(read_buffer); SAME(draw_buffer); SAME(program); SAME(vao); SAME(active); SAME(array_buffer); SAME(pack_buffer);
    for (k = 0; k < 4; k++) {
        SAME_I(viewport, k); SAME_I(scissor_box, k); SAME_I(color_mask, k); SAME_I(clear_color, k);
    }
    for (u = 0; u < UNITS; u++) {
        if (u == except_table) { SAME_I(tex2da, u); continue; }   /* the RMSM page table: 2D + sampler */
        SAME_I(tex2d, u);
        SAME_I(texcube, u);
        if (u == except_unit) continue;
        SAME_I(tex2da, u); SAME_I(sampler, u);
    }
    SAME(seamless); SAME(depth_func); SAME(cull_mode); SAME(depth_test); SAME(depth_mask); SAME(cull); SAME(blend);
    SAME(scissor); SAME(poly_fill); SAME(poly_factor); SAME(poly_units); SAME(clear_depth);
#undef SAME
#undef SAME_I
    return bad;
}

/* after one shadowkit call under state set v: it returned SK_OK, left no
   GL error, and changed none of the state read before it */
static void check_call(const tb_gl_funcs *gl, const ext_funcs *x, sk_result r, const skgl_context *sk,
                       const char *tn, int v, const char *fn, const gl_state *before) {
    gl_state after;
    char what[128];
    snprintf(what, sizeof what, "%s set %c: %s", tn, "AB"[v], fn);
    SK_CHECK_MSG(r == SK_OK, "%s: %s (%s)", what, sk_result_string(r), skgl_error_log(sk));
    read_state(gl, x, &after);
    SK_CHECK_MSG(compare_state(before, &after, what, -1, -1) == 0, "%s", what);
    SK_CHECK_MSG(gl->GetError() == 0, "%s", what);
}

static void test_state_and_objects(void) {
    gt_env e;
    ext_funcs x;
    objs o;
    gt_forward fw;
    unsigned point_prog[2];   /* the point snippet, cube and VSDCT: skgl_point_bind's programs */
    skgl_desc desc;
    skgl_context *sk = NULL;
    tb_gl_funcs *gl;
    sk_vec3 light = gt_v3(-0.5f, -1, -0.35f);
    skgl_camera cam = gt_camera(gt_v3(-9, 7, 12), gt_v3(0, 1, 0), 0.9f, 0.5f, 100, W, H);
    skgl_scene sc;
    int t, v, u, own = 0, own_programs;
    sk_result r;
    float *mask = NULL;
    if (gt_env_init_named(&e, "ground-boxes", W, H) != 0) { gt_env_free(&e); return; }
    gl = &e.gl;
    ext_load(&x, tb_gl_context_getproc(e.ctx));
    /* the env's context loads through the plain getproc: replace it by one
       that loads through the tracking getproc */
    skgl_destroy(e.sk);
    e.sk = NULL;
    tracking_init(tb_gl_context_getproc(e.ctx));
    memset(&desc, 0, sizeof desc);
    desc.getproc = tracking_getproc;
    desc.debug = 1;
    desc.timing = 1;   /* the timer query objects too */
    r = skgl_create(&desc, &sk);
    SK_CHECK_MSG(r == SK_OK, "skgl_create: %s (%s)", sk_result_string(r), sk ? skgl_error_log(sk) : "");
    if (r != SK_OK) { gt_env_free(&e); return; }
    e.sk = sk;
    sc = gt_scene(&e);
    own = skgl_gl_object_count(sk);
    own_programs = live_n[K_PROGRAM];
    printf("after skgl_create: skgl_gl_object_count %d; tracked live: %d (+%d shaders)\n", own,
           live_objects(0), live_n[K_SHADER]);
    SK_CHECK_MSG(own == live_objects(0), "skgl_gl_object_count %d, tracked %d", own, live_objects(0));

    /* the caller's objects (made with the testbed's own table: not tracked) */
    memset(&o, 0, sizeof o);
    SK_CHECK(tb_gl_fbo_create(gl, &o.draw_fbo, 64, 64, TB_GL_COLOR_RGBA8) == 0);
    SK_CHECK(tb_gl_fbo_create(gl, &o.read_fbo, 32, 32, TB_GL_COLOR_RGBA8) == 0);
    gl->GenTextures(UNITS, o.tex2d);
    gl->GenTextures(UNITS, o.tex2da);
    x.GenSamplers(UNITS, o.sampler);
    gl->GenVertexArrays(1, &o.vao);
    gl->GenBuffers(1, &o.pack_buffer);
    for (u = 0; u < UNITS; u++) {
        gl->BindTexture(E_TEXTURE_2D, o.tex2d[u]);
        gl->TexImage2D(E_TEXTURE_2D, 0, (int)E_RGBA8, 4, 4, 0, E_RGBA, E_UNSIGNED_BYTE, NULL);
        gl->BindTexture(E_TEXTURE_2D_ARRAY, o.tex2da[u]);
        x.TexImage3D(E_TEXTURE_2D_ARRAY, 0, (int)E_RGBA8, 4, 4, 2, 0, E_RGBA, E_UNSIGNED_BYTE, NULL);
    }
    gl->GenTextures(UNITS, o.texcube);
    for (u = 0; u < UNITS; u++) {
        int f;
        gl->BindTexture(E_TEXTURE_CUBE_MAP, o.texcube[u]);
        for (f = 0; f < 6; f++)
            gl->TexImage2D(E_TEXTURE_CUBE_MAP_POSITIVE_X + (unsigned)f, 0, (int)E_RGBA8, 4, 4, 0, E_RGBA,
                           E_UNSIGNED_BYTE, NULL);
    }
    gl->BindTexture(E_TEXTURE_CUBE_MAP, 0);
    gl->BindTexture(E_TEXTURE_2D, 0);
    gl->BindTexture(E_TEXTURE_2D_ARRAY, 0);
    SK_CHECK(gt_forward_create(&e, &fw) == 0);
    point_prog[0] = gt_point_program(gl, 0);
    point_prog[1] = gt_point_program(gl, 1);
    mask = gt_alloc(&e);
    SK_CHECK(gt_gbuffer(&e, &cam) == 0);
    SK_CHECK(gl->GetError() == 0);

    for (t = 0; t < 9; t++) {
        static const char *const names[9] = {"standard", "pssm", "psm", "lispsm", "lispsm-cascades", "lspsm",
                                              "ferko", "ferko-late", "rmsm"};
        static const skgl_technique techs[9] = {SKGL_STANDARD, SKGL_PSSM, SKGL_PSM, SKGL_LISPSM, SKGL_LISPSM,
                                                SKGL_LSPSM, SKGL_FERKO, SKGL_FERKO, SKGL_RMSM};
        skgl_shadow_desc d;
        skgl_shadow *s = NULL;
        const char *tn = names[t];
        memset(&d, 0, sizeof d);
        d.technique = techs[t];
        d.resolution = techs[t] == SKGL_RMSM ? 4096 : 512;
        d.cascades = t == 4 ? 3 : 0;
        d.sync_readback = t != 7;   /* "ferko": this frame's estimate, read at once */
        d.blend_band = t == 1 || t == 4 ? 0.1f : 0.0f;
        for (v = 0; v < 2; v++) {
            gl_state before, after;
            char what[96];
            /* create under the unusual state too */
            set_state(gl, &x, &o, fw.program, v);
            read_state(gl, &x, &before);
            if (!s) {
                r = skgl_shadow_create(sk, &d, &s);
                SK_CHECK_MSG(r == SK_OK, "%s: skgl_shadow_create: %s (%s)", tn, sk_result_string(r), skgl_error_log(sk));
                if (r != SK_OK) break;
                read_state(gl, &x, &after);
                snprintf(what, sizeof what, "%s set %c: skgl_shadow_create", tn, "AB"[v]);
                SK_CHECK_MSG(compare_state(&before, &after, what, -1, -1) == 0, "%s", what);
                SK_CHECK_MSG(skgl_gl_object_count(sk) == live_objects(0), "%s: count %d, tracked %d", tn,
                             skgl_gl_object_count(sk), live_objects(0));
            }
            if (techs[t] == SKGL_FERKO || techs[t] == SKGL_RMSM) {
                r = skgl_shadow_analyze(sk, s, &cam, &sc, light, e.gbuf.depth_tex);
                check_call(gl, &x, r, sk, tn, v, "skgl_shadow_analyze", &before);
            }
            r = skgl_shadow_render(sk, s, &cam, &sc, light);
            check_call(gl, &x, r, sk, tn, v, "skgl_shadow_render", &before);

            r = skgl_shadow_mask(sk, s, &cam, e.gbuf.depth_tex, e.gbuf.color_tex, e.mask.color_tex);
            check_call(gl, &x, r, sk, tn, v, "skgl_shadow_mask", &before);

            /* bind needs its program current: it is (fw.program, part of the state) */
            r = skgl_shadow_bind(sk, s, fw.program, 6);
            SK_CHECK_MSG(r == SK_OK, "%s: bind: %s (%s)", tn, sk_result_string(r), skgl_error_log(sk));
            read_state(gl, &x, &after);
            snprintf(what, sizeof what, "%s set %c: skgl_shadow_bind", tn, "AB"[v]);
            SK_CHECK_MSG(compare_state(&before, &after, what, 6, techs[t] == SKGL_RMSM ? 7 : -1) == 0, "%s", what);
            SK_CHECK_MSG(after.tex2da[6] == (int)skgl_shadow_texture(s), "%s: unit 6 has %d, map is %u", what,
                         after.tex2da[6], skgl_shadow_texture(s));
            SK_CHECK_MSG(gl->GetError() == 0, "%s", what);

            /* the results are still right under that state: the mask is
               the same as one made under the default state (checked below) */
            SK_CHECK(tb_gl_read_texture_red(gl, e.mask.color_tex, W, H, mask) == 0);
            set_state(gl, &x, &o, fw.program, v);
        }
        /* sanity of the mask made under set B: some shadow, some light */
        {
            size_t i, lit = 0, dark = 0;
            for (i = 0; i < e.n; i++) {
                if (!(e.depth[i] < 1.0f)) continue;
                if (mask[i] >= 0.5f) lit++; else dark++;
            }
            SK_CHECK_MSG(lit > e.n / 4 && dark > e.n / 100, "%s: mask under set B: %zu lit, %zu shadowed", tn,
                         lit, dark);
        }
        skgl_shadow_destroy(sk, s);
        /* the programs of FERKO's analysis (3) and of RMSM's (2) stay with the context */
        SK_CHECK_MSG(skgl_gl_object_count(sk) - live_n[K_PROGRAM] == own - own_programs &&
                         live_n[K_PROGRAM] - own_programs <= 5,
                     "%s: after skgl_shadow_destroy: %d (%d programs), after create %d (%d programs)", tn,
                     skgl_gl_object_count(sk), live_n[K_PROGRAM], own, own_programs);
    }
    own += live_n[K_PROGRAM] - own_programs;
    /* point lights: cube and VSDCT, naive and with every optimization on */
    for (t = 0; t < 5; t++) {
        static const char *const names[5] = {"point-cube", "point-vsdct", "point-cube-all", "point-vsdct-all",
                                             "point-vsdct-atlas"};
        skgl_point_desc d;
        skgl_point *p = NULL;
        skgl_point_atlas *atlas = NULL;
        const char *tn = names[t];
        sk_vec3 lp = gt_v3(0.5f, 2.5f, 0.5f);
        memset(&d, 0, sizeof d);
        d.technique = (t & 1) || t == 4 ? SKGL_POINT_VSDCT : SKGL_POINT_CUBE;
        d.resolution = 256;
        d.range = 12.0f;
        d.cull_faces = d.cull_casters = d.scissor = d.select_resolution = t >= 2;
        for (v = 0; v < 2; v++) {
            gl_state before, after;
            char what[96];
            int ind = d.technique == SKGL_POINT_VSDCT;
            set_state(gl, &x, &o, fw.program, v);
            read_state(gl, &x, &before);
            if (t == 4 && !atlas) {
                r = skgl_point_atlas_create(sk, 512, 512, &atlas);
                SK_CHECK_MSG(r == SK_OK, "%s: atlas: %s (%s)", tn, sk_result_string(r), skgl_error_log(sk));
                if (r != SK_OK) break;
                read_state(gl, &x, &after);
                snprintf(what, sizeof what, "%s set %c: skgl_point_atlas_create", tn, "AB"[v]);
                SK_CHECK_MSG(compare_state(&before, &after, what, -1, -1) == 0, "%s", what);
                SK_CHECK_MSG(skgl_gl_object_count(sk) == live_objects(0), "%s: count %d, tracked %d", tn,
                             skgl_gl_object_count(sk), live_objects(0));
                d.atlas = atlas;
            }
            if (!p) {
                r = skgl_point_create(sk, &d, &p);
                SK_CHECK_MSG(r == SK_OK, "%s: skgl_point_create: %s (%s)", tn, sk_result_string(r), skgl_error_log(sk));
                if (r != SK_OK) break;
                read_state(gl, &x, &after);
                snprintf(what, sizeof what, "%s set %c: skgl_point_create", tn, "AB"[v]);
                SK_CHECK_MSG(compare_state(&before, &after, what, -1, -1) == 0, "%s", what);
                SK_CHECK_MSG(skgl_gl_object_count(sk) == live_objects(0), "%s: count %d, tracked %d", tn,
                             skgl_gl_object_count(sk), live_objects(0));
            }
            if (atlas) {
                r = skgl_point_atlas_pack(sk, atlas, &p, 1, &cam, &lp);
                check_call(gl, &x, r, sk, tn, v, "skgl_point_atlas_pack", &before);
            }
            r = skgl_point_render(sk, p, &cam, &sc, lp);
            check_call(gl, &x, r, sk, tn, v, "skgl_point_render", &before);

            r = skgl_point_mask(sk, p, &cam, e.gbuf.depth_tex, e.gbuf.color_tex, e.mask.color_tex);
            check_call(gl, &x, r, sk, tn, v, "skgl_point_mask", &before);

            /* bind: the map on unit 6 (cube, or the 2D atlas), VSDCT's
               indirection cube on unit 7, their samplers; nothing else */
            /* with a program that holds the point snippet current (desc.debug
               refuses one without), fw.program current again after it */
            gl->UseProgram(point_prog[ind]);
            r = skgl_point_bind(sk, p, point_prog[ind], 6);
            gl->UseProgram(fw.program);
            SK_CHECK_MSG(r == SK_OK, "%s: bind: %s (%s)", tn, sk_result_string(r), skgl_error_log(sk));
            read_state(gl, &x, &after);
            snprintf(what, sizeof what, "%s set %c: skgl_point_bind", tn, "AB"[v]);
            SK_CHECK_MSG((ind ? after.tex2d[6] : after.texcube[6]) == (int)skgl_point_texture(p),
                         "%s: unit 6 does not hold the map", what);
            SK_CHECK_MSG(!ind || after.texcube[7] != before.texcube[7], "%s: unit 7 lacks the indirection", what);
            after.tex2d[6] = before.tex2d[6]; after.texcube[6] = before.texcube[6]; after.sampler[6] = before.sampler[6];
            if (ind) { after.texcube[7] = before.texcube[7]; after.sampler[7] = before.sampler[7]; }
            SK_CHECK_MSG(compare_state(&before, &after, what, -1, -1) == 0, "%s", what);
            SK_CHECK_MSG(gl->GetError() == 0, "%s", what);
            SK_CHECK(tb_gl_read_texture_red(gl, e.mask.color_tex, W, H, mask) == 0);
            set_state(gl, &x, &o, fw.program, v);
        }
        {
            size_t i, lit = 0, dark = 0;
            for (i = 0; i < e.n; i++) {
                if (!(e.depth[i] < 1.0f)) continue;
                if (mask[i] >= 0.5f) lit++; else dark++;
            }
            SK_CHECK_MSG(lit > e.n / 4 && dark > e.n / 100, "%s: mask under set B: %zu lit, %zu shadowed", tn,
                         lit, dark);
        }
        skgl_point_destroy(sk, p);
        skgl_point_atlas_destroy(sk, atlas);
        SK_CHECK_MSG(skgl_gl_object_count(sk) == own, "%s: after skgl_point_destroy: %d, after create %d", tn,
                     skgl_gl_object_count(sk), own);
    }
    /* restore a sane state before tearing down */
    gl->BindFramebuffer(0x8D40, 0);
    gl->UseProgram(0);
    gl->DeleteProgram(point_prog[0]);
    gl->DeleteProgram(point_prog[1]);
    gl->BindVertexArray(0);
    SK_CHECK_MSG(skgl_gl_object_count(sk) == live_objects(0), "count %d, tracked %d", skgl_gl_object_count(sk),
                 live_objects(0));
    skgl_destroy(sk);
    e.sk = NULL;
    {
        int k;
        printf("after skgl_destroy: created/deleted:");
        for (k = 0; k < K_KINDS; k++)
            if (created[k]) printf(" %s %d/%d", kind_names[k], created[k], deleted[k]);
        printf("; foreign deletes %d\n", foreign_deletes);
        for (k = 0; k < K_KINDS; k++)
            SK_CHECK_MSG(live_n[k] == 0, "%d %s object(s) leaked", live_n[k], kind_names[k]);
        SK_CHECK(foreign_deletes == 0 && !overflow);
        SK_CHECK(created[K_PROGRAM] >= 2 && created[K_TEXTURE] >= 2);  /* the wrapper saw its calls */
    }
    SK_CHECK(gl->GetError() == 0);
    free(mask);
    gt_forward_destroy(&e, &fw);
    tb_gl_fbo_destroy(gl, &o.draw_fbo);
    tb_gl_fbo_destroy(gl, &o.read_fbo);
    gl->DeleteTextures(UNITS, o.tex2d);
    gl->DeleteTextures(UNITS, o.tex2da);
    gl->DeleteTextures(UNITS, o.texcube);
    x.DeleteSamplers(UNITS, o.sampler);
    gl->DeleteVertexArrays(1, &o.vao);
    gl->DeleteBuffers(1, &o.pack_buffer);
    gt_env_free(&e);
}

SK_TEST_MAIN(test_state_and_objects)
