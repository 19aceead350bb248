// texel_formats.h: what a float texel becomes when it is stored in each
// format, as llvmpipe stores it (docs/llvmpipe/mipmaps-cubes-formats.md §4),
// so that the CPU sampler reads the values the GPU reads.
//
// - RGBA32F keeps the float.
// - R32F keeps red; sampling returns (r, 0, 0, 1).
// - RGBA16F: glTexImage2D(GL_RGBA16F, GL_FLOAT) rounds toward zero: finite
//   values past the largest half become +-65504, +-inf stays, values below
//   2^-24 in magnitude become +-0, every other value (fp16 denormals too) is
//   truncated; sampling converts the half back exactly.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

#include "frame/frame.h"

namespace st {

// The float a half holds after a round-toward-zero store of x.
inline float rgba16f_stored(float x) {
    if (std::isnan(x)) return std::bit_cast<float>(0x7fc00000u);  // a quiet NaN (payload not modelled)
    const float sign = std::signbit(x) ? -1.0f : 1.0f;
    const float a = std::fabs(x);
    if (std::isinf(a)) return x;
    if (a >= 65504.0f) return sign * 65504.0f;
    if (a < 0x1p-24f) return sign * 0.0f;
    // Keep the bits a half keeps: 11 significant bits for normals (a >=
    // 2^-14), a fixed quantum of 2^-24 below.
    const float quantum = a >= 0x1p-14f ? std::ldexp(1.0f, std::ilogb(a) - 10) : 0x1p-24f;
    return sign * (std::floor(a / quantum) * quantum);  // exact: powers of two
}

// The RGBA a shader reads from a stored texel given as RGBA floats.
inline void stored_texel(TextureFormat format, const float* in, float* out) {
    switch (format) {
        case TextureFormat::R32F:
            out[0] = in[0], out[1] = 0.0f, out[2] = 0.0f, out[3] = 1.0f;
            return;
        case TextureFormat::RGBA16F:
            for (int c = 0; c < 4; ++c) out[c] = rgba16f_stored(in[c]);
            return;
        default:
            for (int c = 0; c < 4; ++c) out[c] = in[c];
    }
}

}  // namespace st
