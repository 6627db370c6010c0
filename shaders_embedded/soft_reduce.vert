/* One level of PVSM's low-resolution MIN pyramid per triangle, all from one
   program: triangle k (vertices 3k..3k+2, glDrawArrays' first) draws level
   k + 1. The viewport is level 1's; the triangle covers level k + 1's
   texels, the lower-left 1/2^k of it. */
flat out int v_level;
void main()
{
    int k = gl_VertexID / 3, v = gl_VertexID - 3 * k;
    vec2 p = vec2(float((v << 1) & 2), float(v & 2));
    v_level = k + 1;
    gl_Position = vec4(p * (2.0 / float(1 << k)) - 1.0, 0.0, 1.0);
}
