// profile_material.h: a diffusion-profile scene's material, turned into what
// its passes read (Donner and Jensen Sec. 3): the R(r) and T(r) tables per
// channel (optics/profile_table.h), the sample pattern of the gather
// (optics/radial_sampler.h), the boundary's rho_dt table of a rough
// surface (Eq. 26). Profiles are built once per material and kept for the
// process, keyed by everything they depend on; the build time is kept with
// them, apart from any frame's time.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "frame/frame.h"
#include "scene/json_reader.h"

namespace st {

struct ProfileMaterial {
    std::string model;   // "dipole", "multipole"
    std::array<double, 3> sigma_a{}, sigma_s{};  // per mm, R G B
    double g = 0, eta = 1.3, thickness = 0;      // thickness 0: semi-infinite
    double roughness = 0;                        // RMS slope; 0: smooth
    bool thin() const { return thickness > 0; }
};

// Reads the scene's "material" object; InputError names a bad field.
ProfileMaterial read_profile_material(JsonReader& material);

struct GatherSettings {
    std::string pattern = "importance";  // or "disk"
    int samples = 64;
    int table_size = 256;
    double tail_fraction = 1e-3;  // share of the profile the reach may leave out
};
inline constexpr int kMaxGatherSamples = 4096;

// The host side of one material: textures and the numbers the shaders need.
struct BuiltProfiles {
    Texture profile_R, profile_T;  // RGBA32F table_size x 1: (R_r, R_g, R_b, 1), (T_r, T_g, T_b, 1)
    Texture pattern;               // RGBA32F samples x 1: (dx mm, dy mm, area mm^2, 0)
    Texture rho_dt;                // RGBA32F n x 1, rho_dt at cos (i + 0.5) / n (1x1 of 1 when smooth)
    double r_max = 0;              // mm, the tables' last radius and the pattern's reach
    std::array<double, 3> total_R{}, total_T{};  // the profiles' integrals over the plane
    int dipoles = 0;               // per channel, most over the channels
    double build_ms = 0;           // wall time of the first build (0 when the cache had it)
    // The profiles themselves, per mm^2 in double (channel R, G, B), for
    // the ground truth and the tables' own error.
    std::array<std::function<double(double)>, 3> R, T;
};

std::shared_ptr<const BuiltProfiles> build_profiles(const ProfileMaterial& m, const GatherSettings& g);

}  // namespace st
