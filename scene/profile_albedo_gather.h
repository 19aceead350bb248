// profile_albedo_gather.h: the convolution inside the albedo map
// (profile_albedo.h, Donner and Jensen Sec. 3.1). A texture's texels lie on
// the shape's exact surface (a TexelLayout); each gathers the texels within
// the profile's reach in world distance, weighted by the profile and by the
// area each covers, the weights normalised per texel (so the layout's seams
// and borders lose nothing). Its cost is the number of neighbour terms it
// sums, gather_terms(), which grows as the texture's side to the fourth
// once the reach spans many texels; profile_albedo.cpp keeps it bounded.
#pragma once

#include <array>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/profile_material.h"
#include "scene/profile_shape.h"

namespace st {

// A size x size texture's texels on the shape's surface, row-major.
struct TexelLayout {
    int size = 0;
    bool wraps = false;          // u repeats (an ellipsoid's layout wraps there)
    std::vector<glm::dvec3> p;   // texel centres, mm
    std::vector<double> area;    // the area each texel covers, mm^2
};
TexelLayout texel_layout(const ProfileShape& shape, int size);

// The profile (R, plus T for thin geometry) per channel as a table in r
// (the profile's own interpolation is slow), and the radius that holds 99 %
// of each channel's weight: the blur needs the profile's body, not its far
// tail (the gather on screen keeps that).
struct ProfileTable {
    static constexpr int kSize = 1024;
    double reach = 0;      // the table's last radius, mm (the profiles' r_max)
    double reach99 = 0;    // mm
    std::array<std::vector<double>, 3> k;  // kSize + 1 values per channel
};
ProfileTable profile_table(const BuiltProfiles& profiles, bool thin);

// How many neighbour terms gather() sums over the layout.
double gather_terms(const TexelLayout& layout, double reach99);

// Per channel and texel: the weighted mean of `albedo` (channel-major, one
// value per texel of the layout) over the neighbours within reach99, or the
// texel's own value where nothing weighs. Rows run on `threads` threads;
// every texel's sums run in one fixed order, so the result does not depend
// on how many.
std::array<std::vector<double>, 3> gather(const TexelLayout& layout, const std::array<std::vector<double>, 3>& albedo,
                                          const ProfileTable& table, int threads);

}  // namespace st
