/* PVSM step 8 (Sec. 4.1, 4.2, 5.2) for one tile: the smooth texel-coverage
   integration of the pixel's kernel h over the tile's map. Texels are
   quads; the semi-axis-aligned parallelogram is cut into vertical panels
   one texel wide, each taken as an axis-aligned box. Only the part of the
   kernel inside the tile counts; the output (V*A, A) is added into the
   accumulation target, so kernels spanning several tiles merge as
   V = sum(V_i A_i) / sum(A_i). Kernels wider than 24 texels are integrated
   over blocks of 2^k texels, each tested with one hardware 2x2 comparison
   at its centre (for k = 1 that covers the block), so a blocker's edge is
   resolved to a block, not a texel. A block is never larger than the texel
   the prediction asked for this pixel (o_pred.zw, Eq. 5, divided by the
   resolution scale): the tile may be finer than that (another pixel's
   demand, or a resolution scale above 1), and a block sized by the kernel
   alone (1/24 of it) would discard that resolution once rho(n) > 12 or the
   scale > 1. At most 128 blocks per axis, whatever is asked. */
in vec2 v_uv;
out vec4 o_acc;
uniform sampler2DArray u_screen;  /* layers: kernel, prediction, plane */
uniform sampler2DShadow u_tile;   /* window depth, LEQUAL comparison; the tile fills [0, res) of it */
uniform vec4 u_tile_rect;         /* NDC x0, y0, x1, y1 of the tile on the base map */
uniform vec2 u_tile_res;
void main()
{
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec4 k = texelFetch(u_screen, ivec3(px, 0), 0);
    if (k.w != 2.0) discard;
    vec4 pr = texelFetch(u_screen, ivec3(px, 1), 0);
    vec4 pl = texelFetch(u_screen, ivec3(px, 2), 0);
    float ux = k.x, uy = k.y, vy = k.z;
    vec2 c = pr.xy;
    if (c.x + ux <= u_tile_rect.x || c.x - ux >= u_tile_rect.z ||
        c.y + abs(uy) + vy <= u_tile_rect.y || c.y - abs(uy) - vy >= u_tile_rect.w)
        discard;
    vec2 scale = u_tile_res / (u_tile_rect.zw - u_tile_rect.xy);     /* texels per NDC unit */
    vec2 ct = (c - u_tile_rect.xy) * scale;
    float uxt = ux * scale.x, uyt = uy * scale.y, vyt = vy * scale.y;
    float x0 = max(ct.x - uxt, 0.0), x1 = min(ct.x + uxt, u_tile_res.x);
    float span = max(2.0 * uxt, 2.0 * vyt);
    float need = min(pr.z * scale.x, pr.w * scale.y);         /* this pixel's texel, in tile texels */
    float stride = min(exp2(max(ceil(log2(span / 24.0)), 0.0)), exp2(max(floor(log2(need)), 0.0)));
    stride = max(stride, exp2(max(ceil(log2(span / 128.0)), 0.0)));
    vec2 tex_size = vec2(textureSize(u_tile, 0));
    float slack = (abs(pl.y) / scale.x + abs(pl.z) / scale.y) * stride * 0.5 + pl.w;
    float lit = 0.0, area = 0.0;
    for (float tx = floor(x0 / stride) * stride; tx < x1; tx += stride) {
        float px0 = max(tx, x0), px1 = min(tx + stride, x1);
        if (px1 <= px0) continue;
        float a = (0.5 * (px0 + px1) - ct.x) / uxt;
        float yc = ct.y + a * uyt;
        float py0 = max(yc - vyt, 0.0), py1 = min(yc + vyt, u_tile_res.y);
        for (float ty = floor(py0 / stride) * stride; ty < py1; ty += stride) {
            float cov = (px1 - px0) * (min(ty + stride, py1) - max(ty, py0));
            if (cov <= 0.0) continue;
            vec2 t = min(vec2(tx, ty) + 0.5 * stride, u_tile_res - 0.5);
            vec2 ndc = u_tile_rect.xy + t / scale;
            float plane = pl.x + dot(pl.yz, ndc - c) - slack;
            area += cov;
            /* a plane past the far plane (> 1) must not shadow the empty texels (1) */
            lit += cov * texture(u_tile, vec3(t / tex_size, min(plane, 1.0)));
        }
    }
    if (area <= 0.0) discard;
    float a_ndc = area / (scale.x * scale.y);
    o_acc = vec4(lit / area * a_ndc, a_ndc, 0.0, 0.0);
}
