// bloom.h: twins of the light-blooming passes (glsl/relief/bloom_*.frag,
// Timonen Sec. 3.2), one class per GLSL file. Their vertex stage is the
// triangles' "textured" program (a full-screen quad with uv).
#pragma once

#include "shading/program.h"

namespace st {

class Sampler2D;

class BloomBrightFragment final : public FragmentProgram<BloomBrightFragment> {  // bloom_bright.frag
public:
    void bind(const Bindings& b) override;
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;

private:
    const Sampler2D* hdr_ = nullptr;
    float threshold_ = 1.0f;
};

class BloomBlurFragment final : public FragmentProgram<BloomBlurFragment> {  // bloom_blur.frag
public:
    void bind(const Bindings& b) override;
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;

private:
    Vec3 pair(const Vec2& uv, float k) const;
    const Sampler2D* src_ = nullptr;
    glm::vec2 texel_step_{0.0f};
};

class BloomCompositeFragment final : public FragmentProgram<BloomCompositeFragment> {  // bloom_composite.frag
public:
    void bind(const Bindings& b) override;
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;

private:
    const Sampler2D* hdr_ = nullptr;
    const Sampler2D* bloom_ = nullptr;
    float strength_ = 1.0f;
};

}  // namespace st
