// sample_cube_grad_frag.cpp: twin of glsl/conformance/sample_cube_grad.frag,
// line for line.
#include "kernels/conformance/conformance.h"

#include "shading/derivatives.h"
#include "texture/sampler_cube.h"

namespace st {

namespace {
constexpr int v_colour = 0, v_uv = 1;  // inputs
}  // namespace

uint32_t SampleCubeGradFragment::inputs_read() const { return reads(v_colour, "xz") | reads(v_uv, "xy"); }

Vec4 SampleCubeGradFragment::main(const Fragment& frag) const {
    const Vec3 dir(frag.varying(v_uv).x, frag.varying(v_uv).y, frag.varying(v_colour).z * 2.0f - 1.0f);
    const Float scale = frag.varying(v_colour).x * Float(grad_scale_);
    const Vec3 dx = dFdx(dir) * scale;
    const Vec3 dy = dFdy(dir) * scale;
    return Vec4(env_->sample_grad(dir, dx, dy).xyz(), 1.0f);
}

}  // namespace st
