/* RMSM page requests, reduced on the GPU: one point per pixel of the
   analysis texture, drawn onto the texel of the page it needs in the
   request atlas, so every page asked for by any pixel ends up set. Level l
   needs clamp(floor(lod), 0, u_levels - 1), as sk_rmsm_page_requests
   takes it; when the page pool is short, the CPU folds the requests of
   the finest levels into their ancestors (the same pages a raised minimum
   level would request, from the one read-back). Atlas layout: level
   l's n_l = u_pages0 >> l pages per side start at column 2 u_pages0 - 2 n_l;
   the atlas is (2 u_pages0 - 1) x u_pages0 texels. */
uniform sampler2D u_samples;
uniform int u_pages0;
uniform int u_levels;
void main()
{
    ivec2 size = textureSize(u_samples, 0);
    vec4 s = texelFetch(u_samples, ivec2(gl_VertexID % size.x, gl_VertexID / size.x), 0);
    gl_PointSize = 1.0;
    if (s.w < 0.5) { gl_Position = vec4(2.0, 2.0, 2.0, 1.0); return; }   /* outside: clipped */
    int level = clamp(int(floor(s.z)), 0, u_levels - 1);
    int n = u_pages0 >> level;
    ivec2 page = min(ivec2(s.xy * float(n)), ivec2(n - 1));
    vec2 texel = vec2(float(2 * u_pages0 - 2 * n + page.x), float(page.y)) + 0.5;
    gl_Position = vec4(texel / vec2(float(2 * u_pages0 - 1), float(u_pages0)) * 2.0 - 1.0, 0.0, 1.0);
}
