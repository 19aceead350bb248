// primitives.h: the few operations the built-ins of shading/builtins/ are
// written in, under one name for both number types, so that each built-in
// is one template: scalar:: for `float` (vertex twins, host code), lanes::
// for `Float` (fragment twins, one invocation per lane). Each operation is
// the instruction llvmpipe's code uses (docs/llvmpipe/glsl-builtins.md,
// section 0.3); none is a GLSL built-in itself.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

#include "simd/lane_vec.h"

namespace st::glsl {

namespace scalar {
ST_INLINE float select(bool m, float a, float b) { return m ? a : b; }
ST_INLINE int32_t select(bool m, int32_t a, int32_t b) { return m ? a : b; }
ST_INLINE bool isnan(float x) { return x != x; }
// gallivm's lp_build_fmuladd: one rounding on an FMA host. Only gallivm's
// own helpers fuse (polynomials, range reduction); GLSL's fma() does not.
ST_INLINE float fmuladd(float a, float b, float c) { return std::fma(a, b, c); }
// roundss 1, 2, 3 and 0: exact, as llvm.floor, ceil, trunc and nearbyint.
// As roundps in the shading threads, whatever the C library does
// (simd::like_roundps): a denormal rounds as +-0, a signalling NaN is quieted.
ST_INLINE float floor(float x) { return simd::like_roundps(x, [](float v) { return std::floor(v); }); }
ST_INLINE float ceil(float x) { return simd::like_roundps(x, [](float v) { return std::ceil(v); }); }
ST_INLINE float trunc(float x) { return simd::like_roundps(x, [](float v) { return std::trunc(v); }); }
ST_INLINE float round_even(float x) { return simd::like_roundps(x, [](float v) { return std::nearbyint(v); }); }
ST_INLINE float sqrt(float x) { return std::sqrt(x); }
ST_INLINE float abs(float x) { return std::fabs(x); }
// GLSL's max and min, as gallivm emits fmax and fmin (lp_build_max_ext's
// default path): MAXPS(p, q) = p > q ? p : q, or p where q is NaN. So a
// NaN in either operand gives the other, and a tie gives q: max(-0.0, 0.0)
// is +0.0 and max(0.0, -0.0) is -0.0 (found by explore profile --seed 2026:
// a back-lit sheet's irradiance, max(dot(n, l), 0.0) of a -0.0 dot, was
// -0.0 in the twin and +0.0 in llvmpipe). Where NIR proves p is not NaN and
// cannot prove it of q (a constant first), llvmpipe swaps the operands; a
// twin writes the constant second, as every shader here does.
ST_INLINE float max(float p, float q) { return q != q ? p : simd::maxss(p, q); }
ST_INLINE float min(float p, float q) { return q != q ? p : simd::minss(p, q); }
// 2^i for an integral float i in [-126, 128]: the exponent field alone
// (128 gives +inf's pattern).
ST_INLINE float exponent_to_float(float i) {
    return std::bit_cast<float>(uint32_t(int32_t(i) + 127) << 23);
}
ST_INLINE int32_t bits_of(float x) { return std::bit_cast<int32_t>(x); }
ST_INLINE float from_bits(int32_t i) { return std::bit_cast<float>(i); }
ST_INLINE float int_to_float(int32_t i) { return float(i); }
// Wrapping int32 arithmetic, as the machine's (C++'s signed overflow is
// undefined; GLSL's and LLVM's wrap).
ST_INLINE int32_t wrapping_add(int32_t a, int32_t b) { return int32_t(uint32_t(a) + uint32_t(b)); }
ST_INLINE int32_t shift_left(int32_t a, int n) { return int32_t(uint32_t(a) << n); }
ST_INLINE int32_t imin(int32_t a, int32_t b) { return a < b ? a : b; }
// x with the quiet bit set: what x86 arithmetic makes of a NaN operand.
ST_INLINE float quiet(float x) { return from_bits(bits_of(x) | 0x00400000); }
// MINPS and MAXPS themselves (a NaN or a tie gives q): gallivm's min and max
// where it asks for no NaN rule (lp_build_min, lp_build_clamp).
ST_INLINE float minps(float p, float q) { return simd::minss(p, q); }
ST_INLINE float maxps(float p, float q) { return simd::maxss(p, q); }
// fptosi as cvttps2dq: truncation, INT32_MIN for NaN and out of range.
ST_INLINE int32_t itrunc(float x) {
    return x >= -2147483648.0f && x < 2147483648.0f ? int32_t(x) : INT32_MIN;
}
}  // namespace scalar

namespace lanes {
using simd::abs;
using simd::ceil;
using simd::floor;
using simd::isnan;
using simd::select;
using simd::sqrt;
using simd::trunc;
using simd::fmuladd;
ST_INLINE Float round_even(Float x) { return simd::round_even(x); }
// As scalar::max and min: a tie gives q, a NaN the other operand.
ST_INLINE Float max(Float p, Float q) { return simd::select(q != q, p, simd::maxps(p, q)); }
ST_INLINE Float min(Float p, Float q) { return simd::select(q != q, p, simd::minps(p, q)); }
ST_INLINE Float exponent_to_float(Float i) {
    return simd::bit_cast_float((simd::itrunc(i) + Int(127)) << 23);
}
ST_INLINE Int bits_of(Float x) { return simd::bit_cast_int(x); }
ST_INLINE Float from_bits(Int i) { return simd::bit_cast_float(i); }
ST_INLINE Float int_to_float(Int i) { return simd::to_float(i); }
ST_INLINE Int wrapping_add(Int a, Int b) { return a + b; }  // Int wraps
ST_INLINE Int shift_left(Int a, int n) { return a << n; }
ST_INLINE Int imin(Int a, Int b) { return simd::min(a, b); }
ST_INLINE Float quiet(Float x) { return from_bits(bits_of(x) | Int(0x00400000)); }
using simd::itrunc;
using simd::maxps;
using simd::minps;
}  // namespace lanes

// Where the built-ins' templates are written: both sets of primitives by
// name, found before the public built-ins of the same name in st::glsl
// (GLSL's fma, which does not fuse, beside fmuladd, which does).
namespace detail {
using scalar::select;
using lanes::select;
using scalar::isnan;
using lanes::isnan;
using scalar::fmuladd;
using lanes::fmuladd;
using scalar::floor;
using lanes::floor;
using scalar::ceil;
using lanes::ceil;
using scalar::trunc;
using lanes::trunc;
using scalar::round_even;
using lanes::round_even;
using scalar::sqrt;
using lanes::sqrt;
using scalar::abs;
using lanes::abs;
using scalar::max;
using lanes::max;
using scalar::min;
using lanes::min;
using scalar::exponent_to_float;
using lanes::exponent_to_float;
using scalar::bits_of;
using lanes::bits_of;
using scalar::from_bits;
using lanes::from_bits;
using scalar::int_to_float;
using lanes::int_to_float;
using scalar::wrapping_add;
using lanes::wrapping_add;
using scalar::shift_left;
using lanes::shift_left;
using scalar::imin;
using lanes::imin;
using scalar::minps;
using lanes::minps;
using scalar::maxps;
using lanes::maxps;
using scalar::itrunc;
using lanes::itrunc;
using scalar::quiet;
using lanes::quiet;

}  // namespace detail

}  // namespace st::glsl
