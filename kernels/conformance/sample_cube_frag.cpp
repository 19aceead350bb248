// sample_cube_frag.cpp: twin of glsl/conformance/sample_cube.frag, line for
// line.
#include "kernels/conformance/conformance.h"

#include "texture/sampler_cube.h"

namespace st {

namespace {
constexpr int v_colour = 0, v_uv = 1;  // inputs
}  // namespace

uint32_t SampleCubeFragment::inputs_read() const { return reads(v_colour, "z") | reads(v_uv, "xy"); }

Vec4 SampleCubeFragment::main(const Fragment& frag) const {
    const Vec3 dir(frag.varying(v_uv).x, frag.varying(v_uv).y, frag.varying(v_colour).z * 2.0f - 1.0f);
    return Vec4(env_->sample(dir).xyz(), 1.0f);
}

}  // namespace st
