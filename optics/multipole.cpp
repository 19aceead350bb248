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

Multipole::Multipole(const Slab& slab, int n, SourceDepth source) : slab_(slab), source_(source) {
    alpha_ = slab.albedo_reduced();
    sigma_tr_ = slab.sigma_tr();
    const double D = slab.diffusion_constant();
    double l = slab.mean_free_path();
    if (source == SourceDepth::FirstScatter && !slab.semi_infinite()) {
        const double x = slab.thickness / l;
        const double scatters = -std::expm1(-x);  // 1 - e^(-d/l)
        // l - d e^(-x) / (1 - e^(-x)), written to stay accurate for small x.
        l = l * (1.0 - x / std::expm1(x));
        alpha_ *= scatters;
    }
    const double a_top = slab.boundary_factor_top > 0.0 ? slab.boundary_factor_top : boundary_factor(slab.eta);
    const double zb_top = 2.0 * a_top * D;
    if (slab.semi_infinite()) {
        sources_.push_back({l, -l - 2.0 * zb_top});  // Eq. 3's dipole
        return;
    }
    const double a_bottom =
        slab.boundary_factor_bottom > 0.0 ? slab.boundary_factor_bottom : boundary_factor(slab.eta_below);
    const double zb_bottom = 2.0 * a_bottom * D;
    const double period = 2.0 * (slab.thickness + zb_top + zb_bottom);  // Eq. 16
    for (int i = -n; i <= n; ++i)
        sources_.push_back({i * period + l, i * period - l - 2.0 * zb_top});
}

// A truncated image series, or the cancellation of nearly equal terms far
// from the source, can leave a profile slightly below zero; a radiant
// exitance cannot be, so profiles are clamped at 0 (the totals are not).
double Multipole::reflectance(double r) const {
    double sum = 0.0;
    for (const SourcePair& s : sources_)
        sum += point_profile(s.z_real, r, sigma_tr_) - point_profile(s.z_virtual, r, sigma_tr_);
    return std::max(0.0, alpha_ * sum);
}

double Multipole::transmittance(double r) const {
    if (slab_.semi_infinite()) return 0.0;
    const double d = slab_.thickness;
    double sum = 0.0;
    for (const SourcePair& s : sources_)
        sum += point_profile(d - s.z_real, r, sigma_tr_) - point_profile(d - s.z_virtual, r, sigma_tr_);
    return std::max(0.0, alpha_ * sum);
}

// Without absorption sigma_tr = 0 and every pair's total cancels but the
// first, while the series' sum does not (it converges only for sigma_tr > 0).
// Its limit is the diffusion solution of a non-absorbing slab: a fluence
// linear between the extrapolated boundaries, split at the source depth.
namespace {
double non_absorbing_share(double z_source, double zb_top, double zb_bottom, double d, bool reflected) {
    const double span = d + zb_top + zb_bottom;
    return reflected ? (d + zb_bottom - z_source) / span : (z_source + zb_top) / span;
}
}  // namespace

double Multipole::total_reflectance() const {
    if (sigma_tr_ == 0.0 && !slab_.semi_infinite()) {
        const SourcePair& c = sources_[sources_.size() / 2];  // the central pair
        const double zb_top = -(c.z_virtual + c.z_real) / 2.0;
        const double a_bottom =
            slab_.boundary_factor_bottom > 0.0 ? slab_.boundary_factor_bottom : boundary_factor(slab_.eta_below);
        const double zb_bottom = 2.0 * a_bottom * slab_.diffusion_constant();
        return alpha_ * non_absorbing_share(c.z_real, zb_top, zb_bottom, slab_.thickness, true);
    }
    double sum = 0.0;
    for (const SourcePair& s : sources_) sum += point_total(s.z_real, sigma_tr_) - point_total(s.z_virtual, sigma_tr_);
    return alpha_ * sum;
}

double Multipole::total_transmittance() const {
    if (slab_.semi_infinite()) return 0.0;
    if (sigma_tr_ == 0.0) {
        const SourcePair& c = sources_[sources_.size() / 2];
        const double zb_top = -(c.z_virtual + c.z_real) / 2.0;
        const double a_bottom =
            slab_.boundary_factor_bottom > 0.0 ? slab_.boundary_factor_bottom : boundary_factor(slab_.eta_below);
        const double zb_bottom = 2.0 * a_bottom * slab_.diffusion_constant();
        return alpha_ * non_absorbing_share(c.z_real, zb_top, zb_bottom, slab_.thickness, false);
    }
    const double d = slab_.thickness;
    double sum = 0.0;
    for (const SourcePair& s : sources_)
        sum += point_total(d - s.z_real, sigma_tr_) - point_total(d - s.z_virtual, sigma_tr_);
    return alpha_ * sum;
}

Multipole Multipole::converged(const Slab& slab, double tolerance, SourceDepth source, int max_pairs_per_side) {
    if (slab.semi_infinite()) return Multipole(slab, 0, source);
    auto measures = [](const Multipole& mp) {
        return std::array<double, 4>{mp.total_reflectance(), mp.total_transmittance(), mp.reflectance(0.0),
                                     mp.transmittance(0.0)};
    };
    // Each further pair sits one period deeper, so its contribution shrinks
    // by about a constant factor q = e^(-sigma_tr period) (times an algebraic
    // factor): the series is geometric. Stop when the last pair's change plus
    // the geometric tail it implies, delta q / (1 - q), is within tolerance of
    // every measure; q is estimated from two successive changes.
    std::array<double, 4> prev = measures(Multipole(slab, 0, source)), cur = measures(Multipole(slab, 1, source));
    std::array<double, 4> prev_delta{};
    for (size_t k = 0; k < 4; ++k) prev_delta[k] = std::abs(cur[k] - prev[k]);
    for (int n = 1; n < max_pairs_per_side; ++n) {
        const std::array<double, 4> next = measures(Multipole(slab, n + 1, source));
        bool done = true;
        for (size_t k = 0; k < 4; ++k) {
            const double delta = std::abs(next[k] - cur[k]);
            const double q = prev_delta[k] > 0.0 ? delta / prev_delta[k] : 0.0;
            const double tail = q < 1.0 ? delta * q / (1.0 - q) : INFINITY;
            if (delta + tail > tolerance * std::max(std::abs(next[k]), 1e-300)) done = false;
            prev_delta[k] = delta;
        }
        cur = next;
        if (done) return Multipole(slab, n, source);
    }
    return Multipole(slab, max_pairs_per_side, source);
}

}  // namespace st::optics
