/* Includes shadowkit.h without the implementation and calls into the TU that
   has it (extern_impl.c), possibly compiled in the other language. */
#include "shadowkit.h"
#include "tests/sk_test.h"

static void test_extern_linkage(void) {
    sk_mat4 id = sk_mat4_identity();
    sk_mat4 p = sk_mat4_mul(id, id);
    float s[3] = { -1.0f, -1.0f, -1.0f };
    int i;
    for (i = 0; i < 16; i++) SK_CHECK(p.m[i] == ((i % 5 == 0) ? 1.0f : 0.0f));
    /* uniform splits (lambda = 0): 2, 6, 10 */
    SK_CHECK(sk_pssm_splits(2.0f, 10.0f, 2, 0.0f, s) == SK_OK);
    SK_CHECK_NEAR(s[0], 2.0, 1e-5);
    SK_CHECK_NEAR(s[1], 6.0, 1e-5);
    SK_CHECK_NEAR(s[2], 10.0, 1e-5);
    SK_CHECK(sk_pssm_splits(2.0f, 1.0f, 2, 0.0f, s) == SK_ERR_INVALID_ARG);
    SK_CHECK(sk_result_string(SK_OK) != NULL && strcmp(sk_result_string(SK_OK), "ok") == 0);
}

SK_TEST_MAIN(test_extern_linkage)
