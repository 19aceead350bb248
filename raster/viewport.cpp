// viewport.cpp: the viewport transform (see viewport.h for the arithmetic).
#include "raster/viewport.h"

#include <cmath>

namespace st {

WindowPos to_window(const glm::vec4& clip, const Viewport& vp) {
    // Gallium's viewport state: scale = size/2, translate = origin + size/2.
    const float scale_x = vp.width * 0.5f, trans_x = vp.x0 + vp.width * 0.5f;
    const float scale_y = vp.height * 0.5f, trans_y = vp.y0 + vp.height * 0.5f;
    const float scale_z = (vp.far - vp.near) * 0.5f, trans_z = (vp.far + vp.near) * 0.5f;
    const float inv_w = 1.0f / clip.w;
    WindowPos out;
    out.x = std::fma(clip.x * inv_w, scale_x, trans_x);
    out.y = std::fma(clip.y * inv_w, scale_y, trans_y);
    out.z = std::fma(clip.z * inv_w, scale_z, trans_z);
    out.inv_w = inv_w;
    return out;
}

}  // namespace st
