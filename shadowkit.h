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
     static copy).

     Override before the implementation is included, if you like:
         SK_ASSERT(x)            default assert(x) from <assert.h>
         SK_SQRTF, SK_FABSF, SK_FLOORF, SK_CEILF, SK_LOG2F, SK_POWF, SK_TANF,
         SK_ATANF, SK_SINF, SK_COSF, SK_ACOSF  default the <math.h> functions
         SKDEF                   default extern (static with SHADOWKIT_STATIC)

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

   SECTIONS (in the order of the header)
     1. Core math                 matrices, frusta, convex clipping
     2. Aliasing analysis         seed 002 (aliasing error d, RMSM LOD)
     3. Crops and PSSM            seeds 000, 002 (crop matrix, practical
                                  split scheme, focused and texel-snapped
                                  stable crops)
     4. PSM and LiSPSM            seed 002 (Stamminger & Drettakis 2002;
                                  Wimmer, Scherzer & Purgathofer 2004)
     5. LSPSM                     seed 003 (Tang et al. 2017, Eq. 1)
     6. Omnidirectional lights    seed 004 (King & Newhall, Eqs. 5.4.6-5.4.7,
                                  HalfIntersection, caster culling, scissor,
                                  resolution, VSDCT)
     7. Resolution estimation     seed 000 (Ferko 2013, Sec. 3.1-3.2)
     8. PVSM                      seed 001 (Shen Li et al. 2011, Eqs. 4-5,
                                  rho(n), appendix convolution, SMTG,
                                  kd-tree tiles, V*A/A merge)
     9. RMSM pages                seed 002 (Lefohn et al. 2007 page requests)

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

#define SHADOWKIT_VERSION_MAJOR 0
#define SHADOWKIT_VERSION_MINOR 1
#define SHADOWKIT_VERSION_PATCH 0

#ifndef SKDEF
#ifdef SHADOWKIT_STATIC
#define SKDEF static
#else
#define SKDEF extern
#endif
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* =========================================================================
   1. Core math
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
                         SK_ERR_CAPACITY } sk_result;

/* "ok", "invalid argument", "degenerate configuration", "capacity exceeded";
   "unknown result" for any other value */
SKDEF const char *sk_result_string(sk_result r);

SKDEF sk_mat4 sk_mat4_identity(void);
SKDEF sk_mat4 sk_mat4_mul(sk_mat4 a, sk_mat4 b);                 /* a*b */
/* 1 and *out = inverse; 0 (out untouched) if singular, non-finite or out NULL */
SKDEF int     sk_mat4_inverse(sk_mat4 m, sk_mat4 *out);
/* gluPerspective. Fallback for fovy outside (0,pi), aspect <= 0, zn <= 0,
   zf <= zn or a non-finite argument: the identity. */
SKDEF sk_mat4 sk_mat4_perspective(float fovy, float aspect, float zn, float zf);
/* glOrtho. Fallback for r == l, t == b, zf == zn or non-finite: the identity. */
SKDEF sk_mat4 sk_mat4_ortho(float l, float r, float b, float t, float zn, float zf);
/* gluLookAt. An up vector parallel to the view direction is replaced by the
   world axis least aligned with it; eye == target or non-finite input gives
   the identity. */
SKDEF sk_mat4 sk_mat4_look_at(sk_vec3 eye, sk_vec3 target, sk_vec3 up);
SKDEF sk_vec3 sk_mat4_transform_point(sk_mat4 m, sk_vec3 p);      /* with w-divide (w == 0: no divide) */
SKDEF sk_vec4 sk_mat4_transform_vec4(sk_mat4 m, sk_vec4 p);       /* no divide */
/* corners[i] = unprojected NDC ((i&1)?1:-1, (i&2)?1:-1, (i&4)?1:-1); planes
   point inward (normalised), in the order left, right, bottom, top, near, far.
   A singular or non-finite matrix gives an all-zero frustum, which every test
   below treats as "unknown" (conservatively intersecting). */
SKDEF sk_frustum sk_frustum_from_matrix(sk_mat4 view_proj);
/* Frustum (any convex hexahedron) from 8 corners in the corner order above.
   Planes are recomputed from the corners and oriented inward.
   SK_ERR_DEGENERATE if a face is degenerate (zero area). */
SKDEF sk_result sk_frustum_from_corners(const sk_vec3 corners[8], sk_frustum *out);
/* The 8 corners of an AABB as a frustum (same corner order: bit 0 = x max,
   bit 1 = y max, bit 2 = z max). min > max on an axis: SK_ERR_INVALID_ARG. */
SKDEF sk_result sk_frustum_from_aabb(sk_aabb box, sk_frustum *out);
/* 1 if p is inside or on the frustum (relative tolerance 1e-5) */
SKDEF int sk_frustum_contains_point(const sk_frustum *f, sk_vec3 p);

/* Vertices of the convex intersection of a frustum and an AABB (the body that
   a shadow map must cover). Writes at most cap points; returns the count
   (0 when they do not intersect), or -SK_ERR_INVALID_ARG, or
   -SK_ERR_CAPACITY. SK_CLIP_MAX_POINTS is always enough. */
#define SK_CLIP_MAX_POINTS 144
SKDEF int sk_clip_frustum_aabb(const sk_frustum *f, sk_aabb box, sk_vec3 *out, int cap);

/* =========================================================================
   2. Aliasing analysis (seed 002)
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
   3. Crop matrices and parallel splits (seeds 000, 002)
   ========================================================================= */
/* maps [r.x0,r.x1] x [r.y0,r.y1] x [zmin,zmax] of light clip space onto
   [-1,1]^3 (zmin maps to -1, zmax to +1). An axis with an empty or
   non-finite range is left as the identity. */
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
   its position or orientation (so it does not change as the camera moves):
   centre on the line joining the near and far face centres, balanced between
   the near and far corners; radius rounded up to a multiple of 2^-10 of
   itself so float noise cannot change it. */
SKDEF sk_sphere sk_frustum_bounding_sphere(const sk_frustum *f);
/* World-to-light view for a directional light (looks along light_dir; the up
   vector is a fixed world axis, never the camera's, so it is stable).
   Zero or non-finite direction: looks down -Y. */
SKDEF sk_mat4 sk_light_view_directional(sk_vec3 light_dir);
/* Focused orthographic projection for light_view: x, y fitted to the points
   (e.g. from sk_clip_frustum_aabb) in light view space; the near plane pulled
   back towards the light to include casters (may be NULL) so off-screen
   casters between the light and the receivers still cast. */
SKDEF sk_result sk_fit_ortho(const sk_vec3 *pts, int count, sk_mat4 light_view,
                             const sk_aabb *casters, sk_mat4 *out_proj);
/* Texel-snapped stable crop for a directional light (or one PSSM cascade):
   an orthographic map of res x res texels around the sphere, whose texel grid
   is fixed in light-view space: the crop origin is snapped to whole texels
   (texel = 2r/(res-1), so the snapped square still covers the sphere), hence
   a sub-texel camera move never changes which texel covers a world point.
   Depth range: the sphere, pulled back to the casters' bounds if given. */
SKDEF sk_result sk_stable_crop(sk_sphere s, sk_mat4 light_view, int res,
                               const sk_aabb *casters, sk_mat4 *out_proj);

/* =========================================================================
   4. PSM and LiSPSM warping (seed 002; Stamminger & Drettakis 2002,
      Kozlov 2004, Wimmer et al. 2004)
   ========================================================================= */
typedef enum sk_depth_compare { SK_DEPTH_LESS = 0, SK_DEPTH_GREATER = 1 } sk_depth_compare;
typedef struct sk_psm_desc {
    sk_mat4 cam_view;             /* world -> camera eye space */
    float fovy, aspect, zn, zf;   /* camera projection (sk_mat4_perspective) */
    sk_vec3 light_dir;            /* directional light travel direction */
    const sk_aabb *casters;       /* optional: casters that must be in the map */
    int caster_count;
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
   n > 1e4 * d the uniform map is used directly (warped = 0). */
SKDEF sk_result sk_lispsm_matrices(const sk_lispsm_desc *d, sk_lispsm_result *out);

/* =========================================================================
   5. Light Space Partitioned Shadow Maps (seed 003)
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
   -SK_ERR_CAPACITY when they do not fit in cap. Never loops forever. */
SKDEF int sk_lspsm_partition(float n, float L, float theta, const sk_lspsm_params *p,
                             sk_rect *out, int cap);

typedef struct sk_lspsm_region {
    sk_mat4 light_view;           /* x: trapezoid cross axis, y: trapezoid axis
                                     (view direction projected on the light
                                     plane), z: towards the light */
    sk_vec2 origin;               /* centre of the near base in light_view xy */
    float n, L, theta;            /* the trapezoid of sk_lspsm_partition */
    float zmin, zmax;             /* light-view z range (casters included) */
    int fallback;                 /* 1: view direction parallel to the light or
                                     zero-length region: one focused map over
                                     the bounding rectangle instead */
} sk_lspsm_region;
/* The projective region of seed 003 (Sec. 3.1): the view frustum clipped to
   the receivers' box, projected on the light plane; the smallest enclosing
   isosceles trapezoid (minimum area) whose axis is the projected view
   direction. Casters (may be NULL) extend the depth range only.
   n is kept >= 1e-4 of the far base so the partition stays finite.
   SK_ERR_DEGENERATE when the frustum misses the receivers. */
SKDEF sk_result sk_lspsm_region_extract(const sk_frustum *view, sk_vec3 view_dir,
                                        sk_aabb receivers, const sk_aabb *casters,
                                        sk_vec3 light_dir, sk_lspsm_region *out);
/* One light view-projection (world -> that partition's clip space) per
   partition of the region (or the single focused map of a fallback region),
   and the partition rects in light-view xy. Returns the count, or -sk_result
   as sk_lspsm_partition. out_rects may be NULL. */
SKDEF int sk_lspsm_crops(const sk_lspsm_region *r, const sk_lspsm_params *p,
                         sk_mat4 *out_view_proj, sk_rect *out_rects, int cap);

/* =========================================================================
   6. Omnidirectional lights (seed 004)
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
   instead. SK_ERR_DEGENERATE when the box lies beyond light_range (casts
   nothing), SK_ERR_INVALID_ARG for bad input. */
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
   returns 0 with the rect zeroed; otherwise 1. Bad input: 0, rect zeroed. */
SKDEF int sk_light_scissor(sk_vec3 light_pos, float radius, sk_mat4 view_proj,
                           int vp_w, int vp_h, int out_rect[4]);
/* smallest power of two M with faces*M*M >= c*pixels, clamped to [1, the
   largest power of two <= max_res]; 0 if faces == 0 or on bad input
   (faces outside [0,6], pixels < 0, c <= 0, max_res < 1, NaN). */
SKDEF int sk_cube_resolution(int faces, float pixels, float c, int max_res);

/* Virtual Shadow Depth Cube Texture: six faces as sub-rects of one 2D depth
   texture, laid out 3 x 2 (face f at column f%3, row f/3, row 0 at the
   bottom). face_res in [1, SK_VSDCT_MAX_FACE_RES]. */
#define SK_VSDCT_MAX_FACE_RES 65536
typedef struct sk_vsdct_layout { int face_res, atlas_w, atlas_h; int face_x[6], face_y[6]; } sk_vsdct_layout;
SKDEF sk_result sk_vsdct_layout_make(int face_res, sk_vsdct_layout *out);
/* N_i = 2^(ceil(log2 Ns) + min(ceil(log2 G), D) - D)  (Eq. 5.4.7), at least 1;
   0 on bad input (face_res, grey_levels < 1, deriv_bits < 0). */
SKDEF int sk_vsdct_indirection_size(int face_res, int grey_levels, int deriv_bits);
/* window depth stored for eye depth MA: scale / MA + bias  (Eq. 5.4.6).
   Bad input (zn <= 0, zf <= zn, NaN): scale 0, bias 1. */
SKDEF void sk_vsdct_depth_coeffs(float zn, float zf, float *scale, float *bias);
/* direction -> face and normalised atlas coords (u right, v up: GL texture
   convention, v = 0 at the atlas's bottom row); within its sub-rect a face is
   laid out exactly as GL lays out that cube face. Coords always stay at least
   half a texel inside that face's sub-rect (no sampling across seams).
   Returns the face, or -1 for a zero or non-finite direction or a NULL
   argument (u, v untouched). */
SKDEF int sk_vsdct_lookup(const sk_vsdct_layout *l, sk_vec3 dir, float *u, float *v);
/* fills the RG16 indirection cube map: out[((face*ni + t)*ni + s)*2 + {0,1}]
   = atlas (u,v) * 65535 (rounded) for the direction through that texel's
   centre. ni in [1, 65536]. */
SKDEF sk_result sk_vsdct_indirection_fill(const sk_vsdct_layout *l, int ni, unsigned short *out);

/* =========================================================================
   7. Resolution estimation (seed 000)
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
   pixels around each corner (Sec. 3.2). No sample: SK_OK with samples = 0,
   width and height 0, texel sizes 0, bounds and crop the identity of
   [-1,1]^2. w and h in [1, 65536]; max_res >= 1. */
SKDEF sk_result sk_estimate_resolution(const float *depth, int w, int h,
        sk_mat4 cam_inv_view_proj, sk_mat4 light_view_proj, int max_res, sk_res_estimate *out);

/* =========================================================================
   8. Predicted virtual soft shadow maps (seed 001)
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
   -1). Empty box: the lit value of the texel containing its centre. */
SKDEF float sk_smooth_box_visibility(float x0, float y0, float x1, float y1,
                                     int (*lit)(void *user, int tx, int ty), void *user);
/* Eq. (4)-(5): required texel size (shadow-map units) along each axis,
   r_k = 2 e_k^T h / rho(n_k), n_k = ||M_phi'^-1 e_k e_k^T h_k||: the SMTG keeps
   the MINIMUM per cell; resolution over a span s is s / r. u_phi, v_phi are the
   half-axes of the warped pixel footprint. Non-finite input: +INFINITY. */
SKDEF void sk_pvsm_predict(sk_vec2 u_h, sk_vec2 v_h, sk_vec2 u_phi, sk_vec2 v_phi,
                           int dynamic_scene, float *r0, float *r1);
/* V_dst = V_dst*A_dst + V_src*A_src, A_dst += A_src (Sec. 5.2), with V kept
   normalised: on return *v is the area-weighted visibility, *a the area. */
SKDEF void sk_pvsm_merge(float *v, float *a, float v_src, float a_src);
typedef struct sk_tile { int x0, y0, x1, y1; int res_x, res_y; } sk_tile;  /* cells [x0,x1) x [y0,y1) */
/* Size in floats of the SMTG min-pyramid of a gw x gh grid of 2-float cells
   (all levels, level 0 included, down to 1x1); 0 on bad input. */
SKDEF int sk_smtg_pyramid_size(int gw, int gh);
/* Builds the min-pyramid: level 0 is the grid, each next level the per-2x2
   minimum (odd sizes round up). Returns the number of levels, or -sk_result. */
SKDEF int sk_smtg_pyramid(const float *grid, int gw, int gh, float *out, int cap_floats);
/* grid: gw*gh*2 floats, cell (x,y) at grid[(y*gw + x)*2 + {0,1}], the minimum
   required texel size along x and y in light-clip units (2/gw per cell span);
   +INFINITY or NaN = no sample; <= 0 demands max_res. A cell whose need
   exceeds max_res gets a tile of its own at max_res (clamped, never an error).
   Empty grid: returns 0. Top-down kd-tree (Giegl & Wimmer): a node, shrunk to
   its sampled cells, becomes a tile when its resolution fits max_res, else it
   is split in half along the axis of higher resolution. Tiles are disjoint,
   cover every sampled cell, res <= max_res and res >= node span / min texel
   size of its cells. Returns count or -sk_result. gw, gh in [1, 4096]. */
SKDEF int sk_fvsm_tiles(const float *grid, int gw, int gh, int max_res, sk_tile *out, int cap);

/* =========================================================================
   9. RMSM page requests (seed 002, after Lefohn et al. 2007)
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
