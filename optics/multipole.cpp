// multipole.cpp: see multipole.h.
#include "optics/multipole.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "optics/diffuse_fresnel.h"

namespace st::optics {

namespace {

constexpr double kPi = 3.14159265358979323846;

// One source's contribution to a profile at radius r: z (1 + s d) e^(-s d) / (4 pi d^3),
// d = sqrt(r^2 + z^2) (Eq. 12's summand without alpha').
double point_profile(double z, double r, double sigma_tr) {
    const double d = std::sqrt(r * r + z * z);
    if (d == 0.0) return 0.0;
    return z * (1.0 + sigma_tr * d) * std::exp(-sigma_tr * d) / (4.0 * kPi * d * d * d);
}

// Its integral over the plane: sign(z) e^(-s |z|) / 2 (notes, derived).
double point_total(double z, double sigma_tr) {
    if (z == 0.0) return 0.0;
    return (z > 0.0 ? 0.5 : -0.5) * std::exp(-sigma_tr * std::abs(z));
}

}  // namespace

double diffuse_unscattered(double tau) {
    constexpr int kSteps = 512;
    double sum = 0.0;
    for (int i = 0; i < kSteps; ++i) {
        const double mu = (i + 0.5) / kSteps;
        sum += 2.0 * mu * std::exp(-tau / mu) / kSteps;
    }
    return sum;
}

namespace {

// 1 - 2 E3(tau), the diffuse light that scatters in a layer, without the
// cancellation of 1 - diffuse_unscattered(tau): at tau ~ 1e-17 that was 0,
// and the source depth below 0 / 0.
double diffuse_scattered(double tau) {
    constexpr int kSteps = 512;
    double sum = 0.0;
    for (int i = 0; i < kSteps; ++i) {
        const double mu = (i + 0.5) / kSteps;
        sum += 2.0 * mu * -std::expm1(-tau / mu) / kSteps;
    }
    return sum;
}

// 1 - e^(-x) (1 + x), the share of a path of optical length x that has
// scattered, weighted by depth; a series below 1e-3, where the two terms
// cancel.
double scattered_depth_weight(double x) {
    if (x < 1e-3) return x * x * (0.5 - x * (1.0 / 3.0 - x * (0.125 - x / 30.0)));
    return -std::expm1(-x) - x * std::exp(-x);
}

}  // namespace

Multipole::Multipole(const Slab& slab, int n, SourceDepth source) : slab_(slab) {
    alpha_ = slab.albedo_reduced();
    sigma_tr_ = slab.sigma_tr();
    const double D = slab.diffusion_constant();
    double l = slab.mean_free_path();
    if (source == SourceDepth::DiffuseFirstScatter) {
        // Over cosine-weighted directions mu: first scattering at depth z
        // with density (1/(l mu)) e^(-z/(l mu)), 2 mu dmu.
        if (slab.semi_infinite()) {
            l = l * 2.0 / 3.0;
        } else {
            const double tau = slab.thickness / l;
            constexpr int kSteps = 512;
            double depth = 0.0;
            for (int i = 0; i < kSteps; ++i) {
                const double mu = (i + 0.5) / kSteps, x = tau / mu;
                depth += 2.0 * mu * mu * l * scattered_depth_weight(x) / kSteps;
            }
            const double scatters = diffuse_scattered(tau);
            l = depth / scatters;
            alpha_ *= scatters;
        }
    } else if (source == SourceDepth::FirstScatter && !slab.semi_infinite()) {
        const double x = slab.thickness / l;
        const double scatters = -std::expm1(-x);  // 1 - e^(-d/l)
        // l - d e^(-x) / (1 - e^(-x)) = l (1 - x / (e^x - 1)), about d / 2
        // for small x, where the two terms cancel: at x = 1e-17 x / expm1(x)
        // rounds to 1, the source sat on the surface (z = 0), and the image
        // series of such a slab (--sigma-s 1e-5 --thickness 1e-12) took
        // 250,000 pairs and more to settle. Below 1e-4 its series instead.
        l = x < 1e-4 ? l * x * (0.5 - x * (1.0 / 12.0 - x * x / 720.0)) : l * (1.0 - x / std::expm1(x));
        alpha_ *= scatters;
    }
    const double a_top = slab.boundary_factor_top > 0.0 ? slab.boundary_factor_top : boundary_factor(slab.eta);
    z_source_ = l;
    zb_top_ = 2.0 * a_top * D;
    if (slab.semi_infinite()) {
        sources_.push_back(pair(0));  // Eq. 3's dipole
        return;
    }
    const double a_bottom =
        slab.boundary_factor_bottom > 0.0 ? slab.boundary_factor_bottom : boundary_factor(slab.eta_below);
    zb_bottom_ = 2.0 * a_bottom * D;
    period_ = 2.0 * (slab.thickness + zb_top_ + zb_bottom_);  // Eq. 16
    for (int i = -n; i <= n; ++i) sources_.push_back(pair(i));
}

SourcePair Multipole::pair(int i) const {
    return {i * period_ + z_source_, i * period_ - z_source_ - 2.0 * zb_top_};
}

// The profile of the sources at i P + c for |i| > n, the series' tail, as
// an integral over i (midpoint rule): a source's profile z (1 + s rho)
// e^(-s rho) / (4 pi rho^3) is the z-derivative of -e^(-s rho) / (4 pi rho),
// rho = sqrt(r^2 + z^2), so the tail is a difference of two such terms, with
// an error of the order of the profile's second derivative in i. Without it
// a nearly non-absorbing slab's profiles converge like 1/n^2 (each pair is a
// dipole whose field falls as 1/z^3) and need 10^5 pairs and more.
double Multipole::series_tail(double c, double r, int n) const {
    if (!whole_series_ || slab_.semi_infinite()) return 0.0;
    auto Q = [&](double z) {
        const double rho = std::sqrt(r * r + z * z);
        return -std::exp(-sigma_tr_ * rho) / (4.0 * kPi * rho);
    };
    const double edge = (n + 0.5) * period_;
    return (Q(c - edge) - Q(c + edge)) / period_;
}

// A truncated image series, or the cancellation of nearly equal terms far
// from the source, can leave a profile slightly below zero; a radiant
// exitance cannot be, so profiles are clamped at 0 (the totals are not).
double Multipole::reflectance(double r) const {
    double sum = 0.0;
    for (const SourcePair& s : sources_)
        sum += point_profile(s.z_real, r, sigma_tr_) - point_profile(s.z_virtual, r, sigma_tr_);
    const SourcePair c = pair(0);
    sum += series_tail(c.z_real, r, pairs_per_side()) - series_tail(c.z_virtual, r, pairs_per_side());
    return std::max(alpha_ * sum, 0.0);  // this order lets NaN through, to be caught at output
}

double Multipole::transmittance(double r) const {
    if (slab_.semi_infinite()) return 0.0;
    const double d = slab_.thickness;
    double sum = 0.0;
    for (const SourcePair& s : sources_)
        sum += point_profile(d - s.z_real, r, sigma_tr_) - point_profile(d - s.z_virtual, r, sigma_tr_);
    const SourcePair c = pair(0);
    // d - (i P + c) runs over the lattice (-i) P + (d - c).
    sum += series_tail(d - c.z_real, r, pairs_per_side()) - series_tail(d - c.z_virtual, r, pairs_per_side());
    return std::max(alpha_ * sum, 0.0);  // this order lets NaN through, to be caught at output
}

// The whole image series' totals in closed form. The sources of one kind sit
// at i P + c for every integer i; with a = c mod P in (0, P) their totals sum
// to two geometric series,
//   sum_i sign(i P + c) e^(-s |i P + c|) / 2 = (e^(-s a) - e^(-s (P - a))) / (2 (1 - e^(-s P))),
// which tends to (P - 2 a) / (2 P) as s -> 0: the absorption-free limit, the
// diffusion solution of a non-absorbing slab (fluence linear between the
// extrapolated boundaries), where every truncated sum cancels to the first
// pair and a truncated sum of a nearly non-absorbing slab needs 10^4-10^5
// pairs to settle.
namespace {
double image_series_total(double c, double period, double s) {
    double a = std::fmod(c, period);
    if (a < 0.0) a += period;
    if (a == 0.0) return 0.0;  // a source on the surface, and its images symmetric about it
    const double b = period - a;
    if (s * period == 0.0) return (b - a) / (2.0 * period);
    return (std::expm1(-s * a) - std::expm1(-s * b)) / (-2.0 * std::expm1(-s * period));
}
}  // namespace

namespace {
// At tau ~ 1e-18 the closed forms cancel to -1e-19 where the answer is
// +1e-19: rounding, set to 0. Larger negative totals are the model's (the
// paper's source below a thin slab, docs/optics.md) and are left as they are.
double without_rounding_residue(double total) { return total < 0.0 && total > -1e-12 ? 0.0 : total; }
}  // namespace

double Multipole::total_reflectance() const {
    if (!slab_.semi_infinite() && (whole_series_ || sigma_tr_ == 0.0)) {
        const SourcePair c = pair(0);
        return without_rounding_residue(alpha_ * (image_series_total(c.z_real, period_, sigma_tr_) -
                                                  image_series_total(c.z_virtual, period_, sigma_tr_)));
    }
    double sum = 0.0;
    for (const SourcePair& s : sources_) sum += point_total(s.z_real, sigma_tr_) - point_total(s.z_virtual, sigma_tr_);
    return alpha_ * sum;
}

double Multipole::total_transmittance() const {
    if (slab_.semi_infinite()) return 0.0;
    const double d = slab_.thickness;
    if (whole_series_ || sigma_tr_ == 0.0) {
        // d - (i P + c) runs over the same lattice as (-i) P + (d - c).
        const SourcePair c = pair(0);
        return without_rounding_residue(alpha_ * (image_series_total(d - c.z_real, period_, sigma_tr_) -
                                                  image_series_total(d - c.z_virtual, period_, sigma_tr_)));
    }
    double sum = 0.0;
    for (const SourcePair& s : sources_)
        sum += point_total(d - s.z_real, sigma_tr_) - point_total(d - s.z_virtual, sigma_tr_);
    return alpha_ * sum;
}

Multipole Multipole::converged(const Slab& slab, double tolerance, SourceDepth source, int max_pairs_per_side) {
    Multipole m(slab, 0, source);
    m.whole_series_ = true;
    if (slab.semi_infinite()) return m;
    // The totals are exact (above); the pairs serve the profiles. Measured at
    // r = 0, one period and four (as far as a layering kernel reaches), each
    // profile is a running sum over the pairs +-k, built up one k at a time,
    // plus the tail beyond.
    // Each further pair sits one period deeper, so its change shrinks by a
    // factor q, about e^(-sigma_tr P) times an algebraic factor: stop when the
    // last change plus the geometric tail it implies, delta q / (1 - q), is
    // within tolerance of every measure; q from two successive changes.
    const double d = slab.thickness;
    const std::array<double, 3> radii{0.0, m.period_, 4.0 * m.period_};
    constexpr size_t kMeasures = 6;  // R and T at each radius
    auto add_pair = [&](const SourcePair& p, std::array<double, kMeasures>& sum) {
        for (size_t k = 0; k < radii.size(); ++k) {
            sum[k] += point_profile(p.z_real, radii[k], m.sigma_tr_) - point_profile(p.z_virtual, radii[k], m.sigma_tr_);
            sum[k + 3] +=
                point_profile(d - p.z_real, radii[k], m.sigma_tr_) - point_profile(d - p.z_virtual, radii[k], m.sigma_tr_);
        }
    };
    // The running sums plus the tail beyond pair n, as the profiles add it.
    auto with_tail = [&](const std::array<double, kMeasures>& sum, int n) {
        std::array<double, kMeasures> v = sum;
        const SourcePair c = m.pair(0);
        for (size_t k = 0; k < radii.size(); ++k) {
            v[k] += m.series_tail(c.z_real, radii[k], n) - m.series_tail(c.z_virtual, radii[k], n);
            v[k + 3] += m.series_tail(d - c.z_real, radii[k], n) - m.series_tail(d - c.z_virtual, radii[k], n);
        }
        return v;
    };
    std::array<double, kMeasures> sum{}, prev_delta{};
    add_pair(m.pair(0), sum);
    std::array<double, kMeasures> cur = with_tail(sum, 0);
    int n = 0;
    for (int k = 1; k <= max_pairs_per_side; ++k) {
        add_pair(m.pair(k), sum);
        add_pair(m.pair(-k), sum);
        const std::array<double, kMeasures> next = with_tail(sum, k);
        // q needs two changes, and not the first: with no pairs summed the
        // tail integral runs through the source's singularity at z = 0 and
        // can be far off, which would make q look like 0.
        bool done = k > 2;
        for (size_t j = 0; j < kMeasures; ++j) {
            const double delta = std::abs(next[j] - cur[j]);
            const double q = prev_delta[j] > 0.0 ? delta / prev_delta[j] : 0.0;
            const double tail = q < 1.0 ? delta * q / (1.0 - q) : INFINITY;
            // Relative to the profile's value at r = 0: far out a thin
            // slab's profile is a tiny remainder of cancelling images, whose
            // relative accuracy no table needs.
            if (delta + tail > tolerance * std::abs(next[j < 3 ? 0 : 3])) done = false;
            prev_delta[j] = delta;
        }
        cur = next;
        n = k;
        if (done) break;
    }
    m.sources_.clear();
    for (int i = -n; i <= n; ++i) m.sources_.push_back(m.pair(i));
    return m;
}

}  // namespace st::optics
