/* shadowkit: directional-light shadow lookup, shared by the deferred
   shadow-mask pass and forward shaders (skgl_glsl_snippet()).

   Maps are layers of one depth texture array: one layer for a standard
   focused map, one per cascade for PSSM. A world position picks its layer by
   view depth against the split distances (PSSM practical split scheme,
   seed 002), optionally blending into the next cascade inside a band; or,
   for LSPSM's partitions (seed 003), which tile the light plane rather than
   the view depth, the first layer whose partition rect holds it; or, for
   RMSM (seed 002), a virtual map: the page of the point's level of detail
   through the page table into a pool of pages (layer 0), or the nearest
   coarser page resident. sk_shadow() takes screen derivatives for RMSM:
   call it in uniform control flow (not after a discard or an early return).

   Maps may be orthographic (standard, PSSM) or perspective-warped (PSM,
   LiSPSM): the light-clip w is divided out per pixel.

   Bias, in texels so it follows resolution: the receiver is pushed along its
   normal by sk_normal_bias texels of its layer at that point (normal
   offset; a warped map's texels change size across the view), and the
   casters were rendered with slope-scaled polygon offset. Filtering: one
   hardware 2x2 comparison (bilinear PCF), or a (2r)x(2r) grid of them.
   A surface facing away from the light (given a normal) is in its own
   shadow: 0, whatever the map says near its silhouette. */
uniform sampler2DArrayShadow sk_shadow_map;
uniform mat4 sk_light_vp[8];
uniform float sk_splits[9];        /* view depths: layer i covers [splits[i], splits[i+1]) */
uniform int sk_layers;
uniform float sk_blend_band;       /* fraction of a layer's depth range blended into the next */
uniform float sk_normal_bias;      /* texels */
uniform int sk_pcf_radius;
uniform vec3 sk_light_dir;         /* travel direction, unit */
uniform int sk_select_by_map;      /* 1: layer = the partition holding the point */
uniform int sk_rmsm;               /* 1: a virtual map through sk_page_table */
uniform sampler2D sk_page_table;   /* RMSM: per page of every level, (slot x, slot y)/255 and a = resident */
uniform int sk_rmsm_pages0;        /* RMSM: pages per side at level 0 */
uniform int sk_rmsm_levels;        /* RMSM: levels, the last one page */
uniform int sk_rmsm_min_level;     /* RMSM: the finest level rendered */
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

float sk_shadow_layer(vec3 world_pos, vec3 world_normal, int layer)
{
    vec3 p = world_pos + world_normal * (sk_normal_bias * sk_texel_size(world_pos, layer));
    vec4 c = sk_light_vp[layer] * vec4(p, 1.0);
    if (c.w <= 0.0) return 1.0;
    vec3 ndc = c.xyz / c.w;
    vec3 uvz = ndc * 0.5 + 0.5;
    if (any(lessThan(uvz.xy, vec2(0.0))) || any(greaterThan(uvz.xy, sk_map_extent))) return 1.0;
    if (uvz.z > 1.0) return 1.0;
    float z = max(uvz.z, 0.0);
    if (sk_pcf_radius <= 0)
        return texture(sk_shadow_map, vec4(uvz.xy, float(layer), z));
    vec2 texel = 1.0 / vec2(textureSize(sk_shadow_map, 0).xy);
    float sum = 0.0;
    int r = sk_pcf_radius;
    for (int y = -r; y < r; y++)
        for (int x = -r; x < r; x++)
            sum += texture(sk_shadow_map, vec4(uvz.xy + (vec2(x, y) + 0.5) * texel, float(layer), z));
    return sum / float(4 * r * r);
}

/* RMSM: the point through the page table, from its level up to the
   coarsest; each pool page has a border of one texel, which bounds the
   normal offset's reach and the filter to a 2x2 comparison */
float sk_shadow_rmsm(vec3 world_pos, vec3 world_normal, float lod)
{
    vec4 c0 = sk_light_vp[0] * vec4(world_pos, 1.0);
    vec2 st = c0.xy / c0.w * 0.5 + 0.5;
    if (any(lessThan(st, vec2(0.0))) || any(greaterThanEqual(st, vec2(1.0)))) return 1.0;
    float vres = float(sk_rmsm_pages0 * sk_rmsm_page), page = float(sk_rmsm_page);
    vec2 pool = vec2(textureSize(sk_shadow_map, 0).xy);
    for (int level = clamp(int(floor(lod)), sk_rmsm_min_level, sk_rmsm_levels - 1); level < sk_rmsm_levels; level++) {
        int n = sk_rmsm_pages0 >> level;
        ivec2 pg = min(ivec2(st * float(n)), ivec2(n - 1));
        vec4 e = texelFetch(sk_page_table, ivec2(2 * sk_rmsm_pages0 - 2 * n + pg.x, pg.y), 0);
        if (e.a < 0.5) continue;
        /* texels of this level: the map at vres / 2^level */
        float lres = vres / exp2(float(level));
        float texel = sk_texel_size(world_pos, 0) * (pool.x / lres);
        vec4 c = sk_light_vp[0] * vec4(world_pos + world_normal * (min(sk_normal_bias, 0.9) * texel), 1.0);
        vec3 uvz = c.xyz / c.w * 0.5 + 0.5;
        if (uvz.z > 1.0) return 1.0;
        vec2 f = clamp(uvz.xy * lres - vec2(pg) * page, vec2(-0.5), vec2(page + 0.5));
        vec2 slot = floor(e.rg * 255.0 + 0.5);
        vec2 puv = (slot * (page + 2.0) + 1.0 + f) / pool;
        return texture(sk_shadow_map, vec4(puv, 0.0, max(uvz.z, 0.0)));
    }
    return 1.0;
}

float sk_shadow(vec3 world_pos, vec3 world_normal, float view_depth)
{
    float rmsm_lod = 0.0;
    if (sk_rmsm != 0) {
        /* the level of detail as rmsm_analyze.frag takes it, before any branch */
        vec4 c = sk_light_vp[0] * vec4(world_pos, 1.0);
        float vres = float(sk_rmsm_pages0 * sk_rmsm_page);
        vec2 st = c.xy / c.w * 0.5 + 0.5;
        vec2 dx = dFdx(st) * vres, dy = dFdy(st) * vres;
        rmsm_lod = 0.5 * log2(max(abs(dx.x * dy.y - dx.y * dy.x), 1e-30));
    }
    if (dot(world_normal, sk_light_dir) >= 0.0 && dot(world_normal, world_normal) > 0.0) return 0.0;
    if (sk_rmsm != 0) return sk_shadow_rmsm(world_pos, world_normal, rmsm_lod);
    if (sk_select_by_map != 0) {
        if (view_depth < sk_splits[0] || view_depth >= sk_splits[1]) return 1.0;
        for (int i = 0; i < sk_layers; i++) {
            vec4 c = sk_light_vp[i] * vec4(world_pos, 1.0);
            if (all(lessThanEqual(abs(c.xy), vec2(sk_select_extent * c.w))))
                return sk_shadow_layer(world_pos, world_normal, i);
        }
        return 1.0;
    }
    if (view_depth < sk_splits[0] || view_depth >= sk_splits[sk_layers]) return 1.0;
    int layer = 0;
    for (int i = 1; i < sk_layers; i++)
        if (view_depth >= sk_splits[i]) layer = i;
    float v = sk_shadow_layer(world_pos, world_normal, layer);
    if (sk_blend_band > 0.0 && layer + 1 < sk_layers) {
        float end = sk_splits[layer + 1];
        float band = sk_blend_band * (end - sk_splits[layer]);
        float t = (view_depth - (end - band)) / band;
        if (t > 0.0)
            v = mix(v, sk_shadow_layer(world_pos, world_normal, layer + 1), t);
    }
    return v;
}
