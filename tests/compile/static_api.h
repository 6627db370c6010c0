/* tests/compile: the non-static wrappers that static_a.c and static_b.c export
   from their private (SHADOWKIT_STATIC) copies of the implementation. */
#ifndef SK_STATIC_API_H
#define SK_STATIC_API_H
float sk_static_a_identity_m0(void);   /* sk_mat4_identity().m[0], copy A */
float sk_static_a_split(int i);        /* sk_pssm_splits(1, 100, 4, 0.5)[i], copy A */
float sk_static_b_identity_m5(void);   /* sk_mat4_identity().m[5], copy B */
float sk_static_b_split(int i);        /* sk_pssm_splits(1, 100, 4, 0.5)[i], copy B */
#endif
