// derivatives_frag.cpp: twin of glsl/conformance/derivatives.frag, line for
// line.
#include "kernels/conformance/conformance.h"

#include "shading/derivatives.h"
#include "shading/glsl_math.h"

namespace st {

namespace {
constexpr int v_uv = 1;  // input
}  // namespace

uint32_t DerivativesFragment::inputs_read() const { return reads(v_uv, "xy"); }

Vec4 DerivativesFragment::main(const Fragment& frag) const {
    const Vec2 uv = frag.varying(v_uv).xy();
    const Float f = uv.x * uv.y * Float(scale_) + uv.x * uv.x;
    const Vec2 g(dFdx(f), dFdy(f));
    const Float w = fwidth(f * f);
    const Float h = glsl::floor(f * 4.0f);
    return Vec4(g.x * 10.0f, g.y * 10.0f, w, dFdx(h) + dFdy(h) * 0.5f);
}

}  // namespace st
