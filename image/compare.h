// compare.h: the equivalence metrics between a CPU image and a GL image.
#pragma once

#include <cstdint>
#include <vector>

#include "image/image.h"

namespace st {

struct CompareMetrics {
    int width = 0, height = 0;
    double identical_fraction_8bit = 0;   // pixels whose four unorm8 channels are equal
    int max_diff_8bit = 0;                // LSB, over all channels
    double identical_fraction_float = 0;  // pixels whose four floats are bit-identical
    double max_rel_diff_float = 0;        // max |a - b| / max(|b|, 1e-3)
    // From OpenImageIO's ImageBufAlgo::compare, on the float images.
    double max_abs_diff = 0, mean_abs_diff = 0, rms_error = 0, psnr = 0;
    long nonfinite_a = 0, nonfinite_b = 0;  // NaN or infinite channels
    long nonfinite_mismatch = 0;            // non-finite on a side, bits differ
    // Channels NaN on both sides whose bits differ (payload or sign): where
    // two NaNs meet in one operation, which one comes out is the operand
    // order the compiler emitted (docs/llvmpipe/glsl-builtins.md 0.3).
    long nan_payload_only = 0;
    // identical_fraction_float and max_rel_diff_float with a NaN matching
    // any NaN (for criteria.nonfinite "nan_any_payload").
    double identical_fraction_float_any_nan = 0;
    double max_rel_diff_float_any_nan = 0;
};

// `b` is the reference (GL) in max_rel_diff_float. Sizes must match
// (std::invalid_argument otherwise).
CompareMetrics compare_images(const Image& a, const Image& b);

// Pixels whose fragment counts differ between two coverage images
// (frame/frame.h coverage_frame): covered on one side only, or a different
// number of times.
long coverage_mismatch(const Image& a, const Image& b);

// Per pixel (rows top to bottom), 1 where some channel's unorm8 value
// differs by more than 1 LSB between a and b (or one is non-finite).
std::vector<uint8_t> over_1lsb(const Image& a, const Image& b);

// RGB heat map of the per-pixel difference, rows top to bottom:
// black = bit-identical floats, dark blue = floats differ but 8-bit equal,
// green = 1 LSB, yellow = 2-3 LSB, red = 4 LSB or more, white = non-finite.
std::vector<uint8_t> heat_map(const Image& a, const Image& b);

}  // namespace st
