// builtins_common_frag.cpp: twin of glsl/conformance/builtins_common.frag,
// line for line. The three mixes are the three forms NIR gives them there
// (shading/builtins/common.h): mix, mix_strict, mix_from_one.
#include "kernels/conformance/conformance.h"

#include "kernels/conformance/builtin_inputs.h"

namespace st {

Vec4 BuiltinsCommonFragment::main(const Fragment& frag) const {
    using namespace glsl;
    using namespace builtin_inputs;
    const Int index = pixel_index(frag);
    const Float x = from_bits_of(index);
    const Float y = edge_of(index);
    const Float z = intBitsToFloat(element(kEdges, ((index >> 2) ^ (index >> 7) ^ 5) & 15));
    const Float t = intBitsToFloat(element(kWeights, (index ^ (index >> 5)) & 15));
    const Float u = intBitsToFloat(element(kWeights, ((index >> 3) ^ (index >> 9) ^ 9) & 15));
    const Int e = element(kExponents, ((index >> 1) ^ (index >> 6)) & 15);
    if (group_ == 0) {
        return Vec4(sign(x), floor(x), trunc(x), ceil(x));
    } else if (group_ == 1) {
        Float whole;
        return Vec4(round(x), roundEven(x), fract(x), modf(x, whole));
    } else if (group_ == 2) {
        Float whole;
        modf(x, whole);
        return Vec4(whole, mod(x, y), min(x, y), max(x, y));
    } else if (group_ == 3) {
        return Vec4(clamp(x, y, z), step(y, x), smoothstep(y, z, x), mix(x, y, t));
    } else if (group_ == 4) {
        const Float y4 = intBitsToFloat(element(kOthers, (index ^ (index >> 4) ^ (index >> 8)) & 15));
        const Float z4 = intBitsToFloat(element(kOthers, ((index >> 2) ^ (index >> 7) ^ 5) & 15));
        return Vec4(mix_strict(x, y4, Float(0.3f)), mix_from_one(y4, u), mix(x, y, (index & 2) != Int(0)), fma(x, y4, z4));
    } else {
        Int frexp_exponent;
        const Float mantissa_part = frexp(x, frexp_exponent);
        return Vec4(mantissa_part, float_of(frexp_exponent), ldexp(x, e), float_of(isnan(x)) + 2.0f * float_of(isinf(x)));
    }
}

}  // namespace st
