// output_merge.h: depth test and blending of shaded fragments into the
// framebuffer (the "blending/output" stage), a whole part of a block (kLanes
// lanes) at a time, straight on the framebuffer's block layout.
#pragma once

#include <glm/vec4.hpp>

#include "frame/frame.h"
#include "simd/lane_vec.h"

namespace st {

// Blend equation GL_FUNC_ADD with unclamped float operands, as for an
// RGBA32F target: dst = src * sfactor + dst * dfactor, each product rounded
// and then summed, 1 - As rounded on its own. Measured against llvmpipe:
// the triangles-alpha-blend and triangles-large scenes are bit-identical
// with this form and differ with the lerp form fma(As, src - dst, dst) that
// a reading of lp_bld_blend.c suggested (docs/llvmpipe/). Written once for
// one pixel (glm::vec4) and for lanes (Vec4).
template <class V>
inline V blend(BlendMode mode, const V& src, const V& dst) {
    switch (mode) {
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

// Depth test (GL_LESS against the float depth buffer, written when
// depth_write) and blending of the lanes in `live`, group by group: the
// destination of lanes [8g, 8g + 8) is read from in_colour[g] and
// in_depth[g] and written to out_colour[g] and out_depth[g] (the same
// places, or a group's clear values in and the framebuffer out when the
// tile has not written it yet). Colour is channel by channel, 8 floats
// apart.
inline void merge_lanes(const DrawState& state, const Vec4& src, Float z, Mask live,
                        const float* const* in_colour, const float* const* in_depth, float* const* out_colour,
                        float* const* out_depth) {
    Mask pass = live;
    if (state.depth_test) {
        const Float stored = Float::load_groups(in_depth);
        pass = pass && z < stored;
        if (state.depth_write) select(pass, z, stored).store_groups(out_depth);
    }
    const float* in[4][kLanes / 8];
    float* out[4][kLanes / 8];
    for (int c = 0; c < 4; ++c)
        for (int g = 0; g < kLanes / 8; ++g) {
            in[c][g] = in_colour[g] + c * 8;
            out[c][g] = out_colour[g] + c * 8;
        }
    const Vec4 dst(Float::load_groups(in[0]), Float::load_groups(in[1]), Float::load_groups(in[2]),
                   Float::load_groups(in[3]));
    const Vec4 result = select(pass, blend(state.blend, src, dst), dst);
    result.x.store_groups(out[0]);
    result.y.store_groups(out[1]);
    result.z.store_groups(out[2]);
    result.w.store_groups(out[3]);
}

}  // namespace st
