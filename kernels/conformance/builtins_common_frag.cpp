// builtins_common_frag.cpp: twin of glsl/conformance/builtins_common.frag,
// line for line. The three mixes are the three forms NIR gives them there
// (shading/builtins/common.h): mix, mix_strict, mix_from_one.
#include "kernels/conformance/conformance.h"

#include "kernels/conformance/builtin_inputs.h"

namespace st {

namespace {
// The edges with NaN's place taken by -2 (why: the GLSL).
constexpr int32_t kOthers[16] = {0x00000000, INT32_MIN,  0x3F800000,         int32_t(0xBF800000),
                                 0x3F000000, 0x40200000, int32_t(0xC0700000), 0x0DA24260,
                                 int32_t(0xF149F2CA), 0x7F61B1E6, 0x7F800000, int32_t(0xFF800000),
                                 int32_t(0xC0000000), 0x00400000, 0x3DCCCCCD, 0x40E00000};
constexpr int32_t kWeights[16] = {0x00000000, 0x3F800000, 0x3F000000,         0x3E800000, 0x3DCCCCCD, 0x3F666666,
                                  0x322BCC77, 0x3F7FFFFF, int32_t(0xBF000000), 0x3FC00000, INT32_MIN,  0x40000000,
                                  0x7FC00000, 0x7F800000, 0x3E99999A,         0x3F333333};
constexpr int32_t kExponents[16] = {0, 1, -1, 127, -127, 128, -126, 254, -254, 10, -10, 255, -300, 300, 23, -23};
}  // namespace

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
