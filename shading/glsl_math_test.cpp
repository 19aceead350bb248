// glsl_math_test.cpp: the GLSL built-ins give the same bits on lanes as for
// one float (they are one template), if_else picks per lane and skips a side
// no lane takes, and dFdx/dFdy of computed values stay inside each quad.
#include "shading/glsl_math.h"

#include <bit>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "shading/derivatives.h"

namespace st {

namespace {

std::vector<float> inputs() {
    std::vector<float> v = {0.0f, -0.0f, 1e-40f, 127.99f, 128.0f, 129.0f, -126.99999f, -127.0f, -200.0f, 88.7f,
                            -88.7f, std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                            std::numeric_limits<float>::quiet_NaN()};
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> wide(-150.0f, 150.0f), narrow(-1.0f, 1.0f);
    for (int i = 0; i < 20000; ++i) v.push_back(i % 2 ? wide(rng) : narrow(rng));
    return v;
}

template <class LaneFn, class ScalarFn>
void same_bits(LaneFn lanes, ScalarFn scalar, const char* what) {
    const std::vector<float> v = inputs();
    for (size_t i = 0; i + kLanes <= v.size(); i += kLanes) {
        const Float r = lanes(Float::load(&v[i]));
        for (int lane = 0; lane < kLanes; ++lane)
            ASSERT_EQ(std::bit_cast<uint32_t>(r[lane]), std::bit_cast<uint32_t>(scalar(v[i + size_t(lane)])))
                << what << "(" << v[i + size_t(lane)] << ")";
    }
}

}  // namespace

TEST(GlslMath, LanesGiveTheScalarBits) {
    same_bits([](Float x) { return glsl::exp2(x); }, [](float x) { return glsl::exp2(x); }, "exp2");
    same_bits([](Float x) { return glsl::exp(x); }, [](float x) { return glsl::exp(x); }, "exp");
    same_bits([](Float x) { return glsl::inversesqrt(x); }, [](float x) { return glsl::inversesqrt(x); },
              "inversesqrt");
    same_bits([](Float x) { return glsl::max(x, Float(0.25f)); }, [](float x) { return glsl::max(x, 0.25f); }, "max");
    same_bits([](Float x) { return glsl::min(Float(-0.0f), x); }, [](float x) { return glsl::min(-0.0f, x); }, "min");
    same_bits([](Float x) { return glsl::log2(x); }, [](float x) { return glsl::log2(x); }, "log2");
    same_bits([](Float x) { return glsl::log(x); }, [](float x) { return glsl::log(x); }, "log");
    same_bits([](Float x) { return glsl::pow(glsl::abs(x), Float(2.5f)); },
              [](float x) { return glsl::pow(glsl::abs(x), 2.5f); }, "pow");
    same_bits([](Float x) { return glsl::length(Vec3(x, x * Float(0.5f), Float(2.0f))); },
              [](float x) { return glsl::length(glm::vec3(x, x * 0.5f, 2.0f)); }, "length");
}

// gallivm's fmax/fmin (docs/llvmpipe/glsl-builtins.md 2.8): a tie gives the
// second operand, one NaN the other operand. The twin gave -0.0 for
// max(-0.0, 0.0) where llvmpipe gives +0.0 (explore profile --seed 2026).
TEST(GlslMath, MaxAndMinAreGallivmsOnTiesAndNaN) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    auto bits = [](float x) { return std::bit_cast<uint32_t>(x); };
    EXPECT_EQ(bits(glsl::max(-0.0f, 0.0f)), bits(0.0f));
    EXPECT_EQ(bits(glsl::max(0.0f, -0.0f)), bits(-0.0f));
    EXPECT_EQ(bits(glsl::min(0.0f, -0.0f)), bits(-0.0f));
    EXPECT_EQ(bits(glsl::min(-0.0f, 0.0f)), bits(0.0f));
    EXPECT_EQ(glsl::max(nan, 2.0f), 2.0f);
    EXPECT_EQ(glsl::max(2.0f, nan), 2.0f);
    EXPECT_EQ(glsl::min(nan, -2.0f), -2.0f);
    EXPECT_EQ(glsl::min(-2.0f, nan), -2.0f);
    const Float l = glsl::max(Float(-0.0f), Float(0.0f)), m = glsl::min(Float(nan), Float(3.0f));
    for (int lane = 0; lane < kLanes; ++lane) {
        EXPECT_EQ(bits(l[lane]), bits(0.0f));
        EXPECT_EQ(m[lane], 3.0f);
    }
}

// log2 and pow at their edges, as lp_build_log2_safe and lp_build_pow give
// them (docs/llvmpipe/glsl-builtins.md 1.3, 1.5); the conformance scene
// compares them with llvmpipe itself.
TEST(GlslMath, Log2AndPowEdgesAreGallivms) {
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    auto bits = [](float x) { return std::bit_cast<uint32_t>(x); };
    EXPECT_EQ(glsl::log2(1.0f), 0.0f);
    EXPECT_EQ(glsl::log2(8.0f), 3.0f);
    EXPECT_EQ(glsl::log2(0.125f), -3.0f);
    EXPECT_EQ(glsl::log2(0.0f), -inf);
    EXPECT_EQ(glsl::log2(-0.0f), -inf);
    EXPECT_EQ(glsl::log2(inf), inf);
    EXPECT_EQ(bits(glsl::log2(-1.0f)), 0x7FC00000u);
    EXPECT_EQ(bits(glsl::log2(-nan)), 0x7FC00000u);  // the payload and sign are lost
    EXPECT_NEAR(glsl::log2(3.0f), 1.5849625f, 2e-7f);
    EXPECT_EQ(bits(glsl::pow(nan, 1.0f)), bits(0.0f));
    EXPECT_EQ(bits(glsl::pow(0.0f, -1.0f)), bits(0.0f));
    EXPECT_EQ(bits(glsl::pow(-0.0f, 3.0f)), bits(0.0f));
    EXPECT_TRUE(std::isnan(glsl::pow(-8.0f, 2.0f)));
    EXPECT_EQ(glsl::pow(5.0f, 0.0f), 1.0f);
    // exp2 of a signalling NaN is its quiet NaN, as llvmpipe's arithmetic
    // leaves it (volatile: no compile-time folding).
    volatile uint32_t snan = 0xFF923457u;
    const float x = std::bit_cast<float>(uint32_t(snan));
    EXPECT_EQ(bits(glsl::exp2(x)), 0xFFD23457u);
    EXPECT_EQ(std::bit_cast<uint32_t>(glsl::exp2(Float(x))[0]), 0xFFD23457u);
}

TEST(GlslMath, IfElseTakesEachLanesSideAndSkipsAnUntakenOne) {
    Float x;
    for (int lane = 0; lane < kLanes; ++lane) x.set(lane, float(lane) - 3.5f);
    int then_runs = 0, else_runs = 0;
    auto pick = [&](Mask c) {
        return glsl::if_else(
            c, [&] { ++then_runs; return x * Float(2.0f); }, [&] { ++else_runs; return -x; });
    };
    const Float mixed = pick(x < Float(0.0f));
    EXPECT_EQ(then_runs, 1);
    EXPECT_EQ(else_runs, 1);
    for (int lane = 0; lane < kLanes; ++lane) EXPECT_EQ(mixed[lane], x[lane] < 0 ? x[lane] * 2.0f : -x[lane]);
    then_runs = else_runs = 0;
    pick(Mask(true));
    EXPECT_EQ(then_runs, 1);
    EXPECT_EQ(else_runs, 0);
    pick(Mask(false));
    EXPECT_EQ(else_runs, 1);
    EXPECT_EQ(glsl::if_else(true, [] { return 1.0f; }, [] { return 2.0f; }), 1.0f);
}

// Lane order in a quad: (x, y), (x+1, y), (x, y+1), (x+1, y+1). For
// v = x^2 + 3y per lane, dFdx is the row's difference and dFdy the
// column's, and no quad sees another's values.
TEST(Derivatives, OfComputedValuesStayInTheQuad) {
    Float v;
    for (int lane = 0; lane < kLanes; ++lane) {
        const int quad = lane / 4, dx = lane & 1, dy = lane >> 1 & 1;
        const float x = float(10 * quad + dx), y = float(dy);
        v.set(lane, x * x + 3.0f * y);
    }
    const Float ddx = dFdx(v), ddy = dFdy(v);
    for (int lane = 0; lane < kLanes; ++lane) {
        const int quad = lane / 4, dy = lane >> 1 & 1;
        const float x0 = float(10 * quad);
        const float row_left = x0 * x0 + 3.0f * float(dy), row_right = (x0 + 1) * (x0 + 1) + 3.0f * float(dy);
        EXPECT_EQ(ddx[lane], row_right - row_left) << lane;
        EXPECT_EQ(ddy[lane], 3.0f) << lane;
    }
}

}  // namespace st
