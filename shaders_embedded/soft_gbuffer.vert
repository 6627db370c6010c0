/* Area-light shadows without a user G-buffer: the camera's depth and
   world normals rendered through the draw callback (a caster program's
   skgl_caster_position() in place of attribute 0, as in depth.vert). */
#ifndef SKGL_CASTER
layout(location = 0) in vec3 a_position;
vec4 skgl_caster_position() { return vec4(a_position, 1.0); }
#endif
uniform mat4 skgl_view_proj;
uniform mat4 skgl_model;
out vec3 skgl_world;
void main()
{
    vec4 skgl_w = skgl_model * skgl_caster_position();
    skgl_world = skgl_w.xyz / skgl_w.w;
    gl_Position = skgl_view_proj * skgl_w;
}
