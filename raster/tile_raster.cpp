// tile_raster.cpp: edge functions stepped over the quads of one tile.
#include "raster/tile_raster.h"

#include <algorithm>

namespace st {

void rasterize_in_tile(const SetupTriangle& tri, const TileRect& tile, std::vector<QuadCoverage>& out) {
    const int x_lo = std::max(tri.x_min, tile.x0) & ~1, y_lo = std::max(tri.y_min, tile.y0) & ~1;
    const int x_hi = std::min(tri.x_max, tile.x1 - 1), y_hi = std::min(tri.y_max, tile.y1 - 1);
    if (x_lo > x_hi || y_lo > y_hi) return;
    const EdgeFunction* e = tri.edge;
    for (int y = y_lo; y <= y_hi; y += 2) {
        // Values at lane 0 of the first quad in this row; stepping by the
        // exact integer increments keeps this identical to evaluating at()
        // at every pixel.
        int64_t row[3] = {e[0].at(x_lo, y), e[1].at(x_lo, y), e[2].at(x_lo, y)};
        for (int x = x_lo; x <= x_hi; x += 2) {
            unsigned mask = 0;
            for (int lane = 0; lane < 4; ++lane) {
                const int dx = lane & 1, dy = lane >> 1;
                const int px = x + dx, py = y + dy;
                bool inside = px >= tri.x_min && px <= x_hi && py >= tri.y_min && py <= y_hi;
                for (int i = 0; i < 3 && inside; ++i)
                    inside = row[i] + e[i].dcdx * dx + e[i].dcdy * dy > 0;
                mask |= unsigned(inside) << lane;
            }
            if (mask) out.push_back({x, y, mask});
            for (int i = 0; i < 3; ++i) row[i] += 2 * e[i].dcdx;
        }
    }
}

}  // namespace st
