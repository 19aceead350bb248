// thin_slab_model_test.cpp: the thin-slab model (Frisvad et al. Eq. 4-9)
// against analytic values, limits and an energy bound. All references are
// computed in double precision from the paper's formulas.
#include "kernels/thin_slab/thin_slab_model.h"

#include <cmath>

#include <gtest/gtest.h>

namespace st {

namespace {

double front_ref(double tau1, double mu, double mu0) {  // Eq. 4 bracket
    return mu0 / (mu + mu0) * -std::expm1(-tau1 * (1.0 / mu + 1.0 / mu0));
}

double back_ref(double tau1, double mu, double mu0) {  // Eq. 5 bracket, or its limit
    if (mu == mu0) return tau1 / mu0 * std::exp(-tau1 / mu0);
    return mu0 / (mu - mu0) * std::exp(-tau1 / mu0) * std::expm1(tau1 * (mu - mu0) / (mu * mu0));
}

double rel(double got, double want) { return std::abs(got - want) / std::abs(want); }

}  // namespace

// Eq. 5 has a removable singularity at mu = mu0; its limit is
// (tau1/mu0) e^(-tau1/mu0) (notes: naive float is +205 % off at 1e-7).
TEST(ThinSlabModel, BacklitIsSmoothThroughMuEqualsMu0) {
    for (float tau1 : {0.01f, 0.2f, 2.0f, 8.0f})
        for (float mu0 : {0.1f, 0.5f, 1.0f}) {
            const double limit = double(tau1) / mu0 * std::exp(-double(tau1) / mu0);
            EXPECT_LT(rel(backlit_factor(tau1, mu0, mu0), limit), 2e-6) << tau1 << " " << mu0;
            for (double eps : {1e-7, -1e-7, 1e-5, -1e-4, 1e-3, 0.05, -0.2}) {
                const float mu = float(mu0 * (1.0 + eps));
                if (mu > 1.0f) continue;
                EXPECT_LT(rel(backlit_factor(tau1, mu, mu0), back_ref(tau1, mu, mu0)), 2e-5)
                    << "tau1 " << tau1 << " mu0 " << mu0 << " eps " << eps;
            }
        }
}

// 1 - exp(-x) keeps full relative accuracy down to tiny x (the notes: the
// naive form is -4.6 % off at 1e-6 and -100 % at 1e-8).
TEST(ThinSlabModel, OneMinusExpIsAccurateForSmallX) {
    for (double x = 1e-12; x < 50.0; x *= 1.7) {
        const double want = -std::expm1(-x);
        // Series branch: a few ulps. Exp branch: llvmpipe's exp (<= 9.4 ulp)
        // amplified by e^-x / (1 - e^-x) <= 8 at the switch point x = 0.125.
        const double bound = x < 0.125 ? 4e-7 : 1.2e-5;
        EXPECT_LT(rel(one_minus_exp_neg(float(x)), want), bound) << x;
    }
}

// tau1 -> 0: both brackets tend to tau1 / mu (one scattering, optically thin).
TEST(ThinSlabModel, ThinLimit) {
    for (float tau1 : {1e-8f, 1e-6f, 1e-4f}) {
        EXPECT_LT(rel(frontlit_factor(tau1, 0.6f, 0.9f), tau1 / 0.6), 1e-3);
        EXPECT_LT(rel(backlit_factor(tau1, 0.6f, 0.9f), tau1 / 0.6), 1e-3);
        EXPECT_LT(rel(frontlit_factor(tau1, 0.6f, 0.9f), front_ref(tau1, 0.6, 0.9)), 1e-6);
        EXPECT_LT(rel(backlit_factor(tau1, 0.6f, 0.9f), back_ref(tau1, 0.6, 0.9)), 1e-6);
    }
}

// Grazing view: tau1/mu overflows; alpha must go to 0, the radiance stay finite.
TEST(ThinSlabModel, GrazingAnglesStayFinite) {
    const glm::vec3 n(0, 0, 1), p(0, 0, 0), light(0.3f, 0.2f, 2.0f);
    for (glm::vec3 eye : {glm::vec3(5, 0, 0), glm::vec3(5, 0, 1e-7f), glm::vec3(5, 0, -1e-7f)})
        for (float tau1 : {0.0f, 1e-6f, 2.0f, 1e6f}) {
            const glm::vec4 r = thin_slab(p, n, eye, light, 100.0f, tau1, glm::vec3(1.0f));
            for (int c = 0; c < 4; ++c) EXPECT_TRUE(std::isfinite(r[c])) << tau1 << " channel " << c;
            // mu is held at MU_MIN within 1e-6 of grazing: alpha is
            // exp(-tau1 / MU_MIN) there, which is 0 for any tau1 >= 1e-3.
            if (tau1 >= 1e-3f) EXPECT_EQ(r.a, 0.0f);
            else EXPECT_NEAR(r.a, std::exp(-double(tau1) / MU_MIN), 1e-5);
            EXPECT_GE(r.r, 0.0f);
        }
    // Light in the slab's plane (mu0 = 0) and on the surface (r = 0).
    for (glm::vec3 light2 : {glm::vec3(3, 0, 0), glm::vec3(0, 0, 0)}) {
        const glm::vec4 r = thin_slab(p, n, glm::vec3(0, 1, 3), light2, 100.0f, 2.0f, glm::vec3(1.0f));
        for (int c = 0; c < 4; ++c) EXPECT_TRUE(std::isfinite(r[c])) << c;
    }
    for (float mu : {0.0f, 1e-30f, 1e-9f}) {
        EXPECT_TRUE(std::isfinite(frontlit_factor(2.0f, std::fmax(mu, MU_MIN), 0.5f)));
        EXPECT_TRUE(std::isfinite(backlit_factor(2.0f, std::fmax(mu, MU_MIN), 0.5f)));
    }
}

// Energy: single scattering can never send out more than the light that
// interacts with the slab, Lambda (1 - e^(-tau1/mu0)) of the incident flux.
// With L = Lambda F/(4 pi) f(mu) for a beam of flux density F across the beam
// (irradiance F mu0), the escaping fraction is (1/(2 mu0)) Int (f+ + f-) mu dmu.
// For tau1 -> 0 the bound is reached (no second scattering, no self-shadowing).
TEST(ThinSlabModel, ReflectedPlusTransmittedNeverExceedsIncident) {
    for (float tau1 : {1e-3f, 0.05f, 0.2f, 1.0f, 2.0f, 10.0f})
        for (float mu0 : {0.05f, 0.3f, 0.7f, 1.0f}) {
            double integral = 0.0;
            const int n = 4000;
            for (int i = 0; i < n; ++i) {  // midpoint rule in mu
                const float mu = (float(i) + 0.5f) / float(n);
                integral += double(frontlit_factor(tau1, mu, mu0) + backlit_factor(tau1, mu, mu0)) * mu / n;
            }
            const double escaping = integral / (2.0 * mu0);
            const double interacting = -std::expm1(-double(tau1) / mu0);
            EXPECT_LE(escaping, interacting * (1.0 + 1e-4)) << tau1 << " " << mu0;
            EXPECT_GT(escaping, 0.0);
            if (tau1 <= 1e-3f && mu0 >= 0.3f) {
                EXPECT_GT(escaping / interacting, 0.99) << mu0;
            }
        }
}

}  // namespace st
