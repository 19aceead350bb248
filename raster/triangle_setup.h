// triangle_setup.h: from three window-space vertices to what the tile
// rasterizer needs: integer edge functions on the 1/256-pixel grid, a pixel
// bounding box, facing, and plane equations for depth, 1/w and varyings.
//
// This is the counterpart of llvmpipe's lp_setup_tri.c (edges) and
// lp_state_setup.c (attribute planes); rasterization itself is in
// tile_raster.h.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec4.hpp>

#include "raster/plane.h"
#include "raster/viewport.h"
#include "shading/program.h"

namespace st {

// E(px, py) = c + dcdx * px + dcdy * py, evaluated at pixel indices; the pixel
// is inside the edge when E > 0. The fill rule is folded into c.
struct EdgeFunction {
    int64_t c = 0, dcdx = 0, dcdy = 0;
    int64_t at(int px, int py) const { return c + dcdx * px + dcdy * py; }
};

struct SetupVertex {
    WindowPos pos;
    const glm::vec4* varyings = nullptr;  // varying_count vec4 slots
};

struct SetupTriangle {
    EdgeFunction edge[3];
    int x_min = 0, y_min = 0, x_max = -1, y_max = -1;  // pixel indices, inclusive
    bool front_facing = true;
    uint32_t draw = 0;         // index of the draw call in the pass
    uint32_t first_plane = 0;  // into the pass's plane storage: z, 1/w, then varyings
};

// True when every vertex's window x and y can be snapped (fixed_point.h);
// setup_triangle drops a triangle for which this is false.
bool snappable(const SetupVertex& v0, const SetupVertex& v1, const SetupVertex& v2);

// Returns false when the triangle covers no pixel centre of the target
// (zero area, or its box misses the target) or is not snappable(). On success appends
// 2 + 4 * varying_count planes to `planes`.
bool setup_triangle(const SetupVertex& v0, const SetupVertex& v1, const SetupVertex& v2,
                    int varying_count, const Interpolations& interpolation, int target_width,
                    int target_height, SetupTriangle& tri, std::vector<Plane>& planes);

}  // namespace st
