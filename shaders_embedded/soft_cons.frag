/* PVSM step 2: window depth into two R32F targets, both MIN-blended (no
   depth test): o_cons every texel the grown triangle touches (level 0 of
   the blocker-search pyramid), o_true only texels whose centre the
   original triangle covers (the plain map, for the average blocker
   depth); overfill outside the grown bounding box discarded. A caster
   program's fragment hook may discard first (an alpha test). */
flat in vec4 g_box;
flat in vec3 g_edge[3];
layout(location = 0) out vec4 o_cons;
layout(location = 1) out vec4 o_true;
layout(location = 2) out vec4 o_cons_copy;   /* skgl_soft's low_copy[0], where it has one */
void main()
{
#ifdef SKGL_CASTER_FRAGMENT
    skgl_caster_fragment();
#endif
    vec2 p = gl_FragCoord.xy;
    if (any(lessThan(p, g_box.xy)) || any(greaterThan(p, g_box.zw))) discard;
    bool inside = dot(p, g_edge[0].xy) <= g_edge[0].z && dot(p, g_edge[1].xy) <= g_edge[1].z &&
                  dot(p, g_edge[2].xy) <= g_edge[2].z;
    o_cons = vec4(gl_FragCoord.z);
    o_true = vec4(inside ? gl_FragCoord.z : 1.0);
    o_cons_copy = o_cons;
}
