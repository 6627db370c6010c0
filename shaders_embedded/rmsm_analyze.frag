/* RMSM page analysis, per pixel (after Lefohn, Sengupta and Owens 2007): the
   world point from window depth, its coordinates (s, t) in the virtual
   shadow map of u_virtual_res^2 texels, and the level of detail
   lod = log2(sqrt(|dX x dY|)) from the screen derivatives of the texel
   coordinates (sk_rmsm_lod). The derivatives are those the lookup in
   shadow_sample.glsl takes, so both choose the same page.
   Out: (s, t, lod, 1), or 0 where nothing needs the map. */
uniform sampler2D u_depth;
uniform mat4 u_inv_view_proj;
uniform mat4 u_light;            /* world -> the virtual map's light clip */
uniform float u_virtual_res;
uniform vec4 u_depth_map;           /* the camera's depth convention (skgl_camera): NDC z = d * x + y;
                                      z: the near plane's depth (1 with reverse-Z), w: a far depth
                                      on every pixel's ray (0.5 when the far plane is at infinity) */
out vec4 o_sample;
void main()
{
    ivec2 px = ivec2(gl_FragCoord.xy);
    float d = texelFetch(u_depth, px, 0).r;
    vec2 ndc_xy = gl_FragCoord.xy / vec2(textureSize(u_depth, 0)) * 2.0 - 1.0;
    vec4 w = u_inv_view_proj * vec4(ndc_xy, d * u_depth_map.x + u_depth_map.y, 1.0);
    vec4 c = u_light * vec4(w.xyz / w.w, 1.0);
    vec2 st = c.xy / c.w * 0.5 + 0.5;
    /* derivatives first, in uniform control flow */
    vec2 dx = dFdx(st) * u_virtual_res, dy = dFdy(st) * u_virtual_res;
    float tr = dot(dx, dx) + dot(dy, dy), det = abs(dx.x * dy.y - dx.y * dy.x);
    float lod = log2(max(det / max(sqrt(0.5 * (tr + sqrt(max(tr * tr - 4.0 * det * det, 0.0)))), 1e-30), 1e-30));
    bool ok = (u_depth_map.z == 0.0 ? d < 1.0 : d > 0.0) && all(greaterThanEqual(st, vec2(0.0))) && all(lessThan(st, vec2(1.0))) &&
              abs(c.z) <= c.w;
    o_sample = ok ? vec4(st, lod, 1.0) : vec4(0.0);
}
