/* tb_reference.h - the exact shadow reference: Embree 3 primary and shadow rays.

   EXACT METHOD (tb_reference_trace_exact; what the GL tests and the DESIGN
   call "the reference"):

   1. Primary ray. For pixel (x, y), row 0 at the bottom, the camera ray runs
      through the pixel centre from the near-plane point to the far-plane
      point of view->inv_view_proj, both unprojected in double:
        ndc(d) = (2 (x + 0.5) / width - 1,  2 (y + 0.5) / height - 1,  2 d - 1, 1)
        a = unproject(ndc(0)),  b = unproject(ndc(1))      (divided by w)
      It is traced with Embree (rtcIntersect1, t in [0, |b - a|]). The hit
      triangle's plane is rebuilt in double from its float vertices and the
      double ray a + t (b - a)/|b - a| is intersected with it, so the hit
      point does not carry Embree's float t. The normal is the triangle's
      geometric normal (double cross product), turned to face the camera.
      No hit: TB_VIS_BACKGROUND. Alpha-tested triangles (below) stop the
      ray everywhere unless tb_reference_alpha_primary lets it through
      their holes.

   2. Raster consistency (raster_depth given, the window depth the technique
      used). A pixel whose rasterised surface and traced surface differ is
      TB_VIS_SILHOUETTE: left out of every metric and counted. Rasterised
      background with a traced hit, or the reverse, is a silhouette pixel;
      when both hit, the traced point is projected with the double inverse
      of inv_view_proj and its window depth compared with raster_depth:
      the same surface when they differ by at most TB_REF_SAME_SURFACE_ULPS
      units of 2^-24 (one ulp of a depth in [0.5, 1), where perspective
      depth buffers hold nearly every pixel; see the value for the figures).
      With opt->raster_normals (the G-buffer's normals), the same-face
      test: a pixel at the same depth is a different surface too when the
      rasterised normal g is neither the traced triangle's geometric normal
      nor its vertex normals interpolated at the hit (what a G-buffer of
      face normals or of shading normals writes for that triangle):
      |cos(g, either)| < TB_REF_SAME_FACE_COS. At a box's edge the
      rasteriser may shade one face while the pixel centre's ray meets the
      other, at the same depth; when one of them is turned from the light,
      every technique's mask calls the pixel its own shadow whatever its
      map holds.

   3. Facing. A receiver whose geometric normal faces away from the light
      (dot(n, to_light) <= 0; for a rect light: for all four corners, so for
      every sample) is TB_VIS_BACKFACING, in no metric's denominator. Point
      lights: farther than `range` (> 0) is TB_VIS_OUT_OF_RANGE (tested
      before facing).

   4. Shadow rays (Embree 3 rtcOccluded1 / rtcOccluded16) start AT the hit
      point p, never offset along the normal and never by a fraction of the
      scene. Their origin is p rounded to float, off p by at most half a
      float ulp per coordinate, i.e. at most e0 = (sqrt 3 / 2) ulp(m) off
      the receiver's plane, m = max |p_i|. A ray leaving at angle theta to
      the plane (sin theta = |dot(n, dir)|) and starting e below it crosses
      the plane at t = e / sin theta, so
          tnear = e / sin theta,   e = TB_REF_ULP_BOUND ulp(m) = 2 ulp(m) >= e0
      (the factor 2 over 0.87 covers the double arithmetic of p). The part
      of the ray skipped this way lies within e of the receiver's plane: an
      occluder there cannot be told from one touching the plane in float
      geometry. As a complement that is exact, an intersection filter
      (the Embree 3 context filter, RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION)
      rejects hits on the receiver's own triangle and on every triangle lying
      in the receiver's plane (its three vertices within e of it): a ray that
      leaves a plane at a non-zero angle meets that plane only at its origin,
      so such a triangle can never occlude; this removes the self-hits of the
      receiver's neighbours (ground grids) whatever Embree's own t error.
      Toward a point light or a rect light sample q the ray stops the same
      bound short of q: tfar = |q - p| - ulp bound of q (divided by the sine
      at the light's plane for rect lights), so geometry the light lies on
      does not occlude it.

   5. Rect (area) lights: strata x strata jittered samples (see
      TB_REF_EXACT_STRATA for the default and its measured noise), a per
      pixel PCG32 stream as below; a sample behind the receiver's plane
      counts as occluded. Visibility = unoccluded fraction (unweighted).

   The reference has been checked against closed-form scenes
   (tb_closed_form.h; tests/gl/test_gl_closed_form.c).

   LEGACY APPROXIMATION (tb_reference_trace, tb_reference_trace_points,
   tb_reference_normals; kept for callers that have only a depth buffer):
   the world position is reconstructed from the window-depth buffer,
       world = inv_view_proj * ndc(depth), divided by its w    (in double),
   d >= 1 (cleared depth) is background: TB_VIS_BACKGROUND. Offset:
   eps = eps_rel * scene diagonal, eps_rel = TB_REF_EPS_REL (1e-4) unless
   options say otherwise. The ray origin is moved eps along the unit normal
   when a normal buffer is given, and the ray starts at distance eps along
   itself (tnear). Toward a point or area light sample the ray stops eps
   short of the light. With normals, a surface facing away from the light
   (dot(n, to_light) <= 0) counts as shadowed (per sample for area lights),
   unless ignore_facing. The normal offset moves every shadow edge toward
   the light by eps cot(elevation), the way a technique's own normal-offset
   bias moves its edges, so errors measured against it come out low.

   Lights (both methods):
   - directional: `direction` is the direction the light TRAVELS (light ->
     scene), as in shadowkit.h's sk_light_view_directional(); rays go to -dir.
   - point: `position`; pixels farther than `range` (> 0) from it are
     TB_VIS_OUT_OF_RANGE; range <= 0 means unlimited.
   - rect (area): the parallelogram centre + a*half_u + b*half_v, a,b in
     [-1,1], sampled on strata x strata cells, one sample jittered uniformly
     inside each cell; the jitter comes from a fixed-seed PRNG (PCG32)
     seeded by (seed, pixel index), so results do not depend on thread
     count. Visibility = fraction of samples unoccluded, in [0,1]
     (unweighted: no cosine or distance terms).

   Output per pixel: 1 lit, 0 shadowed (hard), [0,1] (area), negative for
   pixels without a receiver that counts (TB_VIS_BACKGROUND,
   TB_VIS_OUT_OF_RANGE, TB_VIS_BACKFACING, TB_VIS_SILHOUETTE); tb_metrics
   ignores negative reference pixels.

   Threads: rows are interleaved over `threads` pthreads (0: all online CPUs).
   Depends on: shadowkit.h (types only), tb_scene.h, Embree 3, pthreads. */
#ifndef TB_REFERENCE_H
#define TB_REFERENCE_H

#include <stdint.h>
#include "shadowkit.h"
#include "tb_scene.h"

#ifdef __cplusplus
extern "C" {
#endif

#define TB_REF_EPS_REL 1e-4
#define TB_REF_MIN_STRATA 16
/* Exact method: the shadow-ray start bound e in float ulps of max |p_i|
   (point 4). On the closed-form scenes (tests/gl/test_gl_closed_form.c)
   the tnear bound alone and the receiver-plane filter alone each give 100%
   agreement; with neither (tnear 0, no filter) 89-91% of the pixels shadow
   themselves. */
#define TB_REF_ULP_BOUND 2.0
/* Exact method: same-surface tolerance on window depth, in units of 2^-24
   (point 2). Measured on 400 x 225 views of the closed-form scenes
   (llvmpipe, DEPTH_COMPONENT32F): the raster depth of ground pixels and the
   traced hit's window depth differ by at most 2.69 units (rasteriser
   interpolation plus the float inverse of the view-projection); 16 units
   leaves a margin of 6x, and two surfaces closer than that along the ray
   are ones the depth buffer itself barely separates. Pixels excluded as
   silhouettes: 0.0004% pooled over those views (at most 1 pixel a view). */
#define TB_REF_SAME_SURFACE_ULPS 16.0
/* Exact method: same-face tolerance (point 2), |cos| of the angle between
   the rasterised normal and the traced triangle's (geometric or
   interpolated) one: 0.25, about 75.5 degrees. The faces of a box meet at
   90 degrees (cosine 0); the G-buffer's normal for the traced triangle
   itself differs from the test's only by RGBA16F rounding. */
#define TB_REF_SAME_FACE_COS 0.25
/* Exact method: default strata per axis for rect lights (point 5). The
   reference's own noise, mean |difference of two seeds| / sqrt 2 over the
   penumbra (0 < closed form < 1), on the plate scene under a square light of
   half side 0.25, 0.5 and 1 m, 400 x 225: 24 x 24 samples 0.0026 (the
   target: at most 0.004, a fifth of the best soft method's penumbra error
   of about 0.02); 16 x 16: 0.0047-0.0050, 20 x 20: 0.0034-0.0035,
   32 x 32: 0.0017. */
#define TB_REF_EXACT_STRATA 24
/* exact method: rect lights with more strata per axis are refused (-1) */
#define TB_REF_MAX_STRATA 1024
#define TB_VIS_BACKGROUND (-1.0f)
#define TB_VIS_OUT_OF_RANGE (-2.0f)
#define TB_VIS_BACKFACING  (-3.0f)  /* the receiver's geometric normal faces away from the light (every light sample, for area lights): in no metric's denominator */
#define TB_VIS_SILHOUETTE  (-4.0f)  /* the rasterised and the traced primary hit are different surfaces: left out, counted */

typedef enum tb_light_type {
    TB_LIGHT_DIRECTIONAL = 0,
    TB_LIGHT_POINT = 1,
    TB_LIGHT_RECT = 2
} tb_light_type;

typedef struct tb_light {
    tb_light_type type;
    sk_vec3 direction;        /* DIRECTIONAL: travel direction (any length > 0) */
    sk_vec3 position;         /* POINT: position; RECT: centre */
    float range;              /* POINT: <= 0 unlimited */
    sk_vec3 half_u, half_v;   /* RECT: half-axes */
    int strata;               /* RECT: per axis; values < 16 mean 16 (legacy); exact:
                                 <= 0 means TB_REF_EXACT_STRATA, 1..15 mean 16 */
    uint32_t seed;            /* RECT: jitter seed */
} tb_light;

typedef struct tb_view {
    sk_mat4 inv_view_proj;    /* clip -> world, column-major m[col*4+row] */
    int width, height;
} tb_view;

typedef struct tb_ref_options {   /* all-zero = defaults */
    double eps_rel;               /* <= 0: TB_REF_EPS_REL */
    int threads;                  /* <= 0: online CPUs (at most 64) */
    int ignore_facing;            /* 1: no back-facing test with normals */
    const float *raster_normals;  /* exact method with raster_depth: the G-buffer's
                                     world normals, 3 a pixel (any sign, 0 on the
                                     background), for the same-face test (point 2) */
} tb_ref_options;

typedef struct tb_reference tb_reference;

/* Builds the Embree scene (robust flag, high build quality) from the
   scene's triangles; the scene may be freed afterwards. NULL on failure. */
tb_reference *tb_reference_create(const tb_scene *scene);
void tb_reference_destroy(tb_reference *ref);
/* eps_rel * scene diagonal (opt may be NULL) */
double tb_reference_epsilon(const tb_reference *ref, const tb_ref_options *opt);

/* Inverse of a column-major 4x4 in double (Gauss-Jordan, partial
   pivoting), e.g. of the float view-projection a G-buffer was drawn with;
   1 ok, 0 if singular. */
int tb_mat4_inverse_d(const double m[16], double inv[16]);

/* World position of pixel (x, y) at window depth d (see the formula above);
   0 ok, -1 if w is 0 or not finite. */
int tb_unproject_pixel(const sk_mat4 *inv_view_proj, int width, int height, int x, int y,
                       float depth, double out[3]);

/* Per-pixel visibility from a window-depth buffer (width*height floats, row
   0 at the bottom) and optional world-space normals (3 floats per pixel, any
   length; a zero normal = none; NULL = no normals). vis: width*height floats.
   0 ok, -1 bad arguments or out of memory. */
int tb_reference_trace(const tb_reference *ref, const tb_view *view, const float *depth,
                       const float *normals, const tb_light *light,
                       const tb_ref_options *opt, float *vis);

/* Pixel counts of one exact trace; every pixel is in exactly one of
   covered (vis >= 0), background, backfacing, silhouette, out_of_range. */
typedef struct tb_ref_stats {
    uint64_t pixels, covered, background, backfacing, silhouette, out_of_range;
} tb_ref_stats;

/* The exact reference (method at the top): camera rays through pixel
   centres (near-plane point to far-plane point of view->inv_view_proj, in
   double) traced with Embree, the hit recomputed in double on the hit
   triangle's plane, shadow rays from it with the float-error tnear bound
   and the receiver-plane filter. raster_depth: the window depth
   (width*height floats, row 0 at the bottom) the technique used, or NULL
   (then no pixel is TB_VIS_SILHOUETTE). opt (may be NULL): .threads, and
   .raster_normals with raster_depth (the same-face test, point 2). vis: width*height floats. stats (may be NULL) gets the counts.
   0 ok, -1 bad arguments (NULL, sizes <= 0, unknown light type, a
   non-finite light, a zero sun direction, rect strata above
   TB_REF_MAX_STRATA, a non-finite or singular inv_view_proj). */
int tb_reference_trace_exact(const tb_reference *ref, const tb_view *view, const float *raster_depth,
                             const tb_light *light, const tb_ref_options *opt, float *vis,
                             tb_ref_stats *stats);

/* Alpha-tested casters, as a fragment stage that discards on a texture's
   alpha draws them: the exact method's shadow rays (point 4's filter) pass
   through triangles first_tri .. first_tri + tri_count - 1 where the
   texture's alpha at the hit is below `cutoff` (0..1). uv: 2 floats per
   scene vertex; the hit's uv is the barycentric blend of its triangle's
   (in double); the texel is the nearest one under GL_REPEAT
   (floor(u * w) mod w, row floor(v * h) mod h, row 0 first, as glTexImage2D
   takes it). alpha: w x h bytes. The arrays are copied. Primary rays do
   not alpha-test (unless tb_reference_alpha_primary). 0 ok, -1 bad
   arguments. */
int tb_reference_set_alpha(tb_reference *ref, const float *uv, unsigned first_tri, unsigned tri_count,
                           const unsigned char *alpha, int w, int h, float cutoff);
/* on = 1: the exact method's primary rays pass through the same holes (an
   Embree context filter on rtcIntersect1), for a camera pass that
   discards as the shadow pass does; 0: they hit the whole triangle (the
   default). -1 without tb_reference_set_alpha first, or ref NULL. */
int tb_reference_alpha_primary(tb_reference *ref, int on);

/* The same for arbitrary world points (3 doubles each) and optional normals
   (3 doubles each, NULL = none); the jitter seed uses the point index. */
int tb_reference_trace_points(const tb_reference *ref, const double *points, const double *normals,
                              int count, const tb_light *light, const tb_ref_options *opt,
                              float *vis);

/* Geometric normals for a depth buffer, when the renderer has none: for each
   covered pixel a primary ray from the camera through the pixel centre
   (near-plane to far-plane point of the unprojected pixel) is intersected
   with the scene; if it hits within 1% of the scene diagonal of the
   reconstructed position, normals get the unit geometric normal of the
   triangle hit, turned to face the camera; else (0,0,0). Positions are not
   changed: pass the result to tb_reference_trace as `normals`.
   normals: 3*width*height floats. 0 ok, -1 on bad arguments. */
int tb_reference_normals(const tb_reference *ref, const tb_view *view, const float *depth,
                         const tb_ref_options *opt, float *normals);

#ifdef __cplusplus
}
#endif
#endif /* TB_REFERENCE_H */
