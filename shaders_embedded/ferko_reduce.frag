/* Resolution estimation, reduction (Ferko 2013, Sec. 3.3): the
   MIN of the analysis texels, layer 0 the bounds stored as (min x, min y,
   -max x, -max y), so one MIN serves both ends, layer 1 the patch. Texels
   outside the source level's u_src_size are skipped.
   SK_FERKO_FINAL 0: each output texel reduces a 16x16 block of the source
   into the two layers of the next level (attachments 0 and 1).
   SK_FERKO_FINAL 1: the last pass, over a source of at most 32x32 texels,
   into one 2x1 RGBA32F texture: texel 0 the bounds, texel 1 the patch, so
   that one glReadPixels of 2x1 texels reads the whole estimate. */
uniform sampler2DArray u_src;
uniform ivec2 u_src_size;
#if SK_FERKO_FINAL
out vec4 o_result;
#else
layout(location = 0) out vec4 o_bounds;
layout(location = 1) out vec4 o_patch;
#endif
void main()
{
#if SK_FERKO_FINAL
    const int n = 32;
    ivec2 base = ivec2(0);
#else
    const int n = 16;
    ivec2 base = ivec2(gl_FragCoord.xy) * 16;
#endif
    vec4 b = vec4(3.0e38), p = vec4(3.0e38);
    for (int y = 0; y < n; y++)
        for (int x = 0; x < n; x++) {
            ivec2 q = base + ivec2(x, y);
            if (q.x >= u_src_size.x || q.y >= u_src_size.y) continue;
            b = min(b, texelFetch(u_src, ivec3(q, 0), 0));
            p = min(p, texelFetch(u_src, ivec3(q, 1), 0));
        }
#if SK_FERKO_FINAL
    o_result = gl_FragCoord.x < 1.0 ? b : p;
#else
    o_bounds = b;
    o_patch = p;
#endif
}
