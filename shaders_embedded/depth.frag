/* Depth-only pass: the rasteriser writes depth; no colour output. */
void main()
{
}
