// slab.h: one homogeneous scattering layer, in the terms of Donner and Jensen
// 2005 (Sec. 2): coefficients per mm, thickness in mm (infinite for a
// semi-infinite medium), and the index of the layer relative to the media
// above and below it.
#pragma once

#include <cmath>
#include <limits>

namespace st::optics {

struct Slab {
    double sigma_a = 0;     // absorption coefficient, 1/mm
    double sigma_s = 0;     // scattering coefficient, 1/mm
    double g = 0;           // Henyey-Greenstein mean cosine
    double eta = 1;         // index of the slab relative to the medium above
    double eta_below = 1;   // ... relative to the medium below
    double thickness = std::numeric_limits<double>::infinity();  // mm
    // A of the top boundary (Eq. 7 or, for a rough surface, Eq. 24); 0 means
    // "from eta by Eq. 8". Set by the caller once per material, because a
    // rough surface's rho_d is sampled.
    double boundary_factor_top = 0;
    double boundary_factor_bottom = 0;  // likewise, from eta_below

    bool semi_infinite() const { return std::isinf(thickness); }

    // Derived quantities of Sec. 2 (Eq. 3 and around it).
    double sigma_s_reduced() const { return sigma_s * (1.0 - g); }                 // sigma_s'
    double sigma_t_reduced() const { return sigma_a + sigma_s_reduced(); }         // sigma_t'
    double albedo_reduced() const { return sigma_s_reduced() / sigma_t_reduced(); } // alpha'
    double sigma_tr() const { return std::sqrt(3.0 * sigma_a * sigma_t_reduced()); }
    double diffusion_constant() const { return 1.0 / (3.0 * sigma_t_reduced()); }  // D
    double mean_free_path() const { return 1.0 / sigma_t_reduced(); }             // l, depth of the real source
    double sigma_t() const { return sigma_a + sigma_s; }
};

}  // namespace st::optics
