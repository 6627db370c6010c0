/* Deferred shadow mask: camera depth (and optional world normals) in,
   visibility out (1 lit, 0 shadowed), one value per pixel in an R16F target.
   World positions are reconstructed from window depth exactly as the
   reference does: NDC from the pixel centre and 2*depth - 1 (the
   camera's convention: u_depth_map), inverse view-projection, w-divide. */
in vec2 v_uv;
out float o_visibility;
uniform sampler2D u_depth;
uniform sampler2D u_normals;
uniform int u_has_normals;
uniform mat4 u_camera[2];           /* [0]: inverse view-projection, [1]: view (one upload) */
uniform vec4 u_depth_map;           /* the camera's depth convention (skgl_camera): NDC z = d * x + y;
                                      z: the near plane's depth (1 with reverse-Z), w: a far depth
                                      on every pixel's ray (0.5 when the far plane is at infinity) */
void main()
{
    ivec2 px = ivec2(gl_FragCoord.xy);
    float d = texelFetch(u_depth, px, 0).r;
    bool background = u_depth_map.z == 0.0 ? d >= 1.0 : d <= 0.0;
    /* background: done, except where sk_shadow() needs screen derivatives
       (RMSM's level of detail; the receiver's plane without normals), which
       need every pixel of a 2x2 quad (both conditions are uniform: this
       branch keeps the control flow uniform) */
    if (background && sk_rmsm == 0 && u_has_normals != 0) { o_visibility = 1.0; return; }
    vec2 ndc_xy = gl_FragCoord.xy / vec2(textureSize(u_depth, 0)) * 2.0 - 1.0;
    vec4 w = u_camera[0] * vec4(ndc_xy, d * u_depth_map.x + u_depth_map.y, 1.0);
    vec3 world = w.xyz / w.w;
    /* the position four float ulps of depth away: the receiver's uncertainty */
    vec4 w2 = u_camera[0] * vec4(ndc_xy, (d + 4.0 * d / 8388608.0) * u_depth_map.x + u_depth_map.y, 1.0);
    sk_receiver_slack = distance(w2.xyz / w2.w, world);
    vec3 n = u_has_normals != 0 ? normalize(texelFetch(u_normals, px, 0).xyz) : vec3(0.0);
    float view_depth = -(u_camera[1] * vec4(world, 1.0)).z;
    float v = sk_shadow(world, n, view_depth);
    o_visibility = background ? 1.0 : v;
}
