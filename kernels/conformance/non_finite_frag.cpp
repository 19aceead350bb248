// non_finite_frag.cpp: twin of glsl/conformance/non_finite.frag, line for
// line. GLSL's < is an ordered comparison (false with a NaN) and != an
// unordered one (true), as Float's operators are.
#include "kernels/conformance/conformance.h"

namespace st {

namespace {
constexpr int v_uv = 1;  // input
}  // namespace

uint32_t NonFiniteFragment::inputs_read() const { return reads(v_uv, "xy"); }

Vec4 NonFiniteFragment::main(const Fragment& frag) const {
    const Vec2 uv = frag.varying(v_uv).xy() - 0.5f;
    const Float zero(zero_);
    const Float inf = uv.x / zero;
    const Float nan = uv.y * zero / zero;
    const Float picked = select(nan < 1.0f, Float(1.0f), Float(2.0f));
    const Float differs = select(nan != nan, Float(4.0f), Float(8.0f));
    return Vec4(inf, nan, picked + differs, uv.x * inf);
}

}  // namespace st
