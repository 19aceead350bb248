// lane_vec_test.cpp: the lane vectors read like GLSL and compute what GLSL's
// componentwise operators compute, lane by lane: constructors, swizzles in
// both name sets, writes through swizzles, conversions between component
// types (with llvmpipe's answer for NaN), scalar-vector operators.
#include "simd/lane_vec.h"

#include <bit>
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace st {

namespace {

// Lane i holds base + i, so that a test sees lanes kept apart.
Float ramp(float base) {
    Float r;
    for (int i = 0; i < kLanes; ++i) r.set(i, base + float(i));
    return r;
}

void expect_lanes(Float got, float base, const char* what) {
    for (int i = 0; i < kLanes; ++i) EXPECT_EQ(got[i], base + float(i)) << what << ", lane " << i;
}

}  // namespace

TEST(LaneVec, SwizzlesReadAsGlslDoes) {
    const Vec4 c(ramp(10), ramp(20), ramp(30), ramp(40));
    const Vec3 zyx = c.zyx();
    expect_lanes(zyx.x, 30, "zyx.x");
    expect_lanes(zyx.y, 20, "zyx.y");
    expect_lanes(zyx.z, 10, "zyx.z");
    const Vec3 rgb = c.rgb();
    expect_lanes(rgb.z, 30, "rgb.b");
    const Vec4 wwxy = c.wwxy();
    expect_lanes(wwxy.x, 40, "wwxy.x");
    expect_lanes(wwxy.y, 40, "wwxy.y");
    expect_lanes(wwxy.w, 20, "wwxy.w");
    const Vec2 v2(ramp(1), ramp(2));
    const Vec4 yxyx = v2.yxyx();  // a vec2 swizzled to four components
    expect_lanes(yxyx.z, 2, "yxyx.z");
    expect_lanes(Vec3(c).xz().y, 30, "vec3(c).xz.y");
}

TEST(LaneVec, SwizzleWritesTouchOnlyTheirComponents) {
    Vec4 c(ramp(10), ramp(20), ramp(30), ramp(40));
    c.set_wx(Vec2(ramp(1), ramp(2)));  // c.wx = vec2(...)
    expect_lanes(c.w, 1, "w");
    expect_lanes(c.x, 2, "x");
    expect_lanes(c.y, 20, "y untouched");
    expect_lanes(c.z, 30, "z untouched");
    c.set_bgr(Vec3(ramp(7), ramp(8), ramp(9)));
    expect_lanes(c.z, 7, "b");
    expect_lanes(c.x, 9, "r");
}

TEST(LaneVec, ConstructorsTakeComponentsSideBySide) {
    const Vec2 a(ramp(1), ramp(2));
    const Vec4 v(0.5f, a, 9.0f);  // vec4(0.5, a, 9.0)
    EXPECT_EQ(v.x[3], 0.5f);
    expect_lanes(v.y, 1, "y");
    expect_lanes(v.z, 2, "z");
    EXPECT_EQ(v.w[0], 9.0f);
    const Vec4 b(a, a);
    expect_lanes(b.w, 2, "vec4(a, a).w");
    const Vec3 t(Vec4(ramp(3), ramp(4), ramp(5), ramp(6)));  // vec3(vec4): the first three
    expect_lanes(t.z, 5, "vec3(vec4).z");
    const Vec3 u(glm::vec3(1, 2, 3));  // a uniform, in every lane
    for (int i = 0; i < kLanes; ++i) EXPECT_EQ(u.y[i], 2.0f);
    const IVec2 iu(glm::ivec2(-4, 5));
    for (int i = 0; i < kLanes; ++i) EXPECT_EQ(iu.x[i], -4);
}

TEST(LaneVec, ConversionsAreGlslsWithLlvmpipesAnswerForNaN) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const Vec3 f(Float(-2.75f), Float(nan), Float(3e9f));
    const IVec3 i(f);  // int(float) truncates; NaN and out of range give INT32_MIN (cvttps2dq)
    EXPECT_EQ(i.x[0], -2);
    EXPECT_EQ(i.y[0], INT32_MIN);
    EXPECT_EQ(i.z[0], INT32_MIN);
    const Vec3 back(IVec3(Int(7), Int(-1), Int(16777217)));  // float(int) rounds to nearest even
    EXPECT_EQ(back.x[0], 7.0f);
    EXPECT_EQ(back.z[0], 16777216.0f);
    const BVec3 b(Vec3(Float(0.0f), Float(-0.0f), Float(nan)));  // bool(x) is x != 0: NaN is true
    EXPECT_FALSE(b.x[0]);
    EXPECT_FALSE(b.y[0]);
    EXPECT_TRUE(b.z[0]);
    const Vec3 one_zero(b);  // float(bool)
    EXPECT_EQ(one_zero.x[0], 0.0f);
    EXPECT_EQ(one_zero.z[0], 1.0f);
}

TEST(LaneVec, ScalarOperandsAreUsedInTheOrderWritten) {
    const Vec3 v(ramp(1), ramp(2), ramp(3));
    const Vec3 a = 2.0f * v - v / Float(4.0f);  // 2.0 * v - v / 4.0
    for (int i = 0; i < kLanes; ++i) EXPECT_EQ(a.y[i], 2.0f * (2.0f + float(i)) - (2.0f + float(i)) / 4.0f);
    const Vec3 b = 1.0f - v;  // each component 1 - v, not -(v - 1)
    for (int i = 0; i < kLanes; ++i) EXPECT_EQ(b.x[i], 1.0f - (1.0f + float(i)));
    Vec3 c = v;
    c += v;
    c *= 0.5f;
    expect_lanes(c.z, 3, "(v + v) * 0.5");
    const IVec2 n(Int(6), Int(-3));
    const IVec2 m = (n * 2) ^ IVec2(Int(1), Int(1));
    EXPECT_EQ(m.x[0], 13);
    EXPECT_EQ(m.y[0], -5);
}

TEST(LaneVec, WholeVectorEqualityIsOneBoolPerLane) {
    const Vec3 v(ramp(1), ramp(2), ramp(3));
    Vec3 w = v;
    w.z.set(1, 99.0f);  // lane 1 differs in one component
    const Mask eq = v == w;
    EXPECT_TRUE(eq[0]);
    EXPECT_FALSE(eq[1]);
    EXPECT_TRUE((v != w)[1]);
    const Vec3 s = select(eq, v, -v);
    EXPECT_EQ(s.x[0], 1.0f);
    EXPECT_EQ(s.x[1], -2.0f);
}

}  // namespace st
