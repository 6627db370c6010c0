/* split.c - must NOT compile (tests/packaging/run.sh): shadowkit_gl.h's
   implementation without shadowkit.h's in the same file is refused with
   a message saying so. */
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
int main(void) { return 0; }
