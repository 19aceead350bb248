// microsurface_walk_test.cpp: the energy-conserving rough interface against
// the smooth Fresnel limit, the single-bounce Torrance-Sparrow surface, and
// reciprocity between its two sides.
#include "optics/microsurface_walk.h"

#include <cmath>

#include <gtest/gtest.h>

#include "optics/rough_surface.h"

namespace st::optics {

namespace {

struct Split {
    double reflected = 0, transmitted = 0, lost = 0;
};

// Light from medium n1 onto the surface: at normal incidence, or
// cosine-distributed (diffuse) when `diffuse`.
Split shoot(double m, double n1, double n2, bool diffuse, int photons, uint64_t seed = 1) {
    PhotonRng rng(seed, 0);
    Split s;
    for (int i = 0; i < photons; ++i) {
        double ux = 0, uy = 0, uz = 1;
        if (diffuse) {
            const double c = std::sqrt(rng.uniform()), phi = 2.0 * 3.14159265358979323846 * rng.uniform();
            const double st = std::sqrt(1.0 - c * c);
            ux = st * std::cos(phi), uy = st * std::sin(phi), uz = c;
        }
        const InterfaceOutcome o = microsurface_walk(m, n1, n2, ux, uy, uz, rng);
        EXPECT_NEAR(ux * ux + uy * uy + uz * uz, 1.0, 1e-9);
        if (o == InterfaceOutcome::Reflected) {
            EXPECT_LT(uz, 0.0);
            s.reflected += 1.0 / photons;
        } else if (o == InterfaceOutcome::Transmitted) {
            EXPECT_GT(uz, 0.0);
            s.transmitted += 1.0 / photons;
        } else {
            s.lost += 1.0 / photons;
        }
    }
    return s;
}

}  // namespace

// Smith's Lambda: 0 straight up, -1 straight down, Lambda(-w) = -1 - Lambda(w).
TEST(MicrosurfaceWalk, BeckmannLambda) {
    EXPECT_EQ(beckmann_lambda(1.0, 0.5), 0.0);
    EXPECT_EQ(beckmann_lambda(-1.0, 0.5), -1.0);
    for (double c : {0.1, 0.5, 0.9}) EXPECT_NEAR(beckmann_lambda(-c, 0.7), -1.0 - beckmann_lambda(c, 0.7), 1e-12) << c;
}

// Nearly smooth: Fresnel's 4 % at normal incidence onto glass.
TEST(MicrosurfaceWalk, SmoothLimit) {
    const Split s = shoot(0.01, 1.0, 1.5, false, 200000);
    EXPECT_NEAR(s.reflected, 0.04, 4.0 * std::sqrt(0.04 * 0.96 / 200000));
    EXPECT_EQ(s.lost, 0.0);
}

// Nothing is lost, however rough; at normal incidence onto m = 0.5 the
// reflection is the single-bounce surface's (1 - rho_dt(1) = 0.0364) plus
// what its shadowing would have lost and the walk sends back up.
TEST(MicrosurfaceWalk, ConservesEnergy) {
    for (double m : {0.1, 0.5, 1.0}) {
        const Split s = shoot(m, 1.0, 1.5, true, 100000);
        EXPECT_EQ(s.lost, 0.0) << m;
        EXPECT_NEAR(s.reflected + s.transmitted, 1.0, 1e-9) << m;
    }
    const Split n = shoot(0.5, 1.0, 1.5, false, 400000);
    const double single = 1.0 - RoughSurface(0.5, 1.5).rho_dt(1.0);
    EXPECT_GT(n.reflected, single - 4.0 * std::sqrt(single / 400000));
    EXPECT_LT(n.reflected, single + 0.01);
}

// Reciprocity: the diffuse transmittance from inside is that from outside
// divided by eta^2, the law the reciprocal rho_d of Eq. 24 assumes
// (optics/rough_surface.h). A walk with a wrong step breaks it.
TEST(MicrosurfaceWalk, DiffuseTransmittanceIsReciprocal) {
    const int n = 400000;
    for (double m : {0.3, 1.0}) {
        const double eta = 1.5;
        const Split out = shoot(m, 1.0, eta, true, n, 2), in = shoot(m, eta, 1.0, true, n, 3);
        const double sigma = std::sqrt(in.transmitted * (1.0 - in.transmitted) / n) +
                             std::sqrt(out.transmitted * (1.0 - out.transmitted) / n) / (eta * eta);
        EXPECT_NEAR(in.transmitted, out.transmitted / (eta * eta), 4.0 * sigma) << m;
    }
}

// The walk's own diffuse reflection from inside is what Eq. 24's reciprocal
// rho_d predicts from the single-bounce BRDF seen from outside (0.582 and
// 0.573 at m = 0.5 and 1, eta 1.5), not the BRDF read from inside (0.453,
// 0.286): the check behind InternalReflection::Reciprocal being the default.
TEST(MicrosurfaceWalk, InternalReflectionIsTheReciprocalRhoD) {
    const int n = 300000;
    for (double m : {0.5, 1.0}) {
        const double walk = walk_internal_reflectance(m, 1.5, n, 4);
        const double sigma = std::sqrt(walk * (1.0 - walk) / n);
        EXPECT_NEAR(walk, rough_internal_reflectance(m, 1.5), 4.0 * sigma + 0.002) << m;
        EXPECT_GT(walk, rough_internal_reflectance(m, 1.5, InternalReflection::Inside) + 0.1) << m;
    }
}

}  // namespace st::optics

namespace st::optics {

// A roughness so small that cot(theta) / sigma overflows (1e-310, a
// denormal, reaches the walk from `--roughness` or a layers file): the
// sampled slope was NaN, every photon walked on with a NaN direction (Monte
// Carlo's R came out 0). The surface is smooth: Fresnel's 4 % onto glass,
// and total internal reflection from inside as for m = 1e-6.
TEST(MicrosurfaceWalk, DenormalRoughnessIsSmooth) {
    for (double m : {1e-300, 1e-310, 1e-320}) {
        const Split s = shoot(m, 1.0, 1.5, false, 100000);
        EXPECT_NEAR(s.reflected, 0.04, 4.0 * std::sqrt(0.04 * 0.96 / 100000)) << m;
        EXPECT_EQ(s.lost, 0.0) << m;
        const Split in = shoot(m, 1.5, 1.0, true, 100000), smooth = shoot(1e-6, 1.5, 1.0, true, 100000, 2);
        EXPECT_NEAR(in.reflected, smooth.reflected, 4.0 * std::sqrt(2.0 * 0.25 / 100000)) << m;
    }
}

}  // namespace st::optics
