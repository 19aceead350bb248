// block_layout.h: where each lane of a 4x4 block sits, in llvmpipe's order
// (lp_rast_shade_quads_mask shades a 4x4 block as four 2x2 quads): quads
// (0,0), (2,0), (0,2), (2,2), and in each quad (x, y), (x+1, y), (x, y+1),
// (x+1, y+1), in GL window coordinates (y up). A fragment twin gets kLanes
// consecutive lanes of a block (kLanes / 4 whole quads); derivatives only
// ever look inside a quad, so neither the result nor this order depends on
// kLanes.
#pragma once

namespace st {

inline constexpr int kBlockSize = 4;    // pixels on a side
inline constexpr int kBlockLanes = 16;  // lanes of a whole block
// llvmpipe shades a block as two 8-lane vectors, its lower and its upper
// 4x2 half (lanes 0-7, 8-15). Some of its results depend on the whole
// vector (when a loop ends, which filter a mixed min/mag sampler uses:
// docs/llvmpipe/), so a twin always sees such groups whole: kLanes is 8 or
// 16, one group or two (of any blocks of the same triangle).
inline constexpr int kGroupLanes = 8;

constexpr int block_lane_x(int lane) { return ((lane >> 2) & 1) * 2 + (lane & 1); }
constexpr int block_lane_y(int lane) { return (lane >> 3) * 2 + ((lane >> 1) & 1); }
// The lane of the pixel at (dx, dy) inside its block.
constexpr int block_lane(int dx, int dy) { return (dy >> 1) * 8 + (dx >> 1) * 4 + (dy & 1) * 2 + (dx & 1); }

}  // namespace st
