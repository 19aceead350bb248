// fixed_point.h: the 8-sub-pixel-bit grid that llvmpipe snaps vertices to.
#pragma once

#include <cmath>
#include <cstdint>

namespace st {

inline constexpr int kSubpixelBits = 8;  // GL_SUBPIXEL_BITS on llvmpipe
inline constexpr int kFixedOne = 1 << kSubpixelBits;

// Window coordinate -> fixed point, pixel centres at integer multiples of
// kFixedOne. The half-pixel offset is subtracted in float first (one
// rounding), the product with 256 is exact, and the snap rounds half to
// even (lrintf in the default rounding mode), as lp_setup_tri.c does.
inline int64_t snap_to_subpixel(float window_coord) {
    const float centred = window_coord - 0.5f;
    return int64_t(std::nearbyint(double(centred) * kFixedOne));
}

}  // namespace st
