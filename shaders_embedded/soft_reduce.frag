/* One level of a MIN pyramid stored as the mip chain of u_src: each texel
   the minimum of the 2x2 texels of the level below (odd sizes: the missing
   ones are skipped). Only the level below is read (texelFetch), never the
   one drawn; with a non-mipmap sampler on u_src, only the base level would
   be a rendering feedback loop. */
uniform sampler2D u_src;
flat in int v_level;
layout(location = 0) out vec4 o_min;
#ifdef SKGL_REDUCE_COPY
/* skgl_caps.mip_render_level 0 (WebGL2: ANGLE refuses to sample a texture
   while one of its levels is drawn, whatever the sampler): u_src is a
   single-level copy of the level below, and this level goes to a copy too */
layout(location = 1) out vec4 o_copy;
#define SKGL_SRC_LEVEL 0
#else
#define SKGL_SRC_LEVEL (v_level - 1)
#endif
void main()
{
    ivec2 d = ivec2(gl_FragCoord.xy) * 2, size = textureSize(u_src, SKGL_SRC_LEVEL);
    vec4 m = vec4(1e30);
    for (int y = 0; y < 2; y++)
        for (int x = 0; x < 2; x++) {
            ivec2 s = d + ivec2(x, y);
            if (s.x < size.x && s.y < size.y) m = min(m, texelFetch(u_src, s, SKGL_SRC_LEVEL));
        }
    o_min = m;
#ifdef SKGL_REDUCE_COPY
    o_copy = m;
#endif
}
