/* gl.c - a second translation unit using shadowkit_gl.h's declarations, no
   GL library linked: with a getproc that finds nothing, skgl_create must
   refuse (SK_ERR_GL). */
#include <string.h>
#include <shadowkit_gl.h>

int gl_part(void);

static void *no_gl(const char *name)
{
    (void)name;
    return 0;
}

int gl_part(void)
{
    skgl_desc d;
    skgl_context *ctx = 0;
    memset(&d, 0, sizeof d);   /* every field zero: the defaults */
    d.getproc = no_gl;
    return skgl_create(&d, &ctx) == SK_ERR_GL && ctx == 0 &&
           SHADOWKIT_GL_VERSION_MAJOR == SHADOWKIT_VERSION_MAJOR && SHADOWKIT_GL_VERSION_MINOR == SHADOWKIT_VERSION_MINOR;
}
