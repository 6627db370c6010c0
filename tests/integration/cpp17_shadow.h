// cpp17_shadow.h - what the C++17 integration test's two translation units
// share: a small RAII wrapper an engine might write around shadowkit_gl.h.
// cpp17_impl.cpp holds the only copy of the shadowkit implementation (both
// files define SHADOWKIT_STATIC first, so that copy is private to it);
// cpp17_main.cpp sees the same header for its types only and calls
// shadowkit solely through this class.
#ifndef CPP17_SHADOW_H
#define CPP17_SHADOW_H

#include <array>
#include <memory>
#include <optional>
#include <string>

#include "shadowkit_gl.h"

namespace app {

constexpr int kCascades = 4;

// One directional light's shadow, deferred: skgl_shadow_render then
// skgl_shadow_mask. Owns its skgl_context and skgl_shadow; move-only.
class SunShadow {
public:
    // nullopt on failure, with shadowkit's message in *error
    [[nodiscard]] static std::optional<SunShadow> create(skgl_getproc_fn getproc, const skgl_shadow_desc &desc,
                                                         std::string *error);
    SunShadow(SunShadow &&other) noexcept;
    SunShadow &operator=(SunShadow &&other) noexcept;
    SunShadow(const SunShadow &) = delete;
    SunShadow &operator=(const SunShadow &) = delete;
    ~SunShadow();

    // the map for this camera and light, then visibility into mask_tex
    [[nodiscard]] bool render_mask(const skgl_camera &cam, const skgl_scene &scene, sk_vec3 light_dir,
                                   unsigned depth_tex, unsigned normal_tex, unsigned mask_tex);
    const skgl_shadow_frame_stats &stats() const;
    sk_mat4 light_matrix(int layer) const;
    skgl_shadow_desc desc() const;        // with shadowkit's defaults filled in
    int gl_objects() const;               // GL objects the context owns
    void drop_shadow();                   // deletes the shadow, keeps the context
    const std::string &error() const { return error_; }

    // the CPU side: sk_pssm_splits for kCascades cascades
    static std::optional<std::array<float, kCascades + 1>> splits(float zn, float zf, float lambda);

private:
    SunShadow() = default;
    struct ContextDeleter { void operator()(skgl_context *c) const; };
    std::unique_ptr<skgl_context, ContextDeleter> ctx_;
    skgl_shadow *sun_ = nullptr;
    std::string error_;
};

// The shadowkit math the other file uses, from this file's copy.
sk_mat4 look_at(sk_vec3 eye, sk_vec3 target, sk_vec3 up);
sk_mat4 perspective(float fovy, float aspect, float zn, float zf);
sk_mat4 operator*(const sk_mat4 &a, const sk_mat4 &b);
std::optional<sk_mat4> inverse(const sk_mat4 &m);

}  // namespace app

#endif  // CPP17_SHADOW_H
