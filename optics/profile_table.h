// profile_table.h: a material's reflectance and transmittance profiles R(r)
// and T(r) tabulated for a texture lookup by distance, as the gather pass of
// diffusion-profile rendering reads them (Donner and Jensen 2005, Sec. 3 and
// Eq. 27; issue 11). Entry i holds the profiles at r_i = r_max u_i^2, u_i =
// i / (size - 1): dense near 0, where the profiles are steep, and a shader
// finds its entry from u = sqrt(r / r_max) (texture coordinate
// u (size - 1) / size + 0.5 / size, so that u = 0 and 1 land on the first and
// last texel centres). Built once per material and cached by the caller.
#pragma once

#include <functional>
#include <vector>

namespace st::optics {

class ProfileTable {
public:
    // Throws std::invalid_argument for size < 2 or beyond 65536, r_max not
    // positive and finite, or a profile value that is negative or not finite.
    ProfileTable(const std::function<double(double)>& reflectance, const std::function<double(double)>& transmittance,
                 double r_max, int size);

    int size() const { return int(r_.size()); }
    double r_max() const { return r_max_; }
    double radius(int i) const { return r_[size_t(i)]; }
    // RGBA texels, one per entry: (R, T, 0, 1), per mm^2, as floats.
    const std::vector<float>& texels() const { return texels_; }
    // What a LINEAR lookup of the table returns at distance r (interpolated
    // linearly in u between the stored floats; 0 beyond r_max), in double:
    // the table's own error against the profile, for its tests and the docs.
    double reflectance(double r) const { return lookup(r, 0); }
    double transmittance(double r) const { return lookup(r, 1); }

private:
    double lookup(double r, int channel) const;
    double r_max_ = 0;
    std::vector<double> r_;
    std::vector<float> texels_;
};

}  // namespace st::optics
