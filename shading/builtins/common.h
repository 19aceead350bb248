// common.h: GLSL's common built-ins (abs, sign, floor, trunc, round,
// roundEven, ceil, fract, mod, modf, min, max, clamp, mix, step,
// smoothstep, isnan, isinf, the bit casts, fma, frexp, ldexp) as llvmpipe
// computes them, bit for bit (docs/llvmpipe/glsl-builtins.md, section 2;
// proved by the scenes conformance-builtins-common-*).
//
// Where llvmpipe is not what a reader expects:
// - sign(-0.0) and sign(NaN) are +0.0 (an unordered compare with zero).
// - round() is roundEven(): GLSL allows either, Mesa picks one.
// - fract(x) is x - floor(x) with no clamp below 1: fract(-1e-10) is 1.0.
// - mod(x, y) is x - y * floor(x / y), four roundings.
// - min and max give the second operand on a tie and the other operand
//   where one is NaN (primitives.h); clamp(x, lo, hi) is min(max(x, lo), hi).
// - mix(x, y, t) has three forms, which NIR picks from the shader around
//   it (nir_lower_flrp): see mix below.
// - fma(a, b, c) is not fused: a * b rounded, then + c rounded.
// - frexp and ldexp are integer code on the bits; a denormal counts as 0.
#pragma once

#include <bit>
#include <limits>

#include "shading/builtins/componentwise.h"
#include "shading/builtins/primitives.h"

namespace st::glsl {

namespace detail {

// lp_build_sgn: +-1.0 carrying x's sign bit, then +0.0 where x == 0
// (unordered, so NaN too; a denormal is 0 under DAZ).
template <class F> ST_INLINE F sign(F x) {
    using I = decltype(bits_of(x));
    const F r = from_bits((bits_of(x) & I(INT32_MIN)) | I(0x3F800000));
    return select((x == F(0.0f)) || isnan(x), F(0.0f), r);
}

// x - y * floor(x / y): lower_fmod, four plain roundings.
template <class F> ST_INLINE F mod(F x, F y) {
    const F q = x / y;
    const F f = floor(q);
    const F p = y * f;
    return x - p;
}

// t = (x - e0) / (e1 - e0) saturated, then t * (t * (3 - 2 t)) grouped as
// Mesa's built-in writes it, not (t * t) * (3 - 2 t).
template <class F> ST_INLINE F smoothstep(F e0, F e1, F x) {
    const F q = (x - e0) / (e1 - e0);
    const F t = detail::min(detail::max(q, F(0.0f)), F(1.0f));
    return t * (t * (F(3.0f) - F(2.0f) * t));
}

// frexp as GLSL IR builds it for floats (builtin_functions.cpp): integer
// code on x's bits. Zero and (under DAZ) denormals give themselves and
// exponent 0; infinities and NaN give exponent 129 and a mantissa in
// [0.5, 1) with their sign.
template <class F, class I> ST_INLINE F frexp(F x, I& e) {
    const auto nonzero = !(abs(x) == F(0.0f));  // unordered: NaN counts
    e = wrapping_add(bits_of(abs(x)) >> 23, select(nonzero, I(-126), I(0)));
    return from_bits((bits_of(x) & I(int32_t(0x807FFFFF))) | select(nonzero, I(0x3F000000), I(0)));
}

// ldexp as GLSL IR's LDEXP_TO_ARITH lowers it (llvmpipe has no native
// ldexp): the exponent field moved by e and clamped, integer code only. A
// normal result is exact; below 2^-126 gives +-0, above the range +-inf;
// infinities and NaN come back as they are.
template <class F, class I> ST_INLINE F ldexp(F x, I e) {
    const I be = bits_of(abs(x)) >> 23;
    I re = imin(wrapping_add(be, e), I(255));
    I sm = bits_of(x) & I(int32_t(0x807FFFFF));
    const auto flush = imin(re, be) <= I(0);
    re = select(flush, I(0), re);
    sm = select(flush || (re == I(255)), sm & I(INT32_MIN), sm);
    const F r = from_bits(sm | shift_left(re, 23));
    return select(be >= I(255), x, r);
}

}  // namespace detail

// genDType: double for vertex twins, Double lanes for fragment twins.
// llvmpipe has no double rounding of its own (PIPE_SHADER_CAP_DROUND_
// SUPPORTED is 0), so GLSL IR's lower_instructions (DOPS_TO_DFRAC) writes
// ceil, trunc, round, roundEven and sign of doubles in fract(), floor,
// comparisons and selects, each operation rounded once; fract(x) itself is
// x - floor(x), floor the rounding instruction (DAZ: a denormal as +-0). dot
// of dvecN becomes a chain of fma that lower_ffma64 splits, so it sums as
// the float dot does; mix of doubles becomes t * y + (1 - t) * x
// (double_lrp), not one of flrp's three forms. min and max are MINSD and
// MAXSD with gallivm's NaN rule, which under DAZ return a denormal as +-0.
namespace dbl {
ST_INLINE double select(bool m, double a, double b) { return m ? a : b; }
using simd::select;
ST_INLINE double floor_instruction(double x) {
    return simd::like_roundpd(x, [](double v) { return __builtin_floor(v); });
}
ST_INLINE Double floor_instruction(Double x) { return simd::floor_pd(x); }
// ffract: lp_build_fract, x - floor(x).
template <class D> ST_INLINE D fract(D x) { return x - floor_instruction(x); }
// In each lowering below, NIR turns x - fract(x) back into the rounding
// instruction's floor(x) (nir_opt_algebraic: a + -ffract(a) -> ffloor(a)),
// so floor(inf) is inf, not inf - NaN.
// dfloor_to_dfrac: x - fract(x), which is floor(x).
template <class D> ST_INLINE D floor(D x) { return floor_instruction(x); }
// dceil_to_dfrac: floor(x) + (fract(x) != 0 ? 1 : 0) (unordered: NaN counts).
template <class D> ST_INLINE D ceil(D x) {
    return floor_instruction(x) + select(fract(x) != D(0.0), D(1.0), D(0.0));
}
// dtrunc_to_dfrac: floor(x) for x >= 0, else floor(x) + (fract(x) == 0 ? 0 : 1).
template <class D> ST_INLINE D trunc(D x) {
    const D t = floor_instruction(x);
    return select(x >= D(0.0), t, t + select(fract(x) == D(0.0), D(0.0), D(1.0)));
}
// dround_even_to_dfrac: t2 = floor(x + 0.5); where fract(x) is 0.5, t2 or
// t2 - 1, whichever is even (fract(t2 * 0.5) == 0).
template <class D> ST_INLINE D round_even(D x) {
    const D t2 = floor_instruction(x + D(0.5));
    const D even = select(fract(t2 * D(0.5)) == D(0.0), t2, t2 - D(1.0));
    return select(fract(x) == D(0.5), even, t2);
}
// dsign_to_csel: x < 0 ? -1 : (x > 0 ? 1 : 0); NaN gives 0.
template <class D> ST_INLINE D sign(D x) {
    return select(x < D(0.0), D(-1.0), select(x > D(0.0), D(1.0), D(0.0)));
}
// gallivm's fmax and fmin: MAXSD/MINSD(p, q), or p where q is NaN.
ST_INLINE double max(double p, double q) { return q != q ? p : simd::maxsd(p, q); }
ST_INLINE double min(double p, double q) { return q != q ? p : simd::minsd(p, q); }
ST_INLINE Double max(Double p, Double q) { return simd::select(q != q, p, simd::maxpd(p, q)); }
ST_INLINE Double min(Double p, Double q) { return simd::select(q != q, p, simd::minpd(p, q)); }
}  // namespace dbl

// abs clears the sign bit (llvm.fabs): NaN keeps its payload.
ST_INLINE float abs(float x) { return scalar::abs(x); }
using simd::abs;  // Float: the same function, so a twin's unqualified call is not ambiguous
ST_INLINE double abs(double x) { return std::fabs(x); }
ST_GLSL_COMPONENTWISE_1(abs)

ST_INLINE float sign(float x) { return detail::sign(x); }
ST_INLINE Float sign(Float x) { return detail::sign(x); }
ST_INLINE double sign(double x) { return dbl::sign(x); }
ST_INLINE Double sign(Double x) { return dbl::sign(x); }
ST_GLSL_COMPONENTWISE_1(sign)

// floor, ceil, trunc: roundps, exact. round and roundEven are both
// fround_even (roundps 0): ties go to even, round(0.5) is 0.
ST_INLINE float floor(float x) { return scalar::floor(x); }
using simd::floor;  // Float: the same function, so a twin's unqualified call is not ambiguous
ST_INLINE double floor(double x) { return dbl::floor(x); }
ST_INLINE Double floor(Double x) { return dbl::floor(x); }
ST_GLSL_COMPONENTWISE_1(floor)
ST_INLINE float ceil(float x) { return scalar::ceil(x); }
using simd::ceil;  // Float: the same function, so a twin's unqualified call is not ambiguous
ST_INLINE double ceil(double x) { return dbl::ceil(x); }
ST_INLINE Double ceil(Double x) { return dbl::ceil(x); }
ST_GLSL_COMPONENTWISE_1(ceil)
ST_INLINE float trunc(float x) { return scalar::trunc(x); }
using simd::trunc;  // Float: the same function, so a twin's unqualified call is not ambiguous
ST_INLINE double trunc(double x) { return dbl::trunc(x); }
ST_INLINE Double trunc(Double x) { return dbl::trunc(x); }
ST_GLSL_COMPONENTWISE_1(trunc)
ST_INLINE float roundEven(float x) { return scalar::round_even(x); }
ST_INLINE Float roundEven(Float x) { return lanes::round_even(x); }
ST_INLINE double roundEven(double x) { return dbl::round_even(x); }
ST_INLINE Double roundEven(Double x) { return dbl::round_even(x); }
ST_GLSL_COMPONENTWISE_1(roundEven)
ST_INLINE float round(float x) { return scalar::round_even(x); }
ST_INLINE Float round(Float x) { return lanes::round_even(x); }
ST_INLINE double round(double x) { return dbl::round_even(x); }
ST_INLINE Double round(Double x) { return dbl::round_even(x); }
ST_GLSL_COMPONENTWISE_1(round)

// fract(x) = x - floor(x), one subtraction: 1.0 for tiny negative x, NaN
// for infinities (not lp_build_fract_safe's clamp below 1).
ST_INLINE float fract(float x) { return x - scalar::floor(x); }
ST_INLINE Float fract(Float x) { return x - lanes::floor(x); }
ST_INLINE double fract(double x) { return dbl::fract(x); }
ST_INLINE Double fract(Double x) { return dbl::fract(x); }
ST_GLSL_COMPONENTWISE_1(fract)

ST_INLINE float mod(float x, float y) { return detail::mod(x, y); }
ST_INLINE Float mod(Float x, Float y) { return detail::mod(x, y); }
// mod of doubles: NIR's lower_fmod, with the rounding instruction's floor.
ST_INLINE double mod(double x, double y) { return x - y * dbl::floor_instruction(x / y); }
ST_INLINE Double mod(Double x, Double y) { return x - y * dbl::floor_instruction(x / y); }
ST_GLSL_COMPONENTWISE_2(mod)

// modf(x, i): i = trunc(x), returns x - i, so modf(-3.0) is +0.0.
ST_INLINE float modf(float x, float& i) {
    i = scalar::trunc(x);
    return x - i;
}
ST_INLINE Float modf(Float x, Float& i) {
    i = lanes::trunc(x);
    return x - i;
}
template <int N> ST_INLINE LaneVec<Float, N> modf(const LaneVec<Float, N>& x, LaneVec<Float, N>& i) {
    i = trunc(x);
    return x - i;
}

ST_INLINE float max(float p, float q) { return scalar::max(p, q); }
ST_INLINE Float max(Float p, Float q) { return lanes::max(p, q); }
ST_INLINE double max(double p, double q) { return dbl::max(p, q); }
ST_INLINE Double max(Double p, Double q) { return dbl::max(p, q); }
ST_GLSL_COMPONENTWISE_2(max)
ST_INLINE float min(float p, float q) { return scalar::min(p, q); }
ST_INLINE Float min(Float p, Float q) { return lanes::min(p, q); }
ST_INLINE double min(double p, double q) { return dbl::min(p, q); }
ST_INLINE Double min(Double p, Double q) { return dbl::min(p, q); }
ST_GLSL_COMPONENTWISE_2(min)

// min(max(x, lo), hi): NaN x gives lo (then hi if lo > hi), and
// clamp(-0.0, 0.0, 1.0) is +0.0.
ST_INLINE float clamp(float x, float lo, float hi) { return scalar::min(scalar::max(x, lo), hi); }
ST_INLINE Float clamp(Float x, Float lo, Float hi) { return lanes::min(lanes::max(x, lo), hi); }
ST_INLINE double clamp(double x, double lo, double hi) { return dbl::min(dbl::max(x, lo), hi); }
ST_INLINE Double clamp(Double x, Double lo, Double hi) { return dbl::min(dbl::max(x, lo), hi); }
ST_GLSL_COMPONENTWISE_3(clamp)

// mix(x, y, t) for float t is NIR's flrp, which nir_lower_flrp writes in
// one of three forms, chosen from the shader around it (glsl-builtins.md
// 2.13; docs/llvmpipe/compiler-rewrites.md says how to tell):
// - mix: the fast form, x + t * (y - x). The usual case: t varies and no
//   other mix in the shader shares x and t, or y and t. mix(x, y, 1.0) is
//   not always y.
// - mix_strict: x * (1 - t) + y * t, where t is a constant, where another
//   mix shares (x, t) or (y, t) (mix(vec3(k), c, t) splits into three that
//   share them), where y is +-1, or in a precise assignment.
// - mix_from_one: x a constant 1.0, (1 - t) + y * t; mix_from_minus_one:
//   x a constant -1.0, (-1 + t) + y * t.
// Simplified first (and written so in a twin): t of 0 or 1, x == y, x or y
// a constant 0 (y * t, x * (1 - t)).
ST_INLINE float mix(float x, float y, float t) { return x + t * (y - x); }
ST_INLINE Float mix(Float x, Float y, Float t) { return x + t * (y - x); }
// mix of doubles: double_lrp's t * y + (1 - t) * x, whatever the operands.
ST_INLINE double mix(double x, double y, double t) { return t * y + (1.0 - t) * x; }
ST_INLINE Double mix(Double x, Double y, Double t) { return t * y + (Double(1.0) - t) * x; }
ST_GLSL_COMPONENTWISE_3(mix)
ST_INLINE float mix_strict(float x, float y, float t) { return x * (1.0f - t) + y * t; }
ST_INLINE Float mix_strict(Float x, Float y, Float t) { return x * (Float(1.0f) - t) + y * t; }
ST_GLSL_COMPONENTWISE_3(mix_strict)
ST_INLINE float mix_from_one(float y, float t) { return (1.0f - t) + y * t; }
ST_INLINE Float mix_from_one(Float y, Float t) { return (Float(1.0f) - t) + y * t; }
ST_GLSL_COMPONENTWISE_2(mix_from_one)
ST_INLINE float mix_from_minus_one(float y, float t) { return (-1.0f + t) + y * t; }
ST_INLINE Float mix_from_minus_one(Float y, Float t) { return (Float(-1.0f) + t) + y * t; }
ST_GLSL_COMPONENTWISE_2(mix_from_minus_one)
// mix(x, y, bvec a): each component y where a is true, else x; bits as
// they are, NaN payloads too.
ST_INLINE float mix(float x, float y, bool a) { return a ? y : x; }
ST_INLINE Float mix(Float x, Float y, Mask a) { return lanes::select(a, y, x); }
template <int N> ST_INLINE LaneVec<Float, N> mix(const LaneVec<Float, N>& x, const LaneVec<Float, N>& y, const LaneVec<Mask, N>& a) {
    return [&]<int... I>(std::integer_sequence<int, I...>) {
        return LaneVec<Float, N>(lanes::select(a.template component<I>(), y.template component<I>(), x.template component<I>())...);
    }(std::make_integer_sequence<int, N>());
}

// step(edge, x): 1.0 where x >= edge (ordered: NaN in either gives 0.0).
ST_INLINE float step(float edge, float x) { return x >= edge ? 1.0f : 0.0f; }
ST_INLINE Float step(Float edge, Float x) { return lanes::select(x >= edge, Float(1.0f), Float(0.0f)); }
ST_INLINE double step(double edge, double x) { return x >= edge ? 1.0 : 0.0; }
ST_INLINE Double step(Double edge, Double x) { return simd::select(x >= edge, Double(1.0), Double(0.0)); }
ST_GLSL_COMPONENTWISE_2(step)

ST_INLINE float smoothstep(float e0, float e1, float x) { return detail::smoothstep(e0, e1, x); }
ST_INLINE Float smoothstep(Float e0, Float e1, Float x) { return detail::smoothstep(e0, e1, x); }
ST_INLINE double smoothstep(double e0, double e1, double x) {
    const double t = dbl::min(dbl::max((x - e0) / (e1 - e0), 0.0), 1.0);
    return t * (t * (3.0 - 2.0 * t));
}
ST_INLINE Double smoothstep(Double e0, Double e1, Double x) {
    const Double t = dbl::min(dbl::max((x - e0) / (e1 - e0), Double(0.0)), Double(1.0));
    return t * (t * (Double(3.0) - Double(2.0) * t));
}
ST_GLSL_COMPONENTWISE_3(smoothstep)

// isnan(x) is x != x; isinf(x) is abs(x) == inf (ordered).
ST_INLINE bool isnan(float x) { return x != x; }
using simd::isnan;  // Float: x != x
ST_INLINE bool isnan(double x) { return x != x; }
ST_GLSL_COMPONENTWISE_1(isnan)
ST_INLINE bool isinf(float x) { return scalar::abs(x) == std::numeric_limits<float>::infinity(); }
ST_INLINE Mask isinf(Float x) { return lanes::abs(x) == Float(std::numeric_limits<float>::infinity()); }
ST_INLINE bool isinf(double x) { return std::fabs(x) == std::numeric_limits<double>::infinity(); }
ST_INLINE Mask isinf(Double x) { return simd::abs(x) == Double(std::numeric_limits<double>::infinity()); }
ST_GLSL_COMPONENTWISE_1(isinf)

// The bit casts move bits and nothing else: a signalling NaN or a denormal
// comes through unchanged until arithmetic reads it.
ST_INLINE int32_t floatBitsToInt(float x) { return scalar::bits_of(x); }
ST_INLINE Int floatBitsToInt(Float x) { return lanes::bits_of(x); }
ST_GLSL_COMPONENTWISE_1(floatBitsToInt)
ST_INLINE float intBitsToFloat(int32_t i) { return scalar::from_bits(i); }
ST_INLINE Float intBitsToFloat(Int i) { return lanes::from_bits(i); }
ST_GLSL_COMPONENTWISE_1(intBitsToFloat)
ST_INLINE uint32_t floatBitsToUint(float x) { return std::bit_cast<uint32_t>(x); }
ST_INLINE UInt floatBitsToUint(Float x) { return UInt(lanes::bits_of(x)); }
ST_GLSL_COMPONENTWISE_1(floatBitsToUint)
ST_INLINE float uintBitsToFloat(uint32_t u) { return std::bit_cast<float>(u); }
ST_INLINE Float uintBitsToFloat(UInt u) { return lanes::from_bits(simd::int_bits(u)); }
ST_GLSL_COMPONENTWISE_1(uintBitsToFloat)

// GLSL's fma(a, b, c) is not fused on llvmpipe (lower_ffma32 splits it):
// a * b rounded, then + c. -ffp-contract=off keeps the compiler from
// fusing it back.
ST_INLINE float fma(float a, float b, float c) { return a * b + c; }
ST_INLINE Float fma(Float a, Float b, Float c) { return a * b + c; }
ST_GLSL_COMPONENTWISE_3(fma)

// fma, modf and mix(x, y, bool) of doubles: a * b + c (lower_ffma64),
// trunc(x) and x - trunc(x) with trunc as dbl::trunc, and a selection.
ST_INLINE double fma(double a, double b, double c) { return a * b + c; }
ST_INLINE Double fma(Double a, Double b, Double c) { return a * b + c; }
ST_INLINE double modf(double x, double& i) {
    i = dbl::trunc(x);
    return x - i;
}
ST_INLINE Double modf(Double x, Double& i) {
    i = dbl::trunc(x);
    return x - i;
}
ST_INLINE double mix(double x, double y, bool a) { return a ? y : x; }
ST_INLINE Double mix(Double x, Double y, Mask a) { return simd::select(a, y, x); }

ST_INLINE float frexp(float x, int32_t& e) { return detail::frexp(x, e); }
ST_INLINE Float frexp(Float x, Int& e) { return detail::frexp(x, e); }
ST_INLINE float ldexp(float x, int32_t e) { return detail::ldexp(x, e); }
ST_INLINE Float ldexp(Float x, Int e) { return detail::ldexp(x, e); }

// frexp and ldexp of doubles, as GLSL IR's DFREXP_DLDEXP_TO_ARITH writes them
// (llvmpipe reports no double frexp): integer code on the high word. Zero
// and denormals (zero under DAZ) give exponent 0 and themselves; infinities
// and NaN exponent 1025. ldexp(x, e) puts frexp's biased exponent plus e
// into the exponent field where that is at least 1, else gives +-0; so a
// zero or denormal x gives the field 1022 + e over its own mantissa
// (ldexp(0.0, 0) is 0.5), and a field past 2047 wraps (GLSL leaves
// overflow undefined).
namespace dbl {
ST_INLINE bool nonzero_under_daz(uint64_t b) { return (b & 0x7FF0000000000000ull) != 0; }
ST_INLINE double frexp(double x, int32_t& e) {
    const uint64_t b = std::bit_cast<uint64_t>(x);
    const bool nonzero = nonzero_under_daz(b);
    e = nonzero ? int32_t((uint32_t(b >> 32) & 0x7FFFFFFFu) >> 20) - 1022 : 0;
    const uint32_t hi = (uint32_t(b >> 32) & 0x800FFFFFu) | (nonzero ? 0x3FE00000u : 0u);
    return std::bit_cast<double>((uint64_t(hi) << 32) | (b & 0xFFFFFFFFull));
}
ST_INLINE double ldexp(double x, int32_t e) {
    const uint64_t b = std::bit_cast<uint64_t>(x);
    const int32_t exponent = nonzero_under_daz(b) ? int32_t((uint32_t(b >> 32) & 0x7FFFFFFFu) >> 20) - 1022 : 0;
    int32_t biased = int32_t(uint32_t(exponent + 1022) + uint32_t(e));  // wraps, as the GPU's add
    const bool keep = biased >= 1;
    const uint64_t kept = keep ? b : (b & 0x8000000000000000ull);
    biased = keep ? biased : 0;
    const uint32_t hi = (uint32_t(kept >> 32) & ~(0x7FFu << 20)) | ((uint32_t(biased) & 0x7FFu) << 20);
    return std::bit_cast<double>((uint64_t(hi) << 32) | (kept & 0xFFFFFFFFull));
}
}  // namespace dbl
ST_INLINE double frexp(double x, int32_t& e) { return dbl::frexp(x, e); }
ST_INLINE double ldexp(double x, int32_t e) { return dbl::ldexp(x, e); }
ST_INLINE Double frexp(Double x, Int& e) {
    Double r;
    for (int l = 0; l < kLanes; ++l) {
        int32_t el = 0;
        r.set(l, dbl::frexp(x[l], el));
        e.set(l, el);
    }
    return r;
}
ST_INLINE Double ldexp(Double x, Int e) {
    Double r;
    for (int l = 0; l < kLanes; ++l) r.set(l, dbl::ldexp(x[l], e[l]));
    return r;
}

}  // namespace st::glsl
