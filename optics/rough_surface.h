// rough_surface.h: a rough dielectric top surface (Donner and Jensen 2005,
// Sec. 2.4): a Torrance-Sparrow BRDF (Eq. 23) with a Beckmann facet
// distribution whose RMS slope m is the roughness, the Torrance-Sparrow
// geometry term and the exact dielectric Fresnel term; the diffuse
// transmittance rho_dt (Eq. 26) and the average diffuse reflection rho_d that
// replaces F_dr in the boundary factor A (Eq. 24). Below an RMS slope of 0.05
// the lobe is too narrow for the quadrature and the surface counts as smooth.
#pragma once

#include <cstdint>
#include <vector>

#include "optics/diffuse_fresnel.h"  // fresnel_dielectric

namespace st::optics {

class RoughSurface {
public:
    // m: RMS slope of the Beckmann distribution (the paper uses 0.1, 0.5, 1);
    // eta: index of the medium the light enters, relative to where it comes from.
    RoughSurface(double m, double eta) : m_(m), eta_(eta) {}

    // Eq. 23 for incident and outgoing cosines and the azimuth between them,
    // both directions on the same side (reflection).
    double brdf(double cos_i, double cos_o, double phi) const;

    // Eq. 26: 1 - integral of f_r cos_i over the hemisphere of incidence, for
    // light leaving at cosine cos_o; by numerical quadrature.
    double rho_dt(double cos_o) const;

    // rho_d: the BRDF's reflection of diffuse (cosine-distributed) light, the
    // mean of 1 - rho_dt over cosine-weighted directions, by Monte Carlo with
    // a fixed seed (once per material, as the paper does).
    double rho_d(uint64_t samples = 200000, uint64_t seed = 1) const;

    // rho_dt at `n` cosines (i + 0.5) / n: the table the paper generates.
    std::vector<double> rho_dt_table(int n) const;

private:
    double m_, eta_;
};

// How rho_d, the diffuse reflection of the boundary seen from inside, is
// taken from the Torrance-Sparrow surface.
enum class InternalReflection {
    // From the outside view: the paper counts all light the BRDF does not
    // reflect as transmitted; the diffuse transmittance from inside is then
    // that of the outside divided by eta^2 (reciprocity, radiance scaling as
    // n^2), and rho_d = 1 - (1 - rho_d,outside) / eta^2. Equals Eq. 8 when smooth.
    Reciprocal,
    // The BRDF evaluated from inside (relative index 1/eta) directly. Its
    // shadowing loss, counted as escape, grows with roughness: at m = 1 and
    // eta 1.4 it lets 76 % of diffuse light out where reciprocity allows 49 %.
    Inside,
};

// rho_d of a rough boundary seen from inside a medium of relative index eta
// (sampled once, fixed seed).
double rough_internal_reflectance(double m, double eta, InternalReflection how = InternalReflection::Reciprocal);

// A of Eq. 24 from that rho_d.
double rough_boundary_factor(double m, double eta, InternalReflection how = InternalReflection::Reciprocal);

}  // namespace st::optics
