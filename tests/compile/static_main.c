/* Links static_a.c and static_b.c (two SHADOWKIT_STATIC copies of the
   implementation) into one program and checks both copies work. This file
   defines SHADOWKIT_STATIC too, without the implementation: it gets the
   types and constants and must compile without warnings (GCC warns about
   static declarations that are never defined). */
#define SHADOWKIT_STATIC
#include "shadowkit.h"
#include "tests/compile/static_api.h"
#include "tests/sk_test.h"

static void test_two_static_copies(void) {
    int i;
    sk_vec3 v = { 1.0f, 2.0f, 3.0f };         /* the types are usable here */
    SK_CHECK(v.x + v.y + v.z == 6.0f && SK_OK == 0 && SHADOWKIT_VERSION_MAJOR >= 0);
    SK_CHECK(sk_static_a_identity_m0() == 1.0f);
    SK_CHECK(sk_static_b_identity_m5() == 1.0f);
    /* C_i = 0.5*1*100^(i/4) + 0.5*(1 + 99*i/4), from the PSSM formula */
    for (i = 0; i <= 4; i++) {
        double c = 0.5 * pow(100.0, i / 4.0) + 0.5 * (1.0 + 99.0 * i / 4.0);
        SK_CHECK_NEAR(sk_static_a_split(i), c, 1e-3 * c);
        SK_CHECK(sk_static_a_split(i) == sk_static_b_split(i));
    }
}

SK_TEST_MAIN(test_two_static_copies)
