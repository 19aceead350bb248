// sample_cube_bias_frag.cpp: twin of glsl/conformance/sample_cube_bias.frag,
// line for line.
#include "kernels/conformance/conformance.h"

#include "texture/sampler_cube.h"

namespace st {

namespace {
constexpr int v_colour = 0, v_uv = 1;  // inputs
}  // namespace

void SampleCubeBiasFragment::bind(const Bindings& b) {
    env_ = &b.sampler_cube("env");
    lod_min_ = b.get_float("lod_min");
    lod_max_ = b.get_float("lod_max");
}

uint32_t SampleCubeBiasFragment::inputs_read() const { return reads(v_colour, "xz") | reads(v_uv, "xy"); }

Vec4 SampleCubeBiasFragment::main(const Fragment& frag) const {
    const Vec3 dir(frag.varying(v_uv).x, frag.varying(v_uv).y, frag.varying(v_colour).z * 2.0f - 1.0f);
    const Float bias = Float(lod_min_) + frag.varying(v_colour).x * (Float(lod_max_) - Float(lod_min_));
    return Vec4(env_->sample_bias(dir, bias).xyz(), 1.0f);
}

}  // namespace st
