// profile_table_test.cpp: the table's lookup against the profile it
// tabulates (the dipole and the multipole of a thin slab), its layout, and
// bad input.
#include "optics/profile_table.h"

#include <gtest/gtest.h>

#include <cmath>

#include "optics/multipole.h"

namespace st::optics {
namespace {

Slab milk() {
    Slab s;
    s.sigma_a = 0.0014, s.sigma_s = 0.7, s.eta = 1.3;  // skim-milk-like, 1/mm
    return s;
}

TEST(ProfileTable, EntriesSitAtSquaredSpacing) {
    const ProfileTable t([](double r) { return r; }, [](double r) { return 2 * r; }, 9.0, 4);
    EXPECT_EQ(t.size(), 4);
    EXPECT_DOUBLE_EQ(t.radius(0), 0.0);
    EXPECT_DOUBLE_EQ(t.radius(1), 1.0);
    EXPECT_DOUBLE_EQ(t.radius(2), 4.0);
    EXPECT_DOUBLE_EQ(t.radius(3), 9.0);
    EXPECT_FLOAT_EQ(t.texels()[4 * 2 + 1], 8.0f);
    EXPECT_FLOAT_EQ(t.texels()[4 * 3 + 3], 1.0f);
    EXPECT_EQ(t.reflectance(9.5), 0.0);  // beyond the table
}

TEST(ProfileTable, LookupFollowsTheProfile) {
    // 256 entries over 8 mean free paths of reach: the lookup within 1 % of
    // the dipole and of a thin slab's multipole wherever the profile carries
    // more than 1e-3 of its peak, and exact at the entries (to float).
    Slab thin = milk();
    thin.thickness = 2.0;
    const Multipole dipole(milk(), 0);
    const Multipole thin_slab = Multipole::converged(thin, 1e-8);
    for (const Multipole* m : {&dipole, &thin_slab}) {
        auto R = [m](double r) { return m->reflectance(r); };
        auto T = [m](double r) { return m->transmittance(r); };
        const double r_max = 20.0;
        const ProfileTable t(R, T, r_max, 256);
        const double peak = R(0.0);
        double worst = 0;
        for (int k = 0; k <= 4000; ++k) {
            const double r = r_max * k / 4000.0;
            if (R(r) < 1e-3 * peak) continue;
            worst = std::max(worst, std::abs(t.reflectance(r) / R(r) - 1));
        }
        EXPECT_LT(worst, 0.01);
        for (int i = 0; i < t.size(); i += 17) EXPECT_NEAR(t.reflectance(t.radius(i)) / R(t.radius(i)), 1.0, 1e-6);
    }
}

TEST(ProfileTable, RejectsBadInput) {
    auto one = [](double) { return 1.0; };
    EXPECT_THROW(ProfileTable(one, one, 1.0, 1), std::invalid_argument);
    EXPECT_THROW(ProfileTable(one, one, 1.0, 70000), std::invalid_argument);
    EXPECT_THROW(ProfileTable(one, one, 0.0, 16), std::invalid_argument);
    EXPECT_THROW(ProfileTable(one, one, INFINITY, 16), std::invalid_argument);
    EXPECT_THROW(ProfileTable([](double) { return -1.0; }, one, 1.0, 16), std::invalid_argument);
    EXPECT_THROW(ProfileTable(one, [](double) { return NAN; }, 1.0, 16), std::invalid_argument);
}

}  // namespace
}  // namespace st::optics
