// unorm8_test.cpp: the float -> 8-bit conversion llvmpipe applies.
#include "image/unorm8.h"

#include <bit>
#include <cmath>
#include <cstdint>

#include <gtest/gtest.h>

namespace st {

TEST(Unorm8, EndpointsAndClamping) {
    EXPECT_EQ(to_unorm8(0.0f), 0);
    EXPECT_EQ(to_unorm8(1.0f), 255);
    EXPECT_EQ(to_unorm8(-3.0f), 0);
    EXPECT_EQ(to_unorm8(7.0f), 255);
    EXPECT_EQ(to_unorm8(NAN), 0);
    EXPECT_EQ(to_unorm8(INFINITY), 255);
}

TEST(Unorm8, ExactQuotientsRoundTrip) {
    for (int k = 0; k <= 255; ++k) EXPECT_EQ(to_unorm8(float(k) / 255.0f), k) << k;
}

// Where x * 255/256 falls exactly halfway between two 1/256 steps, the result
// is the even one (the float addition rounds half to even).
TEST(Unorm8, HalfwayRoundsToEven) {
    int ties = 0;
    for (int k = 0; k < 255; ++k) {
        // Floats near (k + 0.5) / 255 whose scaled value is exactly (k + 0.5) / 256.
        float x = float((k + 0.5) / 255.0);
        for (int step = 0; step < 8; ++step) x = std::nextafter(x, 0.0f);
        for (int step = 0; step < 16; ++step, x = std::nextafter(x, 1.0f)) {
            if (double(x * (255.0f / 256.0f)) * 256.0 != k + 0.5) continue;
            ++ties;
            EXPECT_EQ(to_unorm8(x), k % 2 == 0 ? k : k + 1) << x;
        }
    }
    EXPECT_GT(ties, 50);  // the loop really met halfway cases
}

}  // namespace st
