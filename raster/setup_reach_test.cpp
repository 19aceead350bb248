// setup_reach_test.cpp: which clip-space triangles setup can snap.
#include "raster/setup_reach.h"

#include <limits>

#include <gtest/gtest.h>

namespace st {

namespace {

const Viewport kViewport{0, 0, 128, 64, 0, 1};

// Window pixels (x, y) to clip space with w = 1, as the triangles kind maps them.
glm::vec4 pixel(float x, float y) { return {x * (2.0f / 128.0f) - 1.0f, y * (2.0f / 64.0f) - 1.0f, 0.0f, 1.0f}; }

}  // namespace

TEST(SetupReach, AnOrdinaryTriangleSnaps) {
    EXPECT_FALSE(first_unsnappable_position(pixel(0, 0), pixel(128, 0), pixel(0, 64), kViewport));
    // Clipped, with vertices a few viewports away: the clipped ones stay near the edges.
    EXPECT_FALSE(first_unsnappable_position(pixel(-300, 10), pixel(400, 20), pixel(60, 900), kViewport));
}

TEST(SetupReach, ATriangleOutsideOnePlaneIsDroppedNotRefused) {
    const float huge = 1e30f;
    EXPECT_FALSE(first_unsnappable_position(pixel(huge, 0), pixel(huge, 10), pixel(2 * huge, 5), kViewport));
}

// The explorer's case (tests/regressions/refused/): a sliver with vertices
// 1e21 pixels out. Clipping in float puts a vertex at y = 4.4e12, where the
// CPU binner would refuse the pass and llvmpipe draws wrapped-int32 garbage.
TEST(SetupReach, ClippingFarApartCoordinatesLosesTheVertex) {
    const auto w = first_unsnappable_position(pixel(1.8714075f, 1e21f), pixel(0, -1e21f),
                                              pixel(-1.624844f, -0.9999999e21f), kViewport);
    ASSERT_TRUE(w);
    EXPECT_GT(std::fabs(w->y), float(1 << 20));
    // The same shape 1e6 pixels out keeps its clipped vertices in place.
    EXPECT_FALSE(first_unsnappable_position(pixel(1.8714075f, 1e6f), pixel(0, -1e6f),
                                            pixel(-1.624844f, -0.9999999e6f), kViewport));
}

TEST(SetupReach, NonFiniteClipDistancesDropTheTriangle) {
    // A NaN coordinate makes a plane distance NaN: the clipper drops the
    // triangle (draw_pipe_clip.c), so there is nothing to snap.
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_FALSE(first_unsnappable_position(glm::vec4(nan, 0, 0, 1), pixel(10, 0), pixel(0, 10), kViewport));
}

}  // namespace st
