// unlocated_frag.cpp: twin of glsl/conformance/unlocated.frag, line for line.
#include "kernels/conformance/conformance.h"

namespace st {

namespace {
constexpr int vColour = 0, vUV = 1;  // input slots (input_names()), as the vertex twin writes them
}  // namespace

uint32_t UnlocatedFragment::inputs_read() const { return reads(vColour, "xyzw") | reads(vUV, "xy"); }

Vec4 UnlocatedFragment::main(const Fragment& frag) const {
    const Vec4 v_colour = frag.varying(vColour);
    const Vec2 v_uv = frag.varying(vUV).xy();
    const Vec3 c = v_colour.xyz() * Vec3(tint_);
    return Vec4(c.x * v_uv.x, c.y * v_uv.y, c.z, v_colour.w);
}

}  // namespace st
