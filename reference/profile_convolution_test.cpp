// profile_convolution_test.cpp: the exact convolutions against closed forms
// (a Gaussian profile's half-plane is the normal CDF, its centred disk
// 1 - exp(-a^2 / 2 sigma^2); an exponential profile's centred disk), exact
// identities (M(d) + M(-d) is the total), and a brute-force 2D sum.
#include "reference/profile_convolution.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>
#include <numbers>

namespace st::reference {
namespace {

constexpr double kPi = std::numbers::pi;

RadialProfile gaussian(double sigma) {
    return [sigma](double r) { return std::exp(-r * r / (2 * sigma * sigma)) / (2 * kPi * sigma * sigma); };
}
RadialProfile exponential(double l) {
    return [l](double r) { return std::exp(-r / l) / (2 * kPi * l * l); };
}

TEST(ProfileConvolution, TotalsAreOne) {
    EXPECT_NEAR(profile_total(gaussian(0.7)), 1.0, 1e-12);
    EXPECT_NEAR(profile_total(exponential(0.3)), 1.0, 1e-12);
}

TEST(ProfileConvolution, GaussianHalfPlaneIsTheNormalCdf) {
    const double sigma = 0.8;
    for (double d : {-5.0, -2.0, -0.5, -1e-9, 0.0, 1e-9, 0.3, 1.0, 2.5, 6.0}) {
        const double exact = 0.5 * std::erfc(-d / (sigma * std::sqrt(2.0)));
        EXPECT_NEAR(convolve_half_plane(gaussian(sigma), d), exact, 1e-11) << d;
    }
}

TEST(ProfileConvolution, HalfPlaneSidesAddToTheTotal) {
    const RadialProfile p = exponential(0.25);
    for (double d : {0.01, 0.2, 1.0, 3.0}) {
        EXPECT_NEAR(convolve_half_plane(p, d) + convolve_half_plane(p, -d), 1.0, 1e-11) << d;
    }
    EXPECT_NEAR(convolve_half_plane(p, 0.0), 0.5, 1e-12);
}

TEST(ProfileConvolution, CentredDisks) {
    for (double a : {0.1, 0.5, 2.0}) {
        EXPECT_NEAR(convolve_disk(gaussian(0.5), a, 0.0), 1 - std::exp(-a * a / (2 * 0.25)), 1e-11) << a;
        const double l = 0.3;
        EXPECT_NEAR(convolve_disk(exponential(l), a, 0.0), 1 - std::exp(-a / l) * (1 + a / l), 1e-11) << a;
    }
}

TEST(ProfileConvolution, OffCentreDiskAgainstABruteForceSum) {
    // Midpoint sum over a fine grid on the disk: converges slowly at its
    // edge, so the agreement is to about 1e-4, which a wrong angular share
    // (say, acos without the 1/pi or a kink missed) exceeds by far.
    const RadialProfile p = exponential(0.2);
    const double a = 0.6;
    for (double rho : {0.0, 0.3, 0.6, 0.9, 1.5}) {
        const int n = 1500;
        const double h = 2 * a / n;
        double sum = 0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const double x = -a + (i + 0.5) * h, y = -a + (j + 0.5) * h;
                if (x * x + y * y > a * a) continue;
                sum += p(std::hypot(x - rho, y)) * h * h;
            }
        EXPECT_NEAR(convolve_disk(p, a, rho), sum, 2e-4) << rho;
    }
}

TEST(ProfileConvolution, TabulatedProfileBreaksAtItsKnots) {
    // A histogram-like profile, linear between 200 knots: its total is a
    // closed form per segment. With the knots as breakpoints each piece is a
    // polynomial that Gauss-Kronrod integrates at once; without them the
    // rule bisects towards every kink (the exact image of a Monte Carlo
    // profile took 17 s of a 23 s sweep that way).
    std::vector<double> x, y;
    for (int i = 0; i < 200; ++i) {
        x.push_back(0.05 * (i + 0.5));
        y.push_back(std::exp(-x.back()) * (1.0 + 0.3 * ((i * 7) % 5)));
    }
    long calls = 0;
    const RadialProfile p = [&](double r) {
        ++calls;
        if (!(r > x.front())) return y.front();
        if (!(r < x.back())) return 0.0;
        const size_t i = size_t(std::upper_bound(x.begin(), x.end(), r) - x.begin()) - 1;
        return y[i] + (r - x[i]) / (x[i + 1] - x[i]) * (y[i + 1] - y[i]);
    };
    // Integral of (y0 + s (r - x0)) 2 pi r over each segment, and the flat
    // disk inside the first knot.
    double exact = y.front() * kPi * x.front() * x.front();
    for (size_t i = 0; i + 1 < x.size(); ++i) {
        const double a = x[i], b = x[i + 1], s = (y[i + 1] - y[i]) / (b - a), c = y[i] - s * a;
        exact += 2 * kPi * (c * (b * b - a * a) / 2 + s * (b * b * b - a * a * a) / 3);
    }
    ConvolutionSettings knotted{20.0, 1e-10, x};
    EXPECT_NEAR(profile_total(p, knotted), exact, 1e-10 * exact);
    const long with_knots = calls;
    calls = 0;
    EXPECT_NEAR(profile_total(p, ConvolutionSettings{20.0, 1e-10, {}}), exact, 1e-8 * exact);
    EXPECT_LT(with_knots * 5, calls) << with_knots << " evaluations with the knots, " << calls << " without";
    // Knots beyond the range, unsorted or not finite are ignored or sorted.
    knotted.knots.push_back(-1.0);
    knotted.knots.push_back(NAN);
    knotted.knots.push_back(1e9);
    std::reverse(knotted.knots.begin(), knotted.knots.end());
    EXPECT_NEAR(profile_total(p, knotted), exact, 1e-10 * exact);
}

TEST(ProfileConvolution, RejectsBadInput) {
    EXPECT_THROW(convolve_half_plane(gaussian(1), NAN), std::invalid_argument);
    EXPECT_THROW(convolve_disk(gaussian(1), -1, 0), std::invalid_argument);
    EXPECT_THROW(convolve_disk(gaussian(1), 1, INFINITY), std::invalid_argument);
    EXPECT_THROW(profile_total(gaussian(1), ConvolutionSettings{0.0, 1e-12, {}}), std::invalid_argument);
    EXPECT_THROW(profile_total(RadialProfile{}), std::invalid_argument);
}

}  // namespace
}  // namespace st::reference
