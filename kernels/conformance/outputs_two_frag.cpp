// outputs_two_frag.cpp: twin of glsl/conformance/outputs_two.frag, line for
// line; main() returns the value of each output location in turn.
#include "kernels/conformance/conformance.h"

namespace st {

namespace {
constexpr int v_colour = 0, v_uv = 1;  // inputs
}  // namespace

uint32_t OutputsTwoFragment::inputs_read() const { return reads(v_colour, "xyzw") | reads(v_uv, "xy"); }

FragmentOutputs<2> OutputsTwoFragment::main(const Fragment& frag) const {
    const Vec4 colour = frag.varying(v_colour);
    const Vec2 uv = frag.varying(v_uv).xy();
    return {Vec4(colour.xyz() * Float(exposure_), colour.w), Vec4(uv, uv.x - uv.y, Float(1.0f))};
}

}  // namespace st
