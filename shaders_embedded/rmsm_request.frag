/* RMSM page requests: a set texel is a requested page. */
out float o_request;
void main()
{
    o_request = 1.0;
}
