/* Flat world normals from the screen derivatives, turned to the camera. */
in vec3 skgl_world;
out vec4 skgl_normal;
uniform vec3 skgl_eye;
void main()
{
#ifdef SKGL_CASTER_FRAGMENT
    skgl_caster_fragment();
#endif
    vec3 skgl_n = cross(dFdx(skgl_world), dFdy(skgl_world));
    skgl_n = dot(skgl_n, skgl_n) > 0.0 ? normalize(skgl_n) : vec3(0.0, 1.0, 0.0);
    if (dot(skgl_n, skgl_eye - skgl_world) < 0.0) skgl_n = -skgl_n;
    skgl_normal = vec4(skgl_n, 1.0);
}
