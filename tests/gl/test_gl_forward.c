/* test_gl_forward.c - the forward path (a shader containing
   skgl_glsl_snippet(), drawing the scene with world positions and normals,
   bound with skgl_shadow_bind on texture unit 3) agrees with the deferred
   mask path (skgl_shadow_mask over the G-buffer of the same view), for both
   techniques, on "ground-boxes" at 400 x 225, maps 1024^2.

   Measured (Mesa 22.3 llvmpipe), default bias (receiver plane): 0
   (standard) and 1 (pssm) of 60099 covered pixels differ in class, mean
   |difference| 0.00001, largest 0.001 / 0.019 (R16F rounding; the pssm
   pixel sits on a shadow edge); against the exact reference the mask and
   the forward pass have covered errors (tb_metric_hard) 0.0625% / 0.0625%
   (standard) and 0.0452% / 0.0469% (pssm), shadow-area errors
   (tb_metric_shadow) 2.37% / 2.37% and 1.71% / 1.77%. Previously (old
   reference, normal-offset bias): 0 pixels differed, both paths 0.1647% /
   0.0715%.
   Bounds: at most 0.05% of the pixels differ in class, mean |difference|
   below 0.002, coverage identical, forward error below test_gl_accuracy's
   bounds for this view: covered 0.09% / 0.065% (previously 0.30% /
   0.13%), area 3.3% / 2.4%. Can fail: with the normal-offset bias
   (SK_GL_TEST_BIAS=normal-offset) the forward pass's errors are 0.1824%
   / 0.0851%, area 6.90% / 3.22%: all four fail. After the forward pass
   skgl_unbind(3) leaves sampler 0 on units 3 and 4 (the bind's comparison
   sampler was on 3), and refuses unit 31 naming the unit. */
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"
#include "sk_test.h"
#include "gl_test_util.h"

#define W 400
#define H 225

static void run(skgl_technique tech) {
    gt_env e;
    gt_forward fw;
    skgl_shadow_desc d;
    skgl_shadow *s = NULL;
    float *ref, *mask, *fwd, *fdepth;
    sk_vec3 light = gt_v3(-0.5f, -1, -0.35f);
    skgl_camera cam = gt_camera(gt_v3(-9, 7, 12), gt_v3(0, 1, 0), 0.9f, 0.5f, 100, W, H);
    size_t i, both = 0, differ = 0, cov_only_one = 0;
    double maxdiff = 0;
    if (gt_env_init_named(&e, "ground-boxes", W, H) != 0) { gt_env_free(&e); return; }
    memset(&d, 0, sizeof d);
    d.technique = tech;
    d.resolution = 1024;
    s = gt_shadow(&e, &d);
    ref = gt_alloc(&e); mask = gt_alloc(&e); fwd = gt_alloc(&e); fdepth = gt_alloc(&e);
    SK_CHECK(gt_forward_create(&e, &fw) == 0);
    SK_CHECK(gt_gbuffer(&e, &cam) == 0);
    SK_CHECK(gt_reference(&e, light, ref) == 0);
    SK_CHECK(gt_mask(&e, s, &cam, light, mask) == 0);
    SK_CHECK(gt_forward_render(&e, &fw, s, &cam, 3, fwd, fdepth) == 0);
    {
        /* the bind left shadowkit's comparison sampler on unit 3;
           skgl_unbind gives plain sampling back on 3 and 4 */
        int before = 0, after3 = -1, after4 = -1, active = 0;
        e.gl.GetIntegerv(0x84E0 /* ACTIVE_TEXTURE */, &active);
        e.gl.ActiveTexture(0x84C0 + 3);
        e.gl.GetIntegerv(0x8919 /* SAMPLER_BINDING */, &before);
        SK_CHECK(skgl_unbind(e.sk, 3) == SK_OK);
        e.gl.GetIntegerv(0x8919, &after3);
        e.gl.ActiveTexture(0x84C0 + 4);
        e.gl.GetIntegerv(0x8919, &after4);
        e.gl.ActiveTexture((unsigned)active);
        SK_CHECK_MSG(before != 0 && after3 == 0 && after4 == 0, "unbind: sampler %d on unit 3 before, %d / %d after",
                     before, after3, after4);
        SK_CHECK(skgl_unbind(e.sk, 31) == SK_ERR_INVALID_ARG && strstr(skgl_error_log(e.sk), "unit"));
        SK_CHECK(skgl_unbind(NULL, 3) == SK_ERR_INVALID_ARG);
    }
    for (i = 0; i < e.n; i++) {
        if ((mask[i] < 0) != (fwd[i] < 0)) { cov_only_one++; continue; }
        if (mask[i] < 0) continue;
        both++;
        if (tb_visibility_class(mask[i]) != tb_visibility_class(fwd[i])) differ++;
        if (fabs(mask[i] - fwd[i]) > maxdiff) maxdiff = fabs(mask[i] - fwd[i]);
    }
    {
        tb_hard_error em = tb_metric_hard(ref, mask, e.n), ef = tb_metric_hard(ref, fwd, e.n);
        tb_shadow_error sm = gt_shadow_error(&e, ref, mask), sf = gt_shadow_error(&e, ref, fwd);
        tb_soft_error sd = tb_metric_soft(mask, fwd, e.n);
        printf("%s: covered %zu, class differs %zu (%.4f%%), mae %.5f max %.3f, coverage differs %zu; "
               "vs reference: mask %.4f%% (area %.4f%%) forward %.4f%% (area %.4f%%)\n",
               tech == SKGL_PSSM ? "pssm" : "standard", both, differ, 100.0 * differ / both, sd.mae, maxdiff,
               cov_only_one, em.pct, sm.area_pct, ef.pct, sf.area_pct);
        gt_images(&e, tech == SKGL_PSSM ? "forward-pssm" : "forward-standard", mask, fwd);
        SK_CHECK(both > e.n / 3);
        SK_CHECK_MSG(cov_only_one == 0, "%zu pixels covered by one path only", cov_only_one);
        SK_CHECK_MSG(100.0 * (double)differ / (double)both <= 0.05, "%zu of %zu pixels differ", differ, both);
        SK_CHECK_MSG(sd.mae < 0.002, "mean |mask - forward| %.5f", sd.mae);
        /* test_gl_accuracy's bounds for this view */
        SK_CHECK_MSG(ef.pct < (tech == SKGL_PSSM ? 0.065 : 0.09), "forward error %.4f%%", ef.pct);
        SK_CHECK_MSG(sf.ok && sf.area_pct < (tech == SKGL_PSSM ? 2.4 : 3.3), "forward shadow-area error %.4f%%",
                     sf.area_pct);
    }
    SK_CHECK(e.gl.GetError() == 0);
    gt_forward_destroy(&e, &fw);
    free(ref); free(mask); free(fwd); free(fdepth);
    skgl_shadow_destroy(e.sk, s);
    gt_env_free(&e);
}

static void test_forward(void) {
    run(SKGL_STANDARD);
    run(SKGL_PSSM);
}

SK_TEST_MAIN(test_forward)
