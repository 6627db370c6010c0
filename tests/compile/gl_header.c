/* shadowkit_gl.h with both implementations in one translation unit, built
   as C99, C++11 and C++17 with the strict warning flags. It needs no GL to
   link (every entry point comes through getproc), so it also checks the
   failure paths that need no context. */
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "tests/sk_test.h"

static void *no_gl(const char *name) { (void)name; return NULL; }

static void test_create_without_gl(void)
{
    skgl_desc d;
    skgl_context *ctx = (skgl_context *)&d;   /* must be reset to NULL on failure */
    memset(&d, 0, sizeof d);
    SK_CHECK(skgl_create(NULL, &ctx) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_create(&d, &ctx) == SK_ERR_INVALID_ARG);          /* no getproc */
    d.getproc = no_gl;
    SK_CHECK(skgl_create(&d, NULL) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_create(&d, &ctx) == SK_ERR_GL);                   /* nothing resolves */
    SK_CHECK(ctx == NULL);
    SK_CHECK(strcmp(sk_result_string(SK_ERR_GL), "GL error") == 0);
}

static void test_null_handles(void)
{
    skgl_shadow_desc sd;
    skgl_shadow *s = NULL;
    memset(&sd, 0, sizeof sd);
    SK_CHECK(skgl_shadow_create(NULL, &sd, &s) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_shadow_render(NULL, NULL, NULL, NULL, sk_mat4_transform_point(sk_mat4_identity(), sk__v3(0, -1, 0))) ==
             SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_shadow_mask(NULL, NULL, NULL, 0, 0, 0) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_shadow_bind(NULL, NULL, 0, 0) == SK_ERR_INVALID_ARG);
    SK_CHECK(skgl_shadow_stats(NULL) == NULL);
    SK_CHECK(skgl_shadow_texture(NULL) == 0);
    SK_CHECK(skgl_gl_object_count(NULL) == 0);
    SK_CHECK(skgl_shadow_matrix(NULL, 0).m[0] == 1.0f);
    SK_CHECK(strstr(skgl_glsl_snippet(), "float sk_shadow(vec3 world_pos, vec3 world_normal, float view_depth)") != NULL);
    skgl_destroy(NULL);
    skgl_shadow_destroy(NULL, NULL);
}

SK_TEST_MAIN(test_create_without_gl, test_null_handles)
