/* tb_closed_form.h - scenes whose shadows are known in closed form, to check
   the reference (tb_reference.h) against the truth.

   Each builder appends a triangle scene (tb_scene, what GL and Embree see)
   AND fills an analytic description (tb_cf_scene) of the same surfaces; all
   coordinates are exactly representable in float, so the triangles are the
   analytic surfaces, not approximations of them. Units are metres, +y up.

     "plate": a horizontal 2 x 2 square, zero thickness (two triangles,
              both sides visible), x, z in [-1, 1] at y = 1
     "pole":  a thin vertical box [-0.0625, 0, -0.0625]..[0.0625, 3, 0.0625]
     "box":   a box [-1, 0, -0.75]..[1, 1.5, 0.75]
   each standing over (or on) the ground "ground": the plane y = 0, x, z in
   [-40, 40], 8 x 8 quads (128 triangles: coplanar neighbours, on purpose).

   tb_cf_visibility() computes per pixel, in double, with no ray tracer:
   - the camera ray through the pixel centre, from the near-plane point to
     the far-plane point of view->inv_view_proj (tb_unproject_pixel at
     window depth 0 and 1; the same convention as tb_reference_trace_exact),
     intersected with the ground rectangle, the boxes (slab test) and the
     plate; the nearest hit, its point snapped exactly onto the face's plane,
     and the face's normal turned to face the camera; no hit:
     TB_VIS_BACKGROUND;
   - point lights: farther than range (> 0): TB_VIS_OUT_OF_RANGE;
   - facing: dot(n, to_light) <= 0 (rect light: for all four corners):
     TB_VIS_BACKFACING;
   - directional and point lights: the shadow segment against every other
     surface (slab test for the boxes; a convex box cannot shadow its own
     faces, nor a plane its own points): 1 lit, 0 shadowed;
   - rect light (plate scene only; the light horizontal, above the plate,
     half_u and half_v along x and z): from a ground point p the plate
     projects onto the light's plane as the axis-aligned rectangle
     p + (corner - p) h / y_plate (h the light's height), and
         visibility = 1 - area(light rectangle intersected with the
                                   projected plate) / area(light),
     the fraction of the light the point sees: a true closed form (the plate
     top sees the whole light). This is the expectation of the reference's
     unweighted stratified estimate.
   Output conventions are tb_reference.h's: 1 / 0 / [0,1], negative codes. */
#ifndef TB_CLOSED_FORM_H
#define TB_CLOSED_FORM_H

#include "tb_reference.h"
#include "tb_scene.h"

#ifdef __cplusplus
extern "C" {
#endif

#define TB_CF_MAX_BOXES 4

typedef struct tb_cf_box {
    double min[3], max[3];
} tb_cf_box;

/* a horizontal zero-thickness rectangle, visible from both sides */
typedef struct tb_cf_quad {
    double y, min_x, max_x, min_z, max_z;
} tb_cf_quad;

typedef struct tb_cf_scene {
    double ground_min[2], ground_max[2];   /* x, z extent of the ground y = 0 */
    int box_count;
    tb_cf_box boxes[TB_CF_MAX_BOXES];
    int has_quad;
    tb_cf_quad quad;
} tb_cf_scene;

/* Each appends the scene's objects to s ("ground" and "plate" / "pole" /
   "box") and overwrites *cf. 0 ok, -1 on NULL or allocation failure (s may
   then hold part of the objects). */
int tb_cf_build_plate(tb_scene *s, tb_cf_scene *cf);
int tb_cf_build_pole(tb_scene *s, tb_cf_scene *cf);
int tb_cf_build_box(tb_scene *s, tb_cf_scene *cf);
/* by name: "plate", "pole", "box"; -1 for an unknown name */
int tb_cf_build(tb_scene *s, tb_cf_scene *cf, const char *name);

/* The exact visibility of every pixel of view (see above): vis gets
   width*height floats, row 0 at the bottom. 0 ok; -1 on NULL, sizes <= 0,
   a non-finite light or matrix, an unknown light type, or a rect light that
   is not the supported case (plate scene without boxes, light above the
   plate, half axes along x and z). */
int tb_cf_visibility(const tb_cf_scene *cf, const tb_view *view, const tb_light *light, float *vis);

/* A spot light: light (TB_LIGHT_POINT, its range as above) with a cone
   about `axis` (any length > 0) of half-angle half_angle_deg in (0, 90):
   tb_cf_visibility's answer with every lit receiver whose direction from
   the light is more than half_angle_deg off the axis set to 0. The cone's
   edge is then as exact as the shadows' (the receiver point is the
   analytic surface's). -1 as tb_cf_visibility, and for a light that is not
   a point light, a zero or non-finite axis or an angle out of range. */
int tb_cf_spot_visibility(const tb_cf_scene *cf, const tb_view *view, const tb_light *light, sk_vec3 axis,
                          double half_angle_deg, float *vis);

#ifdef __cplusplus
}
#endif
#endif /* TB_CLOSED_FORM_H */
