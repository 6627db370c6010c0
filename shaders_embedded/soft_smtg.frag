/* PVSM step 4: the point's predicted texel sizes (MIN-blended). */
flat in vec2 v_r;
out vec4 o_r;
void main()
{
    o_r = vec4(v_r, 0.0, 1.0);
}
