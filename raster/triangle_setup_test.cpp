// triangle_setup_test.cpp: fixed-point snapping and the fill rule.
#include "raster/triangle_setup.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "raster/fixed_point.h"
#include "raster/tile_raster.h"

namespace st {

namespace {

SetupVertex at(float x, float y) {
    static const glm::vec4 none[1] = {glm::vec4(0)};
    return SetupVertex{WindowPos{x, y, 0.5f, 1.0f}, none};
}

// Pixels covered by a triangle on a w x h target, as a set of (x, y).
std::vector<std::pair<int, int>> covered(SetupVertex a, SetupVertex b, SetupVertex c, int w = 16, int h = 16) {
    SetupTriangle tri;
    std::vector<Plane> planes;
    std::vector<std::pair<int, int>> out;
    if (!setup_triangle(a, b, c, 0, Interpolations{}, w, h, tri, planes)) return out;
    std::vector<BlockCoverage> blocks;
    rasterize_in_tile(tri, TileRect{0, 0, w, h}, blocks);
    for (const auto& b : blocks)
        for (int lane = 0; lane < kBlockLanes; ++lane)
            if (b.mask >> lane & 1) out.emplace_back(b.x + block_lane_x(lane), b.y + block_lane_y(lane));
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

TEST(Snap, RoundsHalfToEvenOnTheSubpixelGrid) {
    // (x - 0.5) * 256: 0.5 + 1/512 is exactly half a sub-pixel step.
    EXPECT_EQ(snap_to_subpixel(0.5f), 0);
    EXPECT_EQ(snap_to_subpixel(0.5f + 1.0f / 512.0f), 0);          // 0.5 -> 0 (even)
    EXPECT_EQ(snap_to_subpixel(0.5f + 3.0f / 512.0f), 2);          // 1.5 -> 2 (even)
    EXPECT_EQ(snap_to_subpixel(1.5f), 256);
    EXPECT_EQ(snap_to_subpixel(0.0f), -128);
}

TEST(Setup, ZeroAreaIsCulled) {
    EXPECT_TRUE(covered(at(1, 1), at(5, 5), at(9, 9)).empty());
}

TEST(Setup, FacingFollowsWindingInGlWindowCoordinates) {
    SetupTriangle tri;
    std::vector<Plane> planes;
    ASSERT_TRUE(setup_triangle(at(0, 0), at(8, 0), at(0, 8), 0, Interpolations{}, 16, 16, tri, planes));
    EXPECT_TRUE(tri.front_facing);  // counter-clockwise with y up
    ASSERT_TRUE(setup_triangle(at(0, 0), at(0, 8), at(8, 0), 0, Interpolations{}, 16, 16, tri, planes));
    EXPECT_FALSE(tri.front_facing);
}

// A centre exactly on an edge: inside for left and bottom edges, outside for
// right and top ones (GL window coordinates, y up).
TEST(FillRule, LeftAndBottomEdgesAreInclusive) {
    // Axis-aligned right triangle with legs through pixel centres x = 2.5 and y = 2.5.
    const auto px = covered(at(2.5f, 2.5f), at(6.5f, 2.5f), at(2.5f, 6.5f));
    auto has = [&](int x, int y) { return std::find(px.begin(), px.end(), std::make_pair(x, y)) != px.end(); };
    EXPECT_TRUE(has(2, 2));   // on the left and bottom edges
    EXPECT_TRUE(has(2, 5));   // on the left edge
    EXPECT_TRUE(has(5, 2));   // on the bottom edge
    EXPECT_FALSE(has(6, 2));  // the corner on the hypotenuse end
    EXPECT_FALSE(has(4, 4));  // on the hypotenuse, a top-right edge
    EXPECT_TRUE(has(3, 4));
    // The mirrored triangle's right and top legs exclude their centres.
    const auto mirrored = covered(at(6.5f, 6.5f), at(2.5f, 6.5f), at(6.5f, 2.5f));
    auto has_m = [&](int x, int y) {
        return std::find(mirrored.begin(), mirrored.end(), std::make_pair(x, y)) != mirrored.end();
    };
    EXPECT_FALSE(has_m(6, 4));  // right edge
    EXPECT_FALSE(has_m(4, 6));  // top edge
    EXPECT_TRUE(has_m(4, 4));   // on the diagonal: a bottom-left edge for this one
    EXPECT_TRUE(has_m(5, 5));
}

// Two triangles sharing a diagonal cover every pixel of their square once.
TEST(FillRule, SharedEdgeCoveredExactlyOnce) {
    const auto a = covered(at(1.5f, 1.5f), at(9.5f, 1.5f), at(9.5f, 9.5f));
    const auto b = covered(at(1.5f, 1.5f), at(9.5f, 9.5f), at(1.5f, 9.5f));
    std::vector<std::pair<int, int>> both;
    std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(both));
    EXPECT_TRUE(both.empty());
    EXPECT_EQ(a.size() + b.size(), 64u);  // centres 1.5..8.5 in x and y: 8 x 8
}

// Covering does not depend on where the target is cut into tiles.
TEST(TileRaster, TilesPartitionTheTriangle) {
    SetupTriangle tri;
    std::vector<Plane> planes;
    ASSERT_TRUE(setup_triangle(at(-30.3f, 3.1f), at(150.7f, 20.2f), at(40.4f, 140.9f), 0, Interpolations{}, 130, 130, tri, planes));
    std::vector<BlockCoverage> whole, tiled;
    rasterize_in_tile(tri, TileRect{0, 0, 130, 130}, whole);
    for (int ty = 0; ty < 130; ty += kTileSize)
        for (int tx = 0; tx < 130; tx += kTileSize)
            rasterize_in_tile(tri, TileRect{tx, ty, std::min(130, tx + kTileSize), std::min(130, ty + kTileSize)}, tiled);
    auto count = [](const std::vector<BlockCoverage>& qs) {
        long n = 0;
        for (const auto& q : qs) n += __builtin_popcount(q.mask);
        return n;
    };
    EXPECT_EQ(count(whole), count(tiled));
    EXPECT_GT(count(whole), 1000);
}

// Issue 12: a position that cannot be snapped (not finite, or beyond
// kMaxWindowCoord) drops the triangle instead of reaching an integer
// conversion; one just within the limit is set up.
TEST(Snap, UnsnappablePositionsDropTheTriangle) {
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    for (float bad : {nan, inf, -inf, std::numeric_limits<float>::max(), std::nextafter(kMaxWindowCoord, inf)}) {
        EXPECT_FALSE(snappable(at(bad, 1.0f), at(8.0f, 1.0f), at(1.0f, 8.0f)));
        EXPECT_TRUE(covered(at(bad, 1.0f), at(8.0f, 1.0f), at(1.0f, 8.0f)).empty());
        EXPECT_TRUE(covered(at(1.0f, 1.0f), at(8.0f, bad), at(1.0f, 8.0f)).empty());
    }
    EXPECT_TRUE(snappable(at(-kMaxWindowCoord, 1.0f), at(8.0f, 1.0f), at(1.0f, 8.0f)));
    EXPECT_FALSE(covered(at(-kMaxWindowCoord, 0.0f), at(8.0f, 0.0f), at(8.0f, 8.0f)).empty());
}

}  // namespace st
