/* shadowkit: directional-light shadow lookup, shared by the deferred
   shadow-mask pass and forward shaders (skgl_glsl_snippet()).

   Maps are layers of one depth texture array: one layer for a standard
   focused map, one per cascade for PSSM. A world position picks its layer by
   view depth against the split distances (PSSM practical split scheme,
   Romanick's VGP353 notes), optionally blending into the next cascade inside a band; or,
   for LSPSM's partitions (Tang et al. 2017), which tile the light plane rather than
   the view depth, the first layer whose partition rect holds it; or, for
   RMSM (Romanick's VGP353 notes), a virtual map: the page of the point's level of detail
   through the page table into a pool of pages (layer 0), or the nearest
   coarser page resident. sk_shadow() takes screen derivatives (RMSM's level
   of detail; the receiver's plane when the normal is zero): call it in
   uniform control flow (not after a discard or an early return).

   Maps may be orthographic (standard, PSSM) or perspective-warped (PSM,
   LiSPSM): the light-clip w is divided out per pixel.

   Bias (sk_bias_mode): 0, the receiver plane (the default): every texel of
   the filter footprint is compared with the depth that the receiver's
   tangent plane has at that texel's centre (adaptive depth bias, Dou, Yan,
   Kerzner, Dai and Wyman 2014, Sec. 3), less a tolerance of sk_plane_bias
   texels of the plane's own depth slope plus a few float ulps. A flat
   receiver is then neither in its own shadow (no acne) nor moved (no
   displacement of any shadow edge). The plane comes from the normal, or,
   when the normal is zero, from the screen derivatives of the position
   (receiver-plane depth bias, Isidoro 2006). 1, normal offset: the receiver
   is pushed along its normal by sk_normal_bias texels of its layer at that
   point (a warped map's texels change size across the view); this moves
   every shadow edge toward the light by about sk_normal_bias texels times
   the cotangent of the light's elevation. In both, the casters were drawn
   with slope-scaled polygon offset (skgl_shadow_desc.slope_bias).
   Filtering: a box of half-width R texels (per axis) over the map's texels,
   each texel weighed by the part of the box it covers. R is
   sk_filter_world world units in texels of the layer at the point (its
   texels' world size, so the same penumbra in every cascade, at every
   resolution, across a warped map), at least 1/2 (one bilinear 2x2
   comparison) and at most SK_PCF_MAX_TEXELS; or, when sk_filter_world is
   0, sk_pcf_radius texels (0: 1/2). Mode 1 takes the box's texels two by
   two along each axis in hardware bilinear comparisons placed between
   them in the ratio of their weights (Castano 2013, "Shadow Mapping
   Summary - Part 1", the optimised PCF of The Witness): (ceil(2R)+1)^2
   texels in (ceil((ceil(2R)+1)/2))^2 taps, (r+1)^2 for an integer radius
   r, which weighs exactly what the (2r)^2 taps at p + k + 1/2 of earlier
   versions did. Mode 0 compares each texel against its own plane depth,
   one comparison each, with the same weights. A surface facing away from
   the light (given a normal) is in its own shadow: 0, whatever the map says
   near its silhouette. */
uniform highp sampler2DArrayShadow sk_shadow_map;
uniform mat4 sk_light_vp[8];
uniform float sk_splits[10];       /* view depths: layer i covers [splits[i], splits[i+1]); after the
                                      end of the last, where shadows start to fade (>= the end: no fade) */
uniform int sk_layers;
uniform float sk_blend_band;       /* fraction of a layer's depth range blended into the next */
uniform int sk_bias_mode;          /* 0 receiver plane, 1 normal offset */
uniform float sk_normal_bias;      /* texels (mode 1; mode 0 adds it if > 0) */
uniform float sk_plane_bias;       /* mode 0: tolerance in texels of the plane's depth slope */
/* How far (world units) the receiver position may lie from the true
   surface: the deferred mask sets it from its depth buffer's precision
   before calling sk_shadow(); a forward shader's interpolated positions are
   exact (0). The receiver plane's tolerance grows by the depth this
   distance spans in the map. */
float sk_receiver_slack = 0.0;
uniform int sk_pcf_radius;
uniform float sk_filter_world;     /* the filter's half-width in world units (0: sk_pcf_radius texels) */
uniform vec3 sk_light_dir;         /* travel direction, unit */
uniform int sk_select_by_map;      /* 1: layer = the partition holding the point */
uniform int sk_rmsm;               /* 1: a virtual map through sk_page_table */
uniform highp sampler2D sk_page_table;   /* RMSM: per page of every level, (slot x, slot y)/255 and a = resident */
uniform int sk_rmsm_pages0;        /* RMSM: pages per side at level 0 */
uniform int sk_rmsm_levels;        /* RMSM: levels, the last one page */
uniform int sk_rmsm_min_level;     /* RMSM: the finest level rendered; -b: the pages of request band b (rmsm_request.vert) */
uniform int sk_rmsm_page;          /* RMSM: page side in texels (+2 border texels in the pool) */
uniform float sk_select_extent;    /* a partition's rect in its light NDC: [-e, e]^2 */
uniform vec2 sk_map_extent;        /* the part of each layer this frame rendered, in texture coordinates */

/* World size of one texel of the layer at p: 2/res over the gradient of
   light NDC x (and y), d(c.x/c.w)/dp = (row0 - ndc.x row3) / c.w; the larger
   of the two sizes. For an orthographic map row3 = (0,0,0,1): constant. */
float sk_texel_size(vec3 p, int layer)
{
    mat4 m = sk_light_vp[layer];
    vec4 c = m * vec4(p, 1.0);
    if (c.w <= 0.0) return 0.0;
    vec3 r0 = vec3(m[0][0], m[1][0], m[2][0]), r1 = vec3(m[0][1], m[1][1], m[2][1]);
    vec3 r3 = vec3(m[0][3], m[1][3], m[2][3]);
    float g = min(length(r0 - (c.x / c.w) * r3), length(r1 - (c.y / c.w) * r3)) / c.w;
    return g > 0.0 ? 2.0 / (float(textureSize(sk_shadow_map, 0).x) * g) : 0.0;
}

/* the window depth that sk_receiver_slack spans in the map at p's light
   clip c: half the length of NDC z's gradient over world position */
float sk_slack_depth(mat4 m, vec4 c)
{
    vec3 jz = vec3(m[0][2], m[1][2], m[2][2]) - (c.z / c.w) * vec3(m[0][3], m[1][3], m[2][3]);
    return 0.5 * length(jz) / c.w * sk_receiver_slack;
}

/* The receiver's tangent plane (normal n, any length; p's light clip c) as
   a depth slope of the map: (dz/du, dz/dv) in window depth per texture
   coordinate. With J the Jacobian of light NDC over world position at p
   (rows j0, j1, j2; perspective maps included), the plane's points satisfy
   n . J^-1 dndc = 0, and J^-1's columns are cross(j1, j2), cross(j2, j0),
   cross(j0, j1) over det J. cross(j0, j1) is the map's ray through p: the
   slope grows as tan of the angle between n and that ray, and is capped at
   SK_PLANE_MAX_TAN (88 degrees), beyond which the surface is its own
   silhouette. Window z and texture uv are both NDC / 2 + 1/2: the NDC ratio
   is the window ratio. Zero for a zero normal. */
const float SK_PLANE_MAX_TAN = 28.6;
vec2 sk_plane_slope(mat4 m, vec4 c, vec3 n)
{
    vec3 ndc = c.xyz / c.w;
    vec3 r3 = vec3(m[0][3], m[1][3], m[2][3]);
    vec3 j0 = vec3(m[0][0], m[1][0], m[2][0]) - ndc.x * r3;
    vec3 j1 = vec3(m[0][1], m[1][1], m[2][1]) - ndc.y * r3;
    vec3 j2 = vec3(m[0][2], m[1][2], m[2][2]) - ndc.z * r3;
    vec3 ray = cross(j0, j1);
    float nr = dot(n, ray), len = length(n) * length(ray);
    if (!(abs(nr) > 1e-30 * len) || !(len > 0.0)) return vec2(0.0);
    vec2 g = -vec2(dot(n, cross(j1, j2)), dot(n, cross(j2, j0))) / nr;
    float cosv = abs(nr) / len;
    float tanv = sqrt(max(1.0 - cosv * cosv, 0.0)) / cosv;
    return tanv > SK_PLANE_MAX_TAN ? g * (SK_PLANE_MAX_TAN / tanv) : g;
}

/* the filter's half-width in texels of the layer whose light clip at p is c
   (matrix m, texture size size), per axis of the map: sk_filter_world over
   the world size of the layer's texels there, the length of light NDC's
   gradient over world position (sk_texel_size) for each axis; else the
   texel radius */
const float SK_PCF_MAX_TEXELS = 8.0;
vec2 sk_filter_texels(mat4 m, vec4 c, vec2 size)
{
    if (!(sk_filter_world > 0.0)) return vec2(max(float(sk_pcf_radius), 0.5));
    vec3 r3 = vec3(m[0][3], m[1][3], m[2][3]);
    vec2 g = vec2(length(vec3(m[0][0], m[1][0], m[2][0]) - (c.x / c.w) * r3),
                  length(vec3(m[0][1], m[1][1], m[2][1]) - (c.y / c.w) * r3)) / c.w;
    return clamp(sk_filter_world * 0.5 * g * size, vec2(0.5), vec2(SK_PCF_MAX_TEXELS));
}

/* the part of texel j ([j, j + 1] in texel space) that the box [lo, hi] covers */
float sk_box_cover(float lo, float hi, float j) { return max(min(hi, j + 1.0) - max(lo, j), 0.0); }

/* Percentage-closer filtering against the receiver's plane. p: the lookup
   in texel space of the sampled texture (texel j's centre at j + 0.5); z:
   its window depth; gt: the plane's depth change per texel; R: the box's
   half-width in texels. Each texel the box reaches is compared with the
   plane's depth at its own centre, less the tolerance (plus slack, the
   depth uncertainty of the receiver itself), and weighed by the part of
   the box it covers. */
float sk_pcf_plane(vec2 p, float z, vec2 gt, float slack, float layer, vec2 size, vec2 R)
{
    vec2 lo = p - R, hi = p + R, first = floor(lo);
    ivec2 n = ivec2(ceil(hi) - first);
    float tol = sk_plane_bias * (abs(gt.x) + abs(gt.y)) + slack + 4.0e-7;
    float sum = 0.0;
    for (int ky = 0; ky < n.y; ky++) {
        float wy = sk_box_cover(lo.y, hi.y, first.y + float(ky));
        for (int kx = 0; kx < n.x; kx++) {
            float wx = sk_box_cover(lo.x, hi.x, first.x + float(kx));
            vec2 tc = first + vec2(float(kx), float(ky)) + 0.5;
            float zt = max(z + dot(gt, tc - p) - tol, 0.0);
            if (wx * wy > 0.0) sum += wx * wy * texture(sk_shadow_map, vec4(tc / size, layer, zt));
        }
    }
    return sum / (4.0 * R.x * R.y);
}

/* The same box through hardware 2x2 comparisons against one depth z: along
   each axis the texels it reaches are taken in pairs (j, j + 1), each pair
   one bilinear tap between their centres at j + 1/2 + w(j+1) / (w(j) +
   w(j+1)) weighing w(j) + w(j+1) (a last texel alone: its centre), so the
   tap's bilinear weights are the texels' box weights (Castano 2013) */
float sk_pcf_taps(vec2 p, float z, float layer, vec2 size, vec2 R)
{
    vec2 lo = p - R, hi = p + R, first = floor(lo);
    ivec2 taps = (ivec2(ceil(hi) - first) + 1) / 2;
    float sum = 0.0;
    for (int ty = 0; ty < taps.y; ty++) {
        float y = first.y + float(2 * ty);
        float ay = sk_box_cover(lo.y, hi.y, y), by = sk_box_cover(lo.y, hi.y, y + 1.0);
        for (int tx = 0; tx < taps.x; tx++) {
            float x = first.x + float(2 * tx);
            float ax = sk_box_cover(lo.x, hi.x, x), bx = sk_box_cover(lo.x, hi.x, x + 1.0);
            vec2 tc = vec2(x, y) + 0.5 + vec2(bx / (ax + bx), by / (ay + by));
            sum += (ax + bx) * (ay + by) * texture(sk_shadow_map, vec4(tc / size, layer, z));
        }
    }
    return sum / (4.0 * R.x * R.y);
}

#ifdef SK_SHADOW_EVSM
/* EVSM, the filterable map (desc.filter = SKGL_FILTER_EVSM; compiled in
   when SK_SHADOW_EVSM is defined before the snippet). Each layer has a
   blurred moments map (Lauritzen and McCool 2008, "Layered Variance Shadow
   Maps", Sec. 4): E[exp(c+ x)], E[exp(c+ x)^2], E[-exp(-c- x)],
   E[exp(-c- x)^2] over the filter, x = 2 z - 1 the map's window depth. Each
   warp's Chebyshev upper bound (Donnelly and Lauritzen 2006, "Variance
   Shadow Maps", Eq. 5) bounds the lit fraction; the smaller of the two is
   taken, then the light-bleeding reduction cuts the bound's tail below
   sk_evsm.z and rescales the rest (Lauritzen 2007, GPU Gems 3 ch. 8). */
uniform highp sampler2DArray sk_moments;   /* RGBA32F, bilinear, on `unit` + 2 */
uniform int sk_filter;             /* 1: EVSM, 0: the PCF of sk_shadow_layer */
uniform vec4 sk_evsm;              /* x c+, y c-, z light-bleeding reduction, w the smallest variance,
                                      in window depth (each warp's scaled by its slope) */

float sk_chebyshev(vec2 m, float t, float min_var, float bleed)
{
    if (t <= m.x) return 1.0;
    float var = max(m.y - m.x * m.x, min_var);
    float d = t - m.x;
    float p = var / (var + d * d);
    return clamp((p - bleed) / (1.0 - bleed), 0.0, 1.0);
}

/* uv: the lookup in the layer; z: the receiver's window depth */
float sk_evsm_visibility(vec2 uv, float z, float layer)
{
    vec4 m = textureLod(sk_moments, vec3(uv, layer), 0.0);
    float x = 2.0 * z - 1.0;
    vec2 w = vec2(exp(sk_evsm.x * x), -exp(-sk_evsm.y * x));
    /* the variance a depth spread of sk_evsm.w makes in each warp: its slope times the spread */
    vec2 s = 2.0 * sk_evsm.w * sk_evsm.xy * abs(w);
    return min(sk_chebyshev(m.xy, w.x, s.x * s.x, sk_evsm.z), sk_chebyshev(m.zw, w.y, s.y * s.y, sk_evsm.z));
}
#endif

float sk_shadow_layer(vec3 world_pos, vec3 world_normal, vec3 plane_normal, int layer)
{
    float nb = sk_bias_mode == 1 || sk_normal_bias > 0.0 ? sk_normal_bias : 0.0;
    vec3 p = nb > 0.0 ? world_pos + world_normal * (nb * sk_texel_size(world_pos, layer)) : world_pos;
    vec4 c = sk_light_vp[layer] * vec4(p, 1.0);
    if (c.w <= 0.0) return 1.0;
    vec3 ndc = c.xyz / c.w;
    vec3 uvz = ndc * 0.5 + 0.5;
    if (any(lessThan(uvz.xy, vec2(0.0))) || any(greaterThan(uvz.xy, sk_map_extent))) return 1.0;
    if (uvz.z > 1.0) return 1.0;
    float z = max(uvz.z, 0.0);
#ifdef SK_SHADOW_EVSM
    if (sk_filter == 1) return sk_evsm_visibility(uvz.xy, z, float(layer));
#endif
    vec2 size = vec2(textureSize(sk_shadow_map, 0).xy);
    vec2 R = sk_filter_texels(sk_light_vp[layer], c, size);
    if (sk_bias_mode == 0) {
        vec2 g = sk_plane_slope(sk_light_vp[layer], c, plane_normal);
        return sk_pcf_plane(uvz.xy * size, z, g / size, sk_slack_depth(sk_light_vp[layer], c), float(layer), size,
                            R);
    }
    if (R.x <= 0.5 && R.y <= 0.5)
        return texture(sk_shadow_map, vec4(uvz.xy, float(layer), z));
    return sk_pcf_taps(uvz.xy * size, z, float(layer), size, R);
}

/* RMSM: the point through the page table, from its level up to the
   coarsest; each pool page has a border of one texel, which bounds the
   normal offset's reach and the filter to a 2x2 comparison */
float sk_shadow_rmsm(vec3 world_pos, vec3 world_normal, vec3 plane_normal, float lod)
{
    vec4 c0 = sk_light_vp[0] * vec4(world_pos, 1.0);
    vec2 st = c0.xy / c0.w * 0.5 + 0.5;
    if (any(lessThan(st, vec2(0.0))) || any(greaterThanEqual(st, vec2(1.0)))) return 1.0;
    float vres = float(sk_rmsm_pages0 * sk_rmsm_page), page = float(sk_rmsm_page);
    vec2 pool = vec2(textureSize(sk_shadow_map, 0).xy);
    int band = max(-sk_rmsm_min_level, 0);
    int first = int(floor(lod)) - band;
    for (int level = clamp(first, max(sk_rmsm_min_level, 0), sk_rmsm_levels - 1); level < sk_rmsm_levels; level++) {
        int n = sk_rmsm_pages0 >> level;
        ivec2 pg = min(ivec2(st * float(n)), ivec2(n - 1));
        vec4 e = texelFetch(sk_page_table, ivec2(2 * sk_rmsm_pages0 - 2 * n + pg.x, pg.y), 0);
        if (e.a < 0.5) continue;
        /* texels of this level: the map at vres / 2^level */
        float lres = vres / exp2(float(level));
        float texel = sk_texel_size(world_pos, 0) * (pool.x / lres);
        float nb = sk_bias_mode == 1 || sk_normal_bias > 0.0 ? min(sk_normal_bias, 0.9) : 0.0;
        vec4 c = sk_light_vp[0] * vec4(world_pos + world_normal * (nb * texel), 1.0);
        vec3 uvz = c.xyz / c.w * 0.5 + 0.5;
        if (uvz.z > 1.0) return 1.0;
        vec2 f = clamp(uvz.xy * lres - vec2(pg) * page, vec2(-0.5), vec2(page + 0.5));
        vec2 slot = floor(e.rg * 255.0 + 0.5);
        vec2 pp = slot * (page + 2.0) + 1.0 + f;
        if (sk_bias_mode == 0)
            return sk_pcf_plane(pp, max(uvz.z, 0.0), sk_plane_slope(sk_light_vp[0], c, plane_normal) / lres,
                                sk_slack_depth(sk_light_vp[0], c), 0.0, pool, vec2(0.5));
        return texture(sk_shadow_map, vec4(pp / pool, 0.0, max(uvz.z, 0.0)));
    }
    return 1.0;
}

/* the distance fade: v toward lit over [start, end) of the view depth,
   start stored after the last split (none when it is not before the end) */
float sk_fade(float v, float view_depth, float end)
{
    float start = sk_splits[sk_layers + 1];
    if (!(start < end)) return v;
    return mix(v, 1.0, clamp((view_depth - start) / (end - start), 0.0, 1.0));
}

float sk_shadow_map_visibility(vec3 world_pos, vec3 world_normal, float view_depth)
{
    float rmsm_lod = 0.0;
    if (sk_rmsm != 0) {
        /* the level of detail as rmsm_analyze.frag takes it, before any branch */
        vec4 c = sk_light_vp[0] * vec4(world_pos, 1.0);
        float vres = float(sk_rmsm_pages0 * sk_rmsm_page);
        vec2 st = c.xy / c.w * 0.5 + 0.5;
        vec2 dx = dFdx(st) * vres, dy = dFdy(st) * vres;
        float tr = dot(dx, dx) + dot(dy, dy), det = abs(dx.x * dy.y - dx.y * dy.x);
        rmsm_lod = log2(max(det / max(sqrt(0.5 * (tr + sqrt(max(tr * tr - 4.0 * det * det, 0.0)))), 1e-30), 1e-30));
    }
    /* the receiver's plane: its normal, else the screen derivatives of the
       position (taken here, before any branch) */
    vec3 pn = cross(dFdx(world_pos), dFdy(world_pos));
    if (dot(world_normal, world_normal) > 0.0) pn = world_normal;
    if (dot(world_normal, sk_light_dir) >= 0.0 && dot(world_normal, world_normal) > 0.0) return 0.0;
    if (sk_rmsm != 0) return sk_shadow_rmsm(world_pos, world_normal, pn, rmsm_lod);
    if (sk_select_by_map != 0) {
        if (view_depth < sk_splits[0] || view_depth >= sk_splits[1]) return 1.0;
        for (int i = 0; i < sk_layers; i++) {
            vec4 c = sk_light_vp[i] * vec4(world_pos, 1.0);
            if (all(lessThanEqual(abs(c.xy), vec2(sk_select_extent * c.w))))
                return sk_fade(sk_shadow_layer(world_pos, world_normal, pn, i), view_depth, sk_splits[1]);
        }
        return 1.0;
    }
    if (view_depth < sk_splits[0] || view_depth >= sk_splits[sk_layers]) return 1.0;
    int layer = 0;
    for (int i = 1; i < sk_layers; i++)
        if (view_depth >= sk_splits[i]) layer = i;
    float v = sk_shadow_layer(world_pos, world_normal, pn, layer);
    if (sk_blend_band > 0.0 && layer + 1 < sk_layers) {
        float end = sk_splits[layer + 1];
        float band = sk_blend_band * (end - sk_splits[layer]);
        float t = (view_depth - (end - band)) / band;
        if (t > 0.0)
            v = mix(v, sk_shadow_layer(world_pos, world_normal, pn, layer + 1), t);
    }
    return sk_fade(v, view_depth, sk_splits[sk_layers]);
}

/* Contact shadows in a forward shader (skgl_shadow_desc.contact_length):
   "#define SK_SHADOW_CONTACT 1" before the snippet declares the camera's
   depth buffer and the march's uniforms; skgl_shadow_bind binds the buffer
   named by skgl_shadow_contact_depth on unit + 3 and sets them, when the
   light has contact_length > 0 (without the define, or with length 0, the
   snippet is as it was: no sampler, no call). The march is the mask's
   (shadow_mask.frag, McGuire and Mara 2014's depth-buffer ray casting with
   a constant thickness) from the receiver's own position and normal; the
   buffer's surface normals, which a forward pass has no buffer of, come
   from the depth buffer itself (sk_contact_normal). */
#ifndef SK_SHADOW_CONTACT
#define SK_SHADOW_CONTACT 0
#endif
#if SK_SHADOW_CONTACT
uniform highp sampler2D sk_contact_depth;  /* the camera's depth buffer: a depth pre-pass, not the target drawn */
uniform vec4 sk_contact;                   /* x the march's length (world units; 0: off), y steps, z thickness */
uniform mat4 sk_contact_camera[3];         /* the camera of sk_shadow's positions: view-projection, its
                                              inverse, view */
uniform vec4 sk_contact_depth_map;         /* the buffer's depth convention: NDC z = depth * x + y */

vec3 sk_contact_world(ivec2 q)
{
    vec2 ndc_xy = (vec2(q) + 0.5) / vec2(textureSize(sk_contact_depth, 0)) * 2.0 - 1.0;
    float d = texelFetch(sk_contact_depth, q, 0).r;
    vec4 w = sk_contact_camera[1] * vec4(ndc_xy, d * sk_contact_depth_map.x + sk_contact_depth_map.y, 1.0);
    return w.xyz / w.w;
}

float sk_contact_view_depth(vec3 p) { return -(sk_contact_camera[2] * vec4(p, 1.0)).z; }

/* the buffer surface's normal at pixel q (position b), toward the camera:
   on each axis the one-sided difference toward the side that continues
   q's plane, the one whose next two pixels extrapolate q's view depth best
   (the second difference; at a crease, such as a wall's foot on the
   ground, the other side bends away) */
vec3 sk_contact_normal(ivec2 q, vec3 b)
{
    ivec2 last = textureSize(sk_contact_depth, 0) - 1;
    vec3 t[2];
    float zb = sk_contact_view_depth(b);
    for (int a = 0; a < 2; a++) {
        ivec2 e = ivec2(1 - a, a);
        vec3 lo = sk_contact_world(clamp(q - e, ivec2(0), last)), hi = sk_contact_world(clamp(q + e, ivec2(0), last));
        float zl2 = sk_contact_view_depth(sk_contact_world(clamp(q - 2 * e, ivec2(0), last)));
        float zh2 = sk_contact_view_depth(sk_contact_world(clamp(q + 2 * e, ivec2(0), last)));
        float el = abs(2.0 * sk_contact_view_depth(lo) - zl2 - zb), eh = abs(2.0 * sk_contact_view_depth(hi) - zh2 - zb);
        t[a] = eh < el ? hi - b : b - lo;
    }
    vec3 n = cross(t[0], t[1]);
    vec3 to_eye = -(sk_contact_camera[2] * vec4(b, 1.0)).xyz * mat3(sk_contact_camera[2]);
    return normalize(dot(n, to_eye) < 0.0 ? -n : n);
}

/* the buffer's view-depth step at pixel q (depth z): the largest one-sided
   difference to its four neighbours, as shadow_mask.frag's
   receiver_depth_step */
float sk_contact_step(ivec2 q, float z)
{
    ivec2 last = textureSize(sk_contact_depth, 0) - 1;
    float g = 0.0;
    for (int a = 0; a < 2; a++) {
        ivec2 e = ivec2(1 - a, a);
        ivec2 lo = clamp(q - e, ivec2(0), last), hi = clamp(q + e, ivec2(0), last);
        float dl = abs(sk_contact_view_depth(sk_contact_world(lo)) - z);
        float dh = abs(sk_contact_view_depth(sk_contact_world(hi)) - z);
        g = max(g, max(lo == q ? 0.0 : dl, hi == q ? 0.0 : dh));
    }
    return g;
}

/* 0 blocked, 1 clear: shadow_mask.frag's contact_visibility, the receiver's
   normal its own, the buffer's from its depth (a receiver without a
   normal: the buffer must lie in front by more than two of the receiver's
   pixel depth steps) */
float sk_contact_visibility(vec3 world, vec3 n, float z)
{
    vec2 size = vec2(textureSize(sk_contact_depth, 0));
    bool plane = dot(n, n) > 0.0;
    float plane_tol = 1e-3 * z, tol = 0.0;
    int steps = int(sk_contact.y);
    if (!plane) {
        vec4 c0 = sk_contact_camera[0] * vec4(world, 1.0);
        ivec2 q0 = clamp(ivec2((c0.xy / c0.w * 0.5 + 0.5) * size), ivec2(0), ivec2(size) - 1);
        tol = 2.0 * sk_contact_step(q0, z);
    }
    for (int i = 1; i <= steps; i++) {
        vec3 p = world - sk_light_dir * (sk_contact.x * float(i) / float(steps));
        vec4 c = sk_contact_camera[0] * vec4(p, 1.0);
        if (c.w <= 0.0) break;
        vec2 win = (c.xy / c.w * 0.5 + 0.5) * size;
        if (any(lessThan(win, vec2(0.0))) || any(greaterThanEqual(win, size))) break;
        ivec2 q = ivec2(win);
        vec3 b = sk_contact_world(q);
        float in_front = sk_contact_view_depth(p) - sk_contact_view_depth(b);
        if (in_front <= tol || in_front >= sk_contact.z) continue;
        if (!plane) return 0.0;
        if (dot(b - world, normalize(n)) > plane_tol && dot(b - p, sk_contact_normal(q, b)) >= 0.0) return 0.0;
    }
    return 1.0;
}
#endif

/* the map's visibility v combined with the contact march (when on) */
float sk_contact_combine(float v, vec3 world_pos, vec3 world_normal, float view_depth)
{
#if SK_SHADOW_CONTACT
    if (sk_contact.x > 0.0 && v > 0.0) v = min(v, sk_contact_visibility(world_pos, world_normal, view_depth));
#endif
    return v;
}

/* the shadow at world_pos: the map's visibility (sk_shadow_map_visibility),
   with contact shadows when SK_SHADOW_CONTACT is on */
float sk_shadow(vec3 world_pos, vec3 world_normal, float view_depth)
{
    return sk_contact_combine(sk_shadow_map_visibility(world_pos, world_normal, view_depth), world_pos, world_normal,
                              view_depth);
}
