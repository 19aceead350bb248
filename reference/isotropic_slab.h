// isotropic_slab.h: the exact diffuse reflectance and transmittance of a
// plane-parallel, index-matched slab with isotropic scattering, lit by a
// collimated beam: the ground truth that the thin-slab model's single
// scattering (Frisvad et al. Eq. 4-5) is judged against.
//
// Method: the source function S(tau) solves S = S0 + (Lambda/2) Int E1(|tau -
// t|) S(t) dt with S0 the once-scattered beam (Chandrasekhar, Radiative
// Transfer, ch. I); S is piecewise constant on a fine grid of optical depth,
// each cell's kernel integrated exactly with E2, the system solved by
// iteration, and the escaping flux integrated exactly with E3. Double
// precision; a Richardson step on two grids removes the leading error.
#pragma once

namespace st {

struct SlabFluxes {
    double reflectance = 0;    // diffuse, fraction of the incident flux
    double transmittance = 0;  // diffuse, excluding the direct beam
    double direct = 0;         // unscattered transmission e^(-tau1/mu0)
};

// Exact (all orders of scattering).
SlabFluxes isotropic_slab_exact(double tau1, double albedo, double mu0);
// First order of scattering only, by the same quadrature: what Eq. 4-5 model.
SlabFluxes isotropic_slab_single(double tau1, double albedo, double mu0);

// Exponential integrals E1, E2, E3 for x >= 0 (E1(0) = +inf).
double expint_e1(double x);
double expint_e2(double x);
double expint_e3(double x);

}  // namespace st
