// srgb_decode_test.cpp: llvmpipe's per-texel sRGB decode at the values the
// source reading found (docs/llvmpipe/mipmaps-cubes-formats.md 4.6): the
// linear segment up to 15, the fused cubic above, 255 exactly 1, and alpha
// as b * (1 / 255) rounded, which differs from b / 255.
#include "texture/srgb_decode.h"

#include <gtest/gtest.h>

#include "texture/srgb.h"

namespace st {
namespace {

TEST(SrgbDecode, LlvmpipesCubicNotTheIecCurve) {
    EXPECT_EQ(srgb_texel_colour(0), 0.0f);
    EXPECT_EQ(srgb_texel_colour(1), 0x1.465aacp-12f);
    EXPECT_EQ(srgb_texel_colour(15), 0x1.31f502p-8f);
    EXPECT_EQ(srgb_texel_colour(16), 0x1.5ae054p-8f);
    EXPECT_EQ(srgb_texel_colour(128), 0x1.bbacb8p-3f);
    EXPECT_EQ(srgb_texel_colour(254), 0x1.fb684ap-1f);
    EXPECT_EQ(srgb_texel_colour(255), 1.0f);
    EXPECT_NE(srgb_texel_colour(128), float(srgb_to_linear(128.0 / 255.0)));  // 0.216638 against 0.215861
    for (int b = 1; b < 256; ++b) ASSERT_GT(srgb_texel_colour(uint8_t(b)), srgb_texel_colour(uint8_t(b - 1))) << b;
    int differ = 0;
    for (int b = 0; b < 256; ++b) differ += srgb_texel_alpha(uint8_t(b)) != float(b) / 255.0f;
    EXPECT_GT(differ, 100);  // x * (1/255), not x / 255
    EXPECT_EQ(srgb_texel_alpha(255), 1.0f);
}

TEST(SrgbTransfer, EncodeInvertsDecodeOnEveryByte) {
    for (int b = 0; b < 256; ++b) ASSERT_EQ(std::lround(linear_to_srgb(srgb_to_linear(b / 255.0)) * 255.0), b) << b;
}

}  // namespace
}  // namespace st
