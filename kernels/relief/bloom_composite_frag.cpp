// bloom_composite_frag.cpp: twin of glsl/relief/bloom_composite.frag, line
// for line.
#include "kernels/relief/bloom.h"

#include "shading/glsl_math.h"
#include "texture/sampler2d.h"

namespace st {

namespace {
constexpr int v_uv = 1;  // input
}  // namespace

void BloomCompositeFragment::bind(const Bindings& b) {
    hdr_ = &b.sampler("hdr");
    bloom_ = &b.sampler("bloom");
    strength_ = b.get_float("strength");
}

uint32_t BloomCompositeFragment::inputs_read() const { return reads(v_uv, "xy"); }

Vec4 BloomCompositeFragment::main(const Fragment& frag) const {
    const Vec2 uv = frag.varying(v_uv).xy();
    const Vec3 c = hdr_->sample(uv).xyz();
    const Vec3 ldr(glsl::min(c.x, Float(1.0f)), glsl::min(c.y, Float(1.0f)), glsl::min(c.z, Float(1.0f)));
    return Vec4(ldr + Float(strength_) * bloom_->sample(uv).xyz(), Float(1.0f));
}

}  // namespace st
