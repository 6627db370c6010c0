/* Second translation unit with its own static copy of the implementation;
   links with static_a.c without duplicate symbols. */
#define SHADOWKIT_STATIC
#define SHADOWKIT_IMPLEMENTATION
#include "shadowkit.h"
#include "tests/compile/static_api.h"

float sk_static_b_identity_m5(void) { return sk_mat4_identity().m[5]; }

float sk_static_b_split(int i) {
    float s[5];
    if (i < 0 || i > 4 || sk_pssm_splits(1.0f, 100.0f, 4, 0.5f, s) != SK_OK) return -1.0f;
    return s[i];
}
