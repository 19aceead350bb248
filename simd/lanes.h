// lanes.h: the lane vocabulary of the shading runtime. A `Float` holds one
// float per lane, an `Int` one int32, a `Mask` one bool; a fragment twin
// computes on them as a GLSL shader computes on one invocation, and every
// lane rounds exactly as a scalar float would (IEEE per lane, no fusing,
// nothing across lanes except where a function says so).
//
// kLanes is fixed per build (ST_LANES, chosen by CMake from the widest
// vectors the build machine has: 16 with AVX-512, else 8);
// results do not depend on it (docs/shading-runtime.md says why and how it
// is tested). The types are GCC/Clang vector extensions, so the same source
// compiles to zmm, ymm or xmm registers, or to plain loops elsewhere; the
// few operations the compiler would not map to one instruction have
// intrinsics below, each with its portable form beside it.
#pragma once

#include <cstdint>
#include <cstring>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

#ifndef ST_LANES
#define ST_LANES 8
#endif

namespace st::simd {

inline constexpr int kLanes = ST_LANES;
// At least 8: llvmpipe runs loops over 8-lane vectors, and a value read after
// a loop comes from its vector's last pass (docs/llvmpipe/lanes-and-control-flow.md),
// so a twin must see whole 8-lane groups to reproduce it.
static_assert(kLanes == 8 || kLanes == 16, "lanes come in 8-lane groups, at most a 4x4 block");

#define ST_INLINE inline __attribute__((always_inline))

using FloatV = float __attribute__((vector_size(kLanes * 4)));
using IntV = int32_t __attribute__((vector_size(kLanes * 4)));

// Which instructions this build may use for a whole vector of kLanes.
#if ST_LANES == 16 && defined(__AVX512F__) && defined(__AVX512DQ__)
#define ST_SIMD_AVX512 1
#elif ST_LANES == 8 && defined(__AVX2__) && defined(__FMA__)
#define ST_SIMD_AVX2 1
#endif

struct Mask;
struct Int;

// {s, s, ..., s}: a splat the compiler sees as one (a loop of lane stores
// became 16 masked broadcasts).
#if ST_LANES == 16
#define ST_SPLAT(s) {s, s, s, s, s, s, s, s, s, s, s, s, s, s, s, s}
#else
#define ST_SPLAT(s) {s, s, s, s, s, s, s, s}
#endif

// One float per lane.
struct Float {
    FloatV v;

    Float() : v{} {}
    Float(float s) : v(FloatV ST_SPLAT(s)) {}  // broadcast, as GLSL promotes a constant
    explicit Float(FloatV x) : v(x) {}

    static Float load(const float* p) {
        Float r;
        std::memcpy(&r.v, p, sizeof r.v);
        return r;
    }
    void store(float* p) const { std::memcpy(p, &v, sizeof v); }
    // Lanes [8g, 8g + 8) from or to p[g]: each 8-lane group in its own place.
    static Float load_groups(const float* const* p);
    void store_groups(float* const* p) const;
    float operator[](int lane) const { return v[lane]; }
    void set(int lane, float x) { v[lane] = x; }
};

// One int32 per lane. Arithmetic wraps modulo 2^32 (done in unsigned
// lanes, so there is no signed overflow); shifts take counts in [0, 31].
struct Int {
    IntV v;

    Int() : v{} {}
    Int(int32_t s) : v(IntV ST_SPLAT(s)) {}
    explicit Int(IntV x) : v(x) {}

    int32_t operator[](int lane) const { return v[lane]; }
    void set(int lane, int32_t x) { v[lane] = x; }
    static Int load(const int32_t* p) {
        Int r;
        std::memcpy(&r.v, p, sizeof r.v);
        return r;
    }
};

// One bool per lane, held as all-ones or zero.
struct Mask {
    IntV v;

    Mask() : v{} {}
    explicit Mask(IntV x) : v(x) {}
    explicit Mask(bool b) : v(IntV ST_SPLAT(b ? -1 : 0)) {}
    // Bit i of `bits` is lane i.
    static Mask from_bits(unsigned bits);
    bool operator[](int lane) const { return v[lane] != 0; }
};

ST_INLINE Float operator+(Float a, Float b) { return Float(a.v + b.v); }
ST_INLINE Float operator-(Float a, Float b) { return Float(a.v - b.v); }
ST_INLINE Float operator*(Float a, Float b) { return Float(a.v * b.v); }
ST_INLINE Float operator/(Float a, Float b) { return Float(a.v / b.v); }
ST_INLINE Float operator-(Float a) { return Float(-a.v); }
ST_INLINE Float& operator+=(Float& a, Float b) { return a = a + b; }
ST_INLINE Float& operator-=(Float& a, Float b) { return a = a - b; }
ST_INLINE Float& operator*=(Float& a, Float b) { return a = a * b; }
ST_INLINE Float& operator/=(Float& a, Float b) { return a = a / b; }

// Comparisons are IEEE: every ordered comparison with a NaN is false.
ST_INLINE Mask operator<(Float a, Float b) { return Mask(a.v < b.v); }
ST_INLINE Mask operator<=(Float a, Float b) { return Mask(a.v <= b.v); }
ST_INLINE Mask operator>(Float a, Float b) { return Mask(a.v > b.v); }
ST_INLINE Mask operator>=(Float a, Float b) { return Mask(a.v >= b.v); }
ST_INLINE Mask operator==(Float a, Float b) { return Mask(a.v == b.v); }
ST_INLINE Mask operator!=(Float a, Float b) { return Mask(a.v != b.v); }

ST_INLINE Mask operator&&(Mask a, Mask b) { return Mask(a.v & b.v); }
ST_INLINE Mask operator||(Mask a, Mask b) { return Mask(a.v | b.v); }
ST_INLINE Mask operator!(Mask a) { return Mask(~a.v); }
ST_INLINE Mask operator==(Mask a, Mask b) { return Mask(a.v == b.v); }
ST_INLINE Mask and_not(Mask a, Mask b) { return Mask(a.v & ~b.v); }

ST_INLINE Int operator+(Int a, Int b) {
    using UV = uint32_t __attribute__((vector_size(kLanes * 4)));
    return Int(IntV(UV(a.v) + UV(b.v)));
}
ST_INLINE Int operator-(Int a, Int b) {
    using UV = uint32_t __attribute__((vector_size(kLanes * 4)));
    return Int(IntV(UV(a.v) - UV(b.v)));
}
ST_INLINE Int operator*(Int a, Int b) {
    using UV = uint32_t __attribute__((vector_size(kLanes * 4)));
    return Int(IntV(UV(a.v) * UV(b.v)));
}
ST_INLINE Int operator&(Int a, Int b) { return Int(a.v & b.v); }
ST_INLINE Int operator|(Int a, Int b) { return Int(a.v | b.v); }
ST_INLINE Int operator^(Int a, Int b) { return Int(a.v ^ b.v); }
ST_INLINE Int operator<<(Int a, int n) {
    using UV = uint32_t __attribute__((vector_size(kLanes * 4)));
    return Int(IntV(UV(a.v) << n));
}
ST_INLINE Int operator>>(Int a, int n) { return Int(a.v >> n); }  // arithmetic
ST_INLINE Mask operator<(Int a, Int b) { return Mask(a.v < b.v); }
ST_INLINE Mask operator>(Int a, Int b) { return Mask(a.v > b.v); }
ST_INLINE Mask operator<=(Int a, Int b) { return Mask(a.v <= b.v); }
ST_INLINE Mask operator>=(Int a, Int b) { return Mask(a.v >= b.v); }
ST_INLINE Mask operator==(Int a, Int b) { return Mask(a.v == b.v); }
ST_INLINE Mask operator!=(Int a, Int b) { return Mask(a.v != b.v); }

// GLSL's b ? x : y per lane (NIR bcsel).
ST_INLINE Float select(Mask m, Float a, Float b) { return Float(m.v ? a.v : b.v); }
ST_INLINE Int select(Mask m, Int a, Int b) { return Int(m.v ? a.v : b.v); }
ST_INLINE Mask select(Mask m, Mask a, Mask b) { return Mask(m.v ? a.v : b.v); }

#if ST_LANES == 16
inline constexpr IntV kLaneBit = {1, 2, 4, 8, 16, 32, 64, 128, 256, 512, 1024, 2048, 4096, 8192, 16384, 32768};
#else
inline constexpr IntV kLaneBit = {1, 2, 4, 8, 16, 32, 64, 128};
#endif

ST_INLINE Mask Mask::from_bits(unsigned bits) {
#if defined(ST_SIMD_AVX512)
    return Mask(IntV(_mm512_movm_epi32(__mmask16(bits))));
#else
    return Mask((kLaneBit & int32_t(bits)) != 0);
#endif
}

// Bit i set where lane i is true.
ST_INLINE unsigned bits(Mask m) {
#if defined(ST_SIMD_AVX512)
    return _mm512_movepi32_mask(__m512i(m.v));
#elif defined(ST_SIMD_AVX2)
    return unsigned(_mm256_movemask_ps(__m256(m.v)));
#else
    unsigned r = 0;
    for (int i = 0; i < kLanes; ++i) r |= unsigned(m.v[i] != 0) << i;
    return r;
#endif
}
ST_INLINE bool any(Mask m) { return bits(m) != 0; }
ST_INLINE bool all(Mask m) { return bits(m) == (1u << kLanes) - 1; }
ST_INLINE bool none(Mask m) { return bits(m) == 0; }
// (x >> 8) & 0x00ff00ff per lane: bytes 1 and 3 moved down to bytes 0
// and 2 (a texel's green and alpha as two 16-bit halves), one pshufb.
ST_INLINE Int odd_bytes(Int x) {
#if defined(ST_SIMD_AVX512) && defined(__AVX512BW__)
    const __m512i pick = _mm512_set4_epi32(0x800f800d, 0x800b8009, 0x80078005, 0x80038001);
    return Int(IntV(_mm512_shuffle_epi8(__m512i(x.v), pick)));
#elif defined(ST_SIMD_AVX2)
    const __m256i pick = _mm256_setr_epi32(0x80038001, 0x80078005, 0x800b8009, 0x800f800d, 0x80038001, 0x80078005,
                                           0x800b8009, 0x800f800d);
    return Int(IntV(_mm256_shuffle_epi8(__m256i(x.v), pick)));
#else
    return Int(IntV((x.v >> 8) & 0x00ff00ff));
#endif
}

// Whether any bit of any lane is set (ptest).
ST_INLINE bool any_bit(Int x) {
#if defined(ST_SIMD_AVX512)
    return _mm512_test_epi32_mask(__m512i(x.v), __m512i(x.v)) != 0;
#elif defined(ST_SIMD_AVX2)
    return !_mm256_testz_si256(__m256i(x.v), __m256i(x.v));
#else
    int32_t r = 0;
    for (int i = 0; i < kLanes; ++i) r |= x.v[i];
    return r != 0;
#endif
}

ST_INLINE Int bit_cast_int(Float x) { return Int(IntV(x.v)); }
ST_INLINE Float bit_cast_float(Int x) { return Float(FloatV(x.v)); }

// Fused multiply-add, one rounding: llvmpipe's lp_build_mad on an FMA host.
ST_INLINE Float fmuladd(Float a, Float b, Float c) {
#if defined(ST_SIMD_AVX512)
    return Float(FloatV(_mm512_fmadd_ps(__m512(a.v), __m512(b.v), __m512(c.v))));
#elif defined(ST_SIMD_AVX2)
    return Float(FloatV(_mm256_fmadd_ps(__m256(a.v), __m256(b.v), __m256(c.v))));
#else
    Float r;
    for (int i = 0; i < kLanes; ++i) r.v[i] = __builtin_fmaf(a.v[i], b.v[i], c.v[i]);
    return r;
#endif
}

ST_INLINE Float sqrt(Float x) {
    Float r;
    for (int i = 0; i < kLanes; ++i) r.v[i] = __builtin_sqrtf(x.v[i]);
    return r;
}

// The x86 MAXPS and MINPS rule, which gallivm's fmax and fmin build on:
// p > q ? p : q (p < q ? p : q for min), so a tie or a NaN gives q. Written
// as the instructions, not as selects: a compiler may turn the select into
// maxnum, whose tie is either operand (clang -O3 gave min(-0.0, +0.0) as
// -0.0 for one float and +0.0 for lanes). The one-float forms are inline
// assembly because GCC 12 folds _mm_max_ss of constants wrongly
// (_mm_max_ss(NaN, 2) to NaN).
ST_INLINE float maxss(float p, float q) {
    float r;
#if defined(__AVX__)
    __asm__("vmaxss %2, %1, %0" : "=x"(r) : "x"(p), "x"(q));
#else
    r = p;
    __asm__("maxss %1, %0" : "+x"(r) : "x"(q));
#endif
    return r;
}
ST_INLINE float minss(float p, float q) {
    float r;
#if defined(__AVX__)
    __asm__("vminss %2, %1, %0" : "=x"(r) : "x"(p), "x"(q));
#else
    r = p;
    __asm__("minss %1, %0" : "+x"(r) : "x"(q));
#endif
    return r;
}
ST_INLINE Float maxps(Float p, Float q) {
#if defined(ST_SIMD_AVX512)
    return Float(FloatV(_mm512_max_ps(__m512(p.v), __m512(q.v))));
#elif defined(ST_SIMD_AVX2)
    return Float(FloatV(_mm256_max_ps(__m256(p.v), __m256(q.v))));
#else
    Float r;
    for (int i = 0; i < kLanes; ++i) r.v[i] = maxss(p.v[i], q.v[i]);
    return r;
#endif
}
ST_INLINE Float minps(Float p, Float q) {
#if defined(ST_SIMD_AVX512)
    return Float(FloatV(_mm512_min_ps(__m512(p.v), __m512(q.v))));
#elif defined(ST_SIMD_AVX2)
    return Float(FloatV(_mm256_min_ps(__m256(p.v), __m256(q.v))));
#else
    Float r;
    for (int i = 0; i < kLanes; ++i) r.v[i] = minss(p.v[i], q.v[i]);
    return r;
#endif
}

// A denormal as the signed zero DAZ reads it as.
ST_INLINE float denormal_as_zero(float x) {
    const uint32_t b = __builtin_bit_cast(uint32_t, x);
    return (b & 0x7F800000u) == 0 ? __builtin_bit_cast(float, b & 0x80000000u) : x;
}

// A C library rounding function (floorf, ...) made to answer as roundps
// does in the shading threads: roundps quiets a signalling NaN and, under
// their DAZ (raster/float_env.h), rounds a denormal as +-0, so
// floor(-denormal) is -0.0; a C library may be integer code that passes an
// sNaN through and sees the denormal. For the portable forms below and the
// one-float built-ins.
template <class Fn> ST_INLINE float like_roundps(float x, Fn round) {
    const uint32_t b = __builtin_bit_cast(uint32_t, x);
    if ((b & 0x7F800000u) == 0x7F800000u && (b & 0x007FFFFFu) != 0) return __builtin_bit_cast(float, b | 0x00400000u);
    return round(denormal_as_zero(x));
}

// Round toward -infinity (roundps 1, as llvm.floor).
ST_INLINE Float floor(Float x) {
#if defined(ST_SIMD_AVX512)
    return Float(FloatV(_mm512_roundscale_ps(__m512(x.v), _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC)));
#elif defined(ST_SIMD_AVX2)
    return Float(FloatV(_mm256_round_ps(__m256(x.v), _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC)));
#else
    Float r;
    for (int i = 0; i < kLanes; ++i) r.v[i] = like_roundps(x.v[i], [](float v) { return __builtin_floorf(v); });
    return r;
#endif
}

// Round toward +infinity and toward zero (roundps 2 and 3, as llvm.ceil and
// llvm.trunc), exact as floor is.
ST_INLINE Float ceil(Float x) {
#if defined(ST_SIMD_AVX512)
    return Float(FloatV(_mm512_roundscale_ps(__m512(x.v), _MM_FROUND_TO_POS_INF | _MM_FROUND_NO_EXC)));
#elif defined(ST_SIMD_AVX2)
    return Float(FloatV(_mm256_round_ps(__m256(x.v), _MM_FROUND_TO_POS_INF | _MM_FROUND_NO_EXC)));
#else
    Float r;
    for (int i = 0; i < kLanes; ++i) r.v[i] = like_roundps(x.v[i], [](float v) { return __builtin_ceilf(v); });
    return r;
#endif
}
ST_INLINE Float trunc(Float x) {
#if defined(ST_SIMD_AVX512)
    return Float(FloatV(_mm512_roundscale_ps(__m512(x.v), _MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC)));
#elif defined(ST_SIMD_AVX2)
    return Float(FloatV(_mm256_round_ps(__m256(x.v), _MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC)));
#else
    Float r;
    for (int i = 0; i < kLanes; ++i) r.v[i] = like_roundps(x.v[i], [](float v) { return __builtin_truncf(v); });
    return r;
#endif
}

// Round to nearest, ties to even, as a float (roundps 0, as llvm.nearbyint):
// unlike iround, exact for every float, so values beyond 2^31 come back
// unchanged and NaN and infinity stay what they are.
ST_INLINE Float round_even(Float x) {
#if defined(ST_SIMD_AVX512)
    return Float(FloatV(_mm512_roundscale_ps(__m512(x.v), _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC)));
#elif defined(ST_SIMD_AVX2)
    return Float(FloatV(_mm256_round_ps(__m256(x.v), _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC)));
#else
    Float r;
    for (int i = 0; i < kLanes; ++i) r.v[i] = like_roundps(x.v[i], [](float v) { return __builtin_roundevenf(v); });
    return r;
#endif
}

ST_INLINE Float abs(Float x) { return bit_cast_float(bit_cast_int(x) & Int(0x7fffffff)); }

// C's fmax and fmin: a NaN operand yields the other operand (for
// signalling NaNs too); otherwise the larger (smaller), the first on a tie.
// Not GLSL's max and min, whose tie gives the second (glsl::max).
ST_INLINE Float fmax(Float a, Float b) {
    const Float larger = select(a < b, b, a);  // NaN in a or b: a
    return select(a != a, b, larger);
}
ST_INLINE Float fmin(Float a, Float b) {
    const Float smaller = select(b < a, b, a);
    return select(a != a, b, smaller);
}

ST_INLINE Mask isnan(Float x) { return x != x; }

// float -> int32 truncating toward zero, with the x86 answer for what C++
// leaves undefined: NaN and values outside [-2^31, 2^31) give INT32_MIN
// (cvttps2dq, which is what llvmpipe's fptosi compiles to).
// The instruction itself where there is one, in inline assembly: GCC 12
// folds _mm256_cvttps_epi32 of a constant as C's conversion, saturating
// (3e9 gave INT32_MAX at -O2, the instruction INT32_MIN).
ST_INLINE Int itrunc(Float x) {
#if defined(ST_SIMD_AVX512)
    __m512i r;
    __asm__("vcvttps2dq %1, %0" : "=v"(r) : "v"(__m512(x.v)));
    return Int(IntV(r));
#elif defined(ST_SIMD_AVX2)
    __m256i r;
    __asm__("vcvttps2dq %1, %0" : "=x"(r) : "x"(__m256(x.v)));
    return Int(IntV(r));
#else
    const Mask in_range = (x >= Float(-2147483648.0f)) && (x < Float(2147483648.0f));
    const Float safe = select(in_range, x, Float(0.0f));
    const Int r(__builtin_convertvector(safe.v, IntV));
    return select(in_range, r, Int(INT32_MIN));
#endif
}

// float -> int32 rounding to nearest, ties to even (cvtps2dq, llvmpipe's
// lp_build_iround); NaN and values outside [-2^31, 2^31) give INT32_MIN.
ST_INLINE Int iround(Float x) {
#if defined(ST_SIMD_AVX512)
    return Int(IntV(_mm512_cvtps_epi32(__m512(x.v))));
#elif defined(ST_SIMD_AVX2)
    const Int r(IntV(_mm256_cvtps_epi32(__m256(x.v))));
    return r;
#else
    const Mask in_range = (x >= Float(-2147483648.0f)) && (x < Float(2147483648.0f));
    Float rounded;
    for (int i = 0; i < kLanes; ++i) rounded.v[i] = __builtin_nearbyintf(x.v[i]);
    const Int r(__builtin_convertvector(select(in_range, rounded, Float(0.0f)).v, IntV));
    return select(in_range, r, Int(INT32_MIN));
#endif
}

ST_INLINE Float to_float(Int x) { return Float(__builtin_convertvector(x.v, FloatV)); }

ST_INLINE Int min(Int a, Int b) { return select(a < b, a, b); }
ST_INLINE Int max(Int a, Int b) { return select(a < b, b, a); }
ST_INLINE Int clamp(Int x, Int lo, Int hi) { return min(max(x, lo), hi); }

// Two 32-byte halves joined in registers (a 64-byte load of two 32-byte
// stores would stall store forwarding).
ST_INLINE Float Float::load_groups(const float* const* p) {
#if defined(ST_SIMD_AVX512)
    return Float(FloatV(_mm512_insertf32x8(_mm512_castps256_ps512(_mm256_loadu_ps(p[0])), _mm256_loadu_ps(p[1]), 1)));
#else
    Float r;
    for (int g = 0; g < kLanes / 8; ++g) std::memcpy(reinterpret_cast<float*>(&r.v) + 8 * g, p[g], 32);
    return r;
#endif
}
ST_INLINE void Float::store_groups(float* const* p) const {
#if defined(ST_SIMD_AVX512)
    _mm256_storeu_ps(p[0], _mm512_castps512_ps256(__m512(v)));
    _mm256_storeu_ps(p[1], _mm512_extractf32x8_ps(__m512(v), 1));
#else
    for (int g = 0; g < kLanes / 8; ++g) std::memcpy(p[g], reinterpret_cast<const float*>(&v) + 8 * g, 32);
#endif
}

// Each 32-bit lane as two int16 halves (the packed 8-bit texel arithmetic of
// llvmpipe's AoS sampler): half-wise add, subtract and shift wrap modulo
// 2^16; mulhrs16 is pmulhrsw, (a * b + 0x4000) >> 15 per half.
using U16V = uint16_t __attribute__((vector_size(kLanes * 4)));
using I16V = int16_t __attribute__((vector_size(kLanes * 4)));
ST_INLINE Int add16(Int a, Int b) { return Int(IntV(U16V(a.v) + U16V(b.v))); }
ST_INLINE Int sub16(Int a, Int b) { return Int(IntV(U16V(a.v) - U16V(b.v))); }
ST_INLINE Int shl16(Int a, int n) { return Int(IntV(U16V(a.v) << n)); }
ST_INLINE Int mulhrs16(Int a, Int b) {
#if defined(ST_SIMD_AVX512) && defined(__AVX512BW__)
    return Int(IntV(_mm512_mulhrs_epi16(__m512i(a.v), __m512i(b.v))));
#elif defined(ST_SIMD_AVX2)
    return Int(IntV(_mm256_mulhrs_epi16(__m256i(a.v), __m256i(b.v))));
#else
    const I16V x = I16V(a.v), y = I16V(b.v);
    I16V r;
    for (int i = 0; i < 2 * kLanes; ++i) r[i] = int16_t((int32_t(x[i]) * int32_t(y[i]) + 0x4000) >> 15);
    return Int(IntV(r));
#endif
}

// Lane i of the result is lane idx[i] of table, for idx in [0, kLanes).
ST_INLINE Int permute(Int table, Int idx) {
#if defined(ST_SIMD_AVX512)
    return Int(IntV(_mm512_permutexvar_epi32(__m512i(idx.v), __m512i(table.v))));
#elif defined(ST_SIMD_AVX2)
    return Int(IntV(_mm256_permutevar8x32_epi32(__m256i(table.v), __m256i(idx.v))));
#elif defined(__clang__)
    // Clang has no __builtin_shuffle with run-time indices: pick lane by lane.
    IntV r;
    for (int i = 0; i < kLanes; ++i) r[i] = table.v[idx.v[i] & (kLanes - 1)];
    return Int(r);
#else
    return Int(__builtin_shuffle(table.v, idx.v & (kLanes - 1)));
#endif
}

// Lane i of the result is entry idx[i] of the 2 * kLanes entries of lo
// followed by hi, for idx in [0, 2 * kLanes).
ST_INLINE Int permute2(Int lo, Int hi, Int idx) {
#if defined(ST_SIMD_AVX512)
    return Int(IntV(_mm512_permutex2var_epi32(__m512i(lo.v), __m512i(idx.v), __m512i(hi.v))));
#elif defined(ST_SIMD_AVX2)
    const __m256i i = __m256i(idx.v);
    const __m256i a = _mm256_permutevar8x32_epi32(__m256i(lo.v), i), b = _mm256_permutevar8x32_epi32(__m256i(hi.v), i);
    return Int(IntV(_mm256_blendv_epi8(a, b, _mm256_cmpgt_epi32(i, _mm256_set1_epi32(kLanes - 1)))));
#else
    IntV r;
    for (int i = 0; i < kLanes; ++i) {
        const int j = idx.v[i] & (2 * kLanes - 1);
        r[i] = j < kLanes ? lo.v[j] : hi.v[j - kLanes];
    }
    return Int(r);
#endif
}

#if defined(ST_SIMD_AVX2)
// The eight lanes folded by `op` (min or max) in registers: GCC builds a
// plain loop's halves through the stack, and the reload waits on a failed
// store forward (perf: a third of Sampler2D::sample on Zen 2).
template <class Op>
ST_INLINE int32_t reduce8(Int x, Op op) {
    const __m256i v = __m256i(x.v);
    __m128i r = op(_mm256_castsi256_si128(v), _mm256_extracti128_si256(v, 1));
    r = op(r, _mm_shuffle_epi32(r, _MM_SHUFFLE(1, 0, 3, 2)));
    r = op(r, _mm_shuffle_epi32(r, _MM_SHUFFLE(2, 3, 0, 1)));
    return _mm_cvtsi128_si32(r);
}
#endif

ST_INLINE int32_t reduce_min(Int x) {
#if defined(ST_SIMD_AVX512)
    return _mm512_reduce_min_epi32(__m512i(x.v));
#elif defined(ST_SIMD_AVX2)
    return reduce8(x, [](__m128i a, __m128i b) { return _mm_min_epi32(a, b); });
#else
    int32_t r = x.v[0];
    for (int i = 1; i < kLanes; ++i) r = x.v[i] < r ? x.v[i] : r;
    return r;
#endif
}
ST_INLINE int32_t reduce_max(Int x) {
#if defined(ST_SIMD_AVX512)
    return _mm512_reduce_max_epi32(__m512i(x.v));
#elif defined(ST_SIMD_AVX2)
    return reduce8(x, [](__m128i a, __m128i b) { return _mm_max_epi32(a, b); });
#else
    int32_t r = x.v[0];
    for (int i = 1; i < kLanes; ++i) r = x.v[i] > r ? x.v[i] : r;
    return r;
#endif
}

// base[index] per active lane, 0 on the others; inactive lanes read nothing.
ST_INLINE Int gather(const int32_t* base, Int index, Mask active) {
#if defined(ST_SIMD_AVX512)
    const __mmask16 k = _mm512_movepi32_mask(__m512i(active.v));
    return Int(IntV(_mm512_mask_i32gather_epi32(_mm512_setzero_si512(), k, __m512i(index.v), base, 4)));
#elif defined(ST_SIMD_AVX2)
    return Int(IntV(_mm256_mask_i32gather_epi32(_mm256_setzero_si256(), reinterpret_cast<const int*>(base),
                                                __m256i(index.v), __m256i(active.v), 4)));
#else
    Int r;
    for (int i = 0; i < kLanes; ++i) r.v[i] = active.v[i] ? base[index.v[i]] : 0;
    return r;
#endif
}
// base[index] and base[index + 1] for every lane, as one 8-byte load per
// lane (two neighbouring texels); the caller guarantees both are in bounds.
ST_INLINE void gather_pairs(const int32_t* base, Int index, Int& first, Int& second) {
#if defined(ST_SIMD_AVX512)
    const __m512i idx = __m512i(index.v);
    const auto* b = reinterpret_cast<const long long*>(base);
    const __m512i lo = _mm512_i32gather_epi64(_mm512_castsi512_si256(idx), b, 4);
    const __m512i hi = _mm512_i32gather_epi64(_mm512_extracti64x4_epi64(idx, 1), b, 4);
    const __m512i even = _mm512_setr_epi32(0, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 26, 28, 30);
    const __m512i odd = _mm512_setr_epi32(1, 3, 5, 7, 9, 11, 13, 15, 17, 19, 21, 23, 25, 27, 29, 31);
    first = Int(IntV(_mm512_permutex2var_epi32(lo, even, hi)));
    second = Int(IntV(_mm512_permutex2var_epi32(lo, odd, hi)));
#elif defined(ST_SIMD_AVX2)
    // Eight 8-byte loads joined in registers: about as fast as two
    // vpgatherdq on Zen 2 (microbench), and not microcoded anywhere.
    auto pair = [&](int i) __attribute__((always_inline)) {
        return _mm_loadl_epi64(reinterpret_cast<const __m128i*>(base + index.v[i]));
    };
    auto four = [&](int i) __attribute__((always_inline)) {
        const __m128i a = _mm_unpacklo_epi64(pair(i), pair(i + 1)), b = _mm_unpacklo_epi64(pair(i + 2), pair(i + 3));
        return _mm256_castsi256_ps(_mm256_inserti128_si256(_mm256_castsi128_si256(a), b, 1));
    };
    const __m256 lo = four(0), hi = four(4);
    // lo holds lanes 0-3's pairs, hi lanes 4-7's; the even dwords of each
    // 128-bit half are the first texels, in lane order 0 1 4 5 | 2 3 6 7.
    const __m256 even = _mm256_shuffle_ps(lo, hi, _MM_SHUFFLE(2, 0, 2, 0));
    const __m256 odd = _mm256_shuffle_ps(lo, hi, _MM_SHUFFLE(3, 1, 3, 1));
    first = Int(IntV(_mm256_permute4x64_epi64(_mm256_castps_si256(even), _MM_SHUFFLE(3, 1, 2, 0))));
    second = Int(IntV(_mm256_permute4x64_epi64(_mm256_castps_si256(odd), _MM_SHUFFLE(3, 1, 2, 0))));
#else
    for (int i = 0; i < kLanes; ++i) {
        int32_t pair[2];
        std::memcpy(pair, base + index.v[i], sizeof pair);
        first.v[i] = pair[0];
        second.v[i] = pair[1];
    }
#endif
}

ST_INLINE Float gather(const float* base, Int index, Mask active) {
#if defined(ST_SIMD_AVX512)
    const __mmask16 k = _mm512_movepi32_mask(__m512i(active.v));
    return Float(FloatV(_mm512_mask_i32gather_ps(_mm512_setzero_ps(), k, __m512i(index.v), base, 4)));
#elif defined(ST_SIMD_AVX2)
    return Float(FloatV(_mm256_mask_i32gather_ps(_mm256_setzero_ps(), base, __m256i(index.v),
                                                 __m256(active.v), 4)));
#else
    Float r;
    for (int i = 0; i < kLanes; ++i) r.v[i] = active.v[i] ? base[index.v[i]] : 0.0f;
    return r;
#endif
}

// Lane offsets as unsigned scalars, for load_rows8: stored once, they serve
// every texture of one shape read at the same taps, and an unsigned offset
// needs no sign extension in an address.
struct LaneOffsets {
    alignas(64) uint32_t at[kLanes];
    explicit LaneOffsets(Int offset) { std::memcpy(at, &offset.v, sizeof at); }
};

// The 8 floats at base + offset[i] (offset in floats) for every lane i,
// transposed: out[c] holds float c of every lane's eight. Two neighbouring
// RGBA32F texels are one 32-byte load per lane instead of eight gathers;
// the caller guarantees all eight floats are in bounds.
ST_INLINE void load_rows8(const float* base, const LaneOffsets& offset, Float (&out)[8]) {
    const uint32_t* at = offset.at;
#if defined(ST_SIMD_AVX512)
    // Row j of each 8x8 block: lane j in the low half, lane j + 8 in the high.
    __m512 r[8];
    for (int j = 0; j < 8; ++j)
        r[j] = _mm512_insertf32x8(_mm512_castps256_ps512(_mm256_loadu_ps(base + at[j])),
                                  _mm256_loadu_ps(base + at[j + 8]), 1);
    __m512 t[8], u[8];
    for (int j = 0; j < 4; ++j) {
        t[2 * j] = _mm512_unpacklo_ps(r[2 * j], r[2 * j + 1]);
        t[2 * j + 1] = _mm512_unpackhi_ps(r[2 * j], r[2 * j + 1]);
    }
    for (int h = 0; h < 2; ++h) {  // rows 0-3, then 4-7
        const __m512 a0 = t[4 * h], a1 = t[4 * h + 1], b0 = t[4 * h + 2], b1 = t[4 * h + 3];
        u[4 * h + 0] = _mm512_shuffle_ps(a0, b0, 0x44);
        u[4 * h + 1] = _mm512_shuffle_ps(a0, b0, 0xee);
        u[4 * h + 2] = _mm512_shuffle_ps(a1, b1, 0x44);
        u[4 * h + 3] = _mm512_shuffle_ps(a1, b1, 0xee);
    }
    // u[c] (c < 4) holds float c of rows 0-3 in its 128-bit blocks 0 and 2
    // and float c + 4 in blocks 1 and 3; u[c + 4] the same for rows 4-7.
    const __m512i lo = _mm512_setr_epi32(0, 1, 2, 3, 16, 17, 18, 19, 8, 9, 10, 11, 24, 25, 26, 27);
    const __m512i hi = _mm512_setr_epi32(4, 5, 6, 7, 20, 21, 22, 23, 12, 13, 14, 15, 28, 29, 30, 31);
    for (int c = 0; c < 4; ++c) {
        out[c] = Float(FloatV(_mm512_permutex2var_ps(u[c], lo, u[c + 4])));
        out[c + 4] = Float(FloatV(_mm512_permutex2var_ps(u[c], hi, u[c + 4])));
    }
#elif defined(ST_SIMD_AVX2)
    // The 8x8 transpose with its last stage done by the loads: row j < 4
    // holds floats 0-3 of lane j in its low half and of lane j + 4 in its
    // high half, row j + 4 floats 4-7 of the same lanes (a 128-bit load and
    // a vinsertf128 from memory each), so two 4x4 transposes inside the
    // 128-bit halves finish it: 16 shuffles instead of 24.
    __m256 r[8];
    for (int j = 0; j < 4; ++j) {
        r[j] = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(base + at[j])), _mm_loadu_ps(base + at[j + 4]), 1);
        r[j + 4] = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(base + at[j] + 4)),
                                        _mm_loadu_ps(base + at[j + 4] + 4), 1);
    }
    for (int h = 0; h < 2; ++h) {  // floats 0-3, then 4-7
        const __m256 t0 = _mm256_unpacklo_ps(r[4 * h], r[4 * h + 1]), t1 = _mm256_unpackhi_ps(r[4 * h], r[4 * h + 1]);
        const __m256 t2 = _mm256_unpacklo_ps(r[4 * h + 2], r[4 * h + 3]), t3 = _mm256_unpackhi_ps(r[4 * h + 2], r[4 * h + 3]);
        out[4 * h + 0] = Float(FloatV(_mm256_shuffle_ps(t0, t2, 0x44)));
        out[4 * h + 1] = Float(FloatV(_mm256_shuffle_ps(t0, t2, 0xee)));
        out[4 * h + 2] = Float(FloatV(_mm256_shuffle_ps(t1, t3, 0x44)));
        out[4 * h + 3] = Float(FloatV(_mm256_shuffle_ps(t1, t3, 0xee)));
    }
#else
    for (int i = 0; i < kLanes; ++i)
        for (int c = 0; c < 8; ++c) out[c].v[i] = base[size_t(at[i]) + size_t(c)];
#endif
}

ST_INLINE void load_rows8(const float* base, Int offset, Float (&out)[8]) {
    load_rows8(base, LaneOffsets(offset), out);
}

// Lane i of the result is lane idx[i] of x: the quad shuffles behind dFdx.
ST_INLINE Float shuffle(Float x, IntV idx) {
#if defined(__clang__)
    // Clang has no __builtin_shuffle; it folds this loop when idx is a constant.
    FloatV r;
    for (int i = 0; i < kLanes; ++i) r[i] = x.v[idx[i] & (kLanes - 1)];
    return Float(r);
#else
    return Float(__builtin_shuffle(x.v, idx));
#endif
}

}  // namespace st::simd
