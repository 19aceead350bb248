// outputs_frag.cpp: twin of glsl/conformance/outputs.frag, line for line;
// main() returns the value of each output location in turn.
#include "kernels/conformance/conformance.h"

namespace st {

namespace {
constexpr int v_colour = 0, v_uv = 1;  // inputs
}  // namespace

void OutputsFragment::bind(const Bindings& b) {
    exposure_ = b.get<float>("exposure");
    cut_ = b.get<float>("cut");
}

uint32_t OutputsFragment::inputs_read() const { return reads(v_colour, "xyzw") | reads(v_uv, "xy"); }

FragmentOutputs<3> OutputsFragment::main(const Fragment& frag) const {
    Exec& exec = frag.exec();
    const Vec4 colour = frag.varying(v_colour);
    const Vec2 uv = frag.varying(v_uv).xy();
    exec.discard_if(uv.x > Float(cut_));
    const Vec2 n = uv * Float(2.0f) - Vec2(Float(1.0f));
    return {colour, Vec4(n, uv.x * uv.y, Float(0.75f)), Vec4(colour.xyz() * Float(exposure_), uv.y)};
}

}  // namespace st
