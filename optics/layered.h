// layered.h: layers combined in frequency space (Donner and Jensen 2005,
// Sec. 2.3, Eq. 17-22): each layer's multipole profiles R(r), T(r), for the
// incident beam and for diffuse light from above and from below, are laid
// on a zero-padded Cartesian grid (optics/fft_grid.h), Fourier transformed,
// combined per frequency with Kubelka-Munk's formulas (two fluxes: the
// collimated beam and diffuse light; layered.cpp), and transformed back to
// radial profiles.
#pragma once

#include <array>
#include <vector>

namespace st::optics {

struct LayerSpec {
    std::array<double, 3> sigma_a{}, sigma_s{};  // per mm, for R, G, B
    double g = 0;
    double eta = 1;  // index relative to the medium above (the layer above, or air)
    double thickness = 1;  // mm, may be infinite for the last layer
    double roughness = 0;  // RMS slope of the layer's top surface (Beckmann); 0 = smooth
};

struct LayeredOptions {
    int grid = 256;          // N x N cells, a power of two
    double extent = 0;       // mm across the grid; 0: from how far the layers' profiles reach (layered.cpp)
    bool kubelka_munk = true;  // false: the first term of Eq. 20 only (Table 2's no-KM column)
    double tolerance = 1e-6;   // for each layer's multipole
};

struct ChannelResult {
    double R = 0, T = 0, T_direct = 0;
    std::vector<double> R_profile, T_profile;  // per mm^2 at `radii`
    // The most light (per unit of light entering a layer) that any layer's
    // profile carried beyond the kernels' reach, a quarter of the grid, and
    // that the normalisation folded back inside: the profiles are that much
    // too high inside and cut off beyond. Raise --extent (and --grid) if it
    // matters.
    double profile_cut = 0;
};

struct LayeredResult {
    std::array<ChannelResult, 3> channel;
    std::vector<double> radii;  // mm, b * cell for b < grid / 2 (kernels reach grid / 4: see profile_cut)
    double cell = 0;            // mm
    std::vector<int> dipoles;   // per layer, most over the channels
};

LayeredResult combine_layers(const std::vector<LayerSpec>& layers, const LayeredOptions& options);

}  // namespace st::optics
