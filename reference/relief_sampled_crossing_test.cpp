// relief_sampled_crossing_test.cpp: the staircase crossing against a dense
// scan of the sampler itself, against the exact bilinear crossing (it may
// differ by the staircase only), and for the work it skips.
#include "reference/relief_sampled_crossing.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "reference/height_texture_for_tests.h"
#include "texture/sampler2d.h"

namespace st::reference::sampled_crossing_test {
namespace {

using testing_maps::height_texture;
using testing_maps::Rng;

// The sampler's height read at one level pair and weight, every lane alike.
struct Reader {
    const Sampler2D& map;
    texel::LevelChoice levels;
    float at(double u, double v) const {
        float h = 0;
        (*this)(&u, &v, 1, &h);
        return h;
    }
    void operator()(const double* u, const double* v, int n, float* h) const {
        Vec2 p;
        for (int i = 0; i < kLanes; ++i) {
            p.x.set(i, float(u[std::min(i, n - 1)]));
            p.y.set(i, float(v[std::min(i, n - 1)]));
        }
        const Float read = map.sample_grad_alpha(p, levels);
        for (int i = 0; i < n; ++i) h[i] = read[i];
    }
};

texel::LevelChoice level_pair(int l0, int l1, float f) {
    texel::LevelChoice c;
    c.level0 = Int(l0);
    c.level1 = Int(l1);
    c.fpart = Float(f);
    c.minified = Mask(true);
    c.two_levels = l0 != l1;
    return c;
}

struct Ray { double u0, v0, du, dv; };

SearchRay view_ray(const Ray& r) {
    SearchRay s;
    s.u0 = r.u0, s.v0 = r.v0, s.du = r.du, s.dv = r.dv;
    return s;
}

TEST(ReliefSampledCrossing, FlatFieldStopsAtItsRead) {
    for (int k : {0, 1, 77, 254, 255}) {
        const Texture tex = height_texture(8, 8, std::vector<uint8_t>(64, uint8_t(k)));
        const ReliefHeightField field(tex);
        const Sampler2D map(tex);
        const Reader read{map, level_pair(0, 1, 0.5f)};
        for (const Ray r : {Ray{0.3, 0.7, 0.1, -0.05}, Ray{-2.6, 5.1, 7.5, 3.25}, Ray{0.5, 0.5, 0, 0}}) {
            const SampledCrossing c = first_sampled_crossing(field, {0, 1}, view_ray(r), read, kLanes);
            EXPECT_EQ(c.t, std::max(0.0, 1 - double(read.at(0.5, 0.5)))) << "k " << k;
        }
    }
}

// On random fields and rays: no read before the crossing is at or above the
// ray, and the ray is on or under the read just after it.
TEST(ReliefSampledCrossing, NoReadCrossesBeforeIt) {
    Rng rng(28);
    int crossed = 0;
    for (int tex_i = 0; tex_i < 3; ++tex_i) {
        const int w = tex_i == 2 ? 16 : 8, h = tex_i == 1 ? 4 : 8;
        std::vector<uint8_t> alpha(size_t(w) * h);
        for (auto& a : alpha) a = uint8_t(rng.below(tex_i == 0 ? 120 : 256));
        const Texture tex = height_texture(w, h, alpha);
        const ReliefHeightField field(tex);
        const Sampler2D map(tex);
        for (int n = 0; n < 12; ++n) {
            const int l0 = rng.below(field.levels() - 1), l1 = n % 3 == 0 ? l0 : l0 + 1;
            const Reader read{map, level_pair(l0, l1, n % 3 == 0 ? 0.0f : float(rng.uniform(0.05, 0.95)))};
            const std::vector<int> levels = l0 == l1 ? std::vector<int>{l0} : std::vector<int>{l0, l1};
            const double len = n % 2 ? 1.5 : 0.3;
            const Ray r{rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(-len, len), rng.uniform(-len, len)};
            const SampledCrossing c = first_sampled_crossing(field, levels, view_ray(r), read, 5);
            SCOPED_TRACE(testing::Message() << "texture " << tex_i << " ray " << n << " t " << c.t);
            ASSERT_GE(c.t, 0);
            ASSERT_LE(c.t, 1);
            // 400 000 points: a few per step of the staircase on these rays.
            constexpr int kScan = 400000;
            const double stop = c.t - 1e-9;
            for (int i = 0; i < kScan; ++i) {
                const double t = stop * i / kScan;
                if (t < 0) break;
                if (1 - t <= double(read.at(r.u0 + t * r.du, r.v0 + t * r.dv))) {
                    ADD_FAILURE() << "a read at t " << t << " is at or above the ray";
                    break;
                }
            }
            if (c.t < 1) {
                // The reads' coordinates are floats, which move a step's edges
                // by up to ~3e-7 in t on these rays.
                const double after = c.t + 2e-6;
                EXPECT_LE(1 - after, double(read.at(r.u0 + after * r.du, r.v0 + after * r.dv)));
                ++crossed;
            }
        }
    }
    EXPECT_GT(crossed, 30);
}

// Segments from above and below (the two-layer searches' rays): no read
// before the crossing is on its far side, one just after it is, and a
// segment without a hit has none anywhere.
TEST(ReliefSampledCrossing, SegmentsFromEitherSide) {
    Rng rng(2028);
    std::vector<uint8_t> alpha(size_t(16) * 16);
    for (auto& x : alpha) x = uint8_t(rng.below(256));
    const Texture tex = height_texture(16, 16, alpha);
    const ReliefHeightField field(tex);
    const Sampler2D map(tex);
    int hits = 0, misses = 0;
    for (int n = 0; n < 60; ++n) {
        const Reader read{map, level_pair(1, 2, 0.3f)};
        SearchRay r;
        r.u0 = rng.uniform(-2, 2), r.v0 = rng.uniform(-2, 2);
        r.du = rng.uniform(-0.4, 0.4), r.dv = rng.uniform(-0.4, 0.4);
        r.a = rng.uniform(0, 1), r.dh = rng.uniform(-1, 1), r.side = n % 2 ? 1.0 : -1.0;
        const auto f = [&](double s) {
            return r.side * (r.a + r.dh * s - double(read.at(r.u0 + s * r.du, r.v0 + s * r.dv)));
        };
        const SampledCrossing c = first_sampled_crossing(field, {1, 2}, r, read, kLanes);
        SCOPED_TRACE(testing::Message() << "segment " << n << " t " << c.t << " hit " << c.hit);
        // The batch changes the calls only.
        const SampledCrossing one = first_sampled_crossing(field, {1, 2}, r, read, 1);
        EXPECT_EQ(one.t, c.t);
        EXPECT_EQ(one.hit, c.hit);
        EXPECT_EQ(one.steps_read, c.steps_read);
        constexpr int kScan = 100000;
        // (Float coordinates move a step's edges by up to ~3e-7 in s here.)
        const double stop = c.hit ? c.t - 2e-6 : 1.0;
        for (int i = 0; i <= kScan && stop > 0; ++i) {
            const double s = stop * i / kScan;
            if (f(s) <= 0) {
                ADD_FAILURE() << "the ray is on the surface's far side at s " << s;
                break;
            }
        }
        if (!c.hit) {
            EXPECT_EQ(c.t, 1.0);
            ++misses;
            continue;
        }
        ++hits;
        bool crossed = f(c.t) <= 0;
        for (int i = 1; i <= 200 && !crossed; ++i) crossed = f(std::min(1.0, c.t + 1e-6 * i)) <= 0;
        EXPECT_TRUE(crossed);
    }
    EXPECT_GT(hits, 10);
    EXPECT_GT(misses, 10);
}

// A segment that starts on the surface it just crossed (the light's path
// through the liquid, each crossing flipping the side) does not stop there
// again: on a flat field, leaving it upwards meets nothing, and going back
// down meets it at once, one step on.
TEST(ReliefSampledCrossing, LeavingTheCrossingIsNotACrossing) {
    const Texture tex = height_texture(8, 8, std::vector<uint8_t>(64, 100));
    const ReliefHeightField field(tex);
    const Sampler2D map(tex);
    const Reader read{map, level_pair(0, 0, 0.0f)};
    SearchRay r;
    r.u0 = 0.3, r.v0 = 0.6, r.du = 0.2, r.dv = -0.1;
    r.a = double(read.at(0.3, 0.6)), r.dh = 0.5, r.side = 1;  // on the surface, rising: looking for re-entry
    const SampledCrossing touch = first_sampled_crossing(field, {0}, r, read, kLanes);
    EXPECT_TRUE(touch.hit);  // a touch at s = 0 counts...
    EXPECT_EQ(touch.t, 0.0);
    r.leaving = true;
    EXPECT_FALSE(first_sampled_crossing(field, {0}, r, read, kLanes).hit);  // ...unless it is the one left
    r.dh = -0.5;  // sinking back in: met where the first step ends
    const SampledCrossing back = first_sampled_crossing(field, {0}, r, read, kLanes);
    EXPECT_TRUE(back.hit);
    EXPECT_GT(back.t, 0.0);
    EXPECT_LT(back.t, 1.0 / (256 * 8 * 0.2) + 1e-12);  // a step: 1/256 texel of the 8-texel level
}

// The staircase is within a step of the bilinear surface, so on a smooth
// field the two crossings are near; and the pieces below the ray are
// skipped, not read.
TEST(ReliefSampledCrossing, NearTheExactCrossingAndSkipsThePiecesBelowTheRay) {
    const int w = 64;
    std::vector<uint8_t> alpha(size_t(w) * w);
    for (int y = 0; y < w; ++y)
        for (int x = 0; x < w; ++x)
            alpha[size_t(y) * w + x] =
                uint8_t(std::lround(100 + 90 * std::sin(x * 0.2) * std::cos(y * 0.15)));
    const Texture tex = height_texture(w, w, alpha);
    const ReliefHeightField field(tex);
    const Sampler2D map(tex);
    const Reader read{map, level_pair(0, 0, 0.0f)};
    Rng rng(7);
    int near = 0;
    for (int n = 0; n < 50; ++n) {
        const Ray r{rng.uniform(0, 1), rng.uniform(0, 1), rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5)};
        const SampledCrossing c = first_sampled_crossing(field, {0}, view_ray(r), read, kLanes);
        const double exact = field.first_crossing(0, 0, 0.0, r.u0, r.v0, r.du, r.dv).t;
        SCOPED_TRACE(testing::Message() << "ray " << n << " t " << c.t << " exact " << exact);
        // A step of the staircase is 1/256 texel, its height within ~2/255
        // of the surface: where the ray does not graze a hump the two
        // crossings are close; where it does, one may hit and one miss.
        if (std::abs(c.t - exact) < 0.01) ++near;
        // Every step of the ray would be 256 * 64 * (|du| + |dv|) of them.
        const double all_steps = 256.0 * w * (std::abs(r.du) + std::abs(r.dv));
        EXPECT_LT(double(c.steps_read), 0.25 * all_steps + 2 * kLanes);
    }
    EXPECT_GE(near, 45);
}

TEST(ReliefSampledCrossing, RefusesBadInput) {
    const Texture tex = height_texture(4, 4, std::vector<uint8_t>(16, 9));
    const ReliefHeightField field(tex);
    const Sampler2D map(tex);
    const Reader read{map, level_pair(0, 0, 0.0f)};
    const SearchRay ok = view_ray({0, 0, 1, 1});
    EXPECT_NO_THROW(first_sampled_crossing(field, {0}, ok, read, 4));
    EXPECT_THROW(first_sampled_crossing(field, {}, ok, read, 4), std::invalid_argument);
    EXPECT_THROW(first_sampled_crossing(field, {7}, ok, read, 4), std::invalid_argument);
    EXPECT_THROW(first_sampled_crossing(field, {0}, ok, read, 0), std::invalid_argument);
    for (auto bad : {&SearchRay::u0, &SearchRay::du, &SearchRay::a, &SearchRay::dh})
        for (double x : {double(NAN), double(INFINITY)}) {
            SearchRay r = ok;
            r.*bad = x;
            EXPECT_THROW(first_sampled_crossing(field, {0}, r, read, 4), std::invalid_argument);
        }
    SearchRay sideways = ok;
    sideways.side = 0.5;
    EXPECT_THROW(first_sampled_crossing(field, {0}, sideways, read, 4), std::invalid_argument);
    SearchRay far = ok;
    far.du = 1e9;
    EXPECT_THROW(first_sampled_crossing(field, {0}, far, read, 4), std::invalid_argument);
    // Along the surface, within its rounding of it, for 16 000 texels: every
    // step would be read (4e6 of them).
    SearchRay along = ok;
    along.du = 4000, along.dv = 0, along.dh = 0, along.a = double(read.at(0.5, 0.5)) + 5e-7;
    EXPECT_THROW(first_sampled_crossing(field, {0}, along, read, 4), std::invalid_argument);
    along.du = 1;  // 4 texels: read, and no crossing
    const SampledCrossing short_along = first_sampled_crossing(field, {0}, along, read, 4);
    EXPECT_FALSE(short_along.hit);
    EXPECT_GT(short_along.steps_read, 1000);
}

}  // namespace
}  // namespace st::reference::sampled_crossing_test
