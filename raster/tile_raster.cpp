// tile_raster.cpp: edge functions stepped over the 4x4 blocks of one tile.
#include "raster/tile_raster.h"

#include <algorithm>

namespace st {

void rasterize_in_tile(const SetupTriangle& tri, const TileRect& tile, std::vector<BlockCoverage>& out) {
    const int x_lo = std::max(tri.x_min, tile.x0) & ~3, y_lo = std::max(tri.y_min, tile.y0) & ~3;
    const int x_hi = std::min(tri.x_max, tile.x1 - 1), y_hi = std::min(tri.y_max, tile.y1 - 1);
    if (x_lo > x_hi || y_lo > y_hi) return;
    const EdgeFunction* e = tri.edge;
    // Each edge's value at every lane of a block, relative to the block's
    // corner: exact integers, so stepping equals evaluating at() per pixel.
    int64_t lane_offset[3][kBlockLanes];
    for (int i = 0; i < 3; ++i)
        for (int lane = 0; lane < kBlockLanes; ++lane)
            lane_offset[i][lane] = e[i].dcdx * block_lane_x(lane) + e[i].dcdy * block_lane_y(lane);
    for (int y = y_lo; y <= y_hi; y += kBlockSize) {
        int64_t row[3] = {e[0].at(x_lo, y), e[1].at(x_lo, y), e[2].at(x_lo, y)};
        for (int x = x_lo; x <= x_hi; x += kBlockSize) {
            unsigned mask = 0;
            for (int lane = 0; lane < kBlockLanes; ++lane) {
                const int px = x + block_lane_x(lane), py = y + block_lane_y(lane);
                bool inside = px >= tri.x_min && px <= x_hi && py >= tri.y_min && py <= y_hi;
                for (int i = 0; i < 3; ++i) inside = inside && row[i] + lane_offset[i][lane] > 0;
                mask |= unsigned(inside) << lane;
            }
            if (mask) out.push_back({x, y, mask});
            for (int i = 0; i < 3; ++i) row[i] += kBlockSize * e[i].dcdx;
        }
    }
}

}  // namespace st
