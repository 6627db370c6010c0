/* Area-light shadows without a user G-buffer: the camera's depth and
   world normals rendered through the draw callback (a caster program's
   skgl_caster_position() in place of attribute 0, as in depth.vert). */
#ifndef SKGL_CASTER
layout(location = 0) in vec3 a_position;
vec4 skgl_caster_position() { return vec4(a_position, 1.0); }
#endif
uniform mat4 u_view_proj;
uniform mat4 u_model;
out vec3 v_world;
void main()
{
    vec4 w = u_model * skgl_caster_position();
    v_world = w.xyz / w.w;
    gl_Position = u_view_proj * w;
}
