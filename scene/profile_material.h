// profile_material.h: a diffusion-profile scene's material, turned into what
// its passes read (Donner and Jensen Sec. 3): the R(r) and T(r) tables per
// channel (optics/profile_table.h), the sample pattern of the gather
// (optics/radial_sampler.h), the boundary's rho_dt table of a rough
// surface (Eq. 26). Profiles come from the optics the `slab` and `profile`
// commands use: the dipole and the multipole of one slab, the layered
// stack combined in frequency space, or Monte Carlo photon tracing. They are
// built once per material and process (and the slow ones, layered and
// Monte Carlo, kept on disk between processes: profile_cache.h), with the
// build time kept apart from any frame's.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "frame/frame.h"
#include "optics/layered.h"
#include "scene/json_reader.h"

namespace st {

inline constexpr int kDefaultMaxDipolePairs = 1000;

struct ProfileMaterial {
    std::string model;                       // "dipole", "multipole", "layered", "mc"
    std::vector<optics::LayerSpec> layers;   // top first; one for a single slab
    long long photons = 200000;              // mc, per channel
    uint64_t seed = 1;                       // mc
    double mc_r_max = 20;                    // mm, mc: the radial bins' reach
    // multipole: the most dipole pairs per side the profile may take to
    // converge (the paper used 1000); a slab that needs more is refused.
    int max_dipole_pairs = kDefaultMaxDipolePairs;
    std::string max_pairs_field = "material.max_dipole_pairs";  // for the refusal
    bool thin() const;  // the last layer is finite: light crosses to the other face
    double eta() const { return layers.front().eta; }          // of the top boundary
    double roughness() const { return layers.front().roughness; }
    double thickness() const;                                  // mm, all layers; infinite unless thin
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
    int dipoles = 0;               // per channel, most over the channels and layers
    // Wall time of building the profiles in this process (0 when an earlier
    // scene had built them) and where they came from: "built", "disk"
    // (profile_cache.h) or "memory".
    double build_ms = 0;
    std::string source;
    // The profiles themselves, per mm^2 in double (channel R, G, B), for
    // the ground truth and the tables' own error.
    std::array<std::function<double(double)>, 3> R, T;
    // The radii where R and T are kinked (a tabulated profile's, read
    // linearly between them), sorted; empty for the analytic models. An
    // integral of a profile converges fast only if it breaks there.
    std::vector<double> knots;
};

std::shared_ptr<const BuiltProfiles> build_profiles(const ProfileMaterial& m, const GatherSettings& g);

// Every build_profiles call of this process so far, for the tools that
// report build time apart from frame time: a line naming the material's
// model, its source and its time.
std::vector<std::string> profile_build_log();

}  // namespace st
