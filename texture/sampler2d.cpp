// sampler2d.cpp: texture(), mirroring llvmpipe's two filtering paths, on
// all lanes at once (the scalar calls are one lane of the same code).
//
// RGBA32F (and nearest filtering of any format) goes through the float SoA
// sampler (gallivm lp_bld_sample_soa.c); RGBA8 with linear filtering goes
// through the 8-bit fixed-point AoS sampler (lp_bld_sample_aos.c), which
// llvmpipe picks for formats that fit 8-bit unorm with simple wrap modes.
// Texture sizes decide between the power-of-two and general repeat code.
// Integer lanes wrap modulo 2^32 and float-to-int conversions give
// INT32_MIN for NaN or out-of-range values, as on x86 (simd/lanes.h), so no
// coordinate is undefined behaviour; every texel read is bounds-checked or
// in range by construction.
#include "texture/sampler2d.h"

#include <algorithm>
#include <cstring>

namespace st {

namespace {

using simd::fma;
using simd::floor;
using simd::iround;
using simd::itrunc;

bool is_pot(int n) { return (n & (n - 1)) == 0; }

// std::clamp(x, lo, hi) per lane: a NaN stays NaN.
Float clamp_like_std(Float x, Float lo, Float hi) { return select(x < lo, lo, select(hi < x, hi, x)); }

// Float texel coordinates for linear filtering along one axis: the lower
// texel i0, the upper i1 and the weight of i1 (wrap_linear in
// lp_bld_sample_soa.c).
struct LinearTaps {
    Int i0, i1;
    Float weight;
};

ST_INLINE LinearTaps linear_taps_float(Float s, int size, TextureWrap wrap) {
    const Float size_f = Float(float(size));
    LinearTaps t;
    if (wrap == TextureWrap::ClampToEdge) {
        Float u = s * size_f;
        u = select(simd::isnan(u), size_f, select(size_f < u, size_f, u));  // min(u, size), NaN -> size
        u = u - Float(0.5f);
        u = select(u < Float(0.0f), Float(0.0f), u);
        const Float fl = floor(u);
        t.weight = u - fl;
        t.i0 = itrunc(fl);
        t.i1 = simd::min(t.i0 + Int(1), Int(size - 1));
    } else if (is_pot(size)) {
        const Float u = s * size_f - Float(0.5f);
        const Float fl = floor(u);
        t.weight = u - fl;
        t.i0 = itrunc(fl) & Int(size - 1);
        t.i1 = (itrunc(fl) + Int(1)) & Int(size - 1);
    } else {
        // Normalised repeat is fract(); the -0.5 then needs a fix-up below 0.
        Float u = s - floor(s);
        u = u * size_f - Float(0.5f);
        const Float fl = floor(u);
        t.weight = u - fl;
        t.i0 = select(u < Float(0.0f), Int(size - 1), itrunc(fl));
        t.i1 = select(t.i0 != Int(size - 1), t.i0 + Int(1), Int(0));
    }
    return t;
}

// The same in 8.8 fixed point for the AoS path: the weight is an integer
// in [0, 255] (wrap_linear_int and repeat_npot_linear_int).
struct LinearTaps8 {
    Int i0, i1, weight;
};

ST_INLINE LinearTaps8 linear_taps_fixed(Float s, int size, TextureWrap wrap) {
    LinearTaps8 t;
    if (wrap == TextureWrap::Repeat && !is_pot(size)) {
        Float u = s - floor(s);
        u = u * Float(float(size));
        const Int fixed = iround(u * Float(256.0f)) - Int(128);
        t.weight = fixed & Int(255);
        t.i0 = fixed >> 8;
        t.i0 = select(t.i0 < Int(0), Int(size - 1), t.i0);
        t.i0 = simd::min(t.i0, Int(size - 1));
        t.i1 = select(t.i0 != Int(size - 1), t.i0 + Int(1), Int(0));
        return t;
    }
    const Int fixed = iround(s * Float(float(size << 8))) - Int(128);
    t.weight = fixed & Int(255);
    const Int i0 = fixed >> 8;
    if (wrap == TextureWrap::Repeat) {
        t.i0 = i0 & Int(size - 1);
        t.i1 = (i0 + Int(1)) & Int(size - 1);
    } else {
        t.i0 = simd::clamp(i0, Int(0), Int(size - 1));
        t.i1 = simd::clamp(i0 + Int(1), Int(0), Int(size - 1));
    }
    return t;
}

// 8-bit lerp with an 8-bit weight, as pmulhrsw computes it in
// lp_build_lerp_simple: ((w * (d << 7)) >> 14 + 1) >> 1, kept to 8 bits and
// added to v0 modulo 256; here on two channels at once, one per 16-bit half
// of each lane, with the weight in both halves (pmulhrsw itself where the
// build has it).
ST_INLINE Int lerp8_pairs(Int w, Int v0, Int v1) {
    const Int rounded = simd::mulhrs16(w, simd::shl16(simd::sub16(v1, v0), 7));
    return (v0 + (rounded & Int(0x00ff00ff))) & Int(0x00ff00ff);
}

// Float lerp: fma(t, v1 - v0, v0), as lp_build_mad fuses it.
ST_INLINE Float lerp_float(Float t, Float v0, Float v1) { return fma(t, v1 - v0, v0); }

ST_INLINE Int nearest_texel(Float s, int size, TextureWrap wrap) {
    const Float size_f = Float(float(size));
    if (wrap == TextureWrap::ClampToEdge) {
        // itrunc is enough: the clamp removes every negative.
        const Float u = s * size_f;
        const Int i = select(simd::isnan(u), Int(0), itrunc(clamp_like_std(u, Float(-1.0f), size_f)));
        return simd::clamp(i, Int(0), Int(size - 1));
    }
    if (is_pot(size)) return itrunc(floor(s * size_f)) & Int(size - 1);
    // fract_safe keeps the fraction below 1.
    const Float fraction = s - floor(s);
    const Float f = select(Float(0x1.fffffep-1f) < fraction, Float(0x1.fffffep-1f), fraction);
    return itrunc(f * size_f);
}

// unorm8 to float: k * fl(1/255), one rounding (lp_bld_conv.c).
ST_INLINE Float unorm8_to_float(Int k) { return simd::to_float(k) * Float(1.0f / 255.0f); }

// When every lane's four taps lie within kLanes texels of a row and
// kWindowRows rows (a magnified or unscaled texture, where neighbouring
// pixels read neighbouring texels), the rows are loaded whole and each lane
// picks its texels with a permute: the same texels as the gathers, without
// them. Returns false (nothing written) otherwise.
#if defined(ST_SIMD_AVX512)
// The same for AVX-512 and its two 8-lane groups (4x2 pixels each), without
// reductions: each group's window starts at its lane 0's taps (the lowest
// for a texture that is not mirrored on the screen), and is 8 texels by 2
// rows for each row of taps. The four tables of a call (each group's two rows
// under v.i0 and under v.i1) make two 32-entry permutes per tap row.
using simd::IntV;

bool fetch_window_groups(const std::vector<int32_t>& rgba8, int width, int height, const LinearTaps8& u,
                         const LinearTaps8& v, Int& t00, Int& t10, Int& t01, Int& t11) {
    const __m512i lane0_of_group = _mm512_setr_epi32(0, 0, 0, 0, 0, 0, 0, 0, 8, 8, 8, 8, 8, 8, 8, 8);
    auto group_base = [&](Int x) { return Int(IntV(_mm512_permutexvar_epi32(lane0_of_group, __m512i(x.v)))); };
    const Int u_base = group_base(u.i0), v0_base = group_base(v.i0), v1_base = group_base(v.i1);
    const Int x0 = u.i0 - u_base, x1 = u.i1 - u_base, y0 = v.i0 - v0_base, y1 = v.i1 - v1_base;
    using UV = uint32_t __attribute__((vector_size(64)));
    const auto outside = [](Int d, uint32_t n) { return __m512i(IntV(UV(d.v) >= n)); };
    const __m512i bad = _mm512_or_si512(_mm512_or_si512(outside(x0, 8), outside(x1, 8)),
                                        _mm512_or_si512(outside(y0, 2), outside(y1, 2)));
    if (_mm512_test_epi32_mask(bad, bad)) return false;
    // Row r of group g's window under base row b: 8 texels from its u_base.
    auto row = [&](int g, int32_t b, int r) {
        const int32_t y = std::min(b + r, height - 1);  // a row past the edge is loaded but never picked
        return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(
            &rgba8[size_t(y) * size_t(width) + size_t(u_base[8 * g])]));
    };
    auto table = [&](const Int& base, __m512i& lo, __m512i& hi) {
        // lo = row 0 of both groups, hi = row 1: entry r * 16 + g * 8 + x.
        lo = _mm512_inserti64x4(_mm512_castsi256_si512(row(0, base[0], 0)), row(1, base[8], 0), 1);
        hi = _mm512_inserti64x4(_mm512_castsi256_si512(row(0, base[0], 1)), row(1, base[8], 1), 1);
    };
    __m512i a_lo, a_hi, b_lo, b_hi;
    table(v0_base, a_lo, a_hi);
    table(v1_base, b_lo, b_hi);
    const __m512i group8 = _mm512_setr_epi32(0, 0, 0, 0, 0, 0, 0, 0, 8, 8, 8, 8, 8, 8, 8, 8);
    auto index = [&](Int y, Int x) { return _mm512_add_epi32(_mm512_add_epi32(__m512i((y << 4).v), group8), __m512i(x.v)); };
    t00 = Int(IntV(_mm512_permutex2var_epi32(a_lo, index(y0, x0), a_hi)));
    t10 = Int(IntV(_mm512_permutex2var_epi32(a_lo, index(y0, x1), a_hi)));
    t01 = Int(IntV(_mm512_permutex2var_epi32(b_lo, index(y1, x0), b_hi)));
    t11 = Int(IntV(_mm512_permutex2var_epi32(b_lo, index(y1, x1), b_hi)));
    return true;
}
#endif

bool fetch_window(const std::vector<int32_t>& rgba8, int width, const LinearTaps8& u, const LinearTaps8& v,
                  Int& t00, Int& t10, Int& t01, Int& t11) {
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

glm::vec4 lane0(const Vec4& v) { return glm::vec4(v.x[0], v.y[0], v.z[0], v.w[0]); }

}  // namespace

Sampler2D::Sampler2D(const Texture& texture) : tex_(&texture) {
    if (texture.format == TextureFormat::RGBA8) {
        rgba8_.assign(texture.texels8.size() / 4 + kLanes, 0);
        std::memcpy(rgba8_.data(), texture.texels8.data(), texture.texels8.size());
    }
}

Vec4 Sampler2D::fetch(Int x, Int y) const {
    const Mask inside = !(x < Int(0)) && !(y < Int(0)) && x < Int(tex_->width) && y < Int(tex_->height);
    const Int texel = y * Int(tex_->width) + x;
    if (tex_->format == TextureFormat::RGBA8) {
        const Int rgba = simd::gather(rgba8_.data(), texel, inside);
        return Vec4(unorm8_to_float(rgba & Int(0xff)), unorm8_to_float((rgba >> 8) & Int(0xff)),
                    unorm8_to_float((rgba >> 16) & Int(0xff)), unorm8_to_float((rgba >> 24) & Int(0xff)));
    }
    const float* t = tex_->texels32.data();
    const Int i = texel * Int(4);
    return Vec4(simd::gather(t, i, inside), simd::gather(t + 1, i, inside), simd::gather(t + 2, i, inside),
                simd::gather(t + 3, i, inside));
}

Vec4 Sampler2D::sample(const Vec2& st) const {
    if (tex_->filter == TextureFilter::Nearest) return sample_nearest(st);
    return tex_->format == TextureFormat::RGBA8 ? sample_linear_unorm8(st) : sample_linear_float(st);
}

glm::vec4 Sampler2D::sample(const glm::vec2& st) const { return lane0(sample(Vec2(Float(st.x), Float(st.y)))); }

glm::vec4 Sampler2D::fetch(int x, int y) const { return lane0(fetch(Int(x), Int(y))); }

Vec4 Sampler2D::sample_nearest(const Vec2& st) const {
    return fetch(nearest_texel(st.x, tex_->width, tex_->wrap), nearest_texel(st.y, tex_->height, tex_->wrap));
}

Vec4 Sampler2D::sample_linear_float(const Vec2& st) const {
    const LinearTaps u = linear_taps_float(st.x, tex_->width, tex_->wrap);
    const LinearTaps v = linear_taps_float(st.y, tex_->height, tex_->wrap);
    const Vec4 t00 = fetch(u.i0, v.i0), t10 = fetch(u.i1, v.i0);
    const Vec4 t01 = fetch(u.i0, v.i1), t11 = fetch(u.i1, v.i1);
    auto bilinear = [&](Float a00, Float a10, Float a01, Float a11) {
        return lerp_float(v.weight, lerp_float(u.weight, a00, a10), lerp_float(u.weight, a01, a11));
    };
    return Vec4(bilinear(t00.x, t10.x, t01.x, t11.x), bilinear(t00.y, t10.y, t01.y, t11.y),
                bilinear(t00.z, t10.z, t01.z, t11.z), bilinear(t00.w, t10.w, t01.w, t11.w));
}

Vec4 Sampler2D::sample_linear_unorm8(const Vec2& st) const {
    const LinearTaps8 u = linear_taps_fixed(st.x, tex_->width, tex_->wrap);
    const LinearTaps8 v = linear_taps_fixed(st.y, tex_->height, tex_->wrap);
    // Every tap is inside the texture by construction (wrapped or clamped).
    // Each row's two taps are neighbours but where the wrap or the clamp
    // joins them otherwise; those lanes are fetched again.
    Int t00, t10, t01, t11;
#if defined(ST_SIMD_AVX512)
    const bool windowed = fetch_window_groups(rgba8_, tex_->width, tex_->height, u, v, t00, t10, t01, t11) ||
                          fetch_window(rgba8_, tex_->width, u, v, t00, t10, t01, t11);
#else
    const bool windowed = fetch_window(rgba8_, tex_->width, u, v, t00, t10, t01, t11);
#endif
    if (!windowed) {
        const int32_t* texels = rgba8_.data();
        const Int w(tex_->width);
        const Int row0 = v.i0 * w, row1 = v.i1 * w;
        simd::gather_pairs(texels, row0 + u.i0, t00, t10);
        simd::gather_pairs(texels, row1 + u.i0, t01, t11);
        const Mask apart = u.i1 != u.i0 + Int(1);
        if (simd::any(apart)) {
            t10 = select(apart, simd::gather(texels, row0 + u.i1, apart), t10);
            t11 = select(apart, simd::gather(texels, row1 + u.i1, apart), t11);
        }
    }
    // Two channels per lane, one in each 16-bit half (R and B, then G and
    // A), lerped at once.
    const Int wu = u.weight | (u.weight << 16), wv = v.weight | (v.weight << 16);
    auto pairs = [&](int shift) {
        auto half_bytes = [&](Int t) { return (t >> shift) & Int(0x00ff00ff); };
        const Int bottom = lerp8_pairs(wu, half_bytes(t00), half_bytes(t10));
        const Int top = lerp8_pairs(wu, half_bytes(t01), half_bytes(t11));
        return lerp8_pairs(wv, bottom, top);
    };
    const Int rb = pairs(0), ga = pairs(8);
    return Vec4(unorm8_to_float(rb & Int(0xff)), unorm8_to_float(ga & Int(0xff)), unorm8_to_float(rb >> 16),
                unorm8_to_float(ga >> 16));
}

}  // namespace st
