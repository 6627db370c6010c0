/* The shadowkit implementation, compiled once for every fuzz target (with
   coverage instrumentation and the sanitizers, see mk/fuzz.mk). */
#define SHADOWKIT_IMPLEMENTATION
#include "shadowkit.h"
