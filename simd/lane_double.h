// lane_double.h: GLSL's double per lane (Double), for fragment twins of
// shaders with double uniforms or double arithmetic. llvmpipe computes a
// double in 64-bit lanes with the plain IEEE operations of LLVM (fadd, fmul,
// fdiv, llvm.sqrt, fpext, fptrunc: lp_bld_nir.c on its dbl_bld), so each
// operation here is the one IEEE rounding of the same instruction class.
// The shading threads' FTZ and DAZ (raster/float_env.h) govern the double
// instructions as the float ones: a denormal double reads as +-0, and
// float(d) below the float range flushes to +-0, on both pipelines.
//
// GLSL converts float to double implicitly where they meet (f * d is
// double(f) * d); a twin writes the conversion, Double(f) * d (mixed
// operators would make Float * 0.5f ambiguous). double(f) is exact, float(d)
// rounds to nearest (cvtpd2ps): float_of(d).
#pragma once

#include "simd/lanes.h"

namespace st::simd {

using DoubleV = double __attribute__((vector_size(kLanes * 8)));
using LongV = int64_t __attribute__((vector_size(kLanes * 8)));
using ULongV = uint64_t __attribute__((vector_size(kLanes * 8)));

struct Double {
    DoubleV v;

    Double() : v{} {}
    Double(double s) : v(DoubleV ST_SPLAT(s)) {}  // broadcast, as GLSL promotes a constant
    explicit Double(DoubleV x) : v(x) {}
    explicit Double(Float f) : v(__builtin_convertvector(f.v, DoubleV)) {}  // double(f): exact

    double operator[](int lane) const { return v[lane]; }
    void set(int lane, double x) { v[lane] = x; }
};

// A 64-bit comparison's all-ones or zero per lane, as a Mask's 32 bits.
ST_INLINE Mask mask_of(LongV m) { return Mask(__builtin_convertvector(m, IntV)); }
ST_INLINE LongV long_mask(Mask m) { return __builtin_convertvector(m.v, LongV); }

ST_INLINE Double operator+(Double a, Double b) { return Double(a.v + b.v); }
ST_INLINE Double operator-(Double a, Double b) { return Double(a.v - b.v); }
ST_INLINE Double operator*(Double a, Double b) { return Double(a.v * b.v); }
ST_INLINE Double operator/(Double a, Double b) { return Double(a.v / b.v); }
ST_INLINE Double operator-(Double a) { return Double(-a.v); }
ST_INLINE Double& operator+=(Double& a, Double b) { return a = a + b; }
ST_INLINE Double& operator-=(Double& a, Double b) { return a = a - b; }
ST_INLINE Double& operator*=(Double& a, Double b) { return a = a * b; }
ST_INLINE Double& operator/=(Double& a, Double b) { return a = a / b; }

// Comparisons are IEEE: every ordered comparison with a NaN is false.
ST_INLINE Mask operator<(Double a, Double b) { return mask_of(a.v < b.v); }
ST_INLINE Mask operator<=(Double a, Double b) { return mask_of(a.v <= b.v); }
ST_INLINE Mask operator>(Double a, Double b) { return mask_of(a.v > b.v); }
ST_INLINE Mask operator>=(Double a, Double b) { return mask_of(a.v >= b.v); }
ST_INLINE Mask operator==(Double a, Double b) { return mask_of(a.v == b.v); }
ST_INLINE Mask operator!=(Double a, Double b) { return mask_of(a.v != b.v); }

ST_INLINE Double select(Mask m, Double a, Double b) { return Double(long_mask(m) ? a.v : b.v); }

ST_INLINE LongV bits_of(Double x) { return LongV(x.v); }
ST_INLINE Double double_from_bits(LongV b) { return Double(DoubleV(b)); }

// float(d): rounded to nearest (cvtpd2ps); below the float range +-0 (FTZ),
// above it +-inf, NaN stays NaN (its payload's top bits, quieted).
ST_INLINE Float to_float(Double d) { return Float(__builtin_convertvector(d.v, FloatV)); }

// int(d), truncated toward zero, with the x86 answer for what C++ leaves
// undefined: NaN and values outside (-2^31 - 1, 2^31) give INT32_MIN
// (cvttpd2dq, which llvmpipe's fptosi compiles to).
ST_INLINE Int itrunc(Double x) {
    const Mask in_range = (x > Double(-2147483649.0)) && (x < Double(2147483648.0));
    const Double safe = select(in_range, x, Double(0.0));
    const Int r(__builtin_convertvector(safe.v, IntV));
    return select(in_range, r, Int(INT32_MIN));
}

// double(i), double(u): exact.
ST_INLINE Double to_double(Int x) { return Double(__builtin_convertvector(x.v, DoubleV)); }

// sqrt: correctly rounded (sqrtpd, llvm.sqrt).
ST_INLINE Double sqrt(Double x) {
    Double r;
    for (int i = 0; i < kLanes; ++i) r.v[i] = __builtin_sqrt(x.v[i]);
    return r;
}

// A denormal double as the signed zero DAZ reads it as.
ST_INLINE double denormal_as_zero(double x) {
    const uint64_t b = __builtin_bit_cast(uint64_t, x);
    return (b & 0x7FF0000000000000ull) == 0 ? __builtin_bit_cast(double, b & 0x8000000000000000ull) : x;
}

// A C library rounding function made to answer as roundpd and vrndscalepd
// do in the shading threads (as like_roundps for floats): a signalling NaN
// is quieted, a denormal rounds as +-0.
template <class Fn> ST_INLINE double like_roundpd(double x, Fn round) {
    const uint64_t b = __builtin_bit_cast(uint64_t, x);
    if ((b & 0x7FF0000000000000ull) == 0x7FF0000000000000ull && (b & 0x000FFFFFFFFFFFFFull) != 0)
        return __builtin_bit_cast(double, b | 0x0008000000000000ull);
    return round(denormal_as_zero(x));
}

// The rounding instructions themselves (vrndscalepd, roundpd, llvm.floor
// and friends): GLSL's double floor, ceil, trunc and round do not run as
// these (glsl/builtins/common.h's dbl:: says what they run as).
template <class Fn> ST_INLINE Double each_rounded(Double x, Fn round) {
    Double r;
    for (int i = 0; i < kLanes; ++i) r.v[i] = like_roundpd(x.v[i], round);
    return r;
}
ST_INLINE Double floor_pd(Double x) { return each_rounded(x, [](double v) { return __builtin_floor(v); }); }
ST_INLINE Double trunc_pd(Double x) { return each_rounded(x, [](double v) { return __builtin_trunc(v); }); }

ST_INLINE Double abs(Double x) { return double_from_bits(bits_of(x) & LongV ST_SPLAT(INT64_MAX)); }
ST_INLINE Mask isnan(Double x) { return x != x; }

// MAXSD and MINSD (p > q ? p : q, so a NaN or a tie gives q), as the
// instructions, for the reason maxss is one (lanes.h); under DAZ they
// return a denormal operand as +-0, which a select would not.
ST_INLINE double maxsd(double p, double q) {
    double r;
#if defined(__AVX__)
    __asm__("vmaxsd %2, %1, %0" : "=x"(r) : "x"(p), "x"(q));
#else
    r = p;
    __asm__("maxsd %1, %0" : "+x"(r) : "x"(q));
#endif
    return r;
}
ST_INLINE double minsd(double p, double q) {
    double r;
#if defined(__AVX__)
    __asm__("vminsd %2, %1, %0" : "=x"(r) : "x"(p), "x"(q));
#else
    r = p;
    __asm__("minsd %1, %0" : "+x"(r) : "x"(q));
#endif
    return r;
}
ST_INLINE Double maxpd(Double p, Double q) {
    Double r;
    for (int i = 0; i < kLanes; ++i) r.v[i] = maxsd(p.v[i], q.v[i]);
    return r;
}
ST_INLINE Double minpd(Double p, Double q) {
    Double r;
    for (int i = 0; i < kLanes; ++i) r.v[i] = minsd(p.v[i], q.v[i]);
    return r;
}

}  // namespace st::simd
