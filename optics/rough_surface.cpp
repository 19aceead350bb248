// rough_surface.cpp: see rough_surface.h.
#include "optics/rough_surface.h"

#include <algorithm>
#include <cmath>

#include "optics/photon_rng.h"

namespace st::optics {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

double RoughSurface::brdf(double cos_i, double cos_o, double phi) const {
    if (cos_i <= 0.0 || cos_o <= 0.0) return 0.0;
    const double si = std::sqrt(1.0 - cos_i * cos_i), so = std::sqrt(1.0 - cos_o * cos_o);
    // Directions with the normal along z: i = (si, 0, ci), o = (so cos phi, so sin phi, co).
    const double hx = si + so * std::cos(phi), hy = so * std::sin(phi), hz = cos_i + cos_o;
    const double len = std::sqrt(hx * hx + hy * hy + hz * hz);
    const double nh = hz / len;
    const double oh = (so * std::cos(phi) * hx + so * std::sin(phi) * hy + cos_o * hz) / len;  // = i.h
    // Beckmann: exp(-tan^2 / m^2) / (pi m^2 cos^4).
    const double nh2 = nh * nh, tan2 = (1.0 - nh2) / nh2;
    const double D = std::exp(-tan2 / (m_ * m_)) / (kPi * m_ * m_ * nh2 * nh2);
    // Torrance-Sparrow shadowing and masking.
    const double G = std::min({1.0, 2.0 * nh * cos_o / oh, 2.0 * nh * cos_i / oh});
    const double F = fresnel_dielectric(oh, eta_);
    return D * G * F / (4.0 * cos_i * cos_o);
}

// Below this RMS slope the specular lobe is narrower than the quadrature
// resolves; the surface is then treated as smooth (exact Fresnel).
constexpr double kSmoothBelow = 0.05;

double RoughSurface::rho_dt(double cos_o) const {
    if (m_ < kSmoothBelow) return 1.0 - fresnel_dielectric(cos_o, eta_);
    // Midpoint rule in (cos theta_i, phi); the integrand is smooth in both.
    const int nt = 256, np = 128;
    double sum = 0.0;
    for (int a = 0; a < nt; ++a) {
        const double ci = (a + 0.5) / nt;
        for (int b = 0; b < np; ++b) {
            const double phi = (b + 0.5) * kPi / np;  // symmetric in phi: integrate [0, pi], double
            sum += brdf(ci, cos_o, phi) * ci;
        }
    }
    const double integral = 2.0 * sum * (1.0 / nt) * (kPi / np);
    return std::clamp(1.0 - integral, 0.0, 1.0);
}

double RoughSurface::rho_d(uint64_t samples, uint64_t seed) const {
    if (m_ < kSmoothBelow) {  // smooth: 2 Int F(mu) mu dmu
        const int n = 100000;
        double sum = 0.0;
        for (int i = 0; i < n; ++i) {
            const double mu = (i + 0.5) / n;
            sum += 2.0 * fresnel_dielectric(mu, eta_) * mu / n;
        }
        return sum;
    }
    // Cosine-weighted pairs of directions: E[f_r pi] is the diffuse
    // reflectance (both cosines in the measure).
    PhotonRng rng(seed, 0);
    double sum = 0.0;
    for (uint64_t k = 0; k < samples; ++k) {
        const double ci = std::sqrt(rng.uniform()), co = std::sqrt(rng.uniform());
        const double phi = 2.0 * kPi * rng.uniform();
        sum += brdf(ci, co, phi) * kPi;
    }
    return std::clamp(sum / double(samples), 0.0, 1.0);
}

std::vector<double> RoughSurface::rho_dt_table(int n) const {
    std::vector<double> t;
    for (int i = 0; i < n; ++i) t.push_back(rho_dt((i + 0.5) / n));
    return t;
}

double rough_internal_reflectance(double m, double eta, InternalReflection how) {
    if (how == InternalReflection::Inside) return RoughSurface(m, 1.0 / eta).rho_d();
    const double transmitted_from_outside = 1.0 - RoughSurface(m, eta).rho_d();
    return std::clamp(1.0 - transmitted_from_outside / (eta * eta), 0.0, 1.0);
}

double rough_boundary_factor(double m, double eta, InternalReflection how) {
    const double rd = rough_internal_reflectance(m, eta, how);
    return (1.0 + rd) / (1.0 - rd);
}

}  // namespace st::optics
