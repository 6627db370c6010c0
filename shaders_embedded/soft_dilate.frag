/* PVSM step 1 without a geometry shader (OpenGL ES 3.0, WebGL2): the
   low-resolution map was rendered u_factor times finer with plain
   rasterisation into u_fine (window depth); each low-resolution texel takes
   o_cons, the minimum over its u_factor x u_factor block grown by one fine
   texel on every side (what conservative rasterisation catches of every
   caster at least one fine texel wide; thinner ones can slip between the
   fine texels' centres), and o_true, the minimum of the four fine texels
   around its centre (the plain map). */
uniform sampler2D u_fine;
uniform int u_factor;
layout(location = 0) out vec4 o_cons;
layout(location = 1) out vec4 o_true;
layout(location = 2) out vec4 o_cons_copy;   /* skgl_soft's low_copy[0], where it has one */
void main()
{
    ivec2 last = textureSize(u_fine, 0) - 1;
    ivec2 base = ivec2(gl_FragCoord.xy) * u_factor;
    float m = 1.0;
    for (int y = -1; y <= u_factor; y++)
        for (int x = -1; x <= u_factor; x++)
            m = min(m, texelFetch(u_fine, clamp(base + ivec2(x, y), ivec2(0), last), 0).r);
    ivec2 c = base + ivec2(u_factor / 2);
    float t = min(min(texelFetch(u_fine, c - ivec2(1, 1), 0).r, texelFetch(u_fine, c - ivec2(0, 1), 0).r),
                  min(texelFetch(u_fine, c - ivec2(1, 0), 0).r, texelFetch(u_fine, c, 0).r));
    o_cons = vec4(m);
    o_true = vec4(t);
    o_cons_copy = o_cons;
}
