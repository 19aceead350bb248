// microsurface_walk.cpp: see microsurface_walk.h.
//
// The walk runs in the frame of the side the light is on: that medium is
// above (z > 0), the mean surface is z = 0, and heights are uniformly
// distributed (Smith's uncorrelated model; only their order matters), so a
// height is kept as its cumulative probability u = C1(h) in [0, 1]. From a
// height u, a ray going up leaves with probability u^Lambda(d) (its Smith
// masking); otherwise, as a ray going down always does, it meets the
// surface at the height u' = u / (1 - U)^(1 / Lambda(d)) (Lambda < -1 going
// down). There a facet visible from the ray is sampled, and Fresnel decides
// between reflection and refraction; refraction changes sides, which flips
// the frame (z -> -z, u -> 1 - u).
#include "optics/microsurface_walk.h"

#include <algorithm>
#include <cmath>

#include "optics/rough_surface.h"

namespace st::optics {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kMaxBounces = 1000;

struct Vec {
    double x, y, z;
};

double dot(const Vec& a, const Vec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

double standard_normal(PhotonRng& rng) {
    return std::sqrt(-2.0 * std::log(rng.uniform())) * std::cos(2.0 * kPi * rng.uniform());
}

// The slope x (in units of the per-axis deviation sigma) of a facet seen
// from a direction tau = cot(theta) off the mean normal: density
// (tau - x) phi(x) on x < tau (the facet's projected area times Beckmann's
// Gaussian slopes).
double visible_slope(double tau, PhotonRng& rng) {
    if (tau < -1.0) {
        // Far below the horizon: with y = tau - x the density is
        // y e^(-|tau| y) e^(-y^2 / 2) (times a constant): a Gamma(2, |tau|)
        // proposal, accepted with e^(-y^2 / 2). The inverse CDF below would
        // lose its digits to cancellation here.
        for (;;) {
            const double y = -(std::log(rng.uniform()) + std::log(rng.uniform())) / -tau;
            if (rng.uniform() <= std::exp(-0.5 * y * y)) return tau - y;
        }
    }
    // Inverse CDF: g(x) = tau Phi(x) + phi(x) rises from 0 to g(tau) on
    // (-inf, tau]; solve g(x) = U g(tau) by Newton's method kept inside a
    // shrinking bracket.
    auto Phi = [](double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); };
    auto phi = [](double x) { return std::exp(-0.5 * x * x) / std::sqrt(2.0 * kPi); };
    auto g = [&](double x) { return tau * Phi(x) + phi(x); };
    const double target = rng.uniform() * g(tau);
    double lo = std::min(tau, 0.0) - 9.0, hi = tau, x = std::min(0.0, tau - 0.5);
    for (int i = 0; i < 100; ++i) {
        const double f = g(x) - target;
        if (f > 0.0) hi = x;
        else lo = x;
        const double slope = (tau - x) * phi(x);
        double next = slope > 0.0 ? x - f / slope : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (std::abs(next - x) < 1e-13 * (1.0 + std::abs(x))) return next;
        x = next;
    }
    return x;
}

// A microfacet normal visible from direction wi (unit, pointing away from
// the surface; may point below the horizon after a bounce), with density
// proportional to max(0, wi.h) D(h). Beckmann slopes are Gaussian with
// per-axis deviation m / sqrt(2).
Vec visible_normal(const Vec& wi, double m, PhotonRng& rng) {
    const double sigma = m / std::sqrt(2.0);
    const double sin_t = std::sqrt(wi.x * wi.x + wi.y * wi.y);
    double sx, sy = sigma * standard_normal(rng);
    if (sin_t < 1e-12) {
        sx = sigma * standard_normal(rng);  // straight on: every facet is seen in proportion to its area
    } else {
        // tau = cot(theta) / sigma overflows for a surface so smooth that
        // sigma is below about 1e-296 (--roughness 1e-310, a denormal): the
        // slope sampled from tau = inf was NaN, and the photon walked on with
        // a NaN direction until roulette took it (R = 0 where the smooth
        // surface gives 0.29, and a thousand times slower). In that limit
        // (tau - x) phi(x) is phi(x): facets are seen in proportion to their
        // area, as straight on.
        const double tau = wi.z / sin_t / sigma;
        sx = sigma * (std::isfinite(tau) ? visible_slope(tau, rng) : standard_normal(rng));
    }
    // Slopes in the frame where wi lies in the x-z plane, then rotated back.
    const double c = sin_t < 1e-12 ? 1.0 : wi.x / sin_t, s = sin_t < 1e-12 ? 0.0 : wi.y / sin_t;
    const double hx = -(c * sx - s * sy), hy = -(s * sx + c * sy);
    const double len = std::sqrt(hx * hx + hy * hy + 1.0);
    return {hx / len, hy / len, 1.0 / len};
}

}  // namespace

double beckmann_lambda(double cos_theta, double m) {
    if (cos_theta >= 1.0) return 0.0;
    if (cos_theta <= -1.0) return -1.0;
    const double a = cos_theta / (m * std::sqrt(1.0 - cos_theta * cos_theta));
    return 0.5 * (std::erf(a) - 1.0) + std::exp(-a * a) / (2.0 * a * std::sqrt(kPi));
}

InterfaceOutcome microsurface_walk(double m, double n1, double n2, double& ux, double& uy, double& uz,
                                   PhotonRng& rng) {
    // The tracer's z runs into the first medium's far side; `up` maps it to
    // the walk's frame on the side where the light starts.
    const double up = uz > 0.0 ? -1.0 : 1.0;
    Vec d{ux, uy, up * uz};
    bool start_side = true;
    double n_here = n1, n_there = n2;
    double u = 1.0;  // the light comes from far above the surface
    for (int bounce = 0; bounce < kMaxBounces; ++bounce) {
        const double r = rng.uniform();
        if (d.z > 0.0) {
            const double lambda = beckmann_lambda(d.z, m);
            if (r > 1.0 - std::pow(u, lambda)) {  // leaves this side
                const double sign = start_side ? up : -up;
                ux = d.x, uy = d.y, uz = sign * d.z;
                return start_side ? InterfaceOutcome::Reflected : InterfaceOutcome::Transmitted;
            }
            u = u / std::pow(1.0 - r, 1.0 / lambda);
        } else if (d.z < 0.0) {
            u = u / std::pow(1.0 - r, 1.0 / beckmann_lambda(d.z, m));
        }  // a horizontal ray meets the surface at its own height
        u = std::clamp(u, 0.0, 1.0);
        const Vec wi{-d.x, -d.y, -d.z};
        // A visible facet faces the ray; rounding at grazing can break that
        // by a hair: sample the facet again, at the same height.
        Vec h = visible_normal(wi, m, rng);
        double c = dot(wi, h);
        for (int retry = 0; c <= 0.0 && retry < 16; ++retry) {
            h = visible_normal(wi, m, rng);
            c = dot(wi, h);
        }
        if (c <= 0.0) return InterfaceOutcome::Lost;
        const double eta = n_there / n_here;
        if (rng.uniform() <= fresnel_dielectric(c, eta)) {
            d = {d.x + 2.0 * c * h.x, d.y + 2.0 * c * h.y, d.z + 2.0 * c * h.z};
        } else {
            const double e = n_here / n_there;
            const double k = e * c - std::sqrt(std::max(0.0, 1.0 - e * e * (1.0 - c * c)));
            Vec t{e * d.x + k * h.x, e * d.y + k * h.y, e * d.z + k * h.z};
            const double len = std::sqrt(dot(t, t));
            d = {t.x / len, t.y / len, -t.z / len};  // in the frame of the other side
            u = 1.0 - u;
            start_side = !start_side;
            std::swap(n_here, n_there);
        }
        const double len = std::sqrt(dot(d, d));
        d = {d.x / len, d.y / len, d.z / len};
    }
    return InterfaceOutcome::Lost;
}

double walk_internal_reflectance(double m, double eta, uint64_t photons, uint64_t seed) {
    PhotonRng rng(seed, 0);
    uint64_t reflected = 0;
    for (uint64_t i = 0; i < photons; ++i) {
        const double c = std::sqrt(rng.uniform()), phi = 2.0 * kPi * rng.uniform(), s = std::sqrt(1.0 - c * c);
        double ux = s * std::cos(phi), uy = s * std::sin(phi), uz = c;
        if (microsurface_walk(m, eta, 1.0, ux, uy, uz, rng) == InterfaceOutcome::Reflected) ++reflected;
    }
    return double(reflected) / double(photons);
}

}  // namespace st::optics
