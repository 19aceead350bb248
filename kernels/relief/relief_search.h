// relief_search.h: twin of glsl/relief/relief_search.glsl; definitions in
// relief_search.cpp.
#pragma once

#include "shading/control_flow.h"

namespace st {
class Sampler2D;
}

namespace st::relief {

// `exec` is the invocation's execution mask: the linear search is a loop
// whose lanes leave at different steps.
Float trace_segment(Exec& exec, const Sampler2D& map, const Vec2& uv, const Vec2& offset, Float a, Float dh,
                    Float side, const Vec2& dx, const Vec2& dy, int linear_steps, int binary_steps, bool secant,
                    Mask& hit);

Mask segment_blocked(Exec& exec, const Sampler2D& map, const Vec2& uv, const Vec2& offset, Float a, Float dh,
                     const Vec2& dx, const Vec2& dy, int linear_steps);

// `exec` is the invocation's execution mask: the linear search is a loop
// whose lanes leave at different steps.
Float trace_height_field(Exec& exec, const Sampler2D& map, const Vec2& uv, const Vec2& offset, const Vec2& dx,
                         const Vec2& dy, int linear_steps, int binary_steps, bool secant);

}  // namespace st::relief
