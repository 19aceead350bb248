// compare_test.cpp: coverage_mismatch counts differences in fragment counts,
// not only in presence (issue 12: a pixel covered twice on one side and once
// on the other was not counted).
#include "image/compare.h"

#include <gtest/gtest.h>

namespace st {
namespace {

Image counts(std::initializer_list<float> per_pixel) {
    Image im(int(per_pixel.size()), 1);
    size_t p = 0;
    for (float c : per_pixel) {
        for (int ch = 0; ch < 4; ++ch) im.rgba[p * 4 + size_t(ch)] = c;
        ++p;
    }
    return im;
}

TEST(CoverageMismatch, CountsMultiplicity) {
    EXPECT_EQ(coverage_mismatch(counts({0, 1, 2, 3}), counts({0, 1, 2, 3})), 0);
    EXPECT_EQ(coverage_mismatch(counts({0, 1, 2, 3}), counts({1, 1, 2, 3})), 1);  // covered on one side only
    EXPECT_EQ(coverage_mismatch(counts({0, 2, 2, 3}), counts({0, 1, 2, 1})), 2);  // twice against once, 3 against 1
}

}  // namespace
}  // namespace st
