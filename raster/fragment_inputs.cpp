// fragment_inputs.cpp: see fragment_inputs.h.
#include "raster/fragment_inputs.h"

#include <algorithm>

namespace st {

void interpolate_quad(const Plane* planes, int varying_count, const QuadCoverage& quad,
                      bool front_facing, FragmentQuad& out) {
    const Plane& z_plane = planes[0];
    const Plane& inv_w_plane = planes[1];
    const Plane* varying_planes = planes + 2;
    out.front_facing = front_facing;
    out.coverage_mask = quad.mask;
    for (int lane = 0; lane < 4; ++lane) {
        const int px = quad.x + (lane & 1), py = quad.y + (lane >> 1);
        // Depth is clamped to the depth range [0, 1] before the test.
        const float z = std::clamp(z_plane.at(px, py), 0.0f, 1.0f);
        const float inv_w = inv_w_plane.at(px, py);
        const float w = 1.0f / inv_w;
        out.frag_coord[lane] = glm::vec4(float(px) + 0.5f, float(py) + 0.5f, z, inv_w);
        for (int slot = 0; slot < varying_count; ++slot)
            for (int c = 0; c < 4; ++c)
                out.varyings[slot][lane][c] = varying_planes[slot * 4 + c].at(px, py) * w;
    }
}

}  // namespace st
