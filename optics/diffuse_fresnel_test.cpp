// diffuse_fresnel_test.cpp: the exact Fresnel term and F_dr.
#include "optics/diffuse_fresnel.h"

#include <gtest/gtest.h>

namespace st::optics {

TEST(Fresnel, NormalIncidenceAndTotalInternalReflection) {
    EXPECT_NEAR(fresnel_dielectric(1.0, 1.5), 0.04, 1e-15);
    EXPECT_NEAR(fresnel_dielectric(1.0, 1.0 / 1.5), 0.04, 1e-15);
    EXPECT_EQ(fresnel_dielectric(0.5, 1.0 / 1.5), 1.0);  // sin 60 deg > 1 / 1.5
    EXPECT_EQ(fresnel_dielectric(1.0, 1.0), 0.0);
}

// Eq. 8 is used where it matches the integral of the exact term; at the ends
// of that range the switch is small, and outside it F_dr stays below 1.
TEST(DiffuseFresnel, FitMeetsTheIntegral) {
    for (double eta : {0.5, 2.0}) {
        EXPECT_NEAR(diffuse_fresnel_reflectance(eta), diffuse_fresnel_reflectance(eta * (1.0 - 1e-12)), 6e-4) << eta;
        EXPECT_NEAR(diffuse_fresnel_reflectance(eta), diffuse_fresnel_reflectance(eta * (1.0 + 1e-12)), 6e-4) << eta;
    }
    // Beyond the critical cosine all light returns: F_dr -> 1 - 1 / eta^2 for
    // eta >> 1 is a lower bound, since the rest reflects partly too.
    double previous = 0.0;
    for (double eta : {1.0, 1.5, 2.0, 3.0, 5.0, 10.0, 100.0}) {
        const double f = diffuse_fresnel_reflectance(eta);
        EXPECT_GE(f, 1.0 - 1.0 / (eta * eta) - 1e-3) << eta;
        EXPECT_LT(f, 1.0) << eta;
        EXPECT_GE(f, previous) << eta;
        previous = f;
    }
    for (double eta : {0.01, 0.1, 0.3, 0.5}) {
        EXPECT_GE(diffuse_fresnel_reflectance(eta), 0.0) << eta;
        EXPECT_LT(diffuse_fresnel_reflectance(eta), 1.0) << eta;
    }
}

}  // namespace st::optics
