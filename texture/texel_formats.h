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
#include "simd/lane_vec.h"

namespace st {

// The few operations rz16_impl needs, for float and for lanes.
ST_INLINE int32_t bit_cast_to_int(float x) { return std::bit_cast<int32_t>(x); }
ST_INLINE float bit_cast_to_float(int32_t x) { return std::bit_cast<float>(x); }
ST_INLINE float floor_of(float x) { return std::floor(x); }
ST_INLINE float abs_of(float x) { return std::fabs(x); }
ST_INLINE int32_t select_of(bool m, int32_t a, int32_t b) { return m ? a : b; }
ST_INLINE Int bit_cast_to_int(Float x) { return simd::bit_cast_int(x); }
ST_INLINE Float bit_cast_to_float(Int x) { return simd::bit_cast_float(x); }
ST_INLINE Float floor_of(Float x) { return simd::floor(x); }
ST_INLINE Float abs_of(Float x) { return simd::abs(x); }
ST_INLINE Int select_of(Mask m, Int a, Int b) { return select(m, a, b); }

// The float a half holds after a round-toward-zero store of x (F16C
// vcvtps2ph with immediate 3, as llvmpipe writes an RGBA16F target, and the
// GL upload of floats into RGBA16F): the low 13 mantissa bits go for
// normal halves, below 2^-14 the quantum is 2^-24, finite values past 65504
// become +-65504, and a NaN stays a quiet NaN with its sign and top 10
// payload bits (docs/llvmpipe/render-targets-and-blending.md). Written on
// the bits, once for a float and for lanes.
template <class F, class I, class M>
ST_INLINE F rz16_impl(F x) {
    const I bits = st::bit_cast_to_int(x);
    const I sign = bits & I(int32_t(0x80000000u));
    const I a = bits & I(0x7fffffff);
    const I truncated = bits & I(int32_t(0xffffe000u));
    // |x| * 2^24 is exact for |x| >= 2^-24; floor, then back by 2^-24.
    const F denormal = st::floor_of(st::abs_of(x) * F(16777216.0f)) * F(1.0f / 16777216.0f);
    I r = st::select_of(a < I(0x38800000), sign | st::bit_cast_to_int(denormal), truncated);
    r = st::select_of(a < I(0x33800000), sign, r);                                   // below 2^-24
    r = st::select_of(!(a < I(0x477fe000)), sign | I(0x477fe000), r);              // 65504 and past
    r = st::select_of(a == I(0x7f800000), bits, r);                                  // +-inf
    r = st::select_of(I(0x7f800000) < a, truncated | I(0x00400000), r);            // NaN, quietened
    return st::bit_cast_to_float(r);
}

inline float rgba16f_stored(float x) { return rz16_impl<float, int32_t, bool>(x); }
ST_INLINE Float rgba16f_stored(Float x) { return rz16_impl<Float, Int, Mask>(x); }

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
