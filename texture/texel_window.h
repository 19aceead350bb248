// texel_window.h: the 8-bit sampler's texel windows. Where the taps of a
// vector's lanes lie close together (a magnified, unscaled or slightly
// minified read, where neighbouring pixels read neighbouring texels), a few
// rows of the level are loaded whole and each lane picks its texels with a
// permute: the same texels as gathers, without them. Each function returns
// false (nothing written) where its window does not hold every tap; the
// caller (Sampler2D::filter_unorm8) tries them in order, then gathers.
// Inline, for texture/sampler2d.cpp only.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "simd/lane_vec.h"
#include "texture/texel_math.h"

namespace st::texel {

#if defined(ST_SIMD_AVX512)
// Each lane's x at lane 0 of its 8-lane group.
ST_INLINE Int group_lane0(Int x) {
    const __m512i lane0_of_group = _mm512_setr_epi32(0, 0, 0, 0, 0, 0, 0, 0, 8, 8, 8, 8, 8, 8, 8, 8);
    return Int(IntV(_mm512_permutexvar_epi32(lane0_of_group, __m512i(x.v))));
}
// All ones in the lanes where d is outside [0, n) (a negative d compares
// as a large unsigned one).
ST_INLINE __m512i outside(Int d, uint32_t n) {
    using UV = uint32_t __attribute__((vector_size(64)));
    return __m512i(IntV(UV(d.v) >= n));
}

// Row r of both groups' windows, each 8 texels from its group's u_base on
// row v_base + r: entry g * 8 + x is group g's texel x. A row past the
// last is loaded but never picked (in bounds: the texels have kLanes of
// padding).
ST_INLINE __m512i group_rows(const int32_t* rgba8, int width, int height, const Int& u_base, const Int& v_base, int r) {
    auto load = [&](int g) __attribute__((always_inline)) {
        const int32_t y = std::min(v_base[8 * g] + r, height - 1);
        return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(&rgba8[size_t(y) * size_t(width) + size_t(u_base[8 * g])]));
    };
    return _mm512_inserti64x4(_mm512_castsi256_si512(load(0)), load(1), 1);
}

// AVX-512's two 8-lane groups (4x2 pixels each), without reductions: each
// group's window starts at its lane 0's taps (the lowest for a texture that
// is not mirrored on the screen), and is 8 texels by 2 rows for each row of
// taps (a magnified or unscaled read). The four tables
// of a call (each group's two rows under v.i0 and under v.i1) make two
// 32-entry permutes per tap row.
ST_INLINE bool fetch_window_groups_2rows(const int32_t* rgba8, int width, int height, const LinearTaps8& u, const LinearTaps8& v,
                         Int& t00, Int& t10, Int& t01, Int& t11) {
    const Int u_base = group_lane0(u.i0), v0_base = group_lane0(v.i0), v1_base = group_lane0(v.i1);
    const Int x0 = u.i0 - u_base, x1 = u.i1 - u_base, y0 = v.i0 - v0_base, y1 = v.i1 - v1_base;
    const __m512i bad = _mm512_or_si512(_mm512_or_si512(outside(x0, 8), outside(x1, 8)),
                                        _mm512_or_si512(outside(y0, 2), outside(y1, 2)));
    if (_mm512_test_epi32_mask(bad, bad)) return false;
    // Row r of group g's window under base row b: 8 texels from its u_base.
    auto row = [&](int g, int32_t b, int r) __attribute__((always_inline)) {
        const int32_t y = std::min(b + r, height - 1);  // a row past the edge is loaded but never picked
        return _mm256_loadu_si256(
            reinterpret_cast<const __m256i*>(&rgba8[size_t(y) * size_t(width) + size_t(u_base[8 * g])]));
    };
    auto table = [&](const Int& base, __m512i& lo, __m512i& hi) __attribute__((always_inline)) {
        // lo = row 0 of both groups, hi = row 1: entry r * 16 + g * 8 + x.
        lo = _mm512_inserti64x4(_mm512_castsi256_si512(row(0, base[0], 0)), row(1, base[8], 0), 1);
        hi = _mm512_inserti64x4(_mm512_castsi256_si512(row(0, base[0], 1)), row(1, base[8], 1), 1);
    };
    __m512i a_lo, a_hi, b_lo, b_hi;
    table(v0_base, a_lo, a_hi);
    table(v1_base, b_lo, b_hi);
    const __m512i group8 = _mm512_setr_epi32(0, 0, 0, 0, 0, 0, 0, 0, 8, 8, 8, 8, 8, 8, 8, 8);
    auto index = [&](Int y, Int x) __attribute__((always_inline)) {
        return _mm512_add_epi32(_mm512_add_epi32(__m512i((y << 4).v), group8), __m512i(x.v));
    };
    t00 = Int(IntV(_mm512_permutex2var_epi32(a_lo, index(y0, x0), a_hi)));
    t10 = Int(IntV(_mm512_permutex2var_epi32(a_lo, index(y0, x1), a_hi)));
    t01 = Int(IntV(_mm512_permutex2var_epi32(b_lo, index(y1, x0), b_hi)));
    t11 = Int(IntV(_mm512_permutex2var_epi32(b_lo, index(y1, x1), b_hi)));
    return true;
}
// The lower-left taps alone (every lane at a texel centre): each group's
// two rows under its lane 0's, one permute.
ST_INLINE bool fetch_window_groups_centre(const int32_t* rgba8, int width, int height, const LinearTaps8& u,
                                          const LinearTaps8& v, Int& t00) {
    const Int u_base = group_lane0(u.i0), v_base = group_lane0(v.i0);
    const Int x0 = u.i0 - u_base, y0 = v.i0 - v_base;
    const __m512i bad = _mm512_or_si512(outside(x0, 8), outside(y0, 2));
    if (_mm512_test_epi32_mask(bad, bad)) return false;
    auto rows = [&](int r) __attribute__((always_inline)) { return group_rows(rgba8, width, height, u_base, v_base, r); };
    const __m512i group8 = _mm512_setr_epi32(0, 0, 0, 0, 0, 0, 0, 0, 8, 8, 8, 8, 8, 8, 8, 8);
    const __m512i index = _mm512_add_epi32(_mm512_add_epi32(__m512i((y0 << 4).v), group8), __m512i(x0.v));
    t00 = Int(IntV(_mm512_permutex2var_epi32(rows(0), index, rows(1))));
    return true;
}
// Where that fails, each group's window 8 texels by 4 rows from its lane
// 0's lower taps, as in the 8-lane form below: the four tables of a call
// (row r of both groups) make two 32-entry permutes and a select per tap.
ST_INLINE bool fetch_window_groups_4rows(const int32_t* rgba8, int width, int height, const LinearTaps8& u, const LinearTaps8& v,
                         Int& t00, Int& t10, Int& t01, Int& t11) {
    const Int u_base = group_lane0(u.i0), v_base = group_lane0(v.i0);
    const Int x0 = u.i0 - u_base, x1 = u.i1 - u_base, y0 = v.i0 - v_base, y1 = v.i1 - v_base;
    const __m512i bad = _mm512_or_si512(_mm512_or_si512(outside(x0, 8), outside(x1, 8)),
                                        _mm512_or_si512(outside(y0, 4), outside(y1, 4)));
    if (_mm512_test_epi32_mask(bad, bad)) return false;
    auto rows = [&](int r) __attribute__((always_inline)) { return group_rows(rgba8, width, height, u_base, v_base, r); };
    const __m512i r0 = rows(0), r1 = rows(1), r2 = rows(2), r3 = rows(3);
    const __m512i group8 = _mm512_setr_epi32(0, 0, 0, 0, 0, 0, 0, 0, 8, 8, 8, 8, 8, 8, 8, 8);
    // Row y of the window at column x: the permutes read index bits 0-4,
    // so (y << 4) picks between rows 0 and 1 (or 2 and 3) by y's low bit.
    auto pick = [&](Int y, Int x) __attribute__((always_inline)) {
        const __m512i index = _mm512_add_epi32(_mm512_add_epi32(__m512i((y << 4).v), group8), __m512i(x.v));
        const __m512i low = _mm512_permutex2var_epi32(r0, index, r1), high = _mm512_permutex2var_epi32(r2, index, r3);
        return Int(IntV(_mm512_mask_blend_epi32(_mm512_test_epi32_mask(__m512i(y.v), _mm512_set1_epi32(2)), low, high)));
    };
    t00 = pick(y0, x0);
    t10 = pick(y0, x1);
    t01 = pick(y1, x0);
    t11 = pick(y1, x1);
    return true;
}
#else
// One 8-lane group (4x2 pixels) without reductions: the window
// starts at lane 0's taps and is 8 texels by 2 rows for each row of taps
// (a magnified or unscaled read), so four row loads and two permutes a
// tap. Lane 0 is the group's top-left pixel; where its taps are not the
// lowest (a texture mirrored on the screen, lanes of a loop that moved
// apart) this returns false.
ST_INLINE bool fetch_window_group_2rows(const int32_t* rgba8, int width, int height, const LinearTaps8& u, const LinearTaps8& v,
                                  Int& t00, Int& t10, Int& t01, Int& t11) {
    const int32_t u_base = u.i0[0], v0_base = v.i0[0], v1_base = v.i1[0];
    const Int x0 = u.i0 - Int(u_base), x1 = u.i1 - Int(u_base), y0 = v.i0 - Int(v0_base), y1 = v.i1 - Int(v1_base);
    // Inside means x0, x1 in [0, kLanes) and y0, y1 in [0, 2): no bit set
    // outside the low ones (a negative difference has the sign bit).
    const Int bad = ((x0 | x1) & Int(~(kLanes - 1))) | ((y0 | y1) & Int(~1));
    if (simd::any_bit(bad)) return false;
    auto row = [&](int32_t y) __attribute__((always_inline)) {
        // A row past the last is loaded but never picked (in bounds: the
        // texels have kLanes of padding).
        return Int::load(&rgba8[size_t(std::min(y, height - 1)) * size_t(width) + size_t(u_base)]);
    };
    const Int a0 = row(v0_base), a1 = row(v0_base + 1), b0 = row(v1_base), b1 = row(v1_base + 1);
    const Mask second0 = y0 != Int(0), second1 = y1 != Int(0);
    t00 = select(second0, simd::permute(a1, x0), simd::permute(a0, x0));
    t10 = select(second0, simd::permute(a1, x1), simd::permute(a0, x1));
    t01 = select(second1, simd::permute(b1, x0), simd::permute(b0, x0));
    t11 = select(second1, simd::permute(b1, x1), simd::permute(b0, x1));
    return true;
}
// The lower-left taps alone (every lane at a texel centre): two rows from
// lane 0's, a permute of each and a select.
ST_INLINE bool fetch_window_group_centre(const int32_t* rgba8, int width, int height, const LinearTaps8& u,
                                         const LinearTaps8& v, Int& t00) {
    const int32_t u_base = u.i0[0], v_base = v.i0[0];
    const Int x0 = u.i0 - Int(u_base), y0 = v.i0 - Int(v_base);
    if (simd::any_bit((x0 & Int(~(kLanes - 1))) | (y0 & Int(~1)))) return false;
    auto row = [&](int32_t y) __attribute__((always_inline)) {
        return Int::load(&rgba8[size_t(std::min(y, height - 1)) * size_t(width) + size_t(u_base)]);
    };
    t00 = select(y0 != Int(0), simd::permute(row(v_base + 1), x0), simd::permute(row(v_base), x0));
    return true;
}
// Where that fails, a window from lane 0's lower taps 8 texels by 4 rows,
// enough for both rows of taps of a quad pair that reads up to two texels
// a pixel (the finer level of a trilinear read): four row loads and, per
// tap, a permute of each row and three selects (the 2-row form first: this
// one costs a third more where both fit).
ST_INLINE bool fetch_window_group_4rows(const int32_t* rgba8, int width, int height, const LinearTaps8& u, const LinearTaps8& v,
                                  Int& t00, Int& t10, Int& t01, Int& t11) {
    const int32_t u_base = u.i0[0], v_base = v.i0[0];
    const Int x0 = u.i0 - Int(u_base), x1 = u.i1 - Int(u_base), y0 = v.i0 - Int(v_base), y1 = v.i1 - Int(v_base);
    // Inside means x0, x1 in [0, kLanes) and y0, y1 in [0, 4): no bit set
    // outside the low ones (a negative difference has the sign bit).
    const Int bad = ((x0 | x1) & Int(~(kLanes - 1))) | ((y0 | y1) & Int(~3));
    if (simd::any_bit(bad)) return false;
    auto row = [&](int32_t r) __attribute__((always_inline)) {
        // A row past the last is loaded but never picked (in bounds: the
        // texels have kLanes of padding).
        return Int::load(&rgba8[size_t(std::min(v_base + r, height - 1)) * size_t(width) + size_t(u_base)]);
    };
    const Int r0 = row(0), r1 = row(1), r2 = row(2), r3 = row(3);
    // Row y of the window, in each lane, at column x.
    auto pick = [&](Int y, Int x) __attribute__((always_inline)) {
        const Mask odd = (y & Int(1)) != Int(0), upper = (y & Int(2)) != Int(0);
        const Int low = select(odd, simd::permute(r1, x), simd::permute(r0, x));
        const Int high = select(odd, simd::permute(r3, x), simd::permute(r2, x));
        return select(upper, high, low);
    };
    t00 = pick(y0, x0);
    t10 = pick(y0, x1);
    t01 = pick(y1, x0);
    t11 = pick(y1, x1);
    return true;
}
#endif

// Any vector whose taps lie within kLanes texels of a row and kWindowRows
// rows, found by reductions: the fallback of the group windows above.
ST_INLINE bool fetch_window(const int32_t* rgba8, int width, const LinearTaps8& u, const LinearTaps8& v, Int& t00, Int& t10,
                  Int& t01, Int& t11) {
    constexpr int kWindowRows = 6;
    const int32_t u_lo = simd::reduce_min(simd::min(u.i0, u.i1)), u_hi = simd::reduce_max(simd::max(u.i0, u.i1));
    const int32_t v_lo = simd::reduce_min(simd::min(v.i0, v.i1)), v_hi = simd::reduce_max(simd::max(v.i0, v.i1));
    if (u_hi - u_lo >= kLanes || v_hi - v_lo >= kWindowRows) return false;
    const int rows = v_hi - v_lo + 1;
    const Int x0 = u.i0 - Int(u_lo), x1 = u.i1 - Int(u_lo);
    for (int r = 0; r < rows; ++r) {
        // In bounds: the texels have kLanes of padding past the last row.
        const Int row = Int::load(&rgba8[size_t(v_lo + r) * size_t(width) + size_t(u_lo)]);
        const Int a = simd::permute(row, x0), b = simd::permute(row, x1);
        const Mask on0 = v.i0 == Int(v_lo + r), on1 = v.i1 == Int(v_lo + r);
        t00 = r ? select(on0, a, t00) : a;
        t10 = r ? select(on0, b, t10) : b;
        t01 = r ? select(on1, a, t01) : a;
        t11 = r ? select(on1, b, t11) : b;
    }
    return true;
}

}  // namespace st::texel
