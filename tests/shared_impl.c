/* shared_impl.c - shadowkit.h's implementation, compiled once per flavour
   (build/obj/<flavour>/shared_impl.o, see the Makefile) and linked by every
   tests/test_*.c built with tests/shared_impl.h. */
#define SHADOWKIT_IMPLEMENTATION
#include "shadowkit.h"
