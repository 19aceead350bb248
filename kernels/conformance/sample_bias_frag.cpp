// sample_bias_frag.cpp: twin of glsl/conformance/sample_bias.frag, line for
// line.
#include "kernels/conformance/conformance.h"

#include "texture/sampler2d.h"

namespace st {

namespace {
constexpr int v_colour = 0, v_uv = 1;  // inputs
}  // namespace

void SampleBiasFragment::bind(const Bindings& b) {
    tex_ = &b.sampler("tex");
    lod_min_ = b.get_float("lod_min");
    lod_max_ = b.get_float("lod_max");
}

uint32_t SampleBiasFragment::inputs_read() const { return reads(v_colour, "x") | reads(v_uv, "xy"); }

Vec4 SampleBiasFragment::main(const Fragment& frag) const {
    const Float bias = Float(lod_min_) + frag.varying(v_colour).x * (Float(lod_max_) - Float(lod_min_));
    return Vec4(tex_->sample_bias(frag.varying(v_uv).xy(), bias).xyz(), 1.0f);
}

}  // namespace st
