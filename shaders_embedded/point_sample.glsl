/* shadowkit: point-light (omnidirectional) shadow lookup, shared by the
   deferred point mask pass and forward shaders (skgl_point_glsl_snippet()).
   King & Newhall 2004.

   Two storages, chosen at compile time: define SK_POINT_VSDCT 1 before this
   text for the Virtual Shadow Depth Cube Texture, leave it undefined (or 0)
   for the native depth cube map.
   - cube: GL_TEXTURE_CUBE_MAP of depth, samplerCubeShadow looked up with the
     light-to-point vector; hardware 2x2 comparison (seamless cube filtering
     when GL_TEXTURE_CUBE_MAP_SEAMLESS is on, as the mask pass sets it).
   - VSDCT: the six faces as sub-rects of one 2D depth atlas; an RG16
     indirection cube map, bilinearly filtered, turns the direction into the
     atlas (u, v) (face selection, side divide, (s, t) remap, scale and face
     offset in one lookup, King & Newhall Fig. 5.4.7), kept half a texel inside the
     face so a 2x2 comparison never reads across a seam (King & Newhall: "Sampling
     across Cube Map Seams"); then sampler2DShadow in the atlas. Where RG16
     textures are missing (OpenGL ES 3.0, WebGL2), SK_POINT_VSDCT_ANALYTIC 1
     computes the same (u, v) in the shader (the indirection is not used).
   Both store window depth per Eq. (5.4.6): z = scale / MA + bias, MA the
   major-axis component of the light-to-point vector (the eye depth in the
   face that holds it), so both compare the same way.

   Bias (sk_point_bias_mode): 0, the receiver plane (the default): each tap
   compares the depth that the receiver's tangent plane has along the tap's
   own direction (where that ray meets the plane), less the plane's depth
   change over the one texel a hardware 2x2 comparison reaches in each face
   axis, times (1 + sk_point_plane_bias); the receiver is not moved, so no
   shadow is displaced (after Dou, Yan, Kerzner, Dai and Wyman 2014). 1,
   normal offset: the receiver is pushed along its normal by
   sk_point_normal_bias texels of its face at its distance (a face texel is
   2 MA / resolution wide), which moves shadow edges toward the light. In
   both, casters were drawn with slope-scaled polygon offset. Filtering: one
   hardware 2x2 comparison, or a (2r)x(2r) grid of them spaced one texel in
   the face plane; a tap that leaves the face reads the neighbouring face
   (its direction picks it), compared with the receiver's depth along that
   face's axis. A surface facing away from the light (given a normal) is in
   its own shadow: 0. Beyond sk_point_range: 1 (no shadow from this light;
   attenuation is the shader's business).

   Spot lights (SK_POINT_SPOT 1, which implies SK_POINT_VSDCT 1): one perspective
   map down the spot's axis in sk_point_faces[0]'s rectangle of the atlas,
   sk_point_spot (light-relative position -> the map's clip space) and
   sk_point_basis (the map's right, up and axis) in place of the six faces;
   MA is the depth along the axis, so Eq. (5.4.6) and both biases hold as
   they are. Outside the cone (cosine below sk_point_cos): 0, the spot
   does not light it. */
#ifndef SK_POINT_VSDCT
#define SK_POINT_VSDCT 0
#endif
#ifndef SK_POINT_SPOT
#define SK_POINT_SPOT 0
#endif
#if SK_POINT_SPOT   /* a spot's map lives in a VSDCT atlas */
#undef SK_POINT_VSDCT
#define SK_POINT_VSDCT 1
#endif
#ifndef SK_POINT_VSDCT_ANALYTIC
#define SK_POINT_VSDCT_ANALYTIC 0
#endif
uniform vec3 sk_point_pos;          /* light position, world */
uniform float sk_point_range;       /* far plane of the faces */
uniform vec2 sk_point_depth;        /* Eq. (5.4.6): (scale, bias) of sk_vsdct_depth_coeffs */
uniform float sk_point_texel;       /* 2 / face resolution: one texel at MA = 1 */
uniform float sk_point_normal_bias; /* texels (mode 1; mode 0 adds it if > 0) */
uniform int sk_point_bias_mode;     /* 0 receiver plane, 1 normal offset */
uniform float sk_point_plane_bias;  /* mode 0: extra tolerance, in texels of the plane's depth slope */
/* How far (world units) the receiver position may lie from the true
   surface: the deferred mask sets it from its depth buffer's precision
   before calling sk_point_shadow(); 0 for a forward shader's positions */
float sk_point_receiver_slack = 0.0;
uniform int sk_point_pcf;           /* 0: one 2x2 comparison; r: (2r)^2 of them */
#if SK_POINT_VSDCT
uniform highp sampler2DShadow sk_point_atlas;
uniform highp samplerCube sk_point_indirection;
uniform vec4 sk_point_faces[6];     /* per face: its sub-rect inset by half a texel, (u0, v0, u1, v1) */
#else
uniform highp samplerCubeShadow sk_point_cube;
#endif
#if SK_POINT_SPOT
uniform mat4 sk_point_spot;         /* light-relative position -> the map's clip space */
uniform mat4 sk_point_basis;        /* columns: the map's right, up and axis (world), 0 */
uniform float sk_point_cos;         /* cosine of the cone's half-angle */
#endif

/* the major-axis component of |v| along the axis that d's face looks down */
float sk_point_ma(vec3 av, vec3 d)
{
    vec3 ad = abs(d);
    if (ad.x >= ad.y && ad.x >= ad.z) return av.x;
    return ad.y >= ad.z ? av.y : av.z;
}

/* MA of the light-relative point v itself: its major-axis component, or
   for a spot its depth along the axis */
float sk_point_ma_of(vec3 v)
{
#if SK_POINT_SPOT
    return dot(v, sk_point_basis[2].xyz);
#else
    vec3 av = abs(v);
    return max(av.x, max(av.y, av.z));
#endif
}

/* one hardware 2x2 comparison of depth ref along direction d */
float sk_point_tap(vec3 d, float ref)
{
#if SK_POINT_SPOT
    /* the map's clip space, into face 0's rectangle (its full extent is the
       inset one grown by half a texel), clamped inside it */
    vec4 c = sk_point_spot * vec4(d, 1.0);
    vec4 r = sk_point_faces[0];
    vec2 st = 0.5 * c.xy / c.w + 0.5;
    vec2 texel = 1.0 / vec2(textureSize(sk_point_atlas, 0));
    vec2 uv = clamp(r.xy - 0.5 * texel + st * (r.zw - r.xy + texel), r.xy, r.zw);
    return texture(sk_point_atlas, vec3(uv, ref));
#elif SK_POINT_VSDCT
    /* the indirection keeps (u, v) half a texel inside the face, but its 16
       bits round to 1/65535 of the atlas: clamped again here, in float, or
       the 2x2 filter could give a neighbouring sub-rect a sliver of weight */
    vec3 ad = abs(d);
    int f = ad.x >= ad.y && ad.x >= ad.z ? (d.x >= 0.0 ? 0 : 1) : ad.y >= ad.z ? (d.y >= 0.0 ? 2 : 3) : (d.z >= 0.0 ? 4 : 5);
    vec4 r = sk_point_faces[f];
#if SK_POINT_VSDCT_ANALYTIC
    /* the indirection's arithmetic in the shader (no RG16 texture, which
       OpenGL ES 3.0 and WebGL2 lack): (s, t) on the face's axes (the GL
       cube map convention, sk_cube_face_view's), then into the face's
       sub-rect, whose full extent is the inset one grown by half a texel */
    const vec3 sk_axis_s[6] = vec3[6](vec3(0.0, 0.0, -1.0), vec3(0.0, 0.0, 1.0), vec3(1.0, 0.0, 0.0),
                                      vec3(1.0, 0.0, 0.0), vec3(1.0, 0.0, 0.0), vec3(-1.0, 0.0, 0.0));
    const vec3 sk_axis_t[6] = vec3[6](vec3(0.0, -1.0, 0.0), vec3(0.0, -1.0, 0.0), vec3(0.0, 0.0, 1.0),
                                      vec3(0.0, 0.0, -1.0), vec3(0.0, -1.0, 0.0), vec3(0.0, -1.0, 0.0));
    float ma = max(ad.x, max(ad.y, ad.z));
    vec2 st = 0.5 * vec2(dot(sk_axis_s[f], d), dot(sk_axis_t[f], d)) / ma + 0.5;
    vec2 texel = 1.0 / vec2(textureSize(sk_point_atlas, 0));
    vec2 uv = clamp(r.xy - 0.5 * texel + st * (r.zw - r.xy + texel), r.xy, r.zw);
#else
    vec2 uv = clamp(texture(sk_point_indirection, d).rg, r.xy, r.zw);
#endif
    return texture(sk_point_atlas, vec3(uv, ref));
#else
    return texture(sk_point_cube, vec4(d, ref));
#endif
}

/* the major-axis distance (MA, Eq. 5.4.6's) at which the receiver's
   tangent plane (normal n through v, both relative to the light) meets the
   ray along direction d, the ray's distance to the plane kept within
   [1/2, 2] of v's (at grazing incidence the plane leaves the tap's
   neighbourhood) */
float sk_point_plane_ma(vec3 v, vec3 n, vec3 d)
{
    float t = dot(n, v) / dot(n, d);
    float t0 = sk_point_ma_of(v) / max(sk_point_ma_of(d), 1e-30);
    t = clamp(t, 0.5 * t0, 2.0 * t0);
    return t * sk_point_ma_of(d);
}

/* one tap along d compared with the receiver plane: the plane's window
   depth along d (Eq. 5.4.6), less its change over one texel in each face
   axis (t1, t2 of length one texel at d). The change is taken on the
   distances, |dz/dMA| = |scale| / MA^2 times the change of MA: a difference
   of two window depths near 1 would keep only a few bits (and none on GPUs
   whose division is not correctly rounded). */
float sk_point_plane_tap(vec3 v, vec3 n, vec3 d, vec3 t1, vec3 t2)
{
    float m = max(sk_point_plane_ma(v, n, d), 1e-30);
    float z = sk_point_depth.x / m + sk_point_depth.y;
    float dz_dma = abs(sk_point_depth.x) / (m * m);
    float slope = dz_dma * (abs(sk_point_plane_ma(v, n, d + t1) - m) + abs(sk_point_plane_ma(v, n, d + t2) - m));
    /* the receiver's own uncertainty: dz/dMA = -scale / MA^2 at v */
    float ma = sk_point_ma_of(v);
    float slack = abs(sk_point_depth.x) / max(ma * ma, 1e-30) * sk_point_receiver_slack;
    return sk_point_tap(d, z - (1.0 + sk_point_plane_bias) * slope - slack - 4.0e-7);
}

float sk_point_shadow(vec3 world_pos, vec3 world_normal)
{
    vec3 v = world_pos - sk_point_pos;
    float dist = length(v);
    if (!(dist > 0.0) || dist > sk_point_range) return 1.0;
    if (dot(world_normal, v) >= 0.0 && dot(world_normal, world_normal) > 0.0) return 0.0;
#if SK_POINT_SPOT
    if (dot(v, sk_point_basis[2].xyz) < sk_point_cos * dist) return 0.0;
#endif
    vec3 av = abs(v);
    float ma = sk_point_ma_of(v);
    bool plane = sk_point_bias_mode == 0 && dot(world_normal, world_normal) > 0.0;
    vec3 n = world_normal;
    if (sk_point_bias_mode == 1 || sk_point_normal_bias > 0.0)
        v += world_normal * (sk_point_normal_bias * sk_point_texel * ma);
    av = abs(v);
    ma = sk_point_ma_of(v);
    if (!(ma > 0.0)) return 1.0;
    /* the face plane's axes at v (any two axes other than the major one;
       a spot's map's right and up) */
    vec3 t1, t2;
#if SK_POINT_SPOT
    t1 = sk_point_basis[0].xyz; t2 = sk_point_basis[1].xyz;
#else
    if (av.x >= av.y && av.x >= av.z) { t1 = vec3(0.0, 0.0, 1.0); t2 = vec3(0.0, 1.0, 0.0); }
    else if (av.y >= av.z) { t1 = vec3(1.0, 0.0, 0.0); t2 = vec3(0.0, 0.0, 1.0); }
    else { t1 = vec3(1.0, 0.0, 0.0); t2 = vec3(0.0, 1.0, 0.0); }
#endif
    float step = sk_point_texel * ma;
    if (sk_point_pcf <= 0)
        return plane ? sk_point_plane_tap(v, n, v, t1 * step, t2 * step)
                     : sk_point_tap(v, sk_point_depth.x / ma + sk_point_depth.y);
    int r = sk_point_pcf;
    float sum = 0.0;
    for (int y = -r; y < r; y++)
        for (int x = -r; x < r; x++) {
            vec3 d = v + (t1 * (float(x) + 0.5) + t2 * (float(y) + 0.5)) * step;
            if (plane) {
                sum += sk_point_plane_tap(v, n, d, t1 * step, t2 * step);
            } else {
#if SK_POINT_SPOT
                float m = max(ma, 1e-30);
#else
                float m = max(sk_point_ma(av, d), 1e-30);
#endif
                sum += sk_point_tap(d, sk_point_depth.x / m + sk_point_depth.y);
            }
        }
    return sum / float(4 * r * r);
}
