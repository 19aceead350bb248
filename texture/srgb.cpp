// srgb.cpp: see srgb.h.
#include "texture/srgb.h"

#include <cmath>

namespace st {

double srgb_to_linear(double encoded) {
    if (!(encoded > 0.0)) return 0.0;  // NaN and below
    if (encoded >= 1.0) return 1.0;
    return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

double linear_to_srgb(double linear) {
    if (!(linear > 0.0)) return 0.0;
    if (linear >= 1.0) return 1.0;
    return linear <= 0.0031308 ? linear * 12.92 : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

}  // namespace st
