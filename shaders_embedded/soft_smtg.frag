/* PVSM step 3: the point's predicted texel sizes (MIN-blended) and a count
   of one (added). */
flat in vec2 v_r;
out vec4 o_r;
void main()
{
    o_r = vec4(v_r, 1e30, 1.0);
}
