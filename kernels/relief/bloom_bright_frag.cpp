// bloom_bright_frag.cpp: twin of glsl/relief/bloom_bright.frag, line for line.
#include "kernels/relief/bloom.h"

#include "shading/glsl_math.h"
#include "texture/sampler2d.h"

namespace st {

namespace {
constexpr int v_uv = 1;  // input
}  // namespace

void BloomBrightFragment::bind(const Bindings& b) {
    hdr_ = &b.sampler("hdr");
    threshold_ = b.get_float("threshold");
}

uint32_t BloomBrightFragment::inputs_read() const { return reads(v_uv, "xy"); }

Vec4 BloomBrightFragment::main(const Fragment& frag) const {
    const Vec3 c = hdr_->sample(frag.varying(v_uv).xy()).xyz();
    auto bright = [&](Float x) { return simd::sqrt(glsl::max(x - Float(threshold_), Float(0.0f))); };
    return Vec4(bright(c.x), bright(c.y), bright(c.z), Float(1.0f));
}

}  // namespace st
