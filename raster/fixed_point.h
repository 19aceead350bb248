// fixed_point.h: the 8-sub-pixel-bit grid that llvmpipe snaps vertices to.
#pragma once

#include <cmath>
#include <cstdint>

namespace st {

inline constexpr int kSubpixelBits = 8;  // GL_SUBPIXEL_BITS on llvmpipe
inline constexpr int kFixedOne = 1 << kSubpixelBits;

// The window coordinates setup takes. Clipping at -w..w keeps every finite
// window position within the viewport (at most 16384 pixels from the
// origin); beyond this limit, or not finite (a vertex with clip w at or
// within a few ULP of 0, an edge through the clip-space origin), a position
// cannot be snapped: llvmpipe converts it to INT32_MIN and wraps its edge
// arithmetic, which we do not reproduce. Within it, every product of the
// edge functions fits in 64 bits with room to spare.
inline constexpr float kMaxWindowCoord = float(1 << 20);
inline bool snappable(float window_coord) { return std::fabs(window_coord) <= kMaxWindowCoord; }  // false for NaN

// Window coordinate -> fixed point (only for snappable() ones), pixel centres at integer multiples of
// kFixedOne. The half-pixel offset is subtracted in float first (one
// rounding), the product with 256 is exact, and the snap rounds half to
// even (lrintf in the default rounding mode), as lp_setup_tri.c does.
inline int64_t snap_to_subpixel(float window_coord) {
    const float centred = window_coord - 0.5f;
    return int64_t(std::nearbyint(double(centred) * kFixedOne));
}

}  // namespace st
