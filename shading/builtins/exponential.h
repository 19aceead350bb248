// exponential.h: GLSL's exponential built-ins (pow, exp, log, exp2, log2,
// sqrt, inversesqrt) as llvmpipe computes them, bit for bit
// (docs/llvmpipe/glsl-builtins.md, section 1; proved by the scenes
// conformance-builtins-exponential and -exp).
//
// What llvmpipe does (Mesa 22.3, NIR + gallivm), for an FMA3 host:
// - exp(x) is exp2(x * fl(log2 e)) (glsl_to_nir), exp2 is lp_build_exp2: clamp
//   to [-126.99999, 128], split into floor and fraction, 2^fraction from a
//   degree-5 minimax polynomial evaluated with fused multiply-adds (odd and
//   even terms apart), times 2^floor built in the exponent bits.
// - log2 is lp_build_log2_safe, log is log2 times fl(ln 2), pow is
//   exp2(log2(x) * y) with pow(0, y) = 0.
// - inversesqrt(x) is 1 / sqrt(x), two correctly rounded operations.
// The arithmetic follows gallivm/lp_bld_arit.c (lp_build_exp2,
// lp_build_polynomial, lp_build_ifloor_fract, lp_build_rsqrt).
#pragma once

#include <limits>

#include "shading/builtins/componentwise.h"
#include "shading/builtins/primitives.h"

namespace st::glsl {

namespace detail {

// 2^x on [0, 1): minimax fit, the coefficients llvmpipe uses, as floats.
inline constexpr float kExp2Poly[6] = {
    float(1.000000000000000000000), float(0.693153073200168932794), float(0.240153617044375388211),
    float(0.0558263180532956664775), float(0.00898934009049466391101), float(0.00187757667519147912699),
};

// Even and odd coefficients in two Horner chains over x^2, joined by one
// more multiply-add: c0 + x2 (c2 + x2 c4) + x (c1 + x2 (c3 + x2 c5)).
template <class F> ST_INLINE F exp2_polynomial(F x) {
    const F x2 = x * x;
    F even = F(kExp2Poly[4]);
    even = fmuladd(x2, even, F(kExp2Poly[2]));
    even = fmuladd(x2, even, F(kExp2Poly[0]));
    F odd = F(kExp2Poly[5]);
    odd = fmuladd(x2, odd, F(kExp2Poly[3]));
    odd = fmuladd(x2, odd, F(kExp2Poly[1]));
    return fmuladd(odd, x, even);
}

template <class F> ST_INLINE F exp2(F x) {
    const auto nan = isnan(x);
    F c = select(x < F(128.0f), x, F(128.0f));
    c = select(c > F(-126.99999f), c, F(-126.99999f));
    const F ipart = floor(c);
    const F fpart = c - ipart;
    const F r = exponent_to_float(ipart) * exp2_polynomial(fpart);
    // NaN passes through, quieted as llvmpipe's arithmetic on it quiets it
    // (found by conformance-builtins-exponential-exp: exp2 of a signalling
    // NaN is the quiet NaN of its payload). The quiet bit is set with
    // integer code: x + x served too, but a compiler may rewrite float
    // arithmetic on NaN freely (GCC gave exp(NaN) the default NaN beside an
    // exp(-x)), and integer code it leaves alone.
    return select(nan, quiet(x), r);
}

// log2 of m in [1, 2) as y P(y^2), y = (m - 1) / (m + 1): the coefficients
// of lp_build_log2_approx (LOG_POLY_DEGREE 4), as floats.
inline constexpr uint32_t kLog2Poly[5] = {0x4038AA3B, 0x3F7637F9, 0x3F13D321, 0x3ECE8316, 0x3ED03D59};
template <class F> ST_INLINE F log2_coefficient(int k) { return F(std::bit_cast<float>(kLog2Poly[k])); }

// log2(x) as lp_build_log2_safe (docs/llvmpipe/glsl-builtins.md 1.3): the
// exponent E and the mantissa m of x's bits, y = (m - 1) / (m + 1), the
// polynomial in z = y^2 with its even and odd terms apart and every
// multiply-add fused, then y P + E, fused. No re-centring about sqrt 2, so
// just below 1 the relative error is large, as in llvmpipe. The edges are
// unordered compares, in this order: x >= inf gives +inf, x == 0 gives -inf
// (denormals too, under DAZ), x < 0 gives NaN; a NaN takes all three and
// comes out as 0x7FC00000, its payload lost.
template <class F> ST_INLINE F log2(F x) {
    using I = decltype(bits_of(x));
    const I i = bits_of(x);
    const F e = int_to_float(((i & I(0x7F800000)) >> 23) - I(127));
    const F m = from_bits((i & I(0x007FFFFF)) | I(0x3F800000));
    const F y = (m - F(1.0f)) / (m + F(1.0f));
    const F z = y * y;
    const F z2 = z * z;
    const F even = fmuladd(z2, fmuladd(z2, log2_coefficient<F>(4), log2_coefficient<F>(2)), log2_coefficient<F>(0));
    const F odd = fmuladd(z2, log2_coefficient<F>(3), log2_coefficient<F>(1));
    const F p = fmuladd(odd, z, even);
    F r = fmuladd(y, p, e);
    const F inf = F(std::numeric_limits<float>::infinity());
    r = select(!(x < inf), inf, r);                          // UGE(x, +inf)
    r = select((x == F(0.0f)) || isnan(x), -inf, r);         // UEQ(x, 0)
    r = select(!(x >= F(0.0f)), F(from_bits(0x7FC00000)), r);  // ULT(x, 0)
    return r;
}

// pow(x, y) as lp_build_pow: exp2(log2(x) * y), then +0 where x == 0
// (unordered: NaN x too). So pow(NaN, y) and pow(0, y <= 0) are +0, and a
// negative x gives NaN even for an integral y (glsl-builtins.md 1.5).
template <class F> ST_INLINE F pow(F x, F y) {
    const F r = exp2(log2(x) * y);
    return select((x == F(0.0f)) || isnan(x), F(0.0f), r);
}

}  // namespace detail

ST_INLINE float exp2(float x) { return detail::exp2(x); }
ST_INLINE Float exp2(Float x) { return detail::exp2(x); }

// M_LOG2E as NIR folds it.
inline constexpr float kLog2e = float(1.44269504088896340736);
ST_INLINE float exp(float x) { return exp2(x * kLog2e); }
ST_INLINE Float exp(Float x) { return exp2(x * Float(kLog2e)); }

ST_INLINE float log2(float x) { return detail::log2(x); }
ST_INLINE Float log2(Float x) { return detail::log2(x); }
// log(x) = log2(x) * fl(ln 2) (glsl_to_nir: flog2, then one multiply).
inline constexpr float kLn2 = float(0.69314718055994530942);
ST_INLINE float log(float x) { return log2(x) * kLn2; }
ST_INLINE Float log(Float x) { return log2(x) * Float(kLn2); }
// pow(x, y) (lp_build_pow). A constant y of 1, 2 or 4 and a constant x of 1
// or 2 are rewritten by the compiler first (x, x*x, (x*x)*(x*x), 1,
// exp2(y)): a twin writes what the compiler leaves.
ST_INLINE float pow(float x, float y) { return detail::pow(x, y); }
ST_INLINE Float pow(Float x, Float y) { return detail::pow(x, y); }

ST_INLINE float sqrt(float x) { return std::sqrt(x); }  // sqrtps: correctly rounded
ST_INLINE double sqrt(double x) { return std::sqrt(x); }  // sqrtpd: correctly rounded
using simd::sqrt;
ST_INLINE float inversesqrt(float x) { return 1.0f / std::sqrt(x); }
ST_INLINE double inversesqrt(double x) { return 1.0 / std::sqrt(x); }
ST_INLINE Double inversesqrt(Double x) { return Double(1.0) / simd::sqrt(x); }
ST_INLINE Float inversesqrt(Float x) { return Float(1.0f) / simd::sqrt(x); }

// The genType forms (vec2-vec4, and dvecN where a double form exists),
// component by component as NIR scalarises them.
ST_GLSL_COMPONENTWISE_1(exp2)
ST_GLSL_COMPONENTWISE_1(exp)
ST_GLSL_COMPONENTWISE_1(log2)
ST_GLSL_COMPONENTWISE_1(log)
ST_GLSL_COMPONENTWISE_2(pow)
ST_GLSL_COMPONENTWISE_1(sqrt)
ST_GLSL_COMPONENTWISE_1(inversesqrt)

}  // namespace st::glsl
