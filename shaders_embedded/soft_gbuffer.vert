/* Area-light shadows without a user G-buffer: the camera's depth and
   world normals rendered through the draw callback. */
layout(location = 0) in vec3 a_position;
uniform mat4 u_view_proj;
uniform mat4 u_model;
out vec3 v_world;
void main()
{
    vec4 w = u_model * vec4(a_position, 1.0);
    v_world = w.xyz / w.w;
    gl_Position = u_view_proj * w;
}
