/* Resolution estimation, first pass (Ferko 2013, Sec. 3): each
   output texel covers a 4x4 block of camera pixels. Per pixel: the world
   point from its window depth, in the light's clip space; samples outside
   the light frustum are discarded (Sec. 3.1). Per kept pixel: its light-clip
   xy bounds the crop, and the axis-aligned extent of its patch, the four
   pixel corners projected with depth averaged over the pixels that share
   each corner (Sec. 3.2), gives the smallest texel the view needs; the
   corners are taken relative to the pixel centre for float precision.
   The same definition as sk_estimate_resolution on the CPU.
   Per kept pixel also its view depth, so that the same reduction gives
   the depth range the view holds (what sample distribution shadow maps
   split, Lauritzen, Salvi and Lefohn 2011).
   Out: o_bounds = (min x, min y, -max x, -max y) and
        o_patch  = (min patch width, min patch height, min view depth,
                    -max view depth); "none" is +SK_BIG in every channel. A
   MIN reduction (ferko_reduce.frag) takes both to one texel. */
uniform sampler2D u_depth;           /* window depth, row 0 at the bottom */
uniform mat4 u_ndc_to_light;         /* light view-projection * inverse camera view-projection */
uniform vec4 u_world_w;              /* row 3 of the inverse camera view-projection */
uniform int u_depth_only;            /* 1: only the bounds and the view depths (AUTO, fit_to_depth): no patch */
uniform vec4 u_view_z;               /* row 2 of the inverse camera projection: view z = dot(u_view_z, ndc) / dot(u_world_w, ndc) */
uniform vec4 u_depth_map;           /* the camera's depth convention (skgl_camera): NDC z = d * x + y;
                                      z: the near plane's depth (1 with reverse-Z), w: a far depth
                                      on every pixel's ray (0.5 when the far plane is at infinity) */
layout(location = 0) out vec4 o_bounds;
layout(location = 1) out vec4 o_patch;

const float SK_BIG = 3.0e38;

float sk_depth_at(ivec2 p, ivec2 size)
{
    if (p.x < 0 || p.y < 0 || p.x >= size.x || p.y >= size.y) return -1.0;
    float d = texelFetch(u_depth, p, 0).r;
    return d >= 0.0 && d <= 1.0 && (u_depth_map.z == 0.0 ? d < 1.0 : d > 0.0) ? d : -1.0;
}

/* light clip of NDC (x, y, z), with the sign of the homogeneous world w folded in */
vec4 sk_to_light(vec3 ndc)
{
    vec4 h = vec4(ndc, 1.0);
    vec4 l = u_ndc_to_light * h;
    float ww = dot(u_world_w, h);
    if (ww < 0.0) l = -l;
    if (ww == 0.0) l.w = 0.0;
    return l;
}

void main()
{
    ivec2 size = textureSize(u_depth, 0);
    ivec2 base = ivec2(gl_FragCoord.xy) * 4;
    vec2 to_ndc = 2.0 / vec2(size);
    float d[36];                     /* pixels base-1 .. base+4, 6 x 6 */
    float cz[25];                    /* corners base .. base+4, 5 x 5: NDC z of the averaged depth, or 2 (none) */
    vec4 b = vec4(SK_BIG), pt = vec4(SK_BIG);
    int x, y, k;
    if (u_depth_only != 0) {
        /* the 16 pixels of the block alone: no neighbours, no corners */
        for (y = 0; y < 4; y++)
            for (x = 0; x < 4; x++) {
                float dp = sk_depth_at(base + ivec2(x, y), size);
                if (dp < 0.0) continue;
                vec3 c = vec3((vec2(base + ivec2(x, y)) + 0.5) * to_ndc - 1.0, dp * u_depth_map.x + u_depth_map.y);
                float ww = dot(u_world_w, vec4(c, 1.0));
                vec4 l = sk_to_light(c);
                if (!(l.w > 0.0) || any(greaterThan(abs(l.xyz), vec3(l.w)))) continue;
                vec2 p = l.xy / l.w;
                b = min(b, vec4(p, -p));
                float depth = -dot(u_view_z, vec4(c, 1.0)) / ww;
                pt.zw = min(pt.zw, vec2(depth, -depth));
            }
        o_bounds = b;
        o_patch = pt;
        return;
    }
    for (y = 0; y < 6; y++)
        for (x = 0; x < 6; x++) d[y * 6 + x] = sk_depth_at(base + ivec2(x - 1, y - 1), size);
    for (y = 0; y < 5; y++)
        for (x = 0; x < 5; x++) {
            /* corner base + (x, y) touches pixels (x-1..x, y-1..y): d[y..y+1][x..x+1] */
            float s = 0.0, n = 0.0, v;
            v = d[y * 6 + x];           if (v >= 0.0) { s += v; n += 1.0; }
            v = d[y * 6 + x + 1];       if (v >= 0.0) { s += v; n += 1.0; }
            v = d[(y + 1) * 6 + x];     if (v >= 0.0) { s += v; n += 1.0; }
            v = d[(y + 1) * 6 + x + 1]; if (v >= 0.0) { s += v; n += 1.0; }
            cz[y * 5 + x] = n > 0.0 ? (s * (1.0 / n)) * u_depth_map.x + u_depth_map.y : 2.0;
        }
    for (y = 0; y < 4; y++)
        for (x = 0; x < 4; x++) {
            float dp = d[(y + 1) * 6 + x + 1];
            if (dp < 0.0) continue;
            vec3 c = vec3((vec2(base + ivec2(x, y)) + 0.5) * to_ndc - 1.0, dp * u_depth_map.x + u_depth_map.y);
            float ww = dot(u_world_w, vec4(c, 1.0));
            vec4 l = sk_to_light(c);
            if (!(l.w > 0.0) || any(greaterThan(abs(l.xyz), vec3(l.w)))) continue;
            vec2 p = l.xy / l.w;
            b = min(b, vec4(p, -p));
            float depth = -dot(u_view_z, vec4(c, 1.0)) / ww;
            pt.zw = min(pt.zw, vec2(depth, -depth));
            /* the patch: its four corners relative to the pixel centre,
               (C.xy P.w - P.xy C.w) / (C.w P.w) with C = P + M delta, so the
               extent comes from small differences, not from subtracting
               nearly equal light-clip positions (float has no room for that) */
            vec2 lo = vec2(SK_BIG), hi = vec2(-SK_BIG);
            bool ok = true;
            for (k = 0; k < 4; k++) {
                int kx = k & 1, ky = k >> 1, ci = (y + ky) * 5 + x + kx;
                if (cz[ci] > 1.5) { ok = false; break; }
                vec3 delta = vec3((vec2(kx, ky) - 0.5) * to_ndc, cz[ci] - c.z);
                vec4 md = u_ndc_to_light * vec4(delta, 0.0);
                float cw = dot(u_world_w, vec4(c + delta, 1.0));
                if (ww < 0.0) md = -md;
                vec4 cl = l + md;
                if (!(cl.w > 0.0) || cw * ww <= 0.0) { ok = false; break; }
                vec2 q = (md.xy * l.w - l.xy * md.w) / (cl.w * l.w);
                lo = min(lo, q);
                hi = max(hi, q);
            }
            if (ok) pt.xy = min(pt.xy, hi - lo);
        }
    o_bounds = b;
    o_patch = pt;
}
