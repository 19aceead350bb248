// relief_intersection_test.cpp: the exact relief-ray intersection against
// closed forms (a flat field, a ray tangent to a bilinear bump) and against a
// dense scan refined by bisection on random textures and rays.
#include "reference/relief_intersection.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "reference/height_texture_for_tests.h"

namespace st::reference {
namespace {

using testing_maps::height_texture;
using testing_maps::Rng;

struct Ray { int l0, l1; double f, u0, v0, du, dv; };

double g_at(const ReliefHeightField& field, const Ray& r, double t) {
    return (1 - t) - field.height(r.l0, r.l1, r.f, r.u0 + t * r.du, r.v0 + t * r.dv);
}

// The first sign change of g on 200000 samples, refined by bisection.
double brute_force(const ReliefHeightField& field, const Ray& r) {
    if (g_at(field, r, 0) <= 0) return 0;
    constexpr int n = 200000;
    for (int i = 1; i <= n; ++i) {
        const double t = double(i) / n;
        if (g_at(field, r, t) > 0) continue;
        double lo = double(i - 1) / n, hi = t;
        while (hi - lo > 1e-13) {
            const double mid = 0.5 * (lo + hi);
            (g_at(field, r, mid) > 0 ? lo : hi) = mid;
        }
        return hi;
    }
    return 1;
}

ReliefHeightField::Crossing cross(const ReliefHeightField& field, const Ray& r) {
    return field.first_crossing(r.l0, r.l1, r.f, r.u0, r.v0, r.du, r.dv);
}

TEST(ReliefIntersection, FlatFieldStopsAtItsHeight) {
    for (int k : {0, 1, 77, 128, 254, 255}) {
        const ReliefHeightField field(height_texture(8, 4, std::vector<uint8_t>(32, uint8_t(k))));
        ASSERT_EQ(field.levels(), 4);
        for (const Ray r : {Ray{0, 0, 0, 0.3, 0.7, 0.1, -0.05}, Ray{0, 1, 0.25, -2.6, 5.1, 7.5, 3.25},
                            Ray{1, 2, 0.5, 0.0, 0.0, 0.0, -11.0}, Ray{3, 3, 0, 0.5, 0.5, 0.0, 0.0},
                            Ray{2, 3, 1.0, 0.9, -0.2, -0.3, 0.0}}) {
            const auto c = cross(field, r);
            EXPECT_NEAR(c.t, 1 - k / 255.0, 1e-12) << "k " << k;
            EXPECT_NEAR(c.height, k / 255.0, 1e-12);
            EXPECT_DOUBLE_EQ(c.u, r.u0 + c.t * r.du);
            EXPECT_DOUBLE_EQ(c.v, r.v0 + c.t * r.dv);
        }
    }
}

TEST(ReliefIntersection, TexelCentresAreTheStoredHeights) {
    std::vector<uint8_t> alpha(8 * 4);
    for (size_t i = 0; i < alpha.size(); ++i) alpha[i] = uint8_t(i * 37 % 256);
    const ReliefHeightField field(height_texture(8, 4, alpha, false));
    ASSERT_EQ(field.levels(), 1);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x)
            for (int wrap : {-2, 0, 3})  // REPEAT: whole periods change nothing
                EXPECT_EQ(field.height(0, (x + 0.5) / 8 + wrap, (y + 0.5) / 4 - wrap),
                          alpha[size_t(y) * 8 + x] / 255.0);
}

TEST(ReliefIntersection, BlendIsTheWeightedSumOfLevels) {
    Rng rng(7);
    std::vector<uint8_t> alpha(64);
    for (auto& a : alpha) a = uint8_t(rng.below(256));
    const ReliefHeightField field(height_texture(8, 8, alpha));
    for (int n = 0; n < 500; ++n) {
        const int l0 = rng.below(field.levels()), l1 = rng.below(field.levels());
        const double f = n % 10 == 0 ? 0.0 : n % 10 == 1 ? 1.0 : rng.uniform(0, 1);
        const double u = rng.uniform(-4, 4), v = rng.uniform(-4, 4);
        const double h0 = field.height(l0, u, v), h1 = field.height(l1, u, v);
        const double expected = (f == 0 || l0 == l1) ? h0 : (1 - f) * h0 + f * h1;
        EXPECT_EQ(field.height(l0, l1, f, u, v), expected);
        EXPECT_NEAR(field.height(l0, l1, f, u, v), (1 - f) * h0 + f * h1, 1e-15);
    }
}

TEST(ReliefIntersection, MatchesDenseScanOnRandomFields) {
    Rng rng(20240611);
    int rays = 0, long_rays = 0;
    for (int tex = 0; tex < 4; ++tex) {
        const int w = tex == 3 ? 4 : 8, h = tex == 2 ? 4 : 8;
        const int top = tex % 2 ? 255 : 140;  // low fields let rays travel far
        std::vector<uint8_t> alpha(size_t(w) * h);
        for (auto& a : alpha) a = uint8_t(rng.below(top + 1));
        const ReliefHeightField field(height_texture(w, h, alpha));
        for (int n = 0; n < 40; ++n, ++rays) {
            Ray r{};
            r.l0 = rng.below(field.levels());
            r.l1 = n % 5 == 0 ? r.l0 : std::min(field.levels() - 1, r.l0 + 1);
            r.f = n % 7 == 0 ? 0.0 : n % 7 == 1 ? 1.0 : rng.uniform(0, 1);
            r.u0 = rng.uniform(-3, 3);
            r.v0 = rng.uniform(-3, 3);
            const double len = n % 3 == 0 ? 6.0 : 0.4;  // long rays cross many cells and wrap
            r.du = n % 8 == 2 ? 0.0 : rng.uniform(-len, len);
            r.dv = n % 8 == 3 ? 0.0 : rng.uniform(-len, len);
            const auto c = cross(field, r);
            const double brute = brute_force(field, r);
            SCOPED_TRACE(testing::Message() << "texture " << tex << " ray " << n << " t " << c.t
                                            << " brute " << brute);
            EXPECT_NEAR(c.t, brute, 1e-9);
            ASSERT_GE(c.t, 0);
            ASSERT_LE(c.t, 1);
            if (c.t > 0) EXPECT_NEAR(g_at(field, r, c.t), 0, 1e-9);
            else EXPECT_LE(g_at(field, r, 0), 0);
            EXPECT_EQ(c.height, field.height(r.l0, r.l1, r.f, c.u, c.v));
            for (int i = 0; i < 20000; ++i) {
                const double t = (c.t - 1e-7) * i / 20000;
                if (t < 0) break;
                if (!(g_at(field, r, t) > 0)) {
                    ADD_FAILURE() << "g <= 0 at t " << t << " before the crossing";
                    break;
                }
            }
            if (std::abs(c.t * r.du) > 1 || std::abs(c.t * r.dv) > 1) ++long_rays;
        }
    }
    EXPECT_EQ(rays, 160);
    EXPECT_GT(long_rays, 10);  // the sample really exercises wrapping over many cells
}

// A 2x2 checkerboard of 0 and a: along the diagonal through the zero texels
// each cell is a bump H = 2 a s (1 - s) (s the cell coordinate), concave, so
// a line of slope -1/k in s touches it at s* = 1/2 + 1/(4 a k). The ray
// entering at s0 = s* - k (1 - H(s*)) is tangent there and above all earlier
// bumps: g has a double root at t* = 1 - H(s*).
Ray tangent_ray(double a, double k, double* t_star) {
    const double s_star = 0.5 + 1 / (4 * a * k), h_star = 2 * a * s_star * (1 - s_star);
    const double s0 = s_star - k * (1 - h_star);
    *t_star = 1 - h_star;
    const double u0 = (s0 + 0.5) / 2;  // x = 2u - 0.5 on the 2x2 level
    return Ray{0, 0, 0, u0, u0, k / 2, k / 2};
}

TEST(ReliefIntersection, GrazingAPeakIsAHit) {
    for (int alpha : {255, 200, 131}) {
        const ReliefHeightField field(
            height_texture(2, 2, {0, uint8_t(alpha), uint8_t(alpha), 0}, false));
        for (double k : {2.0, 3.0, 1.7, 5.0}) {
            double t_star = 0;
            const Ray r = tangent_ray(alpha / 255.0, k, &t_star);
            SCOPED_TRACE(testing::Message() << "alpha " << alpha << " k " << k);
            const auto c = cross(field, r);
            // A double root is ill-conditioned: rounding u0 and the
            // coefficients by ~1e-16 moves it by ~sqrt(1e-16), and there is
            // no better answer for the rounded ray. It must not be lost.
            EXPECT_NEAR(c.t, t_star, 1e-7);
            EXPECT_NEAR(c.height, 1 - t_star, 1e-7);
        }
    }
    // Exactly representable case: u0 = 1/32, du = 1, t* = 17/32, H = 15/32.
    const ReliefHeightField field(height_texture(2, 2, {0, 255, 255, 0}, false));
    const auto c = field.first_crossing(0, 0, 0, 0.03125, 0.03125, 1, 1);
    EXPECT_NEAR(c.t, 0.53125, 1e-12);
    EXPECT_NEAR(c.height, 0.46875, 1e-12);
    // Lifted by 1e-6 it misses this bump and lands on the next one; lowered,
    // it cuts the bump just before the tangent point. Both as the scan says.
    for (double shift : {1e-6, -1e-6}) {
        const Ray r{0, 0, 0, 0.03125 + shift, 0.03125 + shift, 1, 1};
        const auto m = cross(field, r);
        EXPECT_NEAR(m.t, brute_force(field, r), 1e-9) << "shift " << shift;
        if (shift > 0) EXPECT_GT(m.t, 0.6);
        else EXPECT_LT(m.t, 0.53125);
    }
}

TEST(ReliefIntersection, RejectsBadInput) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const ReliefHeightField field(height_texture(4, 4, std::vector<uint8_t>(16, 100)));
    for (double bad : {nan, inf, -inf}) {
        EXPECT_THROW(field.first_crossing(0, 1, bad, 0, 0, 1, 1), std::invalid_argument);
        EXPECT_THROW(field.first_crossing(0, 1, 0.5, bad, 0, 1, 1), std::invalid_argument);
        EXPECT_THROW(field.first_crossing(0, 1, 0.5, 0, bad, 1, 1), std::invalid_argument);
        EXPECT_THROW(field.first_crossing(0, 1, 0.5, 0, 0, bad, 1), std::invalid_argument);
        EXPECT_THROW(field.first_crossing(0, 1, 0.5, 0, 0, 1, bad), std::invalid_argument);
        EXPECT_THROW(field.height(0, bad, 0.5), std::invalid_argument);
        EXPECT_THROW(field.height(0, 0.5, bad), std::invalid_argument);
    }
    EXPECT_THROW(field.first_crossing(0, 1, 1.5, 0, 0, 1, 1), std::invalid_argument);
    EXPECT_THROW(field.first_crossing(0, 7, 0.5, 0, 0, 1, 1), std::invalid_argument);
    EXPECT_THROW(field.height(-1, 0.5, 0.5), std::invalid_argument);
    EXPECT_THROW(field.first_crossing(0, 0, 0, 0, 0, 1e9, 0), std::invalid_argument);  // 4e9 boundaries
    EXPECT_THROW(field.first_crossing(0, 0, 0, 0, 0, 1e308, 1e308), std::invalid_argument);

    Texture t = height_texture(4, 4, std::vector<uint8_t>(16, 100));
    t.wrap_t = TextureWrap::ClampToEdge;
    EXPECT_THROW(ReliefHeightField{t}, std::invalid_argument);
    t.set_wrap(TextureWrap::MirroredRepeat);
    EXPECT_THROW(ReliefHeightField{t}, std::invalid_argument);
    t.set_wrap(TextureWrap::Repeat);
    t.format = TextureFormat::R32F;
    EXPECT_THROW(ReliefHeightField{t}, std::invalid_argument);
    t.format = TextureFormat::RGBA8;
    t.texels8.pop_back();
    EXPECT_THROW(ReliefHeightField{t}, std::invalid_argument);
}

}  // namespace
}  // namespace st::reference
