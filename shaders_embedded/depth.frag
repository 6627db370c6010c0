/* Depth-only pass: the rasteriser writes depth; no colour output. A
   caster program's fragment hook may discard (an alpha test). */
void main()
{
#ifdef SKGL_CASTER_FRAGMENT
    skgl_caster_fragment();
#endif
}
