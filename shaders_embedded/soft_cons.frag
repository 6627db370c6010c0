/* PVSM step 2: window depth into the R32F level 0 of the MIN pyramid
   (the depth attachment does the depth test), overfill outside the
   triangle's grown bounding box discarded. */
flat in vec4 g_box;
out vec4 o_depth;
void main()
{
    if (any(lessThan(gl_FragCoord.xy, g_box.xy)) || any(greaterThan(gl_FragCoord.xy, g_box.zw))) discard;
    o_depth = vec4(gl_FragCoord.z);
}
