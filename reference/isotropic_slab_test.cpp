// isotropic_slab_test.cpp: the exact slab solver against the published
// values in ../shared/notes/techniques.md, and the thin-slab model's single
// scattering against the solver's first order.
#include "reference/isotropic_slab.h"

#include <cmath>

#include <gtest/gtest.h>

#include "kernels/thin_slab/thin_slab_model.h"

namespace st {

TEST(ExpInt, KnownValues) {
    // Abramowitz and Stegun, Table 5.1.
    EXPECT_NEAR(expint_e1(0.5), 0.5597735948, 1e-9);
    EXPECT_NEAR(expint_e1(1.0), 0.2193839344, 1e-9);
    EXPECT_NEAR(expint_e1(2.0), 0.0489005107, 1e-9);
    EXPECT_NEAR(expint_e2(1.0), 0.1484955068, 1e-9);
    EXPECT_NEAR(expint_e3(1.0), 0.1096919672, 1e-9);
}

// Exact values for an isotropic, index-matched slab at normal incidence
// (notes): tau = 1, albedo 1: R 0.34133, T 0.29079, direct 0.36788;
// tau = 1, albedo 0.5: 0.09912 / 0.07818; tau = 0.2, albedo 1: 0.09127 / 0.09000.
TEST(IsotropicSlab, ReproducesPublishedExactValues) {
    struct Case { double tau1, albedo, r, t; };
    for (const Case c : {Case{1.0, 1.0, 0.34133, 0.29079}, Case{1.0, 0.5, 0.09912, 0.07818},
                         Case{0.2, 1.0, 0.09127, 0.09000}}) {
        const SlabFluxes f = isotropic_slab_exact(c.tau1, c.albedo, 1.0);
        EXPECT_NEAR(f.reflectance, c.r, 2e-5) << c.tau1 << " " << c.albedo;
        EXPECT_NEAR(f.transmittance, c.t, 2e-5) << c.tau1 << " " << c.albedo;
        EXPECT_NEAR(f.direct, std::exp(-c.tau1), 1e-15);
        // Energy: with albedo 1 nothing is absorbed.
        if (c.albedo == 1.0) {
            EXPECT_NEAR(f.reflectance + f.transmittance + f.direct, 1.0, 5e-5);
        }
    }
}

// Eq. 4-5 are exactly the first order of scattering: their hemispherical
// integrals, (Lambda / (2 mu0)) Int f(mu) mu dmu, equal the solver's single
// scattering.
TEST(IsotropicSlab, ModelIsItsFirstOrder) {
    for (double tau1 : {0.05, 0.2, 1.0, 2.0})
        for (double mu0 : {1.0, 0.5}) {
            double front = 0.0, back = 0.0;
            const int n = 20000;
            for (int i = 0; i < n; ++i) {
                const float mu = float((i + 0.5) / n);
                front += double(frontlit_factor(float(tau1), mu, float(mu0))) * mu / n;
                back += double(backlit_factor(float(tau1), mu, float(mu0))) * mu / n;
            }
            const SlabFluxes single = isotropic_slab_single(tau1, 1.0, mu0);
            EXPECT_NEAR(front / (2.0 * mu0), single.reflectance, 2e-5) << tau1 << " " << mu0;
            EXPECT_NEAR(back / (2.0 * mu0), single.transmittance, 2e-5) << tau1 << " " << mu0;
        }
}

}  // namespace st
