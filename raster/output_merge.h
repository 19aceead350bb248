// output_merge.h: depth test and blending of shaded fragments into the
// framebuffer (the "blending/output" stage), a whole part of a block (kLanes
// lanes) at a time, straight on the framebuffer's block layout.
#pragma once

#include <glm/vec4.hpp>

#include "frame/frame.h"
#include "simd/lane_vec.h"
#include "texture/texel_formats.h"

namespace st {

// Blend equation GL_FUNC_ADD with unclamped float operands, as for an
// RGBA32F target: dst = src * sfactor + dst * dfactor, each product rounded
// and then summed, 1 - As rounded on its own. Measured against llvmpipe:
// the triangles-alpha-blend and triangles-large scenes are bit-identical
// with this form and differ with the lerp form fmuladd(As, src - dst, dst) that
// a reading of lp_bld_blend.c suggested (docs/llvmpipe/). Written once for
// one pixel (glm::vec4) and for lanes (Vec4).
// glBlendFuncSeparate with GL_FUNC_ADD on a float target, as llvmpipe's
// lp_build_blend computes it (docs/llvmpipe/render-targets-and-blending.md
// §2-§3): a side whose rgb and alpha factors are both ZERO is dropped and
// both ONE is the value itself; any other side multiplies every channel by
// its factor (1 - x its own rounding, nothing clamped); equal src and dst
// factors blend as (s + d) * F. No FMA.
template <class V>
inline V blend_factors(const BlendFactors& f, const V& s, const V& d) {
    using F = decltype(V().x);
    auto factor = [&](BlendFactor k, F sc, F dc) -> F {
        switch (k) {
            case BlendFactor::Zero: return F(0.0f);
            case BlendFactor::One: return F(1.0f);
            case BlendFactor::SrcColor: return sc;
            case BlendFactor::OneMinusSrcColor: return F(1.0f) - sc;
            case BlendFactor::SrcAlpha: return s.w;
            case BlendFactor::OneMinusSrcAlpha: return F(1.0f) - s.w;
            case BlendFactor::DstColor: return dc;
            case BlendFactor::OneMinusDstColor: return F(1.0f) - dc;
            case BlendFactor::DstAlpha: return d.w;
            case BlendFactor::OneMinusDstAlpha: return F(1.0f) - d.w;
        }
        return F(1.0f);
    };
    auto factors = [&](BlendFactor rgb, BlendFactor alpha) {
        return V(factor(rgb, s.x, d.x), factor(rgb, s.y, d.y), factor(rgb, s.z, d.z), factor(alpha, s.w, d.w));
    };
    enum Kind { Dropped, Plain, Multiplied };
    auto kind = [](BlendFactor rgb, BlendFactor alpha) {
        if (rgb == BlendFactor::Zero && alpha == BlendFactor::Zero) return Dropped;
        if (rgb == BlendFactor::One && alpha == BlendFactor::One) return Plain;
        return Multiplied;
    };
    const Kind ks = kind(f.src_rgb, f.src_alpha), kd = kind(f.dst_rgb, f.dst_alpha);
    if (f.src_rgb == f.dst_rgb && f.src_alpha == f.dst_alpha) {
        if (ks == Dropped) return V(F(0.0f), F(0.0f), F(0.0f), F(0.0f));
        const V sum = s + d;
        return ks == Plain ? sum : sum * factors(f.src_rgb, f.src_alpha);
    }
    if (ks == Dropped && kd == Dropped) return V(F(0.0f), F(0.0f), F(0.0f), F(0.0f));
    const V ts = ks == Plain ? s : s * factors(f.src_rgb, f.src_alpha);
    const V td = kd == Plain ? d : d * factors(f.dst_rgb, f.dst_alpha);
    if (ks == Dropped) return td;
    if (kd == Dropped) return ts;
    return ts + td;
}

template <class V>
inline V blend(const DrawState& state, const V& src, const V& dst) {
    switch (state.blend) {
        case BlendMode::Factors: return blend_factors(state.factors, src, dst);
        case BlendMode::None: return src;
        case BlendMode::OneSrcAlpha: {
            const auto sa = src.w;
            return V(src.x + dst.x * sa, src.y + dst.y * sa, src.z + dst.z * sa, src.w + dst.w * sa);
        }
        case BlendMode::SrcAlphaOneMinusSrcAlpha: {
            const auto sa = src.w;
            const auto one_minus_sa = decltype(sa)(1.0f) - src.w;
            return V(src.x * sa + dst.x * one_minus_sa, src.y * sa + dst.y * one_minus_sa,
                     src.z * sa + dst.z * one_minus_sa, src.w * sa + dst.w * one_minus_sa);
        }
    }
    return src;
}

// The depth test (GL_LESS against the float depth buffer, written when
// depth_write) of the lanes in `live`, group by group: the destination of
// lanes [8g, 8g + 8) is read from in_depth[g] and written to out_depth[g]
// (the same place, or the group's clear values in and the framebuffer out
// when the tile has not written it yet). Returns the lanes that pass.
ST_INLINE Mask depth_tested(const DrawState& state, Float z, Mask live, const float* const* in_depth,
                         float* const* out_depth) {
    if (!state.depth_test) return live;
    const Float stored = Float::load_groups(in_depth);
    const Mask pass = live && z < stored;
    if (state.depth_write) select(pass, z, stored).store_groups(out_depth);
    return pass;
}

// Blending of `src` into one colour buffer for the lanes in `pass`, read
// from in_colour[g] and written to out_colour[g] as above, channel by
// channel, 8 floats apart.
ST_INLINE void merge_colour(const DrawState& state, bool rgba16f, const Vec4& src, Mask pass,
                         const float* const* in_colour, float* const* out_colour) {
    const float* in[4][kLanes / 8];
    float* out[4][kLanes / 8];
    for (int c = 0; c < 4; ++c)
        for (int g = 0; g < kLanes / 8; ++g) {
            in[c][g] = in_colour[g] + c * 8;
            out[c][g] = out_colour[g] + c * 8;
        }
    const Vec4 dst(Float::load_groups(in[0]), Float::load_groups(in[1]), Float::load_groups(in[2]),
                   Float::load_groups(in[3]));
    Vec4 result = state.blend == BlendMode::None ? src : blend(state, src, dst);
    // An RGBA16F target stores halves, rounded toward zero.
    if (rgba16f) result = Vec4(rgba16f_stored(result.x), rgba16f_stored(result.y), rgba16f_stored(result.z),
                               rgba16f_stored(result.w));
    result = select(pass, result, dst);
    result.x.store_groups(out[0]);
    result.y.store_groups(out[1]);
    result.z.store_groups(out[2]);
    result.w.store_groups(out[3]);
}

// Both, for a pass with one colour buffer.
ST_INLINE void merge_lanes(const DrawState& state, bool rgba16f, const Vec4& src, Float z, Mask live,
                        const float* const* in_colour, const float* const* in_depth, float* const* out_colour,
                        float* const* out_depth) {
    merge_colour(state, rgba16f, src, depth_tested(state, z, live, in_depth, out_depth), in_colour, out_colour);
}

}  // namespace st
