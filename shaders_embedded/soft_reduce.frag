/* One level of a MIN pyramid stored as the mip chain of u_src: each texel
   the minimum of the 2x2 texels of the level below (odd sizes: the missing
   ones are skipped). Only the level below is read (texelFetch), never the
   one drawn; with a non-mipmap sampler on u_src, only the base level would
   be a rendering feedback loop. */
uniform sampler2D u_src;
flat in int v_level;
out vec4 o_min;
void main()
{
    ivec2 d = ivec2(gl_FragCoord.xy) * 2, size = textureSize(u_src, v_level - 1);
    vec4 m = vec4(1e30);
    for (int y = 0; y < 2; y++)
        for (int x = 0; x < 2; x++) {
            ivec2 s = d + ivec2(x, y);
            if (s.x < size.x && s.y < size.y) m = min(m, texelFetch(u_src, s, v_level - 1));
        }
    o_min = m;
}
