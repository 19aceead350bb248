// attribute_setup_test.cpp: plane equations and perspective-correct
// interpolation against barycentric interpolation in double precision; the
// noperspective and flat qualifiers.
#include "raster/attribute_setup.h"

#include <bit>
#include <cmath>

#include <gtest/gtest.h>

#include "shading/derivatives.h"
#include "shading/program.h"
#include "raster/float_env.h"
#include "raster/fragment_inputs.h"
#include "shading/block_layout.h"

namespace st {

namespace {

struct Vert {
    double x, y, w;  // window x, y; clip w
    glm::vec4 colour;
};

// The perspective-correct value at window point (px, py): screen-space
// barycentrics weighted by 1/w, renormalised (or not weighted, for a
// noperspective input).
double exact_attribute(const Vert v[3], double px, double py, int c, bool perspective = true) {
    const double area = (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[2].x - v[0].x) * (v[1].y - v[0].y);
    double b[3];
    for (int i = 0; i < 3; ++i) {
        const Vert &p = v[(i + 1) % 3], &q = v[(i + 2) % 3];
        b[i] = ((q.x - p.x) * (py - p.y) - (q.y - p.y) * (px - p.x)) / area;
    }
    double num = 0, den = 0;
    for (int i = 0; i < 3; ++i) {
        const double weight = perspective ? 1.0 / v[i].w : 1.0;
        num += b[i] * v[i].colour[c] * weight;
        den += b[i] * weight;
    }
    return num / den;
}

// The inputs of the lanes of the block whose lower-left pixel is (bx, by),
// in block lane order (all parts).
struct BlockInputs {
    std::array<glm::vec4, kBlockLanes> colour, frag_coord;
};

// z, 1/w and colour planes of the triangle, as setup builds them.
std::vector<Plane> planes_of(const Vert v[3], const Interpolations& modes = {}) {
    std::array<glm::vec4, 3> colours = {v[0].colour, v[1].colour, v[2].colour};
    SetupVertex sv[3];
    for (int i = 0; i < 3; ++i)
        sv[i] = {WindowPos{float(v[i].x), float(v[i].y), 0.5f, float(1.0 / v[i].w)}, &colours[size_t(i)]};
    std::vector<Plane> planes;
    setup_attribute_planes(sv[0], sv[1], sv[2], 1, modes, planes);
    return planes;
}

BlockInputs interpolate(const Vert v[3], int bx, int by, const Interpolations& modes = {}) {
    const std::vector<Plane> planes = planes_of(v, modes);
    BlockInputs out;
    for (int part = 0; part < kBlockLanes / kLanes; ++part) {
        FragmentLanes lanes;
        LaneGroup groups[kLanes / kGroupLanes];
        for (int g = 0; g < kLanes / kGroupLanes; ++g) groups[g] = {bx, by, part * (kLanes / kGroupLanes) + g, 0xff};
        interpolate_lanes(planes.data(), 1, ~0u, modes, groups, true, lanes);
        for (int lane = 0; lane < kLanes; ++lane) {
            const Vec4& c = lanes.varyings[0];
            const Vec4& f = lanes.frag_coord;
            out.colour[size_t(part * kLanes + lane)] = glm::vec4(c.x[lane], c.y[lane], c.z[lane], c.w[lane]);
            out.frag_coord[size_t(part * kLanes + lane)] = glm::vec4(f.x[lane], f.y[lane], f.z[lane], f.w[lane]);
        }
    }
    return out;
}

}  // namespace

TEST(Interpolation, AffineWhenWIsConstant) {
    const Vert v[3] = {{2.5, 2.5, 1, {0, 0, 0, 1}}, {34.5, 2.5, 1, {32, 0, 0, 1}}, {2.5, 34.5, 1, {0, 32, 0, 1}}};
    // Colour = window position - 2.5: a linear function, so exact at every centre.
    for (int by = 4; by < 20; by += 4)
        for (int bx = 4; bx < 20; bx += 4) {
            const BlockInputs q = interpolate(v, bx, by);
            for (int lane = 0; lane < kBlockLanes; ++lane) {
                const float x = float(bx + block_lane_x(lane)), y = float(by + block_lane_y(lane));
                EXPECT_FLOAT_EQ(q.colour[size_t(lane)].r, x - 2.0f);
                EXPECT_FLOAT_EQ(q.colour[size_t(lane)].g, y - 2.0f);
                EXPECT_EQ(q.frag_coord[size_t(lane)].x, x + 0.5f);
                EXPECT_EQ(q.frag_coord[size_t(lane)].y, y + 0.5f);
            }
        }
}

TEST(Interpolation, PerspectiveCorrect) {
    const Vert v[3] = {{3.2, 1.7, 0.5, {1, 0, 0.25, 1}}, {60.9, 12.3, 7.0, {0, 1, 0.5, 0}},
                       {20.1, 55.5, 2.5, {0, 0, 1, 0.5}}};
    double worst = 0;
    for (int by = 4; by < 40; by += 4)
        for (int bx = 8; bx < 40; bx += 4) {
            const BlockInputs q = interpolate(v, bx, by);
            for (int lane = 0; lane < kBlockLanes; ++lane)
                for (int c = 0; c < 4; ++c) {
                    const double want = exact_attribute(v, bx + block_lane_x(lane) + 0.5, by + block_lane_y(lane) + 0.5, c);
                    worst = std::max(worst, std::abs(double(q.colour[size_t(lane)][c]) - want));
                }
        }
    // Bound: the numerator planes (colour/w, |.| <= 2) come out of about ten
    // roundings at distances up to 40 px from v0, an absolute error of a few
    // 1e-7; the final product by w (up to 7 here) scales that by w. So a few
    // 1e-6 at most; 4e-6 is 32 ulp of 1.
    EXPECT_LT(worst, 4e-6);
    EXPECT_GT(worst, 0.0);  // float arithmetic, not a copy of the reference
}

TEST(Interpolation, NoPerspectiveIsLinearOnTheScreen) {
    const Vert v[3] = {{3.2, 1.7, 0.5, {1, 0, 0.25, 1}}, {60.9, 12.3, 7.0, {0, 1, 0.5, 0}},
                       {20.1, 55.5, 2.5, {0, 0, 1, 0.5}}};
    Interpolations modes{};
    modes[0] = Interpolation::NoPerspective;
    double worst = 0, worst_perspective = 0;
    for (int by = 4; by < 40; by += 4)
        for (int bx = 8; bx < 40; bx += 4) {
            const BlockInputs q = interpolate(v, bx, by, modes);
            for (int lane = 0; lane < kBlockLanes; ++lane)
                for (int c = 0; c < 4; ++c) {
                    const double x = bx + block_lane_x(lane) + 0.5, y = by + block_lane_y(lane) + 0.5;
                    const double got = q.colour[size_t(lane)][c];
                    worst = std::max(worst, std::abs(got - exact_attribute(v, x, y, c, false)));
                    worst_perspective = std::max(worst_perspective, std::abs(got - exact_attribute(v, x, y, c)));
                }
        }
    // The planes of values within [0, 1], without the product by w: a few
    // 1e-7 (see PerspectiveCorrect); and far from the perspective answer.
    EXPECT_LT(worst, 1e-6);
    EXPECT_GT(worst_perspective, 0.1);
}

// A flat input is the provoking (last) vertex's bits in every lane, under
// the flush-to-zero environment the pipeline renders in: signalling NaN,
// payload, -0 and a denormal (an int varying's bits) untouched.
TEST(Interpolation, FlatCopiesTheProvokingVertexBits) {
    const FlushDenormals float_env;
    const glm::vec4 bits(std::bit_cast<float>(0x7F800001u), std::bit_cast<float>(0xFFC0ABCDu),
                         std::bit_cast<float>(0x80000000u), std::bit_cast<float>(0x00000001u));
    Interpolations modes{};
    modes[0] = Interpolation::Flat;
    for (bool clockwise : {false, true}) {
        Vert v[3] = {{3.2, 1.7, 0.5, {1, 2, 3, 4}}, {60.9, 12.3, 7.0, {5, 6, 7, 8}}, {20.1, 55.5, 2.5, bits}};
        if (clockwise) std::swap(v[0], v[1]);
        const BlockInputs q = interpolate(v, 16, 16, modes);
        for (int lane = 0; lane < kBlockLanes; ++lane)
            for (int c = 0; c < 4; ++c)
                EXPECT_EQ(std::bit_cast<uint32_t>(q.colour[size_t(lane)][c]), std::bit_cast<uint32_t>(bits[c]))
                    << "lane " << lane << " component " << c << (clockwise ? " (clockwise)" : "");
    }
}

// The derivative of a linear varying across each quad is its slope, in
// every lane.
TEST(Interpolation, QuadDerivatives) {
    const Vert v[3] = {{0.5, 0.5, 1, {0, 0, 0, 0}}, {64.5, 0.5, 1, {16, 0, 0, 0}}, {0.5, 64.5, 1, {0, -8, 0, 0}}};
    const std::vector<Plane> planes = planes_of(v);
    FragmentLanes lanes;
    LaneGroup groups[kLanes / kGroupLanes];
    for (int g = 0; g < kLanes / kGroupLanes; ++g) groups[g] = {8, 20, g, 0xff};
    interpolate_lanes(planes.data(), 1, ~0u, Interpolations{}, groups, true, lanes);
    const Float ddx = dFdx(lanes.varyings[0].x), ddy = dFdy(lanes.varyings[0].y);
    for (int lane = 0; lane < kLanes; ++lane) {
        EXPECT_FLOAT_EQ(ddx[lane], 0.25f);
        EXPECT_FLOAT_EQ(ddy[lane], -0.125f);
    }
}

}  // namespace st
