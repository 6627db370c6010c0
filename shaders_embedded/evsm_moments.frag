/* EVSM moments (exponential variance shadow maps: Lauritzen and McCool
   2008, "Layered Variance Shadow Maps", Sec. 4, the exponential warp with
   a positive and a negative exponent). One separable box blur in two
   passes over a layer of the light's map: the horizontal pass reads the
   depth layer, warps each texel's depth x = 2 z - 1 into
   (exp(c+ x), exp(c+ x)^2, -exp(-c- x), exp(-c- x)^2) and averages 2r+1 of
   them along a row; the vertical pass (SK_EVSM_VERTICAL) averages 2r+1 of
   those along a column into the layer of the moments array. Reads clamp
   to the texels this frame rendered (u_extent). Two draws per layer
   whatever the radius. */
in vec2 v_uv;
out vec4 o_moments;
uniform int u_radius;
uniform vec2 u_extent;              /* the rendered region, in texels */
#ifdef SK_EVSM_VERTICAL
uniform highp sampler2D u_src;      /* the horizontal pass's moments */
#else
uniform highp sampler2DArray u_depth;   /* the light's depth maps (no comparison) */
uniform int u_layer;
uniform vec2 u_exponents;           /* c+, c- */
#endif

vec4 moments_at(ivec2 t)
{
#ifdef SK_EVSM_VERTICAL
    return texelFetch(u_src, t, 0);
#else
    float x = 2.0 * texelFetch(u_depth, ivec3(t, u_layer), 0).r - 1.0;
    float p = exp(u_exponents.x * x), n = -exp(-u_exponents.y * x);
    return vec4(p, p * p, n, n * n);
#endif
}

void main()
{
    ivec2 px = ivec2(gl_FragCoord.xy), last = ivec2(u_extent) - 1;
#ifdef SK_EVSM_VERTICAL
    ivec2 step = ivec2(0, 1);
#else
    ivec2 step = ivec2(1, 0);
#endif
    vec4 sum = vec4(0.0);
    for (int k = -u_radius; k <= u_radius; k++) sum += moments_at(clamp(px + k * step, ivec2(0), last));
    o_moments = sum / float(2 * u_radius + 1);
}
