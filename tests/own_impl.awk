# tests/own_impl.awk FILE... - prints the test programs that compile their
# own copy of the implementation rather than link the shared one
# (tests/shared_impl.h): those that define a macro starting with SK, other
# than SHADOWKIT_IMPLEMENTATION and SHADOWKIT_GL_IMPLEMENTATION, before their
# first #include "..." (a configuration of the implementation, e.g.
# SKGL_MALLOC, or the marker SK_TEST_OWN_IMPLEMENTATION). Used by the
# Makefile and mk/testbed.mk, mk/hygiene.mk.
FNR == 1 { done = 0 }
/^[ \t]*#[ \t]*include[ \t]*"/ { done = 1 }
!done && /^[ \t]*#[ \t]*define[ \t]+SK/ && !/#[ \t]*define[ \t]+SHADOWKIT_(GL_)?IMPLEMENTATION([ \t]|$)/ {
    print FILENAME
    done = 1
}
