/* gl_wrap.h - a getproc around the testbed's that counts some entry points
   and can lie about two, for the tests of what shadowkit_gl.h keeps between
   frames (test_gl_rings.c, test_gl_soft_rings.c): glClientWaitSync answers
   GL_TIMEOUT_EXPIRED to a zero-timeout poll while R.not_ready is set (a
   fence the GPU has not reached: the rings' error path, which a GPU that
   keeps up, or llvmpipe, never takes on its own), and glGetQueryObjectuiv
   answers 0 for GL_QUERY_RESULT_AVAILABLE while R.not_available is set.
   Counted: glReadPixels into client memory and into a pixel pack buffer,
   glGetBufferSubData, glGetUniformLocation, glTexSubImage2D, glBeginQuery,
   GL_QUERY_RESULT reads, glCheckFramebufferStatus. Include once, after
   shadowkit_gl.h, sk_test.h and gl_test_util.h. */
#ifndef GL_WRAP_H
#define GL_WRAP_H

/* ---- the wrapping getproc: counts, and two lies on demand ---- */
static struct {
    int not_ready, not_available;
    long client_reads, buffer_reads, pbo_reads, locations, subimages, begins, results, fb_checks;
} R;
typedef void (*readpixels_fn)(int, int, int, int, unsigned, unsigned, void *);
typedef unsigned (*clientwait_fn)(void *, unsigned, unsigned long long);
typedef void (*getqueryuiv_fn)(unsigned, unsigned, unsigned *);
typedef void (*getqueryui64v_fn)(unsigned, unsigned, unsigned long long *);
typedef void (*getbuffersub_fn)(unsigned, ptrdiff_t, ptrdiff_t, void *);
typedef int (*getuniformloc_fn)(unsigned, const char *);
typedef void (*texsub_fn)(unsigned, int, int, int, int, int, unsigned, unsigned, const void *);
typedef void (*beginquery_fn)(unsigned, unsigned);
typedef unsigned (*checkfb_fn)(unsigned);
typedef void (*getintegerv_fn)(unsigned, int *);
static tb_gl_getproc_fn real_getproc;
static readpixels_fn real_read_pixels;
static clientwait_fn real_client_wait;
static getqueryuiv_fn real_query_uiv;
static getqueryui64v_fn real_query_ui64v;
static getbuffersub_fn real_buffer_sub;
static getuniformloc_fn real_uniform_loc;
static texsub_fn real_tex_sub;
static beginquery_fn real_begin_query;
static checkfb_fn real_check_fb;
static getintegerv_fn real_get_integerv;

static void w_read_pixels(int x, int y, int w, int h, unsigned fmt, unsigned type, void *data) {
    int pack = 0;
    real_get_integerv(0x88ED /* PIXEL_PACK_BUFFER_BINDING */, &pack);
    if (pack) R.pbo_reads++; else R.client_reads++;
    real_read_pixels(x, y, w, h, fmt, type, data);
}
static unsigned w_client_wait(void *sync, unsigned flags, unsigned long long timeout) {
    unsigned r = real_client_wait(sync, flags, timeout);
    return R.not_ready && timeout == 0 ? 0x911B /* TIMEOUT_EXPIRED */ : r;
}
static void w_query_uiv(unsigned id, unsigned pname, unsigned *v) {
    real_query_uiv(id, pname, v);
    if (pname == 0x8867 /* QUERY_RESULT_AVAILABLE */ && R.not_available) *v = 0;
    if (pname == 0x8866 /* QUERY_RESULT */) R.results++;
}
static void w_query_ui64v(unsigned id, unsigned pname, unsigned long long *v) {
    if (pname == 0x8866) R.results++;
    real_query_ui64v(id, pname, v);
}
static void w_buffer_sub(unsigned target, ptrdiff_t off, ptrdiff_t size, void *data) {
    R.buffer_reads++;
    real_buffer_sub(target, off, size, data);
}
static int w_uniform_loc(unsigned p, const char *name) {
    R.locations++;
    return real_uniform_loc(p, name);
}
static void w_tex_sub(unsigned target, int level, int x, int y, int w, int h, unsigned fmt, unsigned type,
                      const void *data) {
    R.subimages++;
    real_tex_sub(target, level, x, y, w, h, fmt, type, data);
}
static void w_begin_query(unsigned target, unsigned id) {
    R.begins++;
    real_begin_query(target, id);
}
static unsigned w_check_fb(unsigned target) {
    R.fb_checks++;
    return real_check_fb(target);
}

/* void* <-> function pointers through memcpy: ISO C has no cast between them */
#define FN_TO_PTR(f, p) memcpy(&(p), &(f), sizeof(p))
#define PTR_TO_FN(p, f) memcpy(&(f), &(p), sizeof(f))
static void *ring_getproc(const char *name) {
    void *p = NULL;
    readpixels_fn rp = w_read_pixels;
    clientwait_fn cw = w_client_wait;
    getqueryuiv_fn qu = w_query_uiv;
    getqueryui64v_fn q64 = w_query_ui64v;
    getbuffersub_fn bs = w_buffer_sub;
    getuniformloc_fn ul = w_uniform_loc;
    texsub_fn ts = w_tex_sub;
    beginquery_fn bq = w_begin_query;
    checkfb_fn cf = w_check_fb;
    if (!strcmp(name, "glReadPixels")) FN_TO_PTR(rp, p);
    else if (!strcmp(name, "glClientWaitSync")) FN_TO_PTR(cw, p);
    else if (!strcmp(name, "glGetQueryObjectuiv")) FN_TO_PTR(qu, p);
    else if (!strcmp(name, "glGetQueryObjectui64v")) FN_TO_PTR(q64, p);
    else if (!strcmp(name, "glGetBufferSubData")) FN_TO_PTR(bs, p);
    else if (!strcmp(name, "glGetUniformLocation")) FN_TO_PTR(ul, p);
    else if (!strcmp(name, "glTexSubImage2D")) FN_TO_PTR(ts, p);
    else if (!strcmp(name, "glBeginQuery")) FN_TO_PTR(bq, p);
    else if (!strcmp(name, "glCheckFramebufferStatus")) FN_TO_PTR(cf, p);
    else return real_getproc(name);
    return p;
}
static void ring_install(tb_gl_getproc_fn gp) {
    void *p;
    real_getproc = gp;
    p = gp("glReadPixels"); PTR_TO_FN(p, real_read_pixels);
    p = gp("glClientWaitSync"); PTR_TO_FN(p, real_client_wait);
    p = gp("glGetQueryObjectuiv"); PTR_TO_FN(p, real_query_uiv);
    p = gp("glGetQueryObjectui64v"); PTR_TO_FN(p, real_query_ui64v);
    p = gp("glGetBufferSubData"); PTR_TO_FN(p, real_buffer_sub);
    p = gp("glGetUniformLocation"); PTR_TO_FN(p, real_uniform_loc);
    p = gp("glTexSubImage2D"); PTR_TO_FN(p, real_tex_sub);
    p = gp("glBeginQuery"); PTR_TO_FN(p, real_begin_query);
    p = gp("glCheckFramebufferStatus"); PTR_TO_FN(p, real_check_fb);
    p = gp("glGetIntegerv"); PTR_TO_FN(p, real_get_integerv);
}
static void counts_reset(void) {
    int a = R.not_ready, b = R.not_available;
    memset(&R, 0, sizeof R);
    R.not_ready = a;
    R.not_available = b;
}

/* a shadowkit context of this test: through ring_getproc */
static skgl_context *ring_context(int debug, int timing, int owns) {
    skgl_desc d;
    skgl_context *sk = NULL;
    sk_result r;
    memset(&d, 0, sizeof d);
    d.getproc = ring_getproc;
    d.debug = debug;
    d.timing = timing;
    d.caller_owns_state = owns;
    r = skgl_create(&d, &sk);
    SK_CHECK_MSG(r == SK_OK, "skgl_create: %s", sk_result_string(r));
    return sk;
}

#endif /* GL_WRAP_H */
