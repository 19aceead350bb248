// srgb_decode.cpp: see srgb_decode.h. The 256 values are computed once.
#include "texture/srgb_decode.h"

#include <array>
#include <cmath>

namespace st {

namespace {

// lp_bld_format_srgb.c:103-107 and :137, as C float expressions.
constexpr float kC0 = 0.0023f;
constexpr float kC1 = 0.0030f / 255.0f;
constexpr float kC2 = 0.6935f / (255.0f * 255.0f);
constexpr float kC3 = 0.3012f / (255.0f * 255.0f * 255.0f);
constexpr float kLinear = 1.0f / (12.6f * 255.0f);

float decode(int b) {
    const float x = float(b);
    const float x2 = x * x;  // exact for x <= 255
    // lp_build_polynomial: odd and even terms apart, then joined.
    const float odd = std::fma(x2, kC3, kC1);
    const float even = std::fma(x2, kC2, kC0);
    const float poly = std::fma(odd, x, even);
    return x <= 15.0f ? x * kLinear : poly;
}

const std::array<float, 256>& table() {
    static const std::array<float, 256> t = [] {
        std::array<float, 256> out{};
        for (int b = 0; b < 256; ++b) out[size_t(b)] = decode(b);
        return out;
    }();
    return t;
}

}  // namespace

float srgb_texel_colour(uint8_t b) { return table()[b]; }

float srgb_texel_alpha(uint8_t b) { return float(b) * 0x1.010102p-8f; }

}  // namespace st
