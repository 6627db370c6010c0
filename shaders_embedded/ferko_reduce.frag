/* Resolution estimation, reduction (seed 000, Sec. 3.3): the MIN of a 4x4
   neighbourhood of both analysis textures (the bounds are stored as
   (min x, min y, -max x, -max y), so one MIN serves both ends). Texels
   outside the source level's u_src_size are skipped. */
uniform sampler2D u_bounds;
uniform sampler2D u_patch;
uniform ivec2 u_src_size;
layout(location = 0) out vec4 o_bounds;
layout(location = 1) out vec4 o_patch;
void main()
{
    ivec2 base = ivec2(gl_FragCoord.xy) * 4;
    vec4 b = vec4(3.0e38), p = vec4(3.0e38, 3.0e38, 0.0, 0.0);
    for (int y = 0; y < 4; y++)
        for (int x = 0; x < 4; x++) {
            ivec2 q = base + ivec2(x, y);
            if (q.x >= u_src_size.x || q.y >= u_src_size.y) continue;
            b = min(b, texelFetch(u_bounds, q, 0));
            p = min(p, texelFetch(u_patch, q, 0));
        }
    o_bounds = b;
    o_patch = p;
}
