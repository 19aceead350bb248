// sample_implicit_frag.cpp: twin of glsl/conformance/sample_implicit.frag,
// line for line.
#include "kernels/conformance/conformance.h"

#include "texture/sampler2d.h"

namespace st {

namespace {
constexpr int v_colour = 0, v_uv = 1;  // inputs
}  // namespace

uint32_t SampleImplicitFragment::inputs_read() const { return reads(v_colour, "xyzw") | reads(v_uv, "xy"); }

Vec4 SampleImplicitFragment::main(const Fragment& frag) const {
    return tex_->sample(frag.varying(v_uv).xy()) * frag.varying(v_colour);
}

}  // namespace st
