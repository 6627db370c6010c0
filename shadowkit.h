/* shadowkit.h - v0.1.0 - public domain / MIT - CPU-side math for shadow mapping

   Single-header C99 library (compiles as C++ too) with the math behind the
   shadow-mapping methods of five papers: crop matrices and parallel splits,
   perspective (PSM) and light-space perspective (LiSPSM) warping, Light Space
   Partitioned Shadow Maps, omnidirectional cube-map culling and the Virtual
   Shadow Depth Cube Texture, Ferko's resolution estimation, and the
   prediction and filtering pieces of Predicted Virtual Soft Shadow Maps.
   The OpenGL passes that use it live in shadowkit_gl.h.

   USAGE
     In exactly one C or C++ file:
         #define SHADOWKIT_IMPLEMENTATION
         #include "shadowkit.h"
     Everywhere else, include it without the define. To keep every symbol
     private to one translation unit, define SHADOWKIT_STATIC as well (then
     each translation unit that defines SHADOWKIT_IMPLEMENTATION gets its own
     static copy; define it before the file's first #include of the header).
     A file that defines SHADOWKIT_STATIC without the implementation has no
     copy: it gets the types and constants, and plain extern declarations
     that it must not call (static ones never defined would make GCC warn).

     Override before the implementation is included, if you like:
         SK_ASSERT(x)            default assert(x) from <assert.h>
         SK_SQRTF, SK_FABSF, SK_FLOORF, SK_CEILF       float math (hot loops)
         SK_SQRT, SK_FABS, SK_FLOOR, SK_CEIL, SK_LOG2, SK_POW, SK_TAN, SK_ATAN,
         SK_COS, SK_FREXP, SK_LDEXP                    double math
                                 all default to the <math.h> functions
         SKDEF                   default extern (static with SHADOWKIT_STATIC
                                 and SHADOWKIT_IMPLEMENTATION)

   CONVENTIONS
     - No allocation, no global mutable state, no I/O, no GL. Callers pass
       buffers and their capacities. Every function is thread-safe on
       distinct data.
     - Matrices are column-major (m[col*4 + row]), right-handed, OpenGL clip
       space: NDC x, y, z in [-1,1]; window depth is 0.5*z_ndc + 0.5.
       Points transform as column vectors, M * p.
     - Angles are radians. "Light clip space" is the NDC of a light's
       view-projection.
     - Functions that can fail return sk_result (or a count, negated sk_result
       on failure). Bad input (NaN/Inf, sizes or counts <= 0, far <= near,
       counts out of range, NULL where a pointer is required) yields
       SK_ERR_INVALID_ARG and writes nothing else unless documented.
       Functions that return a value directly document their fallback for bad
       input; none returns NaN.
     - A light direction is the direction the light TRAVELS (from the light
       towards the scene), need not be normalised.

   SECTIONS (in the order of the header). A technique's section has the
   number of shadowkit_gl.h's section for the same technique (6.2 fits,
   6.3 FERKO, 6.4 RMSM, 7 point lights, 9 area lights); the math both
   share is A and B. Each has a declarations banner and an implementation
   banner; the implementation's opens with an anchor, a line of its own
   "// >>name" (search for it; shadowkit_gl.h anchors its part of the same
   technique alike: >>fits for all of 6.2, >>point, >>ferko, >>soft, >>rmsm):
     A.   Core math               matrices, frusta, convex clipping     >>core
     B.   Aliasing analysis       (Romanick's VGP353 notes: aliasing    >>aliasing
                                  error d, RMSM LOD)
     6.2a Crops and PSSM          Ferko 2013; Zhang et al. 2006 (crop   >>fits
                                  matrix, practical split scheme,
                                  focused and texel-snapped stable crops)
     6.2b PSM and LiSPSM          (Stamminger & Drettakis 2002;         >>warps
                                  Wimmer, Scherzer & Purgathofer 2004)
     6.2c LSPSM                   (Tang et al. 2017, Eq. 1)             >>lspsm
     7.   Omnidirectional lights  (King & Newhall 2004, Eqs. 5.4.6-     >>point
                                  5.4.7, HalfIntersection, caster
                                  culling, scissor, resolution, VSDCT)
     6.3  Resolution estimation   (Ferko 2013, Sec. 3.1-3.2)            >>ferko
     9.   PVSM                    (Shen et al. 2011, Eqs. 4-5, rho(n),  >>soft
                                  appendix convolution, SMTG, kd-tree
                                  tiles, V*A/A merge)
     6.4  RMSM pages              (Lefohn et al. 2007 page requests)    >>rmsm

   REFERENCES
     Ferko 2013, "Resolution Estimation for Shadow Mapping".
     Shen, Guennebaud, Yang and Feng 2011, "Predicted Virtual Soft Shadow
       Maps with High Quality Filtering" (PVSM).
     Romanick, VGP353 course notes (aliasing, PSM, PSSM, RMSM), after:
       Stamminger and Drettakis 2002, "Perspective Shadow Maps"; Wimmer,
       Scherzer and Purgathofer 2004, "Light Space Perspective Shadow Maps";
       Zhang, Sun, Xu and Lun 2006, "Parallel-Split Shadow Maps"; Lefohn,
       Sengupta and Owens 2007, "Resolution-Matched Shadow Maps".
     Tang, Luo, Ni, Duan and Gao 2017, "Light Space Partitioned Shadow Maps".
     King and Newhall 2004, "Efficient Omnidirectional Shadow Maps" (VSDCT).

   QUICK START (directional light, one focused map)
       sk_mat4 cam_vp = sk_mat4_mul(cam_proj, cam_view);
       sk_frustum view = sk_frustum_from_matrix(cam_vp);
       sk_vec3 pts[SK_CLIP_MAX_POINTS];
       int n = sk_clip_frustum_aabb(&view, scene_box, pts, SK_CLIP_MAX_POINTS);
       sk_mat4 lview = sk_light_view_directional(light_dir);
       sk_mat4 lproj;
       if (n > 0 && sk_fit_ortho(pts, n, lview, &scene_box, &lproj) == SK_OK)
           light_vp = sk_mat4_mul(lproj, lview);   render depth with light_vp

   LICENSE: see the end of the file.
*/
#ifndef SHADOWKIT_H
#define SHADOWKIT_H

/* the release (shadowkit_gl.h checks that it is its own; CMakeLists.txt and
   shadowkit.pc take their version from these three lines) */
#define SHADOWKIT_VERSION_MAJOR 0
#define SHADOWKIT_VERSION_MINOR 1
#define SHADOWKIT_VERSION_PATCH 0

#ifndef SKDEF
#if defined(SHADOWKIT_STATIC) && !defined(SHADOWKIT_IMPLEMENTATION)
/* no copy of the implementation here: declarations only (see USAGE) */
#define SKDEF extern
#define SK__STATIC_WITHOUT_IMPLEMENTATION 1
#elif defined(SHADOWKIT_STATIC)
#if defined(__GNUC__) || defined(__clang__)
#define SKDEF static __attribute__((unused))
#else
#define SKDEF static
#endif
#else
#define SKDEF extern
#endif
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* =========================================================================
   A. Core math
   ========================================================================= */
typedef struct sk_vec2 { float x, y; } sk_vec2;
typedef struct sk_vec3 { float x, y, z; } sk_vec3;
typedef struct sk_vec4 { float x, y, z, w; } sk_vec4;
typedef struct sk_mat4 { float m[16]; } sk_mat4;
typedef struct sk_aabb { sk_vec3 min, max; } sk_aabb;
typedef struct sk_rect { float x0, y0, x1, y1; } sk_rect;      /* min corner, then max corner */
typedef struct sk_plane { sk_vec3 n; float d; } sk_plane;     /* dot(n,p)+d >= 0 is inside */
typedef struct sk_frustum { sk_vec3 corners[8]; sk_plane planes[6]; } sk_frustum;
typedef struct sk_sphere { sk_vec3 c; float r; } sk_sphere;
typedef enum sk_result { SK_OK = 0, SK_ERR_INVALID_ARG, SK_ERR_DEGENERATE,
                         SK_ERR_CAPACITY,
                         SK_ERR_GL           /* shadowkit_gl.h: a GL error or an unsupported context */
} sk_result;

/* "ok", "invalid argument", "degenerate configuration", "capacity exceeded",
   "GL error"; "unknown result" for any other value */
SKDEF const char *sk_result_string(sk_result r);

SKDEF sk_mat4 sk_mat4_identity(void);
/* a*b; an entry beyond the float range saturates to +-FLT_MAX (finite
   input never gives NaN or an infinity; NaN or infinite input gives 0 in
   the entries it would make NaN) */
SKDEF sk_mat4 sk_mat4_mul(sk_mat4 a, sk_mat4 b);
/* 1 and *out = inverse; 0 (out untouched) if singular, non-finite or out NULL */
SKDEF int     sk_mat4_inverse(sk_mat4 m, sk_mat4 *out);
/* gluPerspective. Fallback for fovy outside (0,pi), aspect <= 0, zn <= 0,
   zf <= zn or a non-finite argument: the identity. */
SKDEF sk_mat4 sk_mat4_perspective(float fovy, float aspect, float zn, float zf);
/* glOrtho. Fallback for r == l, t == b, zf == zn or non-finite: the identity. */
SKDEF sk_mat4 sk_mat4_ortho(float l, float r, float b, float t, float zn, float zf);
/* gluLookAt. An up vector parallel to the view direction is replaced by the
   world axis least aligned with it; eye == target, non-finite input or a
   translation too large for float (|eye| near FLT_MAX) gives the identity. */
SKDEF sk_mat4 sk_mat4_look_at(sk_vec3 eye, sk_vec3 target, sk_vec3 up);
/* with w-divide (w == 0: no divide); a coordinate beyond the float range
   (a sum near FLT_MAX, a w as small as 1e-45) saturates to +-FLT_MAX, NaN
   to 0 */
SKDEF sk_vec3 sk_mat4_transform_point(sk_mat4 m, sk_vec3 p);
SKDEF sk_vec4 sk_mat4_transform_vec4(sk_mat4 m, sk_vec4 p);       /* no divide */
/* corners[i] = unprojected NDC ((i&1)?1:-1, (i&2)?1:-1, (i&4)?1:-1); planes
   point inward (normalised), in the order left, right, bottom, top, near, far.
   A singular or non-finite matrix gives an all-zero frustum, which every test
   below treats as "unknown" (conservatively intersecting); so does one whose
   clip volume is no bounded frustum in front of its eye (an NDC corner
   unprojects to clip w <= 0, at or beyond infinity) and one whose corners or
   planes do not fit a float. */
SKDEF sk_frustum sk_frustum_from_matrix(sk_mat4 view_proj);
/* Frustum (any convex hexahedron) from 8 corners in the corner order above.
   Planes are recomputed from the corners and oriented inward.
   SK_ERR_INVALID_ARG for a non-finite corner or NULL; SK_ERR_DEGENERATE if a
   face is degenerate (zero area) or a plane does not fit a float (corners
   near FLT_MAX); out is untouched on error. */
SKDEF sk_result sk_frustum_from_corners(const sk_vec3 corners[8], sk_frustum *out);
/* The 8 corners of an AABB as a frustum (same corner order: bit 0 = x max,
   bit 1 = y max, bit 2 = z max). min > max on an axis: SK_ERR_INVALID_ARG. */
SKDEF sk_result sk_frustum_from_aabb(sk_aabb box, sk_frustum *out);
/* 1 if p is inside or on the frustum (relative tolerance 1e-5) */
SKDEF int sk_frustum_contains_point(const sk_frustum *f, sk_vec3 p);

/* Vertices of the convex intersection of a frustum and an AABB (the body that
   a shadow map must cover). Writes at most cap points; returns the count
   (0 when they do not intersect), or -SK_ERR_INVALID_ARG (NULL, cap < 0,
   an all-zero or non-finite frustum, an invalid box), or -SK_ERR_CAPACITY;
   nothing is written on error. SK_CLIP_MAX_POINTS is always enough. The
   points are finite for any valid input: a box far larger than the frustum
   (even +-FLT_MAX) is first cut to the frustum's bounds. */
#define SK_CLIP_MAX_POINTS 144
SKDEF int sk_clip_frustum_aabb(const sk_frustum *f, sk_aabb box, sk_vec3 *out, int cap);

/* =========================================================================
   B. Aliasing analysis (Romanick's VGP353 notes)
   ========================================================================= */
/* d = ds * (rs/ri) * (n_dot_v / n_dot_l); aliasing where d > di.
   +INFINITY if n_dot_l <= 0, ri <= 0 or an argument is NaN; n_dot_v < 0 is
   taken as 0 (a back-facing receiver is not seen). */
SKDEF float sk_aliasing_error(float ds, float rs, float ri, float n_dot_v, float n_dot_l);
/* RMSM level of detail: log2(sqrt(|dX x dY|)) of the shadow-map
   texel-coordinate derivatives (texels of level 0 per pixel).
   Zero area or NaN: -INFINITY (finest; callers clamp to their level range). */
SKDEF float sk_rmsm_lod(sk_vec2 dx, sk_vec2 dy);

/* =========================================================================
   6.2a Crop matrices and parallel splits (Ferko 2013; Zhang et al. 2006)
   ========================================================================= */
/* maps [r.x0,r.x1] x [r.y0,r.y1] x [zmin,zmax] of light clip space onto
   [-1,1]^3 (zmin maps to -1, zmax to +1). An axis with an empty or
   non-finite range, or one too thin for its scale to fit a float (a width
   below about 6e-39), is left as the identity; the other axes still map. */
SKDEF sk_mat4 sk_crop_matrix(sk_rect r, float zmin, float zmax);
/* C_0 = zn, C_m = zf, C_i = lambda*zn*(zf/zn)^(i/m) + (1-lambda)*(zn + (zf-zn)*i/m).
   out has m+1 entries. m in [1, SK_MAX_SPLITS], lambda in [0,1].
   zn must be > 0 when lambda > 0 (zn = 0 is allowed for uniform splits). */
#define SK_MAX_SPLITS 16
SKDEF sk_result sk_pssm_splits(float zn, float zf, int m, float lambda, float *out);
/* The 8 corners of the slice [d0,d1] (eye depths, zn <= d0 < d1 <= zf) of a
   perspective view frustum whose own planes are at zn and zf, in the corner
   order of sk_frustum. Eye depth is linear along each frustum edge, so every
   corner is a lerp of a near and a far corner. */
SKDEF sk_result sk_frustum_slice(const sk_frustum *view, float zn, float zf,
                                 float d0, float d1, sk_frustum *out);
/* Bounding sphere of a frustum slice that depends only on its shape, not on
   its position or orientation: centre on the line joining the near and far
   face centres, balanced between the near and far corners; radius rounded up
   to a multiple of 2^-10 of itself, which absorbs the float noise of the
   corners except when the exact radius lies within that noise of a rounding
   step. Every corner lies inside the sphere as returned (the radius is
   measured from the float centre and rounded up in float, subnormal
   frusta included). For a radius that is bitwise the same wherever the
   camera is, use sk_cascade_sphere. NULL, a non-finite corner, or a sphere float cannot
   hold (corners near FLT_MAX): a zero sphere (r = 0). */
SKDEF sk_sphere sk_frustum_bounding_sphere(const sk_frustum *f);
/* The same sphere computed from the camera's parameters: a symmetric
   perspective camera (cam_view rigid, fovy, aspect) and the slice [d0, d1] of
   eye depths. The radius depends on fovy, aspect, d0 and d1 only, so it is
   bitwise identical at every camera position and orientation: what stable
   cascades need. Bad input, or a sphere float cannot hold (a radius or
   centre beyond FLT_MAX): a zero sphere (r = 0). */
SKDEF sk_sphere sk_cascade_sphere(sk_mat4 cam_view, float fovy, float aspect, float d0, float d1);
/* World-to-light view for a directional light (looks along light_dir; the up
   vector is a fixed world axis, never the camera's, so it is stable).
   Zero or non-finite direction: looks down -Y. */
SKDEF sk_mat4 sk_light_view_directional(sk_vec3 light_dir);
/* Focused orthographic projection for light_view: x, y fitted to the points
   (e.g. from sk_clip_frustum_aabb) in light view space; the near plane pulled
   back towards the light to include casters (may be NULL) so off-screen
   casters between the light and the receivers still cast.
   SK_ERR_INVALID_ARG for NULL, count < 1, a non-finite point or matrix or
   an invalid caster box; SK_ERR_DEGENERATE when the fitted box does not fit
   a float projection (light-view coordinates near FLT_MAX). out_proj is
   untouched on error. */
SKDEF sk_result sk_fit_ortho(const sk_vec3 *pts, int count, sk_mat4 light_view,
                             const sk_aabb *casters, sk_mat4 *out_proj);
/* Texel-snapped stable crop for a directional light (or one PSSM cascade):
   an orthographic map of res x res texels around the sphere, whose texel grid
   is fixed in light-view space: the crop origin is snapped to whole texels
   (texel = 2r/(res-1), so the snapped square still covers the sphere), hence
   a sub-texel camera move never changes which texel covers a world point.
   Depth range: the sphere, pulled back to the casters' bounds if given.
   SK_ERR_INVALID_ARG for NULL, res < 2, r <= 0, non-finite input or an
   invalid caster box; SK_ERR_DEGENERATE when the crop does not fit float
   (bounds beyond FLT_MAX, or a sphere too small for float to resolve at its
   distance from the light view's origin). out_proj is untouched on error. */
SKDEF sk_result sk_stable_crop(sk_sphere s, sk_mat4 light_view, int res,
                               const sk_aabb *casters, sk_mat4 *out_proj);
/* sk_stable_crop for coordinates relative to a world point (large worlds):
   the sphere and the casters are given relative to `origin` (p - origin),
   so that float keeps its digits near the camera, and the projection
   applies to light_view * (p - origin). The texel grid stays where
   sk_stable_crop puts it for the same points in world coordinates: fixed
   in world light space, whatever the origin (light_view's rotation takes
   origin to light space in double). origin NULL: exactly sk_stable_crop. */
SKDEF sk_result sk_stable_crop_origin(sk_sphere s, sk_mat4 light_view, int res, const sk_aabb *casters,
                                      const double origin[3], sk_mat4 *out_proj);

/* =========================================================================
   6.2b PSM and LiSPSM warping (Stamminger & Drettakis 2002,
        Kozlov 2004, Wimmer et al. 2004)
   ========================================================================= */
typedef enum sk_depth_compare { SK_DEPTH_LESS = 0, SK_DEPTH_GREATER = 1 } sk_depth_compare;
typedef struct sk_psm_desc {
    sk_mat4 cam_view;             /* world -> camera eye space */
    float fovy, aspect, zn, zf;   /* camera projection (sk_mat4_perspective) */
    sk_vec3 light_dir;            /* directional light travel direction */
    const sk_aabb *casters;       /* optional: caster boxes. Their depth range is
                                     covered, and any part whose shadow can
                                     reach the view lies inside the map */
    int caster_count;
    const sk_vec3 *body;          /* optional focus body: world points of the
                                     receivers the map must cover (e.g. the
                                     view frustum clipped to the scene, from
                                     sk_clip_frustum_aabb); the light frustum
                                     is fitted to them in post-perspective
                                     space instead of to the whole unit cube */
    int body_count;               /* 0..SK_CLIP_MAX_POINTS */
    float extra_slide;            /* >= 0: the virtual camera moves this much
                                     further back, its near plane with it
                                     (near' = zn + extra_slide): a more uniform
                                     map, the PSM analogue of LiSPSM's n [0] */
} sk_psm_desc;
typedef struct sk_psm_result {
    sk_mat4 light_view_proj;      /* world -> light clip; the whole chain */
    sk_mat4 virtual_cam_view_proj;/* world -> post-perspective space used */
    sk_vec3 light_pp;             /* light position (or direction if ortho) in post-perspective space */
    sk_depth_compare compare;     /* GREATER: light behind the viewer, depth
                                     order reversed (clear depth to 0, test and
                                     compare with GREATER/GEQUAL) */
    int inverted;                 /* 1 when the light is behind the viewer */
    int orthographic;             /* 1: light direction perpendicular to the view
                                     direction, light at infinity in PP space */
    float slide;                  /* how far the virtual camera moved back */
} sk_psm_result;
/* Perspective shadow map for a directional light: the light is transformed
   into the camera's post-perspective space, where it becomes a point light
   on the plane z = (f+n)/(f-n) (or stays directional when perpendicular to
   the view direction), and a perspective light frustum is fitted there
   around the unit cube. Light behind the viewer: the post-perspective light
   is a sink; the frustum is the same but the depth order reverses
   (compare = SK_DEPTH_GREATER). Casters behind the camera: the virtual camera
   is slid back until every caster box is in front of its near plane, keeping
   the field of view (Kozlov's fix). */
SKDEF sk_result sk_psm_matrices(const sk_psm_desc *d, sk_psm_result *out);

typedef struct sk_lispsm_desc {
    sk_vec3 eye, view_dir;        /* camera position and view direction */
    float zn;                     /* camera near distance (n_opt uses it) */
    sk_vec3 light_dir;            /* directional light travel direction */
    const sk_vec3 *body;          /* focus body: points the map must cover
                                     (e.g. sk_clip_frustum_aabb output) */
    int body_count;
    const sk_aabb *casters;       /* optional: near plane pulled back to them */
    float n_override;             /* > 0: use this n instead of n_opt */
} sk_lispsm_desc;
typedef struct sk_lispsm_result {
    sk_mat4 light_view_proj;      /* world -> light clip */
    float n;                      /* distance of the warp's projection centre to
                                     the body (n_opt); +INFINITY when uniform */
    float sin_gamma;              /* sine of the angle between view and light */
    int warped;                   /* 0: fell back to a uniform (focused) map */
} sk_lispsm_result;
/* Light-space perspective shadow map: a perspective warp whose axis is the
   view direction projected perpendicular to the light, with the projection
   centre at n_opt = (zn + sqrt(zn*zf')) / sin(gamma), zf' = zn + d*sin(gamma),
   d the body's depth along the warp axis (Wimmer et al. 2004, Sec. 5).
   As the light becomes parallel to the view direction n_opt grows without
   bound and the map degrades smoothly to the uniform focused one; beyond
   n > 1e4 * d, or for a body thinner along the warp axis than 1e-4 of the
   magnitudes it is computed from (its points and the eye: too flat for
   float to warp), the uniform map is used directly (warped = 0). SK_ERR_INVALID_ARG for NULL, non-finite or
   zero directions, zn <= 0, no body, a non-finite body point or
   n_override, or an invalid caster box (out untouched);
   SK_ERR_DEGENERATE when the map does not fit float. */
SKDEF sk_result sk_lispsm_matrices(const sk_lispsm_desc *d, sk_lispsm_result *out);

/* =========================================================================
   6.2c Light Space Partitioned Shadow Maps (Tang et al. 2017)
   ========================================================================= */
typedef struct sk_lspsm_params { float zeta, sigma; int h_max, nw_max; } sk_lspsm_params;
/* paper defaults: zeta 0.25, sigma 0.5, h_max 4, nw_max 2 */
SKDEF sk_lspsm_params sk_lspsm_default_params(void);
/* Partitions an isosceles trapezoid given in its own frame: y runs from the
   near base (y=0, length n) to the far base (y=L); half-width at y is
   n/2 + y*tan(theta); x is centred on the axis. Rows follow Eq. (1) exactly
   (W_i, H_i); if h_max rows do not reach L the last row is stretched to end
   at L with the trapezoid's width there (this library's rule). The last row
   may reach past L and is not clipped. A row with W/H > 1+sigma is split into
   N_w = min(nw_max, ceil((W/H)/(1+sigma))) equal columns.
   Writes rects row by row (near first), returns how many, or
   -SK_ERR_INVALID_ARG (theta outside [0, pi/2), n <= 0, L <= 0, zeta outside
   (0, 0.5), sigma <= 0, h_max or nw_max < 1, NULL, non-finite input),
   -SK_ERR_CAPACITY when they do not fit in cap, -SK_ERR_DEGENERATE when a
   rect cannot be written in float (a bound beyond FLT_MAX, or a side that
   rounds to zero length: n far below float resolution at L, or theta at
   pi/2 with a tiny n). An error writes nothing; every rect written has
   x0 < x1 and y0 < y1. Never loops forever. */
SKDEF int sk_lspsm_partition(float n, float L, float theta, const sk_lspsm_params *p,
                             sk_rect *out, int cap);

typedef struct sk_lspsm_region {
    sk_mat4 light_view;           /* x: trapezoid cross axis, y: trapezoid axis
                                     (view direction projected on the light
                                     plane), z: towards the light */
    sk_vec2 origin;               /* centre of the near base in light_view xy */
    float n, L, theta;            /* the trapezoid of sk_lspsm_partition */
    float zmin, zmax;             /* light-view z range (casters included) */
    int fallback;                 /* 1: view direction parallel to the light,
                                     zero-length or zero-width region: one
                                     focused map over the bounding rectangle
                                     instead */
} sk_lspsm_region;
/* The projective region of Tang et al. 2017 (Sec. 3.1): the view frustum clipped to
   the receivers' box, projected on the light plane; the smallest enclosing
   isosceles trapezoid (minimum area) whose axis is the projected view
   direction. Casters (may be NULL) extend the depth range only.
   n is kept >= 1e-2 of the far base: as n -> 0 the rows of Eq. (1) would
   shrink to nothing (and past float precision); and >= 1e-5 of the
   region's coordinates, so a body of no width across the axis still gets
   a trapezoid. SK_ERR_INVALID_ARG for NULL, non-finite or zero directions,
   an invalid view or box; SK_ERR_DEGENERATE when the frustum misses the
   receivers or the region does not fit float (coordinates near FLT_MAX).
   out is untouched on error. */
SKDEF sk_result sk_lspsm_region_extract(const sk_frustum *view, sk_vec3 view_dir,
                                        sk_aabb receivers, const sk_aabb *casters,
                                        sk_vec3 light_dir, sk_lspsm_region *out);
/* One light view-projection (world -> that partition's clip space) per
   partition of the region (or the single focused map of a fallback region),
   and the partition rects in light-view xy. Returns the count, or -sk_result
   as sk_lspsm_partition; -SK_ERR_DEGENERATE also when a rect moved by the
   origin, or its matrix, does not fit float (a region filled by hand whose
   fields do not belong together). An error writes nothing. out_rects may
   be NULL. */
SKDEF int sk_lspsm_crops(const sk_lspsm_region *r, const sk_lspsm_params *p,
                         sk_mat4 *out_view_proj, sk_rect *out_rects, int cap);

/* =========================================================================
   7. Omnidirectional lights (King & Newhall 2004)
   ========================================================================= */
/* GL cube-map face order +X,-X,+Y,-Y,+Z,-Z and orientation (sampling a
   samplerCube with the light-to-point vector finds the texel rendered here).
   Face outside [0,5]: the +X face. */
SKDEF sk_mat4 sk_cube_face_view(int face, sk_vec3 light_pos);
/* 90 deg, aspect 1, w = eye depth. Invalid zn/zf: the identity. */
SKDEF sk_mat4 sk_cube_face_proj(float zn, float zf);
/* frustum-frustum test: a corner of one inside the other, or an edge of one
   crossing the other, either way round (HalfIntersection). Conservative:
   touching counts, with a small relative tolerance; never misses a real
   intersection. An all-zero (invalid) frustum intersects everything. */
SKDEF int sk_frustum_intersects(const sk_frustum *a, const sk_frustum *b);
/* bit f set = cube face f intersects the view frustum and must be rendered.
   Invalid zn/zf or NULL view: all six bits (0x3f). */
SKDEF unsigned sk_cube_visible_faces(sk_vec3 light_pos, float zn, float zf, const sk_frustum *view);
/* The frustum bounding the shadow a caster box can throw: the square pyramid
   circumscribing the light-to-box cone, near plane at the box's nearest point
   along the cone axis, far plane at light_range. If the light is inside the
   box (or the cone would be wider than 170 degrees), the light-range box
   instead. The cone is built in double and is never thinner than 1e-6 of
   the magnitudes at hand, so a caster too small or too far to subtend an
   angle float resolves (a point) still gets a frustum that holds it; if
   float cannot hold the pyramid's corners, the light-range box.
   SK_ERR_DEGENERATE only when the box lies beyond light_range (casts
   nothing), SK_ERR_INVALID_ARG for bad input; out untouched on error. */
SKDEF sk_result sk_caster_shadow_frustum(sk_vec3 light_pos, float light_range,
                                         sk_aabb caster, sk_frustum *out);
/* 1 if the caster's shadow (light-to-box cone, capped at light_range) can
   reach the view frustum; a light inside the box uses the light-range box
   instead. Conservative. Bad input: 1 (never culls what it cannot judge). */
SKDEF int sk_caster_visible(sk_vec3 light_pos, float light_range, sk_aabb caster,
                            const sk_frustum *view);
/* scissor rect {x,y,w,h} (GL window coordinates, origin bottom-left; floor of
   the minimum, ceil of the maximum, clipped to the viewport) of the light's
   range box (side 2*radius). Some box corners behind the eye (clip w <= 0)
   and some in front: the full viewport; all behind, or the rect empty:
   returns 0 with the rect zeroed; otherwise 1. The corners are projected
   in double (no overflow of light_pos +- radius, no clip w rounding to 0).
   Bad input: 0, rect zeroed. */
SKDEF int sk_light_scissor(sk_vec3 light_pos, float radius, sk_mat4 view_proj,
                           int vp_w, int vp_h, int out_rect[4]);
/* smallest power of two M with faces*M*M >= c*pixels, clamped to [1, the
   largest power of two <= max_res]; 0 if faces == 0 or on bad input
   (faces outside [0,6], pixels < 0, c <= 0, max_res < 1, NaN). */
SKDEF int sk_cube_resolution(int faces, float pixels, float c, int max_res);

/* Spot lights: a cone from `apex` along `axis` (any length > 0) of
   half-angle `half_angle` radians in (0, 1.5], capped at `range`; its map is
   one perspective projection looking down the axis.
   sk_spot_view: world -> the spot's eye space (gluLookAt's convention: the
   axis is -z; x and y are the cross products with the world axis least
   aligned with the axis, so they depend on the axis alone); the identity on
   bad input.
   sk_spot_window: the map's window {x0, y0, x1, y1} in that eye space at
   unit depth (tangent units): the cone's square [-tan a, tan a]^2 clipped
   to the bounding rectangle, seen from the apex beyond depth zn, of
   `bounds` (NULL: not clipped), or with a `view` frustum of the part of
   bounds inside it (sk_clip_frustum_aabb: the receivers the view can see;
   the casters between them and the light project inside the same
   rectangle); the body is cut exactly by the plane at zn (its vertices in
   front and every crossing of the plane by a segment between two of
   them). That rectangle is made square: res = 0: about its centre at the
   larger side, shifted (not shrunk) to stay inside the cone's square;
   res > 0 (a map of res texels, snapped for a stable map as the view
   moves, like a stable directional crop): the side the smallest
   2 tan a / 2^k that holds the rectangle grown by `margin` texels (0 or
   more: a filter's reach) on each side and one texel more, the corner on
   the grid of that side's texels laid from the cone's corner, so texels
   stay put in the cone while the window follows the view, and the side
   changes only by factors of two. Returns 1; 0 (win the cone's square)
   when the body lies wholly behind zn or beside the cone (nothing to
   render), -1 on bad input (win zeroed).
   sk_spot_matrix: world -> clip of the map: glFrustum over the window
   (x0 zn .. x1 zn, y0 zn .. y1 zn, zn, zf) times sk_spot_view; its window
   depth is sk_vsdct_depth_coeffs(zn, zf) of the depth along the axis. The
   identity on bad input.
   sk_spot_box_visible: 0 when the box cannot meet the cone (its bounding
   sphere lies outside the cone, behind the apex, or beyond range), else 1.
   Conservative (a sphere that only meets the cone's round cap's corner
   region counts); bad input: 1. */
SKDEF sk_mat4 sk_spot_view(sk_vec3 apex, sk_vec3 axis);
SKDEF int sk_spot_window(sk_vec3 apex, sk_vec3 axis, float half_angle, float zn, const sk_aabb *bounds,
                         const sk_frustum *view, int res, float margin, float win[4]);
SKDEF sk_mat4 sk_spot_matrix(sk_vec3 apex, sk_vec3 axis, const float win[4], float zn, float zf);
SKDEF int sk_spot_box_visible(sk_vec3 apex, sk_vec3 axis, float half_angle, float range, sk_aabb box);

/* Virtual Shadow Depth Cube Texture: six faces as sub-rects of one 2D depth
   texture, laid out 3 x 2 (face f at column f%3, row f/3, row 0 at the
   bottom). face_res in [1, SK_VSDCT_MAX_FACE_RES].
   A layout filled by hand (faces packed into a larger atlas) is valid when
   face_res is in that range, the atlas is at most SK_VSDCT_MAX_ATLAS texels
   on a side (float u, v then place a texel to within 1/64 of its width) and
   every face's sub-rect lies inside it; sk_vsdct_lookup and
   sk_vsdct_indirection_fill refuse any other. */
#define SK_VSDCT_MAX_FACE_RES 65536
#define SK_VSDCT_MAX_ATLAS (4 * SK_VSDCT_MAX_FACE_RES)
typedef struct sk_vsdct_layout { int face_res, atlas_w, atlas_h; int face_x[6], face_y[6]; } sk_vsdct_layout;
SKDEF sk_result sk_vsdct_layout_make(int face_res, sk_vsdct_layout *out);
/* N_i = 2^(ceil(log2 Ns) + min(ceil(log2 G), D) - D)  (Eq. 5.4.7), at least 1;
   0 on bad input (face_res outside [1, SK_VSDCT_MAX_FACE_RES],
   grey_levels < 1, deriv_bits < 0). */
SKDEF int sk_vsdct_indirection_size(int face_res, int grey_levels, int deriv_bits);
/* window depth stored for eye depth MA: scale / MA + bias  (Eq. 5.4.6).
   Bad input (zn <= 0, zf <= zn, NaN): scale 0, bias 1. */
SKDEF void sk_vsdct_depth_coeffs(float zn, float zf, float *scale, float *bias);
/* direction -> face and normalised atlas coords (u right, v up: GL texture
   convention, v = 0 at the atlas's bottom row); within its sub-rect a face is
   laid out exactly as GL lays out that cube face. Coords always stay at least
   half a texel inside that face's sub-rect (no sampling across seams), up
   to the rounding of u, v to float. Returns the face, or -1 for a zero or
   non-finite direction, an invalid layout (see above) or a NULL argument
   (u, v untouched). */
SKDEF int sk_vsdct_lookup(const sk_vsdct_layout *l, sk_vec3 dir, float *u, float *v);
/* fills the RG16 indirection cube map: out[((face*ni + t)*ni + s)*2 + {0,1}]
   = atlas (u,v) * 65535 (rounded) for the direction through that texel's
   centre. ni in [1, 65536]; SK_ERR_INVALID_ARG (nothing written) for ni out
   of range, an invalid layout or NULL. */
SKDEF sk_result sk_vsdct_indirection_fill(const sk_vsdct_layout *l, int ni, unsigned short *out);

/* =========================================================================
   6.3 Resolution estimation (Ferko 2013)
   ========================================================================= */
typedef struct sk_res_estimate {
    sk_rect bounds;          /* light-clip xy AABB of visible samples, within [-1,1]^2 */
    float texel_w, texel_h;  /* smallest light-clip extent of one pixel's patch */
    int width, height;       /* ceil(bounds extent / texel extent), clamped to [1,max_res] */
    int samples;             /* pixels that landed inside the light frustum */
    sk_mat4 crop;            /* sk_crop_matrix of bounds */
} sk_res_estimate;
/* depth: w*h window depths in [0,1], row 0 at the bottom (glReadPixels
   order); 1.0 = background, skipped (so are NaN and values outside [0,1)).
   A sample is the pixel centre's world position; it counts when it lands
   inside the light's clip volume (w > 0, |x|,|y|,|z| <= w). Patches come from
   the four pixel corners, their depth bilinearly interpolated from the valid
   pixels around each corner (Sec. 3.2). If no patch has all four corners in
   front of the light, or none a finite extent along an axis (projections
   beyond double range), the texel size is the bounds over max_res (so the
   map is max_res wide); a texel size beyond FLT_MAX reads FLT_MAX: every
   output is finite. No sample: SK_OK with samples = 0,
   width and height 0, texel sizes 0, bounds and crop the identity of
   [-1,1]^2. w and h in [1, 65536]; max_res >= 1. */
SKDEF sk_result sk_estimate_resolution(const float *depth, int w, int h,
        sk_mat4 cam_inv_view_proj, sk_mat4 light_view_proj, int max_res, sk_res_estimate *out);

/* =========================================================================
   9. Predicted virtual soft shadow maps (Shen et al. 2011)
   ========================================================================= */
/* perceptual polynomials in log2(n); n clamped to [1, n_peak] so rho never
   decreases. NaN or n < 1 is taken as 1. */
SKDEF float sk_rho_dynamic(float n);   /* 0.667 + 0.7794x + 0.3967x^2 - 0.02716x^3 */
SKDEF float sk_rho_static(float n);    /* 0.5477 + 1.406x - 0.04687x^2 - 0.003944x^3 */
/* Parallelograms by HALF-axes: the kernel covers c + a*u + b*v, a,b in [-1,1].
   Gaussian-variance sum of two parallelograms converted back by Cholesky to
   one with v_out along the vertical axis (appendix, u2 read as u_out).
   Zero area gives finite axes; non-finite input gives zero axes. */
SKDEF void sk_convolve_parallelograms(sk_vec2 u0, sk_vec2 v0, sk_vec2 u1, sk_vec2 v1,
                                      sk_vec2 *u_out, sk_vec2 *v_out);
/* area of [x0,x1]x[y0,y1] inside texel [tx,tx+1]x[ty,ty+1] (texel units);
   0 for an empty box or NaN */
SKDEF float sk_texel_box_coverage(float x0, float y0, float x1, float y1, int tx, int ty);
/* Smooth texel-coverage filtering (Sec. 4.1): fraction of the axis-aligned
   box [x0,x1]x[y0,y1] (texel units) that is lit, each texel taken as a quad
   weighted by its coverage. lit(user, tx, ty) returns 1 when that texel passes
   the depth test. Texels are visited at most 64 x 64 (a larger box returns
   -1). Empty box: the lit value of the texel containing its centre.
   Coverage is summed in double, so a box thinner than float's range of
   areas still reads its true fraction. Bad input (lit NULL, a non-finite
   coordinate, |coordinate| > 1e9): -1, lit never called. */
SKDEF float sk_smooth_box_visibility(float x0, float y0, float x1, float y1,
                                     int (*lit)(void *user, int tx, int ty), void *user);
/* Eq. (4)-(5): required texel size (shadow-map units) along each axis,
   r_k = 2 e_k^T h / rho(n_k), n_k = ||M_phi'^-1 e_k e_k^T h_k||: the SMTG keeps
   the MINIMUM per cell; resolution over a span s is s / r. u_phi, v_phi are the
   half-axes of the warped pixel footprint. Non-finite input: +INFINITY; a
   size too large for float: FLT_MAX (finite input never gives +INFINITY,
   which the SMTG reads as "no sample"). r0 or r1 may be NULL. */
SKDEF void sk_pvsm_predict(sk_vec2 u_h, sk_vec2 v_h, sk_vec2 u_phi, sk_vec2 v_phi,
                           int dynamic_scene, float *r0, float *r1);
/* V_dst = V_dst*A_dst + V_src*A_src, A_dst += A_src (Sec. 5.2), with V kept
   normalised: on return *v is the area-weighted visibility, *a the area. */
SKDEF void sk_pvsm_merge(float *v, float *a, float v_src, float a_src);
typedef struct sk_tile { int x0, y0, x1, y1; int res_x, res_y; } sk_tile;  /* cells [x0,x1) x [y0,y1) */
/* Size in floats of the SMTG min-pyramid of a gw x gh grid of 2-float cells
   (all levels, level 0 included, down to 1x1); 0 on bad input (gw, gh
   outside [1, 4096]). */
SKDEF int sk_smtg_pyramid_size(int gw, int gh);
/* Builds the min-pyramid: level 0 is the grid, each next level the per-2x2
   minimum (odd sizes round up). Returns the number of levels, or -sk_result. */
SKDEF int sk_smtg_pyramid(const float *grid, int gw, int gh, float *out, int cap_floats);
/* grid: gw*gh*2 floats, cell (x,y) at grid[(y*gw + x)*2 + {0,1}], the minimum
   required texel size along x and y in light-clip units (2/gw per cell span);
   +INFINITY or NaN = no sample; <= 0 is an unbounded demand (that cell ends
   in a 1x1 tile at max_res). A cell whose need
   exceeds max_res gets a tile of its own at max_res (clamped, never an error).
   Empty grid: returns 0. Top-down kd-tree (Giegl & Wimmer): a node, shrunk to
   its sampled cells, becomes a tile when its resolution fits max_res, else it
   is split in half along the axis of higher resolution. Tiles are disjoint,
   cover every sampled cell, res <= max_res and res >= node span / min texel
   size of its cells. Returns count or -sk_result. gw, gh in [1, 4096]. */
SKDEF int sk_fvsm_tiles(const float *grid, int gw, int gh, int max_res, sk_tile *out, int cap);

/* =========================================================================
   6.4 RMSM page requests (after Lefohn, Sengupta and Owens 2007)
   ========================================================================= */
typedef struct sk_page { int level, px, py; } sk_page;
/* samples: (s, t, lod) with s,t in [0,1) shadow-map coordinates of level 0
   and lod = sk_rmsm_lod of the pixel. A virtual map of virtual_res^2 texels
   (power of two) is cut into pages of page_size^2 texels (power of two,
   <= virtual_res) at every level; a sample needs level
   clamp(floor(lod), 0, log2(virtual_res/page_size)) and the page holding
   (s,t) there. Writes the unique requests sorted by (level, py, px) and
   returns their count, -SK_ERR_CAPACITY if more than cap, -SK_ERR_INVALID_ARG
   on bad sizes. Samples with s or t outside [0,1) or NaN are skipped. */
SKDEF int sk_rmsm_page_requests(const sk_vec3 *samples, int count, int virtual_res,
                                int page_size, sk_page *out, int cap);

#ifdef __cplusplus
}
#endif
#endif /* SHADOWKIT_H */

/* =========================================================================
   IMPLEMENTATION
   ========================================================================= */
#ifdef SHADOWKIT_IMPLEMENTATION
#ifndef SHADOWKIT_IMPLEMENTATION_INCLUDED
#define SHADOWKIT_IMPLEMENTATION_INCLUDED
#ifdef SK__STATIC_WITHOUT_IMPLEMENTATION
#error "SHADOWKIT_STATIC: define SHADOWKIT_IMPLEMENTATION before this file's first #include of shadowkit.h"
#endif

#include <float.h>
#include <math.h>
#include <string.h>

#ifndef SK_ASSERT
#include <assert.h>
#define SK_ASSERT(x) assert(x)
#endif
#ifndef SK_SQRTF
#define SK_SQRTF(x) sqrtf(x)
#endif
#ifndef SK_FABSF
#define SK_FABSF(x) fabsf(x)
#endif
#ifndef SK_FLOORF
#define SK_FLOORF(x) floorf(x)
#endif
#ifndef SK_CEILF
#define SK_CEILF(x) ceilf(x)
#endif
#ifndef SK_SQRT
#define SK_SQRT(x) sqrt(x)
#endif
#ifndef SK_FABS
#define SK_FABS(x) fabs(x)
#endif
#ifndef SK_FLOOR
#define SK_FLOOR(x) floor(x)
#endif
#ifndef SK_CEIL
#define SK_CEIL(x) ceil(x)
#endif
#ifndef SK_LOG2
#define SK_LOG2(x) (log(x) * 1.4426950408889634)
#endif
#ifndef SK_POW
#define SK_POW(x, y) pow(x, y)
#endif
#ifndef SK_TAN
#define SK_TAN(x) tan(x)
#endif
#ifndef SK_ATAN
#define SK_ATAN(x) atan(x)
#endif
#ifndef SK_COS
#define SK_COS(x) cos(x)
#endif
#ifndef SK_FREXP
#define SK_FREXP(x, e) frexp(x, e)
#endif
#ifndef SK_LDEXP
#define SK_LDEXP(x, e) ldexp(x, e)
#endif

#define SK__INF ((float)HUGE_VAL)
#define SK__PI 3.14159265358979323846

#ifdef __cplusplus
extern "C" {
#endif

/* ---- A. Core math ------------------------------------------------------ */
// >>core

/* Bit test, so it keeps working under -ffast-math. */
static int sk__finite(float x)
{
    unsigned int u;
    memcpy(&u, &x, sizeof u);
    return (u & 0x7f800000u) != 0x7f800000u;
}
static int sk__finite_d(double x) { return x == x && x - x == 0.0; }
static int sk__v3_finite(sk_vec3 v) { return sk__finite(v.x) && sk__finite(v.y) && sk__finite(v.z); }
/* all 16 at once: the exponent bits of each, or-ed together without branches */
static int sk__mat_finite(const sk_mat4 *m)
{
    unsigned u[16], bad = 0u;
    int i;
    memcpy(u, m->m, sizeof u);
    for (i = 0; i < 16; i++) bad |= (unsigned)((u[i] & 0x7f800000u) == 0x7f800000u);
    return !bad;
}
/* sk__v3_finite of each of n points, without branches */
static int sk__v3s_finite(const sk_vec3 *p, int n)
{
    unsigned bad = 0u;
    int i;
    for (i = 0; i < n; i++) {
        unsigned u[3];
        memcpy(u, &p[i], sizeof u);
        bad |= (unsigned)((u[0] & 0x7f800000u) == 0x7f800000u) | (unsigned)((u[1] & 0x7f800000u) == 0x7f800000u) |
               (unsigned)((u[2] & 0x7f800000u) == 0x7f800000u);
    }
    return !bad;
}
static int sk__aabb_valid(const sk_aabb *b)
{
    return sk__v3_finite(b->min) && sk__v3_finite(b->max) &&
           b->min.x <= b->max.x && b->min.y <= b->max.y && b->min.z <= b->max.z;
}
/* the smallest float >= r, for finite r >= 0 (FLT_MAX and beyond round to
   infinity): a bound held in float stays a bound, subnormals included */
static float sk__float_up(double r)
{
    float f = (float)r;
    int e;
    if ((double)f < r) {
        SK_FREXP((double)f, &e);
        f += (float)SK_LDEXP(1.0, f > 0.0f && e - 24 > -149 ? e - 24 : -149);
    }
    return f;
}
static sk_vec3 sk__v3(float x, float y, float z) { sk_vec3 r; r.x = x; r.y = y; r.z = z; return r; }
static sk_vec3 sk__add(sk_vec3 a, sk_vec3 b) { return sk__v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static sk_vec3 sk__sub(sk_vec3 a, sk_vec3 b) { return sk__v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static sk_vec3 sk__scale(sk_vec3 a, float s) { return sk__v3(a.x * s, a.y * s, a.z * s); }
static float sk__dot(sk_vec3 a, sk_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static float sk__clampf(float x, float lo, float hi) { return x < lo ? lo : x > hi ? hi : x; }
static sk_vec3 sk__cross(sk_vec3 a, sk_vec3 b)
{
    return sk__v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static float sk__len(sk_vec3 a) { return (float)SK_SQRT((double)a.x * a.x + (double)a.y * a.y + (double)a.z * a.z); }
/* zero vector stays zero. A length whose reciprocal float cannot hold (a
   denormal vector, or one longer than FLT_MAX) divides in double instead,
   so the result is a unit vector for every finite non-zero input. */
static sk_vec3 sk__normalize(sk_vec3 a)
{
    float l = sk__len(a);
    double x = a.x, y = a.y, z = a.z, dl;
    if (l >= 1e-18f && l <= 1e18f) return sk__scale(a, 1.0f / l);
    dl = SK_SQRT(x * x + y * y + z * z);
    return dl > 0.0 ? sk__v3((float)(x / dl), (float)(y / dl), (float)(z / dl)) : a;
}
/* in double: b - a of two finite floats may not fit a float, the lerp
   (t in [0,1]) always does */
static sk_vec3 sk__lerp3(sk_vec3 a, sk_vec3 b, float t)
{
    return sk__v3((float)(a.x + ((double)b.x - a.x) * t), (float)(a.y + ((double)b.y - a.y) * t),
                  (float)(a.z + ((double)b.z - a.z) * t));
}
static float sk__maxabs3(sk_vec3 a)
{
    float m = SK_FABSF(a.x);
    if (SK_FABSF(a.y) > m) m = SK_FABSF(a.y);
    if (SK_FABSF(a.z) > m) m = SK_FABSF(a.z);
    return m;
}
static sk_vec3 sk__aabb_corner(const sk_aabb *b, int i)
{
    return sk__v3((i & 1) ? b->max.x : b->min.x, (i & 2) ? b->max.y : b->min.y,
                  (i & 4) ? b->max.z : b->min.z);
}
/* Matrix whose rows are the axes x, y, z, translated so that `origin` maps to 0. */
static sk_mat4 sk__basis_view(sk_vec3 x, sk_vec3 y, sk_vec3 z, sk_vec3 origin)
{
    sk_mat4 r;
    memset(&r, 0, sizeof r);
    r.m[0] = x.x; r.m[4] = x.y; r.m[8] = x.z;
    r.m[1] = y.x; r.m[5] = y.y; r.m[9] = y.z;
    r.m[2] = z.x; r.m[6] = z.y; r.m[10] = z.z;
    r.m[12] = -sk__dot(x, origin);
    r.m[13] = -sk__dot(y, origin);
    r.m[14] = -sk__dot(z, origin);
    r.m[15] = 1.0f;
    return r;
}
/* z of sk__xform_affine alone */
static float sk__xform_z(const sk_mat4 *m, sk_vec3 p)
{
    return m->m[2] * p.x + m->m[6] * p.y + m->m[10] * p.z + m->m[14];
}
/* Affine part only (no w): for view matrices. */
static sk_vec3 sk__xform_affine(const sk_mat4 *m, sk_vec3 p)
{
    return sk__v3(m->m[0] * p.x + m->m[4] * p.y + m->m[8] * p.z + m->m[12],
                  m->m[1] * p.x + m->m[5] * p.y + m->m[9] * p.z + m->m[13],
                  m->m[2] * p.x + m->m[6] * p.y + m->m[10] * p.z + m->m[14]);
}

SKDEF const char *sk_result_string(sk_result r)
{
    switch (r) {
    case SK_OK: return "ok";
    case SK_ERR_INVALID_ARG: return "invalid argument";
    case SK_ERR_DEGENERATE: return "degenerate configuration";
    case SK_ERR_CAPACITY: return "capacity exceeded";
    case SK_ERR_GL: return "GL error";
    }
    return "unknown result";
}

SKDEF sk_mat4 sk_mat4_identity(void)
{
    sk_mat4 r;
    memset(&r, 0, sizeof r);
    r.m[0] = r.m[5] = r.m[10] = r.m[15] = 1.0f;
    return r;
}

/* a double that a float cannot hold, as a float: NaN 0, beyond the float
   range the largest float of its sign */
static float sk__saturate(double v)
{
    if (v != v) return 0.0f;
    if (v > 3.4028234663852886e38) return 3.4028234663852886e38f;
    if (v < -3.4028234663852886e38) return -3.4028234663852886e38f;
    return (float)v;
}

/* the plain float product: an entry beyond float is an infinity (or NaN
   from inf - inf), which the fits below test for (sk__mat_finite) to
   report SK_ERR_DEGENERATE; the public sk_mat4_mul saturates instead */
static sk_mat4 sk__mat_mul(sk_mat4 a, sk_mat4 b)
{
    sk_mat4 r;
    int c, row;
    for (c = 0; c < 4; c++)
        for (row = 0; row < 4; row++)
            r.m[c * 4 + row] = a.m[row] * b.m[c * 4] + a.m[4 + row] * b.m[c * 4 + 1] +
                               a.m[8 + row] * b.m[c * 4 + 2] + a.m[12 + row] * b.m[c * 4 + 3];
    return r;
}

SKDEF sk_mat4 sk_mat4_mul(sk_mat4 a, sk_mat4 b)
{
    sk_mat4 r;
    int c, row;
    for (c = 0; c < 4; c++)
        for (row = 0; row < 4; row++) {
            float v = a.m[row] * b.m[c * 4] + a.m[4 + row] * b.m[c * 4 + 1] + a.m[8 + row] * b.m[c * 4 + 2] +
                      a.m[12 + row] * b.m[c * 4 + 3];
            /* an entry that overflowed float (or met inf - inf) is formed
               again in double, whose range holds any product of floats, and
               saturated: finite input never gives NaN or an infinity */
            if (!sk__finite(v))
                v = sk__saturate((double)a.m[row] * b.m[c * 4] + (double)a.m[4 + row] * b.m[c * 4 + 1] +
                                 (double)a.m[8 + row] * b.m[c * 4 + 2] + (double)a.m[12 + row] * b.m[c * 4 + 3]);
            r.m[c * 4 + row] = v;
        }
    return r;
}

/* Cofactor expansion in double precision. */
SKDEF int sk_mat4_inverse(sk_mat4 mat, sk_mat4 *out)
{
    double m[16], inv[16], det;
    int i;
    if (!out || !sk__mat_finite(&mat)) return 0;
    for (i = 0; i < 16; i++) m[i] = mat.m[i];
    inv[0] = m[5]*m[10]*m[15] - m[5]*m[11]*m[14] - m[9]*m[6]*m[15] + m[9]*m[7]*m[14] + m[13]*m[6]*m[11] - m[13]*m[7]*m[10];
    inv[4] = -m[4]*m[10]*m[15] + m[4]*m[11]*m[14] + m[8]*m[6]*m[15] - m[8]*m[7]*m[14] - m[12]*m[6]*m[11] + m[12]*m[7]*m[10];
    inv[8] = m[4]*m[9]*m[15] - m[4]*m[11]*m[13] - m[8]*m[5]*m[15] + m[8]*m[7]*m[13] + m[12]*m[5]*m[11] - m[12]*m[7]*m[9];
    inv[12] = -m[4]*m[9]*m[14] + m[4]*m[10]*m[13] + m[8]*m[5]*m[14] - m[8]*m[6]*m[13] - m[12]*m[5]*m[10] + m[12]*m[6]*m[9];
    inv[1] = -m[1]*m[10]*m[15] + m[1]*m[11]*m[14] + m[9]*m[2]*m[15] - m[9]*m[3]*m[14] - m[13]*m[2]*m[11] + m[13]*m[3]*m[10];
    inv[5] = m[0]*m[10]*m[15] - m[0]*m[11]*m[14] - m[8]*m[2]*m[15] + m[8]*m[3]*m[14] + m[12]*m[2]*m[11] - m[12]*m[3]*m[10];
    inv[9] = -m[0]*m[9]*m[15] + m[0]*m[11]*m[13] + m[8]*m[1]*m[15] - m[8]*m[3]*m[13] - m[12]*m[1]*m[11] + m[12]*m[3]*m[9];
    inv[13] = m[0]*m[9]*m[14] - m[0]*m[10]*m[13] - m[8]*m[1]*m[14] + m[8]*m[2]*m[13] + m[12]*m[1]*m[10] - m[12]*m[2]*m[9];
    inv[2] = m[1]*m[6]*m[15] - m[1]*m[7]*m[14] - m[5]*m[2]*m[15] + m[5]*m[3]*m[14] + m[13]*m[2]*m[7] - m[13]*m[3]*m[6];
    inv[6] = -m[0]*m[6]*m[15] + m[0]*m[7]*m[14] + m[4]*m[2]*m[15] - m[4]*m[3]*m[14] - m[12]*m[2]*m[7] + m[12]*m[3]*m[6];
    inv[10] = m[0]*m[5]*m[15] - m[0]*m[7]*m[13] - m[4]*m[1]*m[15] + m[4]*m[3]*m[13] + m[12]*m[1]*m[7] - m[12]*m[3]*m[5];
    inv[14] = -m[0]*m[5]*m[14] + m[0]*m[6]*m[13] + m[4]*m[1]*m[14] - m[4]*m[2]*m[13] - m[12]*m[1]*m[6] + m[12]*m[2]*m[5];
    inv[3] = -m[1]*m[6]*m[11] + m[1]*m[7]*m[10] + m[5]*m[2]*m[11] - m[5]*m[3]*m[10] - m[9]*m[2]*m[7] + m[9]*m[3]*m[6];
    inv[7] = m[0]*m[6]*m[11] - m[0]*m[7]*m[10] - m[4]*m[2]*m[11] + m[4]*m[3]*m[10] + m[8]*m[2]*m[7] - m[8]*m[3]*m[6];
    inv[11] = -m[0]*m[5]*m[11] + m[0]*m[7]*m[9] + m[4]*m[1]*m[11] - m[4]*m[3]*m[9] - m[8]*m[1]*m[7] + m[8]*m[3]*m[5];
    inv[15] = m[0]*m[5]*m[10] - m[0]*m[6]*m[9] - m[4]*m[1]*m[10] + m[4]*m[2]*m[9] + m[8]*m[1]*m[6] - m[8]*m[2]*m[5];
    det = m[0] * inv[0] + m[1] * inv[4] + m[2] * inv[8] + m[3] * inv[12];
    if (det == 0.0 || !sk__finite_d(det)) return 0;
    det = 1.0 / det;
    {
        sk_mat4 r;
        for (i = 0; i < 16; i++) {
            r.m[i] = (float)(inv[i] * det);
            if (!sk__finite(r.m[i])) return 0;
        }
        *out = r;
    }
    return 1;
}

SKDEF sk_mat4 sk_mat4_perspective(float fovy, float aspect, float zn, float zf)
{
    sk_mat4 r;
    double f;
    if (!sk__finite(fovy) || !sk__finite(aspect) || !sk__finite(zn) || !sk__finite(zf) ||
        !(fovy > 0.0f) || !(fovy < SK__PI) || !(aspect > 0.0f) || !(zn > 0.0f) || !(zf > zn))
        return sk_mat4_identity();
    f = 1.0 / SK_TAN(0.5 * (double)fovy);
    memset(&r, 0, sizeof r);
    r.m[0] = (float)(f / aspect);
    r.m[5] = (float)f;
    r.m[10] = (float)(((double)zf + zn) / ((double)zn - zf));
    r.m[11] = -1.0f;
    r.m[14] = (float)(2.0 * zf * zn / ((double)zn - zf));
    if (!sk__mat_finite(&r)) return sk_mat4_identity();
    return r;
}

SKDEF sk_mat4 sk_mat4_ortho(float l, float r, float b, float t, float zn, float zf)
{
    sk_mat4 m;
    if (!sk__finite(l) || !sk__finite(r) || !sk__finite(b) || !sk__finite(t) ||
        !sk__finite(zn) || !sk__finite(zf) || r == l || t == b || zf == zn)
        return sk_mat4_identity();
    memset(&m, 0, sizeof m);
    m.m[0] = (float)(2.0 / ((double)r - l));
    m.m[5] = (float)(2.0 / ((double)t - b));
    m.m[10] = (float)(-2.0 / ((double)zf - zn));
    m.m[12] = (float)(-((double)r + l) / ((double)r - l));
    m.m[13] = (float)(-((double)t + b) / ((double)t - b));
    m.m[14] = (float)(-((double)zf + zn) / ((double)zf - zn));
    m.m[15] = 1.0f;
    if (!sk__mat_finite(&m)) return sk_mat4_identity();
    return m;
}

/* The world axis least aligned with d. */
static sk_vec3 sk__least_aligned_axis(sk_vec3 d)
{
    float ax = SK_FABSF(d.x), ay = SK_FABSF(d.y), az = SK_FABSF(d.z);
    if (ax <= ay && ax <= az) return sk__v3(1, 0, 0);
    if (ay <= az) return sk__v3(0, 1, 0);
    return sk__v3(0, 0, 1);
}

SKDEF sk_mat4 sk_mat4_look_at(sk_vec3 eye, sk_vec3 target, sk_vec3 up)
{
    sk_vec3 f, s, u;
    if (!sk__v3_finite(eye) || !sk__v3_finite(target) || !sk__v3_finite(up))
        return sk_mat4_identity();
    f = sk__sub(target, eye);
    if (f.x == 0.0f && f.y == 0.0f && f.z == 0.0f) return sk_mat4_identity();
    if (sk__v3_finite(f)) f = sk__normalize(f);
    else {
        /* target - eye does not fit a float: the direction in double */
        double dx = (double)target.x - eye.x, dy = (double)target.y - eye.y, dz = (double)target.z - eye.z;
        double dl = SK_SQRT(dx * dx + dy * dy + dz * dz);
        f = sk__v3((float)(dx / dl), (float)(dy / dl), (float)(dz / dl));
    }
    s = sk__cross(f, up);
    if (!(sk__len(s) > 1e-6f * (sk__len(up) > 0.0f ? sk__len(up) : 1.0f)))
        s = sk__cross(f, sk__least_aligned_axis(f));
    s = sk__normalize(s);
    u = sk__cross(s, f);
    {
        sk_mat4 r = sk__basis_view(s, u, sk__scale(f, -1.0f), eye);
        return sk__mat_finite(&r) ? r : sk_mat4_identity();
    }
}

SKDEF sk_vec4 sk_mat4_transform_vec4(sk_mat4 m, sk_vec4 p)
{
    sk_vec4 r;
    r.x = m.m[0] * p.x + m.m[4] * p.y + m.m[8] * p.z + m.m[12] * p.w;
    r.y = m.m[1] * p.x + m.m[5] * p.y + m.m[9] * p.z + m.m[13] * p.w;
    r.z = m.m[2] * p.x + m.m[6] * p.y + m.m[10] * p.z + m.m[14] * p.w;
    r.w = m.m[3] * p.x + m.m[7] * p.y + m.m[11] * p.z + m.m[15] * p.w;
    return r;
}

/* sk_mat4_transform_point without copying the matrix */
static sk_vec3 sk__xform_point(const sk_mat4 *m, sk_vec3 p)
{
    float x = m->m[0] * p.x + m->m[4] * p.y + m->m[8] * p.z + m->m[12];
    float y = m->m[1] * p.x + m->m[5] * p.y + m->m[9] * p.z + m->m[13];
    float z = m->m[2] * p.x + m->m[6] * p.y + m->m[10] * p.z + m->m[14];
    float w = m->m[3] * p.x + m->m[7] * p.y + m->m[11] * p.z + m->m[15];
    if (w != 0.0f) { float iw = 1.0f / w; return sk__v3(x * iw, y * iw, z * iw); }
    return sk__v3(x, y, z);
}

/* sk__xform_point of the 8 corners of b (sk__aabb_corner order), with the
   products of m's columns and the box bounds formed once: the same sums of
   the same products in the same order as corner by corner. */
static void sk__xform_box(const sk_mat4 *m, const sk_aabb *b, sk_vec3 *out)
{
    float px[2][4], py[2][4], pz[2][4];
    int r, i;
    for (r = 0; r < 4; r++) {
        px[0][r] = m->m[r] * b->min.x; px[1][r] = m->m[r] * b->max.x;
        py[0][r] = m->m[4 + r] * b->min.y; py[1][r] = m->m[4 + r] * b->max.y;
        pz[0][r] = m->m[8 + r] * b->min.z; pz[1][r] = m->m[8 + r] * b->max.z;
    }
    for (i = 0; i < 8; i++) {
        int a = i & 1, c = (i >> 1) & 1, e = (i >> 2) & 1;
        float x = px[a][0] + py[c][0] + pz[e][0] + m->m[12];
        float y = px[a][1] + py[c][1] + pz[e][1] + m->m[13];
        float z = px[a][2] + py[c][2] + pz[e][2] + m->m[14];
        float w = px[a][3] + py[c][3] + pz[e][3] + m->m[15];
        if (w != 0.0f) { float iw = 1.0f / w; out[i] = sk__v3(x * iw, y * iw, z * iw); }
        else out[i] = sk__v3(x, y, z);
    }
}

SKDEF sk_vec3 sk_mat4_transform_point(sk_mat4 m, sk_vec3 p)
{
    sk_vec3 r = sk__xform_point(&m, p);
    double x, y, z, w;
    if (sk__finite(r.x) && sk__finite(r.y) && sk__finite(r.z)) return r;
    /* a sum beyond float, or a divide by a w so small (1e-45) that the
       quotient is: again in double, saturated (no NaN, no infinity) */
    x = (double)m.m[0] * p.x + (double)m.m[4] * p.y + (double)m.m[8] * p.z + m.m[12];
    y = (double)m.m[1] * p.x + (double)m.m[5] * p.y + (double)m.m[9] * p.z + m.m[13];
    z = (double)m.m[2] * p.x + (double)m.m[6] * p.y + (double)m.m[10] * p.z + m.m[14];
    w = (double)m.m[3] * p.x + (double)m.m[7] * p.y + (double)m.m[11] * p.z + m.m[15];
    if (w != 0.0 && w == w) { x /= w; y /= w; z /= w; }
    return sk__v3(sk__saturate(x), sk__saturate(y), sk__saturate(z));
}

static sk_plane sk__plane_normalized(double a, double b, double c, double d)
{
    sk_plane p;
    double l = SK_SQRT(a * a + b * b + c * c);
    if (!(l > 0.0)) l = 1.0;
    p.n = sk__v3((float)(a / l), (float)(b / l), (float)(c / l));
    p.d = (float)(d / l);
    return p;
}

/* All-zero (what a singular matrix gives) or non-finite: not a usable frustum. */
static int sk__frustum_invalid(const sk_frustum *f)
{
    /* the 48 floats' exponent bits at once (as sk__finite), then the normals */
    unsigned u[sizeof(sk_frustum) / sizeof(unsigned)], bad = 0u;
    int i;
    memcpy(u, f, sizeof u);
    for (i = 0; i < (int)(sizeof u / sizeof u[0]); i++) bad |= (unsigned)((u[i] & 0x7f800000u) == 0x7f800000u);
    for (i = 0; i < 6; i++)
        bad |= (unsigned)(f->planes[i].n.x == 0.0f && f->planes[i].n.y == 0.0f && f->planes[i].n.z == 0.0f);
    return (int)bad;
}

SKDEF sk_frustum sk_frustum_from_matrix(sk_mat4 vp)
{
    sk_frustum f;
    sk_mat4 inv;
    const float *m = vp.m;
    int i, k;
    memset(&f, 0, sizeof f);
    if (!sk_mat4_inverse(vp, &inv)) return f;
    for (i = 0; i < 8; i++) {
        sk_vec4 c, r;
        c.x = (i & 1) ? 1.0f : -1.0f; c.y = (i & 2) ? 1.0f : -1.0f;
        c.z = (i & 4) ? 1.0f : -1.0f; c.w = 1.0f;
        r = sk_mat4_transform_vec4(inv, c);
        /* clip w = 1 / r.w: a corner at or beyond infinity (w <= 0) leaves a
           clip volume that is no bounded frustum in front of the eye */
        if (!(r.w > 0.0f)) { memset(&f, 0, sizeof f); return f; }
        f.corners[i] = sk__v3(r.x / r.w, r.y / r.w, r.z / r.w);
        if (!sk__v3_finite(f.corners[i])) { memset(&f, 0, sizeof f); return f; }
    }
    /* Gribb & Hartmann: plane = row3 +/- row k; inside has w +/- x_k >= 0 */
    for (k = 0; k < 3; k++) {
        double r3[4], rk[4];
        for (i = 0; i < 4; i++) { r3[i] = m[i * 4 + 3]; rk[i] = m[i * 4 + k]; }
        f.planes[2 * k] = sk__plane_normalized(r3[0] + rk[0], r3[1] + rk[1], r3[2] + rk[2], r3[3] + rk[3]);
        f.planes[2 * k + 1] = sk__plane_normalized(r3[0] - rk[0], r3[1] - rk[1], r3[2] - rk[2], r3[3] - rk[3]);
    }
    if (sk__frustum_invalid(&f)) memset(&f, 0, sizeof f);   /* a plane offset beyond FLT_MAX */
    return f;
}

/* Corner indices of the 6 faces in cyclic order, same plane order as
   sk_frustum: left, right, bottom, top, near, far. */
static const unsigned char sk__face_quads[6][4] = {
    {0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}
};
/* 12 edges as corner pairs differing in one index bit. */
static const unsigned char sk__edges[12][2] = {
    {0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3}, {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}
};

SKDEF sk_result sk_frustum_from_corners(const sk_vec3 corners[8], sk_frustum *out)
{
    sk_frustum f;
    double cx = 0, cy = 0, cz = 0, scale = 0;
    int i, k;
    if (!corners || !out) return SK_ERR_INVALID_ARG;
    for (i = 0; i < 8; i++) {
        if (!sk__v3_finite(corners[i])) return SK_ERR_INVALID_ARG;
        f.corners[i] = corners[i];
        cx += corners[i].x; cy += corners[i].y; cz += corners[i].z;
    }
    cx /= 8; cy /= 8; cz /= 8;
    for (i = 0; i < 8; i++) {
        double dx = corners[i].x - cx, dy = corners[i].y - cy, dz = corners[i].z - cz;
        double d2 = dx * dx + dy * dy + dz * dz;
        if (d2 > scale) scale = d2;
    }
    if (!(scale > 0.0)) return SK_ERR_DEGENERATE;
    for (k = 0; k < 6; k++) {
        /* Newell's normal of the (possibly non-planar) quad */
        double nx = 0, ny = 0, nz = 0, px = 0, py = 0, pz = 0, d;
        for (i = 0; i < 4; i++) {
            sk_vec3 a = corners[sk__face_quads[k][i]], b = corners[sk__face_quads[k][(i + 1) & 3]];
            nx += ((double)a.y - b.y) * ((double)a.z + b.z);
            ny += ((double)a.z - b.z) * ((double)a.x + b.x);
            nz += ((double)a.x - b.x) * ((double)a.y + b.y);
            px += a.x; py += a.y; pz += a.z;
        }
        px /= 4; py /= 4; pz /= 4;
        if (!(nx * nx + ny * ny + nz * nz > 0.0) || !sk__finite_d(nx * nx + ny * ny + nz * nz)) return SK_ERR_DEGENERATE;
        d = -(nx * px + ny * py + nz * pz);
        if (nx * cx + ny * cy + nz * cz + d < 0.0) { nx = -nx; ny = -ny; nz = -nz; d = -d; }
        f.planes[k] = sk__plane_normalized(nx, ny, nz, d);
    }
    if (sk__frustum_invalid(&f)) return SK_ERR_DEGENERATE;   /* a plane offset beyond FLT_MAX */
    *out = f;
    return SK_OK;
}

SKDEF sk_result sk_frustum_from_aabb(sk_aabb b, sk_frustum *out)
{
    int i;
    if (!out || !sk__aabb_valid(&b)) return SK_ERR_INVALID_ARG;
    for (i = 0; i < 8; i++) out->corners[i] = sk__aabb_corner(&b, i);
    out->planes[0].n = sk__v3(1, 0, 0);  out->planes[0].d = -b.min.x;
    out->planes[1].n = sk__v3(-1, 0, 0); out->planes[1].d = b.max.x;
    out->planes[2].n = sk__v3(0, 1, 0);  out->planes[2].d = -b.min.y;
    out->planes[3].n = sk__v3(0, -1, 0); out->planes[3].d = b.max.y;
    out->planes[4].n = sk__v3(0, 0, 1);  out->planes[4].d = -b.min.z;
    out->planes[5].n = sk__v3(0, 0, -1); out->planes[5].d = b.max.z;
    return SK_OK;
}

static float sk__plane_dist(const sk_plane *pl, sk_vec3 p) { return sk__dot(pl->n, p) + pl->d; }

SKDEF int sk_frustum_contains_point(const sk_frustum *f, sk_vec3 p)
{
    int i;
    if (!f || !sk__v3_finite(p)) return 0;
    for (i = 0; i < 6; i++) {
        float tol = 1e-5f * (1.0f + sk__maxabs3(p) + SK_FABSF(f->planes[i].d));
        if (sk__plane_dist(&f->planes[i], p) < -tol) return 0;
    }
    return 1;
}

/* The parts of the 12 edges of hexahedron c (corner order of sk_frustum)
   inside the other body, by parametric clipping against its six planes
   (Cyrus & Beck 1978): dist[k][i] is corner i's signed distance to plane k,
   bit k of out[i] set where corner i is outside plane k beyond the
   containment tolerance (see below). A plane constrains an
   edge where exactly one end is outside it; the edge enters the body at the
   largest entering crossing and leaves at the smallest leaving one. Those
   points are appended (an end within tolerance of the body is a corner,
   appended by the caller). Planes the whole edge is within tolerance of do
   not cut it, so faces that touch or coincide keep their vertices. */
static int sk__clip_edges(const sk_vec3 *c, const float (*dist)[8], const unsigned *out, sk_vec3 *pts, int n)
{
    int e, k;
    for (e = 0; e < 12; e++) {
        int a = sk__edges[e][0], b = sk__edges[e][1], enter = 0, leave = 0;
        unsigned oa = out[a], ob = out[b], x = oa | ob;
        float t0 = 0.0f, t1 = 1.0f;
        if (!x || (oa & ob)) continue;   /* inside all along, or beyond one plane at both ends */
        for (k = 0; x >> k; k++) {
            float d0 = dist[k][a], t;
            if (!(x >> k & 1u)) continue;
            t = d0 / (d0 - dist[k][b]);
            if (oa >> k & 1u) { enter = 1; if (t > t0) t0 = t < 1.0f ? t : 1.0f; }
            else { leave = 1; if (t < t1) t1 = t > 0.0f ? t : 0.0f; }
        }
        if (t0 > t1 + 1e-6f) continue;   /* passes by the body */
        if (enter) pts[n++] = sk__lerp3(c[a], c[b], t0);
        if (leave) pts[n++] = sk__lerp3(c[a], c[b], t1);
    }
    return n;
}

/* A vertex of the intersection of two convex bodies is a corner of one
   inside the other, or where an edge of one crosses a face of the other.
   The 8 x 6 signed distances of each body's corners to the other's planes
   are computed once, plane by plane over the 8 corners (the box corners'
   coordinates and their products with each plane normal taken once per
   axis: the same products and sums as corner by corner). Containment has a
   tolerance relative to the magnitudes involved: 1e-5 (1 + |p| + |d|) for a
   point p and a plane's offset d. */
SKDEF int sk_clip_frustum_aabb(const sk_frustum *f, sk_aabb box, sk_vec3 *out, int cap)
{
    sk_vec3 bc[8], pts[16 + 2 * 24];
    float fd[6][8], bd[6][8];   /* frustum corners to box planes, box corners to frustum planes */
    float fx[8], fy[8], fz[8], fm[8], bm[8], bx[8], by[8], bz[8];
    float kx[16 + 2 * 24 + 3], ky[16 + 2 * 24 + 3], kz[16 + 2 * 24 + 3];
    float lo[3], hi[3], alo[3], ahi[3];
    unsigned fo[8], bo[8];
    int count = 0, i, j, n = 0;
    if (!f || !out || cap < 0 || sk__frustum_invalid(f) || !sk__aabb_valid(&box))
        return -(int)SK_ERR_INVALID_ARG;
    lo[0] = box.min.x; lo[1] = box.min.y; lo[2] = box.min.z;
    hi[0] = box.max.x; hi[1] = box.max.y; hi[2] = box.max.z;
    {
        /* the box cut to the frustum's corner bounds, 1e-4 (1 + their
           magnitude) wider (beyond the containment tolerance): the same
           intersection, but an edge of a box far larger than the frustum
           is no longer too long for float to place a crossing on it */
        float cl[3], ch[3], mag = 0.0f, tol;
        for (j = 0; j < 3; j++) cl[j] = ch[j] = (&f->corners[0].x)[j];
        for (i = 0; i < 8; i++) {
            for (j = 0; j < 3; j++) {
                float c = (&f->corners[i].x)[j];
                if (c < cl[j]) cl[j] = c;
                if (c > ch[j]) ch[j] = c;
            }
            if (sk__maxabs3(f->corners[i]) > mag) mag = sk__maxabs3(f->corners[i]);
        }
        tol = 1e-4f * (1.0f + mag);
        for (j = 0; j < 3; j++) {
            if (lo[j] < cl[j] - tol) lo[j] = cl[j] - tol;
            if (hi[j] > ch[j] + tol) hi[j] = ch[j] + tol;
            if (!(lo[j] <= hi[j])) return 0;   /* apart along this axis */
        }
    }
    for (j = 0; j < 3; j++) { alo[j] = SK_FABSF(lo[j]); ahi[j] = SK_FABSF(hi[j]); }
    /* the box corners in sk__aabb_corner order, by coordinate */
    bx[0] = bx[2] = bx[4] = bx[6] = lo[0]; bx[1] = bx[3] = bx[5] = bx[7] = hi[0];
    by[0] = by[1] = by[4] = by[5] = lo[1]; by[2] = by[3] = by[6] = by[7] = hi[1];
    bz[0] = bz[1] = bz[2] = bz[3] = lo[2]; bz[4] = bz[5] = bz[6] = bz[7] = hi[2];
    for (i = 0; i < 8; i++) {
        fx[i] = f->corners[i].x; fy[i] = f->corners[i].y; fz[i] = f->corners[i].z;
        bc[i] = sk__v3(bx[i], by[i], bz[i]);
        fo[i] = bo[i] = 0u;
    }
    for (i = 0; i < 8; i++) {
        /* -1e-5 (1 + |p|) of each corner p, |p| its largest coordinate magnitude (sk__maxabs3) */
        float mb = SK_FABSF(bx[i]), mf = SK_FABSF(fx[i]);
        if (SK_FABSF(by[i]) > mb) mb = SK_FABSF(by[i]);
        if (SK_FABSF(bz[i]) > mb) mb = SK_FABSF(bz[i]);
        if (SK_FABSF(fy[i]) > mf) mf = SK_FABSF(fy[i]);
        if (SK_FABSF(fz[i]) > mf) mf = SK_FABSF(fz[i]);
        bm[i] = -1e-5f * (1.0f + mb);
        fm[i] = -1e-5f * (1.0f + mf);
    }
    /* the box's planes in sk_frustum_from_aabb's order: x - min.x, max.x - x, ... */
    for (i = 0; i < 8; i++) {
        fd[0][i] = fx[i] - lo[0]; fd[1][i] = hi[0] - fx[i];
        fd[2][i] = fy[i] - lo[1]; fd[3][i] = hi[1] - fy[i];
        fd[4][i] = fz[i] - lo[2]; fd[5][i] = hi[2] - fz[i];
    }
    for (j = 0; j < 6; j++) {
        const sk_plane *pl = &f->planes[j];
        /* outside plane j: distance + 1e-5 |d_j| < -1e-5 (1 + |p|) */
        float bt = 1e-5f * ((j & 1) ? ahi[j >> 1] : alo[j >> 1]), ft = 1e-5f * SK_FABSF(pl->d);
        for (i = 0; i < 8; i++) {
            bd[j][i] = pl->n.x * bx[i] + pl->n.y * by[i] + pl->n.z * bz[i] + pl->d;
            fo[i] |= (unsigned)(fd[j][i] + bt < fm[i]) << j;
            bo[i] |= (unsigned)(bd[j][i] + ft < bm[i]) << j;
        }
    }
    for (i = 0; i < 8; i++) {
        if (!fo[i]) pts[n++] = f->corners[i];
        if (!bo[i]) pts[n++] = bc[i];
    }
    if (n < 16) {
        n = sk__clip_edges(f->corners, (const float (*)[8])fd, fo, pts, n);
        n = sk__clip_edges(bc, (const float (*)[8])bd, bo, pts, n);
    }
    /* drop coincident points (shared corners, edges through corners): a
       point is kept unless within tolerance of one kept before it. The kept
       points' coordinates are stored apart, in groups of four; appending
       also writes the next three slots, so the last group's tail holds
       copies of its last point (a copy matches exactly when its original
       does) and each group is compared at once, without branches. */
    for (i = 0; i < n; i++) {
        sk_vec3 p = pts[i];
        float tol = 1e-6f * (1.0f + sk__maxabs3(p));
        int h[4] = {0, 0, 0, 0}, k;
        for (j = 0; j < count; j += 4)
            for (k = 0; k < 4; k++)
                h[k] |= (SK_FABSF(kx[j + k] - p.x) <= tol) & (SK_FABSF(ky[j + k] - p.y) <= tol) &
                        (SK_FABSF(kz[j + k] - p.z) <= tol);
        if (!((h[0] | h[1]) | (h[2] | h[3]))) {
            for (k = 0; k < 4; k++) { kx[count + k] = p.x; ky[count + k] = p.y; kz[count + k] = p.z; }
            pts[count++] = p;
        }
    }
    if (count > cap) return -(int)SK_ERR_CAPACITY;
    for (i = 0; i < count; i++) out[i] = pts[i];
    return count;
}

/* ---- B. Aliasing analysis (Romanick's VGP353 notes) ------------------ */
// >>aliasing

/* d = d_s (r_s / r_i) (N.V / N.L), the slides' aliasing error */
SKDEF float sk_aliasing_error(float ds, float rs, float ri, float n_dot_v, float n_dot_l)
{
    double d;
    if (ds != ds || rs != rs || ri != ri || n_dot_v != n_dot_v || n_dot_l != n_dot_l) return SK__INF;
    if (!(n_dot_l > 0.0f) || !(ri > 0.0f) || ds < 0.0f || rs < 0.0f) return SK__INF;
    if (n_dot_v < 0.0f) n_dot_v = 0.0f;
    d = (double)ds * ((double)rs / ri) * ((double)n_dot_v / n_dot_l);
    if (d != d || d > 3.0e38) return SK__INF;
    return (float)d;
}

/* l = log2(sqrt(A)), A = |dX x dY| (RMSM phase one) */
SKDEF float sk_rmsm_lod(sk_vec2 dx, sk_vec2 dy)
{
    double a = SK_FABS((double)dx.x * dy.y - (double)dx.y * dy.x);
    if (a != a || a == 0.0) return -SK__INF;
    if (!sk__finite_d(a)) return SK__INF;
    return (float)(0.5 * SK_LOG2(a));
}

/* ---- 6.2a Crop matrices and parallel splits (Ferko 2013; Zhang et al. 2006) --- */
// >>fits

/* one axis of sk_crop_matrix: [lo, hi] onto [-1, 1], or left alone */
static void sk__crop_axis(float lo, float hi, float *scale, float *offset)
{
    float s, o;
    if (!sk__finite(lo) || !sk__finite(hi) || !(hi > lo)) return;
    s = (float)(2.0 / ((double)hi - lo));
    o = (float)(-((double)hi + lo) / ((double)hi - lo));
    if (!sk__finite(s) || !sk__finite(o)) return;   /* a range too thin for float */
    *scale = s;
    *offset = o;
}

SKDEF sk_mat4 sk_crop_matrix(sk_rect r, float zmin, float zmax)
{
    sk_mat4 m = sk_mat4_identity();
    sk__crop_axis(r.x0, r.x1, &m.m[0], &m.m[12]);
    sk__crop_axis(r.y0, r.y1, &m.m[5], &m.m[13]);
    sk__crop_axis(zmin, zmax, &m.m[10], &m.m[14]);
    return m;
}

/* Practical split scheme (PSSM, Zhang, Sun, Xu and Lun 2006):
   C_i = lambda C_i^log + (1 - lambda) C_i^uni */
SKDEF sk_result sk_pssm_splits(float zn, float zf, int m, float lambda, float *out)
{
    int i;
    if (!out || !sk__finite(zn) || !sk__finite(zf) || !sk__finite(lambda) || m < 1 ||
        m > SK_MAX_SPLITS || !(lambda >= 0.0f && lambda <= 1.0f) || !(zn >= 0.0f) || !(zf > zn) ||
        (lambda > 0.0f && !(zn > 0.0f)))
        return SK_ERR_INVALID_ARG;
    out[0] = zn;
    for (i = 1; i < m; i++) {
        double f = (double)i / m;
        double c_uni = zn + ((double)zf - zn) * f;
        double c_log = lambda > 0.0f ? zn * SK_POW((double)zf / zn, f) : 0.0;
        out[i] = (float)(lambda * c_log + (1.0 - lambda) * c_uni);
    }
    out[m] = zf;
    return SK_OK;
}

SKDEF sk_result sk_frustum_slice(const sk_frustum *view, float zn, float zf, float d0, float d1,
                                 sk_frustum *out)
{
    sk_vec3 c[8];
    float t0, t1;
    int i;
    if (!view || !out || !sk__finite(zn) || !sk__finite(zf) || !sk__finite(d0) || !sk__finite(d1) ||
        !(zn >= 0.0f) || !(zf > zn) || !(d0 >= zn) || !(d1 > d0) || !(d1 <= zf) || sk__frustum_invalid(view))
        return SK_ERR_INVALID_ARG;
    t0 = (float)(((double)d0 - zn) / ((double)zf - zn));
    t1 = (float)(((double)d1 - zn) / ((double)zf - zn));
    for (i = 0; i < 8; i++)
        c[i] = sk__lerp3(view->corners[i & 3], view->corners[(i & 3) + 4], (i & 4) ? t1 : t0);
    return sk_frustum_from_corners(c, out);
}

SKDEF sk_sphere sk_frustum_bounding_sphere(const sk_frustum *f)
{
    sk_sphere s;
    double cn[3] = {0, 0, 0}, cf[3] = {0, 0, 0}, a2 = 0, b2 = 0, l2 = 0, t, c[3], r2 = 0, r;
    int i, k, e;
    s.c = sk__v3(0, 0, 0); s.r = 0.0f;
    if (!f) return s;
    for (i = 0; i < 8; i++) if (!sk__v3_finite(f->corners[i])) return s;
    for (i = 0; i < 4; i++) {
        cn[0] += f->corners[i].x / 4.0; cn[1] += f->corners[i].y / 4.0; cn[2] += f->corners[i].z / 4.0;
        cf[0] += f->corners[i + 4].x / 4.0; cf[1] += f->corners[i + 4].y / 4.0; cf[2] += f->corners[i + 4].z / 4.0;
    }
    for (i = 0; i < 4; i++) {
        double da = 0, db = 0;
        const float *pn = &f->corners[i].x, *pf = &f->corners[i + 4].x;
        for (k = 0; k < 3; k++) {
            da += (pn[k] - cn[k]) * (pn[k] - cn[k]);
            db += (pf[k] - cf[k]) * (pf[k] - cf[k]);
        }
        if (da > a2) a2 = da;
        if (db > b2) b2 = db;
    }
    for (k = 0; k < 3; k++) l2 += (cf[k] - cn[k]) * (cf[k] - cn[k]);
    /* centre on the axis where the farthest near and far corners are equidistant */
    t = l2 > 0.0 ? (b2 - a2 + l2) / (2.0 * l2) : 0.5;
    if (t < 0.0) t = 0.0;
    if (t > 1.0) t = 1.0;
    /* the radius is measured from the centre as stored (float), so that its
       rounding cannot leave a corner outside, even for subnormal frusta */
    for (k = 0; k < 3; k++) c[k] = (float)(cn[k] + t * (cf[k] - cn[k]));
    for (i = 0; i < 8; i++) {
        const float *p = &f->corners[i].x;
        double d2 = 0;
        for (k = 0; k < 3; k++) d2 += (p[k] - c[k]) * (p[k] - c[k]);
        if (d2 > r2) r2 = d2;
    }
    r = SK_SQRT(r2) * (1.0 + 4e-16);
    if (r > 0.0) {
        double q;
        SK_FREXP(r, &e);
        q = SK_LDEXP(1.0, e - 10);
        r = SK_CEIL(r / q) * q;
    }
    s.c = sk__v3((float)c[0], (float)c[1], (float)c[2]);
    s.r = sk__float_up(r);
    if (!sk__v3_finite(s.c) || !sk__finite(s.r)) { s.c = sk__v3(0, 0, 0); s.r = 0.0f; }   /* beyond FLT_MAX */
    return s;
}

SKDEF sk_sphere sk_cascade_sphere(sk_mat4 v, float fovy, float aspect, float d0, float d1)
{
    sk_sphere s;
    double t2, a2, b2, zc, r, eye[3], fwd[3];
    int k;
    s.c = sk__v3(0, 0, 0); s.r = 0.0f;
    if (!sk__mat_finite(&v) || !sk__finite(fovy) || !sk__finite(aspect) || !sk__finite(d0) ||
        !sk__finite(d1) || !(fovy > 0.0f) || !(fovy < SK__PI) || !(aspect > 0.0f) || !(d0 >= 0.0f) || !(d1 > d0))
        return s;
    /* squared half-diagonal of the cross-section at unit depth */
    t2 = SK_TAN(0.5 * fovy);
    t2 = t2 * t2 * (1.0 + (double)aspect * aspect);
    a2 = t2 * d0 * d0;
    b2 = t2 * d1 * d1;
    zc = (b2 - a2 + (double)d1 * d1 - (double)d0 * d0) / (2.0 * ((double)d1 - d0));
    if (zc > d1) zc = d1;
    r = zc >= d1 ? SK_SQRT(b2) : SK_SQRT(a2 + (zc - d0) * (zc - d0));
    /* eye = -R^T t, forward = -(third row of R) for the rigid view matrix */
    for (k = 0; k < 3; k++) {
        eye[k] = -((double)v.m[k * 4] * v.m[12] + (double)v.m[k * 4 + 1] * v.m[13] + (double)v.m[k * 4 + 2] * v.m[14]);
        fwd[k] = -(double)v.m[k * 4 + 2];
    }
    s.c = sk__v3((float)(eye[0] + zc * fwd[0]), (float)(eye[1] + zc * fwd[1]), (float)(eye[2] + zc * fwd[2]));
    s.r = (float)(r * (1.0 + 1e-4));   /* covers float corners of the same camera */
    if (!sk__v3_finite(s.c) || !sk__finite(s.r)) { s.c = sk__v3(0, 0, 0); s.r = 0.0f; }   /* beyond FLT_MAX */
    return s;
}

SKDEF sk_mat4 sk_light_view_directional(sk_vec3 light_dir)
{
    sk_vec3 d = sk__normalize(light_dir), up;
    if (!sk__v3_finite(light_dir) || sk__len(light_dir) == 0.0f) d = sk__v3(0, -1, 0);
    /* fixed world up, never the camera's: a stable light-space texel grid */
    up = SK_FABSF(d.z) < 0.9f ? sk__v3(0, 0, 1) : sk__v3(0, 1, 0);
    return sk_mat4_look_at(sk__v3(0, 0, 0), d, up);
}

/* Orthographic projection of the light-view box [lo, hi]: x, y onto [-1,1],
   larger z (nearer the light: the view looks down -z) onto depth -1. A
   side thinner than 1e-4 of the magnitudes at hand (a flat body) is widened
   to that: the points' float coordinates carry an error of about 1e-7 of
   them, which a thinner side would magnify past the map's edge. `mag` is
   the magnitude the coordinates were computed from (world points and the
   view's translation), or 0. Returns 0 (out untouched) when the box does
   not fit a float matrix (a bound beyond FLT_MAX). */
static int sk__ortho_box_fit(double xlo, double xhi, double ylo, double yhi, double zlo, double zhi, double mag,
                             sk_mat4 *out)
{
    double e = 1e-4 * (1.0 + SK_FABS(xlo) + SK_FABS(xhi) + mag);
    float b[6];
    int i;
    if (xhi - xlo < e) { xlo -= 0.5 * (e - (xhi - xlo)); xhi += 0.5 * (e - (xhi - xlo)); }
    e = 1e-4 * (1.0 + SK_FABS(ylo) + SK_FABS(yhi) + mag);
    if (yhi - ylo < e) { ylo -= 0.5 * (e - (yhi - ylo)); yhi += 0.5 * (e - (yhi - ylo)); }
    e = 1e-4 * (1.0 + SK_FABS(zlo) + SK_FABS(zhi) + mag);
    if (zhi - zlo < e) { zlo -= 0.5 * (e - (zhi - zlo)); zhi += 0.5 * (e - (zhi - zlo)); }
    b[0] = (float)xlo; b[1] = (float)xhi; b[2] = (float)ylo; b[3] = (float)yhi; b[4] = (float)-zhi; b[5] = (float)-zlo;
    for (i = 0; i < 6; i++) if (!sk__finite(b[i])) return 0;
    if (!(b[1] > b[0]) || !(b[3] > b[2]) || !(b[5] > b[4])) return 0;
    *out = sk_mat4_ortho(b[0], b[1], b[2], b[3], b[4], b[5]);
    return 1;
}

/* Largest light-view z (nearest the light) of the casters' corners. */
static double sk__casters_zmax(const sk_mat4 *view, const sk_aabb *casters, double z)
{
    int i;
    if (!casters || !sk__aabb_valid(casters)) return z;
    for (i = 0; i < 8; i++) {
        double cz = sk__xform_z(view, sk__aabb_corner(casters, i));
        if (cz > z) z = cz;
    }
    return z;
}

SKDEF sk_result sk_fit_ortho(const sk_vec3 *pts, int count, sk_mat4 light_view,
                             const sk_aabb *casters, sk_mat4 *out_proj)
{
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300}, mag = 0.0;
    int i, k;
    if (!pts || count < 1 || !out_proj || !sk__mat_finite(&light_view) ||
        (casters && !sk__aabb_valid(casters)))
        return SK_ERR_INVALID_ARG;
    for (i = 0; i < count; i++) {
        sk_vec3 p;
        if (!sk__v3_finite(pts[i])) return SK_ERR_INVALID_ARG;
        if (sk__maxabs3(pts[i]) > mag) mag = sk__maxabs3(pts[i]);
        p = sk__xform_affine(&light_view, pts[i]);
        for (k = 0; k < 3; k++) {
            double v = (&p.x)[k];
            if (v < lo[k]) lo[k] = v;
            if (v > hi[k]) hi[k] = v;
        }
    }
    hi[2] = sk__casters_zmax(&light_view, casters, hi[2]);
    mag += sk__maxabs3(sk__v3(light_view.m[12], light_view.m[13], light_view.m[14]));
    return sk__ortho_box_fit(lo[0], hi[0], lo[1], hi[1], lo[2], hi[2], mag, out_proj) ? SK_OK : SK_ERR_DEGENERATE;
}

SKDEF sk_result sk_stable_crop(sk_sphere s, sk_mat4 light_view, int res,
                               const sk_aabb *casters, sk_mat4 *out_proj)
{
    return sk_stable_crop_origin(s, light_view, res, casters, NULL, out_proj);
}

SKDEF sk_result sk_stable_crop_origin(sk_sphere s, sk_mat4 light_view, int res, const sk_aabb *casters,
                                      const double origin[3], sk_mat4 *out_proj)
{
    sk_vec3 c;
    double texel, x0, y0, ext, zhi, ox = 0.0, oy = 0.0;
    if (!out_proj || res < 2 || !sk__v3_finite(s.c) || !sk__finite(s.r) || !(s.r > 0.0f) ||
        !sk__mat_finite(&light_view) || (casters && !sk__aabb_valid(casters)) ||
        (origin && !(SK_FABS(origin[0]) < 1e300 && SK_FABS(origin[1]) < 1e300 && SK_FABS(origin[2]) < 1e300)))
        return SK_ERR_INVALID_ARG;
    c = sk__xform_affine(&light_view, s.c);
    texel = 2.0 * s.r / (res - 1);
    if (origin) {
        /* where the origin lies in light-view space (the rotation only: the
           translation cancels between p and origin) */
        const float *m = light_view.m;
        ox = (double)m[0] * origin[0] + (double)m[4] * origin[1] + (double)m[8] * origin[2];
        oy = (double)m[1] * origin[0] + (double)m[5] * origin[1] + (double)m[9] * origin[2];
    }
    /* snap the crop origin to whole texels of a grid fixed in light space
       (in world light space: the origin's own light-space position added
       before the snap, taken off after, all in double) */
    if (origin) {
        x0 = SK_FLOOR(((double)c.x - s.r + ox) / texel) * texel - ox;
        y0 = SK_FLOOR(((double)c.y - s.r + oy) / texel) * texel - oy;
    } else {
        x0 = SK_FLOOR(((double)c.x - s.r) / texel) * texel;
        y0 = SK_FLOOR(((double)c.y - s.r) / texel) * texel;
    }
    ext = texel * res;
    zhi = sk__casters_zmax(&light_view, casters, (double)c.z + s.r);
    {
        /* bounds float cannot hold, or a sphere too small for float to
           tell its edges apart at this distance from the light's origin */
        float b[6];
        int i;
        b[0] = (float)x0; b[1] = (float)(x0 + ext); b[2] = (float)y0; b[3] = (float)(y0 + ext);
        b[4] = (float)-zhi; b[5] = (float)(-(double)c.z + s.r);
        for (i = 0; i < 6; i++) if (!sk__finite(b[i])) return SK_ERR_DEGENERATE;
        if (!(b[1] > b[0]) || !(b[3] > b[2]) || !(b[5] > b[4])) return SK_ERR_DEGENERATE;
        *out_proj = sk_mat4_ortho(b[0], b[1], b[2], b[3], b[4], b[5]);
    }
    return SK_OK;
}

/* ---- 6.2b PSM and LiSPSM (Romanick's VGP353 notes) ------------------- */
// >>warps

/* Off-centre perspective from `eye` looking along `dir`, fitted around the
   points (all must lie in front); the casters' corners, taken to space `pp`
   first (or given so in cpts, when not NULL), widen only the depth range.
   Returns 0 if a point is not in front. */
static int sk__fit_perspective(sk_vec3 eye, sk_vec3 dir, const sk_vec3 *pts, int n, const sk_vec3 *cpts,
                               const sk_aabb *casters, int nc, const sk_mat4 *pp, sk_mat4 *out)
{
    sk_mat4 view = sk_mat4_look_at(eye, sk__add(eye, dir), sk__least_aligned_axis(dir));
    double l = 1e300, r = -1e300, b = 1e300, t = -1e300, zn = 1e300, zf = -1e300;
    double eps = 1e-7 * (1.0 + sk__maxabs3(eye)), cond = 1.0;
    int i;
    sk_mat4 p;
    /* depths first (all points, then the casters' corners): a point behind
       fails the fit early. `cond` = max (|point| + |eye|) / depth, at least
       1: how much a tangent coordinate x / depth magnifies the float error
       of the coordinates it comes from. It is large when the light is close
       to the body in post-perspective space: a light behind the viewer lies
       on z = (f+n)/(f-n), about 2n/D beyond a body at eye depth D (and
       n/D is small when the camera slid back for casters behind it) */
    for (i = 0; i < n; i++) {
        double depth = -(double)sk__xform_z(&view, pts[i]), c;
        if (!(depth > eps)) return 0;
        if (depth < zn) zn = depth;
        if (depth > zf) zf = depth;
        c = ((double)sk__maxabs3(pts[i]) + sk__maxabs3(eye)) / depth;
        if (c > cond) cond = c;
    }
    for (i = 0; i < 8 * nc; i++) {
        sk_vec3 q = cpts ? cpts[i] : sk__xform_point(pp, sk__aabb_corner(&casters[i / 8], i & 7));
        double depth = -(double)sk__xform_z(&view, q);
        if (!(depth > eps)) return 0;
        if (depth < zn) zn = depth;
        if (depth > zf) zf = depth;
    }
    for (i = 0; i < n; i++) {
        sk_vec3 q = sk__xform_affine(&view, pts[i]);
        double depth = -(double)q.z, x = q.x / depth, y = q.y / depth;
        if (x < l) l = x;
        if (x > r) r = x;
        if (y < b) b = y;
        if (y > t) t = y;
    }
    /* a small margin so the fitted points land inside, not on, the
       frustum; and no side thinner than 1e-4 cond of its offset from the
       axis (a flat body). The points' float coordinates, and the eye's,
       carry an error of about 1e-7 of their magnitudes, 1e-7 cond of the
       offset in tangent space; the float matrices made from them (m[8] =
       (r+l)/(r-l) holds only 24 bits, and the product with the camera's
       post-perspective matrix cancels as much) lose about as much again:
       a point lands about 1e-7 cond |m[8]| off in clip space. The floor
       keeps |m[8]| below 1e4 / cond, that error near 1e-3 */
    {
        double mx = 1e-4 * (r - l) + 1e-6, my = 1e-4 * (t - b) + 1e-6;
        double wx = 1e-4 * cond * (SK_FABS(l) + SK_FABS(r)), wy = 1e-4 * cond * (SK_FABS(b) + SK_FABS(t));
        if (r - l + 2.0 * mx < wx) mx = 0.5 * (wx - (r - l));
        if (t - b + 2.0 * my < wy) my = 0.5 * (wy - (t - b));
        l -= mx; r += mx; b -= my; t += my;
    }
    zn *= 0.999;
    zf *= 1.001;
    memset(&p, 0, sizeof p);
    p.m[0] = (float)(2.0 / (r - l));
    p.m[8] = (float)((r + l) / (r - l));
    p.m[5] = (float)(2.0 / (t - b));
    p.m[9] = (float)((t + b) / (t - b));
    p.m[10] = (float)(-(zf + zn) / (zf - zn));
    p.m[14] = (float)(-2.0 * zf * zn / (zf - zn));
    p.m[11] = -1.0f;
    *out = sk__mat_mul(p, view);
    return sk__mat_finite(out);
}

/* Perspective shadow maps (Stamminger & Drettakis 2002; the slides' special
   cases: lights behind the viewer invert, casters behind the camera). */
#define SK__PSM_CORNERS 256   /* caster corners kept in post-perspective space (32 boxes) */
SKDEF sk_result sk_psm_matrices(const sk_psm_desc *d, sk_psm_result *out)
{
    sk_vec3 l, le, fit[SK_CLIP_MAX_POINTS], cbuf[SK__PSM_CORNERS];
    const sk_vec3 *cpts = NULL;
    sk_mat4 vview, vproj, ppv, lvp;
    sk_vec4 lh;
    float slide = 0.0f, zf;
    int i, nfit, inverted = 0, ortho = 0;
    if (!d || !out || !sk__mat_finite(&d->cam_view) || !sk__v3_finite(d->light_dir) ||
        sk__len(d->light_dir) == 0.0f || !sk__finite(d->fovy) || !sk__finite(d->aspect) ||
        !sk__finite(d->zn) || !sk__finite(d->zf) || !(d->fovy > 0.0f) || !(d->fovy < SK__PI) ||
        !(d->aspect > 0.0f) || !(d->zn > 0.0f) || !(d->zf > d->zn) || d->caster_count < 0 ||
        (d->caster_count > 0 && !d->casters) || d->body_count < 0 || d->body_count > SK_CLIP_MAX_POINTS ||
        (d->body_count > 0 && !d->body) || !sk__finite(d->extra_slide) || d->extra_slide < 0.0f)
        return SK_ERR_INVALID_ARG;
    if (d->body_count > 0 && !sk__v3s_finite(d->body, d->body_count)) return SK_ERR_INVALID_ARG;
    for (i = 0; i < d->caster_count; i++)
        if (!sk__aabb_valid(&d->casters[i])) return SK_ERR_INVALID_ARG;
    /* casters behind the camera: slide the virtual camera back (Kozlov 2004) */
    for (i = 0; i < d->caster_count; i++) {
        /* the nearest corner: the larger product on each axis (float sums are
           monotone in each term, so this is the largest of the eight z) */
        const float *m = d->cam_view.m;
        const sk_aabb *c = &d->casters[i];
        float zx = m[2] * c->min.x > m[2] * c->max.x ? m[2] * c->min.x : m[2] * c->max.x;
        float zy = m[6] * c->min.y > m[6] * c->max.y ? m[6] * c->min.y : m[6] * c->max.y;
        float zz = m[10] * c->min.z > m[10] * c->max.z ? m[10] * c->min.z : m[10] * c->max.z;
        float depth = -(zx + zy + zz + m[14]);
        float s = d->zn - depth;
        if (s > slide) slide = s;
    }
    if (slide > 0.0f) slide += 0.01f * d->zn;
    slide += d->extra_slide;
    vview = d->cam_view;
    vview.m[14] -= slide;
    zf = d->zf + slide;
    vproj = sk_mat4_perspective(d->fovy, d->aspect, d->zn + d->extra_slide, zf);
    ppv = sk__mat_mul(vproj, vview);
    if (!sk__mat_finite(&ppv)) return SK_ERR_DEGENERATE;
    /* the casters' corners in post-perspective space, once for all fits below */
    if (d->caster_count <= SK__PSM_CORNERS / 8) {
        for (i = 0; i < d->caster_count; i++) sk__xform_box(&ppv, &d->casters[i], cbuf + 8 * i);
        cpts = cbuf;
    }

    /* the light in post-perspective space: P V (-dir, 0) */
    l = sk__normalize(sk__scale(d->light_dir, -1.0f));
    le = sk__v3(vview.m[0] * l.x + vview.m[4] * l.y + vview.m[8] * l.z,
                vview.m[1] * l.x + vview.m[5] * l.y + vview.m[9] * l.z,
                vview.m[2] * l.x + vview.m[6] * l.y + vview.m[10] * l.z);
    {
        sk_vec4 h;
        h.x = le.x; h.y = le.y; h.z = le.z; h.w = 0.0f;
        lh = sk_mat4_transform_vec4(vproj, h);
    }
    /* what the map covers in post-perspective space: the focus body, clamped
       to the unit cube (the view frustum), or the whole cube */
    nfit = 0;
    for (i = 0; i < d->body_count; i++) {
        sk_vec4 h, q;
        h.x = d->body[i].x; h.y = d->body[i].y; h.z = d->body[i].z; h.w = 1.0f;
        q = sk_mat4_transform_vec4(ppv, h);
        if (!(q.w > 0.0f)) continue;
        fit[nfit++] = sk__v3(sk__clampf(q.x / q.w, -1.0f, 1.0f), sk__clampf(q.y / q.w, -1.0f, 1.0f),
                             sk__clampf(q.z / q.w, -1.0f, 1.0f));
    }
    if (nfit < 4) {
        for (i = 0; i < 8; i++)
            fit[i] = sk__v3((i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f, (i & 4) ? 1.0f : -1.0f);
        nfit = 8;
    }
    if (SK_FABSF(le.z) < 1e-4f) {
        /* light perpendicular to the view: parallel rays in PP space too */
        sk_vec3 dir = sk__normalize(sk__v3(-lh.x, -lh.y, -lh.z));
        sk_mat4 lv = sk_mat4_look_at(sk__v3(0, 0, 0), dir, sk__least_aligned_axis(dir)), lp;
        double zlo = 1e300, zhi = -1e300;
        ortho = 1;
        if (sk_fit_ortho(fit, nfit, lv, NULL, &lp) != SK_OK) return SK_ERR_DEGENERATE;
        for (i = 0; i < 8 * d->caster_count; i++) {
            sk_vec3 q = sk__xform_affine(&lv, cpts ? cpts[i] : sk__xform_point(&ppv, sk__aabb_corner(&d->casters[i / 8], i & 7)));
            if (q.z < zlo) zlo = q.z;
            if (q.z > zhi) zhi = q.z;
        }
        if (d->caster_count > 0) {
            /* widen the fitted depth range [-1,1] to the casters' */
            double za = (-1.0 - lp.m[14]) / lp.m[10], zb = (1.0 - lp.m[14]) / lp.m[10];  /* view z at depth -1, +1 */
            if (zhi > za) za = zhi;
            if (zlo < zb) zb = zlo;
            lp.m[10] = (float)(2.0 / (zb - za));
            lp.m[14] = (float)(-1.0 - 2.0 * za / (zb - za));
        }
        lvp = sk__mat_mul(lp, lv);
        out->light_pp = dir;
    } else {
        /* finite point on z = (f+n)/(f-n); w < 0: the light is behind the
           viewer and becomes a sink: same frustum, reversed depth order */
        sk_vec3 lp = sk__v3(lh.x / lh.w, lh.y / lh.w, lh.z / lh.w), dir;
        inverted = lh.w < 0.0f;
        dir = sk__normalize(sk__scale(lp, -1.0f));
        if (!sk__fit_perspective(lp, dir, fit, nfit, cpts, d->casters, d->caster_count, &ppv, &lvp) &&
            !sk__fit_perspective(lp, sk__v3(0, 0, -1), fit, nfit, cpts, d->casters, d->caster_count, &ppv, &lvp))
            return SK_ERR_DEGENERATE;
        out->light_pp = lp;
    }
    out->light_view_proj = sk__mat_mul(lvp, ppv);
    if (!sk__mat_finite(&out->light_view_proj)) return SK_ERR_DEGENERATE;
    out->virtual_cam_view_proj = ppv;
    out->inverted = inverted;
    out->compare = inverted ? SK_DEPTH_GREATER : SK_DEPTH_LESS;
    out->orthographic = ortho;
    out->slide = slide;
    return SK_OK;
}

/* Light-space perspective shadow maps (Wimmer, Scherzer & Purgathofer 2004). */
SKDEF sk_result sk_lispsm_matrices(const sk_lispsm_desc *d, sk_lispsm_result *out)
{
    sk_vec3 l, v, yax, zax, xax, lbody[SK_CLIP_MAX_POINTS];   /* light-space body, when it fits */
    sk_mat4 lv;
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    double cosg, sing, depth, n, mag;
    int i, k;
    if (!d || !out || !sk__v3_finite(d->eye) || !sk__v3_finite(d->view_dir) ||
        !sk__v3_finite(d->light_dir) || sk__len(d->view_dir) == 0.0f || sk__len(d->light_dir) == 0.0f ||
        !sk__finite(d->zn) || !(d->zn > 0.0f) || !d->body || d->body_count < 1 ||
        !sk__finite(d->n_override) || (d->casters && !sk__aabb_valid(d->casters)))
        return SK_ERR_INVALID_ARG;
    if (!sk__v3s_finite(d->body, d->body_count)) return SK_ERR_INVALID_ARG;
    l = sk__normalize(d->light_dir);
    v = sk__normalize(d->view_dir);
    {
        /* sin(gamma) = |v x l| and the warp axis v - (v.l) l, in double: both
           cancel badly in float as the light turns parallel to the view */
        double lx = l.x, ly = l.y, lz = l.z, vx = v.x, vy = v.y, vz = v.z;
        double cx = vy * lz - vz * ly, cy = vz * lx - vx * lz, cz = vx * ly - vy * lx;
        cosg = vx * lx + vy * ly + vz * lz;
        sing = SK_SQRT(cx * cx + cy * cy + cz * cz);
        if (sing > 1.0) sing = 1.0;   /* float unit vectors: |v x l| may round past 1 */
        yax = sk__v3((float)(vx - cosg * lx), (float)(vy - cosg * ly), (float)(vz - cosg * lz));
    }
    /* light space: z towards the light, y the view direction projected
       perpendicular to the light (the warp axis), origin at the eye */
    zax = sk__scale(l, -1.0f);
    if (sing < 1e-6 || sk__len(yax) < 1e-7f) {
        sk_mat4 fixed = sk_light_view_directional(l);
        yax = sk__v3(fixed.m[1], fixed.m[5], fixed.m[9]);
        sing = 0.0;
    }
    yax = sk__normalize(yax);
    xax = sk__normalize(sk__cross(yax, zax));
    lv = sk__basis_view(xax, yax, zax, d->eye);
    for (i = 0; i < d->body_count; i++) {
        sk_vec3 p = sk__xform_affine(&lv, d->body[i]);
        if (i < SK_CLIP_MAX_POINTS) lbody[i] = p;
        for (k = 0; k < 3; k++) {
            if ((&p.x)[k] < lo[k]) lo[k] = (&p.x)[k];
            if ((&p.x)[k] > hi[k]) hi[k] = (&p.x)[k];
        }
    }
    hi[2] = sk__casters_zmax(&lv, d->casters, hi[2]);
    depth = hi[1] - lo[1];
    if (d->n_override > 0.0f) n = d->n_override;
    else if (sing > 0.0) {
        double zf = d->zn + depth * sing;
        n = (d->zn + SK_SQRT((double)d->zn * zf)) / sing;   /* n_opt */
    } else n = SK__INF;
    out->sin_gamma = (float)sing;
    /* the magnitude the light-space body was computed from (its world
       points and the eye): its float error is about 1e-7 of that. A body
       thinner along the warp axis than 1e-4 of it cannot be warped: it is
       flat, the uniform map holds it */
    mag = 0.0;
    for (i = 0; i < d->body_count; i++) if (sk__maxabs3(d->body[i]) > mag) mag = sk__maxabs3(d->body[i]);
    mag += sk__maxabs3(d->eye);
    if (!(depth > 1e-4 * (1.0 + SK_FABS(lo[1]) + SK_FABS(hi[1]) + mag)) || !sk__finite_d(n) || n > 1e4 * depth) {
        /* uniform focused map: the limit of the warp as n -> infinity */
        sk_mat4 box;
        if (!sk__ortho_box_fit(lo[0], hi[0], lo[1], hi[1], lo[2], hi[2], mag, &box)) return SK_ERR_DEGENERATE;
        out->light_view_proj = sk__mat_mul(box, lv);
        out->n = SK__INF;
        out->warped = 0;
        return sk__mat_finite(&out->light_view_proj) ? SK_OK : SK_ERR_DEGENERATE;
    }
    {
        /* projection centre n before the body along y; perspective along y:
           x' = x, y' = a y + b, z' = z, w' = y (depth order along a light
           ray, fixed x and y, is kept since w is constant there) */
        double f = n + depth, a = (f + n) / (f - n), b = -2.0 * f * n / (f - n);
        double wlo[3] = {1e300, 1e300, 1e300}, whi[3] = {-1e300, -1e300, -1e300};
        sk_mat4 t = sk_mat4_identity(), w, crop;
        t.m[13] = (float)-(lo[1] - n);
        memset(&w, 0, sizeof w);
        w.m[0] = 1.0f;
        w.m[5] = (float)a;
        w.m[13] = (float)b;
        w.m[10] = 1.0f;
        w.m[7] = 1.0f;
        w = sk__mat_mul(w, t);
        /* the light-space body kept above, or (a longer one) transformed again */
        const sk_vec3 *kept = d->body_count <= SK_CLIP_MAX_POINTS ? lbody : NULL;
        for (i = 0; i < d->body_count; i++) {
            sk_vec3 p = sk__xform_point(&w, kept ? kept[i] : sk__xform_affine(&lv, d->body[i]));
            for (k = 0; k < 3; k++) {
                if ((&p.x)[k] < wlo[k]) wlo[k] = (&p.x)[k];
                if ((&p.x)[k] > whi[k]) whi[k] = (&p.x)[k];
            }
        }
        /* casters reach the map only on light rays through the body, where
           w lies in [n, n + depth]: bound their warped z conservatively */
        if (hi[2] > 0.0) { if (hi[2] / n > whi[2]) whi[2] = hi[2] / n; }
        else if (hi[2] / f > whi[2]) whi[2] = hi[2] / f;
        {
            /* the light-space coordinates carry a float error of about 1e-7
               of mag (and the matrix applies the same translations in
               float); the warp divides it by w >= n: the warped x and z =
               x / w are off by about 1e-7 of mag (1 + |x / w|) / n, the
               warped y = a + b / w by 1e-7 of mag |b| / n^2 =
               mag 2 f / (depth n). A warped side thinner than 1e-4 of its
               magnitude is widened to that, as sk__ortho_box_fit does for
               an unwarped box (a body seen end-on from the projection
               centre is a sliver in x or z however wide it is in light
               space) */
            double wm = 0.0, e[3];
            for (k = 0; k < 3; k += 2) {
                if (SK_FABS(wlo[k]) > wm) wm = SK_FABS(wlo[k]);
                if (SK_FABS(whi[k]) > wm) wm = SK_FABS(whi[k]);
            }
            e[0] = e[2] = 1e-4 * mag * (1.0 + wm) / n;
            e[1] = 1e-4 * mag * 2.0 * f / (depth * n);
            for (k = 0; k < 3; k++)
                if (whi[k] - wlo[k] < e[k]) {
                    double grow = 0.5 * (e[k] - (whi[k] - wlo[k]));
                    wlo[k] -= grow;
                    whi[k] += grow;
                }
        }
        if (!sk__ortho_box_fit(wlo[0], whi[0], wlo[1], whi[1], wlo[2], whi[2], 0.0, &crop)) return SK_ERR_DEGENERATE;
        out->light_view_proj = sk__mat_mul(sk__mat_mul(crop, w), lv);
        out->n = (float)n;
        out->warped = 1;
    }
    return sk__mat_finite(&out->light_view_proj) ? SK_OK : SK_ERR_DEGENERATE;
}

/* ---- 6.2c Light Space Partitioned Shadow Maps (Tang et al. 2017) ----- */
// >>lspsm

SKDEF sk_lspsm_params sk_lspsm_default_params(void)
{
    sk_lspsm_params p;
    p.zeta = 0.25f;   /* maximum space-wasting factor (Sec. 4) */
    p.sigma = 0.5f;   /* uv footprint difference tolerance */
    p.h_max = 4;      /* lengthways partitions */
    p.nw_max = 2;     /* transverse partitions per row */
    return p;
}

typedef struct sk__lspsm_sink {
    sk_rect *rects;                 /* may be NULL */
    sk_mat4 *vps;                   /* may be NULL */
    const sk_lspsm_region *region;  /* NULL: rects in the trapezoid's own frame */
} sk__lspsm_sink;

/* Partition i, [x0,x1] x [y0,y1] in the trapezoid's frame, as the caller
   gets it: in float, moved by the region's origin, with its view-projection
   when asked for. Returns 0 if float cannot hold it (a bound beyond
   FLT_MAX, a side that rounds to zero length, a matrix that overflows);
   writes only when `write` and the rect is held. */
static int sk__lspsm_put(const sk__lspsm_sink *s, int write, int i, double x0, double y0, double x1, double y1)
{
    sk_rect r;
    sk_mat4 vp;
    r.x0 = (float)x0; r.y0 = (float)y0; r.x1 = (float)x1; r.y1 = (float)y1;
    if (s->region) {
        r.x0 += s->region->origin.x; r.x1 += s->region->origin.x;
        r.y0 += s->region->origin.y; r.y1 += s->region->origin.y;
    }
    if (!sk__finite(r.x0) || !sk__finite(r.y0) || !sk__finite(r.x1) || !sk__finite(r.y1) || !(r.x1 > r.x0) ||
        !(r.y1 > r.y0))
        return 0;
    if (s->region && s->vps) {
        if (!sk__ortho_box_fit(r.x0, r.x1, r.y0, r.y1, s->region->zmin, s->region->zmax, 0.0, &vp)) return 0;
        vp = sk__mat_mul(vp, s->region->light_view);
        if (!sk__mat_finite(&vp)) return 0;
        if (write) s->vps[i] = vp;
    }
    if (write && s->rects) s->rects[i] = r;
    return 1;
}

/* Eq. (1): rows of width W_i and height H_i from the near base; each row's
   width is the trapezoid's width at its far edge. Transverse split when
   W/H > 1 + sigma (Sec. 3.2). Counts, and stops as soon as the count passes
   `limit`; with `write`, also writes (sk__lspsm_put). Returns the count,
   -1 if a value is not finite, -2 if float cannot hold a partition. */
static int sk__lspsm_rows(double n, double L, double theta, const sk_lspsm_params *p, const sk__lspsm_sink *sink,
                          int write, int limit)
{
    double t = SK_TAN(theta), zeta = p->zeta, q, hfac, W = n, y = 0.0;
    int i, count = 0;
    if (t <= zeta) { q = 1.0 / (1.0 - 2.0 * t); hfac = 1.0; }
    else { q = 1.0 / (1.0 - 2.0 * zeta); hfac = zeta / t; }
    for (i = 1; i <= p->h_max; i++) {
        double H, y1, row_w, ratio;
        int nw = 1, j;
        W *= q;
        H = W * hfac;
        y1 = y + H;
        row_w = W;
        if (i == p->h_max && y1 < L) { y1 = L; row_w = n + 2.0 * L * t; }
        if (!sk__finite_d(y1) || !sk__finite_d(row_w) || !(y1 > y)) return -1;
        ratio = row_w / (y1 - y);
        if (ratio > 1.0 + p->sigma) {
            double c = ratio / (1.0 + p->sigma);
            nw = c >= (double)p->nw_max ? p->nw_max : (int)SK_CEIL(c);
        }
        if (nw > limit - count) return limit + 1;    /* more than the caller can take */
        for (j = 0; j < nw; j++)
            if (!sk__lspsm_put(sink, write, count + j, -0.5 * row_w + row_w * j / nw, y,
                               -0.5 * row_w + row_w * (j + 1) / nw, y1))
                return -2;
        count += nw;
        y = y1;
        if (y >= L) break;
    }
    return count;
}

/* a count from a counting pass of sk__lspsm_rows as the public result */
static int sk__lspsm_count_result(int count, int cap)
{
    if (count == -1) return -(int)SK_ERR_INVALID_ARG;
    if (count < 0) return -(int)SK_ERR_DEGENERATE;
    if (count > cap) return -(int)SK_ERR_CAPACITY;
    return count;
}

static int sk__lspsm_params_valid(const sk_lspsm_params *p)
{
    return p && sk__finite(p->zeta) && sk__finite(p->sigma) && p->zeta > 0.0f && p->zeta < 0.5f &&
           p->sigma > 0.0f && p->h_max >= 1 && p->nw_max >= 1;
}

SKDEF int sk_lspsm_partition(float n, float L, float theta, const sk_lspsm_params *p, sk_rect *out, int cap)
{
    sk__lspsm_sink sink;
    int count;
    if (!out || cap < 0 || !sk__lspsm_params_valid(p) || !sk__finite(n) || !sk__finite(L) ||
        !sk__finite(theta) || !(n > 0.0f) || !(L > 0.0f) || !(theta >= 0.0f) ||
        !((double)theta < 0.5 * SK__PI))
        return -(int)SK_ERR_INVALID_ARG;
    sink.rects = out; sink.vps = NULL; sink.region = NULL;
    /* counted and checked first: an error writes nothing */
    count = sk__lspsm_count_result(sk__lspsm_rows(n, L, theta, p, &sink, 0, cap), cap);
    if (count < 0) return count;
    return sk__lspsm_rows(n, L, theta, p, &sink, 1, cap);
}

/* An isosceles trapezoid with legs of slope t >= 0 around points (x, s),
   s = y - y0 >= 0, has legs x = u - s t and x = v + s t with u = min(x + s t)
   and v = max(x - s t). A point with no larger x and no smaller s than
   another never gives v, for any t (float rounding is monotone, so not even
   by rounding), nor one with no smaller x and no smaller s u. Only the
   rest, the "fronts" of points not so dominated, are kept: (xs, s) with
   xs = x for v's front and xs = -x for u's, each dominated point removed as
   it is found. Returns the new front size. */
static int sk__front_add(double *fxs, double *fs, int k, double xs, double s)
{
    int j, m = 0;
    for (j = 0; j < k; j++)
        if (fxs[j] >= xs && fs[j] <= s) return k;
    for (j = 0; j < k; j++)
        if (!(xs >= fxs[j] && s <= fs[j])) { fxs[m] = fxs[j]; fs[m] = fs[j]; m++; }
    fxs[m] = xs;
    fs[m] = s;
    return m + 1;
}
/* point (x, y - y0 = s) to both fronts */
static void sk__fronts_add(double *lx, double *ls, int *nl, double *rx, double *rs, int *nr, double x, double s)
{
    *nl = sk__front_add(lx, ls, *nl, -x, s);
    *nr = sk__front_add(rx, rs, *nr, x, s);
}

/* Width at mid-height of the narrowest enclosing isosceles trapezoid with
   legs of slope t, plus L t (its area over L); u and v as above, from the
   fronts (lx: -x of u's front, rx: x of v's front). */
static double sk__trap_cost(const double *lx, const double *ls, int nl, const double *rx, const double *rs, int nr,
                            double L, double t, double *u, double *v)
{
    double lo = 1e300, hi = -1e300;
    int i;
    for (i = 0; i < nl; i++) {
        double a = -lx[i] + ls[i] * t;
        if (a < lo) lo = a;
    }
    for (i = 0; i < nr; i++) {
        double b = rx[i] - rs[i] * t;
        if (b > hi) hi = b;
    }
    *u = lo; *v = hi;
    return (hi - lo > 0.0 ? hi - lo : 0.0) + L * t;
}

/* Candidate slopes for the minimum of sk__trap_cost, evaluated
   SK__TRAP_BATCH at a time: for each line of the fronts in turn, every
   candidate's u and v (the same products, sums and comparisons as
   sk__trap_cost, candidate by candidate, so the same values); then taken in
   order as sk__trap_cost would be: a candidate in (0, tmax] wins if cheaper
   than *best (relative 1e-12), or as cheap and smaller than *t. Unused
   slots hold t = 0 and are not looked at. */
#define SK__TRAP_BATCH 16
typedef struct sk__trap_batch {
    const double *lx, *ls, *rx, *rs;
    int nl, nr, k;
    double L, c[SK__TRAP_BATCH];
} sk__trap_batch;

static void sk__trap_flush(sk__trap_batch *q, double *best, double *t)
{
    double lo[SK__TRAP_BATCH], hi[SK__TRAP_BATCH];
    int i, j, kk = (q->k + 1) & ~1;   /* in pairs (one 2-wide vector operation each) */
    for (j = 0; j < kk; j += 2) { lo[j] = lo[j + 1] = 1e300; hi[j] = hi[j + 1] = -1e300; }
    for (i = 0; i < q->nl; i++) {
        double x = -q->lx[i], s = q->ls[i];
        for (j = 0; j < kk; j += 2) {
            double a0 = x + s * q->c[j], a1 = x + s * q->c[j + 1];
            lo[j] = a0 < lo[j] ? a0 : lo[j];
            lo[j + 1] = a1 < lo[j + 1] ? a1 : lo[j + 1];
        }
    }
    for (i = 0; i < q->nr; i++) {
        double x = q->rx[i], s = q->rs[i];
        for (j = 0; j < kk; j += 2) {
            double b0 = x - s * q->c[j], b1 = x - s * q->c[j + 1];
            hi[j] = b0 > hi[j] ? b0 : hi[j];
            hi[j + 1] = b1 > hi[j + 1] ? b1 : hi[j + 1];
        }
    }
    for (j = 0; j < q->k; j++) {
        double c = q->c[j], f = (hi[j] - lo[j] > 0.0 ? hi[j] - lo[j] : 0.0) + q->L * c;
        if (f < *best - 1e-12 * *best || (f <= *best + 1e-12 * *best && c < *t)) { *best = f; *t = c; }
    }
    for (j = 0; j < kk; j++) q->c[j] = 0.0;
    q->k = 0;
}

static void sk__trap_try(sk__trap_batch *q, double tmax, double c, double *best, double *t)
{
    if (!(c > 0.0 && c <= tmax)) return;
    q->c[q->k++] = c;
    if (q->k == SK__TRAP_BATCH) sk__trap_flush(q, best, t);
}

SKDEF sk_result sk_lspsm_region_extract(const sk_frustum *view, sk_vec3 view_dir, sk_aabb receivers,
                                        const sk_aabb *casters, sk_vec3 light_dir, sk_lspsm_region *out)
{
    sk_vec3 pts[SK_CLIP_MAX_POINTS], l, v, yax, zax, xax, centre = sk__v3(0, 0, 0);
    double lx[SK_CLIP_MAX_POINTS], ls[SK_CLIP_MAX_POINTS], rx[SK_CLIP_MAX_POINTS], rs[SK_CLIP_MAX_POINTS];
    sk_lspsm_region r;
    double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300, zmin = 1e300, zmax = -1e300, L, tiny;
    int n, i, nl = 0, nr = 0;
    if (!view || !out || !sk__v3_finite(view_dir) || !sk__v3_finite(light_dir) ||
        sk__len(view_dir) == 0.0f || sk__len(light_dir) == 0.0f || (casters && !sk__aabb_valid(casters)))
        return SK_ERR_INVALID_ARG;
    n = sk_clip_frustum_aabb(view, receivers, pts, SK_CLIP_MAX_POINTS);
    if (n < 0) return SK_ERR_INVALID_ARG;
    if (n == 0) return SK_ERR_DEGENERATE;
    for (i = 0; i < n; i++) centre = sk__add(centre, sk__scale(pts[i], 1.0f / n));
    memset(&r, 0, sizeof r);
    l = sk__normalize(light_dir);
    v = sk__normalize(view_dir);
    zax = sk__scale(l, -1.0f);
    yax = sk__sub(v, sk__scale(l, sk__dot(v, l)));
    if (sk__len(yax) < 1e-4f) {
        /* view parallel to the light: no trapezoid axis */
        sk_mat4 fixed = sk_light_view_directional(l);
        yax = sk__v3(fixed.m[1], fixed.m[5], fixed.m[9]);
        r.fallback = 1;
    }
    yax = sk__normalize(yax);
    xax = sk__normalize(sk__cross(yax, zax));
    r.light_view = sk__basis_view(xax, yax, zax, centre);
    for (i = 0; i < n; i++) {
        const float *m = r.light_view.m;
        sk_vec3 p = pts[i], q;
        q.x = m[0] * p.x + m[4] * p.y + m[8] * p.z + m[12];
        q.y = m[1] * p.x + m[5] * p.y + m[9] * p.z + m[13];
        q.z = m[2] * p.x + m[6] * p.y + m[10] * p.z + m[14];
        pts[i] = q;
        if (q.x < xmin) xmin = q.x;
        if (q.x > xmax) xmax = q.x;
        if (q.y < ymin) ymin = q.y;
        if (q.y > ymax) ymax = q.y;
        if (q.z < zmin) zmin = q.z;
        if (q.z > zmax) zmax = q.z;
    }
    if (casters)
        for (i = 0; i < 8; i++) {
            double z = sk__xform_z(&r.light_view, sk__aabb_corner(casters, i));
            if (z < zmin) zmin = z;
            if (z > zmax) zmax = z;
        }
    r.zmin = (float)zmin;
    r.zmax = (float)zmax;
    L = ymax - ymin;
    /* no length, or no width (every point on one line along the axis, where
       the trapezoid's bases would be 0): one focused map */
    if (!r.fallback && (!(L > 1e-6 * (1.0 + (xmax - xmin))) || !(xmax - xmin > 1e-6 * (1.0 + L))))
        r.fallback = 1;
    /* the narrowest side kept: enough float steps at these coordinates for
       partition rects that do not round to nothing */
    tiny = 1e-5 * (1.0 + SK_FABS(xmin) + SK_FABS(xmax) + SK_FABS(ymin) + SK_FABS(ymax));
    if (r.fallback) {
        r.n = (float)(xmax - xmin > tiny ? xmax - xmin : tiny);
        r.L = (float)(L > tiny ? L : tiny);
        r.theta = 0.0f;
        r.origin.x = (float)(0.5 * (xmin + xmax));
        r.origin.y = (float)ymin;
    } else {
        /* minimise area L*(n + L tan theta) over t = tan theta in
           [0, (xmax-xmin)/L]: the cost is convex and piecewise linear in t
           (sk__trap_cost), so its minimum lies at t = 0, at the end, or where
           two lines of one front cross (a breakpoint); all are tried, the
           smallest t winning ties */
        double tmax = (xmax - xmin) / L, u, w, t = 0.0, nn, far_w, best;
        sk__trap_batch q;
        int j;
        for (i = 0; i < n; i++)
            sk__fronts_add(lx, ls, &nl, rx, rs, &nr, pts[i].x, pts[i].y - ymin);
        best = sk__trap_cost(lx, ls, nl, rx, rs, nr, L, 0.0, &u, &w);
        q.lx = lx; q.ls = ls; q.rx = rx; q.rs = rs; q.nl = nl; q.nr = nr; q.k = 0; q.L = L;
        for (i = 0; i < SK__TRAP_BATCH; i++) q.c[i] = 0.0;
        sk__trap_try(&q, tmax, tmax, &best, &t);
        for (i = 0; i < nl; i++)
            for (j = i + 1; j < nl; j++)
                if (ls[i] != ls[j]) sk__trap_try(&q, tmax, (lx[i] - lx[j]) / (ls[i] - ls[j]), &best, &t);
        for (i = 0; i < nr; i++)
            for (j = i + 1; j < nr; j++)
                if (rs[i] != rs[j]) sk__trap_try(&q, tmax, (rx[i] - rx[j]) / (rs[i] - rs[j]), &best, &t);
        if (q.k) sk__trap_flush(&q, &best, &t);
        sk__trap_cost(lx, ls, nl, rx, rs, nr, L, t, &u, &w);
        nn = w - u;
        far_w = nn + 2.0 * L * t;
        if (nn < 1e-2 * far_w) nn = 1e-2 * far_w;     /* n -> 0: rows of usable size */
        if (nn < tiny) nn = tiny;                       /* a body of no width */
        r.n = (float)nn;
        r.L = (float)L;
        /* rounded up: near pi/2 a float step of theta is 0.1% of tan theta,
           and a narrower trapezoid would cut off the body's far corners */
        r.theta = sk__float_up(SK_ATAN(t));
        r.origin.x = (float)(0.5 * (u + w));
        r.origin.y = (float)ymin;
    }
    /* coordinates near FLT_MAX: a region float cannot hold */
    if (!sk__mat_finite(&r.light_view) || !sk__finite(r.n) || !sk__finite(r.L) || !sk__finite(r.zmin) ||
        !sk__finite(r.zmax) || !sk__finite(r.origin.x) || !sk__finite(r.origin.y) || !(r.n > 0.0f) || !(r.L > 0.0f))
        return SK_ERR_DEGENERATE;
    *out = r;
    return SK_OK;
}

SKDEF int sk_lspsm_crops(const sk_lspsm_region *r, const sk_lspsm_params *p,
                         sk_mat4 *out_view_proj, sk_rect *out_rects, int cap)
{
    sk__lspsm_sink sink;
    int count;
    if (!r || !out_view_proj || cap < 0 || !sk__lspsm_params_valid(p) || !sk__mat_finite(&r->light_view) ||
        !sk__finite(r->n) || !sk__finite(r->L) || !sk__finite(r->theta) || !(r->n > 0.0f) ||
        !(r->L > 0.0f) || !(r->theta >= 0.0f) || !((double)r->theta < 0.5 * SK__PI) ||
        !sk__finite(r->zmin) || !sk__finite(r->zmax) || !sk__finite(r->origin.x) || !sk__finite(r->origin.y))
        return -(int)SK_ERR_INVALID_ARG;
    sink.rects = out_rects; sink.vps = out_view_proj; sink.region = r;
    if (r->fallback) {
        if (cap < 1) return -(int)SK_ERR_CAPACITY;
        if (!sk__lspsm_put(&sink, 1, 0, -0.5 * r->n, 0.0, 0.5 * r->n, r->L)) return -(int)SK_ERR_DEGENERATE;
        return 1;
    }
    count = sk__lspsm_count_result(sk__lspsm_rows(r->n, r->L, r->theta, p, &sink, 0, cap), cap);
    if (count < 0) return count;
    return sk__lspsm_rows(r->n, r->L, r->theta, p, &sink, 1, cap);
}

/* ---- 7. Omnidirectional lights (King & Newhall 2004) ----------------- */
// >>point

/* Per face: right, up, forward (GL cube-map face table: s runs along
   right, t along up, the major axis is forward). */
static const signed char sk__cube_axes[6][3][3] = {
    {{0, 0, -1}, {0, -1, 0}, {1, 0, 0}},   /* +X: sc = -rz, tc = -ry */
    {{0, 0, 1}, {0, -1, 0}, {-1, 0, 0}},   /* -X: sc = +rz, tc = -ry */
    {{1, 0, 0}, {0, 0, 1}, {0, 1, 0}},     /* +Y: sc = +rx, tc = +rz */
    {{1, 0, 0}, {0, 0, -1}, {0, -1, 0}},   /* -Y: sc = +rx, tc = -rz */
    {{1, 0, 0}, {0, -1, 0}, {0, 0, 1}},    /* +Z: sc = +rx, tc = -ry */
    {{-1, 0, 0}, {0, -1, 0}, {0, 0, -1}}   /* -Z: sc = -rx, tc = -ry */
};
static sk_vec3 sk__cube_axis(int face, int which)
{
    const signed char *a = sk__cube_axes[face][which];
    return sk__v3(a[0], a[1], a[2]);
}

SKDEF sk_mat4 sk_cube_face_view(int face, sk_vec3 light_pos)
{
    if (face < 0 || face > 5) face = 0;
    if (!sk__v3_finite(light_pos)) light_pos = sk__v3(0, 0, 0);
    return sk__basis_view(sk__cube_axis(face, 0), sk__cube_axis(face, 1),
                          sk__scale(sk__cube_axis(face, 2), -1.0f), light_pos);
}

SKDEF sk_mat4 sk_cube_face_proj(float zn, float zf)
{
    sk_mat4 r;
    if (!sk__finite(zn) || !sk__finite(zf) || !(zn > 0.0f) || !(zf > zn)) return sk_mat4_identity();
    memset(&r, 0, sizeof r);
    r.m[0] = r.m[5] = 1.0f;
    r.m[10] = (float)(((double)zf + zn) / ((double)zn - zf));
    r.m[11] = -1.0f;
    r.m[14] = (float)(2.0 * zf * zn / ((double)zn - zf));
    return r;
}

/* HalfIntersection(A, B): does an edge of A (a corner inside B included)
   reach B? Each edge is clipped against B's planes (Liang-Barsky). */
static int sk__half_intersection(const sk_frustum *a, const sk_frustum *b, float tol)
{
    int e, k;
    for (e = 0; e < 12; e++) {
        sk_vec3 p0 = a->corners[sk__edges[e][0]], p1 = a->corners[sk__edges[e][1]];
        float t0 = 0.0f, t1 = 1.0f;
        for (k = 0; k < 6; k++) {
            float d0 = sk__plane_dist(&b->planes[k], p0) + tol, d1 = sk__plane_dist(&b->planes[k], p1) + tol;
            if (d0 < 0.0f && d1 < 0.0f) break;
            if (d0 < 0.0f) { float t = d0 / (d0 - d1); if (t > t0) t0 = t; }
            else if (d1 < 0.0f) { float t = d0 / (d0 - d1); if (t < t1) t1 = t; }
            if (t0 > t1) break;
        }
        if (k == 6) return 1;
    }
    return 0;
}

SKDEF int sk_frustum_intersects(const sk_frustum *a, const sk_frustum *b)
{
    float scale = 0.0f;
    int i;
    if (!a || !b || sk__frustum_invalid(a) || sk__frustum_invalid(b)) return 1;
    for (i = 0; i < 8; i++) {
        float sa = sk__maxabs3(a->corners[i]), sb = sk__maxabs3(b->corners[i]);
        if (sa > scale) scale = sa;
        if (sb > scale) scale = sb;
    }
    scale = 1e-5f * (1.0f + scale);
    return sk__half_intersection(a, b, scale) || sk__half_intersection(b, a, scale);
}

/* The frustum of one cube face, built directly (90 degree side planes). */
static void sk__cube_face_frustum(int face, sk_vec3 lp, float zn, float zf, sk_frustum *f)
{
    sk_vec3 r = sk__cube_axis(face, 0), u = sk__cube_axis(face, 1), fw = sk__cube_axis(face, 2);
    const float s = 0.70710678118654752f;
    int i;
    for (i = 0; i < 8; i++) {
        float d = (i & 4) ? zf : zn;
        sk_vec3 c = sk__add(lp, sk__scale(fw, d));
        c = sk__add(c, sk__scale(r, (i & 1) ? d : -d));
        f->corners[i] = sk__add(c, sk__scale(u, (i & 2) ? d : -d));
    }
    /* inside: |right.(p-l)| <= fw.(p-l) and the same for up */
    f->planes[0].n = sk__scale(sk__add(fw, r), s);
    f->planes[1].n = sk__scale(sk__sub(fw, r), s);
    f->planes[2].n = sk__scale(sk__add(fw, u), s);
    f->planes[3].n = sk__scale(sk__sub(fw, u), s);
    for (i = 0; i < 4; i++) f->planes[i].d = -sk__dot(f->planes[i].n, lp);
    f->planes[4].n = fw;
    f->planes[4].d = -sk__dot(fw, lp) - zn;
    f->planes[5].n = sk__scale(fw, -1.0f);
    f->planes[5].d = sk__dot(fw, lp) + zf;
}

SKDEF unsigned sk_cube_visible_faces(sk_vec3 light_pos, float zn, float zf, const sk_frustum *view)
{
    unsigned bits = 0;
    int face;
    if (!view || !sk__v3_finite(light_pos) || !sk__finite(zn) || !sk__finite(zf) || !(zn > 0.0f) ||
        !(zf > zn) || sk__frustum_invalid(view))
        return 0x3fu;
    if (sk_frustum_contains_point(view, light_pos)) return 0x3fu;
    for (face = 0; face < 6; face++) {
        sk_frustum f;
        sk__cube_face_frustum(face, light_pos, zn, zf, &f);
        if (sk_frustum_intersects(&f, view)) bits |= 1u << face;
    }
    return bits;
}

SKDEF sk_result sk_caster_shadow_frustum(sk_vec3 light_pos, float light_range, sk_aabb caster, sk_frustum *out)
{
    /* in double: a small box far away subtends an angle below float
       resolution, and a cone that rounds to zero width would cull it */
    double lp[3], lo[3], hi[3], ax[3] = {0, 0, 0}, u[3], v[3], dist2 = 0.0, al = 0.0, tan_a = 0.0, near_d = 1e300;
    double mag = sk__maxabs3(light_pos);
    sk_vec3 c[8];
    int i, k, wide = 1;
    if (!out || !sk__v3_finite(light_pos) || !sk__finite(light_range) || !(light_range > 0.0f) ||
        !sk__aabb_valid(&caster))
        return SK_ERR_INVALID_ARG;
    lp[0] = light_pos.x; lp[1] = light_pos.y; lp[2] = light_pos.z;
    lo[0] = caster.min.x; lo[1] = caster.min.y; lo[2] = caster.min.z;
    hi[0] = caster.max.x; hi[1] = caster.max.y; hi[2] = caster.max.z;
    for (k = 0; k < 3; k++) {
        double nearest = lp[k] < lo[k] ? lo[k] : lp[k] > hi[k] ? hi[k] : lp[k];
        dist2 += (nearest - lp[k]) * (nearest - lp[k]);
        ax[k] = 0.5 * (lo[k] + hi[k]) - lp[k];
        al += ax[k] * ax[k];
    }
    if (!(SK_SQRT(dist2) < light_range)) return SK_ERR_DEGENERATE;   /* out of reach: no shadow */
    al = SK_SQRT(al);
    if (dist2 > 0.0 && al > 0.0) {
        /* the cone around the axis to the box centre, through the corner
           farthest off it; near plane at the corner nearest along it */
        for (k = 0; k < 3; k++) ax[k] /= al;
        wide = 0;
        for (i = 0; i < 8 && !wide; i++) {
            double d[3], along = 0.0, lat = 0.0;
            for (k = 0; k < 3; k++) { d[k] = ((i >> k & 1) ? hi[k] : lo[k]) - lp[k]; along += d[k] * ax[k]; }
            for (k = 0; k < 3; k++) lat += (d[k] - along * ax[k]) * (d[k] - along * ax[k]);
            if (!(along > 0.0)) { wide = 1; break; }
            if (SK_SQRT(lat) / along > tan_a) tan_a = SK_SQRT(lat) / along;
            if (along < near_d) near_d = along;
        }
    }
    /* light inside the box, or a cone wider than 170 degrees: the range box */
    if (wide || !(tan_a <= 11.430052302761343)) {
        sk_aabb b;
        b.min = sk__sub(light_pos, sk__v3(light_range, light_range, light_range));
        b.max = sk__add(light_pos, sk__v3(light_range, light_range, light_range));
        return sk_frustum_from_aabb(b, out);
    }
    {
        /* u, v: unit axes across the cone */
        sk_vec3 a = sk__v3((float)ax[0], (float)ax[1], (float)ax[2]), w = sk__least_aligned_axis(a);
        double ul;
        u[0] = ax[1] * w.z - ax[2] * w.y; u[1] = ax[2] * w.x - ax[0] * w.z; u[2] = ax[0] * w.y - ax[1] * w.x;
        ul = SK_SQRT(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
        for (k = 0; k < 3; k++) u[k] /= ul;
        v[0] = ax[1] * u[2] - ax[2] * u[1]; v[1] = ax[2] * u[0] - ax[0] * u[2]; v[2] = ax[0] * u[1] - ax[1] * u[0];
    }
    for (i = 0; i < 8; i++) {
        /* a margin of 1e-4 relative, and at least 1e-6 of the magnitudes at
           hand, so float corners still hold the cone */
        double d = (i & 4) ? light_range : near_d;
        double h = d * tan_a * 1.0001 + 1e-6 * (1.0 + mag + d), p[3];
        for (k = 0; k < 3; k++) p[k] = lp[k] + ax[k] * d + u[k] * ((i & 1) ? h : -h) + v[k] * ((i & 2) ? h : -h);
        c[i] = sk__v3((float)p[0], (float)p[1], (float)p[2]);
    }
    if (sk_frustum_from_corners(c, out) == SK_OK) return SK_OK;
    {
        /* corners float cannot hold: the range box, which holds the cone */
        sk_aabb b;
        b.min = sk__sub(light_pos, sk__v3(light_range, light_range, light_range));
        b.max = sk__add(light_pos, sk__v3(light_range, light_range, light_range));
        return sk_frustum_from_aabb(b, out);
    }
}

SKDEF int sk_caster_visible(sk_vec3 light_pos, float light_range, sk_aabb caster, const sk_frustum *view)
{
    sk_frustum f;
    sk_result r;
    if (!view) return 1;
    r = sk_caster_shadow_frustum(light_pos, light_range, caster, &f);
    if (r == SK_ERR_DEGENERATE) return 0;
    if (r != SK_OK) return 1;
    return sk_frustum_intersects(&f, view);
}

SKDEF int sk_light_scissor(sk_vec3 light_pos, float radius, sk_mat4 view_proj, int vp_w, int vp_h, int out_rect[4])
{
    double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
    int i, behind = 0, x0, y0, x1, y1;
    if (!out_rect) return 0;
    out_rect[0] = out_rect[1] = out_rect[2] = out_rect[3] = 0;
    if (!sk__v3_finite(light_pos) || !sk__finite(radius) || !(radius > 0.0f) || vp_w < 1 || vp_h < 1 ||
        !sk__mat_finite(&view_proj))
        return 0;
    for (i = 0; i < 8; i++) {
        /* in double: in float the corners may overflow, and tiny clip w
           underflow to 0 (every corner then "behind") */
        const float *m = view_proj.m;
        double p[3], c[4];
        int r;
        p[0] = (double)light_pos.x + ((i & 1) ? radius : -radius);
        p[1] = (double)light_pos.y + ((i & 2) ? radius : -radius);
        p[2] = (double)light_pos.z + ((i & 4) ? radius : -radius);
        for (r = 0; r < 4; r++) c[r] = m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r];
        if (c[3] <= 0.0) { behind++; continue; }
        {
            double x = (0.5 * c[0] / c[3] + 0.5) * vp_w, y = (0.5 * c[1] / c[3] + 0.5) * vp_h;
            if (x < xmin) xmin = x;
            if (x > xmax) xmax = x;
            if (y < ymin) ymin = y;
            if (y > ymax) ymax = y;
        }
    }
    if (behind == 8) return 0;
    if (behind > 0) { out_rect[2] = vp_w; out_rect[3] = vp_h; return 1; }
    if (xmin < 0.0) xmin = 0.0;
    if (ymin < 0.0) ymin = 0.0;
    if (xmax > vp_w) xmax = vp_w;
    if (ymax > vp_h) ymax = vp_h;
    if (!(xmax > xmin) || !(ymax > ymin)) return 0;      /* off-screen */
    x0 = (int)SK_FLOOR(xmin); y0 = (int)SK_FLOOR(ymin);
    x1 = (int)SK_CEIL(xmax); y1 = (int)SK_CEIL(ymax);
    if (x1 <= x0 || y1 <= y0) return 0;
    out_rect[0] = x0; out_rect[1] = y0; out_rect[2] = x1 - x0; out_rect[3] = y1 - y0;
    return 1;
}

/* N * M^2 >= c * S with c = 2 in King & Newhall 2004 ("Optimizing Shadow Texture Resolution") */
SKDEF int sk_cube_resolution(int faces, float pixels, float c, int max_res)
{
    int top = 1, m = 1;
    double need;
    if (faces < 0 || faces > 6 || !sk__finite(c) || !(c > 0.0f) || pixels != pixels || pixels < 0.0f ||
        max_res < 1 || faces == 0)
        return 0;
    while (top <= max_res / 2) top *= 2;
    need = (double)c * pixels / faces;
    while (m < top && (double)m * m < need) m *= 2;
    return m;
}

static int sk__spot_args(sk_vec3 apex, sk_vec3 axis, float half_angle)
{
    return sk__v3_finite(apex) && sk__v3_finite(axis) && sk__len(axis) > 0.0f && sk__finite(half_angle) &&
           half_angle > 0.0f && half_angle <= 1.5f;
}

SKDEF sk_mat4 sk_spot_view(sk_vec3 apex, sk_vec3 axis)
{
    sk_vec3 f, s, u;
    if (!sk__v3_finite(apex) || !sk__v3_finite(axis) || !(sk__len(axis) > 0.0f)) return sk_mat4_identity();
    f = sk__normalize(axis);
    s = sk__normalize(sk__cross(f, sk__least_aligned_axis(f)));
    u = sk__cross(s, f);
    return sk__basis_view(s, u, sk__scale(f, -1.0f), apex);
}

/* the rectangle (at unit depth) that the convex body of points pts covers
   beyond depth zn in eye space view: its points in front, and the crossings
   of the plane zn by every segment between two of them (a superset of its
   edges: the others lie inside the body); 0 when none of it lies beyond zn */
static int sk__spot_rect(const sk_mat4 *view, const sk_vec3 *pts, int n, double zn, double r[4])
{
    double p[SK_CLIP_MAX_POINTS][3];
    int i, j, any = 0;
    r[0] = r[1] = 1e300;
    r[2] = r[3] = -1e300;
    for (i = 0; i < n; i++) {
        int k;
        for (k = 0; k < 3; k++)
            p[i][k] = (double)view->m[k] * pts[i].x + (double)view->m[4 + k] * pts[i].y +
                      (double)view->m[8 + k] * pts[i].z + view->m[12 + k];
        p[i][2] = -p[i][2];   /* depth along the axis */
    }
    for (i = 0; i < n; i++)
        for (j = i; j < n; j++) {
            double x, y, d;
            if (j == i) {
                if (p[i][2] < zn) continue;
                x = p[i][0]; y = p[i][1]; d = p[i][2];
            } else {
                double t;
                if ((p[i][2] < zn) == (p[j][2] < zn)) continue;
                t = (zn - p[i][2]) / (p[j][2] - p[i][2]);
                x = p[i][0] + t * (p[j][0] - p[i][0]); y = p[i][1] + t * (p[j][1] - p[i][1]); d = zn;
            }
            x /= d; y /= d;
            if (x < r[0]) r[0] = x;
            if (y < r[1]) r[1] = y;
            if (x > r[2]) r[2] = x;
            if (y > r[3]) r[3] = y;
            any = 1;
        }
    return any;
}

/* the square window over rectangle r inside the cone's square [-t, t]^2:
   centred (res 0) or snapped to the grid of res texels over its side */
static void sk__spot_square(const double r[4], double t, int res, double margin, float win[4])
{
    double side = r[2] - r[0] > r[3] - r[1] ? r[2] - r[0] : r[3] - r[1], c, x0, tex, full;
    int k;
    if (res > 0) {
        /* the smallest 2t / 2^k holding the rectangle, its margins and one texel */
        full = 2.0 * t;
        while (full * 0.5 >= side + (2.0 * margin + 1.0) * full * 0.5 / res) full *= 0.5;
        tex = full / res;
        for (k = 0; k < 2; k++) {
            x0 = -t + SK_FLOOR((r[k] - margin * tex + t) / tex) * tex;
            if (x0 + full > t) x0 = t - full;
            if (x0 < -t) x0 = -t;
            win[k] = (float)x0;
            win[k + 2] = (float)(x0 + full);
        }
        return;
    }
    for (k = 0; k < 2; k++) {
        c = 0.5 * (r[k] + r[k + 2]);
        if (c - 0.5 * side < -t) c = -t + 0.5 * side;
        if (c + 0.5 * side > t) c = t - 0.5 * side;
        win[k] = (float)(c - 0.5 * side);
        win[k + 2] = (float)(c + 0.5 * side);
    }
}

SKDEF int sk_spot_window(sk_vec3 apex, sk_vec3 axis, float half_angle, float zn, const sk_aabb *bounds,
                         const sk_frustum *view, int res, float margin, float win[4])
{
    double t, r[4];
    sk_vec3 pts[SK_CLIP_MAX_POINTS];
    sk_mat4 eye;
    int k, n;
    if (!win) return -1;
    win[0] = win[1] = win[2] = win[3] = 0.0f;
    if (!sk__spot_args(apex, axis, half_angle) || !sk__finite(zn) || !(zn > 0.0f) ||
        (bounds && !sk__aabb_valid(bounds)) || res < 0 || !sk__finite(margin) || margin < 0.0f)
        return -1;
    t = SK_TAN((double)half_angle);
    win[0] = win[1] = (float)-t;
    win[2] = win[3] = (float)t;
    if (!bounds) return 1;
    if (view) {
        n = sk_clip_frustum_aabb(view, *bounds, pts, SK_CLIP_MAX_POINTS);
        if (n < 0) return -1;
    } else {
        for (n = 0; n < 8; n++) pts[n] = sk__aabb_corner(bounds, n);
    }
    eye = sk_spot_view(apex, axis);
    if (n == 0 || !sk__spot_rect(&eye, pts, n, zn, r)) return 0;
    for (k = 0; k < 2; k++) {
        if (r[k] < -t) r[k] = -t;
        if (r[k + 2] > t) r[k + 2] = t;
        if (r[k] >= r[k + 2]) return 0;
    }
    sk__spot_square(r, t, res, margin, win);
    return 1;
}

SKDEF sk_mat4 sk_spot_matrix(sk_vec3 apex, sk_vec3 axis, const float win[4], float zn, float zf)
{
    sk_mat4 p, view;
    double l, r, b, t, n = zn, f = zf;
    if (!win || !sk__v3_finite(apex) || !sk__v3_finite(axis) || !(sk__len(axis) > 0.0f) || !sk__finite(zn) ||
        !sk__finite(zf) || !(zn > 0.0f) || !(zf > zn) || !sk__finite(win[0]) || !sk__finite(win[1]) ||
        !sk__finite(win[2]) || !sk__finite(win[3]) || !(win[2] > win[0]) || !(win[3] > win[1]))
        return sk_mat4_identity();
    l = win[0] * n; r = win[2] * n; b = win[1] * n; t = win[3] * n;
    memset(&p, 0, sizeof p);
    p.m[0] = (float)(2.0 * n / (r - l));
    p.m[5] = (float)(2.0 * n / (t - b));
    p.m[8] = (float)((r + l) / (r - l));
    p.m[9] = (float)((t + b) / (t - b));
    p.m[10] = (float)(-(f + n) / (f - n));
    p.m[11] = -1.0f;
    p.m[14] = (float)(-2.0 * f * n / (f - n));
    view = sk_spot_view(apex, axis);
    return sk_mat4_mul(p, view);
}

SKDEF int sk_spot_box_visible(sk_vec3 apex, sk_vec3 axis, float half_angle, float range, sk_aabb box)
{
    double v[3], a[3], al, along, dist2, perp, rad, ca, sa;
    int k;
    if (!sk__spot_args(apex, axis, half_angle) || !sk__finite(range) || !(range > 0.0f) || !sk__aabb_valid(&box))
        return 1;
    al = SK_SQRT((double)axis.x * axis.x + (double)axis.y * axis.y + (double)axis.z * axis.z);
    a[0] = axis.x / al; a[1] = axis.y / al; a[2] = axis.z / al;
    v[0] = 0.5 * ((double)box.min.x + box.max.x) - apex.x;
    v[1] = 0.5 * ((double)box.min.y + box.max.y) - apex.y;
    v[2] = 0.5 * ((double)box.min.z + box.max.z) - apex.z;
    rad = 0.5 * SK_SQRT(((double)box.max.x - box.min.x) * ((double)box.max.x - box.min.x) +
                        ((double)box.max.y - box.min.y) * ((double)box.max.y - box.min.y) +
                        ((double)box.max.z - box.min.z) * ((double)box.max.z - box.min.z));
    along = dist2 = 0.0;
    for (k = 0; k < 3; k++) { along += v[k] * a[k]; dist2 += v[k] * v[k]; }
    if (SK_SQRT(dist2) > (double)range + rad) return 0;
    if (along < -rad) return 0;
    perp = dist2 - along * along;
    perp = perp > 0.0 ? SK_SQRT(perp) : 0.0;
    /* the centre's distance to the cone's side (negative inside) */
    ca = SK_COS((double)half_angle);
    sa = SK_SQRT(1.0 - ca * ca);   /* half_angle in (0, 1.5]: sin > 0 */
    return perp * ca - along * sa <= rad;
}

SKDEF sk_result sk_vsdct_layout_make(int face_res, sk_vsdct_layout *out)
{
    int f;
    if (!out || face_res < 1 || face_res > SK_VSDCT_MAX_FACE_RES) return SK_ERR_INVALID_ARG;
    out->face_res = face_res;
    out->atlas_w = 3 * face_res;
    out->atlas_h = 2 * face_res;
    for (f = 0; f < 6; f++) {
        out->face_x[f] = (f % 3) * face_res;
        out->face_y[f] = (f / 3) * face_res;
    }
    return SK_OK;
}

static int sk__ceil_log2(int x)
{
    int e = 0;
    while (e < 31 && (1u << e) < (unsigned)x) e++;
    return e;
}

/* Eq. (5.4.7) */
SKDEF int sk_vsdct_indirection_size(int face_res, int grey_levels, int deriv_bits)
{
    int e, g;
    if (face_res < 1 || face_res > SK_VSDCT_MAX_FACE_RES || grey_levels < 1 || deriv_bits < 0)
        return 0;
    g = sk__ceil_log2(grey_levels);
    e = sk__ceil_log2(face_res) + (g < deriv_bits ? g : deriv_bits) - deriv_bits;
    return e <= 0 ? 1 : 1 << e;
}

/* Eq. (5.4.6): Z_s = -1/MA * zf zn/(zf - zn) + zf/(zf - zn), the same in GL
   window depth as in D3D's [0,1] NDC */
SKDEF void sk_vsdct_depth_coeffs(float zn, float zf, float *scale, float *bias)
{
    double s = 0.0, b = 1.0;
    if (sk__finite(zn) && sk__finite(zf) && zn > 0.0f && zf > zn) {
        s = -(double)zf * zn / ((double)zf - zn);
        b = (double)zf / ((double)zf - zn);
    }
    if (scale) *scale = (float)s;
    if (bias) *bias = (float)b;
}

static int sk__layout_valid(const sk_vsdct_layout *l)
{
    int f;
    if (!l || l->face_res < 1 || l->face_res > SK_VSDCT_MAX_FACE_RES || l->atlas_w < l->face_res ||
        l->atlas_h < l->face_res || l->atlas_w > SK_VSDCT_MAX_ATLAS || l->atlas_h > SK_VSDCT_MAX_ATLAS)
        return 0;
    for (f = 0; f < 6; f++)
        if (l->face_x[f] < 0 || l->face_y[f] < 0 || l->face_x[f] > l->atlas_w - l->face_res ||
            l->face_y[f] > l->atlas_h - l->face_res)
            return 0;
    return 1;
}

/* face-local s, t in [0,1] -> atlas u, v, at least half a texel inside */
static void sk__vsdct_atlas(const sk_vsdct_layout *l, int face, double s, double t, float *u, float *v)
{
    double fs = s * l->face_res, ft = t * l->face_res, hi = l->face_res - 0.5;
    if (fs < 0.5) fs = 0.5;
    if (fs > hi) fs = hi;
    if (ft < 0.5) ft = 0.5;
    if (ft > hi) ft = hi;
    *u = (float)((l->face_x[face] + fs) / l->atlas_w);
    *v = (float)((l->face_y[face] + ft) / l->atlas_h);
}

SKDEF int sk_vsdct_lookup(const sk_vsdct_layout *l, sk_vec3 dir, float *u, float *v)
{
    double ax = SK_FABS(dir.x), ay = SK_FABS(dir.y), az = SK_FABS(dir.z), ma;
    int face;
    sk_vec3 d;
    if (!u || !v || !sk__layout_valid(l) || !sk__v3_finite(dir) || (ax == 0.0 && ay == 0.0 && az == 0.0))
        return -1;
    if (ax >= ay && ax >= az) { face = dir.x >= 0.0f ? 0 : 1; ma = ax; }
    else if (ay >= az) { face = dir.y >= 0.0f ? 2 : 3; ma = ay; }
    else { face = dir.z >= 0.0f ? 4 : 5; ma = az; }
    d = dir;
    sk__vsdct_atlas(l, face, 0.5 * (sk__dot(sk__cube_axis(face, 0), d) / ma + 1.0),
                    0.5 * (sk__dot(sk__cube_axis(face, 1), d) / ma + 1.0), u, v);
    return face;
}

SKDEF sk_result sk_vsdct_indirection_fill(const sk_vsdct_layout *l, int ni, unsigned short *out)
{
    int face, s, t;
    if (!out || !sk__layout_valid(l) || ni < 1 || ni > 65536) return SK_ERR_INVALID_ARG;
    for (face = 0; face < 6; face++)
        for (t = 0; t < ni; t++)
            for (s = 0; s < ni; s++) {
                float u, v;
                unsigned short *o = out + (((size_t)face * ni + t) * ni + s) * 2;
                sk__vsdct_atlas(l, face, (s + 0.5) / ni, (t + 0.5) / ni, &u, &v);
                o[0] = (unsigned short)(u * 65535.0 + 0.5);
                o[1] = (unsigned short)(v * 65535.0 + 0.5);
            }
    return SK_OK;
}

/* ---- 6.3 Resolution estimation (Ferko 2013) ------------------------- */
// >>ferko

/* Seed 000, Sec. 3: every pixel's corners are shared with its neighbours, so
   one row of corners is projected per pixel row, in strips of SK__RES_STRIP
   columns that keep the rows in cache. Evaluated in double precision: the
   NDC -> light-clip map nearly cancels for distant points (the depth
   unprojection), and a patch extent is a difference of neighbouring
   corners, so float rounding would show in the smallest patch, which
   decides the resolution.
   Every loop over a strip has a fixed length (a partial last strip is
   padded with invalid columns) and selects instead of branching, so a
   compiler can run it on vectors; the minima, maxima and counts are kept
   per strip column and combined at the end (a minimum does not depend on
   the order it is taken in). */
#define SK__RES_STRIP 64
#define SK__RES_ROW (SK__RES_STRIP + 8)   /* depth columns x0-1 .. x0+S+6 */
#define SK__RES_CORNERS (SK__RES_STRIP + 4)

SKDEF sk_result sk_estimate_resolution(const float *depth, int w, int h, sk_mat4 inv, sk_mat4 lvp,
                                       int max_res, sk_res_estimate *out)
{
    double m[16], g[16];
    double bx0 = SK__INF, by0 = SK__INF, bx1 = -SK__INF, by1 = -SK__INF, tw = SK__INF, th = SK__INF;
    double sx, sy, nsamples = 0.0, npatches = 0.0;
    int samples, x0, i, j;
    /* per depth row (two, alternating): valid depths (0 where invalid) and
       1 or 0 for valid; their vertical pair sums */
    double rowd[2][SK__RES_ROW], rowc[2][SK__RES_ROW], colsum[SK__RES_ROW], colcnt[SK__RES_ROW];
    /* per corner row (two, alternating): per pair of neighbouring corners
       their x and y ranges in light clip space and 1 or 0 for both valid */
    double cxr[SK__RES_CORNERS], cyr[SK__RES_CORNERS], cok[SK__RES_CORNERS];
    double pxl[2][SK__RES_STRIP], pxh[2][SK__RES_STRIP], pyl[2][SK__RES_STRIP], pyh[2][SK__RES_STRIP];
    double pok[2][SK__RES_STRIP];
    /* per pixel of the row: inside (1 or 0), x/w, y/w, patch (1 or 0) and its extents */
    double pin[SK__RES_STRIP], pqx[SK__RES_STRIP], pqy[SK__RES_STRIP], ppa[SK__RES_STRIP];
    double pex[SK__RES_STRIP], pey[SK__RES_STRIP];
    /* NDC x of the strip's corners and pixel centres */
    double ncx[SK__RES_CORNERS], npx[SK__RES_STRIP];
    /* per strip column, over all rows and strips: bounds, smallest patch
       extents, sample and patch counts */
    double abx0[SK__RES_STRIP], aby0[SK__RES_STRIP], abx1[SK__RES_STRIP], aby1[SK__RES_STRIP];
    double atw[SK__RES_STRIP], ath[SK__RES_STRIP], asam[SK__RES_STRIP], apat[SK__RES_STRIP];
    if (!depth || !out || w < 1 || h < 1 || w > 65536 || h > 65536 || max_res < 1 ||
        !sk__mat_finite(&inv) || !sk__mat_finite(&lvp))
        return SK_ERR_INVALID_ARG;
    /* NDC -> light clip in one matrix (in double): the homogeneous world
       point needs no divide in between, only the sign of its w (row 3 of inv) */
    for (i = 0; i < 16; i++) g[i] = inv.m[i];
    for (j = 0; j < 4; j++)
        for (i = 0; i < 4; i++)
            m[j * 4 + i] = (double)lvp.m[i] * g[j * 4] + (double)lvp.m[4 + i] * g[j * 4 + 1] +
                           (double)lvp.m[8 + i] * g[j * 4 + 2] + (double)lvp.m[12 + i] * g[j * 4 + 3];
    sx = 2.0 / w;
    sy = 2.0 / h;
    for (i = 0; i < SK__RES_STRIP; i++) {
        abx0[i] = aby0[i] = atw[i] = ath[i] = SK__INF;
        abx1[i] = aby1[i] = -SK__INF;
        asam[i] = apat[i] = 0.0;
    }
    for (x0 = 0; x0 < w; x0 += SK__RES_STRIP) {
        int cy, cur = 0;
        /* the strip lies inside the image with all its depth columns */
        int inner = x0 >= 1 && x0 - 1 + SK__RES_ROW <= w;
        for (i = 0; i < SK__RES_CORNERS; i++) ncx[i] = (x0 + i) * sx - 1.0;
        for (i = 0; i < SK__RES_STRIP; i++) npx[i] = (x0 + i + 0.5) * sx - 1.0;
        for (cy = 0; cy <= h; cy++) {
            /* corner row cy: corner (cx, cy) is shared by pixels (cx-1..cx, cy-1..cy) */
            const float *rb = cy < h ? depth + (size_t)cy * w : NULL;
            double ny = cy * sy - 1.0;
            double bx = m[4] * ny + m[12], by = m[5] * ny + m[13], bw = m[7] * ny + m[15];
            double gw = g[7] * ny + g[15];
            double *rd = rowd[cur], *rc = rowc[cur];
            const double *rdp = rowd[cur ^ 1], *rcp = rowc[cur ^ 1];
            /* depth row cy (column x0-1+i at index i); row cy-1 is kept from the last pass */
            /* (converted first, then selected: a float -> double conversion
               under a condition keeps compilers from using vectors) */
            if (rb && inner) {
                const float *src = rb + x0 - 1;
                for (i = 0; i < SK__RES_ROW; i++) rd[i] = src[i];
            } else {
                for (i = 0; i < SK__RES_ROW; i++) {
                    int c = x0 - 1 + i;
                    rd[i] = rb && c >= 0 && c < w ? (double)rb[c] : -1.0;
                }
            }
            for (i = 0; i < SK__RES_ROW; i++) {
                double d = rd[i];
                int v = (d >= 0.0) & (d < 1.0);   /* as the float comparisons */
                rd[i] = v ? d : 0.0;
                rc[i] = v ? 1.0 : 0.0;
            }
            if (cy == 0)
                for (i = 0; i < SK__RES_ROW; i++) { colsum[i] = rd[i]; colcnt[i] = rc[i]; }
            else
                for (i = 0; i < SK__RES_ROW; i++) { colsum[i] = rdp[i] + rd[i]; colcnt[i] = rcp[i] + rc[i]; }
            /* the corners: depth the mean of the valid pixels around */
            for (i = 0; i < SK__RES_CORNERS; i++) {
                double nv = colcnt[i] + colcnt[i + 1], nx = ncx[i];
                /* 1/nv for nv = 1..4 (correctly rounded, as the constants 1, 1/2,
                   1/3, 1/4 are; nv = 0 gives a corner that is not used) */
                double nz = 2.0 * ((colsum[i] + colsum[i + 1]) * (1.0 / nv)) - 1.0;
                double lx = bx + m[0] * nx + m[8] * nz, ly = by + m[1] * nx + m[9] * nz;
                double lw = bw + m[3] * nx + m[11] * nz, ww = gw + g[3] * nx + g[11] * nz;
                /* valid: a pixel around, and w > 0 once the point's world w is made
                   positive (the sign flip of x, y and w cancels in x/w, y/w); an
                   invalid corner's x, y are never looked at */
                int ok = (nv > 0.0) & (((ww < 0.0) & (lw < 0.0)) | ((ww > 0.0) & (lw > 0.0)));
                double iw = 1.0 / lw;
                cxr[i] = lx * iw;
                cyr[i] = ly * iw;
                cok[i] = ok ? 1.0 : 0.0;
            }
            /* x and y ranges of neighbouring corner pairs, shared by the
               patches of the pixel rows above and below */
            for (i = 0; i < SK__RES_STRIP; i++) {
                double a = cxr[i], b = cxr[i + 1], c = cyr[i], e = cyr[i + 1];
                pok[cur][i] = cok[i] * cok[i + 1];
                pxl[cur][i] = a < b ? a : b; pxh[cur][i] = a > b ? a : b;
                pyl[cur][i] = c < e ? c : e; pyh[cur][i] = c > e ? c : e;
            }
            if (cy > 0) {
                /* pixel row cy-1 (depths rdp, column x0+i at index i+1): centres,
                   then patches from corner rows cy-1 (lo) and cy (hi) */
                int lo = cur ^ 1;
                double ny2 = (cy - 0.5) * sy - 1.0;
                double cbx = m[4] * ny2 + m[12], cby = m[5] * ny2 + m[13];
                double cbz = m[6] * ny2 + m[14], cbw = m[7] * ny2 + m[15];
                double cgw = g[7] * ny2 + g[15];
                /* first every pixel's light-clip x/w, y/w, patch extents and
                   flags, then (from those, with no arithmetic left under a
                   condition) the per-column minima, maxima and counts */
                for (i = 0; i < SK__RES_STRIP; i++) {
                    double nx = npx[i], nz = 2.0 * rdp[i + 1] - 1.0;
                    double lx = cbx + m[0] * nx + m[8] * nz, ly = cby + m[1] * nx + m[9] * nz;
                    double lz = cbz + m[2] * nx + m[10] * nz, lw = cbw + m[3] * nx + m[11] * nz;
                    double ww = cgw + g[3] * nx + g[11] * nz;
                    /* w with the world point's w made positive (x, y, z flip with
                       it, which changes neither |x|, |y|, |z| nor x/w, y/w) */
                    double sw = lw * (ww < 0.0 ? -1.0 : 1.0);
                    /* a valid pixel inside the light's clip volume (Sec. 3.1) */
                    int in = (rcp[i + 1] != 0.0) & (sw > 0.0) & (SK_FABS(lx) <= sw) & (SK_FABS(ly) <= sw) &
                             (SK_FABS(lz) <= sw);
                    pin[i] = in ? 1.0 : 0.0;
                    pqx[i] = lx / lw;
                    pqy[i] = ly / lw;
                    /* the patch: AABB of the four projected corners (Sec. 3.2) */
                    ppa[i] = pin[i] * pok[lo][i] * pok[cur][i];
                    pex[i] = (pxh[lo][i] > pxh[cur][i] ? pxh[lo][i] : pxh[cur][i]) -
                             (pxl[lo][i] < pxl[cur][i] ? pxl[lo][i] : pxl[cur][i]);
                    pey[i] = (pyh[lo][i] > pyh[cur][i] ? pyh[lo][i] : pyh[cur][i]) -
                             (pyl[lo][i] < pyl[cur][i] ? pyl[lo][i] : pyl[cur][i]);
                }
                for (i = 0; i < SK__RES_STRIP; i++) {
                    double qx = pqx[i], qy = pqy[i], ex = pex[i], ey = pey[i];
                    int in = pin[i] != 0.0, patch = ppa[i] != 0.0;
                    asam[i] += pin[i];
                    apat[i] += ppa[i];
                    abx0[i] = (in & (qx < abx0[i])) ? qx : abx0[i];
                    abx1[i] = (in & (qx > abx1[i])) ? qx : abx1[i];
                    aby0[i] = (in & (qy < aby0[i])) ? qy : aby0[i];
                    aby1[i] = (in & (qy > aby1[i])) ? qy : aby1[i];
                    atw[i] = (patch & (ex < atw[i])) ? ex : atw[i];
                    ath[i] = (patch & (ey < ath[i])) ? ey : ath[i];
                }
            }
            cur ^= 1;
        }
    }
    for (i = 0; i < SK__RES_STRIP; i++) {
        if (abx0[i] < bx0) bx0 = abx0[i];
        if (abx1[i] > bx1) bx1 = abx1[i];
        if (aby0[i] < by0) by0 = aby0[i];
        if (aby1[i] > by1) by1 = aby1[i];
        if (atw[i] < tw) tw = atw[i];
        if (ath[i] < th) th = ath[i];
        nsamples += asam[i];
        npatches += apat[i];
    }
    samples = nsamples < 2147483647.0 ? (int)nsamples : 2147483647;
    memset(out, 0, sizeof *out);
    out->bounds.x0 = -1.0f; out->bounds.y0 = -1.0f; out->bounds.x1 = 1.0f; out->bounds.y1 = 1.0f;
    out->crop = sk_mat4_identity();
    if (samples == 0) return SK_OK;
    {
        double bw = bx1 - bx0, bh = by1 - by0, rw, rh;
        /* no patch, or (corners at the edge of double range) no patch of
           finite extent along an axis: the map is max_res wide there */
        if (!(npatches > 0.0) || !(tw < SK__INF)) tw = bw / max_res;
        if (!(npatches > 0.0) || !(th < SK__INF)) th = bh / max_res;
        rw = tw > 0.0 ? bw / tw : (double)max_res;
        rh = th > 0.0 ? bh / th : (double)max_res;
        out->width = !(rw < max_res) ? max_res : rw < 1.0 ? 1 : (int)SK_CEIL(rw);
        out->height = !(rh < max_res) ? max_res : rh < 1.0 ? 1 : (int)SK_CEIL(rh);
        if (out->width > max_res) out->width = max_res;
        if (out->height > max_res) out->height = max_res;
    }
    out->bounds.x0 = (float)bx0; out->bounds.y0 = (float)by0; out->bounds.x1 = (float)bx1; out->bounds.y1 = (float)by1;
    /* a patch wider than float holds (and wider than the bounds: the map is
       1 texel there) reads as FLT_MAX */
    out->texel_w = tw < FLT_MAX ? (float)tw : FLT_MAX;
    out->texel_h = th < FLT_MAX ? (float)th : FLT_MAX;
    out->samples = samples;
    out->crop = sk_crop_matrix(out->bounds, -1.0f, 1.0f);
    return SK_OK;
}

/* ---- 9. Predicted virtual soft shadow maps (Shen et al. 2011) -------- */
// >>soft

/* The cubics' maxima, where their derivatives vanish:
   dynamic 0.7794 + 0.7934x - 0.08148x^2 = 0, static 1.406 - 0.09374x - 0.011832x^2 = 0 */
static double sk__rho_x(float n, double peak)
{
    double x;
    if (!(n > 1.0f)) return 0.0;
    x = SK_LOG2((double)n);
    return x > peak ? peak : x;
}
static double sk__peak(double a1, double a2, double a3)
{
    /* positive root of a1 + 2 a2 x + 3 a3 x^2 = 0 (a3 < 0) */
    double A = 3.0 * a3, B = 2.0 * a2, C = a1;
    return (-B - SK_SQRT(B * B - 4.0 * A * C)) / (2.0 * A);
}
SKDEF float sk_rho_dynamic(float n)
{
    double x = sk__rho_x(n, sk__peak(0.7794, 0.3967, -0.02716));
    return (float)(0.667 + x * (0.7794 + x * (0.3967 - 0.02716 * x)));
}
SKDEF float sk_rho_static(float n)
{
    double x = sk__rho_x(n, sk__peak(1.406, -0.04687, -0.003944));
    return (float)(0.5477 + x * (1.406 + x * (-0.04687 - 0.003944 * x)));
}

/* Appendix: V_h = M0 M0^T + M1 M1^T, then the Cholesky factor's columns */
SKDEF void sk_convolve_parallelograms(sk_vec2 u0, sk_vec2 v0, sk_vec2 u1, sk_vec2 v1,
                                      sk_vec2 *u_out, sk_vec2 *v_out)
{
    double m00, m10, m11, ux, uy, vy;
    sk_vec2 zero;
    zero.x = zero.y = 0.0f;
    if (!u_out || !v_out) return;
    if (!sk__finite(u0.x) || !sk__finite(u0.y) || !sk__finite(v0.x) || !sk__finite(v0.y) ||
        !sk__finite(u1.x) || !sk__finite(u1.y) || !sk__finite(v1.x) || !sk__finite(v1.y)) {
        *u_out = zero; *v_out = zero;
        return;
    }
    m00 = (double)u0.x * u0.x + (double)v0.x * v0.x + (double)u1.x * u1.x + (double)v1.x * v1.x;
    m10 = (double)u0.x * u0.y + (double)v0.x * v0.y + (double)u1.x * u1.y + (double)v1.x * v1.y;
    m11 = (double)u0.y * u0.y + (double)v0.y * v0.y + (double)u1.y * u1.y + (double)v1.y * v1.y;
    ux = SK_SQRT(m00);
    uy = ux > 0.0 ? m10 / ux : 0.0;
    vy = m11 - uy * uy;
    vy = vy > 0.0 ? SK_SQRT(vy) : 0.0;
    u_out->x = (float)ux; u_out->y = (float)uy;
    v_out->x = 0.0f; v_out->y = (float)vy;
    if (!sk__finite(u_out->x) || !sk__finite(u_out->y) || !sk__finite(v_out->y)) { *u_out = zero; *v_out = zero; }
}

/* sk_texel_box_coverage in double: a box thinner than about 1e-19 texels
   on both axes covers less than float can hold */
static double sk__texel_box_coverage_d(float x0, float y0, float x1, float y1, int tx, int ty)
{
    double ax0, ax1, ay0, ay1;
    if (x0 != x0 || y0 != y0 || x1 != x1 || y1 != y1) return 0.0;
    ax0 = x0 > (double)tx ? x0 : (double)tx; ax1 = x1 < (double)tx + 1 ? x1 : (double)tx + 1;
    ay0 = y0 > (double)ty ? y0 : (double)ty; ay1 = y1 < (double)ty + 1 ? y1 : (double)ty + 1;
    if (!(ax1 > ax0) || !(ay1 > ay0)) return 0.0;
    return (ax1 - ax0) * (ay1 - ay0);
}

SKDEF float sk_texel_box_coverage(float x0, float y0, float x1, float y1, int tx, int ty)
{
    return (float)sk__texel_box_coverage_d(x0, y0, x1, y1, tx, ty);
}

/* Sec. 4.1: texels as quads clipped by the kernel, so the result varies
   continuously with the kernel's position and size. */
SKDEF float sk_smooth_box_visibility(float x0, float y0, float x1, float y1,
                                     int (*lit)(void *user, int tx, int ty), void *user)
{
    double sum = 0.0, area;
    int tx0, ty0, tx1, ty1, tx, ty;
    if (!lit || !sk__finite(x0) || !sk__finite(y0) || !sk__finite(x1) || !sk__finite(y1) ||
        SK_FABS(x0) > 1e9 || SK_FABS(x1) > 1e9 || SK_FABS(y0) > 1e9 || SK_FABS(y1) > 1e9)
        return -1.0f;
    if (!(x1 > x0) || !(y1 > y0))
        return lit(user, (int)SK_FLOOR(0.5 * ((double)x0 + x1)), (int)SK_FLOOR(0.5 * ((double)y0 + y1))) ? 1.0f : 0.0f;
    tx0 = (int)SK_FLOOR(x0); tx1 = (int)SK_CEIL(x1);
    ty0 = (int)SK_FLOOR(y0); ty1 = (int)SK_CEIL(y1);
    if (tx1 - tx0 > 64 || ty1 - ty0 > 64) return -1.0f;
    for (ty = ty0; ty < ty1; ty++)
        for (tx = tx0; tx < tx1; tx++)
            if (lit(user, tx, ty)) sum += sk__texel_box_coverage_d(x0, y0, x1, y1, tx, ty);
    area = ((double)x1 - x0) * ((double)y1 - y0);
    sum /= area;
    return (float)(sum > 1.0 ? 1.0 : sum);
}

/* Eq. (4): n_0 = ||M^-1 e0 e0^T u_h||, n_1 = ||M^-1 e1 e1^T v_h||;
   Eq. (5): r_0 = 2 e0^T u_h / rho(n_0), r_1 = 2 e1^T v_h / rho(n_1) */
SKDEF void sk_pvsm_predict(sk_vec2 u_h, sk_vec2 v_h, sk_vec2 u_phi, sk_vec2 v_phi,
                           int dynamic_scene, float *r0, float *r1)
{
    double det, n0, n1, a, b;
    if (!sk__finite(u_h.x) || !sk__finite(u_h.y) || !sk__finite(v_h.x) || !sk__finite(v_h.y) ||
        !sk__finite(u_phi.x) || !sk__finite(u_phi.y) || !sk__finite(v_phi.x) || !sk__finite(v_phi.y)) {
        if (r0) *r0 = SK__INF;
        if (r1) *r1 = SK__INF;
        return;
    }
    det = (double)u_phi.x * v_phi.y - (double)v_phi.x * u_phi.y;
    a = SK_FABS((double)u_h.x);
    b = SK_FABS((double)v_h.y);
    /* M^-1 (a,0) = a/det (v.y, -u.y); M^-1 (0,b) = b/det (-v.x, u.x) */
    if (det != 0.0) {
        n0 = a * SK_SQRT((double)v_phi.y * v_phi.y + (double)u_phi.y * u_phi.y) / SK_FABS(det);
        n1 = b * SK_SQRT((double)v_phi.x * v_phi.x + (double)u_phi.x * u_phi.x) / SK_FABS(det);
    } else n0 = n1 = 1e30;
    if (!(n0 < 1e30)) n0 = 1e30;
    if (!(n1 < 1e30)) n1 = 1e30;
    /* a size past FLT_MAX stays finite: +INFINITY would read as "no sample" */
    a = 2.0 * a / (dynamic_scene ? sk_rho_dynamic((float)n0) : sk_rho_static((float)n0));
    b = 2.0 * b / (dynamic_scene ? sk_rho_dynamic((float)n1) : sk_rho_static((float)n1));
    if (r0) *r0 = a < FLT_MAX ? (float)a : FLT_MAX;
    if (r1) *r1 = b < FLT_MAX ? (float)b : FLT_MAX;
}

/* Sec. 5.2: V_dst = V_dst A_dst + V_src A_src, A_dst = A_dst + A_src */
SKDEF void sk_pvsm_merge(float *v, float *a, float v_src, float a_src)
{
    double na;
    if (!v || !a || !sk__finite(v_src) || !sk__finite(a_src) || !(a_src > 0.0f) || !sk__finite(*v) ||
        !sk__finite(*a) || *a < 0.0f)
        return;
    na = (double)*a + a_src;
    *v = (float)(((double)*v * *a + (double)v_src * a_src) / na);
    *a = (float)na;
}

SKDEF int sk_smtg_pyramid_size(int gw, int gh)
{
    long total = 0;
    if (gw < 1 || gh < 1 || gw > 4096 || gh > 4096) return 0;
    for (;;) {
        total += (long)gw * gh * 2;
        if (gw == 1 && gh == 1) break;
        gw = (gw + 1) / 2;
        gh = (gh + 1) / 2;
    }
    return (int)total;
}

/* min that ignores NaN (NaN = no sample) */
static float sk__minf(float a, float b) { return (b < a || a != a) ? b : a; }

SKDEF int sk_smtg_pyramid(const float *grid, int gw, int gh, float *out, int cap_floats)
{
    int need = sk_smtg_pyramid_size(gw, gh), levels = 1, i;
    float *src;
    if (!grid || !out || need == 0 || cap_floats < 0) return -(int)SK_ERR_INVALID_ARG;
    if (cap_floats < need) return -(int)SK_ERR_CAPACITY;
    for (i = 0; i < gw * gh * 2; i++) out[i] = grid[i] != grid[i] ? SK__INF : grid[i];
    src = out;
    while (gw > 1 || gh > 1) {
        int nw = (gw + 1) / 2, nh = (gh + 1) / 2, x, y, c;
        float *dst = src + (size_t)gw * gh * 2;
        for (y = 0; y < nh; y++)
            for (x = 0; x < nw; x++)
                for (c = 0; c < 2; c++) {
                    float v = src[((2 * y) * gw + 2 * x) * 2 + c];
                    if (2 * x + 1 < gw) v = sk__minf(v, src[((2 * y) * gw + 2 * x + 1) * 2 + c]);
                    if (2 * y + 1 < gh) {
                        v = sk__minf(v, src[((2 * y + 1) * gw + 2 * x) * 2 + c]);
                        if (2 * x + 1 < gw) v = sk__minf(v, src[((2 * y + 1) * gw + 2 * x + 1) * 2 + c]);
                    }
                    dst[(y * nw + x) * 2 + c] = v;
                }
        src = dst;
        gw = nw; gh = nh;
        levels++;
    }
    return levels;
}

/* Resolution a node of `cells` cells needs along one axis, or a huge value. */
static double sk__node_res(int cells, int g, float min_texel)
{
    double span = 2.0 * cells / g;
    if (!(min_texel < SK__INF)) return 1.0;
    if (!(min_texel > 0.0f)) return 1e30;
    return SK_CEIL(span / min_texel);
}

/* Giegl & Wimmer's kd-tree over the SMTG, traversed top-down (Sec. 5.2, steps 5-7) */
SKDEF int sk_fvsm_tiles(const float *grid, int gw, int gh, int max_res, sk_tile *out, int cap)
{
    int stack[64][4], sp = 0, count = 0;
    if (!grid || !out || cap < 0 || gw < 1 || gh < 1 || gw > 4096 || gh > 4096 || max_res < 1)
        return -(int)SK_ERR_INVALID_ARG;
    stack[0][0] = 0; stack[0][1] = 0; stack[0][2] = gw; stack[0][3] = gh;
    sp = 1;
    while (sp > 0) {
        int x0, y0, x1, y1, x, y, bx0 = 1 << 30, by0 = 1 << 30, bx1 = -1, by1 = -1;
        float mx = SK__INF, my = SK__INF;
        double rx, ry;
        sp--;
        x0 = stack[sp][0]; y0 = stack[sp][1]; x1 = stack[sp][2]; y1 = stack[sp][3];
        for (y = y0; y < y1; y++)
            for (x = x0; x < x1; x++) {
                float a = grid[((size_t)y * gw + x) * 2], b = grid[((size_t)y * gw + x) * 2 + 1];
                if (a != a) a = SK__INF;
                if (b != b) b = SK__INF;
                if (!(a < SK__INF) && !(b < SK__INF)) continue;
                if (a < 0.0f) a = 0.0f;
                if (b < 0.0f) b = 0.0f;
                if (a < mx) mx = a;
                if (b < my) my = b;
                if (x < bx0) bx0 = x;
                if (x + 1 > bx1) bx1 = x + 1;
                if (y < by0) by0 = y;
                if (y + 1 > by1) by1 = y + 1;
            }
        if (bx1 < 0) continue;                         /* no sample in this node */
        rx = sk__node_res(bx1 - bx0, gw, mx);
        ry = sk__node_res(by1 - by0, gh, my);
        if ((rx <= max_res && ry <= max_res) || (bx1 - bx0 == 1 && by1 - by0 == 1)) {
            if (count == cap) return -(int)SK_ERR_CAPACITY;
            out[count].x0 = bx0; out[count].y0 = by0; out[count].x1 = bx1; out[count].y1 = by1;
            out[count].res_x = rx > max_res ? max_res : rx < 1.0 ? 1 : (int)rx;
            out[count].res_y = ry > max_res ? max_res : ry < 1.0 ? 1 : (int)ry;
            count++;
            continue;
        }
        {
            /* split in half along the axis that exceeds the limit more */
            int split_x = rx >= ry ? (bx1 - bx0 > 1) : !(by1 - by0 > 1);
            SK_ASSERT(sp + 2 <= 64);
            stack[sp][0] = bx0; stack[sp][1] = by0; stack[sp][2] = bx1; stack[sp][3] = by1;
            stack[sp + 1][0] = bx0; stack[sp + 1][1] = by0; stack[sp + 1][2] = bx1; stack[sp + 1][3] = by1;
            if (split_x) { int mid = (bx0 + bx1) / 2; stack[sp][2] = mid; stack[sp + 1][0] = mid; }
            else { int mid = (by0 + by1) / 2; stack[sp][3] = mid; stack[sp + 1][1] = mid; }
            sp += 2;
        }
    }
    return count;
}

/* ---- 6.4 RMSM page requests (Romanick's VGP353 notes) --------------- */
// >>rmsm

static int sk__page_cmp(const sk_page *a, const sk_page *b)
{
    if (a->level != b->level) return a->level < b->level ? -1 : 1;
    if (a->py != b->py) return a->py < b->py ? -1 : 1;
    if (a->px != b->px) return a->px < b->px ? -1 : 1;
    return 0;
}

static int sk__is_pow2(int x) { return x > 0 && (x & (x - 1)) == 0; }

SKDEF int sk_rmsm_page_requests(const sk_vec3 *samples, int count, int virtual_res, int page_size,
                                sk_page *out, int cap)
{
    int i, n = 0, max_level = 0, have_last = 0;
    sk_page last;
    if (count < 0 || cap < 0 || (count > 0 && !samples) || (cap > 0 && !out) || !sk__is_pow2(virtual_res) ||
        !sk__is_pow2(page_size) || page_size > virtual_res)
        return -(int)SK_ERR_INVALID_ARG;
    while ((page_size << max_level) < virtual_res) max_level++;
    memset(&last, 0, sizeof last);
    for (i = 0; i < count; i++) {
        sk_page p;
        double lod = samples[i].z, pages;
        int lo, hi;
        if (!(samples[i].x >= 0.0f && samples[i].x < 1.0f && samples[i].y >= 0.0f && samples[i].y < 1.0f))
            continue;
        p.level = lod != lod || lod < 0.0 ? 0 : lod >= max_level ? max_level : (int)SK_FLOOR(lod);
        pages = (double)((virtual_res >> p.level) / page_size);
        p.px = (int)((double)samples[i].x * pages);
        p.py = (int)((double)samples[i].y * pages);
        /* neighbouring samples mostly ask for the same page */
        if (have_last && sk__page_cmp(&p, &last) == 0) continue;
        last = p; have_last = 1;
        lo = 0; hi = n;
        while (lo < hi) {
            int mid = (lo + hi) / 2;
            if (sk__page_cmp(&out[mid], &p) < 0) lo = mid + 1; else hi = mid;
        }
        if (lo < n && sk__page_cmp(&out[lo], &p) == 0) continue;
        if (n == cap) return -(int)SK_ERR_CAPACITY;
        memmove(out + lo + 1, out + lo, (size_t)(n - lo) * sizeof *out);
        out[lo] = p;
        n++;
    }
    return n;
}

#ifdef __cplusplus
}
#endif

#endif /* SHADOWKIT_IMPLEMENTATION_INCLUDED */
#endif /* SHADOWKIT_IMPLEMENTATION */

/*
------------------------------------------------------------------------------
This software is available under 2 licenses -- choose whichever you prefer.
------------------------------------------------------------------------------
ALTERNATIVE A - MIT License
Copyright (c) 2026 shadowkit authors
Permission is hereby granted, free of charge, to any person obtaining a copy of
this software and associated documentation files (the "Software"), to deal in
the Software without restriction, including without limitation the rights to
use, copy, modify, merge, publish, distribute, sublicense, and/or sell copies
of the Software, and to permit persons to whom the Software is furnished to do
so, subject to the following conditions:
The above copyright notice and this permission notice shall be included in all
copies or substantial portions of the Software.
THE SOFTWARE IS PROVIDED "AS IS", WITHOUT WARRANTY OF ANY KIND, EXPRESS OR
IMPLIED, INCLUDING BUT NOT LIMITED TO THE WARRANTIES OF MERCHANTABILITY,
FITNESS FOR A PARTICULAR PURPOSE AND NONINFRINGEMENT. IN NO EVENT SHALL THE
AUTHORS OR COPYRIGHT HOLDERS BE LIABLE FOR ANY CLAIM, DAMAGES OR OTHER
LIABILITY, WHETHER IN AN ACTION OF CONTRACT, TORT OR OTHERWISE, ARISING FROM,
OUT OF OR IN CONNECTION WITH THE SOFTWARE OR THE USE OR OTHER DEALINGS IN THE
SOFTWARE.
------------------------------------------------------------------------------
ALTERNATIVE B - Public Domain (www.unlicense.org)
This is free and unencumbered software released into the public domain.
Anyone is free to copy, modify, publish, use, compile, sell, or distribute this
software, either in source code form or as a compiled binary, for any purpose,
commercial or non-commercial, and by any means.
In jurisdictions that recognize copyright laws, the author or authors of this
software dedicate any and all copyright interest in the software to the public
domain. We make this dedication for the benefit of the public at large and to
the detriment of our heirs and successors. We intend this dedication to be an
overt act of relinquishment in perpetuity of all present and future rights to
this software under copyright law.
THE SOFTWARE IS PROVIDED "AS IS", WITHOUT WARRANTY OF ANY KIND, EXPRESS OR
IMPLIED, INCLUDING BUT NOT LIMITED TO THE WARRANTIES OF MERCHANTABILITY,
FITNESS FOR A PARTICULAR PURPOSE AND NONINFRINGEMENT. IN NO EVENT SHALL THE
AUTHORS BE LIABLE FOR ANY CLAIM, DAMAGES OR OTHER LIABILITY, WHETHER IN AN
ACTION OF CONTRACT, TORT OR OTHERWISE, ARISING FROM, OUT OF OR IN CONNECTION
WITH THE SOFTWARE OR THE USE OR OTHER DEALINGS IN THE SOFTWARE.
------------------------------------------------------------------------------
*/
