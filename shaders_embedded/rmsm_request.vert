/* RMSM page requests, reduced on the GPU: one point per pixel of the
   analysis texture, drawn onto the texel of the page it needs in the
   request atlas, so every page asked for by any pixel ends up set. Level l
   needs clamp(floor(lod), 0, u_levels - 1), as sk_rmsm_page_requests
   takes it; when the page pool is short, the CPU folds the requests of
   the finest levels into their ancestors (the same pages a raised minimum
   level would request, from the one read-back). Atlas layout: level
   l's n_l = u_pages0 >> l pages per side start at column 2 u_pages0 - 2 n_l;
   the atlas is (2 u_pages0 - 1) x u_pages0 texels.
   u_bands > 1 (banded requests): the atlas in RGBA8, cleared to 1 and
   blended by MIN, two points per sample: one onto that texel with blue 0,
   one onto its level-0 page with (f, 254 - f) / 255 in red and green, f
   the level above: per level-0 page the least and the greatest level its
   samples ask for. Request band b's pages follow on the CPU
   (skgl__rmsm_bands): band 0 the level f (blue), band b > 0 at most
   level u_levels - 1 - b (and one level finer where the pool holds
   it), each the ancestor of the sample's level-0 page. */
uniform sampler2D u_samples;
uniform int u_pages0;
uniform int u_levels;
uniform int u_bands;
flat out vec3 v_request;
void main()
{
    ivec2 size = textureSize(u_samples, 0);
    int i = u_bands > 1 ? gl_VertexID / 2 : gl_VertexID;
    vec4 s = texelFetch(u_samples, ivec2(i % size.x, i / size.x), 0);
    gl_PointSize = 1.0;
    v_request = u_bands > 1 ? vec3(1.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
    if (s.w < 0.5) { gl_Position = vec4(2.0, 2.0, 2.0, 1.0); return; }   /* outside: clipped */
    int level = clamp(int(floor(s.z)), 0, u_levels - 1);
    if (u_bands > 1 && gl_VertexID % 2 == 1) {
        v_request = vec3(float(level), float(254 - level), 255.0) / 255.0;
        level = 0;
    }
    int n = u_pages0 >> level;
    ivec2 page = min(ivec2(s.xy * float(n)), ivec2(n - 1));
    vec2 texel = vec2(float(2 * u_pages0 - 2 * n + page.x), float(page.y)) + 0.5;
    gl_Position = vec4(texel / vec2(float(2 * u_pages0 - 1), float(u_pages0)) * 2.0 - 1.0, 0.0, 1.0);
}
