// Tests of profile_albedo.h: Sec. 3.1's convolved, white-normalised texture.
#include "scene/profile_albedo.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

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

TEST(ProfileAlbedo, WithoutAMapTheTextureIsWhite) {
    Fixture f;
    f.map.pattern.clear();
    const Texture t = albedo_texture(f.map, f.shape, f.profiles, false, 128);
    EXPECT_EQ(t.width, 1);
    EXPECT_EQ(t.texels8, (std::vector<uint8_t>{255, 255, 255, 255}));
}

}  // namespace
}  // namespace st
