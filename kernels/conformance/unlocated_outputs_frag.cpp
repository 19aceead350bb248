// unlocated_outputs_frag.cpp: twin of glsl/conformance/unlocated_outputs.frag,
// line for line. Its outputs have no locations; the scene binds `normal` to
// 0 and `colour` to 1 (DrawCall::output_names), so main() returns them in
// that order.
#include "kernels/conformance/conformance.h"

namespace st {

namespace {
constexpr int vColour = 0, vUV = 1;  // input slots (input_names()), as the vertex twin writes them
}  // namespace

uint32_t UnlocatedOutputsFragment::inputs_read() const { return reads(vColour, "xyzw") | reads(vUV, "xy"); }

FragmentOutputs<2> UnlocatedOutputsFragment::main(const Fragment& frag) const {
    const Vec4 v_colour = frag.varying(vColour);
    const Vec2 v_uv = frag.varying(vUV).xy();
    const Vec4 colour(v_colour.xyz() * Vec3(tint_), v_colour.w);
    const Vec4 normal(v_uv * Float(2.0f) - Vec2(Float(1.0f)), v_uv.x * v_uv.y, Float(0.5f));
    return {normal, colour};
}

}  // namespace st
