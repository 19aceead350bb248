// sampler2d_test.cpp: filtering and wrapping, against values worked out by
// hand. (The live comparisons with llvmpipe are the triangles-texture-*
// scenes, run by the cli.compare_builtin test.)
#include "texture/sampler2d.h"

#include "texture/mip_generation.h"
#include "texture/texel_math.h"

#include <algorithm>
#include <cstring>
#include <iterator>
#include <limits>
#include <random>
#include <stdexcept>

#include <gtest/gtest.h>

namespace st {

namespace {

Texture ramp(TextureFormat format, TextureFilter filter, TextureWrap wrap, int w, int h) {
    Texture t;
    t.format = format;
    t.set_filter(filter);
    t.set_wrap(wrap);
    t.width = w;
    t.height = h;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 4; ++c) {
                const int v = (x * 40 + y * 7 + c) % 256;  // distinct per texel
                if (format == TextureFormat::RGBA8) t.texels8.push_back(uint8_t(v));
                else t.texels32.push_back(float(v) / 256.0f);
            }
    return t;
}

// A Vec2 of random values, lane by lane.
Vec2 random_lanes(std::mt19937& rng, std::uniform_real_distribution<float>& dist) {
    Vec2 v;
    for (int lane = 0; lane < kLanes; ++lane) v.x.set(lane, dist(rng)), v.y.set(lane, dist(rng));
    return v;
}

glm::vec2 centre(int x, int y, const Texture& t) {
    return {(float(x) + 0.5f) / float(t.width), (float(y) + 0.5f) / float(t.height)};
}

}  // namespace

class FilterTest : public ::testing::TestWithParam<std::tuple<TextureFormat, TextureWrap, int>> {};

// Coordinates (x + 0.5) / w are exact in float only for power-of-two w;
// otherwise s * w - 0.5 lands a few ulps off the texel centre and the weight
// of the neighbour is ~1e-7 instead of 0.
float coordinate_rounding(int w) { return (w & (w - 1)) == 0 ? 0.0f : 1e-6f; }

// At a texel centre, linear filtering returns that texel.
TEST_P(FilterTest, TexelCentres) {
    const auto [format, wrap, w] = GetParam();
    const Texture t = ramp(format, TextureFilter::Linear, wrap, w, 4);
    const Sampler2D s(t);
    for (int y = 0; y < t.height; ++y)
        for (int x = 0; x < t.width; ++x) {
            const glm::vec4 got = s.sample(centre(x, y, t)), want = s.fetch(x, y);
            for (int c = 0; c < 4; ++c) EXPECT_NEAR(got[c], want[c], coordinate_rounding(w)) << x << "," << y;
        }
}

// Halfway between two texel centres gives their mean (within 8-bit
// rounding for the fixed-point path).
TEST_P(FilterTest, HalfwayIsTheMean) {
    const auto [format, wrap, w] = GetParam();
    const Texture t = ramp(format, TextureFilter::Linear, wrap, w, 4);
    const Sampler2D s(t);
    const glm::vec2 st{2.0f / float(t.width), 0.5f / float(t.height)};  // between texels 1 and 2 of row 0
    const glm::vec4 expected = (s.fetch(1, 0) + s.fetch(2, 0)) * 0.5f;
    const float tolerance = format == TextureFormat::RGBA8 ? 0.5f / 255.0f + 1e-6f : 0.0f;
    const glm::vec4 got = s.sample(st);
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(got[c], expected[c], tolerance) << c;
}

// Outside [0, 1]: repeat wraps by one period, clamp holds the edge texel.
TEST_P(FilterTest, WrapModes) {
    const auto [format, wrap, w] = GetParam();
    const Texture t = ramp(format, TextureFilter::Linear, wrap, w, 4);
    const Sampler2D s(t);
    const glm::vec2 inside = centre(1, 2, t);
    if (wrap == TextureWrap::Repeat) {
        for (glm::vec2 shift : {glm::vec2(1.0f, 0.0f), glm::vec2(-2.0f, 1.0f)}) {
            const glm::vec4 a = s.sample(inside + shift), b = s.sample(inside);
            for (int c = 0; c < 4; ++c) EXPECT_NEAR(a[c], b[c], coordinate_rounding(w)) << c;
        }
        // Between the last and the first texel, across the seam.
        const glm::vec4 seam = s.sample(glm::vec2(0.0f, inside.y));
        const glm::vec4 mean = (s.fetch(0, 2) + s.fetch(t.width - 1, 2)) * 0.5f;
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(seam[c], mean[c], 1.0f / 255.0f) << c;
    } else {
        EXPECT_EQ(s.sample(glm::vec2(-3.0f, inside.y)), s.fetch(0, 2));
        EXPECT_EQ(s.sample(glm::vec2(7.5f, inside.y)), s.fetch(t.width - 1, 2));
        EXPECT_EQ(s.sample(glm::vec2(0.0f, inside.y)), s.fetch(0, 2));
    }
}

INSTANTIATE_TEST_SUITE_P(
    FormatsWrapsSizes, FilterTest,
    ::testing::Combine(::testing::Values(TextureFormat::RGBA8, TextureFormat::RGBA32F),
                       ::testing::Values(TextureWrap::Repeat, TextureWrap::ClampToEdge),
                       ::testing::Values(8, 13)));  // power of two and not

// All lanes at once give, lane by lane, what one lane alone gives, on both
// RGBA8 fetch paths: a small footprint (whole rows loaded and permuted) and
// scattered coordinates (gathers), wraps and seams included.
TEST_P(FilterTest, LanesAreIndependent) {
    const auto [format, wrap, size] = GetParam();
    for (TextureFilter filter : {TextureFilter::Linear, TextureFilter::Nearest}) {
        const Texture t = ramp(format, filter, wrap, size, size + 3);
        const Sampler2D s(t);
        std::mt19937 rng{uint32_t(size)};
        std::uniform_real_distribution<float> anywhere(-2.0f, 3.0f), near(-0.01f, 0.01f);
        for (int round = 0; round < 200; ++round) {
            Vec2 uv;
            // Even rounds: one block's worth of neighbouring texels around a
            // point (near a seam every fourth round); odd rounds: anywhere.
            const glm::vec2 base = round % 4 == 0 ? glm::vec2(0.0f) : glm::vec2(anywhere(rng), anywhere(rng));
            for (int lane = 0; lane < kLanes; ++lane) {
                const bool scattered = round % 2 == 1;
                uv.x.set(lane, scattered ? anywhere(rng) : base.x + float(lane % 4) / float(size) + near(rng));
                uv.y.set(lane, scattered ? anywhere(rng) : base.y + float(lane / 4 % 4) / float(size + 3) + near(rng));
            }
            const Vec4 all = s.sample(uv);
            for (int lane = 0; lane < kLanes; ++lane) {
                const glm::vec4 one = s.sample(glm::vec2(uv.x[lane], uv.y[lane]));
                ASSERT_EQ(glm::vec4(all.x[lane], all.y[lane], all.z[lane], all.w[lane]), one)
                    << "round " << round << " lane " << lane;
            }
        }
    }
}

// A texture read texel for texel (every lane at a texel centre, to within
// the 8-bit weights) gives each lane its texel exactly, whether every lane
// is centred (only the lower-left taps are read) or one is not (the whole
// filter runs): blocks of lanes over random texels of both wraps, at the
// edges too, and with lanes left out by an active mask.
TEST(Unorm8Filter, TexelForTexelReadsGiveTheTexels) {
    for (TextureWrap wrap : {TextureWrap::Repeat, TextureWrap::ClampToEdge})
    for (int w : {16, 13, 512}) {
        const Texture t = ramp(TextureFormat::RGBA8, TextureFilter::Linear, wrap, w, 11);
        const Sampler2D s(t);
        std::mt19937 rng{uint32_t(w)};
        std::uniform_int_distribution<int> x0(-2, w), y0(-2, 11);
        std::uniform_real_distribution<float> jitter(-0.0015f, 0.0015f);  // under 1/512 texel
        std::uniform_int_distribution<unsigned> lanes(1, (1u << kLanes) - 1);
        for (int round = 0; round < 300; ++round) {
            const int bx = x0(rng), by = y0(rng);
            Vec2 st;
            int tx[kLanes], ty[kLanes];
            for (int lane = 0; lane < kLanes; ++lane) {
                tx[lane] = bx + lane % 4, ty[lane] = by + lane / 4;  // a block of texels, as pixels cover them
                st.x.set(lane, (float(tx[lane]) + 0.5f + jitter(rng)) / float(w));
                st.y.set(lane, (float(ty[lane]) + 0.5f + jitter(rng)) / 11.0f);
            }
            const int off_centre = round % 3 == 2 ? int(rng() % kLanes) : -1;
            if (off_centre >= 0) st.x.set(off_centre, st.x[off_centre] + 0.3f / float(w));
            const unsigned on = round % 2 ? lanes(rng) : (1u << kLanes) - 1;
            const Vec4 got = s.sample(st, texel::kReadRGBA, Mask::from_bits(on));
            for (int lane = 0; lane < kLanes; ++lane) {
                if (lane == off_centre || !(on >> lane & 1u)) continue;
                auto wrapped = [&](int i, int n) {
                    return wrap == TextureWrap::Repeat ? ((i % n) + n) % n : std::clamp(i, 0, n - 1);
                };
                const glm::vec4 want = s.fetch(wrapped(tx[lane], w), wrapped(ty[lane], 11));
                for (int c = 0; c < 4; ++c)
                    ASSERT_EQ(got[c][lane], want[c]) << "lane " << lane << " round " << round << " size " << w;
            }
        }
    }
}

TEST(Nearest, PicksTheTexelUnderTheCoordinate) {
    for (TextureWrap wrap : {TextureWrap::Repeat, TextureWrap::ClampToEdge})
        for (int w : {8, 13}) {
            const Texture t = ramp(TextureFormat::RGBA32F, TextureFilter::Nearest, wrap, w, 3);
            const Sampler2D s(t);
            for (int x = 0; x < w; ++x) {
                const float left = (float(x) + 0.01f) / float(w), right = (float(x) + 0.99f) / float(w);
                EXPECT_EQ(s.sample(glm::vec2(left, 0.5f)), s.fetch(x, 1));
                EXPECT_EQ(s.sample(glm::vec2(right, 0.5f)), s.fetch(x, 1));
            }
        }
}

// Coordinates whose texel position s * size is beyond the int32 range, or
// infinite, or NaN: llvmpipe converts with cvttps2dq (INT32_MIN) and wraps
// that integer, and its mirror rounds in float (lp_build_sample_wrap_nearest,
// lp_build_coord_mirror). The rules were measured on llvmpipe with triangles
// scenes, finite s to 3.4e38 and NaN (tests/regressions/
// triangles-texture-*-uvs-*.json); infinity follows from the same code.
TEST(Nearest, HugeInfiniteAndNaNCoordinates) {
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    struct Case {
        TextureWrap wrap;
        int size;
        float s;
        int texel;
    };
    const Case cases[] = {
        // CLAMP_TO_EDGE: past 2^31 texels the integer is INT32_MIN, so the
        // clamp gives texel 0 however far right; below that, the last texel.
        {TextureWrap::ClampToEdge, 8, 268435440.0f, 7},  // s * 8 just below 2^31
        {TextureWrap::ClampToEdge, 8, 268435456.0f, 0},  // s * 8 = 2^31
        {TextureWrap::ClampToEdge, 13, 3e8f, 0},
        {TextureWrap::ClampToEdge, 13, 1e30f, 0},
        {TextureWrap::ClampToEdge, 13, -1e30f, 0},
        {TextureWrap::ClampToEdge, 13, inf, 0},
        {TextureWrap::ClampToEdge, 13, -inf, 0},
        {TextureWrap::ClampToEdge, 13, nan, 0},
        // REPEAT, power of two: INT32_MIN & (size - 1) is 0.
        {TextureWrap::Repeat, 8, 1e30f, 0},
        {TextureWrap::Repeat, 8, -1e30f, 0},
        {TextureWrap::Repeat, 8, inf, 0},
        {TextureWrap::Repeat, 8, nan, 0},
        // REPEAT, not a power of two: a huge float has no fraction (texel
        // 0); inf and NaN have a NaN one, which fract_safe makes 1 - ulp.
        {TextureWrap::Repeat, 13, 1e30f, 0},
        {TextureWrap::Repeat, 13, -1e30f, 0},
        {TextureWrap::Repeat, 13, inf, 12},
        {TextureWrap::Repeat, 13, nan, 12},
        // MIRRORED_REPEAT: an odd integer folds to 1 (the last texel), an
        // even one to 0; from 2^24 on every float is even, also past 2^32
        // where an integer rounding would have given INT32_MIN; inf - inf
        // and NaN fold to 0.
        {TextureWrap::MirroredRepeat, 13, 8388609.0f, 12},
        {TextureWrap::MirroredRepeat, 13, 4294967296.0f, 0},
        {TextureWrap::MirroredRepeat, 13, 1e10f, 0},
        {TextureWrap::MirroredRepeat, 13, -1e30f, 0},
        {TextureWrap::MirroredRepeat, 13, inf, 0},
        {TextureWrap::MirroredRepeat, 13, nan, 0},
    };
    for (const Case& c : cases) {
        const bool pot = (c.size & (c.size - 1)) == 0;
        const Int i = texel::nearest_texel(Float(c.s), Int(c.size), Float(float(c.size)), pot, c.wrap);
        for (int lane = 0; lane < kLanes; ++lane)
            ASSERT_EQ(i[lane], c.texel) << "wrap " << int(c.wrap) << " size " << c.size << " s " << c.s;
        // The whole sampler, both formats (RGBA8 REPEAT and CLAMP_TO_EDGE
        // take the 8-bit path, which floors before converting: the same
        // texel).
        for (TextureFormat format : {TextureFormat::RGBA32F, TextureFormat::RGBA8}) {
            const Texture t = ramp(format, TextureFilter::Nearest, c.wrap, c.size, 3);
            const Sampler2D s(t);
            EXPECT_EQ(s.sample(glm::vec2(c.s, 0.5f)), s.fetch(c.texel, 1))
                << "wrap " << int(c.wrap) << " size " << c.size << " s " << c.s << " format " << int(format);
        }
    }
}

// The 8-bit path quantises the weight to 1/256: a quarter of the way from 0
// to 255 gives 64 (255 * 64/256 = 63.75, rounded), not a float 63.75/255.
TEST(Unorm8Filter, WeightsAreQuantisedTo8Bits) {
    Texture t;
    t.format = TextureFormat::RGBA8;
    t.set_wrap(TextureWrap::ClampToEdge);
    t.width = 2;
    t.height = 1;
    t.texels8 = {0, 0, 0, 0, 255, 255, 255, 255};
    const Sampler2D s(t);
    const glm::vec4 v = s.sample(glm::vec2((0.5f + 0.25f) / 2.0f, 0.5f));
    EXPECT_EQ(v.r, 64.0f * (1.0f / 255.0f));
}

}  // namespace st

namespace st {
namespace {

// The hoisted forms a search uses give sample_grad's bits: levels chosen
// once for the derivatives, and the alpha-only read.
TEST(SampleGrad, HoistedLevelsAndAlphaOnlyAreTheSameBits) {
    // RGBA8 bilinear with mips reads footprint quads: every wrap they are
    // built for, power-of-two or not, including the edge where a
    // CLAMP_TO_EDGE pair is no quad.
    struct Case {
        TextureWrap wrap;
        int w, h;
    };
    for (const Case& k : {Case{TextureWrap::Repeat, 64, 64}, Case{TextureWrap::Repeat, 48, 20},
                          Case{TextureWrap::ClampToEdge, 64, 64}, Case{TextureWrap::ClampToEdge, 37, 64}})
    for (TextureFormat format : {TextureFormat::RGBA8, TextureFormat::RGBA32F}) {
        for (TextureFilter filter : {TextureFilter::Linear, TextureFilter::Nearest}) {
            Texture t = ramp(format, filter, k.wrap, k.w, k.h);
            t.mip_filter = MipFilter::Linear;
            generate_box_mips(t, full_chain_levels(k.w, k.h));
            const Sampler2D s(t);
            std::mt19937 rng(7);
            std::uniform_real_distribution<float> coord(-2.0f, 3.0f), grad(-0.2f, 0.2f);
            for (int round = 0; round < 200; ++round) {
                const Vec2 st = random_lanes(rng, coord), dx = random_lanes(rng, grad), dy = random_lanes(rng, grad);
                const Vec4 direct = s.sample_grad(st, dx, dy);
                const texel::LevelChoice levels = s.grad_levels(dx, dy);
                const Vec4 hoisted = s.sample_grad(st, levels);
                const Float alpha = s.sample_grad_alpha(st, levels);
                for (int lane = 0; lane < kLanes; ++lane) {
                    ASSERT_EQ(direct.x[lane], hoisted.x[lane]);
                    ASSERT_EQ(direct.y[lane], hoisted.y[lane]);
                    ASSERT_EQ(direct.z[lane], hoisted.z[lane]);
                    ASSERT_EQ(direct.w[lane], hoisted.w[lane]);
                    ASSERT_EQ(direct.w[lane], alpha[lane]) << "lane " << lane << " round " << round;
                }
            }
        }
    }
}

// texture() and textureLod() with a read mask (texel::kReadR for .r) give
// the full read's bits on the channels they name, on both filtering paths
// (RGBA8 and the float formats), with and without mips, magnified and
// minified quads, min != mag included.
TEST(ReadMask, NamedChannelsKeepTheirBits) {
    const unsigned masks[] = {texel::kReadR, texel::kReadRGB, 0x2u, 0x8u, 0xau, texel::kReadRGBA};
    for (TextureFormat format : {TextureFormat::RGBA8, TextureFormat::RGBA32F})
    for (MipFilter mip : {MipFilter::None, MipFilter::Nearest, MipFilter::Linear})
    for (TextureFilter min : {TextureFilter::Linear, TextureFilter::Nearest})
    for (TextureFilter mag : {TextureFilter::Linear, TextureFilter::Nearest}) {
        Texture t = ramp(format, min, TextureWrap::Repeat, 64, 32);
        t.mag_filter = mag;
        t.mip_filter = mip;
        if (mip != MipFilter::None) generate_box_mips(t, full_chain_levels(64, 32));
        const Sampler2D s(t);
        std::mt19937 rng(11);
        std::uniform_real_distribution<float> coord(-1.0f, 2.0f), lod(-2.0f, 7.0f);
        for (int round = 0; round < 100; ++round) {
            // Quads of lanes a little apart (magnified) or far apart (minified).
            Vec2 st = random_lanes(rng, coord);
            if (round % 2 == 0)
                for (int lane = 0; lane < kLanes; ++lane)
                    st.x.set(lane, st.x[lane & ~3] + 0.003f * float(lane & 1)),
                        st.y.set(lane, st.y[lane & ~3] + 0.003f * float(lane >> 1 & 1));
            Float l;
            for (int lane = 0; lane < kLanes; ++lane) l.set(lane, lod(rng));
            const Vec4 all = s.sample(st), all_lod = s.sample_lod(st, l);
            for (unsigned read : masks) {
                const Vec4 some = s.sample(st, read), some_lod = s.sample_lod(st, l, read);
                for (int c = 0; c < 4; ++c) {
                    if (!(read >> c & 1u)) continue;
                    for (int lane = 0; lane < kLanes; ++lane) {
                        ASSERT_EQ(all[c][lane], some[c][lane]) << "read " << read << " channel " << c << " lane " << lane;
                        ASSERT_EQ(all_lod[c][lane], some_lod[c][lane]) << "read " << read << " channel " << c;
                    }
                }
            }
        }
    }
}

// Levels chosen once at a coordinate serve every sampler of the same
// shape bit for bit, and a sampler of another shape (size, levels, mip
// filter, LOD bias) chooses its own from the coordinate.
TEST(ImplicitLevels, SharedAmongSamplersOfOneShape) {
    auto texture = [](int w, int h, MipFilter mip, TextureFilter min, float bias) {
        Texture t = ramp(TextureFormat::RGBA8, min, TextureWrap::Repeat, w, h);
        t.mag_filter = TextureFilter::Linear;
        t.mip_filter = mip;
        t.lod_bias = bias;
        if (mip != MipFilter::None) generate_box_mips(t, full_chain_levels(w, h));
        return t;
    };
    const Texture a = texture(64, 32, MipFilter::Linear, TextureFilter::Linear, 0.0f);
    const Texture others[] = {texture(64, 32, MipFilter::Linear, TextureFilter::Linear, 0.0f),
                              texture(64, 32, MipFilter::Linear, TextureFilter::Nearest, 0.0f),
                              texture(32, 32, MipFilter::Linear, TextureFilter::Linear, 0.0f),
                              texture(64, 32, MipFilter::Nearest, TextureFilter::Linear, 0.0f),
                              texture(64, 32, MipFilter::Linear, TextureFilter::Linear, 1.5f),
                              texture(64, 32, MipFilter::None, TextureFilter::Nearest, 0.0f),
                              ramp(TextureFormat::RGBA32F, TextureFilter::Linear, TextureWrap::Repeat, 64, 32)};
    const Sampler2D sa(a);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> coord(-1.0f, 2.0f), near(-0.05f, 0.05f);
    for (const Texture& t : others) {
        const Sampler2D sb(t);
        for (int round = 0; round < 200; ++round) {
            Vec2 st = random_lanes(rng, coord);
            for (int lane = 0; lane < kLanes; ++lane)  // quads from magnified to far minified
                st.x.set(lane, st.x[lane & ~3] + near(rng) * float(round % 4)), st.y.set(lane, st.y[lane & ~3] + near(rng));
            const Sampler2D::ImplicitLevels levels = sa.implicit_levels(st);
            const Vec4 own_a = sa.sample(st), own_b = sb.sample(st);
            const Vec4 shared_a = sa.sample(st, levels), shared_b = sb.sample(st, levels);
            for (int c = 0; c < 4; ++c)
                for (int lane = 0; lane < kLanes; ++lane) {
                    ASSERT_EQ(own_a[c][lane], shared_a[c][lane]);
                    ASSERT_EQ(own_b[c][lane], shared_b[c][lane]) << "texture " << (&t - others);
                }
        }
    }
}

// texture() told which lanes use its result (`active`) gives those lanes
// the bits of a read on all lanes, whatever the others read: lanes far
// apart, on other levels, at the edges, with every wrap, all filters; and
// reads nothing when no lane is active.
TEST(ActiveLanes, ActiveLanesKeepTheirBits) {
    for (TextureFormat format : {TextureFormat::RGBA8, TextureFormat::RGBA32F})
    for (TextureWrap wrap : {TextureWrap::Repeat, TextureWrap::ClampToEdge, TextureWrap::MirroredRepeat})
    for (MipFilter mip : {MipFilter::None, MipFilter::Linear})
    for (TextureFilter filter : {TextureFilter::Linear, TextureFilter::Nearest}) {
        Texture t = ramp(format, filter, wrap, 48, 64);
        t.mip_filter = mip;
        if (mip != MipFilter::None) generate_box_mips(t, full_chain_levels(48, 64));
        const Sampler2D s(t);
        std::mt19937 rng(5);
        std::uniform_real_distribution<float> coord(-1.5f, 2.5f), near(-0.02f, 0.02f);
        std::uniform_int_distribution<unsigned> lanes(0, (1u << kLanes) - 1);
        for (int round = 0; round < 300; ++round) {
            // Most lanes close together, as in a loop, a few far off.
            Vec2 st = random_lanes(rng, coord);
            const float cx = coord(rng), cy = coord(rng);
            for (int lane = 0; lane < kLanes; ++lane)
                if (lane % 5 != 0) st.x.set(lane, cx + near(rng)), st.y.set(lane, cy + near(rng));
            const unsigned on = round == 0 ? 0u : lanes(rng);
            const Mask active = Mask::from_bits(on);
            const Vec4 all = s.sample(st), some = s.sample(st, texel::kReadRGBA, active);
            for (int lane = 0; lane < kLanes; ++lane) {
                if (!(on >> lane & 1u)) continue;
                for (int c = 0; c < 4; ++c) ASSERT_EQ(all[c][lane], some[c][lane]) << "lane " << lane << " round " << round;
            }
        }
    }
}

}  // namespace
}  // namespace st

namespace st {
namespace {

uint32_t bits_of(float f) {
    uint32_t b;
    std::memcpy(&b, &f, sizeof b);
    return b;
}

// sample_lod through taps found once (texture/bilinear_taps.h, the inlined
// clamped filter) gives the general float filter's bits, sample(st) on a
// one-level texture: at random points, at and past the edges (the last
// column's pair), on tables one texel high, for NaN and infinite
// coordinates, with one or all channels read; and a texture of another
// shape or state given the taps samples afresh.
TEST(BilinearTaps, SameBitsAsTheGeneralFilter) {
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    const float specials[] = {nan, inf, -inf, 0.0f, 1.0f, -0.0f, 1e30f, -1e30f, 0.99999994f, 1.00001f};
    struct Shape {
        int w, h;
    };
    for (const Shape& k : {Shape{64, 64}, Shape{37, 5}, Shape{256, 1}, Shape{1, 1}, Shape{7, 1}})
    for (TextureFormat format : {TextureFormat::RGBA32F, TextureFormat::RGBA16F}) {
        const Texture a = ramp(format, TextureFilter::Linear, TextureWrap::ClampToEdge, k.w, k.h);
        Texture b = ramp(format, TextureFilter::Linear, TextureWrap::ClampToEdge, k.w, k.h);
        for (float& v : b.texels32) v = 1.0f - v;  // another texture of the same shape
        const Texture other_shape = ramp(format, TextureFilter::Linear, TextureWrap::ClampToEdge, k.w + 3, k.h);
        const Texture repeat = ramp(format, TextureFilter::Linear, TextureWrap::Repeat, k.w, k.h);
        const Texture bytes = ramp(TextureFormat::RGBA8, TextureFilter::Linear, TextureWrap::ClampToEdge, k.w, k.h);
        const Sampler2D sa(a), sb(b), s_other(other_shape), s_repeat(repeat), s_bytes(bytes);
        std::mt19937 rng(11);
        std::uniform_real_distribution<float> coord(-0.2f, 1.2f);
        std::uniform_int_distribution<int> special(0, int(std::size(specials)) - 1), pick(0, 3);
        for (int round = 0; round < 300; ++round) {
            Vec2 st;
            for (int lane = 0; lane < kLanes; ++lane) {
                const int how = pick(rng);  // random, a special value, or the last column's centre and beyond
                st.x.set(lane, how == 0 ? specials[special(rng)] : how == 1 ? 1.0f - 0.5f / float(k.w) : coord(rng));
                st.y.set(lane, how == 2 ? specials[special(rng)] : coord(rng));
            }
            const BilinearTaps taps = sa.bilinear_taps(st);
            for (const Sampler2D* s : {&sa, &sb, &s_other, &s_repeat, &s_bytes}) {
                const Vec4 general = s->sample(st);  // one level: the filter alone, no LOD
                const Vec4 all = s->sample_lod(taps);
                const Vec4 rgb = s->sample_lod(taps, texel::kReadRGB);
                const Vec4 direct = s->sample_lod(st, Float(0.0f), texel::kReadRGB);
                for (int lane = 0; lane < kLanes; ++lane) {
                    const float g[4] = {general.x[lane], general.y[lane], general.z[lane], general.w[lane]};
                    const float t[4] = {all.x[lane], all.y[lane], all.z[lane], all.w[lane]};
                    const float c[3] = {rgb.x[lane], rgb.y[lane], rgb.z[lane]};
                    const float d[3] = {direct.x[lane], direct.y[lane], direct.z[lane]};
                    for (int ch = 0; ch < 4; ++ch)
                        ASSERT_EQ(bits_of(g[ch]), bits_of(t[ch]))
                            << k.w << "x" << k.h << " lane " << lane << " channel " << ch << " st " << st.x[lane]
                            << ", " << st.y[lane];
                    for (int ch = 0; ch < 3; ++ch) {
                        ASSERT_EQ(bits_of(g[ch]), bits_of(c[ch]));
                        ASSERT_EQ(bits_of(g[ch]), bits_of(d[ch]));
                    }
                }
            }
        }
    }
}

}  // namespace
}  // namespace st

namespace st {
namespace {

// A render target sampled by a later pass: its texels change each frame and
// the sampler reloads them in place from the target's level arrays (not
// through its texture). The reloaded sampler gives what a sampler made
// afresh from the new texels gives, and levels of another size or count
// are refused.
TEST(ReloadTexels, SameAsANewSampler) {
    for (TextureFormat format : {TextureFormat::RGBA32F, TextureFormat::RGBA16F}) {
        Texture t = ramp(format, TextureFilter::Linear, TextureWrap::Repeat, 32, 16);
        t.mip_filter = MipFilter::Linear;
        generate_box_mips(t, full_chain_levels(32, 16));
        const Texture original = t;
        Sampler2D reloaded(original);
        // New texels in every level, as a pass that drew them would leave.
        auto change = [](std::vector<float>& texels, int seed) {
            for (size_t i = 0; i < texels.size(); ++i) texels[i] = float((i * 37 + size_t(seed) * 11) % 251) / 251.0f;
        };
        change(t.texels32, 0);
        for (size_t l = 0; l < t.mips.size(); ++l) change(t.mips[l].texels32, int(l) + 1);
        std::vector<std::vector<float>> levels{t.texels32};
        for (const auto& m : t.mips) levels.push_back(m.texels32);
        reloaded.reload_texels(levels);
        const Sampler2D fresh(t);
        std::mt19937 rng(11);
        std::uniform_real_distribution<float> coord(-1.0f, 2.0f), grad(-0.3f, 0.3f);
        for (int round = 0; round < 100; ++round) {
            const Vec2 st = random_lanes(rng, coord), dx = random_lanes(rng, grad), dy = random_lanes(rng, grad);
            const Vec4 a = reloaded.sample_grad(st, dx, dy), b = fresh.sample_grad(st, dx, dy);
            for (int lane = 0; lane < kLanes; ++lane)
                for (int c = 0; c < 4; ++c) ASSERT_EQ(bits_of(a[c][lane]), bits_of(b[c][lane])) << int(format) << " " << round;
        }
        levels.back().pop_back();
        EXPECT_THROW(reloaded.reload_texels(levels), std::invalid_argument);  // a level of another size
        levels.pop_back();
        EXPECT_THROW(reloaded.reload_texels(levels), std::invalid_argument);  // a level short
    }
}

}  // namespace
}  // namespace st
