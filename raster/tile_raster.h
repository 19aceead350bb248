// tile_raster.h: which 4x4 blocks of one tile a triangle covers.
//
// Tiles are 64x64 pixels and blocks 4x4, as in llvmpipe; blocks start at
// pixel indices that are multiples of 4. A block is emitted when at least
// one of its sixteen pixel centres is inside all three edges; the mask says
// which, bit i for lane i of the block (shading/block_layout.h).
#pragma once

#include <cstdint>
#include <vector>

#include "raster/triangle_setup.h"
#include "shading/block_layout.h"

namespace st {

inline constexpr int kTileSize = 64;

struct BlockCoverage {
    int x = 0, y = 0;    // pixel index of the block's lower-left pixel, multiples of 4
    unsigned mask = 0;   // bit i = lane i covered (16 bits)
};

// Pixel rectangle [x0, x1) x [y0, y1) of the tile, already clipped to the
// target; x0 and y0 multiples of 4.
struct TileRect {
    int x0, y0, x1, y1;
};

void rasterize_in_tile(const SetupTriangle& tri, const TileRect& tile, std::vector<BlockCoverage>& out);

}  // namespace st
