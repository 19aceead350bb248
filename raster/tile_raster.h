// tile_raster.h: which 2x2 quads of one tile a triangle covers.
//
// Tiles are 64x64 pixels as in llvmpipe; quads start at even pixel indices.
// A quad is emitted when at least one of its four pixel centres is inside
// all three edges; the mask says which (lane order as in FragmentQuad).
#pragma once

#include <cstdint>
#include <vector>

#include "raster/triangle_setup.h"

namespace st {

inline constexpr int kTileSize = 64;

struct QuadCoverage {
    int x = 0, y = 0;    // pixel index of lane 0, both even
    unsigned mask = 0;   // bit i = lane i covered
};

// Pixel rectangle [x0, x1) x [y0, y1) of the tile, already clipped to the
// target; x0 and y0 even.
struct TileRect {
    int x0, y0, x1, y1;
};

void rasterize_in_tile(const SetupTriangle& tri, const TileRect& tile, std::vector<QuadCoverage>& out);

}  // namespace st
