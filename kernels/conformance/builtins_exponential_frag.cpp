// builtins_exponential_frag.cpp: twin of
// glsl/conformance/builtins_exponential.frag, line for line.
#include "kernels/conformance/conformance.h"

#include "shading/glsl_math.h"

namespace st {

namespace {
constexpr int32_t kMantissas[8] = {0, 1, 0x400000, 0x7FFFFF, 0x2AAAAA, 0x555555, 0x123457, 0x7FFFFE};
}  // namespace

Vec4 BuiltinsExponentialFragment::main(const Fragment& frag) const {
    const IVec2 p(frag.frag_coord().xy());
    const Int index = p.y * 64 + p.x;
    const Int sign_bit = index & 1;
    const Int exponent = (index >> 1) & 255;
    Int mantissa;
    const Int which = (index >> 9) & 7;
    for (int lane = 0; lane < kLanes; ++lane) mantissa.set(lane, kMantissas[which[lane]]);
    const Float x = simd::bit_cast_float((sign_bit << 31) | (exponent << 23) | mantissa);
    const Float y = simd::to_float((index >> 3) & 15) * 0.5f - 3.0f;
    if (group_ == 0) return Vec4(glsl::log2(x), glsl::log(x), glsl::pow(x, y), glsl::pow(glsl::abs(x), y));
    return Vec4(glsl::exp2(x), glsl::exp(x), simd::sqrt(x), glsl::inversesqrt(x));
}

}  // namespace st
