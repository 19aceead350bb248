// output_merge.h: depth test and blending of one shaded fragment into the
// framebuffer (the "blending/output" stage).
#pragma once

#include <glm/vec4.hpp>

#include "frame/frame.h"

namespace st {

// GL_LESS against a float depth buffer. Returns whether the fragment passes.
inline bool depth_test(const DrawState& state, float z, float& stored) {
    if (!state.depth_test) return true;
    if (!(z < stored)) return false;
    if (state.depth_write) stored = z;
    return true;
}

// Blend equation GL_FUNC_ADD with unclamped float operands, as for an
// RGBA32F target: dst = src * sfactor + dst * dfactor, each product rounded
// and then summed, 1 - As rounded on its own. Measured against llvmpipe:
// the triangles-alpha-blend and triangles-large scenes are bit-identical
// with this form and differ with the lerp form fma(As, src - dst, dst) that
// a reading of lp_bld_blend.c suggested (docs/llvmpipe/).
inline glm::vec4 blend(BlendMode mode, const glm::vec4& src, const glm::vec4& dst) {
    switch (mode) {
        case BlendMode::None: return src;
        case BlendMode::OneSrcAlpha: {
            const float sa = src.a;
            return {src.r + dst.r * sa, src.g + dst.g * sa, src.b + dst.b * sa, src.a + dst.a * sa};
        }
        case BlendMode::SrcAlphaOneMinusSrcAlpha: {
            const float sa = src.a, one_minus_sa = 1.0f - src.a;
            return {src.r * sa + dst.r * one_minus_sa, src.g * sa + dst.g * one_minus_sa,
                    src.b * sa + dst.b * one_minus_sa, src.a * sa + dst.a * one_minus_sa};
        }
    }
    return src;
}

}  // namespace st
