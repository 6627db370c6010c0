// cpp17_main.cpp - shadowkit in a C++17 program of two translation units.
//
// Both files define SHADOWKIT_STATIC and include shadowkit_gl.h (and so
// shadowkit.h); only cpp17_impl.cpp defines SHADOWKIT_IMPLEMENTATION and
// SHADOWKIT_GL_IMPLEMENTATION. Both are compiled with -std=c++17 -Wall
// -Wextra -Wpedantic -Werror. This file uses the headers' types and
// constants only (its declarations are the plain ones a file without the
// implementation gets) and reaches shadowkit through app::SunShadow.
//
// What it checks, on OSMesa through the testbed:
//   - the PSSM splits from the implementation's copy equal the practical
//     split scheme C_i = l*n*(f/n)^(i/m) + (1-l)*(n + (f-n)*i/m), in double;
//   - a getproc that resolves nothing gives no object and shadowkit's message;
//   - a deferred PSSM mask (4 x 1024^2) of the ground-boxes scene against the
//     Embree reference: at most 0.5% of covered pixels wrong (measured 0.052%,
//     44 of 84824 at 480x270), over 10% of them shadowed (16.5%), four finite
//     cascade matrices with increasing splits;
//   - the same frame again leaves the GL object count unchanged, deleting
//     the shadow lowers it, and a moved-from wrapper refuses to render.
// It can fail: with the light direction negated in render_mask's call of
// skgl_shadow_render (a sign slip between engine and library) 83.6% of the
// covered pixels are wrong and the error check fails.
#define SHADOWKIT_STATIC
#include "cpp17_shadow.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>
#include <utility>
#include <vector>

#include "sk_test.h"
#include "tb_gl_context.h"
#include "tb_gl_fbo.h"
#include "tb_gl_funcs.h"
#include "tb_gl_scene.h"
#include "tb_metrics.h"
#include "tb_reference.h"
#include "tb_scene.h"

namespace {

constexpr int kW = 480, kH = 270;

sk_vec3 v3(float x, float y, float z) {
    sk_vec3 v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}

// the split scheme evaluated here, independently of shadowkit
void test_splits() {
    const double n = 0.5, f = 120.0, l = 0.75;
    auto s = app::SunShadow::splits(0.5f, 120.0f, 0.75f);
    SK_CHECK(s.has_value());
    if (!s) return;
    for (int i = 0; i <= app::kCascades; i++) {
        double t = double(i) / app::kCascades;
        double c = l * n * std::pow(f / n, t) + (1.0 - l) * (n + (f - n) * t);
        SK_CHECK_NEAR((*s)[size_t(i)], c, 1e-4 * c);
    }
    SK_CHECK(!app::SunShadow::splits(2.0f, 1.0f, 0.5f).has_value());   // far < near
}

void *no_gl(const char *) { return nullptr; }

void test_create_fails_cleanly() {
    std::string err;
    skgl_shadow_desc d{};
    auto s = app::SunShadow::create(no_gl, d, &err);
    SK_CHECK(!s.has_value());
    SK_CHECK_MSG(err == "skgl_create: GL error", "error '%s'", err.c_str());
}

// the testbed side of the program: context, scene, G-buffer, reference
struct Testbed {
    tb_gl_context *ctx = nullptr;
    tb_gl_funcs gl{};
    tb_scene scene{};
    tb_gl_mesh mesh{};
    tb_gl_gbuffer gpass{};
    tb_gl_fbo gbuf{}, mask{};
    tb_reference *ref = nullptr;

    bool open() {
        char err[512] = "";
        tb_scene_init(&scene);
        if (tb_scene_build_ground_boxes(&scene) != 0) return false;
        ctx = tb_gl_context_create(TB_GL_OSMESA, err, sizeof err);
        if (!ctx) {
            std::printf("OSMesa: %s\n", err);
            return false;
        }
        return tb_gl_funcs_load(&gl, tb_gl_context_getproc(ctx)) == 0 &&
               tb_gl_mesh_create(&gl, &mesh, &scene) == 0 &&
               tb_gl_gbuffer_create(&gl, &gpass, err, sizeof err) == 0 &&
               tb_gl_fbo_create(&gl, &gbuf, kW, kH, TB_GL_COLOR_RGBA16F) == 0 &&
               tb_gl_fbo_create(&gl, &mask, kW, kH, TB_GL_COLOR_R16F) == 0 &&
               (ref = tb_reference_create(&scene)) != nullptr;
    }
    ~Testbed() {
        if (ctx) {
            tb_gl_fbo_destroy(&gl, &gbuf);
            tb_gl_fbo_destroy(&gl, &mask);
            tb_gl_gbuffer_destroy(&gl, &gpass);
            tb_gl_mesh_destroy(&gl, &mesh);
            tb_gl_context_destroy(ctx);
        }
        tb_reference_destroy(ref);
        tb_scene_free(&scene);
    }
};

void test_mask_against_reference() {
    Testbed tb;
    SK_CHECK_MSG(tb.open(), "testbed set-up failed");
    if (!tb.ref) return;

    skgl_shadow_desc d{};
    d.technique = SKGL_PSSM;
    d.cascades = app::kCascades;
    d.resolution = 1024;
    std::string err;
    auto made = app::SunShadow::create(tb_gl_context_getproc(tb.ctx), d, &err);
    SK_CHECK_MSG(made.has_value(), "%s", err.c_str());
    if (!made) return;
    app::SunShadow sun = std::move(*made);   // the wrapper moves
    SK_CHECK(!made->render_mask(skgl_camera{}, skgl_scene{}, v3(0, -1, 0), 0, 0, 0));
    SK_CHECK(sun.desc().pcf_radius == 1 && sun.desc().cascades == app::kCascades);   // defaults filled in

    skgl_camera cam{};
    cam.view = app::look_at(v3(10, 7, 12), v3(0, 1, 0), v3(0, 1, 0));
    cam.proj = app::perspective(0.9f, float(kW) / float(kH), 0.1f, 80.0f);
    const sk_vec3 light = v3(0.4f, -1.0f, 0.3f);
    // shadowkit's draw callback: a captureless lambda is a plain function pointer
    skgl_scene sc{};
    sc.draw = [](void *user, const skgl_draw_info *) {
        auto *t = static_cast<Testbed *>(user);
        tb_gl_mesh_draw(&t->gl, &t->mesh, 0, 0);
    };
    sc.user = &tb;
    sc.bounds = tb.scene.bounds;

    using app::operator*;
    const sk_mat4 vp = cam.proj * cam.view;
    SK_CHECK(tb_gl_gbuffer_render(&tb.gl, &tb.gpass, &tb.mesh, &tb.gbuf, &vp) == 0);
    const size_t n = size_t(kW) * kH;
    std::vector<float> depth(n), rgba(4 * n), normals(3 * n), ref(n), vis(n);
    SK_CHECK(tb_gl_read_depth(&tb.gl, tb.gbuf.fbo, kW, kH, depth.data()) == 0);
    SK_CHECK(tb_gl_read_rgba_float(&tb.gl, tb.gbuf.fbo, kW, kH, rgba.data()) == 0);
    for (size_t i = 0; i < n; i++)
        for (size_t c = 0; c < 3; c++) normals[3 * i + c] = rgba[4 * i + c];

    SK_CHECK_MSG(sun.render_mask(cam, sc, light, tb.gbuf.depth_tex, tb.gbuf.color_tex, tb.mask.color_tex), "%s",
                 sun.error().c_str());
    const int objects = sun.gl_objects();
    SK_CHECK(tb_gl_read_texture_red(&tb.gl, tb.mask.color_tex, kW, kH, vis.data()) == 0);
    for (size_t i = 0; i < n; i++)
        if (!(depth[i] < 1.0f)) vis[i] = -1.0f;

    tb_view view{};
    const std::optional<sk_mat4> inv = app::inverse(vp);
    SK_CHECK(inv.has_value());
    if (!inv) return;
    view.inv_view_proj = *inv;
    view.width = kW;
    view.height = kH;
    tb_light sunlight{};
    sunlight.type = TB_LIGHT_DIRECTIONAL;
    sunlight.direction = light;
    SK_CHECK(tb_reference_trace(tb.ref, &view, depth.data(), normals.data(), &sunlight, nullptr, ref.data()) == 0);

    const tb_hard_error e = tb_metric_hard(ref.data(), vis.data(), n);
    size_t shadowed = 0;
    for (size_t i = 0; i < n; i++) shadowed += ref[i] >= 0.0f && tb_visibility_class(ref[i]) == 0;
    std::printf("PSSM 4 x 1024^2 mask vs reference: %.3f%% wrong (%llu of %llu covered), %zu shadowed\n", e.pct,
                (unsigned long long)e.wrong, (unsigned long long)e.covered, shadowed);
    SK_CHECK(e.covered > n / 2);
    SK_CHECK_MSG(e.pct <= 0.5, "error %.3f%%", e.pct);
    SK_CHECK(shadowed * 10 > size_t(e.covered));

    const skgl_shadow_frame_stats &st = sun.stats();
    SK_CHECK(st.maps == app::kCascades);
    for (int i = 0; i < app::kCascades; i++) {
        SK_CHECK(st.splits[i] < st.splits[i + 1]);
        const sk_mat4 m = sun.light_matrix(i);
        bool finite = true;
        for (float x : m.m) finite = finite && std::isfinite(x);
        SK_CHECK(finite);
    }

    // a second frame creates nothing that stays; dropping the shadow deletes its objects
    SK_CHECK(sun.render_mask(cam, sc, light, tb.gbuf.depth_tex, tb.gbuf.color_tex, tb.mask.color_tex));
    SK_CHECK(sun.gl_objects() == objects);
    sun.drop_shadow();
    SK_CHECK_MSG(sun.gl_objects() < objects, "%d objects after dropping the shadow, %d before", sun.gl_objects(),
                 objects);
    SK_CHECK(tb.gl.GetError() == 0);
}

}  // namespace

SK_TEST_MAIN(test_splits, test_create_fails_cleanly, test_mask_against_reference)
