// trigonometry.h: GLSL's angle and trigonometry built-ins (radians,
// degrees, sin, cos, tan, asin, acos, atan of one and two arguments, sinh,
// cosh, tanh, asinh, acosh, atanh) as llvmpipe computes them, bit for bit
// (docs/llvmpipe/glsl-builtins.md, section 3; proved by the scenes
// conformance-builtins-trigonometry-*).
//
// Where llvmpipe is not what a reader expects:
// - sin and cos are gallivm's Cephes port (lp_build_sin_or_cos): a range
//   reduction by pi/4 in three fused steps and two degree-3 polynomials.
//   They lose accuracy as |x| grows, and past |x| * 4/pi = 2^31 the
//   octant is garbage (clamped to [-1, 1]); inf and NaN give NaN.
// - tan is sin / cos, each with its own reduction.
// - asin and acos are GLSL IR's polynomials (one set of coefficients each)
//   around sqrt(1 - |x|), unfused; asin(-0.0) is +0.0.
// - atan(v) is NIR's degree-11 odd polynomial on min(|v|, 1) / max(|v|, 1),
//   times sign(v): atan(NaN) and atan(-0.0) are +0.0, atan(1) is
//   0.785394847, not pi/4.
// - atan(y, x) works on s / t as s * (1 / t), treats |x| == |y| as tan = 1
//   (so atan(0, 0) is 3 pi / 4), and gives a number, not NaN, for NaN
//   arguments.
// - sinh, cosh, tanh, asinh, acosh, atanh are GLSL IR's formulas over this
//   file's exp and log; tanh clamps to [-10, 10] first (tanh(NaN) is -1).
#pragma once

#include <cstdint>

#include "shading/builtins/common.h"
#include "shading/builtins/exponential.h"

namespace st::glsl {

namespace detail {

// float(M_PI_2), float(M_PI / 180) and float(180 / M_PI) as the built-ins
// write them (builtin_functions.cpp: 0.0174532925f, 57.29578f).
inline constexpr float kHalfPi = 1.57079637f;  // 0x3FC90FDB
inline constexpr float kRadiansPerDegree = 0.0174532925f;
inline constexpr float kDegreesPerRadian = 57.29578f;

// lp_build_sin_or_cos. The octant j of |x| * 4/pi (rounded up to even),
// |x| less j pi/4 in three fused steps (DP1 + DP2 + DP3 = -pi/4), then the
// sine or the cosine polynomial by octant, the sign by octant, a clamp to
// [-1, 1] and NaN where x is not finite.
template <class F, bool kCos> ST_INLINE F sin_or_cos(F x) {
    using I = decltype(bits_of(x));
    const I xi = bits_of(x);
    const F ax = from_bits(xi & I(0x7FFFFFFF));
    const F scaled = ax * F(float(1.27323954473516));
    const I j_add = wrapping_add(itrunc(scaled), I(1));
    const I j = j_add & I(~1);
    const F yj = int_to_float(j);
    const I k = kCos ? wrapping_add(j, I(-2)) : j;
    const I sign_bit = kCos ? shift_left((k ^ I(-1)) & I(4), 29) : (xi ^ shift_left(j_add, 29)) & I(INT32_MIN);
    const auto sine_polynomial = (k & I(2)) == I(0);
    F r = fmuladd(yj, F(float(-0.78515625)), ax);
    r = fmuladd(yj, F(float(-2.4187564849853515625e-4)), r);
    r = fmuladd(yj, F(float(-3.77489497744594108e-8)), r);
    const F z = r * r;
    F c = fmuladd(z, F(float(2.443315711809948E-005)), F(float(-1.388731625493765E-003)));
    c = fmuladd(c, z, F(float(4.166664568298827E-002)));
    c = (c * z) * z;
    c = c - z * F(0.5f);
    c = c + F(1.0f);
    F s = fmuladd(z, F(float(-1.9515295891E-4)), F(float(8.3321608736E-3)));
    s = fmuladd(s, z, F(float(-1.6666654611E-1)));
    s = s * z;
    s = fmuladd(s, r, r);
    F y = from_bits(bits_of(select(sine_polynomial, s, c)) ^ sign_bit);
    y = maxps(minps(y, F(1.0f)), F(-1.0f));
    const auto finite = (xi & I(0x7F800000)) != I(0x7F800000);
    return select(finite, y, from_bits(I(0x7FC00000)));
}

// GLSL IR's asin_expr: sign(x) * (pi/2 - sqrt(1 - |x|) * (pi/2 + |x| * (pi/4 - 1
// + |x| * (p0 + |x| * p1)))), every operation rounded alone.
template <class F> ST_INLINE F asin_expr(F x, float p0, float p1) {
    const F a = abs(x);
    const F inner = F(kHalfPi) + a * (F(float(0.785398163397448309616) - 1.0f) + a * (F(p0) + a * F(p1)));
    return sign(x) * (F(kHalfPi) - sqrt(F(1.0f) - a) * inner);
}

// nir_atan: the odd polynomial of degree 11 on xr = min(|v|, 1) / max(|v|, 1)
// (min and max with a constant: MINPS and MAXPS, so NaN gives xr = 1), its
// terms summed in order, pi/2 - p where |v| > 1, times sign(v). The term
// x^11 A11 is (x^9 A11) x^2: x^11 is used once, and nir_opt_algebraic moves
// the constant inward ((a * b) * #c -> (a * #c) * b).
template <class F> ST_INLINE F atan(F v) {
    const F a = abs(v);
    const F xr = minps(a, F(1.0f)) / maxps(a, F(1.0f));
    const F x2 = xr * xr;
    const F x3 = x2 * xr;
    const F x5 = x3 * x2;
    const F x7 = x5 * x2;
    const F x9 = x7 * x2;
    F p = xr * F(0.9999793128310355f);
    p = p + x3 * F(-0.3326756418091246f);
    p = p + x5 * F(0.1938924977115610f);
    p = p + x7 * F(-0.1173503194786851f);
    p = p + x9 * F(0.0536813784310406f);
    p = p + (x9 * F(-0.0121323213173444f)) * x2;
    // b2f(1 < |v|) * (p * -2 + pi/2) + p, the fused multiply-adds split.
    const F w = select(F(1.0f) < a, (p * F(-2.0f) + F(kHalfPi)) + p, p);
    return w * sign(v);
}

// nir_atan2.
template <class F> ST_INLINE F atan2(F y, F x) {
    const auto flip = F(0.0f) >= x;
    const F ax = abs(x);
    const F s = select(flip, ax, y);
    const F t = select(flip, y, ax);
    const F scale = select(abs(t) >= F(1e18f), F(0.25f), F(1.0f));
    const F rcp_scaled_t = F(1.0f) / (t * scale);
    const F s_over_t = (s * scale) * rcp_scaled_t;
    const F tan = select(ax == abs(y), F(1.0f), abs(s_over_t));
    const F arc = select(flip, F(kHalfPi), F(0.0f)) + atan(tan);
    return select(detail::min(y, rcp_scaled_t) < F(0.0f), -arc, arc);
}

}  // namespace detail

// radians(d) = d * 0.0174532925f, degrees(r) = r * 57.29578f: one multiply.
ST_INLINE float radians(float d) { return d * detail::kRadiansPerDegree; }
ST_INLINE Float radians(Float d) { return d * Float(detail::kRadiansPerDegree); }
ST_GLSL_COMPONENTWISE_1(radians)
ST_INLINE float degrees(float r) { return r * detail::kDegreesPerRadian; }
ST_INLINE Float degrees(Float r) { return r * Float(detail::kDegreesPerRadian); }
ST_GLSL_COMPONENTWISE_1(degrees)

ST_INLINE float sin(float x) { return detail::sin_or_cos<float, false>(x); }
ST_INLINE Float sin(Float x) { return detail::sin_or_cos<Float, false>(x); }
ST_GLSL_COMPONENTWISE_1(sin)
ST_INLINE float cos(float x) { return detail::sin_or_cos<float, true>(x); }
ST_INLINE Float cos(Float x) { return detail::sin_or_cos<Float, true>(x); }
ST_GLSL_COMPONENTWISE_1(cos)
ST_INLINE float tan(float x) { return sin(x) / cos(x); }
ST_INLINE Float tan(Float x) { return sin(x) / cos(x); }
ST_GLSL_COMPONENTWISE_1(tan)

ST_INLINE float asin(float x) { return detail::asin_expr(x, 0.086566724f, -0.03102955f); }
ST_INLINE Float asin(Float x) { return detail::asin_expr(x, 0.086566724f, -0.03102955f); }
ST_GLSL_COMPONENTWISE_1(asin)
// acos(x) = pi/2 - asin_expr(x) with its own coefficients.
ST_INLINE float acos(float x) { return detail::kHalfPi - detail::asin_expr(x, 0.08132463f, -0.02363318f); }
ST_INLINE Float acos(Float x) { return Float(detail::kHalfPi) - detail::asin_expr(x, 0.08132463f, -0.02363318f); }
ST_GLSL_COMPONENTWISE_1(acos)

ST_INLINE float atan(float y_over_x) { return detail::atan(y_over_x); }
ST_INLINE Float atan(Float y_over_x) { return detail::atan(y_over_x); }
ST_GLSL_COMPONENTWISE_1(atan)
ST_INLINE float atan(float y, float x) { return detail::atan2(y, x); }
ST_INLINE Float atan(Float y, Float x) { return detail::atan2(y, x); }
ST_GLSL_COMPONENTWISE_2(atan)

// 0.5 * (exp(x) - exp(-x)) and 0.5 * (exp(x) + exp(-x)), exp as exp2(x *
// log2 e). For NaN x both exps are NaN and llvmpipe's sum keeps the first,
// x's own NaN quieted (measured). The twin says so outright: GCC rewrites
// (-x) * c as -(x * c) or x * -c as it likes, which moves a NaN's sign bit,
// and C++ leaves a NaN's sign to the compiler.
namespace detail {
template <class F> ST_INLINE F sinh(F x) { return select(isnan(x), quiet(x), F(0.5f) * (exp(x) - exp(-x))); }
template <class F> ST_INLINE F cosh(F x) { return select(isnan(x), quiet(x), F(0.5f) * (exp(x) + exp(-x))); }
}  // namespace detail
ST_INLINE float sinh(float x) { return detail::sinh(x); }
ST_INLINE Float sinh(Float x) { return detail::sinh(x); }
ST_GLSL_COMPONENTWISE_1(sinh)
ST_INLINE float cosh(float x) { return detail::cosh(x); }
ST_INLINE Float cosh(Float x) { return detail::cosh(x); }
ST_GLSL_COMPONENTWISE_1(cosh)
// t = clamp(x, -10, 10), then (exp(t) - exp(-t)) / (exp(t) + exp(-t)).
ST_INLINE float tanh(float x) {
    const float t = clamp(x, -10.0f, 10.0f), p = exp(t), q = exp(-t);
    return (p - q) / (p + q);
}
ST_INLINE Float tanh(Float x) {
    const Float t = clamp(x, Float(-10.0f), Float(10.0f)), p = exp(t), q = exp(-t);
    return (p - q) / (p + q);
}
ST_GLSL_COMPONENTWISE_1(tanh)
// sign(x) * log(|x| + sqrt(x * x + 1)).
ST_INLINE float asinh(float x) { return sign(x) * log(abs(x) + sqrt(x * x + 1.0f)); }
ST_INLINE Float asinh(Float x) { return sign(x) * log(abs(x) + sqrt(x * x + Float(1.0f))); }
ST_GLSL_COMPONENTWISE_1(asinh)
// log(x + sqrt(x * x - 1)).
ST_INLINE float acosh(float x) { return log(x + sqrt(x * x - 1.0f)); }
ST_INLINE Float acosh(Float x) { return log(x + sqrt(x * x - Float(1.0f))); }
ST_GLSL_COMPONENTWISE_1(acosh)
// 0.5 * log((1 + x) / (1 - x)).
ST_INLINE float atanh(float x) { return 0.5f * log((1.0f + x) / (1.0f - x)); }
ST_INLINE Float atanh(Float x) { return Float(0.5f) * log((Float(1.0f) + x) / (Float(1.0f) - x)); }
ST_GLSL_COMPONENTWISE_1(atanh)

}  // namespace st::glsl
