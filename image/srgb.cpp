// srgb.cpp: see srgb.h.
#include "image/srgb.h"

#include <cmath>

namespace st {

double srgb_to_linear(double encoded) {
    if (!(encoded > 0.0)) return 0.0;  // NaN and below
    if (encoded >= 1.0) return 1.0;
    return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

}  // namespace st
