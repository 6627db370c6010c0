/* One level of a MIN pyramid: each texel the minimum of the 2x2 texels
   below it (odd sizes: the missing ones are skipped). The source is the
   same texture with its base and max level set to the level below, so
   level 0 of textureLod is that level. PVSM: the low-res map's blocker
   search pyramid and the SMTG pyramid (step 5). */
uniform sampler2D u_src;
uniform ivec2 u_src_size;
out vec4 o_min;
void main()
{
    ivec2 d = ivec2(gl_FragCoord.xy) * 2;
    vec4 m = vec4(1e30);
    for (int y = 0; y < 2; y++)
        for (int x = 0; x < 2; x++) {
            ivec2 s = d + ivec2(x, y);
            if (s.x < u_src_size.x && s.y < u_src_size.y)
                m = min(m, textureLod(u_src, (vec2(s) + 0.5) / vec2(u_src_size), 0.0));
        }
    o_min = m;
}
