// Tests of profile_albedo.h: Sec. 3.1's convolved, white-normalised texture.
#include "scene/profile_albedo.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace st {
namespace {

// A flat 40 mm slab, a profile about 1 mm wide, freckles of 1 mm.
struct Fixture {
    ProfileShape shape;
    BuiltProfiles profiles;
    AlbedoMap map;
    Fixture() {
        shape.size_mm = 40;
        profiles.r_max = 6;
        for (int c = 0; c < 3; ++c) {
            profiles.R[size_t(c)] = [](double r) { return std::exp(-r); };
            profiles.T[size_t(c)] = [](double) { return 0.0; };
        }
        map.pattern = "freckles";
        map.count = 60;
        map.radius_mm = 1.0;
        map.strength = {0.3, 0.5, 0.7};
    }
};

TEST(ProfileAlbedo, MeanIsWhiteAndTheProfileBlurs) {
    Fixture f;
    const Texture t = albedo_texture(f.map, f.shape, f.profiles, false, 128);
    ASSERT_EQ(t.width, 128);
    for (int c = 0; c < 3; ++c) {
        double sum = 0, lowest = 1e9;
        for (size_t x = 0; x < t.texels32.size() / 4; ++x) {
            sum += t.texels32[x * 4 + size_t(c)];
            lowest = std::min(lowest, double(t.texels32[x * 4 + size_t(c)]));
        }
        // Every texel has the same area on the slab: the plain mean is the area mean.
        EXPECT_NEAR(sum / (128.0 * 128.0), 1.0, 1e-5) << c;
        // A freckle's centre takes 1 - strength of the raw map; blurred by a
        // profile wider than it, much less (the raw minimum over the mean,
        // which is below 1, bounds it from below).
        EXPECT_GT(lowest, 1.0 - f.map.strength[size_t(c)] + 0.1) << c;
        EXPECT_LT(lowest, 0.999) << c;
    }
}

// Relative differences between two textures' colour channels, sorted.
std::vector<double> relative_differences(const Texture& a, const Texture& b) {
    std::vector<double> d;
    for (size_t x = 0; x < a.texels32.size(); ++x)
        if (x % 4 != 3) d.push_back(std::abs(double(a.texels32[x]) - b.texels32[x]) / a.texels32[x]);
    std::sort(d.begin(), d.end());
    return d;
}

// Past its budget the convolution runs on a coarser layout: the same blur
// by another quadrature. A profile exp(-r / 4 mm) over 0.42 mm texels (each
// gathers about 5,300 neighbours: 4.8e7 terms) and freckles of 1.5 mm at
// strength 0.95 (steep edges). Measured 2026-12-04: at a side of 77
// instead of 96 (budget 2.5e7), the median texel 0.022 % from the full
// layout's, the largest 0.14 %; at 48 (4e6), 0.050 % and 0.35 %.
TEST(ProfileAlbedo, ACoarserLayoutPastTheBudgetGivesTheSameBlur) {
    Fixture f;
    for (int c = 0; c < 3; ++c) f.profiles.R[size_t(c)] = [](double r) { return std::exp(-r / 4); };
    f.profiles.r_max = 40;
    f.map.count = 200, f.map.radius_mm = 1.5, f.map.strength = {0.95, 0.95, 0.95};
    const Texture full = albedo_texture(f.map, f.shape, f.profiles, false, 96, 1e30);
    const Texture coarse = albedo_texture(f.map, f.shape, f.profiles, false, 96, 2.5e7);
    const Texture coarser = albedo_texture(f.map, f.shape, f.profiles, false, 96, 4e6);
    const std::vector<double> d = relative_differences(full, coarse), e = relative_differences(full, coarser);
    EXPECT_GT(d.back(), 0);  // a coarser layout indeed
    EXPECT_LT(d[d.size() / 2], 0.0004);
    EXPECT_LT(d.back(), 0.0025);
    EXPECT_LT(e[e.size() / 2], 0.001);
    EXPECT_LT(e.back(), 0.006);
    // Still normalised to a white mean.
    for (int c = 0; c < 3; ++c) {
        double sum = 0;
        for (size_t x = 0; x < coarser.texels32.size() / 4; ++x) sum += coarser.texels32[x * 4 + size_t(c)];
        EXPECT_NEAR(sum / (96.0 * 96.0), 1.0, 1e-5) << c;
    }
}

// A scene's texture is kept for its next load: the same texels for the
// same inputs, and a change to any of them convolves anew.
TEST(ProfileAlbedo, ASceneKeepsItsTextureForTheSameInputsOnly) {
    Fixture f;
    auto profiles = std::make_shared<const BuiltProfiles>(f.profiles);
    const Texture first = scene_albedo_texture(f.map, f.shape, profiles, false, 64);
    EXPECT_EQ(first.texels32, albedo_texture(f.map, f.shape, f.profiles, false, 64).texels32);
    EXPECT_EQ(scene_albedo_texture(f.map, f.shape, profiles, false, 64).texels32, first.texels32);
    AlbedoMap stronger = f.map;
    stronger.strength[1] = 0.55;
    EXPECT_NE(scene_albedo_texture(stronger, f.shape, profiles, false, 64).texels32, first.texels32);
    ProfileShape larger = f.shape;
    larger.size_mm = 41;
    EXPECT_NE(scene_albedo_texture(f.map, larger, profiles, false, 64).texels32, first.texels32);
    BuiltProfiles wider = f.profiles;
    for (int c = 0; c < 3; ++c) wider.R[size_t(c)] = [](double r) { return std::exp(-r / 2); };
    EXPECT_NE(scene_albedo_texture(f.map, f.shape, std::make_shared<const BuiltProfiles>(wider), false, 64).texels32,
              first.texels32);
    EXPECT_EQ(scene_albedo_texture(f.map, f.shape, profiles, false, 64).texels32, first.texels32);
}

TEST(ProfileAlbedo, WithoutAMapTheTextureIsWhite) {
    Fixture f;
    f.map.pattern.clear();
    const Texture t = albedo_texture(f.map, f.shape, f.profiles, false, 128);
    EXPECT_EQ(t.width, 1);
    EXPECT_EQ(t.texels8, (std::vector<uint8_t>{255, 255, 255, 255}));
}

}  // namespace
}  // namespace st
