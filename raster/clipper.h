// clipper.h: clipping of a triangle against the near and far planes
// (-w <= z <= w), the only planes llvmpipe clips geometrically; x and y are
// left to the rasterizer inside the guard band.
#pragma once

#include <vector>

#include "kernels/program.h"

namespace st {

// True when a vertex is outside the near or far plane.
inline bool outside_near_far(const glm::vec4& clip) {
    return clip.z < -clip.w || clip.z > clip.w;
}

// Clips triangle (a, b, c) and writes the resulting convex polygon (0, or 3
// to 5 vertices, in the triangle's winding) to `polygon`. New vertices
// interpolate position and every varying linearly in clip space.
void clip_near_far(const VertexOut& a, const VertexOut& b, const VertexOut& c, int varying_count,
                   std::vector<VertexOut>& polygon);

}  // namespace st
