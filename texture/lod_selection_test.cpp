// lod_selection_test.cpp: level selection for LINEAR mip filtering at the
// ends of the chain (docs/llvmpipe/mipmaps-cubes-formats.md §2.6).
#include "texture/lod_selection.h"

#include <cmath>
#include <iterator>
#include <limits>

#include <gtest/gtest.h>

namespace st::texel {

namespace {

// One LOD per lane, with what §2.6 says both levels and the weight become
// for a chain of levels 0..3.
struct Expected {
    float lod;
    int level0, level1;
    float fpart;
};

const Expected kCases[] = {
    {-2.5f, 0, 0, 0.0f},    // below the base: both levels are the base
    {-0.25f, 0, 0, 0.0f},   // (llvmpipe's second pass reads level 0 here, not 1)
    {0.0f, 0, 1, 0.0f},     // inside: l0, l0 + 1 and the fraction
    {0.75f, 0, 1, 0.75f},
    {2.5f, 2, 3, 0.5f},
    {3.0f, 3, 3, 0.0f},     // at or past the last level: both are the last
    {7.5f, 3, 3, 0.0f},
    {std::numeric_limits<float>::quiet_NaN(), 0, 0, 0.0f},  // INT_MIN: below
};

}  // namespace

TEST(LodSelection, LinearClampsBothLevelsAtEitherEnd) {
    constexpr int n = int(std::size(kCases));
    for (int first = 0; first < n; first += kLanes) {
        Float lod(0.0f);
        for (int lane = 0; lane < kLanes; ++lane) lod.set(lane, kCases[(first + lane) % n].lod);
        const LevelChoice c = choose_levels(lod, MipFilter::Linear, 3);
        ASSERT_TRUE(c.two_levels);
        for (int lane = 0; lane < kLanes; ++lane) {
            const Expected& e = kCases[(first + lane) % n];
            SCOPED_TRACE(e.lod);
            EXPECT_EQ(c.level0[lane], e.level0);
            EXPECT_EQ(c.level1[lane], e.level1);
            EXPECT_EQ(c.fpart[lane], e.fpart);
        }
    }
}

}  // namespace st::texel
