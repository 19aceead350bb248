// sample_grad_frag.cpp: twin of glsl/conformance/sample_grad.frag, line for
// line.
#include "kernels/conformance/conformance.h"

#include "shading/derivatives.h"
#include "texture/sampler2d.h"

namespace st {

namespace {
constexpr int v_colour = 0, v_uv = 1;  // inputs
}  // namespace

uint32_t SampleGradFragment::inputs_read() const { return reads(v_colour, "xy") | reads(v_uv, "xy"); }

Vec4 SampleGradFragment::main(const Fragment& frag) const {
    const Vec2 uv = frag.varying(v_uv).xy();
    const Vec2 dx = dFdx(uv) * (frag.varying(v_colour).x * Float(grad_scale_));
    const Vec2 dy = dFdy(uv) * (frag.varying(v_colour).y * Float(grad_scale_));
    return Vec4(tex_->sample_grad(uv, dx, dy).xyz(), 1.0f);
}

}  // namespace st
