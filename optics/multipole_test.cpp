// multipole_test.cpp: the dipole and multipole against closed forms, the
// numbers in ../shared/notes/techniques.md and the paper's Table 1.
#include "optics/multipole.h"

#include <cmath>

#include <gtest/gtest.h>

#include "optics/diffuse_fresnel.h"

namespace st::optics {

namespace {

// The notes' example: reduced albedo 0.99873, eta = 1, sigma_t' = 1/mm.
Slab notes_slab(double thickness) {
    Slab s{.sigma_a = 1.0 - 0.99873, .sigma_s = 0.99873, .thickness = thickness};
    return s;
}

// Midpoint integration of a radial profile over the plane, 2 pi r dr.
double integrate(const Multipole& m, bool reflect, double r_max, int steps) {
    double sum = 0.0;
    const double dr = r_max / steps;
    for (int i = 0; i < steps; ++i) {
        const double r = (i + 0.5) * dr;
        sum += 2.0 * M_PI * r * dr * (reflect ? m.reflectance(r) : m.transmittance(r));
    }
    return sum;
}

}  // namespace

TEST(DiffuseFresnel, Eq8) {
    EXPECT_NEAR(diffuse_fresnel_reflectance(1.0), 0.0017, 1e-12);  // the fit is not exactly 0 at eta = 1
    EXPECT_NEAR(diffuse_fresnel_reflectance(1.3), -1.4399 / 1.69 + 0.7099 / 1.3 + 0.6681 + 0.0636 * 1.3, 1e-15);
    EXPECT_GT(boundary_factor(1.4), boundary_factor(1.2));  // more internal reflection, larger A
}

// Jensen et al. 2001: R_d = alpha'/2 (1 + e^(-4/3 A sqrt(3 (1 - alpha')))) e^(-sqrt(3 (1 - alpha'))).
TEST(Dipole, TotalMatchesJensenClosedForm) {
    for (double albedo : {0.5, 0.9, 0.99})
        for (double eta : {1.0, 1.3, 1.5}) {
            Slab s;
            s.sigma_s = albedo;
            s.sigma_a = 1.0 - albedo;
            s.eta = eta;
            const double a = boundary_factor(eta), k = std::sqrt(3.0 * (1.0 - albedo));
            const double expected = albedo / 2.0 * (1.0 + std::exp(-4.0 / 3.0 * a * k)) * std::exp(-k);
            EXPECT_NEAR(Multipole(s, 0).total_reflectance(), expected, 1e-14) << albedo << " " << eta;
        }
}

// The closed-form totals equal the integrals of the profiles, where the
// profiles are positive everywhere (slabs of a few mean free paths and more;
// thinner ones can dip below zero far out, and profiles are clamped at 0).
TEST(Multipole, TotalsAreTheProfileIntegrals) {
    for (double d : {2.0, 5.0, 10.0}) {
        Slab s = notes_slab(d);
        s.sigma_a = 0.05;  // sigma_tr ~ 0.4/mm: the profiles fall off within ~60 mm
        s.eta = 1.4;
        s.eta_below = 1.1;
        const Multipole m = Multipole::converged(s, 1e-9);
        EXPECT_NEAR(integrate(m, true, 80.0, 100000), m.total_reflectance(), 2e-6) << d;
        EXPECT_NEAR(integrate(m, false, 80.0, 100000), m.total_transmittance(), 2e-6) << d;
    }
}

// Notes: total R with 0, 1, 2, 5 extra pairs per side is 90.2 %, 76.6 %,
// 67.5 %, 54.9 % and settles near 49.7 %.
TEST(Multipole, NotesConvergenceExample) {
    const Slab s = notes_slab(2.0);
    const auto paper = SourceDepth::MeanFreePath;
    EXPECT_NEAR(Multipole(s, 0, paper).total_reflectance(), 0.902, 0.0006);
    EXPECT_NEAR(Multipole(s, 1, paper).total_reflectance(), 0.766, 0.0012);
    EXPECT_NEAR(Multipole(s, 2, paper).total_reflectance(), 0.675, 0.0006);
    EXPECT_NEAR(Multipole(s, 5, paper).total_reflectance(), 0.549, 0.0006);
    const Multipole m = Multipole::converged(s, 1e-6, paper);
    EXPECT_NEAR(m.total_reflectance(), 0.497, 0.0006);
    // converged() sums the totals' series to infinity, and its profiles (a
    // few pairs and the rest as an integral) are within the tolerance of a
    // long truncated sum, relative to the profile at r = 0.
    const Multipole many(s, 400, paper);
    EXPECT_NEAR(m.total_reflectance(), many.total_reflectance(), 1e-12);
    EXPECT_NEAR(m.total_transmittance(), many.total_transmittance(), 1e-12);
    EXPECT_LT(m.pairs_per_side(), 20);
    for (double r : {0.0, 0.3, 1.0, 3.0, 10.0, 30.0}) {
        EXPECT_NEAR(m.reflectance(r), many.reflectance(r), 1e-6 * many.reflectance(0.0)) << r;
        EXPECT_NEAR(m.transmittance(r), many.transmittance(r), 1e-6 * many.transmittance(0.0)) << r;
    }
}

// Nearly and exactly absorption-free slabs: a truncated series needs 10^4-10^5
// pairs there; the whole series stays cheap and continuous in sigma_a.
TEST(Multipole, NearlyAbsorptionFreeIsCheap) {
    Slab s = notes_slab(1.0);
    s.eta = 1.4;
    s.eta_below = 1.2;
    s.sigma_a = 0.0;
    const Multipole none = Multipole::converged(s, 1e-6);
    s.sigma_a = 1e-9;
    const Multipole nearly = Multipole::converged(s, 1e-6);
    EXPECT_LT(none.pairs_per_side(), 50);
    EXPECT_LT(nearly.pairs_per_side(), 50);
    EXPECT_NEAR(nearly.total_reflectance(), none.total_reflectance(), 1e-6);
    EXPECT_NEAR(nearly.total_transmittance(), none.total_transmittance(), 1e-6);
    for (double r : {0.0, 0.5, 2.0, 8.0}) {
        EXPECT_NEAR(nearly.reflectance(r), none.reflectance(r), 1e-5 * none.reflectance(0.0)) << r;
        EXPECT_NEAR(nearly.transmittance(r), none.transmittance(r), 1e-5 * none.transmittance(0.0)) << r;
    }
}

// Table 1 (1 mm mean free path; the paper's albedo is not given: the notes'
// 0.99873 reproduces its dipole column, 90.2 % at every thickness).
TEST(Multipole, PaperTable1) {
    // Within half a point of the paper's multipole column, but for T at 2
    // mean free paths: 49.7 % against 48.1 % (its other parameters are
    // unknown; docs/optics.md gives the differences).
    struct Row { double d, r, t, t_tolerance; };
    for (const Row row : {Row{2, 0.498, 0.481, 0.02}, Row{10, 0.838, 0.138, 0.005}, Row{20, 0.890, 0.059, 0.005}}) {
        const Multipole m = Multipole::converged(notes_slab(row.d), 1e-6, SourceDepth::MeanFreePath);
        EXPECT_NEAR(Multipole(notes_slab(row.d), 0, SourceDepth::MeanFreePath).total_reflectance(), 0.902, 0.0006);
        EXPECT_NEAR(m.total_reflectance(), row.r, 0.005) << row.d;
        EXPECT_NEAR(m.total_transmittance(), row.t, row.t_tolerance) << row.d;
    }
}

// Thick slabs approach the semi-infinite dipole.
TEST(Multipole, ThickSlabIsTheDipole) {
    Slab thick = notes_slab(400.0), semi = notes_slab(INFINITY);
    const Multipole m = Multipole::converged(thick, 1e-8);
    EXPECT_NEAR(m.total_reflectance(), Multipole(semi, 0).total_reflectance(), 1e-8);
    EXPECT_LT(m.total_transmittance(), 1e-8);
    EXPECT_EQ(Multipole(semi, 5).dipoles(), 1);
}

// Where the paper's model breaks: the real source below a thin slab
// (l > d). With the first-scattering source the totals stay positive and
// follow the Monte Carlo (docs/optics.md has the table); with l = 1/sigma_t'
// they go negative.
TEST(Multipole, ThinSlabsStayPhysical) {
    for (double d : {1e-9, 1e-4, 0.01, 0.1, 0.5, 0.9, 1.0, 2.0}) {
        Slab s{.sigma_a = 0.01, .sigma_s = 1.0, .thickness = d};
        const Multipole m = Multipole::converged(s, 1e-6);
        const double r = m.total_reflectance(), t = m.total_transmittance();
        EXPECT_TRUE(std::isfinite(r) && std::isfinite(t)) << d;
        EXPECT_GE(r, 0.0) << d;
        EXPECT_GE(t, 0.0) << d;
        // Not more than the light that scatters in the slab at all.
        EXPECT_LE(r + t, -std::expm1(-d * s.sigma_t_reduced()) * (1.0 + 1e-9)) << d;
        for (double radius : {0.0, 0.1, 1.0, 5.0}) {
            EXPECT_GE(m.reflectance(radius), 0.0) << d << " " << radius;
            EXPECT_GE(m.transmittance(radius), 0.0) << d << " " << radius;
        }
    }
    Slab thin{.sigma_a = 0.01, .sigma_s = 1.0, .thickness = 0.5};
    EXPECT_LT(Multipole::converged(thin, 1e-6, SourceDepth::MeanFreePath).total_transmittance(), 0.0);  // the paper's model
}

// Thickness going to 0: nothing scatters, nothing comes back.
TEST(Multipole, VanishingThickness) {
    double previous = INFINITY;
    for (double d = 1.0; d > 1e-12; d /= 10.0) {
        Slab s{.sigma_a = 0.1, .sigma_s = 2.0, .thickness = d};
        const double r = Multipole::converged(s, 1e-6).total_reflectance();
        EXPECT_LT(r, previous);
        EXPECT_GE(r, 0.0);
        previous = r;
    }
    EXPECT_LT(previous, 1e-10);
}

// The same for the diffuse-incidence source, down to an optical depth of
// 1e-18 (the input bounds allow it): its depth was 0 / 0 below 1e-17. The
// light that scatters at all is 1 - 2 E3(tau), about 2 tau (1 + tau ln tau).
TEST(Multipole, VanishingThicknessDiffuseSource) {
    double previous = INFINITY;
    for (double d = 1.0; d > 1e-18; d /= 10.0) {
        Slab s{.sigma_a = 0.1, .sigma_s = 0.9, .thickness = d};
        const Multipole m = Multipole::converged(s, 1e-6, SourceDepth::DiffuseFirstScatter);
        const double r = m.total_reflectance(), t = m.total_transmittance();
        EXPECT_TRUE(std::isfinite(r) && std::isfinite(t)) << d;
        EXPECT_LE(r, previous) << d;
        EXPECT_LE(r + t, 2.0 * d * 1.01) << d;  // no more than scatters
        previous = r;
    }
    EXPECT_GT(previous, 0.0);
}

// No absorption: sigma_tr = 0, the image series does not converge, and the
// totals come from its limit; with albedo 1 and matched indices all light
// leaves, and the limit joins the absorbing case continuously.
TEST(Multipole, AbsorptionFree) {
    Slab s{.sigma_a = 0.0, .sigma_s = 1.0, .thickness = 2.0};
    const Multipole m = Multipole::converged(s, 1e-6);
    const double direct = std::exp(-2.0);
    EXPECT_NEAR(m.total_reflectance() + m.total_transmittance() + direct, 1.0, 1e-12);
    s.sigma_a = 1e-7;
    const Multipole nearly = Multipole::converged(s, 1e-9);
    EXPECT_NEAR(nearly.total_reflectance(), m.total_reflectance(), 1e-4);
    EXPECT_NEAR(nearly.total_transmittance(), m.total_transmittance(), 1e-4);
}

// An index below 1 (the slab optically thinner than its surroundings) takes
// Eq. 8's other branch, and far outside 1 the fit gives way to the exact
// integral (the fit's F_dr passes 1 at eta 3.9 and A turns negative: R was
// -325 at eta 5). Every index gives a slab's totals within [0, 1], also with
// a different medium below.
TEST(Multipole, AnyIndexGivesAReflectance) {
    for (double eta : {0.01, 0.1, 0.3, 0.5, 0.6, 0.8, 0.99, 1.0, 1.01, 1.4, 2.0, 2.5, 5.0, 10.0, 100.0}) {
        for (double below : {eta, 1.0, 1.4}) {
            for (const char* depth : {"2", "inf"}) {
                Slab s;
                s.sigma_a = 0.05;
                s.sigma_s = 1.0;
                s.eta = eta;
                s.eta_below = below;
                s.thickness = depth[0] == 'i' ? std::numeric_limits<double>::infinity() : 2.0;
                const Multipole m = Multipole::converged(s, 1e-6);
                const double R = m.total_reflectance(), T = m.total_transmittance();
                EXPECT_GT(boundary_factor(eta), 0.0) << eta;
                EXPECT_TRUE(std::isfinite(R) && std::isfinite(T)) << eta << " " << below;
                EXPECT_GT(R, 0.0) << eta << " " << below;
                EXPECT_GE(T, 0.0) << eta << " " << below;
                EXPECT_LT(R + T, 1.0) << eta << " " << below;
            }
        }
    }
}

}  // namespace st::optics

namespace st::optics {

// An optically very thin slab: the first-scatter source sits half way
// down. At d / l = 1e-17 the closed form l (1 - x / expm1(x)) rounded to 0,
// the source sat on the surface, and the series of --sigma-s 1e-5
// --thickness 1e-12 took 126,380 pairs a side to settle (issue 26's option
// domains); its series for small x keeps the depth and a few pairs do.
TEST(Multipole, OpticallyThinSourceSitsHalfWayDown) {
    for (double d : {1e-12, 1e-9, 1e-6}) {
        Slab s{.sigma_a = 0.0, .sigma_s = 1e-5, .thickness = d};
        const Multipole m = Multipole::converged(s, 1e-6);
        EXPECT_LT(m.pairs_per_side(), 50) << d;
        EXPECT_NEAR(m.sources()[size_t(m.pairs_per_side())].z_real, d / 2.0, d * 1e-6) << d;
        EXPECT_TRUE(std::isfinite(m.reflectance(0.0)) && std::isfinite(m.total_transmittance())) << d;
    }
    // Where the series takes over (x = 1e-4), it meets the closed form.
    Slab a{.sigma_a = 0.0, .sigma_s = 1.0, .thickness = 0.99999e-4}, b = a;
    b.thickness = 1.00001e-4;
    const double za = Multipole(a, 0).sources()[0].z_real, zb = Multipole(b, 0).sources()[0].z_real;
    EXPECT_NEAR(za / a.thickness, zb / b.thickness, 1e-9);
}

}  // namespace st::optics
