/* Deferred point-light shadow mask: camera depth (and optional world
   normals) in, visibility out (1 lit, 0 shadowed). World positions from
   window depth exactly as shadow_mask.frag reconstructs them. The pass runs
   inside the light's scissor rectangle (sk_light_scissor) when asked: the
   pixels outside it are not written. */
in vec2 v_uv;
out float o_visibility;
uniform sampler2D u_depth;
uniform sampler2D u_normals;
uniform int u_has_normals;
uniform mat4 u_inv_view_proj;
uniform vec4 u_depth_map;           /* the camera's depth convention (skgl_camera): NDC z = d * x + y;
                                      z: the near plane's depth (1 with reverse-Z), w: a far depth
                                      on every pixel's ray (0.5 when the far plane is at infinity) */
void main()
{
    ivec2 px = ivec2(gl_FragCoord.xy);
    float d = texelFetch(u_depth, px, 0).r;
    if (u_depth_map.z == 0.0 ? d >= 1.0 : d <= 0.0) { o_visibility = 1.0; return; }
    vec2 ndc_xy = gl_FragCoord.xy / vec2(textureSize(u_depth, 0)) * 2.0 - 1.0;
    vec4 w = u_inv_view_proj * vec4(ndc_xy, d * u_depth_map.x + u_depth_map.y, 1.0);
    vec3 world = w.xyz / w.w;
    /* the position four float ulps of depth away: the receiver's uncertainty */
    vec4 w2 = u_inv_view_proj * vec4(ndc_xy, (d + 4.0 * d / 8388608.0) * u_depth_map.x + u_depth_map.y, 1.0);
    sk_point_receiver_slack = distance(w2.xyz / w2.w, world);
    vec3 n = u_has_normals != 0 ? normalize(texelFetch(u_normals, px, 0).xyz) : vec3(0.0);
    o_visibility = sk_point_shadow(world, n);
}
