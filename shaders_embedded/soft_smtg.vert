/* PVSM step 4 (Sec. 5.2): one attribute-less point per screen pixel; the
   pixel's predicted texel sizes land in its SMTG cell, where MIN blending
   keeps the smallest. Pixels that need no filtering fall outside the clip
   volume. */
uniform sampler2D u_kernel;
uniform sampler2D u_pred;
uniform int u_width;
uniform int u_grid;
flat out vec2 v_r;
void main()
{
    ivec2 px = ivec2(gl_VertexID % u_width, gl_VertexID / u_width);
    vec4 k = texelFetch(u_kernel, px, 0);
    vec4 p = texelFetch(u_pred, px, 0);
    v_r = p.zw;
    gl_PointSize = 1.0;
    if (k.w != 2.0 || any(greaterThan(abs(p.xy), vec2(1.0)))) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        return;
    }
    vec2 cell = min(floor((p.xy * 0.5 + 0.5) * float(u_grid)), vec2(float(u_grid - 1)));
    gl_Position = vec4((cell + 0.5) / float(u_grid) * 2.0 - 1.0, 0.0, 1.0);
}
