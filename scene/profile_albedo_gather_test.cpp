// Tests of profile_albedo_gather.h: the albedo map's convolution.
#include "scene/profile_albedo_gather.h"

#include <gtest/gtest.h>

#include <cmath>

namespace st {
namespace {

BuiltProfiles exponential_profiles(double width_mm, double r_max) {
    BuiltProfiles p;
    p.r_max = r_max;
    for (int c = 0; c < 3; ++c) {
        p.R[size_t(c)] = [width_mm, c](double r) { return std::exp(-r / (width_mm * (c + 1))); };
        p.T[size_t(c)] = [](double) { return 0.0; };
    }
    return p;
}

// Every texel's sums run in one order, whichever thread takes its row.
TEST(ProfileAlbedoGather, TheThreadCountChangesNoBit) {
    ProfileShape sphere;
    sphere.kind = "ellipsoid";
    sphere.radii = {10, 14, 8};
    const TexelLayout layout = texel_layout(sphere, 40);
    ASSERT_TRUE(layout.wraps);
    const ProfileTable table = profile_table(exponential_profiles(1.0, 12), false);
    std::array<std::vector<double>, 3> map;
    for (int c = 0; c < 3; ++c)
        for (size_t x = 0; x < layout.p.size(); ++x) map[size_t(c)].push_back(std::sin(0.37 * double(x) + c));
    const auto one = gather(layout, map, table, 1), three = gather(layout, map, table, 3);
    EXPECT_EQ(one, three);
    EXPECT_NE(one[0], map[0]);  // it blurs
}

// The cost is the windows' terms, each window clipped at the borders of a
// slab's layout: along a row of 16, w = 8 (half the layout, for a reach
// past it) covers 9, 10, ..., 16, 16, ..., 9 columns (200), w = 2 (a reach
// of a tenth of a texel: ceil(0.1) + 1) 3, 4, 5 x 12, 4, 3 (74).
TEST(ProfileAlbedoGather, TermsCountTheWindows) {
    ProfileShape slab;  // 40 mm
    const TexelLayout layout = texel_layout(slab, 16);
    EXPECT_DOUBLE_EQ(gather_terms(layout, 1e6), 200.0 * 200);
    EXPECT_DOUBLE_EQ(gather_terms(layout, 0.25), 74.0 * 74);
}

TEST(ProfileAlbedoGather, ReachHoldsNinetyNinePercent) {
    // exp(-r / w): in 2D the weight r exp(-r / w) holds 99 % within
    // r = 6.638 w; the widest channel's (w = 3) is the reach, to within the
    // table's step (50 / 1024).
    const ProfileTable t = profile_table(exponential_profiles(1.0, 50), false);
    EXPECT_NEAR(t.reach99, 3 * 6.638, 50.0 / 1024);
}

}  // namespace
}  // namespace st
