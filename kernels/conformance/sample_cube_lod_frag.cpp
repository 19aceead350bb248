// sample_cube_lod_frag.cpp: twin of glsl/conformance/sample_cube_lod.frag,
// line for line.
#include "kernels/conformance/conformance.h"

#include "texture/sampler_cube.h"

namespace st {

namespace {
constexpr int v_colour = 0, v_uv = 1;  // inputs
}  // namespace

void SampleCubeLodFragment::bind(const Bindings& b) {
    env_ = &b.sampler_cube("env");
    lod_min_ = b.get_float("lod_min");
    lod_max_ = b.get_float("lod_max");
}

uint32_t SampleCubeLodFragment::inputs_read() const { return reads(v_colour, "xz") | reads(v_uv, "xy"); }

Vec4 SampleCubeLodFragment::main(const Fragment& frag) const {
    const Vec3 dir(frag.varying(v_uv).x, frag.varying(v_uv).y, frag.varying(v_colour).z * 2.0f - 1.0f);
    const Float lod = Float(lod_min_) + frag.varying(v_colour).x * (Float(lod_max_) - Float(lod_min_));
    return Vec4(env_->sample_lod(dir, lod).xyz(), 1.0f);
}

}  // namespace st
