// cpp17_impl.cpp - the translation unit that holds shadowkit: both
// implementations, static (SHADOWKIT_STATIC), compiled as C++17 with
// -Wall -Wextra -Wpedantic -Werror, and app::SunShadow on top of it.
// See cpp17_main.cpp for what the program checks.
#define SHADOWKIT_STATIC
#define SHADOWKIT_IMPLEMENTATION
#define SHADOWKIT_GL_IMPLEMENTATION
#include "shadowkit_gl.h"

#include "cpp17_shadow.h"

#include <utility>

namespace app {

void SunShadow::ContextDeleter::operator()(skgl_context *c) const { skgl_destroy(c); }

std::optional<SunShadow> SunShadow::create(skgl_getproc_fn getproc, const skgl_shadow_desc &desc,
                                           std::string *error) {
    skgl_desc d{};
    d.getproc = getproc;
    d.debug = 1;
    skgl_context *raw = nullptr;
    SunShadow s;
    if (sk_result r = skgl_create(&d, &raw); r != SK_OK) {
        if (error) *error = std::string("skgl_create: ") + sk_result_string(r);
        return std::nullopt;
    }
    s.ctx_.reset(raw);
    if (sk_result r = skgl_shadow_create(raw, &desc, &s.sun_); r != SK_OK) {
        if (error) *error = std::string("skgl_shadow_create: ") + sk_result_string(r) + " " + skgl_error_log(raw);
        return std::nullopt;
    }
    return std::optional<SunShadow>(std::move(s));
}

SunShadow::SunShadow(SunShadow &&o) noexcept
    : ctx_(std::move(o.ctx_)), sun_(std::exchange(o.sun_, nullptr)), error_(std::move(o.error_)) {}

SunShadow &SunShadow::operator=(SunShadow &&o) noexcept {
    if (this != &o) {
        drop_shadow();
        ctx_ = std::move(o.ctx_);
        sun_ = std::exchange(o.sun_, nullptr);
        error_ = std::move(o.error_);
    }
    return *this;
}

SunShadow::~SunShadow() { drop_shadow(); }

void SunShadow::drop_shadow() {
    if (sun_ && ctx_) skgl_shadow_destroy(ctx_.get(), sun_);
    sun_ = nullptr;
}

bool SunShadow::render_mask(const skgl_camera &cam, const skgl_scene &scene, sk_vec3 light_dir, unsigned depth_tex,
                            unsigned normal_tex, unsigned mask_tex) {
    if (!ctx_ || !sun_) {
        error_ = "no shadow";
        return false;
    }
    if (sk_result r = skgl_shadow_render(ctx_.get(), sun_, &cam, &scene, light_dir); r != SK_OK) {
        error_ = std::string("skgl_shadow_render: ") + sk_result_string(r) + " " + skgl_error_log(ctx_.get());
        return false;
    }
    if (sk_result r = skgl_shadow_mask(ctx_.get(), sun_, &cam, depth_tex, normal_tex, mask_tex); r != SK_OK) {
        error_ = std::string("skgl_shadow_mask: ") + sk_result_string(r) + " " + skgl_error_log(ctx_.get());
        return false;
    }
    return true;
}

const skgl_shadow_frame_stats &SunShadow::stats() const {
    static const skgl_shadow_frame_stats none{};
    const skgl_shadow_frame_stats *st = skgl_shadow_stats(sun_);
    return st ? *st : none;
}

sk_mat4 SunShadow::light_matrix(int layer) const { return skgl_shadow_matrix(sun_, layer); }

skgl_shadow_desc SunShadow::desc() const { return skgl_shadow_get_desc(sun_); }

int SunShadow::gl_objects() const { return skgl_gl_object_count(ctx_.get()); }

std::optional<std::array<float, kCascades + 1>> SunShadow::splits(float zn, float zf, float lambda) {
    std::array<float, kCascades + 1> out{};
    if (sk_pssm_splits(zn, zf, kCascades, lambda, out.data()) != SK_OK) return std::nullopt;
    return out;
}

sk_mat4 look_at(sk_vec3 eye, sk_vec3 target, sk_vec3 up) { return sk_mat4_look_at(eye, target, up); }
sk_mat4 perspective(float fovy, float aspect, float zn, float zf) { return sk_mat4_perspective(fovy, aspect, zn, zf); }
sk_mat4 operator*(const sk_mat4 &a, const sk_mat4 &b) { return sk_mat4_mul(a, b); }
std::optional<sk_mat4> inverse(const sk_mat4 &m) {
    sk_mat4 out{};
    if (!sk_mat4_inverse(m, &out)) return std::nullopt;
    return out;
}

}  // namespace app
