// builtin_inputs.h: the inputs the built-in families' programs
// (glsl/conformance/builtins_*.frag) enumerate, as their twins read them:
// the same tables and the same lines as the GLSL's `mantissas`, `edges` and
// the x built from the pixel's index.
#pragma once

#include <cstdint>

#include "shading/glsl_math.h"

namespace st::builtin_inputs {

inline constexpr int32_t kMantissas[8] = {0, 1, 0x400000, 0x7FFFFF, 0x2AAAAA, 0x555555, 0x123457, 0x7FFFFE};
// 0, -0, 1, -1, 0.5, 2.5, -3.75, 1e-30, -1e30, 3e38, inf, -inf, NaN, a
// denormal, 0.1, 7.
inline constexpr int32_t kEdges[16] = {0x00000000, INT32_MIN,  0x3F800000,          int32_t(0xBF800000),
                                       0x3F000000, 0x40200000, int32_t(0xC0700000), 0x0DA24260,
                                       int32_t(0xF149F2CA), 0x7F61B1E6, 0x7F800000, int32_t(0xFF800000),
                                       0x7FC00000, 0x00400000, 0x3DCCCCCD,          0x40E00000};
// The edges with NaN's place taken by -2 (the GLSL's `others`: where two
// NaNs meet, the payload is the operand order, glsl-builtins.md 0.3).
inline constexpr int32_t kOthers[16] = {0x00000000, INT32_MIN,  0x3F800000,          int32_t(0xBF800000),
                                        0x3F000000, 0x40200000, int32_t(0xC0700000), 0x0DA24260,
                                        int32_t(0xF149F2CA), 0x7F61B1E6, 0x7F800000, int32_t(0xFF800000),
                                        int32_t(0xC0000000), 0x00400000, 0x3DCCCCCD, 0x40E00000};
// Blend weights: 0, 1, 0.5, 0.25, 0.1, 0.9, 1e-8, the float below 1, -0.5,
// 1.5, -0, 2, NaN, inf, 0.3, 0.7.
inline constexpr int32_t kWeights[16] = {0x00000000, 0x3F800000, 0x3F000000,         0x3E800000, 0x3DCCCCCD, 0x3F666666,
                                         0x322BCC77, 0x3F7FFFFF, int32_t(0xBF000000), 0x3FC00000, INT32_MIN,  0x40000000,
                                         0x7FC00000, 0x7F800000, 0x3E99999A,         0x3F333333};
// ldexp's exponents: past the range both ways.
inline constexpr int32_t kExponents[16] = {0, 1, -1, 127, -127, 128, -126, 254, -254, 10, -10, 255, -300, 300, 23, -23};

// The pixel's index in a 64-wide image (GLSL: p.y * 64 + p.x).
inline Int pixel_index(const Fragment& frag) {
    const IVec2 p(frag.frag_coord().xy());
    return p.y * 64 + p.x;
}

// x from the index's bits: the sign from bit 0, the exponent from bits 1-8,
// a mantissa pattern from bits 9-11.
inline Float from_bits_of(Int index) {
    const Int sign_bit = index & 1;
    const Int exponent = (index >> 1) & 255;
    const Int mantissa = glsl::element(kMantissas, (index >> 9) & 7);
    return glsl::intBitsToFloat((sign_bit << 31) | (exponent << 23) | mantissa);
}

// edges[(index ^ (index >> 4) ^ (index >> 8)) & 15], the second operand.
inline Float edge_of(Int index) { return glsl::intBitsToFloat(glsl::element(kEdges, (index ^ (index >> 4) ^ (index >> 8)) & 15)); }

// value(index, k) of the geometric, matrix and rewrite programs: a finite value for
// component k, one of 1024 steps of 0.0137 around zero scaled by 2^-6 ... 2^9.
inline Float finite_value(Int index, int k) {
    const Int h = (index * Int(2 * k + 37) + Int(k * 101)) & 1023;
    const Int e = ((index >> (k & 7)) + Int(k)) & 15;
    return float_of(h - Int(512)) * 0.0137f * glsl::intBitsToFloat((e + Int(121)) << 23);
}

// column(index, k) of the matrix and probe programs: finite values 4k ... 4k + 3.
inline Vec4 finite_column(Int index, int k) {
    return Vec4(finite_value(index, 4 * k), finite_value(index, 4 * k + 1), finite_value(index, 4 * k + 2),
                finite_value(index, 4 * k + 3));
}

}  // namespace st::builtin_inputs
