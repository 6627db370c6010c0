/* shared_impl.h - forced in front of a test program (gcc -include) so that
   the program links its flavour's one compiled implementation
   (tests/shared_impl.c, tests/gl/shared_impl_gl.c) instead of compiling
   the header's implementation again.

   A test program stays a whole program that builds on its own: it defines
   SHADOWKIT_IMPLEMENTATION (and SHADOWKIT_GL_IMPLEMENTATION) and includes
   the header, as the headers' manuals say. Included first, this file has
   already read the declarations and marks both implementations as included
   (the headers' own guards, SHADOWKIT_[GL_]IMPLEMENTATION_INCLUDED), so the
   program's #include adds nothing, and its calls resolve to the shared
   object's extern functions. The program sees only the public part of the
   headers: no sk__/skgl__ internals, no macro the implementation defines
   (SKGL_ORIGIN_CELL, SKGL_MALLOC, ...).

   A program that configures the implementation, i.e. defines an SK_ / SKGL_
   macro (or any macro starting with SK) before its first #include of
   shadowkit, or that reads the implementation's internals, compiles its own
   copy: the Makefile's sk_own_impl finds the first kind itself; a program of
   the second kind says so in its top lines with
       #define SK_TEST_OWN_IMPLEMENTATION 1
   before the #include (which makes it one of the first kind). */
#ifndef SK_TEST_SHARED_IMPL_H
#define SK_TEST_SHARED_IMPL_H
/* read before any system header, the POSIX level the GL tests that time
   themselves ask for (GL flavours only) (clock_gettime): their own #define comes after this
   file's #includes, too late for glibc's <features.h> */
#ifdef SK_TEST_SHARED_IMPL_GL
#if !defined(_POSIX_C_SOURCE)
#define _POSIX_C_SOURCE 199309L
#endif
#include "shadowkit_gl.h"
#define SHADOWKIT_GL_IMPLEMENTATION_INCLUDED 1
#else
#include "shadowkit.h"
#endif
#define SHADOWKIT_IMPLEMENTATION_INCLUDED 1
#endif
