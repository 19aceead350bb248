// level_table_test.cpp: every lane gets its own level's value, whichever
// form the lookup takes (one level, one or two parts of lanes, a gather).
#include "texture/level_table.h"

#include <random>

#include <gtest/gtest.h>

namespace st::texel {
namespace {

TEST(LevelTable, EachLaneReadsItsLevel) {
    std::mt19937 rng(9);
    for (int n : {1, 2, kLanes - 1, kLanes, kLanes + 1, 2 * kLanes, 2 * kLanes + 1, 40}) {
        LevelTable table;
        for (int l = 0; l < n; ++l) table.push_back(1000 * l + 7);
        std::uniform_int_distribution<int> level(0, n - 1);
        for (int round = 0; round < 50; ++round) {
            Int at;
            for (int lane = 0; lane < kLanes; ++lane) at.set(lane, level(rng));
            const Int got = table.lookup(at);
            for (int lane = 0; lane < kLanes; ++lane) ASSERT_EQ(got[lane], 1000 * at[lane] + 7) << n << " levels";
        }
        EXPECT_EQ(table.size(), size_t(n));
        EXPECT_EQ(table.back(), 1000 * (n - 1) + 7);
    }
}

}  // namespace
}  // namespace st::texel
