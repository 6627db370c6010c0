/* EVSM moments (exponential variance shadow maps: Lauritzen and McCool
   2008, "Layered Variance Shadow Maps", Sec. 4, the exponential warp with
   a positive and a negative exponent). One separable box filter in two
   passes over a layer of the light's map: the horizontal pass reads the
   depth layer, warps each texel's depth x = 2 z - 1 into
   (exp(c+ x), exp(c+ x)^2, -exp(-c- x), exp(-c- x)^2) and averages them
   along a row; the vertical pass (SK_EVSM_VERTICAL) averages those along a
   column into the layer of the moments array. The box is 2 u_box.x map
   texels wide (2r+1 for a blur of r), each texel weighed by the part of it
   the box covers, and it is evaluated every u_box.y map texels only (the
   output texel i at (i + 0.5) u_box.y): a wide box at a coarse spacing
   reads about as many texels per map texel as a narrow one at the map's
   own, and the receiver's bilinear tap fills in between. Reads clamp to
   the texels this frame rendered (u_extent). Two draws per layer whatever
   the width. */
in vec2 v_uv;
out vec4 o_moments;
uniform vec2 u_box;                 /* x: the box's half-width, y: the output spacing, in map texels */
uniform vec2 u_extent;              /* the rendered region, in texels of the pass's source */
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
    int i = px.y;
    ivec2 step = ivec2(0, 1);
#else
    int i = px.x;
    ivec2 step = ivec2(1, 0);
#endif
    /* the box [lo, hi] along the pass's axis; texel j spans [j, j + 1] */
    float c = (float(i) + 0.5) * u_box.y, lo = c - u_box.x, hi = c + u_box.x;
    int first = int(floor(lo)), end = int(ceil(hi));
    ivec2 row = px - i * step;
    vec4 sum = vec4(0.0);
    for (int j = first; j < end; j++) {
        float w = min(hi, float(j + 1)) - max(lo, float(j));
        sum += w * moments_at(clamp(row + j * step, ivec2(0), last));
    }
    o_moments = sum / (hi - lo);
}
