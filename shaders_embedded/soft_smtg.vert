/* PVSM step 3 (Sec. 5.2): one attribute-less point per screen pixel. A
   pixel that needs filtering puts its predicted texel sizes in its SMTG
   cell, where MIN blending keeps the smallest (red, green) and additive
   blending counts the pixels (alpha). Every other covered pixel (fully lit,
   facing away, outside the light) is counted in the row above the grid,
   spread over its cells. Background pixels fall outside the clip volume.
   The target is grid x (grid + 1) texels: one read-back brings the SMTG and
   the counts of stats.lit_fraction. */
uniform sampler2DArray u_screen;  /* layers: kernel, prediction, plane */
uniform int u_width;
uniform int u_grid;
flat out vec2 v_r;
void main()
{
    ivec2 px = ivec2(gl_VertexID % u_width, gl_VertexID / u_width);
    vec4 k = texelFetch(u_screen, ivec3(px, 0), 0);
    vec4 p = texelFetch(u_screen, ivec3(px, 1), 0);
    float g = float(u_grid);
    vec2 cell;
    gl_PointSize = 1.0;
    v_r = p.zw;
    if (k.w == 0.0) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
        return;
    }
    if (k.w != 2.0 || any(greaterThan(abs(p.xy), vec2(1.0)))) {
        v_r = vec2(1e30);
        cell = vec2(float(px.x % u_grid), g);
    } else {
        cell = min(floor((p.xy * 0.5 + 0.5) * g), vec2(g - 1.0));
    }
    gl_Position = vec4((cell + 0.5) / vec2(g, g + 1.0) * 2.0 - 1.0, 0.0, 1.0);
}
