// viewport.h: clip coordinates to window coordinates, as llvmpipe's draw
// module computes them, so that our vertices land on the same bits.
//
// Measured (../shared/notes/llvmpipe.md, "Rasterization rules"):
// 1/w is a correctly rounded division, x_ndc = x_clip * (1/w) is rounded,
// and x_win = fmuladd(x_ndc, width/2, x0 + width/2) with one rounding.
#pragma once

#include <glm/vec4.hpp>

namespace st {

struct Viewport {
    float x0 = 0, y0 = 0, width = 0, height = 0;
    float near = 0, far = 1;  // glDepthRange
};

// Window position; w holds 1/w_clip, as llvmpipe keeps it for interpolation.
struct WindowPos {
    float x, y, z, inv_w;
};

WindowPos to_window(const glm::vec4& clip, const Viewport& viewport);

}  // namespace st
