/* shared_impl_gl.c - shadowkit.h's and shadowkit_gl.h's implementations,
   compiled once per GL flavour (build/obj/gl/, build/obj/hygiene/, see
   mk/testbed.mk and mk/hygiene.mk) and linked by every tests/gl/test_gl_*.c
   built with tests/shared_impl.h. */
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
