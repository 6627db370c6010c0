/* SKGL_MALLOC without SKGL_FREE (or, with SK_FREE_ALONE, SKGL_FREE without
   SKGL_MALLOC): shadowkit_gl.h must refuse it with its #error (CONFIGURATION:
   both or neither). mk/shaders.mk compiles it both ways and fails when it
   compiles, or fails for another reason. */
#include <stdlib.h>
#ifdef SK_FREE_ALONE
#define SKGL_FREE(p) free(p)
#else
#define SKGL_MALLOC(n) malloc(n)
#endif
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"

int main(void) { return 0; }
