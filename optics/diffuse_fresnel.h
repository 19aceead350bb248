// diffuse_fresnel.h: the diffuse Fresnel reflectance fit and the boundary
// factor A of diffusion theory (Donner and Jensen 2005, Eq. 7-8, after Egan
// et al. 1973).
#pragma once

namespace st::optics {

// F_dr(eta), Eq. 8: eta is the index of the scattering medium relative to the
// medium outside (the boundary's "ratio of indices of refraction").
double diffuse_fresnel_reflectance(double eta);

// A = (1 + F_dr) / (1 - F_dr), Eq. 7.
double boundary_factor(double eta);

}  // namespace st::optics
