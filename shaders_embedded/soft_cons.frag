/* PVSM step 2: window depth into two R32F targets, both MIN-blended (no
   depth test): skgl_cons every texel the grown triangle touches (level 0 of
   the blocker-search pyramid), skgl_true only texels whose centre the
   original triangle covers (the plain map, for the average blocker
   depth); overfill outside the grown bounding box discarded. A caster
   program's fragment hook may discard first (an alpha test); every name
   declared here starts with skgl_, reserved in the hooks. */
flat in vec4 skgl_box;
flat in vec3 skgl_edge[3];
layout(location = 0) out vec4 skgl_cons;
layout(location = 1) out vec4 skgl_true;
layout(location = 2) out vec4 skgl_cons_copy;   /* skgl_soft's low_copy[0], where it has one */
void main()
{
#ifdef SKGL_CASTER_FRAGMENT
    skgl_caster_fragment();
#endif
    vec2 skgl_p = gl_FragCoord.xy;
    if (any(lessThan(skgl_p, skgl_box.xy)) || any(greaterThan(skgl_p, skgl_box.zw))) discard;
    bool skgl_inside = dot(skgl_p, skgl_edge[0].xy) <= skgl_edge[0].z &&
                       dot(skgl_p, skgl_edge[1].xy) <= skgl_edge[1].z &&
                       dot(skgl_p, skgl_edge[2].xy) <= skgl_edge[2].z;
    skgl_cons = vec4(gl_FragCoord.z);
    skgl_true = vec4(skgl_inside ? gl_FragCoord.z : 1.0);
    skgl_cons_copy = skgl_cons;
}
