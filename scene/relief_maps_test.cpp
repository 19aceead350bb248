// relief_maps_test.cpp: the relief scenes' generated assets are
// deterministic, tileable, in range, and their normals agree with their
// heights.
#include "scene/relief_maps.h"

#include <cmath>

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

namespace st {
namespace {

StoneParams small_stones() {
    StoneParams p;
    p.size = 64;
    p.cells = 4;
    return p;
}

DropParams small_drops() {
    DropParams p;
    p.size = 64;
    p.drops = 6;
    return p;
}

TEST(ReliefMaps, DeterministicPerSeedAndDifferentAcrossSeeds) {
    StoneParams a = small_stones(), b = small_stones();
    EXPECT_EQ(stone_heights(a).h, stone_heights(b).h);
    EXPECT_EQ(relief_texture(stone_heights(a), 0.1, "m").texels8, relief_texture(stone_heights(b), 0.1, "m").texels8);
    EXPECT_EQ(stone_colour_texture(a, "c").texels8, stone_colour_texture(b, "c").texels8);
    b.seed = 99;
    EXPECT_NE(stone_heights(a).h, stone_heights(b).h);
    DropParams d = small_drops(), e = small_drops();
    EXPECT_EQ(drop_heights(d).h, drop_heights(e).h);
    e.seed = 99;
    EXPECT_NE(drop_heights(d).h, drop_heights(e).h);
}

TEST(ReliefMaps, HeightsInRangeWithJointsAndTops) {
    const HeightField stones = stone_heights(small_stones());
    double lo = 1, hi = 0;
    for (double h : stones.h) {
        ASSERT_GE(h, 0.0);
        ASSERT_LE(h, 1.0);
        lo = std::min(lo, h), hi = std::max(hi, h);
    }
    EXPECT_LT(lo, 0.1);  // joints
    EXPECT_GT(hi, 0.6);  // stone tops
    const DropParams dp = small_drops();
    const HeightField drops = drop_heights(dp);
    double drop_hi = 0;
    for (double h : drops.h) {
        ASSERT_GE(h, dp.level);  // the film everywhere
        ASSERT_LE(h, dp.max_peak);
        drop_hi = std::max(drop_hi, h);
    }
    EXPECT_GT(drop_hi, dp.min_peak * 0.9);
}

// Across the wrap the field steps no more, on average, than between
// neighbours inside: REPEAT shows no seam (a ramp, say, would step by its
// whole range there and by 1/size inside).
void expect_tileable(const HeightField& f) {
    double inner = 0, seam = 0;
    for (int y = 0; y < f.size; ++y) {
        for (int x = 0; x + 1 < f.size; ++x)
            inner += std::abs(f.at(x + 1, y) - f.at(x, y)) + std::abs(f.at(y, x + 1) - f.at(y, x));
        seam += std::abs(f.at(0, y) - f.at(f.size - 1, y)) + std::abs(f.at(y, 0) - f.at(y, f.size - 1));
    }
    inner /= double(f.size - 1);
    EXPECT_LE(seam, 2.0 * inner);
}

TEST(ReliefMaps, Tileable) {
    expect_tileable(stone_heights(small_stones()));
    expect_tileable(drop_heights(small_drops()));
    // The check sees a seam where there is one.
    HeightField ramp{32, std::vector<double>(32 * 32)};
    for (int i = 0; i < 32 * 32; ++i) ramp.h[size_t(i)] = (i % 32) / 31.0;
    EXPECT_NONFATAL_FAILURE(expect_tileable(ramp), "");
}

TEST(ReliefMaps, NormalsFollowTheSlopeAndHeightsSitInAlpha) {
    HeightField ramp;
    ramp.size = 16;
    ramp.h.resize(256);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) ramp.h[size_t(y * 16 + x)] = 0.25 + 0.5 * std::sin(x * 3.14159265358979 / 8.0) * 0.5;
    const Texture t = relief_texture(ramp, 0.2, "m");
    // At x = 2 the height rises with u: the normal leans towards -u.
    const uint8_t* rising = &t.texels8[(5 * 16 + 2) * 4];
    EXPECT_LT(rising[0], 128);
    EXPECT_EQ(rising[1], 128);  // no slope in v
    EXPECT_EQ(rising[3], uint8_t(std::lround(ramp.at(2, 5) * 255)));
    // A flat field is the straight-up normal.
    HeightField flat{8, std::vector<double>(64, 0.5)};
    const Texture f = relief_texture(flat, 0.2, "m");
    for (int i = 0; i < 64; ++i) {
        EXPECT_EQ(f.texels8[size_t(i) * 4 + 0], 128);
        EXPECT_EQ(f.texels8[size_t(i) * 4 + 1], 128);
        EXPECT_EQ(f.texels8[size_t(i) * 4 + 2], 255);
        EXPECT_EQ(f.texels8[size_t(i) * 4 + 3], 128);
    }
}

TEST(ReliefMaps, FullTrilinearChains) {
    const Texture t = relief_texture(stone_heights(small_stones()), 0.1, "m");
    EXPECT_EQ(t.level_count(), 7);  // 64 .. 1
    EXPECT_EQ(t.mip_filter, MipFilter::Linear);
    EXPECT_EQ(t.wrap_s, TextureWrap::Repeat);
    const Texture c = stone_colour_texture(small_stones(), "c");
    EXPECT_EQ(c.level_count(), 7);
}

}  // namespace
}  // namespace st

namespace st {
namespace {

TEST(ReliefMaps, SkyCubeIsHdrWithTheSunWhereItShouldBe) {
    const Texture sky = sky_cube_texture(16, glm::dvec3(0, 0, 1), 50.0, 10.0, "environment");
    ASSERT_TRUE(sky.cube);
    ASSERT_EQ(sky.texels32.size(), size_t(6 * 16 * 16 * 4));
    auto texel = [&](int face, int x, int y, int c) { return sky.texels32[((size_t(face) * 16 + y) * 16 + x) * 4 + c]; };
    // A sun at the zenith sits in the middle of the +Z face and is HDR.
    EXPECT_GT(texel(4, 8, 8, 0), 20.0f);
    // Straight down (-Z) is ground: dark, no sun.
    EXPECT_LT(texel(5, 8, 8, 0), 0.5f);
    // Just above the horizon on +X (z = -sc, so column 7) is sky, brighter
    // than the ground just below it (column 8).
    EXPECT_GT(texel(0, 7, 8, 2), 1.0f);
    EXPECT_LT(texel(0, 8, 8, 2), 0.5f);
    for (float v : sky.texels32) ASSERT_TRUE(std::isfinite(v));
}

}  // namespace
}  // namespace st
