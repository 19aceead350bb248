// integer.h: GLSL's integer built-ins (uaddCarry, usubBorrow, umulExtended,
// imulExtended, bitfieldExtract, bitfieldInsert, bitfieldReverse, bitCount,
// findLSB, findMSB) as llvmpipe computes them (docs/llvmpipe/glsl-builtins.md
// 6.1; proved by the scenes conformance-builtins-integer-*). Integer code
// has one right answer where GLSL defines it; what is llvmpipe's own is the
// rest: shift counts are masked to 5 bits, so bitfieldExtract and
// bitfieldInsert with an offset or bits count outside the spec's range give
// what NIR's shift lowering gives (lower_bitfield_*_to_shifts), not an
// error. Each function is written once for one int32 (scalar::) and run
// per lane for the lane types: these are rare in shaders, and the loop is
// plainly the same arithmetic.
#pragma once

#include <bit>
#include <cstdint>

#include "simd/lane_vec.h"

namespace st::glsl {

namespace integer_detail {
ST_INLINE uint32_t shl(uint32_t a, int32_t n) { return a << (uint32_t(n) & 31u); }
ST_INLINE uint32_t shr(uint32_t a, int32_t n) { return a >> (uint32_t(n) & 31u); }
ST_INLINE int32_t ashr(int32_t a, int32_t n) { return a >> (uint32_t(n) & 31u); }

// f applied lane by lane to UInt/Int arguments.
template <class R, class F, class... A> ST_INLINE R per_lane(F f, const A&... args) {
    R r;
    for (int lane = 0; lane < kLanes; ++lane) r.set(lane, f(args[lane]...));
    return r;
}
}  // namespace integer_detail

// uaddCarry(x, y, carry): x + y modulo 2^32, carry 1 where it wrapped.
ST_INLINE uint32_t uaddCarry(uint32_t x, uint32_t y, uint32_t& carry) {
    const uint32_t sum = x + y;
    carry = sum < x ? 1u : 0u;
    return sum;
}
ST_INLINE UInt uaddCarry(UInt x, UInt y, UInt& carry) {
    const UInt sum = x + y;
    carry = simd::select(sum < x, UInt(1u), UInt(0u));
    return sum;
}
// usubBorrow(x, y, borrow): x - y modulo 2^32, borrow 1 where x < y.
ST_INLINE uint32_t usubBorrow(uint32_t x, uint32_t y, uint32_t& borrow) {
    borrow = x < y ? 1u : 0u;
    return x - y;
}
ST_INLINE UInt usubBorrow(UInt x, UInt y, UInt& borrow) {
    borrow = simd::select(x < y, UInt(1u), UInt(0u));
    return x - y;
}

// umulExtended and imulExtended: the 64-bit product's high and low words.
ST_INLINE void umulExtended(uint32_t x, uint32_t y, uint32_t& msb, uint32_t& lsb) {
    const uint64_t p = uint64_t(x) * uint64_t(y);
    msb = uint32_t(p >> 32);
    lsb = uint32_t(p);
}
ST_INLINE void umulExtended(UInt x, UInt y, UInt& msb, UInt& lsb) {
    for (int lane = 0; lane < kLanes; ++lane) {
        uint32_t hi, lo;
        umulExtended(x[lane], y[lane], hi, lo);
        msb.set(lane, hi);
        lsb.set(lane, lo);
    }
}
ST_INLINE void imulExtended(int32_t x, int32_t y, int32_t& msb, int32_t& lsb) {
    const int64_t p = int64_t(x) * int64_t(y);
    msb = int32_t(uint32_t(uint64_t(p) >> 32));
    lsb = int32_t(uint32_t(uint64_t(p)));
}
ST_INLINE void imulExtended(Int x, Int y, Int& msb, Int& lsb) {
    for (int lane = 0; lane < kLanes; ++lane) {
        int32_t hi, lo;
        imulExtended(x[lane], y[lane], hi, lo);
        msb.set(lane, hi);
        lsb.set(lane, lo);
    }
}

// bitfieldExtract(int): bits == 0 ? 0 : (v << (32 - bits - offset)) >> (32 - bits),
// the right shift arithmetic (sign-extending); counts masked.
ST_INLINE int32_t bitfieldExtract(int32_t v, int32_t offset, int32_t bits) {
    using namespace integer_detail;
    if (bits == 0) return 0;
    return ashr(int32_t(shl(uint32_t(v), 32 - bits - offset)), 32 - bits);
}
// bitfieldExtract(uint): (v >> offset) & (bits == 32 ? ~0 : (1 << bits) - 1).
ST_INLINE uint32_t bitfieldExtract(uint32_t v, int32_t offset, int32_t bits) {
    using namespace integer_detail;
    return shr(v, offset) & (bits == 32 ? ~0u : shl(1u, bits) - 1u);
}
// bitfieldInsert: bits > 31 (unsigned) gives insert; else base with the
// field (1 << bits) - 1 at offset taken from insert << offset.
ST_INLINE uint32_t bitfieldInsert(uint32_t base, uint32_t insert, int32_t offset, int32_t bits) {
    using namespace integer_detail;
    if (uint32_t(bits) > 31u) return insert;
    const uint32_t mask = shl(shl(1u, bits) - 1u, offset);
    return (base & ~mask) | (shl(insert, offset) & mask);
}
ST_INLINE int32_t bitfieldInsert(int32_t base, int32_t insert, int32_t offset, int32_t bits) {
    return int32_t(bitfieldInsert(uint32_t(base), uint32_t(insert), offset, bits));
}
ST_INLINE uint32_t bitfieldReverse(uint32_t v) {
    uint32_t r = 0;
    for (int i = 0; i < 32; ++i) r |= ((v >> i) & 1u) << (31 - i);
    return r;
}
ST_INLINE int32_t bitfieldReverse(int32_t v) { return int32_t(bitfieldReverse(uint32_t(v))); }
ST_INLINE int32_t bitCount(uint32_t v) { return std::popcount(v); }
ST_INLINE int32_t bitCount(int32_t v) { return std::popcount(uint32_t(v)); }
// findLSB: -1 for 0. findMSB(uint): -1 for 0. findMSB(int): of ~v for
// negative v, so -1 for both 0 and -1.
ST_INLINE int32_t findLSB(uint32_t v) { return v == 0 ? -1 : std::countr_zero(v); }
ST_INLINE int32_t findLSB(int32_t v) { return findLSB(uint32_t(v)); }
ST_INLINE int32_t findMSB(uint32_t v) { return 31 - std::countl_zero(v); }
ST_INLINE int32_t findMSB(int32_t v) { return findMSB(uint32_t(v < 0 ? ~v : v)); }

// The lane forms: the one-int32 function per lane.
ST_INLINE Int bitfieldExtract(Int v, Int offset, Int bits) {
    return integer_detail::per_lane<Int>([](int32_t a, int32_t o, int32_t b) { return bitfieldExtract(a, o, b); }, v,
                                         offset, bits);
}
ST_INLINE UInt bitfieldExtract(UInt v, Int offset, Int bits) {
    return integer_detail::per_lane<UInt>([](uint32_t a, int32_t o, int32_t b) { return bitfieldExtract(a, o, b); }, v,
                                          offset, bits);
}
ST_INLINE UInt bitfieldInsert(UInt base, UInt insert, Int offset, Int bits) {
    return integer_detail::per_lane<UInt>(
        [](uint32_t a, uint32_t i, int32_t o, int32_t b) { return bitfieldInsert(a, i, o, b); }, base, insert, offset,
        bits);
}
ST_INLINE Int bitfieldInsert(Int base, Int insert, Int offset, Int bits) {
    return simd::int_bits(bitfieldInsert(UInt(base), UInt(insert), offset, bits));
}
ST_INLINE UInt bitfieldReverse(UInt v) {
    return integer_detail::per_lane<UInt>([](uint32_t a) { return bitfieldReverse(a); }, v);
}
ST_INLINE Int bitfieldReverse(Int v) { return simd::int_bits(bitfieldReverse(UInt(v))); }
ST_INLINE Int bitCount(UInt v) { return integer_detail::per_lane<Int>([](uint32_t a) { return bitCount(a); }, v); }
ST_INLINE Int bitCount(Int v) { return bitCount(UInt(v)); }
ST_INLINE Int findLSB(UInt v) { return integer_detail::per_lane<Int>([](uint32_t a) { return findLSB(a); }, v); }
ST_INLINE Int findLSB(Int v) { return findLSB(UInt(v)); }
ST_INLINE Int findMSB(UInt v) { return integer_detail::per_lane<Int>([](uint32_t a) { return findMSB(a); }, v); }
ST_INLINE Int findMSB(Int v) { return integer_detail::per_lane<Int>([](int32_t a) { return findMSB(a); }, v); }

}  // namespace st::glsl
