/* PVSM: the visibility mask from the kernel states and the accumulated
   (V*A, A) of every tile (Sec. 5.2). */
in vec2 v_uv;
out float o_visibility;
uniform sampler2DArray u_screen;  /* layer 0: the kernel */
uniform sampler2D u_acc;
void main()
{
    ivec2 px = ivec2(gl_FragCoord.xy);
    float state = texelFetch(u_screen, ivec3(px, 0), 0).w;
    vec2 acc = texelFetch(u_acc, px, 0).xy;
    if (state == 3.0) o_visibility = 0.0;
    else if (state == 2.0 && acc.y > 0.0) o_visibility = clamp(acc.x / acc.y, 0.0, 1.0);
    else o_visibility = 1.0;
}
