/* test_gl_caster_varyings_loop.c - test_gl_caster_varyings.c with
   SKGL_LAYERED_LOOP: the layered passes' caster programs through the GL 3.3
   core geometry shader that loops over the layers (what a driver without
   GL_ARB_gpu_shader5 runs). */
#define SKGL_LAYERED_LOOP 1
#include "test_gl_caster_varyings.c"
