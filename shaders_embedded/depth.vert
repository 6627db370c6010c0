/* Depth-only pass: shadow maps of every technique. Attribute 0 is the
   position; u_model is set per object through skgl_set_model(). */
layout(location = 0) in vec3 a_position;
uniform mat4 u_view_proj;
uniform mat4 u_model;
void main()
{
    gl_Position = u_view_proj * (u_model * vec4(a_position, 1.0));
}
