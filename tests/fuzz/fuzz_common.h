/* tests/fuzz/fuzz_common.h - what the libFuzzer targets in tests/fuzz/ share:
   decoding the fuzzer's bytes into arguments, output buffers with guard
   canaries, and the check macro.

   DECODING. Every target reads its arguments in a fixed order from the
   input; bytes past the end read as 0, so every input is valid. A float is
   one tag byte t, then:
     t <  64  four raw bytes (little endian): any bit pattern, NaN, Inf,
              denormals and huge values included;
     t < 128  one byte indexing fz_special_bits (zero, signed zero, +-1,
              NaN, +-Inf, FLT_MAX, FLT_MIN, denormals, pi/2 either side, ...);
     else     a 16-bit signed fixed-point value, int16/1024 * 2^((t&15)-4):
              moderate values from 2^-14 to 2^15, where the geometry is
              meaningful.
   An int is a tag byte t, then t < 32: four raw bytes; else two bytes taken
   into [lo, hi] (the range where the call does something).
   Structured arguments (matrices, frusta, boxes) have a mode byte that picks
   raw floats or a constructor (look-at, perspective, ...) so that both
   garbage and real camera set-ups are reached.

   SEEDS. Compiled with -DFZ_SEED_MAIN a target becomes a program that writes
   its seed corpus (fz_seeds(), defined by each target with the fz_put_*
   writers, which produce exactly the encoding above) into the directory
   given as argv[1], then runs every seed through the target once. */
#ifndef FUZZ_COMMON_H
#define FUZZ_COMMON_H
#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "shadowkit.h"

/* ---------------------------------------------------------------- checks */
#define FZ_CHECK(cond, ...) do { if (!(cond)) { \
    fprintf(stderr, "%s:%d: check failed: %s: ", __FILE__, __LINE__, #cond); \
    fprintf(stderr, __VA_ARGS__); fputc('\n', stderr); abort(); } } while (0)

static inline int fz_finite(float x) { return isfinite(x) != 0; }
static inline int fz_finite_n(const float *p, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) if (!fz_finite(p[i])) return 0;
    return 1;
}
static inline int fz_v3_finite(sk_vec3 v) { return fz_finite(v.x) && fz_finite(v.y) && fz_finite(v.z); }
static inline int fz_mat_finite(const sk_mat4 *m) { return fz_finite_n(m->m, 16); }
static inline float fz_maxabs3(sk_vec3 v)
{
    float m = fabsf(v.x);
    if (fabsf(v.y) > m) m = fabsf(v.y);
    if (fabsf(v.z) > m) m = fabsf(v.z);
    return m;
}
/* finite and |x| <= lim (for the checks that need meaningful geometry) */
static inline int fz_moderate(float x, float lim) { return fz_finite(x) && fabsf(x) <= lim; }
static inline int fz_v3_moderate(sk_vec3 v, float lim)
{
    return fz_moderate(v.x, lim) && fz_moderate(v.y, lim) && fz_moderate(v.z, lim);
}

/* ---------------------------------------------- buffers with guard canaries */
/* Every output buffer is allocated with FZ_GUARD bytes after the caller's
   capacity, all filled with FZ_CANARY: a write into the guard is caught by
   fz_guard_ok, one beyond it by AddressSanitizer; fz_untouched tells that a
   function wrote nothing at all. */
#define FZ_GUARD 64
#define FZ_CANARY 0xA5
static inline void *fz_alloc(size_t bytes)
{
    unsigned char *p = (unsigned char *)malloc(bytes + FZ_GUARD);
    if (!p) abort();
    memset(p, FZ_CANARY, bytes + FZ_GUARD);
    return p;
}
static inline int fz_canary_range(const void *p, size_t from, size_t to)
{
    const unsigned char *b = (const unsigned char *)p;
    size_t i;
    for (i = from; i < to; i++) if (b[i] != FZ_CANARY) return 0;
    return 1;
}
/* the guard after `bytes` bytes of capacity is intact */
static inline int fz_guard_ok(const void *p, size_t bytes) { return fz_canary_range(p, bytes, bytes + FZ_GUARD); }
/* nothing written in the first `bytes` bytes nor in the guard */
static inline int fz_untouched(const void *p, size_t bytes) { return fz_canary_range(p, 0, bytes + FZ_GUARD); }
/* a struct filled with the canary before a call */
#define FZ_FILL(x) memset(&(x), FZ_CANARY, sizeof(x))
#define FZ_UNTOUCHED(x) fz_canary_range(&(x), 0, sizeof(x))

/* ---------------------------------------------------------------- decoding */
typedef struct fz_in { const uint8_t *p; size_t n; } fz_in;

static inline uint8_t fz_u8(fz_in *in)
{
    if (!in->n) return 0;
    in->n--;
    return *in->p++;
}
static inline uint16_t fz_u16(fz_in *in) { uint16_t a = fz_u8(in); return (uint16_t)(a | (uint16_t)fz_u8(in) << 8); }
static inline uint32_t fz_u32(fz_in *in) { uint32_t a = fz_u16(in); return a | (uint32_t)fz_u16(in) << 16; }
static inline float fz_from_bits(uint32_t u) { float f; memcpy(&f, &u, sizeof f); return f; }
static inline uint32_t fz_to_bits(float f) { uint32_t u; memcpy(&u, &f, sizeof u); return u; }

static const uint32_t fz_special_bits[] = {
    0x00000000u, 0x80000000u,              /* 0, -0 */
    0x3f800000u, 0xbf800000u,              /* 1, -1 */
    0x3f000000u, 0x40000000u,              /* 0.5, 2 */
    0x7fc00000u, 0xffc00000u, 0x7f800001u, /* quiet NaN, negative NaN, signalling NaN */
    0x7f800000u, 0xff800000u,              /* +Inf, -Inf */
    0x7f7fffffu, 0xff7fffffu,              /* +-FLT_MAX */
    0x00800000u, 0x00000001u, 0x80000001u, 0x007fffffu, /* FLT_MIN, denormals */
    0x3fc90fdbu, 0x3fc90fdau,              /* float pi/2 (just above), just below */
    0x40490fdbu, 0x3e800000u, 0x3effffffu, /* pi, 0.25, just below 0.5 */
    0x33d6bf95u, 0x4b189680u,              /* 1e-7, 1e7 */
    0x0da24260u, 0x7149f2cau,              /* 1e-30, 1e30 */
    0x7e967699u, 0x006ce3eeu,              /* 1e38, 1e-38 */
    0x3f7fffffu, 0x3f800001u,              /* 1 - ulp, 1 + ulp */
    0x47800000u, 0x45800000u,              /* 65536, 4096 */
    0x4f000000u, 0xcf000000u,              /* 2^31, -2^31 */
    0x3dcccccdu, 0x447a0000u               /* 0.1, 1000 */
};
#define FZ_NSPECIAL ((int)(sizeof fz_special_bits / sizeof fz_special_bits[0]))

static inline float fz_float(fz_in *in)
{
    uint8_t t = fz_u8(in);
    if (t < 64) return fz_from_bits(fz_u32(in));
    if (t < 128) return fz_from_bits(fz_special_bits[fz_u8(in) % FZ_NSPECIAL]);
    return (float)(int16_t)fz_u16(in) / 1024.0f * ldexpf(1.0f, (t & 15) - 4);
}
/* a coordinate in [0,1) most of the time (samples, weights) */
static inline float fz_unit(fz_in *in)
{
    uint8_t t = fz_u8(in);
    if (t < 32) return fz_from_bits(fz_u32(in));
    if (t < 48) return fz_from_bits(fz_special_bits[fz_u8(in) % FZ_NSPECIAL]);
    return (float)fz_u16(in) / 65536.0f;
}
static inline int fz_int(fz_in *in, int lo, int hi)
{
    uint8_t t = fz_u8(in);
    if (t < 32) return (int)fz_u32(in);
    return lo + (int)(fz_u16(in) % (uint32_t)(hi - lo + 1));
}
static inline sk_vec2 fz_vec2(fz_in *in) { sk_vec2 v; v.x = fz_float(in); v.y = fz_float(in); return v; }
static inline sk_vec3 fz_vec3(fz_in *in)
{
    sk_vec3 v;
    v.x = fz_float(in); v.y = fz_float(in); v.z = fz_float(in);
    return v;
}
/* mode 0: raw min and max; else centre and half extents (taken absolute) */
static inline sk_aabb fz_aabb(fz_in *in)
{
    sk_aabb b;
    if (fz_u8(in) & 1) {
        b.min = fz_vec3(in); b.max = fz_vec3(in);
    } else {
        sk_vec3 c = fz_vec3(in), e = fz_vec3(in);
        e.x = fabsf(e.x); e.y = fabsf(e.y); e.z = fabsf(e.z);
        b.min.x = c.x - e.x; b.min.y = c.y - e.y; b.min.z = c.z - e.z;
        b.max.x = c.x + e.x; b.max.y = c.y + e.y; b.max.z = c.z + e.z;
    }
    return b;
}

/* How fz_mat4 made the matrix: the checks that need a meaningful camera
   look at it. */
enum { FZ_M_RAW, FZ_M_PERSPECTIVE, FZ_M_ORTHO, FZ_M_VIEW, FZ_M_IDENTITY, FZ_M_NMODES };
static inline sk_mat4 fz_mat4_mode(fz_in *in, int *mode_out)
{
    int mode = fz_u8(in) % FZ_M_NMODES, i;
    sk_mat4 m;
    if (mode_out) *mode_out = mode;
    if (mode == FZ_M_RAW) {
        for (i = 0; i < 16; i++) m.m[i] = fz_float(in);
        return m;
    }
    if (mode == FZ_M_IDENTITY) return sk_mat4_identity();
    {
        sk_vec3 eye = fz_vec3(in), target = fz_vec3(in), up = fz_vec3(in);
        sk_mat4 view = sk_mat4_look_at(eye, target, up);
        if (mode == FZ_M_VIEW) return view;
        if (mode == FZ_M_PERSPECTIVE) {
            float fovy = fz_float(in), aspect = fz_float(in), zn = fz_float(in), zf = fz_float(in);
            return sk_mat4_mul(sk_mat4_perspective(fovy, aspect, zn, zf), view);
        } else {
            float l = fz_float(in), r = fz_float(in), b = fz_float(in), t = fz_float(in);
            float zn = fz_float(in), zf = fz_float(in);
            return sk_mat4_mul(sk_mat4_ortho(l, r, b, t, zn, zf), view);
        }
    }
}
static inline sk_mat4 fz_mat4(fz_in *in) { return fz_mat4_mode(in, NULL); }

/* How fz_frustum made the frustum. FROM_MATRIX and FROM_AABB frusta have
   planes and corners that agree (a convex body), the others need not. */
enum { FZ_F_MATRIX, FZ_F_AABB, FZ_F_CORNERS, FZ_F_RAW, FZ_F_ZERO, FZ_F_NMODES };
static inline sk_frustum fz_frustum_mode(fz_in *in, int *mode_out, int *mat_mode)
{
    sk_frustum f;
    int mode = fz_u8(in) % FZ_F_NMODES, i;
    memset(&f, 0, sizeof f);
    if (mat_mode) *mat_mode = -1;
    if (mode == FZ_F_MATRIX) {
        f = sk_frustum_from_matrix(fz_mat4_mode(in, mat_mode));
    } else if (mode == FZ_F_AABB) {
        if (sk_frustum_from_aabb(fz_aabb(in), &f) != SK_OK) memset(&f, 0, sizeof f);
    } else if (mode == FZ_F_CORNERS) {
        sk_vec3 c[8];
        for (i = 0; i < 8; i++) c[i] = fz_vec3(in);
        if (sk_frustum_from_corners(c, &f) != SK_OK) memset(&f, 0, sizeof f);
    } else if (mode == FZ_F_RAW) {
        for (i = 0; i < 8; i++) f.corners[i] = fz_vec3(in);
        for (i = 0; i < 6; i++) { f.planes[i].n = fz_vec3(in); f.planes[i].d = fz_float(in); }
    }
    if (mode_out) *mode_out = mode;
    return f;
}
/* The library's own test for a usable frustum, restated: every float
   finite and no zero plane normal. */
static inline int fz_frustum_usable(const sk_frustum *f)
{
    int i;
    if (!fz_finite_n(&f->corners[0].x, 24)) return 0;
    for (i = 0; i < 6; i++) {
        const sk_plane *p = &f->planes[i];
        if (!fz_v3_finite(p->n) || !fz_finite(p->d)) return 0;
        if (p->n.x == 0.0f && p->n.y == 0.0f && p->n.z == 0.0f) return 0;
    }
    return 1;
}
/* every corner and plane offset within lim (for the geometric checks) */
static inline int fz_frustum_moderate(const sk_frustum *f, float lim)
{
    int i;
    for (i = 0; i < 8; i++) if (!fz_v3_moderate(f->corners[i], lim)) return 0;
    for (i = 0; i < 6; i++) if (!fz_moderate(f->planes[i].d, lim)) return 0;
    return 1;
}
/* the corners span a solid: along every axis their extent is at least
   rel times the largest. A matrix close to singular gives corners that
   collapse onto a plane or a line while its rows still give six planes;
   those planes and corners need not agree, so the geometric checks of a
   clip against its planes only hold for a solid frustum. */
static inline int fz_frustum_solid(const sk_frustum *f, double rel)
{
    double lo[3], hi[3], e[3], emax;
    int i, k;
    for (k = 0; k < 3; k++) lo[k] = hi[k] = (&f->corners[0].x)[k];
    for (i = 1; i < 8; i++)
        for (k = 0; k < 3; k++) {
            double v = (&f->corners[i].x)[k];
            if (v < lo[k]) lo[k] = v;
            if (v > hi[k]) hi[k] = v;
        }
    for (k = 0; k < 3; k++) e[k] = hi[k] - lo[k];
    emax = e[0] > e[1] ? e[0] : e[1];
    if (e[2] > emax) emax = e[2];
    return emax > 0.0 && e[0] >= rel * emax && e[1] >= rel * emax && e[2] >= rel * emax;
}
/* signed distance of p to plane k, in double */
static inline double fz_plane_dist(const sk_plane *pl, sk_vec3 p)
{
    return (double)pl->n.x * p.x + (double)pl->n.y * p.y + (double)pl->n.z * p.z + pl->d;
}
/* p is inside f with at least `margin` to spare on every plane */
static inline int fz_inside_by(const sk_frustum *f, sk_vec3 p, double margin)
{
    int k;
    for (k = 0; k < 6; k++) if (fz_plane_dist(&f->planes[k], p) < margin) return 0;
    return 1;
}
/* a point inside a convex frustum: corners weighted by input bytes */
static inline sk_vec3 fz_point_in(fz_in *in, const sk_frustum *f)
{
    double w[8], sum = 0.0, x = 0.0, y = 0.0, z = 0.0;
    int i;
    for (i = 0; i < 8; i++) { w[i] = 1.0 + fz_u8(in); sum += w[i]; }
    for (i = 0; i < 8; i++) {
        x += w[i] / sum * f->corners[i].x;
        y += w[i] / sum * f->corners[i].y;
        z += w[i] / sum * f->corners[i].z;
    }
    {
        sk_vec3 p;
        p.x = (float)x; p.y = (float)y; p.z = (float)z;
        return p;
    }
}
/* M * (p, 1) in double; returns w */
static inline double fz_xform(const sk_mat4 *m, sk_vec3 p, double out[3])
{
    int r;
    for (r = 0; r < 3; r++)
        out[r] = (double)m->m[r] * p.x + (double)m->m[4 + r] * p.y + (double)m->m[8 + r] * p.z + m->m[12 + r];
    return (double)m->m[3] * p.x + (double)m->m[7] * p.y + (double)m->m[11] * p.z + m->m[15];
}
/* a rigid view matrix (rotation + translation) with moderate translation */
static inline int fz_is_rigid(const sk_mat4 *m, float lim)
{
    int i, j;
    if (!fz_mat_finite(m) || m->m[3] != 0.0f || m->m[7] != 0.0f || m->m[11] != 0.0f || m->m[15] != 1.0f) return 0;
    for (i = 0; i < 3; i++) {
        if (!(fabsf(m->m[12 + i]) <= lim)) return 0;
        for (j = 0; j < 3; j++) {
            double d = (double)m->m[i * 4] * m->m[j * 4] + (double)m->m[i * 4 + 1] * m->m[j * 4 + 1] +
                       (double)m->m[i * 4 + 2] * m->m[j * 4 + 2];
            if (fabs(d - (i == j ? 1.0 : 0.0)) > 1e-5) return 0;
        }
    }
    return 1;
}

/* ---------------------------------------------------------------- seeds */
/* Writers for the same encoding: exact values through the raw tags. */
typedef struct fz_out { uint8_t b[4096]; size_t n; } fz_out;
static inline void fz_put_u8(fz_out *o, unsigned v) { if (o->n < sizeof o->b) o->b[o->n++] = (uint8_t)v; }
static inline void fz_put_u32(fz_out *o, uint32_t v)
{
    fz_put_u8(o, v & 0xff); fz_put_u8(o, (v >> 8) & 0xff);
    fz_put_u8(o, (v >> 16) & 0xff); fz_put_u8(o, v >> 24);
}
static inline void fz_put_float(fz_out *o, float f) { fz_put_u8(o, 0); fz_put_u32(o, fz_to_bits(f)); }
static inline void fz_put_unit(fz_out *o, float f) { fz_put_u8(o, 0); fz_put_u32(o, fz_to_bits(f)); }
static inline void fz_put_int(fz_out *o, int v) { fz_put_u8(o, 0); fz_put_u32(o, (uint32_t)v); }
static inline void fz_put_vec2(fz_out *o, float x, float y) { fz_put_float(o, x); fz_put_float(o, y); }
static inline void fz_put_vec3(fz_out *o, float x, float y, float z)
{
    fz_put_float(o, x); fz_put_float(o, y); fz_put_float(o, z);
}
/* fz_aabb in its raw mode */
static inline void fz_put_aabb(fz_out *o, float x0, float y0, float z0, float x1, float y1, float z1)
{
    fz_put_u8(o, 1);
    fz_put_vec3(o, x0, y0, z0);
    fz_put_vec3(o, x1, y1, z1);
}
/* fz_mat4: a perspective camera at eye looking at target, up +y */
static inline void fz_put_persp(fz_out *o, float ex, float ey, float ez, float tx, float ty, float tz,
                         float fovy, float aspect, float zn, float zf)
{
    fz_put_u8(o, FZ_M_PERSPECTIVE);
    fz_put_vec3(o, ex, ey, ez); fz_put_vec3(o, tx, ty, tz); fz_put_vec3(o, 0, 1, 0);
    fz_put_float(o, fovy); fz_put_float(o, aspect); fz_put_float(o, zn); fz_put_float(o, zf);
}
static inline void fz_put_ortho(fz_out *o, float ex, float ey, float ez, float tx, float ty, float tz,
                         float l, float r, float b, float t, float zn, float zf)
{
    fz_put_u8(o, FZ_M_ORTHO);
    fz_put_vec3(o, ex, ey, ez); fz_put_vec3(o, tx, ty, tz); fz_put_vec3(o, 0, 1, 0);
    fz_put_float(o, l); fz_put_float(o, r); fz_put_float(o, b); fz_put_float(o, t);
    fz_put_float(o, zn); fz_put_float(o, zf);
}
static inline void fz_put_view(fz_out *o, float ex, float ey, float ez, float tx, float ty, float tz)
{
    fz_put_u8(o, FZ_M_VIEW);
    fz_put_vec3(o, ex, ey, ez); fz_put_vec3(o, tx, ty, tz); fz_put_vec3(o, 0, 1, 0);
}
/* fz_frustum from a perspective camera */
static inline void fz_put_frustum_persp(fz_out *o, float ex, float ey, float ez, float tx, float ty, float tz,
                                 float fovy, float aspect, float zn, float zf)
{
    fz_put_u8(o, FZ_F_MATRIX);
    fz_put_persp(o, ex, ey, ez, tx, ty, tz, fovy, aspect, zn, zf);
}
static inline void fz_put_frustum_aabb(fz_out *o, float x0, float y0, float z0, float x1, float y1, float z1)
{
    fz_put_u8(o, FZ_F_AABB);
    fz_put_aabb(o, x0, y0, z0, x1, y1, z1);
}

#ifdef FZ_SEED_MAIN
static void fz_seeds(void);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
static const char *fz_seed_dir_;
static int fz_seed_count_;
/* writes o as <dir>/seed-NN and runs it through the target */
static void fz_seed(const fz_out *o)
{
    char path[1024];
    FILE *f;
    snprintf(path, sizeof path, "%s/seed-%02d", fz_seed_dir_, fz_seed_count_++);
    f = fopen(path, "wb");
    if (!f || fwrite(o->b, 1, o->n, f) != o->n || fclose(f) != 0) { perror(path); exit(1); }
    LLVMFuzzerTestOneInput(o->b, o->n);
}
int main(int argc, char **argv)
{
    if (argc != 2) { fprintf(stderr, "usage: %s DIR\n", argv[0]); return 2; }
    fz_seed_dir_ = argv[1];
    fz_seeds();
    printf("%s: %d seeds\n", argv[1], fz_seed_count_);
    return 0;
}
#endif
#endif
