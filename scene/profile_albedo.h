// profile_albedo.h: texturing a translucent material (Donner and Jensen
// Sec. 3.1): an albedo map, convolved on the host with the material's
// profile (R, plus T for thin geometry), "so that the color of the diffusion
// process is used, rather than the texture color" normalised to a white mean,
// and bound as the gather's `albedo`, which scales the diffused light.
// The convolution runs over the shape's exact surface (profile_shape.h,
// profile_albedo_gather.h): each texel gathers the texels within the
// profile's reach in world distance, weighted by the profile and each
// texel's area, the weights normalised per texel (so the layout's seams and
// borders lose nothing).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>

#include "frame/frame.h"
#include "scene/json_reader.h"
#include "scene/profile_material.h"
#include "scene/profile_shape.h"

namespace st {

struct AlbedoMap {
    std::string pattern;             // "" (white, no texture) or "freckles"
    int count = 400;                 // freckles: how many
    double radius_mm = 1.5;          // their Gaussian radius
    std::array<double, 3> strength{0.35, 0.5, 0.6};  // how much of each channel a freckle's centre takes away
    uint64_t seed = 1;
    bool textured() const { return !pattern.empty(); }
};

// Reads the scene's "albedo" object (absent: white); InputError names a bad field.
AlbedoMap read_albedo_map(JsonReader& albedo);

// The convolution's budget, in neighbour terms (profile_albedo_gather.h):
// about five seconds of one core. Above it the convolution runs on the
// largest coarser layout within it, from the map averaged over each coarse
// texel, and is read back bilinearly. The built-in textured head (512
// texels, about 3,000 neighbours each: 8e8 terms) stays below it.
inline constexpr double kAlbedoGatherBudget = 1.5e9;

// The sampler "albedo": 1x1 white without a map, else the convolved and
// normalised map at `size` x `size` (RGBA32F, bilinear; u repeats on an
// ellipsoid, whose layout wraps there).
Texture albedo_texture(const AlbedoMap& map, const ProfileShape& shape, const BuiltProfiles& profiles, bool thin,
                       int size, double gather_budget = kAlbedoGatherBudget);

// albedo_texture() for a scene: the textures of the last few loads are
// kept (64 MB at most), so a scene loaded again with the same map, shape,
// profiles and size (explore's cases of one base scene, a bench's reloads)
// does not convolve again. The profiles are known by their object:
// build_profiles() hands out one per material and process.
Texture scene_albedo_texture(const AlbedoMap& map, const ProfileShape& shape,
                             const std::shared_ptr<const BuiltProfiles>& profiles, bool thin, int size);

}  // namespace st
