// profile_convolution.h: the exact rendering of a flat, semi-infinite (or
// slab) surface lit by a pattern with sharp edges: the light leaving a point
// is the 2D convolution of the irradiance with the radial diffusion profile,
// M(x) = integral of E(x') R(|x - x'|) dA' (Donner and Jensen 2005, Sec. 3,
// the sum that the gather pass approximates by samples). For a lit region
// whose edge is a straight line or a circle, the angular integral is closed
// form and M is one radial integral, here by adaptive Gauss-Kronrod in double
// precision with the kinks as breakpoints. Ground truth for the gather pass
// (issue 11), used only for measuring.
#pragma once

#include <functional>
#include <vector>

namespace st::reference {

// R(r) (or T(r)): light leaving per unit area at distance r (mm) from a unit
// power entering, per mm^2; finite at r = 0.
using RadialProfile = std::function<double(double r)>;

// Integration settings: the profile is taken as 0 beyond r_max (choose it
// where the profile's tail is negligible: the dipole's falls as
// exp(-sigma_tr r) / r^2), and each piece is refined until its error
// estimate is under `tolerance` times the whole's.
struct ConvolutionSettings {
    double r_max = 100.0;  // mm
    double tolerance = 1e-12;
    // Radii where the profile itself is kinked (a tabulated profile read
    // linearly), sorted: the integral breaks there too. Without them the
    // adaptive rule bisects towards every kink until its error estimate
    // allows, thousands of pieces for a 400-bin histogram.
    std::vector<double> knots;
};

// Unit irradiance on the half-plane on one side of a straight edge; the
// point at signed distance d from the edge (d > 0: on the lit side). d -> inf
// gives the profile's total; d = 0 exactly half of it.
double convolve_half_plane(const RadialProfile& profile, double d, const ConvolutionSettings& s = {});

// Unit irradiance on a disk of radius a (a spot); the point at distance rho
// from its centre.
double convolve_disk(const RadialProfile& profile, double a, double rho, const ConvolutionSettings& s = {});

// The profile's total over the plane, integral of R(r) 2 pi r dr to r_max.
double profile_total(const RadialProfile& profile, const ConvolutionSettings& s = {});

}  // namespace st::reference
