// diffuse_fresnel.h: Fresnel reflectance of a smooth dielectric boundary,
// exact and averaged over diffuse light, and the boundary factor A of
// diffusion theory (Donner and Jensen 2005, Eq. 7-8, after Egan et al. 1973).
#pragma once

namespace st::optics {

// Exact unpolarised Fresnel reflectance at incidence cosine c for relative
// index eta, the index of the far side over the near side (total internal
// reflection gives 1).
double fresnel_dielectric(double c, double eta);

// Its value at normal incidence, ((eta - 1) / (eta + 1))^2, the same from
// either side.
double fresnel_normal(double eta);

// F_dr(eta): the reflectance of the boundary for diffuse light inside a
// medium whose index relative to the outside is eta, the average of
// fresnel_dielectric(c, 1 / eta) weighted by 2 c dc. Eq. 8's fit where it is
// good to 7e-4 (0.5 <= eta <= 2); outside, the fit leaves [0, 1] (F_dr >= 1
// at eta 3.9, so A turns negative) and the integral is taken instead.
double diffuse_fresnel_reflectance(double eta);

// A = (1 + F_dr) / (1 - F_dr), Eq. 7.
double boundary_factor(double eta);

}  // namespace st::optics
