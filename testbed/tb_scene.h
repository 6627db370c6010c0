/* tb_scene.h - triangle-soup scenes for the shadowkit testbed.

   A scene is what both the GL renderer and the Embree reference see:
   float xyz positions, per-vertex unit normals, uint32 triangle indices,
   a list of named objects (each an index range plus its AABB, used as the
   caster bounds where shadowkit culls) and the whole scene's AABB.

   Sources:
   - tb_scene_load(): any file assimp reads (OBJ, glTF 2.0, ...), with node
     transforms applied (aiProcess_PreTransformVertices), triangulated,
     identical vertices joined, smooth normals generated where missing.
     Points and lines are dropped. One object per assimp mesh.
   - procedural builders (tb_scene_add_* append one object; tb_scene_build_*
     make a complete standard scene). Units are metres, +y is up, the ground
     is the plane y = 0. Faces wind counter-clockwise seen from the side their
     normal points to (GL front faces); closed boxes have outward normals,
     the room's surfaces face inward.

   Ownership: every tb_scene is freed with tb_scene_free(); a zeroed struct
   (or tb_scene_init()) is an empty scene. Functions that allocate return 0
   on success and -1 on failure (allocation, unreadable file); on failure the
   scene keeps what it had.

   Depends on: shadowkit.h (types only: sk_vec3, sk_aabb), libassimp. */
#ifndef TB_SCENE_H
#define TB_SCENE_H

#include <stddef.h>
#include <stdint.h>
#include "shadowkit.h"   /* types only; build with -I<repo root> */

#ifdef __cplusplus
extern "C" {
#endif

#define TB_NAME_MAX 64

typedef struct tb_object {
    char name[TB_NAME_MAX];
    uint32_t first_index;     /* into tb_scene.indices (multiple of 3) */
    uint32_t index_count;     /* 3 * triangle count */
    sk_aabb bounds;           /* of the vertices its triangles use */
} tb_object;

typedef struct tb_scene {
    float *positions;         /* 3 * vertex_count floats, xyz */
    float *normals;           /* 3 * vertex_count floats, unit length */
    uint32_t vertex_count;
    uint32_t *indices;        /* index_count entries, 3 per triangle (CCW front) */
    uint32_t index_count;
    tb_object *objects;
    uint32_t object_count;
    sk_aabb bounds;           /* whole scene; min > max while empty */
    /* capacities (internal) */
    uint32_t vertex_cap_, index_cap_, object_cap_;
} tb_scene;

void tb_scene_init(tb_scene *s);
void tb_scene_free(tb_scene *s);               /* frees and re-initialises */
static inline uint32_t tb_scene_triangle_count(const tb_scene *s) { return s->index_count / 3u; }
/* diagonal length of the scene AABB (0 when empty) */
double tb_scene_diagonal(const tb_scene *s);
/* find an object by exact name, -1 if none */
int tb_scene_find_object(const tb_scene *s, const char *name);

/* Loads with assimp (aiImportFile). Appends to s. On failure prints the
   assimp error to stderr and returns -1. */
int tb_scene_load(tb_scene *s, const char *path);

/* ---- primitives: each appends one object and returns its index, or -1 ---- */

/* Horizontal plane y = y0 facing +y, centred at (cx, cz), size 2*hx by 2*hz,
   split into nx x nz quads (each >= 1; 2*nx*nz triangles). */
int tb_scene_add_ground(tb_scene *s, const char *name, float cx, float cz,
                        float hx, float hz, float y0, int nx, int nz);
/* Any triangle mesh: nv vertices (3 floats each), ni indices (3 per
   triangle, into those vertices); area-weighted vertex normals. */
int tb_scene_add_mesh(tb_scene *s, const char *name, const float *pos, uint32_t nv, const uint32_t *idx,
                      uint32_t ni);
/* Axis-aligned closed box from mn to mx, outward normals, 12 triangles. */
int tb_scene_add_box(tb_scene *s, const char *name, sk_vec3 mn, sk_vec3 mx);
/* A thin vertical pole: square prism of side 2*r standing on (x, y0, z),
   height h; a closed box (12 triangles). */
int tb_scene_add_pole(tb_scene *s, const char *name, float x, float y0, float z,
                      float r, float h);

/* ---- standard procedural scenes (each appends several objects) ---- */

/* "ground-boxes": ground 40 x 40 (y = 0, x,z in [-20,20], 8x8 quads, object
   "ground") and five boxes "box0".."box4":
     box0 [-1,0,-1]..[1,2,1]           (2 x 2 x 2 on the ground at the origin)
     box1 [3,0,-4]..[5,4,-2]           (tall)
     box2 [-6,0,2]..[-3,1,5]           (flat)
     box3 [-2,3,4]..[0,3.5,6]          (floating slab, 3 above the ground)
     box4 [6,0,5]..[6.5,6,5.5]         (narrow tower)
   Bounds [-20,0,-20]..[20,6,20]; 8*8*2 + 5*12 = 188 triangles. */
int tb_scene_build_ground_boxes(tb_scene *s);

/* "fence": fine shadow detail. Ground 30 x 30 ("ground", x,z in [-15,15],
   4x4 quads), then along the line z = 0, x in [-10, 10]:
     21 thin poles "pole0".."pole20" at x = -10 + i, side 0.04, height 2;
     a fence grid "fence": 9 horizontal rails (y = 0.2, 0.4, .. 1.8, each a
     box 20 long x 0.02 x 0.02 centred on z = 0) and 41 vertical slats
     (x = -10 + 0.5 i, 0.02 x 2 x 0.02), all as one object;
     plus 8 free-standing poles "post0".."post7" at x = -7 + 2 i, z = 4,
     side 0.1, height 3.
   Bounds [-15,0,-15]..[15,3,15]; 32 + (21 + 50 + 8) * 12 = 980 triangles. */
int tb_scene_build_fence(tb_scene *s);

/* "terrace": perspective aliasing. A ground strip "ground" 12 wide and 200
   long (x in [-6,6], z in [-200,0], 4 x 100 quads = 800 triangles), and regularly spaced features
   receding to the horizon along -z every 5 m (k = 0..39, z_k = -2.5 - 5 k):
     posts "postL<k>" and "postR<k>" at x = -5 and x = +5, side 0.15, height 3;
     boxes "box<k>" [-0.5,0,z_k-0.5]..[0.5,1,z_k+0.5] in the middle.
   Bounds [-6,0,-200]..[6,3,0]; 800 + 120 * 12 = 2240 triangles. */
int tb_scene_build_terrace(tb_scene *s);

/* "room": omni lights. Inward-facing floor "floor" (y = 0), ceiling
   "ceiling" (y = 4), walls "wall_xn" (x = -5), "wall_xp" (x = 5), "wall_zn"
   (z = -5), "wall_zp" (z = 5): a 10 x 4 x 10 room, each surface a 4x4-quad
   grid (32 triangles); four pillars "pillar0".."pillar3" (boxes 0.6 x 4 x 0.6
   centred at (+-2.5, *, +-2.5), floor to ceiling) and a table-like box
   "crate" [0.5,0,-1.5]..[1.5,0.8,-0.5].
   Bounds [-5,0,-5]..[5,4,5]; 6 * 32 + 5 * 12 = 252 triangles. A point light
   at (0, 2, 0) with range >= 8 is the intended setup. */
int tb_scene_build_room(tb_scene *s);

/* "interior": a building of several point lights (King and Newhall's
   regime: each light's range spans rooms, walls hide most of it).
   Deterministic, built in code. Footprint x in [-7.5, 7.5], z in [-7, 7]
   (wall lines; walls 0.2 m thick centred on them), floor y = 0, ceiling
   y = 3. Six rooms of 5 x 6 m in two rows, r0 r1 r2 (x < -2.5, middle,
   x > 2.5) at z in [-7, -1] and r3 r4 r5 at z in [1, 7], either side of a
   corridor z in [-1, 1] (tb_interior_region numbers them 0..5 and 6).
     "floor<r>", "ceiling<r>", "floor_c", "ceiling_c"  0.2 m slabs per room
                   and the corridor (top of the floor y = 0, bottom of
                   the ceiling y = 3);
     "wall_s<c>", "wall_n<c>", "wall_w<p>", "wall_e<p>"  exterior walls
                   per room or corridor span, each with a window 1.4 m wide
                   from 0.9 to 2.1 m (the corridor's ends: 1.0 m wide, 0.6
                   to 2.4 m);
     "wall_ca<c>", "wall_cb<c>"  the corridor's walls (z = -1, z = 1) per
                   room, each with a door 1.0 x 2.1 m; r1's and r4's doors
                   face each other (x = 0.3);
     "wall_p0".."wall_p3"  partitions x = -2.5 and 2.5 per row; doors
                   0.9 x 2.1 m between r0 and r1 (z = -4) and r4 and r5
                   (z = 4), the other two solid;
     furniture: boxes standing on the floor, most against a wall or in a
                   corner (contact): "bed0", "wardrobe0", "nightstand0",
                   "sofa2", "crate2", "cabinet3", "boxes3", "boxes3_top",
                   "pillar4" (floor to ceiling), "counter5", "fridge5",
                   "stool5_seat", "stool5_leg", "bench_c", "plant_c";
     thin objects: tables on legs 5 cm square "table1", "chair1", "desk3",
                   "table4"; floor lamps (4 cm poles) "lamp1", "lamp4"; a
                   bookshelf of 2 cm planks "shelf2"; a 5 cm pole
                   "coat_stand_c";
     "ground"      outside, y = 0 around the footprint out to +-20 m.
   Bounds [-20,-0.2,-20]..[20,3.2,20]; 1652 triangles, 60 objects.
   tb_interior_view and tb_interior_light give its views and lights. */
int tb_scene_build_interior(tb_scene *s);

/* The interior's views: TB_INTERIOR_VIEWS cameras at head height (1.7 m),
   each looking through a doorway into another room or along the corridor;
   the intended projection is 70 degrees vertical (1.2 rad), near 0.05 m,
   far 30 m. Returns 0, or -1 for an index out of range or a NULL. */
#define TB_INTERIOR_VIEWS 5
int tb_interior_view(int view, sk_vec3 *eye, sk_vec3 *target);

/* The interior's point lights: TB_INTERIOR_LIGHTS, light i in room i
   (tb_interior_region(pos) == i), 2.0-2.6 m high, some 0.3-0.4 m from a
   wall; *radius is the light's range (7-9 m: each reaches through its
   doors into the corridor or other rooms, where views from elsewhere see
   it). Returns 0, or -1 for an index out
   of range or a NULL. */
#define TB_INTERIOR_LIGHTS 6
int tb_interior_light(int light, sk_vec3 *pos, float *radius);

/* The interior's region holding the point p (x and z; walls split along
   their lines): the rooms 0..5, 6 for the corridor, -1 outside. */
int tb_interior_region(sk_vec3 p);

/* "contact": contact shadows. Ground 20 x 20 ("ground", x,z in [-10,10],
   one quad, 2 triangles) and a box "box" [-1,0,-1]..[1,1,1] resting exactly
   on the ground (its bottom face lies in y = 0).
   Bounds [-10,0,-10]..[10,1,10]; 2 + 12 = 14 triangles. */
int tb_scene_build_contact(tb_scene *s);

/* "open-world": the regime cascades, warps and virtual maps are made for
   (kilometre views, a camera at head height). Deterministic (a fixed
   xorshift sequence), built in code:
     "ground"      2 km x 2 km (x,z in [-1000,1000], y = 0), 32 x 32 quads;
     "near0".."near5"  small boxes 0.5-1.2 m high, 3-9 m from the origin
                   (the near field: the camera views stand at the origin);
     "bld0".."bld299"  buildings, footprints 8-30 m a side, 6-40 m high,
                   centres 40-950 m from the origin (none within 40 m);
     "pole0".."pole1999"  thin poles (street lights, trees): side 0.3 m,
                   5-9 m high, 12-950 m from the origin.
   Bounds [-1000,0,-1000]..[1000,<=40,1000]; 2048 + 2306 * 12 = 29720
   triangles. tb_open_world_view() gives its camera views and suns. */
int tb_scene_build_open_world(tb_scene *s);

/* The open world's views: TB_OPEN_WORLD_VIEWS cameras at head height
   (1.8 m) near the origin, each looking a few degrees below the horizon
   in its own direction; the intended projection is 60 degrees vertical,
   near 0.5 m, far 1000 m. TB_OPEN_WORLD_SUNS suns per view, relative to
   its direction: sun elevations 45, 20 and 8 degrees, each once behind
   the viewer (the light travels along the view's horizontal direction)
   and once across it (from the view's right). Returns 0, or -1 for an
   index out of range. light_dir is the light's unit travel direction. */
#define TB_OPEN_WORLD_VIEWS 5
#define TB_OPEN_WORLD_SUNS 6
int tb_open_world_view(int view, sk_vec3 *eye, sk_vec3 *target);
int tb_open_world_sun(int view, int sun, sk_vec3 *light_dir);

/* "forest": instanced, alpha-tested trees over uneven ground, a camera
   walking through (the regime of foliage: shadows full of holes, near and
   far). Deterministic (fixed xorshift sequences and integer hashes), built
   in code:
     "ground"   a heightfield 600 m x 600 m (x,z in [-300,300]), 150 x 150
                quads of 4 m (45000 triangles): a valley, flat within 80 m
                of the origin, its sides rising to 35 m at 300 m, plus
                bumps of up to 4.5 m (tb_forest_ground_height: the mesh's
                own height, between vertices too);
     "tree0".."tree599"  one tree (tb_forest_tree, 26 triangles) placed by
                tb_forest_instances: 100 within 60 m of the origin, 100 from
                60 to 150 m, 400 on the valley's sides (150 to 285 m); none
                on the views' trails (3.5 m either side of each eye and of
                the 250 m ahead of it) nor within 3 m of another; scale
                0.7-1.3 (7-14 m high), any yaw.
   Bounds [-300,-4.0,-300]..[300,45.4,300]; 45000 + 600 * 26 = 60600
   triangles. The leaf cards are alpha-tested casters: tb_forest_alpha is
   their texture, tb_forest_uv their uv in this scene (for
   tb_reference_set_alpha); a GL renderer draws the trees instanced from
   tb_forest_tree and tb_forest_instances (tb_gl_scene.h:
   tb_gl_instanced). tb_forest_view / tb_forest_sun give its views. */
#define TB_FOREST_HALF 300.0      /* the ground's half side, m */
#define TB_FOREST_GRID 150        /* quads per side */
#define TB_FOREST_TREES 600
#define TB_FOREST_ALPHA_SIZE 64   /* the alpha atlas is 64 x 64 texels */
#define TB_FOREST_INSTANCE_FLOATS 6
int tb_scene_build_forest(tb_scene *s);
/* appends the forest's ground alone (object "ground") */
int tb_forest_build_ground(tb_scene *s);
/* height of the ground mesh at (x, z) (clamped to the ground's square) */
float tb_forest_ground_height(float x, float z);
/* The tree in its own frame, appended to *tree: object "trunk" (a
   hexagonal prism from y = -0.5 to 6 m, 12 triangles) then "crown" (seven
   leaf cards, 14 triangles: three vertical 6 x 7 m through the axis and
   four near-horizontal); *uv gets 2 floats per vertex of those two objects
   (malloc'd; free it): the cards cover the atlas's leaf half, the trunk one
   bark texel. 0 ok, -1 on allocation failure. */
int tb_forest_tree(tb_scene *tree, float **uv);
/* The alpha atlas, TB_FOREST_ALPHA_SIZE^2 bytes, row 0 first (as
   glTexImage2D takes it; v = 0 is row 0): rows 0-31 leaves (an ellipse of
   4 x 4-texel clusters, 62% of them kept, with single texels knocked out:
   40.2% of the leaf half opaque), rows 32-63 bark (all 255). The leaves'
   cutoff is 0.5. */
void tb_forest_alpha(unsigned char *alpha);
/* The trees' placements, TB_FOREST_INSTANCE_FLOATS floats each for
   TB_FOREST_TREES trees: offset x, y, z (the ground's height there), then
   s, s cos(yaw), s sin(yaw) for scale s. A tree point p goes to
       (c p.x - n p.z + x,  s p.y + y,  n p.x + c p.z + z),  c = s cos, n = s sin
   (tb_forest_instance_point; the GLSL of tb_gl_scene.h's hook is the same
   expression in float). */
void tb_forest_instances(float *instances);
void tb_forest_instance_point(const float instance[TB_FOREST_INSTANCE_FLOATS], const float p[3], float out[3]);
/* For a scene made by tb_scene_build_forest alone: the uv of every vertex
   (malloc'd, 2 floats a vertex, 0 on the ground) and the alpha-tested
   triangle range (every tree's; the trunks sample opaque bark), the
   arguments tb_reference_set_alpha takes. 0 ok, -1 for another scene's
   layout or on allocation failure. */
int tb_forest_uv(const tb_scene *s, float **uv, unsigned *first_tri, unsigned *tri_count);
/* The forest's views: TB_FOREST_VIEWS eyes at head height (1.7 m above
   the ground mesh) within 30 m of the origin, among the trees, each
   looking along its trail 3-6 degrees below the horizon;
   the intended projection is 60 degrees vertical, near 0.3 m, far
   TB_FOREST_FAR. TB_FOREST_SUNS suns per view, relative to its heading:
   elevations 45, 20 and 8 degrees, each once behind the viewer (the light
   travels along the view's horizontal direction) and once ahead of it
   (against it: the light travels toward the camera). 0, or -1 for an index
   out of range. light_dir is the light's unit travel direction. */
#define TB_FOREST_VIEWS 5
#define TB_FOREST_SUNS 6
#define TB_FOREST_FAR 400.0f
int tb_forest_view(int view, sk_vec3 *eye, sk_vec3 *target);
int tb_forest_sun(int view, int sun, sk_vec3 *light_dir);

/* builds one of the standard scenes by name: "ground-boxes", "fence",
   "terrace", "room", "interior", "contact", "open-world", "forest"; -1 for
   an unknown
   name */
int tb_scene_build(tb_scene *s, const char *name);

#ifdef __cplusplus
}
#endif
#endif /* TB_SCENE_H */
