// varyings_frag.cpp: twin of glsl/conformance/varyings.frag, line for line.
// The int and uint inputs are their flat slots' bits (floatBitsToInt).
#include "kernels/conformance/conformance.h"

namespace st {

namespace {
constexpr int v_smooth = 0, v_linear = 1, v_bits = 2, v_flat = 3, v_index = 4;  // inputs
}  // namespace

uint32_t VaryingsFragment::inputs_read() const {
    return reads(v_smooth, "xyzw") | reads(v_linear, "xyzw") | reads(v_bits, "xyzw") | reads(v_flat, "xyzw") |
           reads(v_index, "xy");
}

Interpolations VaryingsFragment::interpolations() const {
    Interpolations q{};
    q[v_linear] = Interpolation::NoPerspective;
    q[v_bits] = q[v_flat] = q[v_index] = Interpolation::Flat;
    return q;
}

Vec4 VaryingsFragment::main(const Fragment& frag) const {
    const IVec4 bits = glsl::floatBitsToInt(frag.varying(v_bits));
    const UVec2 index = glsl::floatBitsToUint(frag.varying(v_index).xy());
    if (show_ == 0) return glsl::intBitsToFloat(bits);
    if (show_ == 1) return frag.varying(v_flat);
    if (show_ == 2) return frag.varying(v_linear);
    if (show_ == 3) return frag.varying(v_smooth);
    return Vec4(frag.varying(v_smooth).x, frag.varying(v_linear).y, glsl::intBitsToFloat(bits.y + Int(1)),
                glsl::uintBitsToFloat(index.y));
}

}  // namespace st
