// glsl_math.h: GLSL built-in functions as llvmpipe evaluates them, the one
// place where twins get them. Every transcendental function a twin calls
// comes from here, so all twins round alike and one fix reaches all. Each
// is written once, as a template over the number type: `float` for vertex
// twins and host code, `Float` (one invocation per lane, lane_vec.h) for
// fragment twins; both give the same bits per value.
//
// What llvmpipe does (Mesa 22.3, NIR + gallivm), for an FMA3 host:
// - exp(x) is exp2(x * fl(log2 e)) (glsl_to_nir), exp2 is lp_build_exp2: clamp
//   to [-126.99999, 128], split into floor and fraction, 2^fraction from a
//   degree-5 minimax polynomial evaluated with fused multiply-adds (odd and
//   even terms apart), times 2^floor built in the exponent bits.
// - inversesqrt(x) is 1 / sqrt(x), two correctly rounded operations.
// - dot() is lowered to products, unfused (lower_fdot), and for vec3 summed
//   as x + (y + z): measured bit for bit, though fsum3 reads left to right;
//   normalize(v) = v * inversesqrt(dot(v, v)); length(v) = sqrt(dot(v, v)).
// - mat4 * vec4 is the column sum ((c0 v.x + c1 v.y) + c2 v.z) + c3 v.w,
//   each product rounded (GLSL IR's matrix lowering).
// - a*b + c in GLSL is never fused (lower_ffma32): twins write it plainly,
//   and -ffp-contract=off keeps the compiler from fusing it.
// - max/min are gallivm's (lp_build_max_ext): one NaN operand gives the
//   other, and a tie gives the second operand, so max(-0.0, 0.0) is +0.0
//   (docs/llvmpipe/glsl-builtins.md, section 2.8).
// The arithmetic follows gallivm/lp_bld_arit.c (lp_build_exp2,
// lp_build_polynomial, lp_build_ifloor_fract, lp_build_rsqrt);
// docs/llvmpipe/ has the reading.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "simd/lane_vec.h"

namespace st::glsl {

// The handful of primitives the templates below need, for plain floats;
// simd/lanes.h has the same names for Float.
namespace scalar {
ST_INLINE float select(bool m, float a, float b) { return m ? a : b; }
ST_INLINE bool isnan(float x) { return x != x; }
ST_INLINE float fma(float a, float b, float c) { return std::fma(a, b, c); }
ST_INLINE float floor(float x) { return std::floor(x); }
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
}  // namespace scalar

namespace lanes {
using simd::abs;
using simd::floor;
using simd::fma;
using simd::isnan;
using simd::select;
using simd::sqrt;
// As scalar::max and min: a tie gives q, a NaN the other operand.
ST_INLINE Float max(Float p, Float q) { return simd::select(q != q, p, simd::maxps(p, q)); }
ST_INLINE Float min(Float p, Float q) { return simd::select(q != q, p, simd::minps(p, q)); }
ST_INLINE Float exponent_to_float(Float i) {
    return simd::bit_cast_float((simd::itrunc(i) + Int(127)) << 23);
}
ST_INLINE Int bits_of(Float x) { return simd::bit_cast_int(x); }
ST_INLINE Float from_bits(Int i) { return simd::bit_cast_float(i); }
ST_INLINE Float int_to_float(Int i) { return simd::to_float(i); }
}  // namespace lanes

namespace detail {

using namespace scalar;
using namespace lanes;

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
    even = fma(x2, even, F(kExp2Poly[2]));
    even = fma(x2, even, F(kExp2Poly[0]));
    F odd = F(kExp2Poly[5]);
    odd = fma(x2, odd, F(kExp2Poly[3]));
    odd = fma(x2, odd, F(kExp2Poly[1]));
    return fma(odd, x, even);
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
    // NaN is the quiet NaN of its payload). x + x, not x * 1, which
    // compilers fold to x.
    return select(nan, x + x, r);
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
    const F even = fma(z2, fma(z2, log2_coefficient<F>(4), log2_coefficient<F>(2)), log2_coefficient<F>(0));
    const F odd = fma(z2, log2_coefficient<F>(3), log2_coefficient<F>(1));
    const F p = fma(odd, z, even);
    F r = fma(y, p, e);
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

ST_INLINE float inversesqrt(float x) { return 1.0f / std::sqrt(x); }
ST_INLINE Float inversesqrt(Float x) { return Float(1.0f) / simd::sqrt(x); }

ST_INLINE float abs(float x) { return std::fabs(x); }
ST_INLINE Float abs(Float x) { return simd::abs(x); }
ST_INLINE float floor(float x) { return std::floor(x); }   // lp_build_floor: roundps, exact
ST_INLINE Float floor(Float x) { return simd::floor(x); }
ST_INLINE float max(float a, float b) { return scalar::max(a, b); }
ST_INLINE Float max(Float a, Float b) { return lanes::max(a, b); }
ST_INLINE float min(float a, float b) { return scalar::min(a, b); }
ST_INLINE Float min(Float a, Float b) { return lanes::min(a, b); }

// Measured against llvmpipe (thin-slab scenes, bit for bit): the three
// products are summed as x + (y + z), not left to right as fsum3 reads.
template <class V> ST_INLINE auto dot3(const V& a, const V& b) {
    const auto xx = a.x * b.x, yy = a.y * b.y, zz = a.z * b.z;
    const auto yz = yy + zz;
    return xx + yz;
}
ST_INLINE float dot(const glm::vec3& a, const glm::vec3& b) { return dot3(a, b); }
ST_INLINE Float dot(const Vec3& a, const Vec3& b) { return dot3(a, b); }

// dot(vec2, vec2): one sum of two products, so no order to choose.
ST_INLINE Float dot(const Vec2& a, const Vec2& b) { return a.x * b.x + a.y * b.y; }

// cross(a, b) as Mesa's builtin writes it: a.yzx * b.zxy - a.zxy * b.yzx,
// two products and one difference per component.
ST_INLINE Vec3 cross(const Vec3& a, const Vec3& b) {
    return Vec3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

ST_INLINE float length(const glm::vec3& v) { return std::sqrt(dot(v, v)); }
ST_INLINE Float length(const Vec3& v) { return simd::sqrt(dot(v, v)); }

ST_INLINE glm::vec3 normalize(const glm::vec3& v) {
    const float s = inversesqrt(dot(v, v));
    return glm::vec3(v.x * s, v.y * s, v.z * s);
}
ST_INLINE Vec3 normalize(const Vec3& v) {
    const Float s = inversesqrt(dot(v, v));
    return Vec3(v.x * s, v.y * s, v.z * s);
}

// GLSL's c ? a : b (NIR bcsel): both sides are evaluated, and each lane
// takes one. A small if/else that only assigns is the same after NIR's
// peephole_select; twins write it this way so one source serves both types.
ST_INLINE float select(bool c, float a, float b) { return c ? a : b; }
ST_INLINE glm::vec3 select(bool c, const glm::vec3& a, const glm::vec3& b) { return c ? a : b; }
ST_INLINE Float select(Mask c, Float a, Float b) { return simd::select(c, a, b); }
ST_INLINE Vec3 select(Mask c, const Vec3& a, const Vec3& b) { return st::select(c, a, b); }
ST_INLINE Vec4 select(Mask c, const Vec4& a, const Vec4& b) { return st::select(c, a, b); }

// GLSL's `if (c) return then(); else return otherwise();` (or a ternary
// whose sides are expensive): each lane gets the side its condition picks,
// and a side that no lane takes is not evaluated, as a GPU skips a branch
// no invocation takes. Twin functions have no side effects, so this gives
// the bits of select(c, then(), otherwise()) at a fraction of the cost
// when a whole vector goes one way.
template <class Then, class Otherwise>
ST_INLINE auto if_else(bool c, Then then, Otherwise otherwise) {
    return c ? then() : otherwise();
}
template <class Then, class Otherwise>
ST_INLINE auto if_else(Mask c, Then then, Otherwise otherwise) {
    const unsigned lanes = simd::bits(c);
    if (lanes == (1u << kLanes) - 1) return then();
    if (lanes == 0) return otherwise();
    return glsl::select(c, then(), otherwise());
}

// GLSL reflect(I, N), as Mesa's built-in writes it: I - 2 * (dot(N, I) * N)
// (the factor 2 is exact, so its place in the product does not matter).
ST_INLINE Vec3 reflect(const Vec3& i, const Vec3& n) {
    const Float d = dot(n, i);
    return i - Vec3(Float(2.0f)) * (Vec3(d) * n);
}

// GLSL refract(I, N, eta), as Mesa's built-in writes it:
// k = 1 - eta * (eta * (1 - dot(N, I) * dot(N, I))); the zero vector where
// k < 0 (total internal reflection), else eta * I - (eta * dot(N, I) + sqrt(k)) * N.
ST_INLINE Vec3 refract(const Vec3& i, const Vec3& n, Float eta) {
    const Float n_dot_i = dot(n, i);
    const Float k = Float(1.0f) - eta * (eta * (Float(1.0f) - n_dot_i * n_dot_i));
    const Vec3 r = Vec3(eta) * i - Vec3(eta * n_dot_i + simd::sqrt(k)) * n;
    return glsl::select(k < Float(0.0f), Vec3(Float(0.0f)), r);
}

glm::vec4 mul(const glm::mat4& m, const glm::vec4& v);  // GLSL m * v

}  // namespace st::glsl
