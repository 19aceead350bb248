// thresholds_test.cpp: idiff's rule on counted pixels, non-finite values
// included.
#include "image/thresholds.h"

#include <cmath>

#include <gtest/gtest.h>

namespace st {
namespace {

Image grey(int w, int h, float v) {
    Image im(w, h);
    for (float& c : im.rgba) c = v;
    return im;
}

TEST(Thresholds, IdiffRule) {
    const Image a = grey(10, 10, 0.5f);
    Image b = a;
    EXPECT_EQ(compare_thresholds(a, b, {}).verdict, Verdict::Pass);

    b.pixel(3, 4)[1] = 0.6f;  // one pixel of 100 off by 0.1 in green
    ThresholdResult r = compare_thresholds(a, b, {});
    EXPECT_EQ(r.verdict, Verdict::Fail);
    EXPECT_EQ(r.failing, 1);
    EXPECT_EQ(r.max_x, 3);
    EXPECT_EQ(r.max_y, 4);
    EXPECT_EQ(r.max_channel, 1);
    EXPECT_NEAR(r.max_error, 0.1, 1e-6);

    Thresholds t;
    t.fail = 0.2;  // within the failure threshold, beyond the warning one
    EXPECT_EQ(compare_thresholds(a, b, t).verdict, Verdict::Warn);
    t.warn = 0.2;
    EXPECT_EQ(compare_thresholds(a, b, t).verdict, Verdict::Pass);

    t = {};
    t.fail_percent = 1.0;  // 1 % of 100 pixels may fail
    t.warn_percent = 1.0;
    EXPECT_EQ(compare_thresholds(a, b, t).verdict, Verdict::Pass);
    t.hard_fail = 0.05;  // but no pixel by more than 0.05
    EXPECT_EQ(compare_thresholds(a, b, t).verdict, Verdict::Fail);
}

TEST(Thresholds, NonFiniteValuesFail) {
    const Image a = grey(4, 4, 0.5f);
    Image b = a;
    b.pixel(1, 2)[0] = NAN;
    ThresholdResult r = compare_thresholds(a, b, {});
    EXPECT_EQ(r.verdict, Verdict::Fail);
    EXPECT_EQ(r.failing, 1);
    EXPECT_TRUE(std::isinf(r.max_error));
    EXPECT_EQ(r.max_x, 1);
    EXPECT_EQ(r.max_y, 2);
    Thresholds t;
    t.fail = t.warn = 1e30;  // no finite threshold lets a NaN through
    EXPECT_EQ(compare_thresholds(a, b, t).verdict, Verdict::Fail);
    Image c = b;  // NaN against NaN, infinity against itself: the same
    c.pixel(0, 0)[3] = b.pixel(0, 0)[3] = INFINITY;
    EXPECT_EQ(compare_thresholds(b, c, {}).verdict, Verdict::Pass);
}

}  // namespace
}  // namespace st
