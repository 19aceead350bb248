// median.h: the median every timing table and statistic in app/ reports
// (the mean of the two middle values for an even count), defined once so
// that two tables of the same frames agree.
#pragma once

#include <algorithm>
#include <vector>

namespace st {

inline double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace st
