// monte_carlo.h: a photon tracer for layered slabs in the manner of MCML
// (Wang, Jacques and Zheng 1995): photon packets with weights, steps drawn
// from the extinction, absorption by weight, Henyey-Greenstein scattering,
// Fresnel reflection or refraction at every interface, Russian roulette, and
// radial bins of the light leaving the top and the bottom. It is the ground
// truth the diffusion models are judged against.
//
// Deterministic: photons are traced in fixed chunks, each with its own random
// stream (photon_rng.h), and chunk results are summed in chunk order, so the
// result depends on the seed and the photon count only, not on threads.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

namespace st::optics {

struct McLayer {
    double sigma_a = 0, sigma_s = 0, g = 0;  // per mm
    double n = 1;                            // absolute refractive index
    double thickness = 0;                    // mm; infinite allowed for the last layer
};

struct McSetup {
    std::vector<McLayer> layers;  // top first
    double n_above = 1, n_below = 1;
    // RMS slope of a rough top surface (Beckmann facets, as optics/
    // rough_surface.h); 0 = smooth. The other interfaces are smooth.
    double top_roughness = 0;
    // How the rough top scatters: by a walk on the microsurface that carries
    // on the light its facets shadow (optics/microsurface_walk.h, energy
    // conserving), or, when false, by the single bounce of Eq. 23's
    // Torrance-Sparrow surface, which loses that light.
    bool top_multiple_scattering = true;
    uint64_t photons = 100000;
    uint64_t seed = 1;
    int threads = 2;
    double bin_width = 0.01;  // mm, radial bins of R(r) and T(r)
    int bins = 200;
    // Called now and then from the calling thread with the fraction done.
    std::function<void(double)> progress;
};

struct McResult {
    double specular = 0;               // reflected at the top surface on entry (sampled when rough)
    double R = 0, T = 0, T_direct = 0; // diffuse reflectance, diffuse and unscattered transmittance
    double absorbed = 0;
    double R_stderr = 0, T_stderr = 0; // standard errors of R and T, from each photon's score
    std::vector<double> R_profile, T_profile;  // per mm^2, at bin centres
    std::vector<double> bin_centres;           // mm, MCML's r_b = [(i + 1/2) + 1/(12 (i + 1/2))] dr
};

McResult trace_photons(const McSetup& setup);

}  // namespace st::optics
