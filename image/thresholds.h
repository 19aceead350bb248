// thresholds.h: idiff's pass/warn/fail rule for two images (OpenImageIO's
// idiff, whose options `diff` takes): a pixel fails when a channel differs
// by more than `fail`, warns beyond `warn`; the comparison fails when more
// than `fail_percent` % of the pixels fail or any difference exceeds
// `hard_fail`, warns likewise, and otherwise passes.
#pragma once

#include <limits>

#include "image/image.h"

namespace st {

struct Thresholds {
    double fail = 1e-6, fail_percent = 0, hard_fail = std::numeric_limits<double>::infinity();
    double warn = 1e-6, warn_percent = 0, hard_warn = std::numeric_limits<double>::infinity();
};

enum class Verdict { Pass, Warn, Fail };
const char* verdict_name(Verdict v);

struct ThresholdResult {
    long failing = 0, warning = 0;  // pixels with a channel beyond fail / warn
    double max_error = 0;           // largest channel difference (infinite when a side is NaN or infinite)
    int max_x = 0, max_y = 0, max_channel = 0;
    Verdict verdict = Verdict::Pass;
};

// Sizes must match (std::invalid_argument otherwise).
ThresholdResult compare_thresholds(const Image& a, const Image& b, const Thresholds& t);

}  // namespace st
