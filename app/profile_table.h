// profile_table.h: the radial R(r) and T(r) tables `profile` writes, in one
// layout whatever computed them (multipole, layered stack, Monte Carlo), so
// that rendering reads one format.
//
// CSV: a header, then one row per radius: r_mm, R, T for one channel, or
// r_mm, R_r, R_g, R_b, T_r, T_g, T_b for three.
// EXR: width = number of radii, height 2; row 0 holds R(r) in RGB, row 1
// T(r), alpha = r in mm. A one-channel table repeats its value in R, G, B.
// Values are per mm^2 (a radial density: R_total = integral of R(r) 2 pi r dr).
#pragma once

#include <string>
#include <vector>

#include "image/image_io.h"

namespace st {

struct ProfileTable {
    std::vector<double> radii;                 // mm
    std::vector<std::vector<double>> R, T;     // [channel][radius], 1 or 3 channels
    Metadata metadata;                         // EXR attributes
};

// Throws InputError unless `path` ends in .csv or .exr; call before the work.
void check_profile_path(const std::string& path);
// Writes CSV or EXR by the name's ending, through a temporary file.
void write_profile_table(const std::string& path, const ProfileTable& table);

}  // namespace st
