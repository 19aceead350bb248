// sample_lod_frag.cpp: twin of glsl/conformance/sample_lod.frag, line for
// line.
#include "kernels/conformance/conformance.h"

#include "texture/sampler2d.h"

namespace st {

namespace {
constexpr int v_colour = 0, v_uv = 1;  // inputs
}  // namespace

void SampleLodFragment::bind(const Bindings& b) {
    tex_ = &b.sampler("tex");
    lod_min_ = b.get_float("lod_min");
    lod_max_ = b.get_float("lod_max");
}

uint32_t SampleLodFragment::inputs_read() const { return reads(v_colour, "x") | reads(v_uv, "xy"); }

Vec4 SampleLodFragment::main(const Fragment& frag) const {
    const Float lod = Float(lod_min_) + frag.varying(v_colour).x * (Float(lod_max_) - Float(lod_min_));
    return Vec4(tex_->sample_lod(frag.varying(v_uv).xy(), lod).xyz(), 1.0f);
}

}  // namespace st
