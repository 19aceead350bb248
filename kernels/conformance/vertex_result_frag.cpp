// vertex_result_frag.cpp: twin of glsl/conformance/vertex_result.frag, line
// for line.
#include "kernels/conformance/conformance.h"

namespace st {

namespace {
constexpr int v_colour = 0, v_uv = 1;  // inputs
}  // namespace

uint32_t VertexResultFragment::inputs_read() const { return reads(v_colour, "xyzw") | reads(v_uv, "xyzw"); }

Vec4 VertexResultFragment::main(const Fragment& frag) const {
    const Vec4 high = frag.varying(v_colour), low = frag.varying(v_uv);
    const auto join = [](const Float& h, const Float& l) {
        return glsl::uintBitsToFloat((uint_of(h) << 16) | uint_of(l));
    };
    return Vec4(join(high.x, low.x), join(high.y, low.y), join(high.z, low.z), join(high.w, low.w));
}

}  // namespace st
