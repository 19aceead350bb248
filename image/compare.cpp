// compare.cpp: per-pixel equivalence metrics and the heat map.
#include "image/compare.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "image/error_stats.h"
#include "image/unorm8.h"

namespace st {

namespace {

void check_sizes(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height)
        throw std::invalid_argument("images differ in size: " + std::to_string(a.width) + "x" +
                                    std::to_string(a.height) + " and " + std::to_string(b.width) +
                                    "x" + std::to_string(b.height));
}

int diff_8bit(float a, float b) { return std::abs(int(to_unorm8(a)) - int(to_unorm8(b))); }

}  // namespace

CompareMetrics compare_images(const Image& a, const Image& b) {
    check_sizes(a, b);
    CompareMetrics m;
    m.width = a.width;
    m.height = a.height;
    const size_t pixels = size_t(a.width) * a.height;
    size_t same8 = 0, same_float = 0, same_float_any_nan = 0;
    for (size_t p = 0; p < pixels; ++p) {
        bool pixel_same8 = true, pixel_same_float = true, pixel_same_any_nan = true;
        for (int c = 0; c < 4; ++c) {
            const float va = a.rgba[p * 4 + c], vb = b.rgba[p * 4 + c];
            if (!std::isfinite(va)) ++m.nonfinite_a;
            if (!std::isfinite(vb)) ++m.nonfinite_b;
            const bool same_bits = std::bit_cast<uint32_t>(va) == std::bit_cast<uint32_t>(vb);
            const bool both_nan = std::isnan(va) && std::isnan(vb);
            if (!same_bits && !(std::isfinite(va) && std::isfinite(vb))) ++m.nonfinite_mismatch;
            if (!same_bits && both_nan) ++m.nan_payload_only;
            const int d8 = diff_8bit(va, vb);
            m.max_diff_8bit = std::max(m.max_diff_8bit, d8);
            pixel_same8 &= d8 == 0;
            pixel_same_float &= same_bits;
            pixel_same_any_nan &= same_bits || both_nan;
            if (same_bits) continue;  // no difference, even for inf and NaN
            const double rel = std::abs(double(va) - double(vb)) / std::max(std::abs(double(vb)), 1e-3);
            // A NaN on either side makes the relative difference infinite.
            const double r = std::isnan(rel) ? INFINITY : rel;
            m.max_rel_diff_float = std::max(m.max_rel_diff_float, r);
            if (!both_nan) m.max_rel_diff_float_any_nan = std::max(m.max_rel_diff_float_any_nan, r);
        }
        same8 += pixel_same8;
        same_float += pixel_same_float;
        same_float_any_nan += pixel_same_any_nan;
    }
    m.identical_fraction_8bit = pixels ? double(same8) / pixels : 1.0;
    m.identical_fraction_float = pixels ? double(same_float) / pixels : 1.0;
    m.identical_fraction_float_any_nan = pixels ? double(same_float_any_nan) / pixels : 1.0;

    const ImageErrorStats r = error_stats(a.rgba.data(), b.rgba.data(), a.width, a.height);
    m.max_abs_diff = r.max_error;
    m.mean_abs_diff = r.mean_error;
    m.rms_error = r.rms_error;
    m.psnr = r.psnr;
    return m;
}

long coverage_mismatch(const Image& a, const Image& b) {
    check_sizes(a, b);
    long mismatch = 0;
    const size_t pixels = size_t(a.width) * a.height;
    // Each pixel holds its fragment count (coverage_frame): any difference,
    // in presence or in multiplicity, is a mismatch.
    for (size_t p = 0; p < pixels; ++p) {
        const float* u = &a.rgba[p * 4];
        const float* v = &b.rgba[p * 4];
        mismatch += !(u[0] == v[0] && u[1] == v[1] && u[2] == v[2] && u[3] == v[3]);
    }
    return mismatch;
}

std::vector<uint8_t> over_1lsb(const Image& a, const Image& b) {
    check_sizes(a, b);
    const size_t pixels = size_t(a.width) * a.height;
    std::vector<uint8_t> mask(pixels, 0);
    for (size_t p = 0; p < pixels; ++p)
        for (int c = 0; c < 4; ++c) {
            const float va = a.rgba[p * 4 + c], vb = b.rgba[p * 4 + c];
            const bool same_bits = std::bit_cast<uint32_t>(va) == std::bit_cast<uint32_t>(vb);
            if (diff_8bit(va, vb) > 1 || (!same_bits && !(std::isfinite(va) && std::isfinite(vb)))) mask[p] = 1;
        }
    return mask;
}

std::vector<uint8_t> heat_map(const Image& a, const Image& b) {
    check_sizes(a, b);
    const size_t pixels = size_t(a.width) * a.height;
    std::vector<uint8_t> rgb(pixels * 3, 0);
    for (size_t p = 0; p < pixels; ++p) {
        int d8 = 0;
        bool same_float = true, finite = true;
        for (int c = 0; c < 4; ++c) {
            const float va = a.rgba[p * 4 + c], vb = b.rgba[p * 4 + c];
            finite &= std::isfinite(va) && std::isfinite(vb);
            same_float &= std::bit_cast<uint32_t>(va) == std::bit_cast<uint32_t>(vb);
            d8 = std::max(d8, diff_8bit(va, vb));
        }
        uint8_t* out = &rgb[p * 3];
        auto set = [out](uint8_t r, uint8_t g, uint8_t bl) { out[0] = r; out[1] = g; out[2] = bl; };
        if (!finite) set(255, 255, 255);
        else if (same_float) set(0, 0, 0);
        else if (d8 == 0) set(0, 0, 110);
        else if (d8 == 1) set(0, 200, 0);
        else if (d8 <= 3) set(230, 230, 0);
        else set(255, 0, 0);
    }
    return rgb;
}

}  // namespace st
