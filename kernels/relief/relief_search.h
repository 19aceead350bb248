// relief_search.h: twin of glsl/relief/relief_search.glsl; definitions in
// relief_search.cpp.
#pragma once

#include "shading/control_flow.h"

namespace st {
class Sampler2D;
}

namespace st::relief {

// The condition map's hook (CPU only; app/comparison.cpp renders with
// ulp_perturbation = +1 and -1): the ray's x and y moved by `ulps` units in
// the last place (zeros stay, so no sign flips into a NaN pattern).
inline Vec3 perturbed(const Vec3& v, int ulps) {
    if (ulps == 0) return v;
    auto nudge = [ulps](Float x) {
        return select(x == Float(0.0f), x, simd::bit_cast_float(simd::bit_cast_int(x) + Int(ulps)));
    };
    return Vec3(nudge(v.x), nudge(v.y), v.z);
}

// `exec` is the invocation's execution mask: the linear search is a loop
// whose lanes leave at different steps.
Float trace_segment(Exec& exec, const Sampler2D& map, const Vec2& uv, const Vec2& offset, Float a, Float dh,
                    Float side, const Vec2& dx, const Vec2& dy, Int linear_steps, int binary_steps, bool secant,
                    Mask& hit);

Mask segment_blocked(Exec& exec, const Sampler2D& map, const Vec2& uv, const Vec2& offset, Float a, Float dh,
                     const Vec2& dx, const Vec2& dy, int linear_steps);

// `exec` is the invocation's execution mask: the linear search is a loop
// whose lanes leave at different steps.
Float trace_height_field(Exec& exec, const Sampler2D& map, const Vec2& uv, const Vec2& offset, const Vec2& dx,
                         const Vec2& dy, Int linear_steps, int binary_steps, bool secant);

}  // namespace st::relief
