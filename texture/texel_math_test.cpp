// texel_math_test.cpp: the 8-bit lerp against llvmpipe's formula for every
// weight and every pair of bytes (lp_build_lerp_simple with pmulhrsw:
// v0 + ((w * ((v1 - v0) << 7) + 0x4000) >> 15), the sum kept to 8 bits).
#include "texture/texel_math.h"

#include <cstdint>

#include <gtest/gtest.h>

namespace st::texel {

namespace {

int llvmpipe_lerp8(int w, int v0, int v1) {
    const int16_t d = int16_t((v1 - v0) * 128);
    const int16_t rounded = int16_t((int32_t(w) * int32_t(d) + 0x4000) >> 15);
    return (v0 + rounded) & 0xff;
}

}  // namespace

TEST(TexelMath, Lerp8PairsIsLlvmpipesLerpForEveryWeightAndBytes) {
    // Lane k holds (v0, v1) = (k, b) in the low half and (b, k) in the high
    // one, so both halves and both signs of v1 - v0 are covered.
    int wrong = 0;
    for (int w = 0; w < 256; ++w) {
        const Int weight = lerp8_weight(Int(w));
        for (int a0 = 0; a0 < 256; a0 += kLanes)
            for (int b = 0; b < 256; ++b) {
                Int v0, v1;
                for (int k = 0; k < kLanes; ++k) {
                    v0.set(k, (a0 + k) | b << 16);
                    v1.set(k, b | (a0 + k) << 16);
                }
                const Int r = lerp8_pairs(weight, v0, v1);
                for (int k = 0; k < kLanes; ++k) {
                    const int a = a0 + k;
                    wrong += r[k] != (llvmpipe_lerp8(w, a, b) | llvmpipe_lerp8(w, b, a) << 16);
                }
            }
    }
    EXPECT_EQ(wrong, 0);
}

TEST(TexelMath, LevelWeight8IsTheTruncatedFraction) {
    Float f(0.0f);
    const float fractions[] = {0.0f, 0.00390625f, 0.0039f, 0.5f, 0.99999994f};
    for (int k = 0; k < kLanes; ++k) f.set(k, fractions[k % 5]);
    const Int w = level_weight8(f);
    const int expected[] = {0, 1, 0, 128, 255};
    for (int k = 0; k < kLanes; ++k) EXPECT_EQ(w[k], expected[k % 5]) << k;
}

}  // namespace st::texel
