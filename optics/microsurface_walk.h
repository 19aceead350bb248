// microsurface_walk.h: a rough dielectric interface that conserves energy,
// for the Monte Carlo tracer. Light meets a Beckmann microsurface of RMS
// slope m and may bounce on it several times, on either side, before it
// leaves: a random walk on the microsurface with Smith's uncorrelated height
// model (Heitz, Hanika, d'Eon and Dachsbacher 2016, "Multiple-scattering
// microfacet BSDFs with the Smith model"), with visible-normal sampling and
// the exact Fresnel choice at each facet. Its first bounce is the
// Torrance-Sparrow surface of Eq. 23 (up to the Smith rather than the
// V-groove shadowing term); where that single-bounce model shadows light and
// loses it, the walk carries it on, so nothing is lost.
#pragma once

#include <cstdint>

#include "optics/photon_rng.h"

namespace st::optics {

enum class InterfaceOutcome { Reflected, Transmitted, Lost };

// A photon travelling along (ux, uy, uz) (unit, uz != 0; the tracer's
// frame) meets a horizontal interface from a medium of index n1 into one of
// index n2. Replaces the direction with the one it leaves the surface in.
// `Lost` only when the walk exceeds a few hundred bounces (not seen in
// practice); the photon should then be dropped.
InterfaceOutcome microsurface_walk(double m, double n1, double n2, double& ux, double& uy, double& uz,
                                   PhotonRng& rng);

// The share of diffuse (cosine-distributed) light from inside a medium of
// relative index eta that the walk reflects back in: the rho_d of Eq. 24 the
// surface really has.
double walk_internal_reflectance(double m, double eta, uint64_t photons, uint64_t seed = 1);

// Beckmann's Smith Lambda for a direction with cosine `cos_theta` to the
// mean normal (negative: pointing into the surface), RMS slope m.
double beckmann_lambda(double cos_theta, double m);

}  // namespace st::optics
