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

Multipole::Multipole(const Slab& slab, int n) : slab_(slab) {
    alpha_ = slab.albedo_reduced();
    sigma_tr_ = slab.sigma_tr();
    const double D = slab.diffusion_constant(), l = slab.mean_free_path();
    const double zb_top = 2.0 * boundary_factor(slab.eta) * D;
    if (slab.semi_infinite()) {
        sources_.push_back({l, -l - 2.0 * zb_top});  // Eq. 3's dipole
        return;
    }
    const double zb_bottom = 2.0 * boundary_factor(slab.eta_below) * D;
    const double period = 2.0 * (slab.thickness + zb_top + zb_bottom);  // Eq. 16
    for (int i = -n; i <= n; ++i)
        sources_.push_back({i * period + l, i * period - l - 2.0 * zb_top});
}

double Multipole::reflectance(double r) const {
    double sum = 0.0;
    for (const SourcePair& s : sources_)
        sum += point_profile(s.z_real, r, sigma_tr_) - point_profile(s.z_virtual, r, sigma_tr_);
    return alpha_ * sum;
}

double Multipole::transmittance(double r) const {
    if (slab_.semi_infinite()) return 0.0;
    const double d = slab_.thickness;
    double sum = 0.0;
    for (const SourcePair& s : sources_)
        sum += point_profile(d - s.z_real, r, sigma_tr_) - point_profile(d - s.z_virtual, r, sigma_tr_);
    return alpha_ * sum;
}

double Multipole::total_reflectance() const {
    double sum = 0.0;
    for (const SourcePair& s : sources_) sum += point_total(s.z_real, sigma_tr_) - point_total(s.z_virtual, sigma_tr_);
    return alpha_ * sum;
}

double Multipole::total_transmittance() const {
    if (slab_.semi_infinite()) return 0.0;
    const double d = slab_.thickness;
    double sum = 0.0;
    for (const SourcePair& s : sources_)
        sum += point_total(d - s.z_real, sigma_tr_) - point_total(d - s.z_virtual, sigma_tr_);
    return alpha_ * sum;
}

Multipole Multipole::converged(const Slab& slab, double tolerance, int max_pairs_per_side) {
    if (slab.semi_infinite()) return Multipole(slab, 0);
    auto measures = [](const Multipole& mp) {
        return std::array<double, 4>{mp.total_reflectance(), mp.total_transmittance(), mp.reflectance(0.0),
                                     mp.transmittance(0.0)};
    };
    // Each further pair sits one period deeper, so its contribution shrinks
    // by about a constant factor q = e^(-sigma_tr period) (times an algebraic
    // factor): the series is geometric. Stop when the last pair's change plus
    // the geometric tail it implies, delta q / (1 - q), is within tolerance of
    // every measure; q is estimated from two successive changes.
    std::array<double, 4> prev = measures(Multipole(slab, 0)), cur = measures(Multipole(slab, 1));
    std::array<double, 4> prev_delta{};
    for (size_t k = 0; k < 4; ++k) prev_delta[k] = std::abs(cur[k] - prev[k]);
    for (int n = 1; n < max_pairs_per_side; ++n) {
        const std::array<double, 4> next = measures(Multipole(slab, n + 1));
        bool done = true;
        for (size_t k = 0; k < 4; ++k) {
            const double delta = std::abs(next[k] - cur[k]);
            const double q = prev_delta[k] > 0.0 ? delta / prev_delta[k] : 0.0;
            const double tail = q < 1.0 ? delta * q / (1.0 - q) : INFINITY;
            if (delta + tail > tolerance * std::max(std::abs(next[k]), 1e-300)) done = false;
            prev_delta[k] = delta;
        }
        cur = next;
        if (done) return Multipole(slab, n);
    }
    return Multipole(slab, max_pairs_per_side);
}

}  // namespace st::optics
