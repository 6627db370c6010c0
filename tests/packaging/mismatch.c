/* mismatch.c - must NOT compile (tests/packaging/run.sh): a shadowkit.h of
   another release already included (its guard and version macros stand in
   for it here), then shadowkit_gl.h, which refuses the pair. */
#define SHADOWKIT_H
#define SHADOWKIT_VERSION_MAJOR 9
#define SHADOWKIT_VERSION_MINOR 0
#define SHADOWKIT_VERSION_PATCH 0
#include "shadowkit_gl.h"
int main(void) { return 0; }
