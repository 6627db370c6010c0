/* tb_closed_form.c - see tb_closed_form.h */
#include "tb_closed_form.h"

#include <math.h>
#include <string.h>

#define TB_CF_GROUND_HALF 40.0
#define TB_CF_GROUND_QUADS 8

/* surfaces: the ground, box k, the plate */
enum { TB_CF_GROUND = 0, TB_CF_BOX = 1, TB_CF_QUAD = 2 };

static sk_vec3 tb_cf_v3_(double x, double y, double z) {
    sk_vec3 r;
    r.x = (float)x; r.y = (float)y; r.z = (float)z;
    return r;
}

static void tb_cf_ground_(tb_cf_scene *cf) {
    memset(cf, 0, sizeof *cf);
    cf->ground_min[0] = cf->ground_min[1] = -TB_CF_GROUND_HALF;
    cf->ground_max[0] = cf->ground_max[1] = TB_CF_GROUND_HALF;
}

static int tb_cf_add_ground_(tb_scene *s) {
    return tb_scene_add_ground(s, "ground", 0, 0, (float)TB_CF_GROUND_HALF, (float)TB_CF_GROUND_HALF, 0,
                               TB_CF_GROUND_QUADS, TB_CF_GROUND_QUADS) < 0 ? -1 : 0;
}

/* a box in both descriptions */
static int tb_cf_add_box_(tb_scene *s, tb_cf_scene *cf, const char *name, const double mn[3], const double mx[3]) {
    tb_cf_box *b;
    if (cf->box_count >= TB_CF_MAX_BOXES) return -1;
    if (tb_scene_add_box(s, name, tb_cf_v3_(mn[0], mn[1], mn[2]), tb_cf_v3_(mx[0], mx[1], mx[2])) < 0) return -1;
    b = &cf->boxes[cf->box_count++];
    memcpy(b->min, mn, sizeof b->min);
    memcpy(b->max, mx, sizeof b->max);
    return 0;
}

int tb_cf_build_plate(tb_scene *s, tb_cf_scene *cf) {
    if (!s || !cf) return -1;
    tb_cf_ground_(cf);
    if (tb_cf_add_ground_(s)) return -1;
    /* the plate: a one-quad "ground" at y = 1 (two triangles, facing +y;
       both sides are drawn and traced, neither is culled) */
    if (tb_scene_add_ground(s, "plate", 0, 0, 1, 1, 1, 1, 1) < 0) return -1;
    cf->has_quad = 1;
    cf->quad.y = 1;
    cf->quad.min_x = cf->quad.min_z = -1;
    cf->quad.max_x = cf->quad.max_z = 1;
    return 0;
}

int tb_cf_build_pole(tb_scene *s, tb_cf_scene *cf) {
    static const double mn[3] = {-0.0625, 0, -0.0625}, mx[3] = {0.0625, 3, 0.0625};
    if (!s || !cf) return -1;
    tb_cf_ground_(cf);
    if (tb_cf_add_ground_(s)) return -1;
    return tb_cf_add_box_(s, cf, "pole", mn, mx);
}

int tb_cf_build_box(tb_scene *s, tb_cf_scene *cf) {
    static const double mn[3] = {-1, 0, -0.75}, mx[3] = {1, 1.5, 0.75};
    if (!s || !cf) return -1;
    tb_cf_ground_(cf);
    if (tb_cf_add_ground_(s)) return -1;
    return tb_cf_add_box_(s, cf, "box", mn, mx);
}

int tb_cf_build(tb_scene *s, tb_cf_scene *cf, const char *name) {
    if (!name) return -1;
    if (strcmp(name, "plate") == 0) return tb_cf_build_plate(s, cf);
    if (strcmp(name, "pole") == 0) return tb_cf_build_pole(s, cf);
    if (strcmp(name, "box") == 0) return tb_cf_build_box(s, cf);
    return -1;
}

/* ---- intersections ---- */

static double tb_cf_dot_(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* Slab test of the ray o + t d against box b: entry and exit parameters,
   the axis of the entry face. 0 when the ray's line misses the box. */
static int tb_cf_slab_(const tb_cf_box *b, const double o[3], const double d[3], double *t_in, double *t_out,
                       int *axis) {
    double lo = -INFINITY, hi = INFINITY;
    int ax, in_ax = -1;
    for (ax = 0; ax < 3; ax++) {
        double t0, t1;
        if (d[ax] == 0) {
            if (o[ax] < b->min[ax] || o[ax] > b->max[ax]) return 0;
            continue;
        }
        t0 = (b->min[ax] - o[ax]) / d[ax];
        t1 = (b->max[ax] - o[ax]) / d[ax];
        if (t0 > t1) { double t = t0; t0 = t1; t1 = t; }
        if (t0 > lo) { lo = t0; in_ax = ax; }
        if (t1 < hi) hi = t1;
    }
    if (!(lo <= hi)) return 0;
    *t_in = lo;
    *t_out = hi;
    *axis = in_ax;
    return 1;
}

/* ray against the horizontal rectangle y = y0, x in [x0,x1], z in [z0,z1]:
   its parameter (> t_min), or -1 */
static double tb_cf_hplane_(const double o[3], const double d[3], double y0, double x0, double x1, double z0,
                            double z1) {
    double t, x, z;
    if (d[1] == 0) return -1;
    t = (y0 - o[1]) / d[1];
    if (!(t >= 0)) return -1;
    x = o[0] + t * d[0];
    z = o[2] + t * d[2];
    if (x < x0 || x > x1 || z < z0 || z > z1) return -1;
    return t;
}

/* Is the open segment o + t d, 0 < t < t_max, blocked by a surface other
   than the receiver (kind, index)? */
static int tb_cf_blocked_(const tb_cf_scene *cf, const double o[3], const double d[3], double t_max, int kind,
                          int index) {
    int k;
    double t;
    if (kind != TB_CF_GROUND && d[1] < 0) {
        t = tb_cf_hplane_(o, d, 0.0, cf->ground_min[0], cf->ground_max[0], cf->ground_min[1], cf->ground_max[1]);
        if (t > 0 && t < t_max) return 1;
    }
    if (cf->has_quad && kind != TB_CF_QUAD) {
        t = tb_cf_hplane_(o, d, cf->quad.y, cf->quad.min_x, cf->quad.max_x, cf->quad.min_z, cf->quad.max_z);
        if (t > 0 && t < t_max) return 1;
    }
    for (k = 0; k < cf->box_count; k++) {
        double t0, t1;
        int ax;
        if (kind == TB_CF_BOX && index == k) continue;   /* convex: cannot shadow itself */
        if (!tb_cf_slab_(&cf->boxes[k], o, d, &t0, &t1, &ax)) continue;
        if (t0 < 0) t0 = 0;
        if (t1 > t_max) t1 = t_max;
        if (t0 < t1) return 1;
    }
    return 0;
}

/* the nearest surface on the camera ray a + t D, t in [0, 1]: 1 and the
   exact point, the camera-facing unit normal and which surface; 0 none */
static int tb_cf_primary_(const tb_cf_scene *cf, const double a[3], const double D[3], double p[3], double n[3],
                          int *kind, int *index) {
    double best = INFINITY, t;
    int k, found = 0;
    t = tb_cf_hplane_(a, D, 0.0, cf->ground_min[0], cf->ground_max[0], cf->ground_min[1], cf->ground_max[1]);
    if (t >= 0 && t <= 1 && t < best) {
        best = t; *kind = TB_CF_GROUND; *index = 0; found = 1;
        n[0] = 0; n[1] = 1; n[2] = 0;
    }
    if (cf->has_quad) {
        t = tb_cf_hplane_(a, D, cf->quad.y, cf->quad.min_x, cf->quad.max_x, cf->quad.min_z, cf->quad.max_z);
        if (t >= 0 && t <= 1 && t < best) {
            best = t; *kind = TB_CF_QUAD; *index = 0; found = 1;
            n[0] = 0; n[1] = 1; n[2] = 0;
        }
    }
    for (k = 0; k < cf->box_count; k++) {
        double t0, t1;
        int ax;
        if (!tb_cf_slab_(&cf->boxes[k], a, D, &t0, &t1, &ax) || ax < 0) continue;
        if (t0 >= 0 && t0 <= 1 && t0 < best) {
            best = t0; *kind = TB_CF_BOX; *index = k; found = 1;
            n[0] = n[1] = n[2] = 0;
            n[ax] = 1;
        }
    }
    if (!found) return 0;
    p[0] = a[0] + best * D[0];
    p[1] = a[1] + best * D[1];
    p[2] = a[2] + best * D[2];
    if (tb_cf_dot_(n, D) > 0) { n[0] = -n[0]; n[1] = -n[1]; n[2] = -n[2]; }
    /* snap onto the face's plane: the exact point of the analytic surface */
    if (*kind == TB_CF_GROUND) p[1] = 0;
    else if (*kind == TB_CF_QUAD) p[1] = cf->quad.y;
    else {
        const tb_cf_box *b = &cf->boxes[*index];
        int ax = n[0] != 0 ? 0 : (n[1] != 0 ? 1 : 2);
        p[ax] = (D[ax] > 0) ? b->min[ax] : b->max[ax];
    }
    return 1;
}

static int tb_cf_v3ok_(sk_vec3 v) { return isfinite(v.x) && isfinite(v.y) && isfinite(v.z); }

/* the supported rect light: horizontal, half axes along x and z, above the
   plate of a scene without boxes; fills the light's x and z ranges */
static int tb_cf_rect_ok_(const tb_cf_scene *cf, const tb_light *L, double lx[2], double lz[2]) {
    double ux = fabs((double)L->half_u.x), uz = fabs((double)L->half_u.z);
    double vx = fabs((double)L->half_v.x), vz = fabs((double)L->half_v.z);
    double hx, hz;
    if (!cf->has_quad || cf->box_count != 0) return 0;
    if (L->half_u.y != 0 || L->half_v.y != 0) return 0;
    if (ux > 0 && uz == 0 && vx == 0 && vz > 0) { hx = ux; hz = vz; }
    else if (uz > 0 && ux == 0 && vz == 0 && vx > 0) { hx = vx; hz = uz; }
    else return 0;
    if (!((double)L->position.y > cf->quad.y) || !(cf->quad.y > 0)) return 0;
    lx[0] = (double)L->position.x - hx; lx[1] = (double)L->position.x + hx;
    lz[0] = (double)L->position.z - hz; lz[1] = (double)L->position.z + hz;
    return 1;
}

/* one receiver point */
static float tb_cf_shade_(const tb_cf_scene *cf, const tb_light *L, const double p[3], const double n[3], int kind,
                          int index, const double lx[2], const double lz[2]) {
    if (L->type == TB_LIGHT_DIRECTIONAL) {
        double d[3];
        d[0] = -(double)L->direction.x; d[1] = -(double)L->direction.y; d[2] = -(double)L->direction.z;
        if (tb_cf_dot_(n, d) <= 0) return TB_VIS_BACKFACING;
        return tb_cf_blocked_(cf, p, d, INFINITY, kind, index) ? 0.0f : 1.0f;
    }
    if (L->type == TB_LIGHT_POINT) {
        double d[3];
        d[0] = (double)L->position.x - p[0]; d[1] = (double)L->position.y - p[1]; d[2] = (double)L->position.z - p[2];
        if (L->range > 0 && sqrt(tb_cf_dot_(d, d)) > L->range) return TB_VIS_OUT_OF_RANGE;
        if (tb_cf_dot_(n, d) <= 0) return TB_VIS_BACKFACING;
        return tb_cf_blocked_(cf, p, d, 1.0, kind, index) ? 0.0f : 1.0f;
    }
    {
        /* rect light: horizontal at height h above every receiver that
           faces it; receivers are horizontal (ground, plate) */
        double h = L->position.y, k, x0, x1, z0, z1, ox, oz, area;
        if (n[1] <= 0 || !(h > p[1])) return TB_VIS_BACKFACING;
        if (kind != TB_CF_GROUND) return 1.0f;   /* the plate top: nothing above it */
        k = (h - p[1]) / (cf->quad.y - p[1]);
        x0 = p[0] + (cf->quad.min_x - p[0]) * k;
        x1 = p[0] + (cf->quad.max_x - p[0]) * k;
        z0 = p[2] + (cf->quad.min_z - p[2]) * k;
        z1 = p[2] + (cf->quad.max_z - p[2]) * k;
        ox = fmin(x1, lx[1]) - fmax(x0, lx[0]);
        oz = fmin(z1, lz[1]) - fmax(z0, lz[0]);
        if (ox <= 0 || oz <= 0) return 1.0f;
        area = (lx[1] - lx[0]) * (lz[1] - lz[0]);
        {
            double v = 1.0 - ox * oz / area;
            return (float)(v < 0 ? 0 : (v > 1 ? 1 : v));
        }
    }
}

/* the visibility loop; cone: NULL, or a spot's unit axis and the cosine of
   its half-angle (receivers outside the cone get 0) */
static int tb_cf_trace_(const tb_cf_scene *cf, const tb_view *view, const tb_light *light, const double *cone,
                        float *vis) {
    double lx[2] = {0, 0}, lz[2] = {0, 0};
    int x, y, k;
    if (!cf || !view || !light || !vis || view->width <= 0 || view->height <= 0) return -1;
    if (cf->box_count < 0 || cf->box_count > TB_CF_MAX_BOXES) return -1;
    for (k = 0; k < 16; k++)
        if (!isfinite(view->inv_view_proj.m[k])) return -1;
    switch (light->type) {
    case TB_LIGHT_DIRECTIONAL:
        if (!tb_cf_v3ok_(light->direction) ||
            !(light->direction.x != 0 || light->direction.y != 0 || light->direction.z != 0))
            return -1;
        break;
    case TB_LIGHT_POINT:
        if (!tb_cf_v3ok_(light->position) || isnan(light->range)) return -1;
        break;
    case TB_LIGHT_RECT:
        if (!tb_cf_v3ok_(light->position) || !tb_cf_v3ok_(light->half_u) || !tb_cf_v3ok_(light->half_v) ||
            !tb_cf_rect_ok_(cf, light, lx, lz))
            return -1;
        break;
    default:
        return -1;
    }
    for (y = 0; y < view->height; y++)
        for (x = 0; x < view->width; x++) {
            size_t i = (size_t)y * (size_t)view->width + (size_t)x;
            double a[3], b[3], D[3], p[3], n[3];
            int kind = 0, index = 0;
            if (tb_unproject_pixel(&view->inv_view_proj, view->width, view->height, x, y, 0.0f, a) ||
                tb_unproject_pixel(&view->inv_view_proj, view->width, view->height, x, y, 1.0f, b)) {
                vis[i] = TB_VIS_BACKGROUND;
                continue;
            }
            D[0] = b[0] - a[0]; D[1] = b[1] - a[1]; D[2] = b[2] - a[2];
            if (!tb_cf_primary_(cf, a, D, p, n, &kind, &index)) {
                vis[i] = TB_VIS_BACKGROUND;
                continue;
            }
            vis[i] = tb_cf_shade_(cf, light, p, n, kind, index, lx, lz);
            if (cone && vis[i] > 0) {
                double d[3], len;
                d[0] = p[0] - (double)light->position.x;
                d[1] = p[1] - (double)light->position.y;
                d[2] = p[2] - (double)light->position.z;
                len = sqrt(tb_cf_dot_(d, d));
                if (!(tb_cf_dot_(d, cone) > cone[3] * len)) vis[i] = 0.0f;
            }
        }
    return 0;
}

int tb_cf_visibility(const tb_cf_scene *cf, const tb_view *view, const tb_light *light, float *vis) {
    return tb_cf_trace_(cf, view, light, NULL, vis);
}

int tb_cf_spot_visibility(const tb_cf_scene *cf, const tb_view *view, const tb_light *light, sk_vec3 axis,
                          double half_angle_deg, float *vis) {
    double cone[4], len;
    if (!light || light->type != TB_LIGHT_POINT || !tb_cf_v3ok_(axis) || !(half_angle_deg > 0) ||
        !(half_angle_deg < 90))
        return -1;
    cone[0] = axis.x; cone[1] = axis.y; cone[2] = axis.z;
    len = sqrt(tb_cf_dot_(cone, cone));
    if (!(len > 0)) return -1;
    cone[0] /= len; cone[1] /= len; cone[2] /= len;
    cone[3] = cos(half_angle_deg * 3.14159265358979323846 / 180.0);
    return tb_cf_trace_(cf, view, light, cone, vis);
}
