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
uniform vec4 u_contact;             /* contact shadows (desc.contact_length): x the march's length in
                                      world units (0: off), y its steps, z the thickness */
uniform mat4 u_view_proj;           /* the camera's view-projection, the inverse of u_camera[0] */

vec3 mask_world(ivec2 px, float d)
{
    vec2 ndc_xy = (vec2(px) + 0.5) / vec2(textureSize(u_depth, 0)) * 2.0 - 1.0;
    vec4 w = u_camera[0] * vec4(ndc_xy, d * u_depth_map.x + u_depth_map.y, 1.0);
    return w.xyz / w.w;
}

float mask_view_depth(vec3 world) { return -(u_camera[1] * vec4(world, 1.0)).z; }

/* one pixel's view-depth step across the receiver: the largest one-sided
   difference to its four neighbours (those inside the frame). At a depth
   edge it is the jump, which turns the march off on the edge's pixels,
   where the buffer's rounding to pixel centres is widest; at a caster's
   foot the depth is continuous and the step small. */
float receiver_depth_step(ivec2 px, float z)
{
    ivec2 last = textureSize(u_depth, 0) - 1;
    float g = 0.0;
    for (int a = 0; a < 2; a++) {
        ivec2 e = ivec2(1 - a, a);
        ivec2 lo = clamp(px - e, ivec2(0), last), hi = clamp(px + e, ivec2(0), last);
        float dl = abs(mask_view_depth(mask_world(lo, texelFetch(u_depth, lo, 0).r)) - z);
        float dh = abs(mask_view_depth(mask_world(hi, texelFetch(u_depth, hi, 0).r)) - z);
        g = max(g, max(lo == px ? 0.0 : dl, hi == px ? 0.0 : dh));
    }
    return g;
}

/* Contact shadows: a short march from the receiver toward the light through
   the depth buffer (screen-space ray marching, as in McGuire and Mara 2014's
   depth-buffer ray casting with a constant thickness). A sample is blocked
   when the buffer's surface at its pixel lies in front of it by less than
   the thickness (a thin caster throws no endless shadow behind it) and is
   not the receiver's own surface. A pixel centre off the sample's exact
   position on a plane the camera grazes lies far in front of or behind the
   sample, so depth alone cannot tell the receiver's ground from a caster;
   with normals, planes can: the buffer's point must lie off the receiver's
   plane by more than 1/1000 of the view depth, and the sample must not lie
   in front of the buffer surface's own plane (the foot of a lit wall
   marching out over the ground). Without normals the buffer must lie in
   front by more than two of the receiver's pixel depth steps.
   0 blocked, 1 clear. */
float contact_visibility(vec3 world, vec3 n, ivec2 px, float z)
{
    vec2 size = vec2(textureSize(u_depth, 0));
    bool plane = u_has_normals != 0;
    float tol = plane ? sk_receiver_slack : 2.0 * receiver_depth_step(px, z) + sk_receiver_slack;
    float plane_tol = 1e-3 * z + sk_receiver_slack;
    int steps = int(u_contact.y);
    for (int i = 1; i <= steps; i++) {
        vec3 p = world - sk_light_dir * (u_contact.x * float(i) / float(steps));
        vec4 c = u_view_proj * vec4(p, 1.0);
        if (c.w <= 0.0) break;
        vec2 win = (c.xy / c.w * 0.5 + 0.5) * size;
        if (any(lessThan(win, vec2(0.0))) || any(greaterThanEqual(win, size))) break;
        ivec2 q = ivec2(win);
        vec3 b = mask_world(q, texelFetch(u_depth, q, 0).r);
        float in_front = mask_view_depth(p) - mask_view_depth(b);
        if (in_front <= tol || in_front >= u_contact.z) continue;
        if (!plane) return 0.0;
        if (dot(b - world, n) > plane_tol && dot(b - p, normalize(texelFetch(u_normals, q, 0).xyz)) >= 0.0)
            return 0.0;
    }
    return 1.0;
}

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
    if (u_contact.x > 0.0 && !background && v > 0.0) v = min(v, contact_visibility(world, n, px, view_depth));
    o_visibility = background ? 1.0 : v;
}
