/* tb_scene.c - see tb_scene.h */
#include "tb_scene.h"

#include <assimp/cimport.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static sk_aabb tb_empty_box_(void) {
    sk_aabb b;
    b.min.x = b.min.y = b.min.z = FLT_MAX;
    b.max.x = b.max.y = b.max.z = -FLT_MAX;
    return b;
}

static void tb_box_add_(sk_aabb *b, const float *p) {
    if (p[0] < b->min.x) b->min.x = p[0];
    if (p[1] < b->min.y) b->min.y = p[1];
    if (p[2] < b->min.z) b->min.z = p[2];
    if (p[0] > b->max.x) b->max.x = p[0];
    if (p[1] > b->max.y) b->max.y = p[1];
    if (p[2] > b->max.z) b->max.z = p[2];
}

void tb_scene_init(tb_scene *s) {
    memset(s, 0, sizeof *s);
    s->bounds = tb_empty_box_();
}

void tb_scene_free(tb_scene *s) {
    free(s->positions);
    free(s->normals);
    free(s->indices);
    free(s->objects);
    tb_scene_init(s);
}

double tb_scene_diagonal(const tb_scene *s) {
    double dx = (double)s->bounds.max.x - s->bounds.min.x;
    double dy = (double)s->bounds.max.y - s->bounds.min.y;
    double dz = (double)s->bounds.max.z - s->bounds.min.z;
    if (s->index_count == 0 || dx < 0 || dy < 0 || dz < 0) return 0.0;
    return sqrt(dx * dx + dy * dy + dz * dz);
}

int tb_scene_find_object(const tb_scene *s, const char *name) {
    uint32_t i;
    for (i = 0; i < s->object_count; i++)
        if (strcmp(s->objects[i].name, name) == 0) return (int)i;
    return -1;
}

/* ---- growth ---- */

static int tb_grow_(void **p, uint32_t *cap, uint64_t need, size_t elem) {
    uint64_t c = *cap ? *cap : 64;
    void *q;
    if (need <= *cap) return 0;
    if (need > 0xFFFFFFFFull) return -1;
    while (c < need) c *= 2;
    if (c > 0xFFFFFFFFull) c = 0xFFFFFFFFull;
    q = realloc(*p, (size_t)c * elem);
    if (!q) return -1;
    *p = q;
    *cap = (uint32_t)c;
    return 0;
}

/* reserve room for nv more vertices and ni more indices */
static int tb_reserve_(tb_scene *s, uint64_t nv, uint64_t ni) {
    uint32_t vcap = s->vertex_cap_, vcap2 = s->vertex_cap_;
    void *pp = s->positions, *np = s->normals, *ip = s->indices;
    if (tb_grow_(&pp, &vcap, (uint64_t)s->vertex_count + nv, 3 * sizeof(float))) return -1;
    s->positions = (float *)pp;
    if (tb_grow_(&np, &vcap2, (uint64_t)s->vertex_count + nv, 3 * sizeof(float))) return -1;
    s->normals = (float *)np;
    s->vertex_cap_ = vcap < vcap2 ? vcap : vcap2;
    if (tb_grow_(&ip, &s->index_cap_, (uint64_t)s->index_count + ni, sizeof(uint32_t))) return -1;
    s->indices = (uint32_t *)ip;
    return 0;
}

/* start an object: returns its index or -1 */
static int tb_begin_object_(tb_scene *s, const char *name) {
    void *op = s->objects;
    tb_object *o;
    if (tb_grow_(&op, &s->object_cap_, (uint64_t)s->object_count + 1, sizeof(tb_object))) return -1;
    s->objects = (tb_object *)op;
    o = &s->objects[s->object_count];
    memset(o, 0, sizeof *o);
    if (name) {
        strncpy(o->name, name, TB_NAME_MAX - 1);
        o->name[TB_NAME_MAX - 1] = 0;
    }
    o->first_index = s->index_count;
    o->bounds = tb_empty_box_();
    return (int)s->object_count++;
}

/* finish the last object: index range and bounds from the indices added */
static void tb_end_object_(tb_scene *s, int obj) {
    tb_object *o = &s->objects[obj];
    uint32_t i;
    o->index_count = s->index_count - o->first_index;
    for (i = o->first_index; i < s->index_count; i++) {
        const float *p = s->positions + 3 * (size_t)s->indices[i];
        tb_box_add_(&o->bounds, p);
        tb_box_add_(&s->bounds, p);
    }
}

/* drop a half-built object (after an allocation failure) */
static void tb_abort_object_(tb_scene *s, int obj, uint32_t vcount) {
    s->index_count = s->objects[obj].first_index;
    s->vertex_count = vcount;
    s->object_count = (uint32_t)obj;
}

/* rectangle origin + a*u + b*v (a, b in [0,1]) as nu x nv quads; the normal
   is cross(u, v) flipped if needed to agree with `want` */
static int tb_add_rect_(tb_scene *s, const double o[3], const double u_in[3],
                        const double v_in[3], int nu, int nv, const double want[3]) {
    double u[3], v[3], n[3], len;
    uint32_t base = s->vertex_count;
    int i, j;
    if (nu < 1) nu = 1;
    if (nv < 1) nv = 1;
    memcpy(u, u_in, sizeof u);
    memcpy(v, v_in, sizeof v);
    n[0] = u[1] * v[2] - u[2] * v[1];
    n[1] = u[2] * v[0] - u[0] * v[2];
    n[2] = u[0] * v[1] - u[1] * v[0];
    if (n[0] * want[0] + n[1] * want[1] + n[2] * want[2] < 0) {
        /* swap u and v: same rectangle, opposite winding */
        memcpy(u, v_in, sizeof u);
        memcpy(v, u_in, sizeof v);
        i = nu; nu = nv; nv = i;
        n[0] = -n[0]; n[1] = -n[1]; n[2] = -n[2];
    }
    len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (len > 0) { n[0] /= len; n[1] /= len; n[2] /= len; }
    if (tb_reserve_(s, (uint64_t)(nu + 1) * (nv + 1), (uint64_t)nu * nv * 6)) return -1;
    for (j = 0; j <= nv; j++)
        for (i = 0; i <= nu; i++) {
            double a = (double)i / nu, b = (double)j / nv;
            float *p = s->positions + 3 * (size_t)s->vertex_count;
            float *q = s->normals + 3 * (size_t)s->vertex_count;
            int k;
            for (k = 0; k < 3; k++) {
                /* exact endpoints: a == 1 gives o + u without rounding drift */
                p[k] = (float)(o[k] + a * u[k] + b * v[k]);
                q[k] = (float)n[k];
            }
            s->vertex_count++;
        }
    for (j = 0; j < nv; j++)
        for (i = 0; i < nu; i++) {
            uint32_t a = base + (uint32_t)(j * (nu + 1) + i);
            uint32_t b = a + 1, c = a + (uint32_t)(nu + 1), d = c + 1;
            uint32_t *t = s->indices + s->index_count;
            /* (a, b, d) and (a, d, c): CCW seen from +cross(u, v) */
            t[0] = a; t[1] = b; t[2] = d;
            t[3] = a; t[4] = d; t[5] = c;
            s->index_count += 6;
        }
    return 0;
}

static int tb_add_box_faces_(tb_scene *s, sk_vec3 mn, sk_vec3 mx) {
    double lo[3], hi[3];
    int ax;
    lo[0] = mn.x; lo[1] = mn.y; lo[2] = mn.z;
    hi[0] = mx.x; hi[1] = mx.y; hi[2] = mx.z;
    for (ax = 0; ax < 3; ax++) {
        int side;
        for (side = 0; side < 2; side++) {
            double o[3], u[3] = {0, 0, 0}, v[3] = {0, 0, 0}, w[3] = {0, 0, 0};
            int a1 = (ax + 1) % 3, a2 = (ax + 2) % 3;
            o[0] = lo[0]; o[1] = lo[1]; o[2] = lo[2];
            o[ax] = side ? hi[ax] : lo[ax];
            u[a1] = hi[a1] - lo[a1];
            v[a2] = hi[a2] - lo[a2];
            w[ax] = side ? 1.0 : -1.0;
            if (tb_add_rect_(s, o, u, v, 1, 1, w)) return -1;
        }
    }
    return 0;
}

int tb_scene_add_mesh(tb_scene *s, const char *name, const float *pos, uint32_t nv, const uint32_t *idx,
                      uint32_t ni) {
    uint32_t vc = s->vertex_count, i;
    int obj;
    if (!pos || !idx || nv == 0 || ni % 3 != 0) return -1;
    for (i = 0; i < ni; i++)
        if (idx[i] >= nv) return -1;
    obj = tb_begin_object_(s, name);
    if (obj < 0) return -1;
    if (tb_reserve_(s, nv, ni)) { tb_abort_object_(s, obj, vc); return -1; }
    memcpy(s->positions + 3 * (size_t)vc, pos, sizeof(float) * 3 * (size_t)nv);
    memset(s->normals + 3 * (size_t)vc, 0, sizeof(float) * 3 * (size_t)nv);
    for (i = 0; i < ni; i += 3) {
        const float *a = pos + 3 * (size_t)idx[i], *b = pos + 3 * (size_t)idx[i + 1], *c = pos + 3 * (size_t)idx[i + 2];
        double e1[3], e2[3], n[3];
        int k, v;
        for (k = 0; k < 3; k++) { e1[k] = (double)b[k] - a[k]; e2[k] = (double)c[k] - a[k]; }
        n[0] = e1[1] * e2[2] - e1[2] * e2[1];
        n[1] = e1[2] * e2[0] - e1[0] * e2[2];
        n[2] = e1[0] * e2[1] - e1[1] * e2[0];
        for (v = 0; v < 3; v++)
            for (k = 0; k < 3; k++) s->normals[3 * ((size_t)vc + idx[i + v]) + k] += (float)n[k];
    }
    for (i = 0; i < nv; i++) {
        float *n = s->normals + 3 * ((size_t)vc + i);
        double len = sqrt((double)n[0] * n[0] + (double)n[1] * n[1] + (double)n[2] * n[2]);
        if (len > 0) { n[0] = (float)(n[0] / len); n[1] = (float)(n[1] / len); n[2] = (float)(n[2] / len); }
        else n[1] = 1.0f;
    }
    for (i = 0; i < ni; i++) s->indices[s->index_count + i] = vc + idx[i];
    s->vertex_count += nv;
    s->index_count += ni;
    tb_end_object_(s, obj);
    return obj;
}

int tb_scene_add_box(tb_scene *s, const char *name, sk_vec3 mn, sk_vec3 mx) {
    uint32_t vc = s->vertex_count;
    int obj = tb_begin_object_(s, name);
    if (obj < 0) return -1;
    if (tb_add_box_faces_(s, mn, mx)) { tb_abort_object_(s, obj, vc); return -1; }
    tb_end_object_(s, obj);
    return obj;
}

int tb_scene_add_pole(tb_scene *s, const char *name, float x, float y0, float z,
                      float r, float h) {
    sk_vec3 mn, mx;
    mn.x = x - r; mn.y = y0; mn.z = z - r;
    mx.x = x + r; mx.y = y0 + h; mx.z = z + r;
    return tb_scene_add_box(s, name, mn, mx);
}

int tb_scene_add_ground(tb_scene *s, const char *name, float cx, float cz,
                        float hx, float hz, float y0, int nx, int nz) {
    uint32_t vc = s->vertex_count;
    double o[3], u[3] = {0, 0, 0}, v[3] = {0, 0, 0}, up[3] = {0, 1, 0};
    int obj = tb_begin_object_(s, name);
    if (obj < 0) return -1;
    o[0] = (double)cx - hx; o[1] = y0; o[2] = (double)cz - hz;
    u[0] = 2.0 * hx;
    v[2] = 2.0 * hz;
    if (tb_add_rect_(s, o, u, v, nx, nz, up)) { tb_abort_object_(s, obj, vc); return -1; }
    tb_end_object_(s, obj);
    return obj;
}

static sk_vec3 tb_v3_(float x, float y, float z) {
    sk_vec3 r;
    r.x = x; r.y = y; r.z = z;
    return r;
}

/* ---- standard scenes ---- */

int tb_scene_build_ground_boxes(tb_scene *s) {
    if (tb_scene_add_ground(s, "ground", 0, 0, 20, 20, 0, 8, 8) < 0) return -1;
    if (tb_scene_add_box(s, "box0", tb_v3_(-1, 0, -1), tb_v3_(1, 2, 1)) < 0) return -1;
    if (tb_scene_add_box(s, "box1", tb_v3_(3, 0, -4), tb_v3_(5, 4, -2)) < 0) return -1;
    if (tb_scene_add_box(s, "box2", tb_v3_(-6, 0, 2), tb_v3_(-3, 1, 5)) < 0) return -1;
    if (tb_scene_add_box(s, "box3", tb_v3_(-2, 3, 4), tb_v3_(0, 3.5f, 6)) < 0) return -1;
    if (tb_scene_add_box(s, "box4", tb_v3_(6, 0, 5), tb_v3_(6.5f, 6, 5.5f)) < 0) return -1;
    return 0;
}

int tb_scene_build_fence(tb_scene *s) {
    char name[TB_NAME_MAX];
    int i, obj;
    uint32_t vc;
    if (tb_scene_add_ground(s, "ground", 0, 0, 15, 15, 0, 4, 4) < 0) return -1;
    for (i = 0; i <= 20; i++) {
        snprintf(name, sizeof name, "pole%d", i);
        if (tb_scene_add_pole(s, name, -10.0f + (float)i, 0, 0, 0.02f, 2) < 0) return -1;
    }
    vc = s->vertex_count;
    obj = tb_begin_object_(s, "fence");
    if (obj < 0) return -1;
    for (i = 1; i <= 9; i++) {
        float y = 0.2f * (float)i;
        if (tb_add_box_faces_(s, tb_v3_(-10, y - 0.01f, -0.01f), tb_v3_(10, y + 0.01f, 0.01f))) {
            tb_abort_object_(s, obj, vc);
            return -1;
        }
    }
    for (i = 0; i <= 40; i++) {
        float x = -10.0f + 0.5f * (float)i;
        if (tb_add_box_faces_(s, tb_v3_(x - 0.01f, 0, -0.01f), tb_v3_(x + 0.01f, 2, 0.01f))) {
            tb_abort_object_(s, obj, vc);
            return -1;
        }
    }
    tb_end_object_(s, obj);
    for (i = 0; i < 8; i++) {
        snprintf(name, sizeof name, "post%d", i);
        if (tb_scene_add_pole(s, name, -7.0f + 2.0f * (float)i, 0, 4, 0.05f, 3) < 0) return -1;
    }
    return 0;
}

int tb_scene_build_terrace(tb_scene *s) {
    char name[TB_NAME_MAX];
    int k;
    if (tb_scene_add_ground(s, "ground", 0, -100, 6, 100, 0, 4, 100) < 0) return -1;
    for (k = 0; k < 40; k++) {
        float z = -2.5f - 5.0f * (float)k;
        snprintf(name, sizeof name, "postL%d", k);
        if (tb_scene_add_pole(s, name, -5, 0, z, 0.075f, 3) < 0) return -1;
        snprintf(name, sizeof name, "postR%d", k);
        if (tb_scene_add_pole(s, name, 5, 0, z, 0.075f, 3) < 0) return -1;
        snprintf(name, sizeof name, "box%d", k);
        if (tb_scene_add_box(s, name, tb_v3_(-0.5f, 0, z - 0.5f), tb_v3_(0.5f, 1, z + 0.5f)) < 0)
            return -1;
    }
    return 0;
}

static int tb_add_surface_(tb_scene *s, const char *name, const double o[3], const double u[3],
                           const double v[3], const double want[3]) {
    uint32_t vc = s->vertex_count;
    int obj = tb_begin_object_(s, name);
    if (obj < 0) return -1;
    if (tb_add_rect_(s, o, u, v, 4, 4, want)) { tb_abort_object_(s, obj, vc); return -1; }
    tb_end_object_(s, obj);
    return obj;
}

int tb_scene_build_room(tb_scene *s) {
    static const double ex[3] = {10, 0, 0}, ey[3] = {0, 4, 0}, ez[3] = {0, 0, 10};
    static const double px[3] = {1, 0, 0}, nx[3] = {-1, 0, 0};
    static const double py[3] = {0, 1, 0}, ny[3] = {0, -1, 0};
    static const double pz[3] = {0, 0, 1}, nz[3] = {0, 0, -1};
    static const double o0[3] = {-5, 0, -5}, oc[3] = {-5, 4, -5};
    static const double oxp[3] = {5, 0, -5}, ozp[3] = {-5, 0, 5};
    char name[TB_NAME_MAX];
    int i;
    if (tb_add_surface_(s, "floor", o0, ex, ez, py) < 0) return -1;
    if (tb_add_surface_(s, "ceiling", oc, ex, ez, ny) < 0) return -1;
    if (tb_add_surface_(s, "wall_xn", o0, ey, ez, px) < 0) return -1;
    if (tb_add_surface_(s, "wall_xp", oxp, ey, ez, nx) < 0) return -1;
    if (tb_add_surface_(s, "wall_zn", o0, ex, ey, pz) < 0) return -1;
    if (tb_add_surface_(s, "wall_zp", ozp, ex, ey, nz) < 0) return -1;
    for (i = 0; i < 4; i++) {
        float cx = (i & 1) ? 2.5f : -2.5f, cz = (i & 2) ? 2.5f : -2.5f;
        snprintf(name, sizeof name, "pillar%d", i);
        if (tb_scene_add_box(s, name, tb_v3_(cx - 0.3f, 0, cz - 0.3f), tb_v3_(cx + 0.3f, 4, cz + 0.3f)) < 0)
            return -1;
    }
    if (tb_scene_add_box(s, "crate", tb_v3_(0.5f, 0, -1.5f), tb_v3_(1.5f, 0.8f, -0.5f)) < 0) return -1;
    return 0;
}

/* ---- "interior": a multi-room building (see tb_scene.h) ---- */

#define TB_INT_T 0.2f    /* wall thickness, centred on the wall's line */
#define TB_INT_H 3.0f    /* floor (y = 0) to ceiling */

/* an opening in a wall: centre along the wall, width, bottom and top */
typedef struct tb_int_opening { float c, w, y0, y1; } tb_int_opening;

/* the closed box spanning [u0, u1] along the wall and [y0, y1] in height
   of a wall on the line w = c (axis 0: the wall runs along x at z = c;
   axis 2: along z at x = c) */
static int tb_int_wall_box_(tb_scene *s, int axis, float c, float u0, float u1, float y0, float y1) {
    float h = 0.5f * TB_INT_T;
    if (!(u1 > u0) || !(y1 > y0)) return 0;
    if (axis == 0) return tb_add_box_faces_(s, tb_v3_(u0, y0, c - h), tb_v3_(u1, y1, c + h));
    return tb_add_box_faces_(s, tb_v3_(c - h, y0, u0), tb_v3_(c + h, y1, u1));
}

/* one wall segment [u0, u1] on the line c as one object: full-height boxes
   between its openings (sorted along the wall), a sill box below each
   opening that does not reach the floor and a lintel box above it */
static int tb_int_wall_(tb_scene *s, const char *name, int axis, float c, float u0, float u1,
                        const tb_int_opening *op, int n) {
    uint32_t vc = s->vertex_count;
    float at = u0;
    int obj = tb_begin_object_(s, name), i, bad = 0;
    if (obj < 0) return -1;
    for (i = 0; i < n && !bad; i++) {
        float a = op[i].c - 0.5f * op[i].w, b = op[i].c + 0.5f * op[i].w;
        bad |= tb_int_wall_box_(s, axis, c, at, a, 0, TB_INT_H);
        bad |= tb_int_wall_box_(s, axis, c, a, b, 0, op[i].y0);
        bad |= tb_int_wall_box_(s, axis, c, a, b, op[i].y1, TB_INT_H);
        at = b;
    }
    if (!bad) bad |= tb_int_wall_box_(s, axis, c, at, u1, 0, TB_INT_H);
    if (bad) { tb_abort_object_(s, obj, vc); return -1; }
    tb_end_object_(s, obj);
    return obj;
}

/* a table: a top [x0, x1] x [z0, z1] of thickness 0.04 at height h on
   four square legs of side 0.05 set 0.05 in from its corners, one object */
static int tb_int_table_(tb_scene *s, const char *name, float x0, float z0, float x1, float z1, float h) {
    uint32_t vc = s->vertex_count;
    int obj = tb_begin_object_(s, name), k, bad;
    if (obj < 0) return -1;
    bad = tb_add_box_faces_(s, tb_v3_(x0, h - 0.04f, z0), tb_v3_(x1, h, z1));
    for (k = 0; k < 4 && !bad; k++) {
        float x = (k & 1) ? x1 - 0.075f : x0 + 0.075f, z = (k & 2) ? z1 - 0.075f : z0 + 0.075f;
        bad = tb_add_box_faces_(s, tb_v3_(x - 0.025f, 0, z - 0.025f), tb_v3_(x + 0.025f, h - 0.04f, z + 0.025f));
    }
    if (bad) { tb_abort_object_(s, obj, vc); return -1; }
    tb_end_object_(s, obj);
    return obj;
}

/* a floor lamp: a pole of side 0.04 and height h at (x, z) under a shade
   0.3 x 0.25 x 0.3, one object */
static int tb_int_floor_lamp_(tb_scene *s, const char *name, float x, float z, float h) {
    uint32_t vc = s->vertex_count;
    int obj = tb_begin_object_(s, name);
    if (obj < 0) return -1;
    if (tb_add_box_faces_(s, tb_v3_(x - 0.02f, 0, z - 0.02f), tb_v3_(x + 0.02f, h, z + 0.02f)) ||
        tb_add_box_faces_(s, tb_v3_(x - 0.15f, h, z - 0.15f), tb_v3_(x + 0.15f, h + 0.25f, z + 0.15f))) {
        tb_abort_object_(s, obj, vc);
        return -1;
    }
    tb_end_object_(s, obj);
    return obj;
}

/* a bookshelf against the wall x = xw (depth 0.4 into the room, toward
   -x when side < 0), [z0, z1] wide, 2 m high: two uprights and five
   planks 2 cm thick, one object */
static int tb_int_shelf_(tb_scene *s, const char *name, float xw, int side, float z0, float z1) {
    uint32_t vc = s->vertex_count;
    float xa = side < 0 ? xw - 0.4f : xw, xb = side < 0 ? xw : xw + 0.4f;
    int obj = tb_begin_object_(s, name), k, bad;
    if (obj < 0) return -1;
    bad = tb_add_box_faces_(s, tb_v3_(xa, 0, z0), tb_v3_(xb, 2.0f, z0 + 0.02f)) ||
          tb_add_box_faces_(s, tb_v3_(xa, 0, z1 - 0.02f), tb_v3_(xb, 2.0f, z1));
    for (k = 0; k < 5 && !bad; k++) {
        float y = 0.4f * (float)k + (k == 0 ? 0.1f : 0.0f);
        bad = tb_add_box_faces_(s, tb_v3_(xa, y, z0 + 0.02f), tb_v3_(xb, y + 0.02f, z1 - 0.02f));
    }
    if (bad) { tb_abort_object_(s, obj, vc); return -1; }
    tb_end_object_(s, obj);
    return obj;
}

/* the outside ground y = 0 around the building's footprint out to
   +-20 m: four rectangles, one object */
static int tb_int_ground_(tb_scene *s) {
    static const double r[4][4] = {   /* x0, z0, x1, z1 */
        {-20, -20, 20, -7.1}, {-20, 7.1, 20, 20}, {-20, -7.1, -7.6, 7.1}, {7.6, -7.1, 20, 7.1}};
    static const double up[3] = {0, 1, 0};
    uint32_t vc = s->vertex_count;
    int obj = tb_begin_object_(s, "ground"), k;
    if (obj < 0) return -1;
    for (k = 0; k < 4; k++) {
        double o[3], u[3] = {0, 0, 0}, v[3] = {0, 0, 0};
        o[0] = r[k][0]; o[1] = 0; o[2] = r[k][1];
        u[0] = r[k][2] - r[k][0];
        v[2] = r[k][3] - r[k][1];
        if (tb_add_rect_(s, o, u, v, 2, 2, up)) { tb_abort_object_(s, obj, vc); return -1; }
    }
    tb_end_object_(s, obj);
    return obj;
}

int tb_scene_build_interior(tb_scene *s) {
    /* windows: 1.4 m wide, sill 0.9, top 2.1; doors: 2.1 high */
    static const float cols[4] = {-7.6f, -2.5f, 2.5f, 7.6f};   /* the rooms' x spans (exterior walls' outer faces) */
    static const float win_s[3] = {-5.0f, 0.0f, 5.0f}, win_n[3] = {-5.0f, 0.5f, 5.0f};
    static const float door_a[3] = {-4.5f, 0.3f, 4.0f}, door_b[3] = {-5.0f, 0.3f, 5.5f};
    static const float furniture[][6] = {
        /* r0 */ {-7.4f, 0, -6.9f, -5.4f, 0.55f, -4.8f}, {-3.4f, 0, -6.9f, -2.6f, 2.2f, -6.3f},
                 {-5.3f, 0, -6.9f, -4.8f, 0.5f, -6.45f},
        /* r2 */ {3.0f, 0, -6.9f, 5.0f, 0.8f, -6.0f}, {4.5f, 0, -3.0f, 5.1f, 0.6f, -2.4f},
        /* r3 */ {-3.6f, 0, 6.3f, -2.6f, 1.2f, 6.9f}, {-5.0f, 0, 5.6f, -4.4f, 0.5f, 6.2f},
                 {-4.9f, 0.5f, 5.7f, -4.5f, 0.85f, 6.1f},
        /* r4 */ {1.3f, 0, 2.8f, 1.7f, 3.0f, 3.2f},
        /* r5 */ {3.5f, 0, 6.3f, 7.4f, 0.9f, 6.9f}, {2.6f, 0, 5.9f, 3.3f, 1.9f, 6.9f},
                 {4.8f, 0.65f, 5.3f, 5.2f, 0.7f, 5.7f}, {4.97f, 0, 5.47f, 5.03f, 0.65f, 5.53f},
        /* corridor */ {-3.5f, 0, 0.5f, -1.8f, 0.45f, 0.9f}, {6.2f, 0, -0.9f, 6.7f, 0.9f, -0.4f}};
    static const char *const furniture_name[] = {"bed0", "wardrobe0", "nightstand0", "sofa2", "crate2",
                                                 "cabinet3", "boxes3", "boxes3_top", "pillar4", "counter5",
                                                 "fridge5", "stool5_seat", "stool5_leg", "bench_c", "plant_c"};
    char name[TB_NAME_MAX];
    tb_int_opening op[2];
    int c, k;
    /* floors (top y = 0) and ceilings (bottom y = 3), per room and the corridor */
    for (k = 0; k < 7; k++) {
        float x0 = k < 6 ? cols[k % 3] : cols[0], x1 = k < 6 ? cols[k % 3 + 1] : cols[3];
        float z0 = k < 3 ? -7.1f : k < 6 ? 1.0f : -1.0f, z1 = k < 3 ? -1.0f : k < 6 ? 7.1f : 1.0f;
        if (k < 6) snprintf(name, sizeof name, "floor%d", k);
        else snprintf(name, sizeof name, "floor_c");
        if (tb_scene_add_box(s, name, tb_v3_(x0, -0.2f, z0), tb_v3_(x1, 0, z1)) < 0) return -1;
        if (k < 6) snprintf(name, sizeof name, "ceiling%d", k);
        else snprintf(name, sizeof name, "ceiling_c");
        if (tb_scene_add_box(s, name, tb_v3_(x0, TB_INT_H, z0), tb_v3_(x1, TB_INT_H + 0.2f, z1)) < 0) return -1;
    }
    /* exterior walls along x (south z = -7, north z = 7), a window per room */
    for (c = 0; c < 3; c++) {
        op[0].w = 1.4f; op[0].y0 = 0.9f; op[0].y1 = 2.1f;
        op[0].c = win_s[c];
        snprintf(name, sizeof name, "wall_s%d", c);
        if (tb_int_wall_(s, name, 0, -7.0f, cols[c], cols[c + 1], op, 1) < 0) return -1;
        op[0].c = win_n[c];
        snprintf(name, sizeof name, "wall_n%d", c);
        if (tb_int_wall_(s, name, 0, 7.0f, cols[c], cols[c + 1], op, 1) < 0) return -1;
    }
    /* exterior walls along z (west x = -7.5, east x = 7.5): a window in each
       end room, a tall one at each end of the corridor */
    for (k = 0; k < 6; k++) {
        static const float span[4] = {-6.9f, -1.0f, 1.0f, 6.9f}, wc[3] = {-4.0f, 0.0f, 4.0f};
        int part = k % 3;
        op[0].c = wc[part];
        op[0].w = part == 1 ? 1.0f : 1.4f;
        op[0].y0 = part == 1 ? 0.6f : 0.9f;
        op[0].y1 = part == 1 ? 2.4f : 2.1f;
        snprintf(name, sizeof name, "wall_%c%d", k < 3 ? 'w' : 'e', part);
        if (tb_int_wall_(s, name, 2, k < 3 ? -7.5f : 7.5f, span[part], span[part + 1], op, 1) < 0) return -1;
    }
    /* the corridor's walls (z = -1 and z = 1), a door into each room */
    for (c = 0; c < 3; c++) {
        float u0 = c == 0 ? -7.4f : cols[c], u1 = c == 2 ? 7.4f : cols[c + 1];
        op[0].w = 1.0f; op[0].y0 = 0.0f; op[0].y1 = 2.1f;
        op[0].c = door_a[c];
        snprintf(name, sizeof name, "wall_ca%d", c);
        if (tb_int_wall_(s, name, 0, -1.0f, u0, u1, op, 1) < 0) return -1;
        op[0].c = door_b[c];
        snprintf(name, sizeof name, "wall_cb%d", c);
        if (tb_int_wall_(s, name, 0, 1.0f, u0, u1, op, 1) < 0) return -1;
    }
    /* partitions x = -2.5 and x = 2.5: doors r0-r1 and r4-r5, the others solid */
    for (k = 0; k < 4; k++) {
        float x = (k & 1) ? 2.5f : -2.5f, z0 = k < 2 ? -6.9f : 1.1f, z1 = k < 2 ? -1.1f : 6.9f;
        int door = k == 0 || k == 3;
        op[0].c = k == 0 ? -4.0f : 4.0f;
        op[0].w = 0.9f; op[0].y0 = 0.0f; op[0].y1 = 2.1f;
        snprintf(name, sizeof name, "wall_p%d", k);
        if (tb_int_wall_(s, name, 2, x, z0, z1, op, door) < 0) return -1;
    }
    /* furniture: boxes on the floor, most against a wall (contact) */
    for (k = 0; k < (int)(sizeof furniture / sizeof furniture[0]); k++) {
        const float *b = furniture[k];
        if (tb_scene_add_box(s, furniture_name[k], tb_v3_(b[0], b[1], b[2]), tb_v3_(b[3], b[4], b[5])) < 0)
            return -1;
    }
    /* thin objects: table legs, lamp poles, shelf planks, a coat stand */
    if (tb_int_table_(s, "table1", -1.2f, -4.8f, 0.4f, -3.8f, 0.76f) < 0) return -1;
    if (tb_int_table_(s, "chair1", -0.6f, -5.4f, -0.2f, -5.0f, 0.46f) < 0) return -1;
    if (tb_int_table_(s, "desk3", -7.4f, 3.0f, -6.6f, 4.6f, 0.78f) < 0) return -1;
    if (tb_int_table_(s, "table4", -1.6f, 3.8f, -0.4f, 5.0f, 0.76f) < 0) return -1;
    if (tb_int_floor_lamp_(s, "lamp1", 1.9f, -6.4f, 1.6f) < 0) return -1;
    if (tb_int_floor_lamp_(s, "lamp4", -2.0f, 6.4f, 1.7f) < 0) return -1;
    if (tb_int_shelf_(s, "shelf2", 7.4f, -1, -6.4f, -5.2f) < 0) return -1;
    if (tb_scene_add_pole(s, "coat_stand_c", 3.5f, 0, -0.6f, 0.025f, 1.8f) < 0) return -1;
    return tb_int_ground_(s) < 0 ? -1 : 0;
}

int tb_interior_view(int view, sk_vec3 *eye, sk_vec3 *target) {
    /* eye x, z and target x, y, z; the eye at head height */
    static const float v[TB_INTERIOR_VIEWS][5] = {
        {-7.0f, 0.0f, 7.0f, 1.2f, 0.3f},      /* the corridor from its west end, eastward */
        {0.5f, 6.6f, 0.3f, 0.9f, -5.0f},      /* r4 southward through both doors into r1 */
        {-7.1f, -3.3f, 2.0f, 1.0f, -4.6f},    /* r0 eastward through its door into r1 */
        {7.1f, 6.6f, -2.0f, 0.7f, 3.0f},      /* r5's corner westward through its door into r4 */
        {6.6f, -6.6f, 2.5f, 1.0f, 2.5f}};     /* r2's corner north-west through its door, across the corridor */
    if (view < 0 || view >= TB_INTERIOR_VIEWS || !eye || !target) return -1;
    *eye = tb_v3_(v[view][0], 1.7f, v[view][1]);
    *target = tb_v3_(v[view][2], v[view][3], v[view][4]);
    return 0;
}

int tb_interior_light(int light, sk_vec3 *pos, float *radius) {
    static const float l[TB_INTERIOR_LIGHTS][4] = {
        {-5.0f, 2.4f, -3.5f, 8.0f},   /* r0, mid-room */
        {0.8f, 2.5f, -4.5f, 9.0f},    /* r1 */
        {7.1f, 2.2f, -4.0f, 7.0f},    /* r2, 0.3 m from the east wall */
        {-4.5f, 2.0f, 1.5f, 8.0f},    /* r3, 0.4 m from the corridor wall */
        {0.0f, 2.6f, 4.0f, 9.0f},     /* r4 */
        {5.0f, 2.3f, 6.5f, 7.0f}};    /* r5, 0.4 m from the north wall, over the counter */
    if (light < 0 || light >= TB_INTERIOR_LIGHTS || !pos || !radius) return -1;
    *pos = tb_v3_(l[light][0], l[light][1], l[light][2]);
    *radius = l[light][3];
    return 0;
}

int tb_interior_region(sk_vec3 p) {
    int col;
    if (!(p.x >= -7.5f && p.x <= 7.5f && p.z >= -7.0f && p.z <= 7.0f)) return -1;
    if (p.z > -1.0f && p.z < 1.0f) return 6;
    col = p.x < -2.5f ? 0 : p.x < 2.5f ? 1 : 2;
    return p.z <= -1.0f ? col : 3 + col;
}

int tb_scene_build_contact(tb_scene *s) {
    if (tb_scene_add_ground(s, "ground", 0, 0, 10, 10, 0, 1, 1) < 0) return -1;
    if (tb_scene_add_box(s, "box", tb_v3_(-1, 0, -1), tb_v3_(1, 1, 1)) < 0) return -1;
    return 0;
}

/* xorshift32: the open world's fixed sequence (same on every platform) */
static uint32_t tb_xorshift_(uint32_t *st) {
    uint32_t x = *st;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    return *st = x;
}

static float tb_uniform_(uint32_t *st, float a, float b) {
    return a + (b - a) * (float)((double)(tb_xorshift_(st) >> 8) / 16777216.0);
}

/* a point at a distance in [r0, r1] from the origin, uniform in angle and
   in area */
static void tb_annulus_point_(uint32_t *st, float r0, float r1, float *x, float *z) {
    double a = tb_uniform_(st, 0.0f, 6.28318531f);
    double r = sqrt(tb_uniform_(st, r0 * r0, r1 * r1));
    *x = (float)(r * cos(a));
    *z = (float)(r * sin(a));
}

int tb_scene_build_open_world(tb_scene *s) {
    static const float near_box[6][5] = {
        /* x, z, half x, half z, height */
        {3.0f, -4.0f, 0.4f, 0.3f, 1.0f},   {-2.5f, -6.0f, 0.5f, 0.5f, 0.6f}, {5.0f, 5.0f, 0.3f, 0.6f, 1.2f},
        {-6.0f, 3.0f, 0.6f, 0.3f, 0.8f},   {7.5f, -2.0f, 0.3f, 0.3f, 0.5f},  {-1.5f, 8.0f, 0.4f, 0.4f, 1.0f}};
    char name[TB_NAME_MAX];
    uint32_t st = 0x9E3779B9u;
    int i;
    if (tb_scene_add_ground(s, "ground", 0, 0, 1000, 1000, 0, 32, 32) < 0) return -1;
    for (i = 0; i < 6; i++) {
        const float *b = near_box[i];
        snprintf(name, sizeof name, "near%d", i);
        if (tb_scene_add_box(s, name, tb_v3_(b[0] - b[2], 0, b[1] - b[3]), tb_v3_(b[0] + b[2], b[4], b[1] + b[3])) < 0)
            return -1;
    }
    for (i = 0; i < 300; i++) {
        float x, z, hx = tb_uniform_(&st, 4, 15), hz = tb_uniform_(&st, 4, 15), h = tb_uniform_(&st, 6, 40);
        tb_annulus_point_(&st, 40, 950, &x, &z);
        snprintf(name, sizeof name, "bld%d", i);
        if (tb_scene_add_box(s, name, tb_v3_(x - hx, 0, z - hz), tb_v3_(x + hx, h, z + hz)) < 0) return -1;
    }
    for (i = 0; i < 2000; i++) {
        float x, z, h = tb_uniform_(&st, 5, 9);
        /* a quarter of the poles within 100 m: the near and middle field */
        if (i % 4 == 0) tb_annulus_point_(&st, 12, 100, &x, &z);
        else tb_annulus_point_(&st, 12, 950, &x, &z);
        snprintf(name, sizeof name, "pole%d", i);
        if (tb_scene_add_pole(s, name, x, 0, z, 0.15f, h) < 0) return -1;
    }
    return 0;
}

int tb_open_world_view(int view, sk_vec3 *eye, sk_vec3 *target) {
    /* positions (x, z) and headings (degrees from -z toward +x), a pitch of
       a few degrees down: the near boxes, poles and buildings all in view */
    static const float v[TB_OPEN_WORLD_VIEWS][4] = {
        {0, 0, 0, 4},  {1, 1, 72, 3},  {-1, 0.5f, 144, 5},  {0.5f, -1, 216, 3},  {0, 0, 288, 4}};
    double yaw, pitch;
    if (view < 0 || view >= TB_OPEN_WORLD_VIEWS || !eye || !target) return -1;
    yaw = v[view][2] * 3.14159265358979 / 180.0;
    pitch = v[view][3] * 3.14159265358979 / 180.0;
    *eye = tb_v3_(v[view][0], 1.8f, v[view][1]);
    *target = tb_v3_((float)(v[view][0] + 10.0 * sin(yaw) * cos(pitch)), (float)(1.8 - 10.0 * sin(pitch)),
                     (float)(v[view][1] - 10.0 * cos(yaw) * cos(pitch)));
    return 0;
}

int tb_open_world_sun(int view, int sun, sk_vec3 *light_dir) {
    static const float elevation[3] = {45, 20, 8};
    double el, hx, hz, c;
    if (view < 0 || view >= TB_OPEN_WORLD_VIEWS || sun < 0 || sun >= TB_OPEN_WORLD_SUNS || !light_dir) return -1;
    {
        sk_vec3 e, t;
        tb_open_world_view(view, &e, &t);
        hx = t.x - e.x;
        hz = t.z - e.z;
        c = sqrt(hx * hx + hz * hz);
        hx /= c;
        hz /= c;
    }
    if (sun & 1) {   /* across: from the view's right, travelling to its left */
        double t = hx;
        hx = hz;
        hz = -t;
    }
    el = elevation[sun / 2] * 3.14159265358979 / 180.0;
    *light_dir = tb_v3_((float)(hx * cos(el)), (float)(-sin(el)), (float)(hz * cos(el)));
    return 0;
}

/* ---- the forest ---- */

/* The heightfield's analytic height: a valley (flat within 80 m of the
   origin, its sides rising as the square of the distance beyond, 35 m at
   300 m: far hillsides the head-height views see above the near ground)
   plus four sines, 0.25 to 2.5 m, wavelengths of 20 m to 300 m (slopes up
   to about 0.3); only sampled at the grid vertices, the ground between
   them is the mesh's */
static double tb_forest_hf_(double x, double z) {
    double r = sqrt(x * x + z * z), v = (r - 80.0) / 220.0;
    if (v < 0) v = 0;
    if (v > 1) v = 1;
    return 35.0 * v * v + 2.5 * sin(0.021 * x + 0.4) * cos(0.017 * z - 0.3) +
           1.2 * sin(0.047 * x + 0.061 * z + 1.1) + 0.5 * sin(0.13 * x - 0.11 * z + 2.0) + 0.25 * sin(0.29 * x + 0.23 * z);
}

#define TB_FOREST_CELL (2.0 * TB_FOREST_HALF / TB_FOREST_GRID)

/* the mesh's height at grid vertex (i, j), rounded to float as stored */
static float tb_forest_vertex_height_(int i, int j) {
    return (float)tb_forest_hf_(-TB_FOREST_HALF + TB_FOREST_CELL * i, -TB_FOREST_HALF + TB_FOREST_CELL * j);
}

float tb_forest_ground_height(float x, float z) {
    double gx = ((double)x + TB_FOREST_HALF) / TB_FOREST_CELL, gz = ((double)z + TB_FOREST_HALF) / TB_FOREST_CELL;
    double fx, fz, ha, hb, hc, hd;
    int i, j;
    if (gx < 0) gx = 0;
    if (gz < 0) gz = 0;
    if (gx > TB_FOREST_GRID) gx = TB_FOREST_GRID;
    if (gz > TB_FOREST_GRID) gz = TB_FOREST_GRID;
    i = (int)floor(gx);
    j = (int)floor(gz);
    if (i > TB_FOREST_GRID - 1) i = TB_FOREST_GRID - 1;
    if (j > TB_FOREST_GRID - 1) j = TB_FOREST_GRID - 1;
    fx = gx - i;
    fz = gz - j;
    ha = tb_forest_vertex_height_(i, j);
    hb = tb_forest_vertex_height_(i + 1, j);
    hc = tb_forest_vertex_height_(i, j + 1);
    hd = tb_forest_vertex_height_(i + 1, j + 1);
    /* the quad's diagonal runs from (i+1, j) to (i, j+1) (tb_forest_build_ground) */
    if (fx + fz <= 1.0) return (float)(ha + fx * (hb - ha) + fz * (hc - ha));
    return (float)(hd + (1.0 - fx) * (hc - hd) + (1.0 - fz) * (hb - hd));
}

int tb_forest_build_ground(tb_scene *s) {
    const uint32_t n = TB_FOREST_GRID, row = n + 1;
    float *pos = (float *)malloc(sizeof(float) * 3 * row * row);
    uint32_t *idx = (uint32_t *)malloc(sizeof(uint32_t) * 6 * n * n);
    uint32_t i, j, k = 0;
    int r;
    if (!pos || !idx) {
        free(pos);
        free(idx);
        return -1;
    }
    for (j = 0; j <= n; j++)
        for (i = 0; i <= n; i++) {
            float *p = pos + 3 * (j * row + i);
            p[0] = (float)(-TB_FOREST_HALF + TB_FOREST_CELL * i);
            p[1] = tb_forest_vertex_height_((int)i, (int)j);
            p[2] = (float)(-TB_FOREST_HALF + TB_FOREST_CELL * j);
        }
    for (j = 0; j < n; j++)
        for (i = 0; i < n; i++) {
            uint32_t a = j * row + i, b = a + 1, c = a + row, d = c + 1;
            /* (a, c, b) and (b, c, d): counter-clockwise seen from +y */
            idx[k++] = a; idx[k++] = c; idx[k++] = b;
            idx[k++] = b; idx[k++] = c; idx[k++] = d;
        }
    r = tb_scene_add_mesh(s, "ground", pos, row * row, idx, 6 * n * n);
    free(pos);
    free(idx);
    return r < 0 ? -1 : 0;
}

/* The tree in its own frame (base at the origin, +y up, 10.5 m at scale 1):
   a hexagonal trunk, radius 0.25 m tapering to 0.15 m, from 0.5 m below
   the base (it stands on slopes) to 6 m; a crown of leaf cards: three
   vertical cards 6 m wide through the axis (y 3.5 to 10.5 m, 60 degrees
   apart) and four near-horizontal ones (tilted 12 degrees) of 5.5, 4.5,
   3.5 and 2.5 m at y = 4.5, 6.0, 7.5 and 9.0 m, each turned 50 degrees
   from the one below. Each card maps the atlas's leaf half (v in [0, 0.5));
   the cards' u starts differ so that they show different leaves; the
   trunk maps one texel of the bark half. */
#define TB_TREE_SIDES 6
#define TB_TREE_VCARDS 3
#define TB_TREE_HCARDS 4
#define TB_TREE_VERTS (4 * TB_TREE_SIDES + 4 * (TB_TREE_VCARDS + TB_TREE_HCARDS))
#define TB_TREE_INDICES (6 * TB_TREE_SIDES + 6 * (TB_TREE_VCARDS + TB_TREE_HCARDS))

static void tb_set3_(float *p, double x, double y, double z) {
    p[0] = (float)x; p[1] = (float)y; p[2] = (float)z;
}

/* one card: centre c, half axes a (along u) and b (along v), uv u0 + [0,1]
   by [0, 0.5); appends 4 vertices and 2 triangles */
static void tb_tree_card_(float *pos, float *uv, uint32_t *idx, uint32_t *nv, uint32_t *ni, const double c[3],
                          const double a[3], const double b[3], double u0) {
    static const double corner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    uint32_t base = *nv;
    int k;
    for (k = 0; k < 4; k++) {
        double sa = corner[k][0], sb = corner[k][1];
        tb_set3_(pos + 3 * (base + k), c[0] + sa * a[0] + sb * b[0], c[1] + sa * a[1] + sb * b[1],
                 c[2] + sa * a[2] + sb * b[2]);
        uv[2 * (base + k)] = (float)(u0 + 0.5 * (sa + 1.0));
        /* v up to 0.499, not 0.5: the top row stays in the leaf half (a
           vertex exactly on the boundary would sample the bark row) */
        uv[2 * (base + k) + 1] = (float)(0.2495 * (sb + 1.0));
    }
    idx[(*ni)++] = base; idx[(*ni)++] = base + 1; idx[(*ni)++] = base + 2;
    idx[(*ni)++] = base; idx[(*ni)++] = base + 2; idx[(*ni)++] = base + 3;
    *nv += 4;
}

int tb_forest_tree(tb_scene *tree, float **uv_out) {
    float pos[3 * TB_TREE_VERTS], uv[2 * TB_TREE_VERTS];
    uint32_t idx[TB_TREE_INDICES], nv = 0, ni = 0, trunk_ni;
    const double pi = 3.14159265358979323846;
    int k;
    if (!tree || !uv_out) return -1;
    *uv_out = NULL;
    for (k = 0; k < TB_TREE_SIDES; k++) {
        double a0 = 2.0 * pi * k / TB_TREE_SIDES, a1 = 2.0 * pi * (k + 1) / TB_TREE_SIDES;
        uint32_t b = nv;
        int c;
        tb_set3_(pos + 3 * b, 0.25 * cos(a0), -0.5, -0.25 * sin(a0));
        tb_set3_(pos + 3 * (b + 1), 0.25 * cos(a1), -0.5, -0.25 * sin(a1));
        tb_set3_(pos + 3 * (b + 2), 0.15 * cos(a1), 6.0, -0.15 * sin(a1));
        tb_set3_(pos + 3 * (b + 3), 0.15 * cos(a0), 6.0, -0.15 * sin(a0));
        for (c = 0; c < 4; c++) {   /* the middle of a bark texel */
            uv[2 * (b + c)] = (float)(8.5 / TB_FOREST_ALPHA_SIZE);
            uv[2 * (b + c) + 1] = (float)(48.5 / TB_FOREST_ALPHA_SIZE);
        }
        /* counter-clockwise seen from outside: angle grows toward -z */
        idx[ni++] = b; idx[ni++] = b + 1; idx[ni++] = b + 2;
        idx[ni++] = b; idx[ni++] = b + 2; idx[ni++] = b + 3;
        nv += 4;
    }
    trunk_ni = ni;
    for (k = 0; k < TB_TREE_VCARDS; k++) {
        double t = pi * k / TB_TREE_VCARDS, c[3] = {0, 7.0, 0}, a[3], b[3] = {0, 3.5, 0};
        a[0] = 3.0 * cos(t); a[1] = 0; a[2] = 3.0 * sin(t);
        tb_tree_card_(pos, uv, idx, &nv, &ni, c, a, b, 0.31 * k);
    }
    for (k = 0; k < TB_TREE_HCARDS; k++) {
        double half = 0.5 * (5.5 - 1.0 * k), t = (50.0 * k) * pi / 180.0, tilt = 12.0 * pi / 180.0;
        double c[3] = {0, 4.5 + 1.5 * k, 0}, a[3], b[3];
        a[0] = half * cos(t); a[1] = 0; a[2] = half * sin(t);
        /* b: perpendicular in the horizontal plane, tilted up */
        b[0] = -half * sin(t) * cos(tilt); b[1] = half * sin(tilt); b[2] = half * cos(t) * cos(tilt);
        tb_tree_card_(pos, uv, idx, &nv, &ni, c, a, b, 0.17 + 0.23 * k);
    }
    if (tb_scene_add_mesh(tree, "trunk", pos, 4 * TB_TREE_SIDES, idx, trunk_ni) < 0) return -1;
    {
        uint32_t crown[TB_TREE_INDICES], i;
        for (i = trunk_ni; i < ni; i++) crown[i - trunk_ni] = idx[i] - 4 * TB_TREE_SIDES;
        if (tb_scene_add_mesh(tree, "crown", pos + 3 * 4 * TB_TREE_SIDES, nv - 4 * TB_TREE_SIDES, crown,
                              ni - trunk_ni) < 0)
            return -1;
    }
    *uv_out = (float *)malloc(sizeof uv);
    if (!*uv_out) return -1;
    memcpy(*uv_out, uv, sizeof uv);
    return 0;
}

/* xorshift32 of a 32-bit key: the alpha atlas's per-texel and per-cell
   hashes */
static uint32_t tb_hash_(uint32_t k) {
    uint32_t st = k * 0x9E3779B1u + 0x7F4A7C15u;
    tb_xorshift_(&st);
    tb_xorshift_(&st);
    return tb_xorshift_(&st);
}

void tb_forest_alpha(unsigned char *alpha) {
    const int n = TB_FOREST_ALPHA_SIZE;
    int x, y;
    for (y = 0; y < n; y++)
        for (x = 0; x < n; x++) {
            unsigned char a = 255;
            if (y < n / 2) {
                /* the crown's outline: an ellipse over the card, then
                   clusters of 4 x 4 texels (62% kept) with single texels
                   knocked out (15%) */
                double ex = (x + 0.5 - 0.5 * n) / (0.5 * n), ey = (y + 0.5 - 0.25 * n) / (0.25 * n);
                uint32_t cell = tb_hash_((uint32_t)((y / 4) * 1024 + x / 4)), texel = tb_hash_((uint32_t)(y * n + x) + 65536u);
                a = (ex * ex + ey * ey <= 1.0 && cell % 100u < 62u && texel % 100u >= 15u) ? 255 : 0;
            }
            alpha[y * n + x] = a;
        }
}

/* the walking views: eye (x, z), heading (degrees from -z toward +x) and
   pitch (degrees down) */
static const float tb_forest_views_[TB_FOREST_VIEWS][4] = {
    {0, 0, 10, 4}, {9, -12, 95, 6}, {-14, 6, 200, 3}, {18, 14, 300, 5}, {-6, -24, 160, 4}};

static void tb_forest_heading_(int view, double *hx, double *hz) {
    double yaw = tb_forest_views_[view][2] * 3.14159265358979 / 180.0;
    *hx = sin(yaw);
    *hz = -cos(yaw);
}

/* instance transform of a tree (see tb_forest_instances): scaled rotation
   about y then the offset, in float as the vertex hook computes it */
static void tb_forest_apply_(const float *t, const float *p, float *out) {
    out[0] = t[4] * p[0] - t[5] * p[2] + t[0];
    out[1] = t[3] * p[1] + t[1];
    out[2] = t[5] * p[0] + t[4] * p[2] + t[2];
}

void tb_forest_instance_point(const float instance[TB_FOREST_INSTANCE_FLOATS], const float p[3], float out[3]) {
    tb_forest_apply_(instance, p, out);
}

void tb_forest_instances(float *inst) {
    uint32_t st = 0x2545F491u;
    int n = 0;
    while (n < TB_FOREST_TREES) {
        float x, z, scale, yaw;
        int k, ok = 1;
        /* a sixth within 60 m of the origin (where the views walk), a sixth
           from 60 to 150 m, the rest on the valley's sides, 150 to 285 m
           (seen above the near ground and along the trails) */
        if (n % 6 == 0) tb_annulus_point_(&st, 0, 60, &x, &z);
        else if (n % 6 == 1) tb_annulus_point_(&st, 60, 150, &x, &z);
        else tb_annulus_point_(&st, 150, 285, &x, &z);
        scale = tb_uniform_(&st, 0.7f, 1.3f);
        yaw = tb_uniform_(&st, 0.0f, 6.28318531f);
        /* the trails: no trunk within 3.5 m of a view's eye nor of the
           250 m ahead of it; none within 3 m of another trunk */
        for (k = 0; k < TB_FOREST_VIEWS && ok; k++) {
            double hx, hz, dx = x - tb_forest_views_[k][0], dz = z - tb_forest_views_[k][1], along, across;
            tb_forest_heading_(k, &hx, &hz);
            along = dx * hx + dz * hz;
            across = fabs(dz * hx - dx * hz);
            if (along > 250.0) along -= 250.0;
            else if (along > 0.0) along = 0.0;
            if (along * along + across * across < 3.5 * 3.5) ok = 0;
        }
        for (k = 0; k < n && ok; k++) {
            float dx = x - inst[TB_FOREST_INSTANCE_FLOATS * k], dz = z - inst[TB_FOREST_INSTANCE_FLOATS * k + 2];
            if (dx * dx + dz * dz < 3.0f * 3.0f) ok = 0;
        }
        if (!ok) continue;
        {
            float *t = inst + TB_FOREST_INSTANCE_FLOATS * n;
            t[0] = x;
            t[1] = tb_forest_ground_height(x, z);
            t[2] = z;
            t[3] = scale;
            t[4] = (float)(scale * cos(yaw));
            t[5] = (float)(scale * sin(yaw));
        }
        n++;
    }
}

int tb_scene_build_forest(tb_scene *s) {
    tb_scene tree;
    float *uv = NULL, *inst, *pos;
    uint32_t nv, k, i;
    char name[TB_NAME_MAX];
    int r = 0;
    if (tb_forest_build_ground(s) != 0) return -1;
    tb_scene_init(&tree);
    inst = (float *)malloc(sizeof(float) * TB_FOREST_INSTANCE_FLOATS * TB_FOREST_TREES);
    if (!inst || tb_forest_tree(&tree, &uv) != 0) {
        free(inst);
        tb_scene_free(&tree);
        return -1;
    }
    tb_forest_instances(inst);
    nv = tree.vertex_count;
    pos = (float *)malloc(sizeof(float) * 3 * nv);
    for (k = 0; pos && k < TB_FOREST_TREES && r == 0; k++) {
        for (i = 0; i < nv; i++) tb_forest_apply_(inst + TB_FOREST_INSTANCE_FLOATS * k, tree.positions + 3 * i, pos + 3 * i);
        snprintf(name, sizeof name, "tree%u", (unsigned)k);
        if (tb_scene_add_mesh(s, name, pos, nv, tree.indices, tree.index_count) < 0) r = -1;
    }
    if (!pos) r = -1;
    free(pos);
    free(inst);
    free(uv);
    tb_scene_free(&tree);
    return r;
}

int tb_forest_uv(const tb_scene *s, float **uv_out, unsigned *first_tri, unsigned *tri_count) {
    tb_scene tree;
    float *tuv = NULL, *uv;
    uint32_t ground_nv = (TB_FOREST_GRID + 1) * (TB_FOREST_GRID + 1), i;
    if (!s || !uv_out || !first_tri || !tri_count) return -1;
    *uv_out = NULL;
    tb_scene_init(&tree);
    if (tb_forest_tree(&tree, &tuv) != 0) {
        tb_scene_free(&tree);
        return -1;
    }
    /* the layout tb_scene_build_forest makes: the ground, then every tree */
    if (s->object_count != 1 + TB_FOREST_TREES || s->vertex_count != ground_nv + TB_FOREST_TREES * tree.vertex_count ||
        s->index_count != s->objects[0].index_count + TB_FOREST_TREES * tree.index_count) {
        free(tuv);
        tb_scene_free(&tree);
        return -1;
    }
    uv = (float *)calloc(2 * (size_t)s->vertex_count, sizeof(float));
    if (uv)
        for (i = 0; i < TB_FOREST_TREES * tree.vertex_count; i++) {
            uv[2 * (ground_nv + i)] = tuv[2 * (i % tree.vertex_count)];
            uv[2 * (ground_nv + i) + 1] = tuv[2 * (i % tree.vertex_count) + 1];
        }
    *first_tri = s->objects[0].index_count / 3;
    *tri_count = TB_FOREST_TREES * tree.index_count / 3;
    free(tuv);
    tb_scene_free(&tree);
    *uv_out = uv;
    return uv ? 0 : -1;
}

int tb_forest_view(int view, sk_vec3 *eye, sk_vec3 *target) {
    double hx, hz, pitch;
    float x, z, y;
    if (view < 0 || view >= TB_FOREST_VIEWS || !eye || !target) return -1;
    x = tb_forest_views_[view][0];
    z = tb_forest_views_[view][1];
    y = tb_forest_ground_height(x, z) + 1.7f;
    pitch = tb_forest_views_[view][3] * 3.14159265358979 / 180.0;
    tb_forest_heading_(view, &hx, &hz);
    *eye = tb_v3_(x, y, z);
    *target = tb_v3_((float)(x + 10.0 * hx * cos(pitch)), (float)(y - 10.0 * sin(pitch)),
                     (float)(z + 10.0 * hz * cos(pitch)));
    return 0;
}

int tb_forest_sun(int view, int sun, sk_vec3 *light_dir) {
    static const float elevation[3] = {45, 20, 8};
    double el, hx, hz;
    if (view < 0 || view >= TB_FOREST_VIEWS || sun < 0 || sun >= TB_FOREST_SUNS || !light_dir) return -1;
    tb_forest_heading_(view, &hx, &hz);
    if (sun & 1) {   /* ahead of the viewer: the light travels toward the camera */
        hx = -hx;
        hz = -hz;
    }
    el = elevation[sun / 2] * 3.14159265358979 / 180.0;
    *light_dir = tb_v3_((float)(hx * cos(el)), (float)(-sin(el)), (float)(hz * cos(el)));
    return 0;
}

int tb_scene_build(tb_scene *s, const char *name) {
    if (!name) return -1;
    if (strcmp(name, "ground-boxes") == 0) return tb_scene_build_ground_boxes(s);
    if (strcmp(name, "fence") == 0) return tb_scene_build_fence(s);
    if (strcmp(name, "terrace") == 0) return tb_scene_build_terrace(s);
    if (strcmp(name, "room") == 0) return tb_scene_build_room(s);
    if (strcmp(name, "interior") == 0) return tb_scene_build_interior(s);
    if (strcmp(name, "contact") == 0) return tb_scene_build_contact(s);
    if (strcmp(name, "open-world") == 0) return tb_scene_build_open_world(s);
    if (strcmp(name, "forest") == 0) return tb_scene_build_forest(s);
    return -1;
}

/* ---- assimp ---- */

int tb_scene_load(tb_scene *s, const char *path) {
    const struct aiScene *sc;
    unsigned m;
    sc = aiImportFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                aiProcess_GenSmoothNormals | aiProcess_PreTransformVertices);
    if (!sc) {
        fprintf(stderr, "tb_scene_load: %s: %s\n", path, aiGetErrorString());
        return -1;
    }
    for (m = 0; m < sc->mNumMeshes; m++) {
        const struct aiMesh *mesh = sc->mMeshes[m];
        uint32_t base = s->vertex_count, vc = s->vertex_count, ntri = 0;
        char name[TB_NAME_MAX];
        unsigned f, v;
        int obj;
        const char *nm = name;
        if (!(mesh->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
        for (f = 0; f < mesh->mNumFaces; f++)
            if (mesh->mFaces[f].mNumIndices == 3) ntri++;
        if (ntri == 0) continue;
        snprintf(name, sizeof name, "mesh%u", m);
        if (mesh->mName.length > 0) nm = mesh->mName.data;   /* truncated to TB_NAME_MAX-1 */
        obj = tb_begin_object_(s, nm);
        if (obj < 0 || tb_reserve_(s, mesh->mNumVertices, (uint64_t)ntri * 3)) {
            if (obj >= 0) tb_abort_object_(s, obj, vc);
            aiReleaseImport(sc);
            return -1;
        }
        for (v = 0; v < mesh->mNumVertices; v++) {
            float *p = s->positions + 3 * (size_t)(base + v);
            float *n = s->normals + 3 * (size_t)(base + v);
            p[0] = mesh->mVertices[v].x;
            p[1] = mesh->mVertices[v].y;
            p[2] = mesh->mVertices[v].z;
            if (mesh->mNormals) {
                double len;
                n[0] = mesh->mNormals[v].x;
                n[1] = mesh->mNormals[v].y;
                n[2] = mesh->mNormals[v].z;
                len = sqrt((double)n[0] * n[0] + (double)n[1] * n[1] + (double)n[2] * n[2]);
                if (len > 0 && len == len) {
                    n[0] = (float)(n[0] / len); n[1] = (float)(n[1] / len); n[2] = (float)(n[2] / len);
                } else {
                    n[0] = 0; n[1] = 1; n[2] = 0;   /* degenerate: any unit vector */
                }
            } else {
                n[0] = 0; n[1] = 1; n[2] = 0;
            }
        }
        s->vertex_count += mesh->mNumVertices;
        for (f = 0; f < mesh->mNumFaces; f++) {
            const struct aiFace *face = &mesh->mFaces[f];
            uint32_t *t;
            if (face->mNumIndices != 3) continue;
            t = s->indices + s->index_count;
            t[0] = base + face->mIndices[0];
            t[1] = base + face->mIndices[1];
            t[2] = base + face->mIndices[2];
            s->index_count += 3;
        }
        tb_end_object_(s, obj);
    }
    aiReleaseImport(sc);
    return 0;
}
