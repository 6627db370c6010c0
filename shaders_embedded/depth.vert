/* Depth-only pass: shadow maps of every technique. skgl_model is set per
   object through skgl_set_model(). A caster program (skgl_caster_create)
   defines SKGL_CASTER and its own skgl_caster_position(); without one,
   attribute 0 is the position. SKGL_LAYERED (layered.geom follows): the
   world position relative to the light's origin, for every layer at once. */
#ifndef SKGL_CASTER
layout(location = 0) in vec3 a_position;
vec4 skgl_caster_position() { return vec4(a_position, 1.0); }
#endif
uniform mat4 skgl_view_proj;
uniform mat4 skgl_model;
void main()
{
#ifdef SKGL_LAYERED
    gl_Position = skgl_model * skgl_caster_position();   /* layered.geom applies each layer's matrix */
#else
    gl_Position = skgl_view_proj * (skgl_model * skgl_caster_position());
#endif
}
