// profile_table.cpp: see profile_table.h.
#include "optics/profile_table.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace st::optics {

ProfileTable::ProfileTable(const std::function<double(double)>& reflectance,
                           const std::function<double(double)>& transmittance, double r_max, int size)
    : r_max_(r_max) {
    if (size < 2 || size > 65536) throw std::invalid_argument("profile table: size " + std::to_string(size) + " outside 2..65536");
    if (!(r_max > 0) || !std::isfinite(r_max)) throw std::invalid_argument("profile table: r_max must be positive and finite");
    r_.resize(size_t(size));
    texels_.resize(size_t(size) * 4);
    for (int i = 0; i < size; ++i) {
        const double u = double(i) / double(size - 1);
        const double r = r_max * u * u;
        const double values[2] = {reflectance(r), transmittance(r)};
        for (double v : values)
            if (!std::isfinite(v) || v < 0)
                throw std::invalid_argument("profile table: a profile is negative or not finite at r = " + std::to_string(r));
        r_[size_t(i)] = r;
        texels_[4 * size_t(i) + 0] = float(values[0]);
        texels_[4 * size_t(i) + 1] = float(values[1]);
        texels_[4 * size_t(i) + 2] = 0.0f;
        texels_[4 * size_t(i) + 3] = 1.0f;
    }
}

double ProfileTable::lookup(double r, int channel) const {
    if (!(r >= 0) || r > r_max_) return 0.0;
    const double x = std::sqrt(r / r_max_) * double(size() - 1);
    const int i = std::min(int(x), size() - 2);
    const double t = x - double(i);
    const double a = texels_[4 * size_t(i) + size_t(channel)], b = texels_[4 * size_t(i + 1) + size_t(channel)];
    return a + t * (b - a);
}

}  // namespace st::optics
