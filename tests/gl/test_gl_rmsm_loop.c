/* test_gl_rmsm_loop.c - test_gl_rmsm.c's test_layered_batches with
   SKGL_LAYERED_LOOP: RMSM's pages 8 at a pass through the GL 3.3 core
   geometry shader that loops over the layers (what a driver without
   GL_ARB_gpu_shader5 runs). */
#define SKGL_LAYERED_LOOP 1
#include "test_gl_rmsm.c"
