// error_stats.cpp: see error_stats.h.
#include "image/error_stats.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace st {

ImageErrorStats error_stats(const float* a, const float* b, int width, int height) {
    const size_t pixels = size_t(width > 0 ? width : 0) * size_t(height > 0 ? height : 0);
    const size_t values = pixels * 4;
    constexpr size_t kBatch = 4096;  // pixels summed apart before joining the total
    double total = 0, total_sq = 0, max_error = 0;
    float peak = 1.0f;
    for (size_t start = 0; start < pixels; start += kBatch) {
        double batch = 0, batch_sq = 0;
        for (size_t i = start * 4; i < std::min(pixels, start + kBatch) * 4; ++i) {
            const float x = a[i], y = b[i];
            if (!std::isfinite(x) || !std::isfinite(y)) {
                if (std::isnan(x) == std::isnan(y) && std::isinf(x) == std::isinf(y)) continue;
                if (std::isfinite(max_error)) {
                    max_error = std::numeric_limits<double>::infinity();
                    continue;
                }
            }
            peak = std::max(peak, std::max(std::abs(x), std::abs(y)));
            const double d = std::abs(x - y);  // in float, then widened
            batch += d;
            batch_sq += d * d;
            if (!(d <= max_error)) max_error = d;
        }
        total += batch;
        total_sq += batch_sq;
    }
    ImageErrorStats s;
    s.max_error = max_error;
    s.mean_error = total / double(values);
    s.rms_error = std::sqrt(total_sq / double(values));
    s.psnr = 20.0 * std::log10(double(peak) / s.rms_error);
    return s;
}

}  // namespace st
