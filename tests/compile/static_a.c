/* First of two translation units with a private copy of the implementation:
   SHADOWKIT_STATIC makes every shadowkit symbol static here. */
#define SHADOWKIT_STATIC
#define SHADOWKIT_IMPLEMENTATION
#include "shadowkit.h"
#include "tests/compile/static_api.h"

float sk_static_a_identity_m0(void) { return sk_mat4_identity().m[0]; }

float sk_static_a_split(int i) {
    float s[5];
    if (i < 0 || i > 4 || sk_pssm_splits(1.0f, 100.0f, 4, 0.5f, s) != SK_OK) return -1.0f;
    return s[i];
}
