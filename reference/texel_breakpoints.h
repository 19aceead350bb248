// texel_breakpoints.h: where a ray's texture coordinate crosses cell edges,
// shared by the exact relief crossings (relief_intersection.cpp,
// relief_sampled_crossing.cpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "reference/relief_intersection.h"

namespace st::reference::breakpoints {

// REPEAT has period 1 in u and v on every level, so reducing the coordinate
// first changes nothing but keeps x = u*w - 0.5 small and accurate.
inline double reduce(double u) { return u - std::floor(u); }

// A proper non-negative modulo of an integer-valued double: plain % on a
// negative cell index would pick the wrong texel.
inline int wrap_index(double i, int n) {
    double r = std::fmod(i, double(n));
    if (r < 0) r += n;
    return int(r);
}

// Appends the t in (0, 1) where x(t) = x0 + t sx crosses an integer, and
// takes their count from `budget`; throws RayTooLong (naming `who`) once
// the budget is spent.
inline void add_integer_crossings(std::vector<double>& ts, double& budget, double x0, double sx, const char* who) {
    if (sx == 0) return;
    const double lo = std::min(x0, x0 + sx), hi = std::max(x0, x0 + sx);
    const double count = std::floor(hi) - std::ceil(lo) + 1;
    budget -= std::max(count, 0.0);
    if (!std::isfinite(sx) || !(budget >= 0))
        throw RayTooLong(std::string(who) + ": the ray crosses more than 1e7 texel boundaries");
    for (double k = std::ceil(lo); k <= hi; ++k) {
        const double t = (k - x0) / sx;
        if (t > 0 && t < 1) ts.push_back(t);
    }
}

}  // namespace st::reference::breakpoints
