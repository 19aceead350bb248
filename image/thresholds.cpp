// thresholds.cpp: see thresholds.h. Counted here rather than by
// ImageBufAlgo::compare, which idiff uses: compare lets a NaN through every
// threshold (NaN > x is false), and a harness must not.
#include "image/thresholds.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>


namespace st {

const char* verdict_name(Verdict v) {
    switch (v) {
        case Verdict::Pass: return "pass";
        case Verdict::Warn: return "warn";
        case Verdict::Fail: return "fail";
    }
    return "?";
}

ThresholdResult compare_thresholds(const Image& a, const Image& b, const Thresholds& t) {
    if (a.width != b.width || a.height != b.height) throw std::invalid_argument("images differ in size");
    ThresholdResult out;
    const size_t pixels = size_t(a.width) * size_t(a.height);
    for (size_t p = 0; p < pixels; ++p) {
        double pixel_error = 0;
        for (int c = 0; c < 4; ++c) {
            const float u = a.rgba[p * 4 + size_t(c)], v = b.rgba[p * 4 + size_t(c)];
            // A non-finite value is an infinite error unless the other side
            // holds the same (NaN and NaN, or the same infinity).
            double e = std::fabs(double(u) - double(v));
            if (!std::isfinite(u) || !std::isfinite(v)) e = (std::isnan(u) ? std::isnan(v) : u == v) ? 0.0 : INFINITY;
            if (e > out.max_error) {
                out.max_error = e;
                out.max_x = int(p % size_t(a.width));
                out.max_y = int(p / size_t(a.width));
                out.max_channel = c;
            }
            pixel_error = std::max(pixel_error, e);
        }
        out.failing += pixel_error > t.fail;
        out.warning += pixel_error > t.warn;
    }
    const auto over = [&](long count, double percent) { return pixels > 0 && 100.0 * double(count) / double(pixels) > percent; };
    if (over(out.failing, t.fail_percent) || out.max_error > t.hard_fail) out.verdict = Verdict::Fail;
    else if (over(out.warning, t.warn_percent) || out.max_error > t.hard_warn) out.verdict = Verdict::Warn;
    return out;
}

}  // namespace st
