// lane_uint.h: GLSL's uint per lane (UInt), and the shifts by a per-lane
// count that GLSL's << and >> allow on int and uint. A UInt holds the same
// 32 bits as an Int; what differs is what they mean: unsigned compares,
// logical right shifts, float(u) from 0 ... 2^32 - 1. Arithmetic wraps
// modulo 2^32. Shift counts are masked to 5 bits, as gallivm masks them
// (lp_bld_nir.c ishl/ishr/ushr): GLSL leaves a count outside 0 ... 31
// undefined, llvmpipe gives count & 31, and so does the twin.
#pragma once

#include "simd/lanes.h"

namespace st::simd {

using UIntV = uint32_t __attribute__((vector_size(kLanes * 4)));

struct UInt {
    IntV v;

    UInt() : v{} {}
    UInt(uint32_t s) : v(IntV ST_SPLAT(int32_t(s))) {}
    explicit UInt(IntV x) : v(x) {}
    explicit UInt(Int x) : v(x.v) {}  // uint(i): the same bits

    uint32_t operator[](int lane) const { return uint32_t(v[lane]); }
    void set(int lane, uint32_t x) { v[lane] = int32_t(x); }
    UIntV u() const { return UIntV(v); }
};

ST_INLINE Int int_bits(UInt x) { return Int(x.v); }  // int(u): the same bits

ST_INLINE UInt operator+(UInt a, UInt b) { return UInt(IntV(a.u() + b.u())); }
ST_INLINE UInt operator-(UInt a, UInt b) { return UInt(IntV(a.u() - b.u())); }
ST_INLINE UInt operator*(UInt a, UInt b) { return UInt(IntV(a.u() * b.u())); }
ST_INLINE UInt operator&(UInt a, UInt b) { return UInt(a.v & b.v); }
ST_INLINE UInt operator|(UInt a, UInt b) { return UInt(a.v | b.v); }
ST_INLINE UInt operator^(UInt a, UInt b) { return UInt(a.v ^ b.v); }
ST_INLINE UInt operator~(UInt a) { return UInt(~a.v); }
ST_INLINE UInt operator<<(UInt a, UInt n) { return UInt(IntV(a.u() << (n.u() & 31u))); }
ST_INLINE UInt operator>>(UInt a, UInt n) { return UInt(IntV(a.u() >> (n.u() & 31u))); }  // logical
ST_INLINE UInt operator<<(UInt a, int n) { return UInt(IntV(a.u() << (n & 31))); }
ST_INLINE UInt operator>>(UInt a, int n) { return UInt(IntV(a.u() >> (n & 31))); }
ST_INLINE Mask operator<(UInt a, UInt b) { return Mask(IntV(a.u() < b.u())); }
ST_INLINE Mask operator>(UInt a, UInt b) { return Mask(IntV(a.u() > b.u())); }
ST_INLINE Mask operator<=(UInt a, UInt b) { return Mask(IntV(a.u() <= b.u())); }
ST_INLINE Mask operator>=(UInt a, UInt b) { return Mask(IntV(a.u() >= b.u())); }
ST_INLINE Mask operator==(UInt a, UInt b) { return Mask(a.v == b.v); }
ST_INLINE Mask operator!=(UInt a, UInt b) { return Mask(a.v != b.v); }
ST_INLINE UInt select(Mask m, UInt a, UInt b) { return UInt(m.v ? a.v : b.v); }

// int << and >> by a per-lane count (arithmetic right shift), masked.
ST_INLINE Int shl(Int a, Int n) { return Int(IntV(UIntV(a.v) << UIntV(n.v & 31))); }
ST_INLINE Int ashr(Int a, Int n) { return Int(a.v >> (n.v & 31)); }
ST_INLINE Int operator~(Int a) { return Int(~a.v); }

// uint(f) for f in [0, 2^32): truncated toward zero (fptoui). Below 2^31 it
// is the int conversion; from 2^31 up, the int conversion of f - 2^31 (exact
// there) with the top bit set. GLSL leaves a negative, NaN or too large f
// undefined, and llvmpipe's answer there depends on the host (LLVM lowers
// fptoui with AVX-512's vcvttps2udq where it can, with this two-step sequence
// on AVX2): the twin gives this sequence's answer, without undefined
// behaviour, and no scene relies on it.
ST_INLINE UInt to_uint(Float x) {
    const Mask high = x >= Float(2147483648.0f);
    const Int low_part = itrunc(x);
    const Int high_part = itrunc(x - Float(2147483648.0f)) ^ Int(INT32_MIN);
    return UInt(select(high, high_part, low_part));
}

// float(u): correctly rounded from the unsigned value (uitofp), as the
// two halves' exact sum: the high 16 bits times 2^16 (exact), plus the low.
ST_INLINE Float to_float(UInt x) {
    const Float hi = to_float(Int(IntV(x.u() >> 16))) * Float(65536.0f);
    const Float lo = to_float(Int(x.v & 0xFFFF));
    return hi + lo;
}

}  // namespace st::simd
