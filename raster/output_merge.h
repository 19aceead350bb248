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
// depth_write) and blending of the lanes in `live`. colour[g] points at the
// framebuffer colour of the pixels of lanes [8g, 8g + 8), channel by
// channel 8 floats apart; depth[g] at their depth values.
inline void merge_lanes(const DrawState& state, const Vec4& src, Float z, Mask live, float* const* colour,
                        float* const* depth) {
    Mask pass = live;
    if (state.depth_test) {
        const Float stored = Float::load_groups(depth);
        pass = pass && z < stored;
        if (state.depth_write) select(pass, z, stored).store_groups(depth);
    }
    float* channel[4][kLanes / 8];
    for (int c = 0; c < 4; ++c)
        for (int g = 0; g < kLanes / 8; ++g) channel[c][g] = colour[g] + c * 8;
    const Vec4 dst(Float::load_groups(channel[0]), Float::load_groups(channel[1]), Float::load_groups(channel[2]),
                   Float::load_groups(channel[3]));
    const Vec4 out = select(pass, blend(state.blend, src, dst), dst);
    out.x.store_groups(channel[0]);
    out.y.store_groups(channel[1]);
    out.z.store_groups(channel[2]);
    out.w.store_groups(channel[3]);
}

}  // namespace st
