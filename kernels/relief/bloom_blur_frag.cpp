// bloom_blur_frag.cpp: twin of glsl/relief/bloom_blur.frag, line for line.
#include "kernels/relief/bloom.h"

#include "texture/sampler2d.h"

namespace st {

namespace {
constexpr int v_uv = 1;  // input
// The GLSL's constants, the same literals.
const float w0 = 0.20416369f, w1 = 0.18017382f, w2 = 0.12383154f, w3 = 0.06628225f, w4 = 0.02763055f;
}  // namespace

void BloomBlurFragment::bind(const Bindings& b) {
    src_ = &b.sampler("src");
    texel_step_ = b.get_vec2("texel_step");
}

uint32_t BloomBlurFragment::inputs_read() const { return reads(v_uv, "xy"); }

Vec3 BloomBlurFragment::pair(const Vec2& uv, float k) const {
    const Vec2 d = Vec2(Float(k) * Float(texel_step_.x), Float(k) * Float(texel_step_.y));
    return src_->sample(uv - d).xyz() + src_->sample(uv + d).xyz();
}

Vec4 BloomBlurFragment::main(const Fragment& frag) const {
    const Vec2 uv = frag.varying(v_uv).xy();
    Vec3 c = Float(w0) * src_->sample(uv).xyz();
    c = c + Float(w1) * pair(uv, 1.0f);
    c = c + Float(w2) * pair(uv, 2.0f);
    c = c + Float(w3) * pair(uv, 3.0f);
    c = c + Float(w4) * pair(uv, 4.0f);
    return Vec4(c, Float(1.0f));
}

}  // namespace st
