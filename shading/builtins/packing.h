// packing.h: GLSL's pack and unpack built-ins (Unorm and Snorm 2x16 and
// 4x8, Half 2x16) as llvmpipe computes them: GLSL IR's
// lower_packing_builtins writes each as float and integer code, which
// llvmpipe runs as any other (docs/llvmpipe/glsl-builtins.md 6.3; proved by
// the scene conformance-builtins-integer-pack). Where it is not what a
// reader expects:
// - pack rounds with roundEven, so ties go to even: packUnorm4x8(0.5 / 255)
//   is 0; NaN packs as 0 (Unorm) or as -1's code (Snorm), through the clamp.
// - unpackUnorm divides by 255 or 65535 (an IEEE division), where a
//   texture fetch of the same byte multiplies by 1/255: 126 of the 256
//   bytes differ by one ulp between the two.
// - packHalf2x16 rounds to nearest even, overflows to infinity and packs
//   every NaN as 0x7FFF with its sign; unpackHalf2x16 gives every half NaN
//   as 0x7FFFFFFF with its sign.
// One function per value for one float (scalar), run per lane for lanes.
#pragma once

#include <bit>
#include <cstdint>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "shading/builtins/common.h"

namespace st::glsl {

namespace packing_detail {

// f2u(roundEven(saturate(c) * scale)), saturate as MINPS(MAXPS(c, 0), 1).
ST_INLINE uint32_t unorm(float c, float scale) {
    const float s = scalar::minps(scalar::maxps(c, 0.0f), 1.0f);
    return uint32_t(int32_t(scalar::round_even(s * scale)));
}
// i2u(f2i(roundEven(clamp(c, -1, 1) * scale))) & mask; clamp is GLSL's
// min(max(c, -1), 1), so NaN gives -1.
ST_INLINE uint32_t snorm(float c, float scale, uint32_t mask) {
    const float s = glsl::clamp(c, -1.0f, 1.0f);
    return uint32_t(int32_t(scalar::round_even(s * scale))) & mask;
}
ST_INLINE float unsnorm(int32_t field, float scale) { return glsl::clamp(float(field) / scale, -1.0f, 1.0f); }

// One float to half bits, as pack_half_1x16 writes it.
ST_INLINE uint32_t half_of(float f) {
    const uint32_t b = std::bit_cast<uint32_t>(f);
    const uint32_t e = b & 0x7F800000u, m = b & 0x007FFFFFu;
    uint32_t h;
    if (e == 0x7F800000u && m != 0) h = 0x7FFFu;
    else if (e < (113u << 23)) h = uint32_t(int32_t(scalar::round_even(scalar::abs(f) * 16777216.0f)));
    else if (e < (143u << 23)) h = ((e - (112u << 23)) >> 13) + uint32_t(int32_t(scalar::round_even(float(m) / 8192.0f)));
    else h = 0x7C00u;
    return h | ((b >> 16) & 0x8000u);
}
// Half bits (the low 16 of h) to a float, as unpack_half_1x16 writes it.
ST_INLINE float float_of_half(uint32_t h) {
    const uint32_t e16 = h & 0x7C00u, m = h & 0x3FFu;
    uint32_t b;
    if (e16 == 0) b = std::bit_cast<uint32_t>(float(m) / 16777216.0f);
    else if (e16 < (31u << 10)) b = ((e16 + (112u << 10)) | m) << 13;
    else if (m == 0) b = 0x7F800000u;
    else b = 0x7FFFFFFFu;
    return std::bit_cast<float>(b | ((h & 0x8000u) << 16));
}

template <class R, class F> ST_INLINE R per_lane(F f) {
    R r;
    for (int lane = 0; lane < kLanes; ++lane) r.set(lane, f(lane));
    return r;
}

}  // namespace packing_detail

ST_INLINE uint32_t packUnorm2x16(const glm::vec2& v) {
    return packing_detail::unorm(v.x, 65535.0f) | (packing_detail::unorm(v.y, 65535.0f) << 16);
}
ST_INLINE uint32_t packSnorm2x16(const glm::vec2& v) {
    return packing_detail::snorm(v.x, 32767.0f, 0xFFFFu) | (packing_detail::snorm(v.y, 32767.0f, 0xFFFFu) << 16);
}
ST_INLINE uint32_t packUnorm4x8(const glm::vec4& v) {
    using packing_detail::unorm;
    return unorm(v.x, 255.0f) | (unorm(v.y, 255.0f) << 8) | (unorm(v.z, 255.0f) << 16) | (unorm(v.w, 255.0f) << 24);
}
ST_INLINE uint32_t packSnorm4x8(const glm::vec4& v) {
    using packing_detail::snorm;
    return snorm(v.x, 127.0f, 0xFFu) | (snorm(v.y, 127.0f, 0xFFu) << 8) | (snorm(v.z, 127.0f, 0xFFu) << 16) |
           (snorm(v.w, 127.0f, 0xFFu) << 24);
}
ST_INLINE uint32_t packHalf2x16(const glm::vec2& v) {
    return packing_detail::half_of(v.x) | (packing_detail::half_of(v.y) << 16);
}
ST_INLINE glm::vec2 unpackUnorm2x16(uint32_t p) {
    return glm::vec2(float(p & 0xFFFFu) / 65535.0f, float(p >> 16) / 65535.0f);
}
ST_INLINE glm::vec2 unpackSnorm2x16(uint32_t p) {
    using packing_detail::unsnorm;
    return glm::vec2(unsnorm(int32_t(int16_t(p & 0xFFFFu)), 32767.0f), unsnorm(int32_t(int16_t(p >> 16)), 32767.0f));
}
ST_INLINE glm::vec4 unpackUnorm4x8(uint32_t p) {
    return glm::vec4(float(p & 0xFFu) / 255.0f, float((p >> 8) & 0xFFu) / 255.0f, float((p >> 16) & 0xFFu) / 255.0f,
                     float(p >> 24) / 255.0f);
}
ST_INLINE glm::vec4 unpackSnorm4x8(uint32_t p) {
    using packing_detail::unsnorm;
    const auto byte = [&](int i) { return int32_t(int8_t(uint8_t(p >> (8 * i)))); };
    return glm::vec4(unsnorm(byte(0), 127.0f), unsnorm(byte(1), 127.0f), unsnorm(byte(2), 127.0f),
                     unsnorm(byte(3), 127.0f));
}
ST_INLINE glm::vec2 unpackHalf2x16(uint32_t p) {
    return glm::vec2(packing_detail::float_of_half(p & 0xFFFFu), packing_detail::float_of_half(p >> 16));
}

// The lane forms: the one-value function per lane.
namespace packing_detail {
ST_INLINE glm::vec2 lane(const Vec2& v, int l) { return glm::vec2(v.x[l], v.y[l]); }
ST_INLINE glm::vec4 lane(const Vec4& v, int l) { return glm::vec4(v.x[l], v.y[l], v.z[l], v.w[l]); }
ST_INLINE void set_lane(Vec2& v, int l, const glm::vec2& g) {
    v.x.set(l, g.x);
    v.y.set(l, g.y);
}
ST_INLINE void set_lane(Vec4& v, int l, const glm::vec4& g) {
    v.x.set(l, g.x);
    v.y.set(l, g.y);
    v.z.set(l, g.z);
    v.w.set(l, g.w);
}
}  // namespace packing_detail

#define ST_GLSL_PACK_LANES(name, V)                                                                 \
    ST_INLINE UInt name(const V& v) {                                                              \
        return packing_detail::per_lane<UInt>([&](int l) { return ::st::glsl::name(packing_detail::lane(v, l)); }); \
    }
#define ST_GLSL_UNPACK_LANES(name, V)                                                               \
    ST_INLINE V name(UInt p) {                                                                     \
        V r;                                                                                       \
        for (int l = 0; l < kLanes; ++l) packing_detail::set_lane(r, l, ::st::glsl::name(p[l]));   \
        return r;                                                                                  \
    }
ST_GLSL_PACK_LANES(packUnorm2x16, Vec2)
ST_GLSL_PACK_LANES(packSnorm2x16, Vec2)
ST_GLSL_PACK_LANES(packUnorm4x8, Vec4)
ST_GLSL_PACK_LANES(packSnorm4x8, Vec4)
ST_GLSL_PACK_LANES(packHalf2x16, Vec2)
ST_GLSL_UNPACK_LANES(unpackUnorm2x16, Vec2)
ST_GLSL_UNPACK_LANES(unpackSnorm2x16, Vec2)
ST_GLSL_UNPACK_LANES(unpackUnorm4x8, Vec4)
ST_GLSL_UNPACK_LANES(unpackSnorm4x8, Vec4)
ST_GLSL_UNPACK_LANES(unpackHalf2x16, Vec2)
#undef ST_GLSL_PACK_LANES
#undef ST_GLSL_UNPACK_LANES

// packDouble2x32(uvec2(lo, hi)) and unpackDouble2x32(d): the 64 bits moved,
// nothing rounded (a bit cast in llvmpipe).
ST_INLINE double packDouble2x32(const glm::uvec2& v) {
    return std::bit_cast<double>((uint64_t(v.y) << 32) | uint64_t(v.x));
}
ST_INLINE glm::uvec2 unpackDouble2x32(double d) {
    const uint64_t b = std::bit_cast<uint64_t>(d);
    return glm::uvec2(uint32_t(b), uint32_t(b >> 32));
}
ST_INLINE Double packDouble2x32(const UVec2& v) {
    const simd::ULongV lo = __builtin_convertvector(v.x.u(), simd::ULongV);
    const simd::ULongV hi = __builtin_convertvector(v.y.u(), simd::ULongV);
    return simd::double_from_bits(simd::LongV((hi << 32) | lo));
}
ST_INLINE UVec2 unpackDouble2x32(Double d) {
    const simd::ULongV b = simd::ULongV(simd::bits_of(d));
    return UVec2(UInt(simd::IntV(__builtin_convertvector(b, simd::UIntV))),
                 UInt(simd::IntV(__builtin_convertvector(b >> 32, simd::UIntV))));
}

}  // namespace st::glsl
