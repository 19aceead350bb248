// srgb_decode.h: what llvmpipe's sampler makes of an SRGB8_ALPHA8 texel's
// bytes, before it filters (docs/llvmpipe/mipmaps-cubes-formats.md 4.6).
// Not the IEC curve: lp_build_srgb_to_linear evaluates a cubic in the byte
// value b (x = b, not b / 255) with fused multiply-adds, x * (1 / (12.6 *
// 255)) up to b = 15; alpha is b * 0x1.010102p-8 as for RGBA8. Fused, as
// llvmpipe's fmuladd is on every host with FMA (Zen 2, 4, 5): 72 of the 256
// bytes decode differently unfused.
#pragma once

#include <cstdint>

namespace st {

// The decoded value of a colour byte (red, green or blue).
float srgb_texel_colour(uint8_t b);
// The value of an alpha byte.
float srgb_texel_alpha(uint8_t b);

}  // namespace st
