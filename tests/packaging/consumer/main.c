/* main.c - a tiny program built against an installed (or add_subdirectory)
   shadowkit: both implementations live here (they go in one file), gl.c
   uses the declarations only. Prints the version and exits 0 when the
   calls give what they must. */
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include <shadowkit_gl.h>

#include <math.h>
#include <stdio.h>

int gl_part(void);   /* gl.c */

int main(void)
{
    float s[5];
    int ok = 1;
    /* the practical split scheme at lambda 1: logarithmic, 1 10 100 1000 10000 */
    ok &= sk_pssm_splits(1.0f, 10000.0f, 4, 1.0f, s) == SK_OK;
    ok &= fabs(s[2] - 100.0) < 1e-2;
    ok &= gl_part();
    printf("consumer: shadowkit %d.%d.%d, splits %g %g %g: %s\n", SHADOWKIT_VERSION_MAJOR, SHADOWKIT_VERSION_MINOR,
           SHADOWKIT_VERSION_PATCH, s[1], s[2], s[3], ok ? "ok" : "WRONG");
    return ok ? 0 : 1;
}
