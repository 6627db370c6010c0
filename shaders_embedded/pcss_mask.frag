/* Percentage-closer soft shadows (Fernando 2005, as in Shen et al. 2011, Sec. 4) on one
   map: a blocker search of u_blocker_cells^2 point samples over the region
   the light's pyramid cuts from the near plane, the filter s_alpha from
   the average blocker depth (Eq. 1), and PCF over it with up to
   u_pcf_taps^2 hardware 2x2 comparisons. Depths are compared against the
   receiver's plane at each sample (receiver-plane depth bias). A steep
   receiver's plane, carried across a wide kernel, can pass the far plane
   (window depth > 1): a texel the depth pass left at its clear value 1 is
   nothing, never a blocker, so blockers are m < min(plane, 1) and the
   comparison reference is clamped to 1 (DEPTH_COMPONENT32F does not clamp
   it, and 1 <= 1 is lit). */
in vec2 v_uv;
out float o_visibility;
uniform sampler2D u_map;          /* window depth, no comparison */
uniform sampler2DShadow u_map_cmp;
uniform int u_blocker_cells;
uniform int u_pcf_taps;
void main()
{
    ivec2 px = ivec2(gl_FragCoord.xy);
    float d = texelFetch(u_depth, px, 0).r;
    if (u_depth_map.z == 0.0 ? d >= 1.0 : d <= 0.0) { o_visibility = 1.0; return; }
    sk_receiver r = sk_receiver_at(px, d);
    if (r.light.w <= 0.0 || any(greaterThan(abs(r.light.xy), vec2(1.0))) || r.light.z > 1.0) {
        o_visibility = 1.0;
        return;
    }
    if (!r.facing) { o_visibility = 0.0; return; }
    float res = float(textureSize(u_map, 0).x);
    float tol = sk_light_tolerance(max(r.zlin, 1e-6));
    vec2 region = sk_filter_half(r.zlin, u_light_proj.z);
    float n = float(u_blocker_cells), sum = 0.0, count = 0.0;
    for (int y = 0; y < u_blocker_cells; y++)
        for (int x = 0; x < u_blocker_cells; x++) {
            vec2 o = ((vec2(x, y) + 0.5) / n * 2.0 - 1.0) * region;
            vec2 ndc = r.light.xy + o;
            float m = textureLod(u_map, ndc * 0.5 + 0.5, 0.0).r;
            float plane = r.light.z + dot(r.grad, o) - tol - (abs(r.grad.x) + abs(r.grad.y)) / res;
            if (m < min(plane, 1.0)) { sum += sk_light_linear(m); count += 1.0; }
        }
    if (count == 0.0) { o_visibility = 1.0; return; }
    vec2 s = sk_filter_half(r.zlin, min(sum / count, r.zlin));
    /* taps one texel apart or spread evenly over the kernel, at most u_pcf_taps per axis */
    vec2 texels = s * res;       /* half-width in texels: s NDC * res / 2, times 2 for the full width */
    ivec2 taps = clamp(ivec2(ceil(texels)) + 1, ivec2(1), ivec2(u_pcf_taps));
    float lit = 0.0;
    for (int y = 0; y < taps.y; y++)
        for (int x = 0; x < taps.x; x++) {
            vec2 f = vec2(taps.x > 1 ? float(x) / float(taps.x - 1) : 0.5,
                          taps.y > 1 ? float(y) / float(taps.y - 1) : 0.5);
            vec2 o = (f * 2.0 - 1.0) * s;
            float plane = r.light.z + dot(r.grad, o) - tol - (abs(r.grad.x) + abs(r.grad.y)) / res;
            lit += texture(u_map_cmp, vec3((r.light.xy + o) * 0.5 + 0.5, min(plane, 1.0)));
        }
    o_visibility = lit / float(taps.x * taps.y);
}
