// sampler2d.cpp: texture(), mirroring llvmpipe's two filtering paths.
//
// RGBA32F (and nearest filtering of any format) goes through the float SoA
// sampler (gallivm lp_bld_sample_soa.c); RGBA8 with linear filtering goes
// through the 8-bit fixed-point AoS sampler (lp_bld_sample_aos.c), which
// llvmpipe picks for formats that fit 8-bit unorm with simple wrap modes.
// Texture sizes decide between the power-of-two and general repeat code.
#include "texture/sampler2d.h"

#include <algorithm>
#include <cmath>

#include <cstring>

#include <xmmintrin.h>
#ifdef __SSSE3__
#include <tmmintrin.h>
#endif

namespace st {

namespace {

bool is_pot(int n) { return (n & (n - 1)) == 0; }

// cvtss2si: round to nearest, ties to even (the default MXCSR mode), as
// llvmpipe's lp_build_iround.
inline int iround(float x) { return _mm_cvtss_si32(_mm_set_ss(x)); }

// Float texel coordinates for linear filtering along one axis: the lower
// texel i0, the upper i1 and the weight of i1 (wrap_linear in
// lp_bld_sample_soa.c).
struct LinearTaps {
    int i0, i1;
    float weight;
};

inline __attribute__((always_inline)) LinearTaps linear_taps_float(float s, int size, TextureWrap wrap) {
    const float size_f = float(size);
    LinearTaps t;
    if (wrap == TextureWrap::ClampToEdge) {
        float u = s * size_f;
        u = std::isnan(u) ? size_f : std::min(u, size_f);
        u = u - 0.5f;
        u = std::max(u, 0.0f);
        const float fl = std::floor(u);
        t.weight = u - fl;
        t.i0 = int(fl);
        t.i1 = std::min(t.i0 + 1, size - 1);
    } else if (is_pot(size)) {
        const float u = s * size_f - 0.5f;
        const float fl = std::floor(u);
        t.weight = u - fl;
        t.i0 = int(fl) & (size - 1);
        t.i1 = (int(fl) + 1) & (size - 1);
    } else {
        // Normalised repeat is fract(); the -0.5 then needs a fix-up below 0.
        float u = s - std::floor(s);
        u = u * size_f - 0.5f;
        const float fl = std::floor(u);
        t.weight = u - fl;
        t.i0 = u < 0.0f ? size - 1 : int(fl);
        t.i1 = t.i0 != size - 1 ? t.i0 + 1 : 0;
    }
    return t;
}

// The same in 8.8 fixed point for the AoS path: the weight is an integer
// in [0, 255] (wrap_linear_int and repeat_npot_linear_int).
struct LinearTaps8 {
    int i0, i1, weight;
};

inline __attribute__((always_inline)) LinearTaps8 linear_taps_fixed(float s, int size, TextureWrap wrap) {
    LinearTaps8 t;
    if (wrap == TextureWrap::Repeat && !is_pot(size)) {
        float u = s - std::floor(s);
        u = u * float(size);
        const int fixed = iround(u * 256.0f) - 128;
        t.weight = fixed & 255;
        t.i0 = fixed >> 8;
        if (t.i0 < 0) t.i0 = size - 1;
        t.i0 = std::min(t.i0, size - 1);
        t.i1 = t.i0 != size - 1 ? t.i0 + 1 : 0;
        return t;
    }
    const int fixed = iround(s * float(size << 8)) - 128;
    t.weight = fixed & 255;
    const int i0 = fixed >> 8;
    if (wrap == TextureWrap::Repeat) {
        t.i0 = i0 & (size - 1);
        t.i1 = (i0 + 1) & (size - 1);
    } else {
        t.i0 = std::clamp(i0, 0, size - 1);
        t.i1 = std::clamp(i0 + 1, 0, size - 1);
    }
    return t;
}

// 8-bit lerp with an 8-bit weight, as pmulhrsw computes it in
// lp_build_lerp_simple: ((w * (d << 7)) >> 14 + 1) >> 1, kept to 8 bits and
// added to v0 modulo 256. The scalar form of the SSSE3 path below, and the
// fallback without SSSE3.
[[maybe_unused]] int lerp8(int w, int v0, int v1) {
    const int product = w * ((v1 - v0) * 128);
    const int rounded = ((product >> 14) + 1) >> 1;
    return (v0 + (rounded & 0xff)) & 0xff;
}

// Float lerp: fma(t, v1 - v0, v0), as lp_build_mad fuses it.
float lerp_float(float t, float v0, float v1) { return std::fma(t, v1 - v0, v0); }

int nearest_texel(float s, int size, TextureWrap wrap) {
    const float size_f = float(size);
    if (wrap == TextureWrap::ClampToEdge) {
        // itrunc is enough: the clamp removes every negative.
        const float u = s * size_f;
        const int i = std::isnan(u) ? 0 : int(std::clamp(u, -1.0f, size_f));
        return std::clamp(i, 0, size - 1);
    }
    if (is_pot(size)) return int(std::floor(s * size_f)) & (size - 1);
    // fract_safe keeps the fraction below 1.
    const float f = std::min(s - std::floor(s), 0x1.fffffep-1f);
    return int(f * size_f);
}

}  // namespace

glm::vec4 Sampler2D::fetch(int x, int y) const {
    if (x < 0 || y < 0 || x >= tex_->width || y >= tex_->height) return glm::vec4(0.0f);
    const size_t i = (size_t(y) * tex_->width + x) * 4;
    if (tex_->format == TextureFormat::RGBA8) {
        // unorm8 to float: k * fl(1/255), one rounding (lp_bld_conv.c).
        const uint8_t* t = &tex_->texels8[i];
        return glm::vec4(t[0], t[1], t[2], t[3]) * (1.0f / 255.0f);
    }
    const float* t = &tex_->texels32[i];
    return glm::vec4(t[0], t[1], t[2], t[3]);
}

glm::vec4 Sampler2D::sample(const glm::vec2& st) const {
    if (tex_->filter == TextureFilter::Nearest) return sample_nearest(st);
    return tex_->format == TextureFormat::RGBA8 ? sample_linear_unorm8(st) : sample_linear_float(st);
}

namespace {
void set_lane(Vec4& out, int lane, const glm::vec4& t) {
    out.x.set(lane, t.x);
    out.y.set(lane, t.y);
    out.z.set(lane, t.z);
    out.w.set(lane, t.w);
}
}  // namespace

Vec4 Sampler2D::sample(const Vec2& st) const {
    Vec4 out;
    for (int lane = 0; lane < kLanes; ++lane) set_lane(out, lane, sample(glm::vec2(st.x[lane], st.y[lane])));
    return out;
}

Vec4 Sampler2D::fetch(Int x, Int y) const {
    Vec4 out;
    for (int lane = 0; lane < kLanes; ++lane) set_lane(out, lane, fetch(x[lane], y[lane]));
    return out;
}

glm::vec4 Sampler2D::sample_nearest(const glm::vec2& st) const {
    return fetch(nearest_texel(st.x, tex_->width, tex_->wrap), nearest_texel(st.y, tex_->height, tex_->wrap));
}

glm::vec4 Sampler2D::sample_linear_float(const glm::vec2& st) const {
    const LinearTaps u = linear_taps_float(st.x, tex_->width, tex_->wrap);
    const LinearTaps v = linear_taps_float(st.y, tex_->height, tex_->wrap);
    const glm::vec4 t00 = fetch(u.i0, v.i0), t10 = fetch(u.i1, v.i0);
    const glm::vec4 t01 = fetch(u.i0, v.i1), t11 = fetch(u.i1, v.i1);
    glm::vec4 out;
    for (int c = 0; c < 4; ++c)
        out[c] = lerp_float(v.weight, lerp_float(u.weight, t00[c], t10[c]),
                            lerp_float(u.weight, t01[c], t11[c]));
    return out;
}

glm::vec4 Sampler2D::sample_linear_unorm8(const glm::vec2& st) const {
    const LinearTaps8 u = linear_taps_fixed(st.x, tex_->width, tex_->wrap);
    const LinearTaps8 v = linear_taps_fixed(st.y, tex_->height, tex_->wrap);
    auto texel = [&](int x, int y) { return &tex_->texels8[(size_t(y) * tex_->width + x) * 4]; };
    const uint8_t *t00 = texel(u.i0, v.i0), *t10 = texel(u.i1, v.i0);
    const uint8_t *t01 = texel(u.i0, v.i1), *t11 = texel(u.i1, v.i1);
    glm::vec4 out;
#ifdef __SSSE3__
    // The four channels of both rows at once, in 16-bit lanes as llvmpipe
    // holds them, with pmulhrsw itself: the same integers as lerp8.
    auto load = [](const uint8_t* p) {
        int32_t word;
        std::memcpy(&word, p, 4);
        return _mm_cvtsi32_si128(word);
    };
    const __m128i zero = _mm_setzero_si128(), low8 = _mm_set1_epi16(0xff);
    const __m128i a = _mm_unpacklo_epi8(_mm_unpacklo_epi32(load(t00), load(t01)), zero);  // t00 | t01
    const __m128i b = _mm_unpacklo_epi8(_mm_unpacklo_epi32(load(t10), load(t11)), zero);  // t10 | t11
    auto lerp = [&](__m128i w, __m128i v0, __m128i v1) {
        const __m128i rounded = _mm_mulhrs_epi16(w, _mm_slli_epi16(_mm_sub_epi16(v1, v0), 7));
        return _mm_and_si128(_mm_add_epi16(v0, _mm_and_si128(rounded, low8)), low8);
    };
    const __m128i rows = lerp(_mm_set1_epi16(int16_t(u.weight)), a, b);  // lerp(t00, t10) | lerp(t01, t11)
    const __m128i value = lerp(_mm_set1_epi16(int16_t(v.weight)), rows, _mm_unpackhi_epi64(rows, rows));
    const __m128 f = _mm_mul_ps(_mm_cvtepi32_ps(_mm_unpacklo_epi16(value, zero)), _mm_set1_ps(1.0f / 255.0f));
    _mm_storeu_ps(&out[0], f);
#else
    for (int c = 0; c < 4; ++c) {
        const int value = lerp8(v.weight, lerp8(u.weight, t00[c], t10[c]), lerp8(u.weight, t01[c], t11[c]));
        out[c] = float(value) * (1.0f / 255.0f);
    }
#endif
    return out;
}

}  // namespace st
