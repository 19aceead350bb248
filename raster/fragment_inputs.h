// fragment_inputs.h: fills the FragmentLanes of one part of a 4x4 block
// from a triangle's plane equations (perspective-correct varyings,
// gl_FragCoord), as llvmpipe's interpolation does it (lp_bld_interp.c):
// numerators and 1/w interpolated linearly on the screen, w = 1 / (1/w) per
// pixel, varying = numerator * w. Every lane is evaluated exactly as the
// scalar Plane::at would, so the result does not depend on kLanes.
#pragma once

#include "raster/plane.h"
#include "raster/tile_raster.h"
#include "shading/program.h"

namespace st {

// `part` selects lanes [part * kLanes, (part + 1) * kLanes) of the block.
void interpolate_lanes(const Plane* planes, int varying_count, const BlockCoverage& block, int part,
                       bool front_facing, FragmentLanes& out);

// Pixel index of each lane of a part of the block at (x, y).
Float lane_pixel_x(int block_x, int part);
Float lane_pixel_y(int block_y, int part);

}  // namespace st
