// unorm8.h: float to 8-bit the way llvmpipe writes an RGBA8 target.
//
// Not floor(x*255 + 0.5): llvmpipe scales by 255/256 in float, adds 2^15 so
// that the float's ulp becomes 1/256, and keeps the low 8 mantissa bits;
// the addition rounds half to even. Measured: zero mismatches over all
// inputs tried (../shared/notes/llvmpipe.md, "Writing 8-bit colour").
#pragma once

#include <bit>
#include <cstdint>

namespace st {

inline uint8_t to_unorm8(float x) {
    // Clamp first, as a unorm target does; NaN goes to 0.
    x = (x > 0.0f) ? (x < 1.0f ? x : 1.0f) : 0.0f;
    const float scaled = x * (255.0f / 256.0f);
    const float biased = scaled + 32768.0f;
    return uint8_t(std::bit_cast<uint32_t>(biased) & 0xffu);
}

}  // namespace st
