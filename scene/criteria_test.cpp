// criteria_test.cpp: the condition-map gate of the search scenes (issue 10):
// pixels off by more than 1 LSB pass only where the map explains them.
#include "scene/criteria.h"

#include <bit>
#include <cmath>

#include <gtest/gtest.h>

#include "image/compare.h"

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

// "nan_any_payload": a NaN against a NaN of other bits passes; a NaN
// against a number, or an infinity against another value, does not.
TEST(Criteria, NanAnyPayloadForgivesOnlyNanAgainstNan) {
    Image a, b;
    a.width = b.width = 2;
    a.height = b.height = 1;
    a.rgba = {std::bit_cast<float>(0x7FC00000u), 1.0f, 2.0f, 3.0f, 4.0f, 5.0f, 6.0f, 7.0f};
    b.rgba = a.rgba;
    b.rgba[0] = std::bit_cast<float>(0xFFD23457u);  // NaN of another payload and sign
    CompareMetrics m = compare_images(a, b);
    EXPECT_EQ(m.nan_payload_only, 1);
    EXPECT_EQ(m.identical_fraction_float, 0.5);
    EXPECT_EQ(m.identical_fraction_float_any_nan, 1.0);
    Criteria c;
    c.min_identical_fraction_float = 1.0;
    c.max_rel_diff_float = 0.0;
    c.nonfinite = Criteria::Nonfinite::Identical;
    EXPECT_EQ(c.failures(m, 0).size(), 3u);  // identical fraction, relative difference, non-finite
    c.nonfinite = Criteria::Nonfinite::AnyNanPayload;
    EXPECT_TRUE(c.failures(m, 0).empty());
    b.rgba[0] = 0.0f;  // a NaN against a number
    m = compare_images(a, b);
    EXPECT_EQ(m.nan_payload_only, 0);
    EXPECT_FALSE(c.failures(m, 0).empty());
    b.rgba[0] = std::bit_cast<float>(0x7FC00000u);
    b.rgba[1] = INFINITY;  // an infinity against a number
    m = compare_images(a, b);
    EXPECT_FALSE(c.failures(m, 0).empty());
}

}  // namespace
}  // namespace st
