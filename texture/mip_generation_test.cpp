// mip_generation_test.cpp: chain sizes, the box filter's averages (odd
// sizes included) and the RGBA16F store's rounding toward zero.
#include "texture/mip_generation.h"

#include <bit>

#include <gtest/gtest.h>

#include "texture/texel_formats.h"

namespace st {

TEST(MipGeneration, ChainSizesGoDownToOneByOne) {
    EXPECT_EQ(full_chain_levels(16, 16), 5);
    EXPECT_EQ(full_chain_levels(12, 10), 4);  // 12x10, 6x5, 3x2, 1x1
    EXPECT_EQ(full_chain_levels(1, 1), 1);
    EXPECT_EQ(full_chain_levels(1, 8), 4);
}

TEST(MipGeneration, BoxFilterAveragesTheFootprint) {
    Texture t;
    t.format = TextureFormat::RGBA32F;
    t.width = 3;
    t.height = 1;
    t.texels32 = {0, 0, 0, 0, 3, 3, 3, 3, 6, 6, 6, 6};
    generate_box_mips(t, full_chain_levels(3, 1));
    ASSERT_EQ(t.mips.size(), 1u);  // 3x1 -> 1x1
    EXPECT_FLOAT_EQ(t.mips[0].texels32[0], 3.0f);
    std::string why;
    EXPECT_TRUE(mip_sizes_valid(t, why)) << why;
    t.mips[0].width = 2;
    EXPECT_FALSE(mip_sizes_valid(t, why));
    EXPECT_NE(why.find("level 1"), std::string::npos);
}

TEST(MipGeneration, Rgba8LevelsRoundToNearest) {
    Texture t;
    t.format = TextureFormat::RGBA8;
    t.width = 2;
    t.height = 1;
    t.texels8 = {0, 1, 10, 255, 1, 2, 11, 255};
    generate_box_mips(t, 2);
    EXPECT_EQ(int(t.mips[0].texels8[0]), 1);   // 0.5 rounds away from zero
    EXPECT_EQ(int(t.mips[0].texels8[1]), 2);   // 1.5
    EXPECT_EQ(int(t.mips[0].texels8[2]), 11);  // 10.5
    EXPECT_EQ(int(t.mips[0].texels8[3]), 255);
}

TEST(TexelFormats, Rgba16fTruncatesTowardZero) {
    EXPECT_EQ(rgba16f_stored(1.0f), 1.0f);
    EXPECT_EQ(rgba16f_stored(1.0f + 0x1.8p-11f), 1.0f);        // below the next half (1 + 2^-10)
    EXPECT_EQ(rgba16f_stored(-(1.0f + 0x1.8p-10f)), -(1.0f + 0x1p-10f));
    EXPECT_EQ(rgba16f_stored(70000.0f), 65504.0f);
    EXPECT_EQ(rgba16f_stored(-1e30f), -65504.0f);
    EXPECT_EQ(rgba16f_stored(0x1.8p-24f), 0x1p-24f);            // a denormal half, truncated
    EXPECT_EQ(rgba16f_stored(0x1p-25f), 0.0f);
    EXPECT_TRUE(std::signbit(rgba16f_stored(-0x1p-25f)));
    EXPECT_TRUE(std::isinf(rgba16f_stored(INFINITY)));
    EXPECT_TRUE(std::isnan(rgba16f_stored(NAN)));
    // Measured on llvmpipe: 0x7FC12345 is stored as the half 0x7E09.
    EXPECT_EQ(std::bit_cast<uint32_t>(rgba16f_stored(std::bit_cast<float>(0x7fc12345u))), 0x7fc12000u);
    EXPECT_EQ(std::bit_cast<uint32_t>(rgba16f_stored(std::bit_cast<float>(0xff812345u))), 0xffc12000u);
}

TEST(TexelFormats, Rgba16fLanesMatchOneFloat) {
    float v[kLanes];
    for (uint32_t i = 0; i < 4000; ++i) {
        for (int lane = 0; lane < kLanes; ++lane)
            v[lane] = std::bit_cast<float>((i * 2654435761u + uint32_t(lane) * 40503u) ^ (i << 20));
        const Float r = rgba16f_stored(Float::load(v));
        for (int lane = 0; lane < kLanes; ++lane)
            ASSERT_EQ(std::bit_cast<uint32_t>(r[lane]), std::bit_cast<uint32_t>(rgba16f_stored(v[lane]))) << v[lane];
    }
}

}  // namespace st
