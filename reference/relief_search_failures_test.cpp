// relief_search_test.cpp: where the search fails (issue 10), on the twin of
// glsl/relief/relief_search.glsl, measured against the exact intersection
// (reference/relief_intersection.h): a wall thinner than one linear step is
// missed and binary search then refines toward a face behind it; the secant
// step never leaves its bracket; a rising ray that leaves the box reports no
// hit; refract() gives GLSL's zero vector at total internal reflection.
// The same programs on llvmpipe: cli.relief_failures.
#include <gtest/gtest.h>

#include <random>

#include "kernels/relief/relief_search.h"
#include "reference/relief_intersection.h"
#include "shading/glsl_math.h"
#include "texture/sampler2d.h"

namespace st {
namespace {

constexpr int kSize = 64;

// One level, REPEAT, bilinear: a floor at height 0 with a wall of height 1
// one texel wide at column `wall`, and (if `back` >= 0) a lower step of
// height 0.5 from column `back` on.
Texture walls(int wall, int back = -1) {
    Texture t;
    t.format = TextureFormat::RGBA8;
    t.set_filter(TextureFilter::Linear);
    t.set_wrap(TextureWrap::Repeat);
    t.width = t.height = kSize;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const uint8_t h = x == wall ? 255 : (back >= 0 && x >= back) ? 128 : 0;
            for (uint8_t c : {uint8_t(128), uint8_t(128), uint8_t(255), h}) t.texels8.push_back(c);
        }
    return t;
}

// The view ray of one lane group: every lane from (u0, 0.5) at the top of
// the box to (u0 + du, 0.5) at its floor.
float search(const Sampler2D& map, float u0, float du, int linear, int binary, bool secant) {
    Exec exec;
    const Vec2 uv(Float(u0), Float(0.5f)), offset(Float(du), Float(0.0f)), d(Float(0.0f), Float(0.0f));
    const Float t = relief::trace_height_field(exec, map, uv, offset, d, d, Int(linear), binary, secant);
    for (int lane = 1; lane < kLanes; ++lane) EXPECT_EQ(t[lane], t[0]);
    return t[0];
}

TEST(ReliefSearch, WallThinnerThanAStepIsMissed) {
    const Texture tex = walls(32);
    const Sampler2D map(tex);
    const reference::ReliefHeightField exact(tex);
    const float u0 = 0.3f, du = 0.5f;
    const double t_exact = exact.first_crossing(0, 0, 0.0, u0, 0.5, du, 0.0).t;
    ASSERT_GT(t_exact, 0.35);
    ASSERT_LT(t_exact, 0.45);  // the wall's front face
    // Four steps land at u = 0.3, 0.425, 0.55, ...: both sides of the wall
    // (whose bilinear footprint is u in (0.492, 0.523)), never on it; the
    // ray goes on to the floor.
    for (int binary : {0, 6}) EXPECT_GT(search(map, u0, du, 4, binary, true), 0.99f) << binary;
    // Steps finer than the wall find it, and the refinement lands on it.
    EXPECT_NEAR(search(map, u0, du, 64, 8, true), t_exact, 2e-3);
}

TEST(ReliefSearch, BinarySearchRefinesTowardTheWrongFace) {
    // The wall, then a floor raised to 0.5 behind it. Two linear steps: the
    // first lands on the raised floor (t = 0.5, where the ray is at 0.5), so
    // the bracket [0, 0.5] holds both the wall's front face (the first
    // crossing) and the raised floor's. Its first halvings land before the
    // wall and just past it, both above the surface, so binary search moves
    // on and converges on the raised floor's face.
    const Texture tex = walls(32, 36);
    const Sampler2D map(tex);
    const reference::ReliefHeightField exact(tex);
    const float u0 = 0.33f, du = 0.5f;
    const double t_exact = exact.first_crossing(0, 0, 0.0, u0, 0.5, du, 0.0).t;
    EXPECT_NEAR(t_exact, 11.38 / 33.0, 1e-3);  // x = 20.62 + 32 t meets h = x - 31 = 1 - t
    EXPECT_FLOAT_EQ(search(map, u0, du, 2, 0, false), 0.5f);
    const float refined = search(map, u0, du, 2, 10, true);
    EXPECT_GT(refined, 0.44f) << "binary search found the wall after all";
    EXPECT_LT(refined, 0.5f);
    // The raised floor's face: the exact crossing of the same ray with the
    // wall removed.
    const Texture no_wall = walls(-1, 36);
    const double t_face = reference::ReliefHeightField(no_wall).first_crossing(0, 0, 0.0, u0, 0.5, du, 0.0).t;
    EXPECT_NEAR(refined, t_face, 0.01);
}

TEST(ReliefSearch, SecantStaysInItsBracket) {
    // Random fields and rays: the secant result lies in the bracket that
    // binary search alone leaves (its s_hi, less one halved step), never
    // beyond it, whatever the differences at the ends.
    std::mt19937 rng(3);
    std::uniform_int_distribution<int> byte(0, 255);
    std::uniform_real_distribution<float> coord(0.0f, 1.0f), dir(-0.6f, 0.6f);
    for (int field = 0; field < 8; ++field) {
        Texture t = walls(0);
        for (size_t i = 3; i < t.texels8.size(); i += 4) t.texels8[i] = uint8_t(byte(rng));
        const Sampler2D map(t);
        for (int ray = 0; ray < 50; ++ray) {
            const float u0 = coord(rng), du = dir(rng);
            for (int linear : {1, 4, 16})
                for (int binary : {0, 3}) {
                    const float hi = search(map, u0, du, linear, binary, false);
                    const float bracket = 1.0f / float(linear) / float(1 << binary);
                    const float s = search(map, u0, du, linear, binary, true);
                    EXPECT_GE(s, hi - bracket - 1e-6f);
                    EXPECT_LE(s, hi);
                    EXPECT_TRUE(std::isfinite(s));
                }
        }
    }
}

TEST(ReliefSearch, RisingRayLeavingTheBoxHasNoHit) {
    const Texture tex = walls(-1);  // the floor alone
    const Sampler2D map(tex);
    Exec exec;
    Mask hit;
    const Vec2 uv(Float(0.2f), Float(0.5f)), offset(Float(0.3f), Float(0.1f)), d(Float(0.0f), Float(0.0f));
    // From height 0.25 up to the top (1): above the floor all the way.
    const Float s = relief::trace_segment(exec, map, uv, offset, Float(0.25f), Float(0.75f), Float(1.0f), d, d,
                                          Int(16), 6, true, hit);
    EXPECT_FALSE(any(hit));
    for (int lane = 0; lane < kLanes; ++lane) EXPECT_EQ(s[lane], 1.0f);
}

TEST(ReliefSearch, RefractGivesZeroAtTotalInternalReflection) {
    // From a denser medium (eta = 1.5) at 60 degrees: sin_t = 1.3, no
    // transmitted ray, and GLSL's refract returns vec3(0).
    const float s = std::sin(1.0472f), c = std::cos(1.0472f);
    const Vec3 i(Float(s), Float(0.0f), Float(-c)), n(Float(0.0f), Float(0.0f), Float(1.0f));
    const Vec3 r = glsl::refract(i, n, Float(1.5f));
    for (int lane = 0; lane < kLanes; ++lane) {
        EXPECT_EQ(r.x[lane], 0.0f);
        EXPECT_EQ(r.y[lane], 0.0f);
        EXPECT_EQ(r.z[lane], 0.0f);
    }
    // Below the critical angle it refracts.
    const Vec3 ok = glsl::refract(Vec3(Float(0.3f), Float(0.0f), Float(-0.953939f)), n, Float(1.5f));
    EXPECT_LT(ok.z[0], 0.0f);
}

}  // namespace
}  // namespace st
