// texel_math.h: the per-axis arithmetic both samplers share, as llvmpipe's
// gallivm computes it (docs/llvmpipe/texture-sampling.md and
// mipmaps-cubes-formats.md): wraps and taps for the float (SoA) and 8-bit
// (AoS) filters, the lerps, unorm8 conversion, quad lanes and 8-lane-vector
// reductions. Inline, for texture/*.cpp only.
#pragma once

#include "frame/frame.h"
#include "simd/lane_vec.h"

namespace st::texel {

using simd::fmuladd;
using simd::floor;
using simd::iround;
using simd::itrunc;
using simd::IntV;

inline bool is_pot(int n) { return (n & (n - 1)) == 0; }

// maxps (simd/lanes.h): a > b ? a : b, so a NaN in either operand gives b.
using simd::maxps;

// MIRRORED_REPEAT folds s into [0, 1] once, at the sample's centre
// (lp_build_coord_mirror, posOnly): |2 (s/2 - rne(s/2))|, NaN -> 0.
// The rounding stays in float (lp_build_round is llvm.nearbyint): an
// integer conversion would give INT32_MIN from |s| >= 2^32 on, where every
// float is even and the fold is 0; infinity folds to inf - inf, NaN, so 0.
ST_INLINE Float mirror(Float s) {
    const Float c = s * Float(0.5f);
    const Float f = c - simd::round_even(c);
    return maxps(simd::abs(f + f), Float(0.0f));
}

// Float texel coordinates for linear filtering along one axis: the lower
// texel i0, the upper i1 and the weight of i1 (wrap_linear in
// lp_bld_sample_soa.c).
struct LinearTaps {
    Int i0, i1;
    Float weight;
};

ST_INLINE LinearTaps linear_taps_float(Float s, Int size, Float size_f, bool pot, TextureWrap wrap) {
    LinearTaps t;
    const Int last = size - Int(1);
    if (wrap == TextureWrap::ClampToEdge) {
        Float u = s * size_f;
        u = select(simd::isnan(u), size_f, select(size_f < u, size_f, u));  // min(u, size), NaN -> size
        u = u - Float(0.5f);
        u = select(u < Float(0.0f), Float(0.0f), u);
        const Float fl = floor(u);
        t.weight = u - fl;
        t.i0 = itrunc(fl);
        t.i1 = simd::min(t.i0 + Int(1), last);
    } else if (wrap == TextureWrap::MirroredRepeat) {
        const Float u = mirror(s) * size_f - Float(0.5f);
        const Float fl = floor(u);
        t.weight = u - fl;
        t.i0 = simd::max(itrunc(fl), Int(0));
        t.i1 = simd::min(itrunc(fl) + Int(1), last);
    } else if (pot) {
        const Float u = s * size_f - Float(0.5f);
        const Float fl = floor(u);
        t.weight = u - fl;
        t.i0 = itrunc(fl) & last;
        t.i1 = (itrunc(fl) + Int(1)) & last;
    } else {
        // Normalised repeat is fract(); the -0.5 then needs a fix-up below 0.
        // The test is unordered (lp_build_compare): a NaN coordinate takes
        // the last texel and texel 0, its taps inside like any other.
        Float u = s - floor(s);
        u = u * size_f - Float(0.5f);
        const Float fl = floor(u);
        t.weight = u - fl;
        t.i0 = select(!(u >= Float(0.0f)), last, itrunc(fl));
        t.i1 = select(t.i0 != last, t.i0 + Int(1), Int(0));
    }
    return t;
}

// The same in 8.8 fixed point for the AoS path: the weight is an integer
// in [0, 255] (wrap_linear_int and repeat_npot_linear_int, §3.2).
struct LinearTaps8 {
    Int i0, i1, weight;
};

ST_INLINE LinearTaps8 linear_taps_fixed(Float s, Int size, Float size_f, bool pot, TextureWrap wrap) {
    LinearTaps8 t;
    const Int last = size - Int(1);
    if (wrap == TextureWrap::Repeat && !pot) {
        Float u = s - floor(s);
        u = u * size_f;
        const Int fixed = iround(u * Float(256.0f)) - Int(128);
        t.weight = fixed & Int(255);
        t.i0 = fixed >> 8;
        t.i0 = select(t.i0 < Int(0), last, t.i0);
        t.i0 = simd::min(t.i0, last);
        t.i1 = select(t.i0 != last, t.i0 + Int(1), Int(0));
        return t;
    }
    const Int fixed = iround(s * simd::to_float(size << 8)) - Int(128);
    t.weight = fixed & Int(255);
    const Int i0 = fixed >> 8;
    if (wrap == TextureWrap::Repeat) {
        t.i0 = i0 & last;
        t.i1 = (i0 + Int(1)) & last;
    } else {
        t.i0 = simd::clamp(i0, Int(0), last);
        t.i1 = simd::clamp(i0 + Int(1), Int(0), last);
    }
    return t;
}

// An 8-bit lerp's weight w in [0, 255], in both 16-bit halves of each lane
// and scaled for pmulhrsw: w << 7 (at most 32640, an int16). Made once per
// weight, shared by every lerp that uses it.
ST_INLINE Int lerp8_weight(Int w) {
    const Int scaled = w << 7;
    return scaled | (scaled << 16);
}

// 8-bit lerp as lp_build_lerp_simple computes it with pmulhrsw,
// v0 + ((w * ((v1 - v0) << 7) + 0x4000) >> 15) kept to 8 bits, on two
// channels at once, one per 16-bit half of each lane (bytes in [0, 255]);
// `w` from lerp8_weight. The product is the same as llvmpipe's
// ((w << 7) * d == w * (d << 7), both factors within int16), and the
// rounded step never exceeds |v1 - v0| in size, so v0 plus it stays in
// [0, 255] and a 16-bit add is the 8-bit add modulo 256 without masks.
ST_INLINE Int lerp8_pairs(Int w, Int v0, Int v1) { return simd::add16(v0, simd::mulhrs16(w, simd::sub16(v1, v0))); }

// Float lerp: fmuladd(t, v1 - v0, v0), as lp_build_mad fuses it.
ST_INLINE Float lerp_float(Float t, Float v0, Float v1) { return fmuladd(t, v1 - v0, v0); }

// The nearest texel along one axis (lp_build_sample_wrap_nearest, and
// wrap_nearest_int on the AoS path, which selects the same texel). Every
// float-to-int conversion is cvttps2dq's: NaN, infinity and anything beyond
// 2^31 in magnitude give INT32_MIN, which the wraps then treat as any
// integer (simd::itrunc).
ST_INLINE Int nearest_texel(Float s, Int size, Float size_f, bool pot, TextureWrap wrap) {
    const Int last = size - Int(1);
    // No clamp of the float first: s * size at or beyond 2^31 converts to
    // INT32_MIN and clamps to texel 0, not the last one. The AoS path
    // floors before converting; after the clamp that is the same texel.
    if (wrap == TextureWrap::ClampToEdge) return simd::clamp(itrunc(s * size_f), Int(0), last);
    if (wrap == TextureWrap::MirroredRepeat) return simd::min(itrunc(mirror(s) * size_f), last);
    // INT32_MIN & (size - 1) is texel 0.
    if (pot) return itrunc(floor(s * size_f)) & last;
    // fract_safe keeps the fraction below 1: minps(fraction, 1 - ulp), so a
    // NaN coordinate gives the last texel.
    const Float fraction = s - floor(s);
    const Float f = select(fraction < Float(0x1.fffffep-1f), fraction, Float(0x1.fffffep-1f));
    return itrunc(f * size_f);
}

// unorm8 to float: k * fl(1/255), one rounding (lp_bld_conv.c).
ST_INLINE Float unorm8_to_float(Int k) { return simd::to_float(k) * Float(1.0f / 255.0f); }

// The channels a caller reads (bits 1, 2, 4, 8 for R, G, B, A), and the
// two byte pairs of the 8-bit path they fall in.
inline constexpr unsigned kReadRGBA = 0xf, kReadRGB = 0x7, kReadR = 0x1;
inline constexpr unsigned kReadRedBlue = 0x5, kReadGreenAlpha = 0xa;

// The R and B bytes (rb) or G and A bytes (ga) of packed RGBA8 texels, one
// per 16-bit half.
ST_INLINE Int red_blue(Int t) { return t & Int(0x00ff00ff); }
ST_INLINE Int green_alpha(Int t) { return simd::odd_bytes(t); }

// The pairs as floats; channels outside `read` are 0, not converted.
ST_INLINE Vec4 unpack_pairs(Int rb, Int ga, unsigned read = kReadRGBA) {
    auto channel = [&](unsigned c, Int bytes) __attribute__((always_inline)) {
        return (read >> c) & 1u ? unorm8_to_float(bytes) : Float(0.0f);
    };
    return Vec4(channel(0, rb & Int(0xff)), channel(1, ga & Int(0xff)), channel(2, rb >> 16), channel(3, ga >> 16));
}

// Lane indices of the top-left, top-right and bottom-left lane of each
// lane's quad: the lanes llvmpipe takes a quad's derivatives from (§2.2).
#define ST_QUAD(q, a) 4 * q + a, 4 * q + a, 4 * q + a, 4 * q + a
#if ST_LANES == 8
#define ST_QUAD_LANES(a) {ST_QUAD(0, a), ST_QUAD(1, a)}
#else
#define ST_QUAD_LANES(a) {ST_QUAD(0, a), ST_QUAD(1, a), ST_QUAD(2, a), ST_QUAD(3, a)}
#endif
constexpr IntV kQuadTL = ST_QUAD_LANES(0), kQuadTR = ST_QUAD_LANES(1), kQuadBL = ST_QUAD_LANES(2);
#undef ST_QUAD_LANES
#undef ST_QUAD

// Lane bits of 8-lane groups where some lane of the group is in m.
ST_INLINE Mask any_in_group(Mask m) {
    const unsigned b = bits(m);
    unsigned out = 0;
    for (int g = 0; g < kLanes / 8; ++g)
        if (b >> (8 * g) & 0xffu) out |= 0xffu << (8 * g);
    return Mask::from_bits(out);
}

// For each lane, a lane whose reads it may share when its own result is
// not used: the first lane of its 8-lane group in `active`, or, in a group
// without one, the first of all (the caller has at least one).
ST_INLINE Int lead_lanes(Mask active) {
    const unsigned b = bits(active);
    Int lead(__builtin_ctz(b));
    for (int g = 0; g < kLanes / 8; ++g)
        if (const unsigned own = b >> (8 * g) & 0xffu)
            lead = select(Mask::from_bits(0xffu << (8 * g)), Int(8 * g + __builtin_ctz(own)), lead);
    return lead;
}

// 0.5 * fast_log2(rho^2): (E - 128) + the mantissa in [1, 2), one rounded
// add, then halved (§2.4).
ST_INLINE Float half_fast_log2(Float rho2) {
    const Int bits = simd::bit_cast_int(rho2);
    const Float mantissa = simd::bit_cast_float((bits & Int(0x7fffff)) | Int(0x3f800000));
    return (simd::to_float(((bits >> 23) & Int(255)) - Int(128)) + mantissa) * Float(0.5f);
}

// Texels at `index` where `active` (0 elsewhere, nothing read there): from
// the packed RGBA8 array when the texture is RGBA8, else from the RGBA
// float array, four floats a texel.
// `read` (bits 1, 2, 4, 8 for R, G, B, A) says which float channels the
// caller uses; the others are not fetched and read 0 (as LLVM drops the
// loads of channels a shader never reads). RGBA8 texels come whole.
ST_INLINE Vec4 gather_texels(bool rgba8, const int32_t* bytes, const float* floats, Int index, Mask active,
                             unsigned read = kReadRGBA) {
    if (rgba8) {
        const Int rgba = simd::gather(bytes, index, active);
        return unpack_pairs(red_blue(rgba), green_alpha(rgba));
    }
    const Int i = index * Int(4);
    auto channel = [&](unsigned c) __attribute__((always_inline)) {
        return (read >> c) & 1u ? simd::gather(floats + c, i, active) : Float(0.0f);
    };
    return Vec4(channel(0), channel(1), channel(2), channel(3));
}

// The channels of a float texel array that vary from texel to texel: R32F
// stores (r, 0, 0, 1) (texel_formats.h), so only red need be fetched.
ST_INLINE unsigned varying_channels(TextureFormat format) {
    return format == TextureFormat::R32F ? kReadR : kReadRGBA;
}
// gather_texels of a float array with the channels varying_channels leaves
// out set to the values every texel holds there, so filtering them gives
// the same bits as filtering fetched ones.
ST_INLINE Vec4 gather_format_texels(TextureFormat format, const int32_t* bytes, const float* floats, Int index,
                                    Mask active) {
    const unsigned read = varying_channels(format);
    Vec4 t = gather_texels(format == TextureFormat::RGBA8, bytes, floats, index, active, read);
    if (read == kReadR) t.w = Float(1.0f);
    return t;
}

// The two trilinear blends (§2.8). Float: fmuladd(max(fpart, 0), C1 - C0, C0)
// in the lanes of `blend`, C0 elsewhere. 8-bit: lerp8 of the byte pairs with
// the weight trunc(fpart * 256).
ST_INLINE Vec4 blend_levels(Float fpart, const Vec4& c0, const Vec4& c1, Mask blend) {
    const Float f = simd::fmax(fpart, Float(0.0f));
    return select(blend, Vec4(lerp_float(f, c0.x, c1.x), lerp_float(f, c0.y, c1.y), lerp_float(f, c0.z, c1.z),
                              lerp_float(f, c0.w, c1.w)),
                  c0);
}
// The 8-bit weight of level1, trunc(fpart * 256). Where it is 0 in every
// lane, lerp8 gives level0's bytes as they are: level1 need not be filtered
// (magnified quads, LODs at the last level, fractions under 1/256).
ST_INLINE Int level_weight8(Float fpart) { return itrunc(fpart * Float(256.0f)); }
ST_INLINE void blend_levels8(Int wl, Int& rb0, Int& ga0, Int rb1, Int ga1, unsigned read = kReadRGBA) {
    const Int w = lerp8_weight(wl);
    if (read & kReadRedBlue) rb0 = lerp8_pairs(w, rb0, rb1);
    if (read & kReadGreenAlpha) ga0 = lerp8_pairs(w, ga0, ga1);
}

}  // namespace st::texel
