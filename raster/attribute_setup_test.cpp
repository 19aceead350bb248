// attribute_setup_test.cpp: plane equations and perspective-correct
// interpolation against barycentric interpolation in double precision.
#include "raster/attribute_setup.h"

#include <cmath>

#include <gtest/gtest.h>

#include "shading/program.h"
#include "raster/fragment_inputs.h"

namespace st {

namespace {

struct Vert {
    double x, y, w;  // window x, y; clip w
    glm::vec4 colour;
};

// The perspective-correct value at window point (px, py): screen-space
// barycentrics weighted by 1/w, renormalised.
double reference(const Vert v[3], double px, double py, int c) {
    const double area = (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[2].x - v[0].x) * (v[1].y - v[0].y);
    double b[3];
    for (int i = 0; i < 3; ++i) {
        const Vert &p = v[(i + 1) % 3], &q = v[(i + 2) % 3];
        b[i] = ((q.x - p.x) * (py - p.y) - (q.y - p.y) * (px - p.x)) / area;
    }
    double num = 0, den = 0;
    for (int i = 0; i < 3; ++i) {
        num += b[i] * v[i].colour[c] / v[i].w;
        den += b[i] / v[i].w;
    }
    return num / den;
}

FragmentQuad interpolate(const Vert v[3], int qx, int qy) {
    std::array<glm::vec4, 3> colours = {v[0].colour, v[1].colour, v[2].colour};
    SetupVertex sv[3];
    for (int i = 0; i < 3; ++i)
        sv[i] = {WindowPos{float(v[i].x), float(v[i].y), 0.5f, float(1.0 / v[i].w)}, &colours[size_t(i)]};
    std::vector<Plane> planes;
    setup_attribute_planes(sv[0], sv[1], sv[2], 1, planes);
    FragmentQuad quad;
    interpolate_quad(planes.data(), 1, QuadCoverage{qx, qy, 0xf}, true, quad);
    return quad;
}

}  // namespace

TEST(Interpolation, AffineWhenWIsConstant) {
    const Vert v[3] = {{2.5, 2.5, 1, {0, 0, 0, 1}}, {34.5, 2.5, 1, {32, 0, 0, 1}}, {2.5, 34.5, 1, {0, 32, 0, 1}}};
    // Colour = window position - 2.5: a linear function, so exact at every centre.
    for (int qy = 2; qy < 20; qy += 2)
        for (int qx = 2; qx < 20; qx += 2) {
            const FragmentQuad q = interpolate(v, qx, qy);
            for (int lane = 0; lane < 4; ++lane) {
                const float x = float(qx + (lane & 1)), y = float(qy + (lane >> 1));
                EXPECT_FLOAT_EQ(q.varyings[0][size_t(lane)].r, x - 2.0f);
                EXPECT_FLOAT_EQ(q.varyings[0][size_t(lane)].g, y - 2.0f);
                EXPECT_EQ(q.frag_coord[size_t(lane)].x, x + 0.5f);
            }
        }
}

TEST(Interpolation, PerspectiveCorrect) {
    const Vert v[3] = {{3.2, 1.7, 0.5, {1, 0, 0.25, 1}}, {60.9, 12.3, 7.0, {0, 1, 0.5, 0}},
                       {20.1, 55.5, 2.5, {0, 0, 1, 0.5}}};
    double worst = 0;
    for (int qy = 4; qy < 40; qy += 2)
        for (int qx = 8; qx < 40; qx += 2) {
            const FragmentQuad q = interpolate(v, qx, qy);
            for (int lane = 0; lane < 4; ++lane)
                for (int c = 0; c < 4; ++c) {
                    const double want = reference(v, qx + (lane & 1) + 0.5, qy + (lane >> 1) + 0.5, c);
                    worst = std::max(worst, std::abs(double(q.varyings[0][size_t(lane)][c]) - want));
                }
        }
    // Bound: the numerator planes (colour/w, |.| <= 2) come out of about ten
    // roundings at distances up to 40 px from v0, an absolute error of a few
    // 1e-7; the final product by w (up to 7 here) scales that by w. So a few
    // 1e-6 at most; 4e-6 is 32 ulp of 1.
    EXPECT_LT(worst, 4e-6);
    EXPECT_GT(worst, 0.0);  // float arithmetic, not a copy of the reference
}

// The derivative of a linear varying across the quad is its slope.
TEST(Interpolation, QuadDerivatives) {
    const Vert v[3] = {{0.5, 0.5, 1, {0, 0, 0, 0}}, {64.5, 0.5, 1, {16, 0, 0, 0}}, {0.5, 64.5, 1, {0, -8, 0, 0}}};
    const FragmentQuad q = interpolate(v, 10, 20);
    for (int lane = 0; lane < 4; ++lane) {
        const Fragment f(q, lane);
        EXPECT_FLOAT_EQ(f.dFdx(0).r, 0.25f);
        EXPECT_FLOAT_EQ(f.dFdy(0).g, -0.125f);
    }
}

}  // namespace st
