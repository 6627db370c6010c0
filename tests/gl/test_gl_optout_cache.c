/* test_gl_optout_cache.c - test_gl_optout.c's checks with SKGL_NO_CACHE
   and SKGL_NO_CASTERS alone (CONFIGURATION): the area lights and RMSM stay,
   and RMSM, whose page render has the cache's parts compiled out, still
   shadows (its pages drawn uncached, after an analysis).
   RMSM (virtual 8192^2, pages of 128, a pool of 16^2, one analysis):
   covered error (tb_metric_hard) 0.0385%, the same as this program built
   without the opt-outs; bound about 1.4x. Can fail: at a quarter of the
   resolution (SK_GL_TEST_RES_SCALE=0.25, virtual 2048^2) 0.0742%, and the
   standard and PSSM maps fail as in test_gl_optout.c. */
#define SK_TEST_OWN_IMPLEMENTATION 1
#define SK_OPTOUT_SOME 1
#define RMSM_MAX_ERR 0.055
#include "test_gl_optout.c"
