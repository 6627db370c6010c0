/* Flat world normals from the screen derivatives, turned to the camera. */
in vec3 v_world;
out vec4 o_normal;
uniform vec3 u_eye;
void main()
{
#ifdef SKGL_CASTER_FRAGMENT
    skgl_caster_fragment();
#endif
    vec3 n = cross(dFdx(v_world), dFdy(v_world));
    n = dot(n, n) > 0.0 ? normalize(n) : vec3(0.0, 1.0, 0.0);
    if (dot(n, u_eye - v_world) < 0.0) n = -n;
    o_normal = vec4(n, 1.0);
}
