// criteria_test.cpp: the condition-map gate of the search scenes (issue 10):
// pixels off by more than 1 LSB pass only where the map explains them.
#include "scene/criteria.h"

#include <gtest/gtest.h>

namespace st {
namespace {

CompareMetrics metrics_with_max_diff(int max_diff) {
    CompareMetrics m;
    m.width = 100;
    m.height = 100;
    m.identical_fraction_8bit = 0.99;
    m.identical_fraction_float = 0.99;
    m.max_diff_8bit = max_diff;
    return m;
}

TEST(Criteria, ConditionMapExplainsLargeDifferences) {
    Criteria c;
    c.max_rel_diff_float = 1e30;
    c.condition_map = true;
    const CompareMetrics m = metrics_with_max_diff(7);
    EXPECT_TRUE(c.failures(m, 0, 5, 5).empty());          // all five explained
    EXPECT_EQ(c.failures(m, 0, 5, 4).size(), 1u);         // one is not
    EXPECT_TRUE(c.failures(m, 0, 50, 50).empty());        // 99.5 % within 1 LSB: enough
    EXPECT_EQ(c.failures(m, 0, 51, 51).size(), 1u);       // 99.49 %: not
    EXPECT_EQ(c.failures(m, 3, 0, 0).size(), 1u);         // coverage still counts
    // Without the map the 8-bit bound stands.
    c.condition_map = false;
    EXPECT_FALSE(c.failures(m, 0, 5, 5).empty());
}

}  // namespace
}  // namespace st
