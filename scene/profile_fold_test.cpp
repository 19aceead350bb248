// profile_fold_test.cpp: where Eq. 27's blend by the normals fails (issue
// 11). The gather weighs each sample by a profile chosen from the normals at
// both ends alone (R where they agree, T where they oppose), whatever lies
// between. Across a fold of thin material, the two sheets' normals oppose,
// so the light entering the lower sheet reaches the upper one through T(r)
// as if the air between them were material. Physically no light diffuses
// across air: the gathered light there should be 0.
//
// The layout is built by hand: N x N texels, the left half one sheet (A, at
// z = 0, normal +z), the right half the same sheet folded under it (B, at
// z = -gap, normal -z, its texel at distance s from the fold lying under
// A's). Only B's outer face is lit.
#include "kernels/profile/profile_gather.h"

#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "scene/profile_material.h"
#include "shading/control_flow.h"
#include "texture/sampler2d.h"

namespace st {
namespace {

constexpr int kN = 256;          // layout texels per side
constexpr float kTexel = 0.05f;  // mm: each sheet 6.4 mm long

Texture target(std::vector<float> texels) {
    Texture t;
    t.format = TextureFormat::RGBA32F;
    t.set_filter(TextureFilter::Linear);
    t.set_wrap(TextureWrap::ClampToEdge);
    t.width = t.height = kN;
    t.texels32 = std::move(texels);
    return t;
}

struct Fold {
    Texture position_area, normal, lit, dark;
    explicit Fold(float gap) {
        std::vector<float> p(size_t(kN) * kN * 4), n(p.size()), e(p.size(), 0.0f);
        for (int j = 0; j < kN; ++j)
            for (int i = 0; i < kN; ++i) {
                const size_t k = (size_t(j) * kN + size_t(i)) * 4;
                const float s = (float(i) + 0.5f) * kTexel - 0.5f * kN * kTexel;  // from the fold, < 0 on A
                const bool on_b = s > 0;
                p[k + 0] = on_b ? -s : s;
                p[k + 1] = (float(j) + 0.5f) * kTexel;
                p[k + 2] = on_b ? -gap : 0.0f;
                p[k + 3] = kTexel * kTexel;
                n[k + 2] = on_b ? -1.0f : 1.0f;
                if (on_b) e[k + 0] = e[k + 1] = e[k + 2] = 1.0f;
            }
        position_area = target(p);
        normal = target(n);
        lit = target(e);
        dark = target(std::vector<float>(p.size(), 0.0f));
    }
};

struct Gathered {
    float on_a = 0;  // green, at a point of the unlit sheet
    float on_b = 0;  // at the point of the lit sheet under it
    double r_max = 0;  // mm, the gather's reach
};

// The gather at A's texel column `column` (and at B's under it), middle row.
Gathered gather(float gap, int column) {
    ProfileMaterial m;  // Figure 4's parchment, 1 mm thick
    m.model = "multipole";
    optics::LayerSpec l;
    l.sigma_a = {0.1, 0.1, 0.1};
    l.sigma_s = {3.9, 3.9, 3.9};
    l.eta = 1.5;
    l.thickness = 1.0;
    m.layers = {l};
    GatherSettings g;
    g.samples = 1024;
    const std::shared_ptr<const BuiltProfiles> built = build_profiles(m, g);
    const Fold fold(gap);
    const Sampler2D irradiance(fold.lit), back(fold.dark), position_area(fold.position_area),
        normal(fold.normal), R(built->profile_R), T(built->profile_T), pattern(built->pattern);
    GatherInputs u;
    u.irradiance = &irradiance;
    u.irradiance_back = &back;  // inner faces: each covered by the other sheet
    u.position_area = &position_area;
    u.surface_normal = &normal;
    u.profile_R = &R;
    u.profile_T = &T;
    u.pattern = &pattern;
    u.samples = g.samples;
    u.r_max = float(built->r_max);
    u.profile_size = float(g.table_size);
    u.texel_uv = 1.0f / kN;
    auto at = [&](int i, float z, float nz) {
        const float s = (float(i) + 0.5f) * kTexel - 0.5f * kN * kTexel;
        const Vec3 x(Float(s > 0 ? -s : s), Float((kN / 2 + 0.5f) * kTexel), Float(z));
        const Vec2 uv(Float((float(i) + 0.5f) / kN), Float((kN / 2 + 0.5f) / kN));
        Exec exec;
        return profile::diffused_light(exec, u, x, Vec3(Float(0.0f), Float(0.0f), Float(nz)), uv, true).y[0];
    };
    return Gathered{at(column, 0.0f, 1.0f), at(kN - 1 - column, -gap, -1.0f), built->r_max};
}

TEST(Eq27Blend, LightCrossesTheAirOfAFold) {
    // A point of the unlit sheet 0.5 mm from the fold (10 texels).
    const int column = kN / 2 - 10;
    const float gaps[] = {0.25f, 0.5f, 1.0f, 2.0f};
    float previous = 1e30f;
    double r_max = 0;
    for (float gap : gaps) {
        const Gathered g = gather(gap, column);
        std::printf("gap %.2f mm: unlit sheet gathers %.5f, the lit one %.5f (%.1f %%)\n", gap, g.on_a, g.on_b,
                    100.0 * g.on_a / g.on_b);
        EXPECT_GT(g.on_b, 0.1f);
        // The failure: light through air, a visible share of the lit sheet's.
        EXPECT_GT(g.on_a, 0.01f * g.on_b) << "gap " << gap;
        // It falls off with the gap as T(r) does, the air taken for material.
        EXPECT_LT(g.on_a, previous) << "gap " << gap;
        previous = g.on_a;
        r_max = g.r_max;
    }
    // Beyond the profile's reach nothing crosses, but for the one column of
    // texels straddling the fold, whose bilinear positions lie in the gap.
    const Gathered far = gather(float(1.01 * r_max), column);
    EXPECT_LT(far.on_a, 1e-4f * far.on_b) << "reach " << r_max << " mm";
}

}  // namespace
}  // namespace st
