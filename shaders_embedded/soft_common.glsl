/* Area-light soft shadows (Shen et al. 2011): what the kernel-shape pass and the
   PCSS mask share. The light is a rectangle at u_light_pos facing along
   the -z axis of its view (sk_mat4_look_at); its shadow maps are
   perspective projections from the rectangle's centre (u_light_vp, the
   base frustum; PVSM tiles are crops of it, which keep its depth).
   Kernels and footprints are in the base frustum's NDC (clip units,
   2 across a map), depths in window units [0,1]. */
uniform sampler2D u_depth;        /* camera window depth */
uniform sampler2D u_normals;      /* world normals in .xyz */
uniform int u_has_normals;
uniform mat4 u_inv_view_proj;
uniform mat4 u_light_vp;
uniform vec3 u_light_pos;
uniform vec2 u_light_half;        /* world half sizes along the light's x and y */
uniform vec4 u_light_proj;        /* P00, P11, near, far of the base frustum */
uniform float u_rel_bias;         /* comparison tolerance, relative to the light distance */
uniform vec4 u_depth_map;           /* the camera's depth convention (skgl_camera): NDC z = d * x + y;
                                      z: the near plane's depth (1 with reverse-Z), w: a far depth
                                      on every pixel's ray (0.5 when the far plane is at infinity) */

vec3 sk_unproject(vec2 frag, float d)
{
    vec2 ndc = frag / vec2(textureSize(u_depth, 0)) * 2.0 - 1.0;
    vec4 w = u_inv_view_proj * vec4(ndc, d * u_depth_map.x + u_depth_map.y, 1.0);
    return w.xyz / w.w;
}

/* eye distance along the light's axis from window depth */
float sk_light_linear(float win)
{
    float n = u_light_proj.z, f = u_light_proj.w, z = win * 2.0 - 1.0;
    return 2.0 * n * f / ((f + n) - z * (f - n));
}

/* the light's window-depth tolerance at eye distance z: u_rel_bias * z,
   through d(win)/dz = n f / ((f - n) z^2) */
float sk_light_tolerance(float z)
{
    float n = u_light_proj.z, f = u_light_proj.w;
    return u_rel_bias * n * f / ((f - n) * z);
}

/* base-frustum NDC xy and window depth of a world point; w <= 0: behind */
vec4 sk_light_project(vec3 p)
{
    vec4 c = u_light_vp * vec4(p, 1.0);
    if (c.w <= 1e-12) return vec4(0.0, 0.0, 0.0, -1.0);
    vec3 ndc = c.xyz / c.w;
    return vec4(ndc.xy, ndc.z * 0.5 + 0.5, c.w);
}

/* the receiver of one pixel, seen from the light */
struct sk_receiver {
    vec3 world, normal;
    vec4 light;       /* ndc xy, window depth, clip w (<= 0: behind the light) */
    vec2 du, dv;      /* half-axes of the pixel footprint on the map (Fig. 5) */
    vec2 grad;        /* window depth per NDC unit along the receiver's plane */
    float zlin;       /* distance along the light's axis */
    bool facing;      /* the receiver faces the light's centre */
};

vec3 sk_gbuffer_normal(ivec2 px, vec3 world, float d)
{
    if (u_has_normals != 0) {
        vec3 n = texelFetch(u_normals, px, 0).xyz;
        if (dot(n, n) > 0.0) return normalize(n);
    }
    /* none given: the plane through the neighbours on the nearer side */
    ivec2 size = textureSize(u_depth, 0);
    ivec2 pxr = ivec2(min(px.x + 1, size.x - 1), px.y), pxl = ivec2(max(px.x - 1, 0), px.y);
    ivec2 pyu = ivec2(px.x, min(px.y + 1, size.y - 1)), pyd = ivec2(px.x, max(px.y - 1, 0));
    float dr = texelFetch(u_depth, pxr, 0).r, dl = texelFetch(u_depth, pxl, 0).r;
    float du_ = texelFetch(u_depth, pyu, 0).r, dd = texelFetch(u_depth, pyd, 0).r;
    vec3 ex = abs(dr - d) < abs(dl - d) ? sk_unproject(vec2(pxr) + 0.5, dr) - world
                                        : world - sk_unproject(vec2(pxl) + 0.5, dl);
    vec3 ey = abs(du_ - d) < abs(dd - d) ? sk_unproject(vec2(pyu) + 0.5, du_) - world
                                         : world - sk_unproject(vec2(pyd) + 0.5, dd);
    vec3 n = cross(ex, ey);
    return dot(n, n) > 0.0 ? normalize(n) : vec3(0.0);
}

/* where the ray through a screen point meets the receiver's tangent plane
   (the affine approximation of the mapping M, Sec. 4.2) */
vec3 sk_on_plane(vec2 frag, vec3 p, vec3 n)
{
    /* the ray from the near plane to the far one (to a point on it when the far plane is at infinity) */
    vec3 o = sk_unproject(frag, u_depth_map.z), e = sk_unproject(frag, u_depth_map.w), dir = e - o;
    float den = dot(n, dir);
    if (abs(den) < 1e-6 * length(dir)) return p;
    float t = dot(n, p - o) / den;
    return o + clamp(t, 0.0, u_depth_map.z + u_depth_map.w == 1.0 ? 1.0 : 1e30) * dir;
}

sk_receiver sk_receiver_at(ivec2 px, float d)
{
    sk_receiver r;
    vec2 frag = vec2(px) + 0.5;
    r.world = sk_unproject(frag, d);
    r.normal = sk_gbuffer_normal(px, r.world, d);
    r.light = sk_light_project(r.world);
    r.zlin = r.light.w;
    r.facing = dot(r.normal, r.normal) == 0.0 || dot(r.normal, u_light_pos - r.world) > 0.0;
    r.du = vec2(0.0); r.dv = vec2(0.0); r.grad = vec2(0.0);
    if (r.light.w <= 0.0 || dot(r.normal, r.normal) == 0.0) return r;
    vec4 lx = sk_light_project(sk_on_plane(frag + vec2(1.0, 0.0), r.world, r.normal));
    vec4 ly = sk_light_project(sk_on_plane(frag + vec2(0.0, 1.0), r.world, r.normal));
    if (lx.w <= 0.0 || ly.w <= 0.0) return r;
    /* a grazing view stretches the footprint without bound: cap it */
    vec2 ax = clamp(lx.xy - r.light.xy, vec2(-0.25), vec2(0.25));
    vec2 ay = clamp(ly.xy - r.light.xy, vec2(-0.25), vec2(0.25));
    r.du = 0.5 * ax;
    r.dv = 0.5 * ay;
    /* window depth is affine in NDC over a plane: solve [ax; ay] g = dz */
    float det = ax.x * ay.y - ax.y * ay.x;
    if (abs(det) > 1e-14) {
        float zx = lx.z - r.light.z, zy = ly.z - r.light.z;
        r.grad = vec2(zx * ay.y - zy * ax.y, ax.x * zy - ay.x * zx) / det;
    }
    return r;
}

/* Sec. 4: the soft shadowing filter s_alpha on the map plane for a blocker
   at distance zo, as half-axes (light rectangle aligned with the map) */
vec2 sk_filter_half(float zy, float zo)
{
    float k = max(zy - zo, 0.0) / (zy * zo);
    return vec2(u_light_proj.x * u_light_half.x, u_light_proj.y * u_light_half.y) * k;
}
