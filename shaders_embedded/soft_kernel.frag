/* PVSM steps 3 and the first half of 4 (Sec. 4 to 5.1): per pixel, the
   blocker search on the conservative low-resolution map's MIN pyramid, the
   filter s_alpha from the average blocker depth, its convolution with the
   warped pixel footprint (appendix), and the predicted texel size (Eqs. 4
   and 5). Background pixels are discarded (the target keeps its clear
   state 0; the SMTG pass counts the covered pixels from it).
   o_kernel: u_h.x, u_h.y, v_h.y (v_h.x is 0), state
             (1 fully lit, 2 in penumbra or umbra: filter, 3 faces away: 0)
   o_pred:   NDC x, y on the base map, r0, r1 (Eq. 5, clip units per texel)
   o_plane:  window depth, its NDC gradient, tolerance */
in vec2 v_uv;
layout(location = 0) out vec4 o_kernel;
layout(location = 1) out vec4 o_pred;
layout(location = 2) out vec4 o_plane;
uniform sampler2D u_lowres;       /* R32F MIN pyramid of the low-res map's window depth (conservative) */
uniform sampler2D u_lowres_true;  /* R32F, the same map rasterised plainly */
uniform int u_lowres_size;
uniform int u_lowres_levels;
uniform int u_blocker_cells;      /* per axis */
uniform int u_static_scene;
uniform int u_hard;               /* zero-size light: the 1:1 criterion */
uniform float u_res_scale;        /* predicted resolutions times this */
uniform float u_antialias;        /* 1: the filter is h, the pixel footprint included (Sec. 4.2);
                                     0: the filter is s_alpha alone (point samples) */

float sk_rho(float n)
{
    /* Shen et al. 2011, Sec. 5.1, clamped at the cubic's peak as sk_rho_dynamic/static */
    float x = log2(max(n, 1.0));
    if (u_static_scene != 0) {
        x = min(x, 10.6085);
        return 0.5477 + x * (1.406 + x * (-0.04687 - 0.003944 * x));
    }
    x = min(x, 10.6262);
    return 0.667 + x * (0.7794 + x * (0.3967 - 0.02716 * x));
}

void main()
{
    ivec2 px = ivec2(gl_FragCoord.xy);
    float d = texelFetch(u_depth, px, 0).r;
    if (u_depth_map.z == 0.0 ? d >= 1.0 : d <= 0.0) discard;
    sk_receiver r = sk_receiver_at(px, d);
    float tol = sk_light_tolerance(max(r.zlin, 1e-6));
    o_plane = vec4(r.light.z, r.grad, tol);
    o_pred = vec4(r.light.xy, 1e30, 1e30);
    if (r.light.w <= 0.0 || any(greaterThan(abs(r.light.xy), vec2(1.0))) || r.light.z > 1.0) {
        o_kernel = vec4(0.0, 0.0, 0.0, 1.0);      /* outside the light's frustum: lit */
        return;
    }
    if (!r.facing) { o_kernel = vec4(0.0, 0.0, 0.0, 3.0); return; }

    /* blocker search region: the pyramid from the receiver to the light cut
       by the near plane, grown by the footprint */
    /* the near plane is the nearest the bounds come; the casters over this
       receiver may be much farther: the region's own minimum (coarse levels
       of the pyramid) moves the cut down, which only shrinks the region */
    float zs = u_light_proj.z;
    for (int it = 0; it < 3; it++) {
        vec2 reg = sk_filter_half(r.zlin, zs) + abs(r.du) + abs(r.dv);
        float t = max(reg.x, reg.y) * float(u_lowres_size);
        int lv = clamp(int(ceil(log2(max(t, 1.0)))), 0, u_lowres_levels - 1);
        int nc = max(u_lowres_size >> lv, 1);
        float cz = 2.0 / float(nc);
        ivec2 a = clamp(ivec2(floor((r.light.xy - reg + 1.0) / cz)), ivec2(0), ivec2(nc - 1));
        ivec2 b = clamp(ivec2(floor((r.light.xy + reg + 1.0) / cz)), ivec2(0), ivec2(nc - 1));
        float m = 1.0;
        for (int y = a.y; y <= b.y; y++)
            for (int x = a.x; x <= b.x; x++)
                m = min(m, texelFetch(u_lowres, ivec2(x, y), lv).r);
        /* nothing in the cells nearer than the receiver's plane anywhere
           over them: no blocker, fully lit (most pixels end here). Texels
           left at the clear depth 1 hold nothing: a steep receiver's plane
           carried across the region can pass the far plane (> 1), and
           must not make empty texels blockers, here and below */
        if (it == 0 && m >= min(r.light.z + abs(r.grad.x) * (reg.x + cz) + abs(r.grad.y) * (reg.y + cz) - tol, 1.0)) {
            o_kernel = vec4(0.0, 0.0, 0.0, 1.0);
            return;
        }
        float zm = clamp(sk_light_linear(m), zs, r.zlin);
        if (zm <= zs * 1.001) break;
        zs = zm;
    }
    vec2 region = sk_filter_half(r.zlin, zs) + abs(r.du) + abs(r.dv);
    float texels = max(region.x, region.y) * float(u_lowres_size);   /* full width in texels */
    int level = clamp(int(ceil(log2(max(texels / float(u_blocker_cells), 1.0)))), 0, u_lowres_levels - 1);
    int cells = max(u_lowres_size >> level, 1);
    float cs = 2.0 / float(cells);                 /* cell side in NDC */
    ivec2 c0 = clamp(ivec2(floor((r.light.xy - region + 1.0) / cs)), ivec2(0), ivec2(cells - 1));
    ivec2 c1 = clamp(ivec2(floor((r.light.xy + region + 1.0) / cs)), ivec2(0), ivec2(cells - 1));
    /* the plane's lowest depth over the cell, and over the half texel the
       conservative rasteriser extends a triangle past its edges */
    float slack = (abs(r.grad.x) + abs(r.grad.y)) * (cs * 0.5 + 1.0 / float(u_lowres_size)) + tol;
    float sum = 0.0, count = 0.0;
    for (int y = c0.y; y <= c1.y; y++)
        for (int x = c0.x; x <= c1.x; x++) {
            vec2 centre = (vec2(x, y) + 0.5) * cs - 1.0;
            float m = texelFetch(u_lowres, ivec2(x, y), level).r;
            float plane = r.light.z + dot(r.grad, centre - r.light.xy) - slack;
            if (m < min(plane, 1.0)) { sum += sk_light_linear(m); count += 1.0; }
        }
    if (count == 0.0) { o_kernel = vec4(0.0, 0.0, 0.0, 1.0); return; }   /* fully lit */
    /* the cells' minima decide "fully lit" conservatively but pull the
       average towards the nearest blocker of each cell: the average comes
       from point samples of the plainly rasterised map (no grown borders
       with their extended depths), or of the conservative one when that
       finds none (casters thinner than a texel) */
    {
        float nb = float(u_blocker_cells);
        float pslack = (abs(r.grad.x) + abs(r.grad.y)) * 2.0 / float(u_lowres_size) + tol;
        vec2 ps = vec2(0.0), pc = vec2(0.0);      /* plain, conservative */
        for (int y = 0; y < u_blocker_cells; y++)
            for (int x = 0; x < u_blocker_cells; x++) {
                vec2 o = ((vec2(x, y) + 0.5) / nb * 2.0 - 1.0) * region;
                ivec2 t = clamp(ivec2((r.light.xy + o + 1.0) * 0.5 * float(u_lowres_size)), ivec2(0),
                                ivec2(u_lowres_size - 1));
                float plane = r.light.z + dot(r.grad, o) - pslack;
                float mt = texelFetch(u_lowres_true, t, 0).r, mc = texelFetch(u_lowres, t, 0).r;
                if (mt < min(plane, 1.0)) { ps.x += sk_light_linear(mt); pc.x += 1.0; }
                if (mc < min(plane, 1.0)) { ps.y += sk_light_linear(mc); pc.y += 1.0; }
            }
        if (pc.x > 0.0) { sum = ps.x; count = pc.x; }
        else if (pc.y > 0.0) { sum = ps.y; count = pc.y; }
    }
    float zo = min(sum / count, r.zlin);
    vec2 s = u_hard != 0 ? vec2(0.0) : sk_filter_half(r.zlin, zo);
    /* appendix: V_h = M_s M_s^T + M_phi M_phi^T, Cholesky columns */
    float m00 = s.x * s.x + r.du.x * r.du.x + r.dv.x * r.dv.x;
    float m10 = r.du.x * r.du.y + r.dv.x * r.dv.y;
    float m11 = s.y * s.y + r.du.y * r.du.y + r.dv.y * r.dv.y;
    float ux = sqrt(max(m00, 1e-20));
    float uy = m10 / ux;
    float vy = sqrt(max(m11 - uy * uy, 1e-20));
    /* the prediction always sizes h; without anti-aliasing the filter is s_alpha alone */
    o_kernel = u_antialias > 0.0 ? vec4(ux, uy, vy, 2.0) : vec4(max(s.x, 1e-10), 0.0, max(s.y, 1e-10), 2.0);

    /* Eq. (4): kernel size in pixels along e0, e1 through M_phi^-1; Eq. (5) */
    float det = r.du.x * r.dv.y - r.dv.x * r.du.y;
    float n0 = abs(det) > 1e-20 ? ux * length(vec2(r.dv.y, r.du.y)) / abs(det) : 1e30;
    float n1 = abs(det) > 1e-20 ? vy * length(vec2(r.dv.x, r.du.x)) / abs(det) : 1e30;
    float rho0 = u_hard != 0 ? 1.0 : sk_rho(n0);
    float rho1 = u_hard != 0 ? 1.0 : sk_rho(n1);
    vec2 r_k = vec2(2.0 * ux / rho0, 2.0 * vy / rho1);
    /* a receiver the light grazes has a footprint one pixel thin along one
       axis of the map and long along the other; its demand along the thin
       axis would cut the grid into slivers of tiles: at most 8:1 */
    r_k = max(r_k, vec2(max(r_k.x, r_k.y) / 8.0));
    o_pred.zw = r_k / u_res_scale;
}
