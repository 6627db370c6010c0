/* RMSM page requests: a set texel is a requested page (banded: the
   levels, rmsm_request.vert). */
flat in vec3 v_request;
out vec4 o_request;
void main()
{
    o_request = vec4(v_request, 1.0);
}
