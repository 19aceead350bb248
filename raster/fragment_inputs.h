// fragment_inputs.h: fills the FragmentLanes of one twin call from a
// triangle's plane equations (perspective-correct varyings, gl_FragCoord),
// as llvmpipe's interpolation does it (lp_bld_interp.c): numerators and 1/w
// interpolated linearly on the screen, w = 1 / (1/w) per pixel, varying =
// numerator * w. Every lane is evaluated exactly as the scalar Plane::at
// would, so the result depends neither on kLanes nor on which groups share
// a call.
#pragma once

#include <cstdint>

#include "raster/plane.h"
#include "shading/program.h"

namespace st {

// One 8-lane group of a 4x4 block (its lower or upper 4x2 half) that a
// triangle covers at least partly.
struct LaneGroup {
    int x = 0, y = 0;     // the block's lower-left pixel
    int half = 0;         // 0: lanes 0-7 of the block, 1: lanes 8-15
    unsigned mask = 0;    // bit i = lane i of the group covered
};

// groups[0 .. kLanes / 8) fill lanes [8g, 8g + 8). Only the varying
// components in `components` (FragmentTwin::inputs_read) are interpolated;
// the others are NaN. A smooth slot's value is its plane times w, a
// noperspective slot's its plane, a flat slot's the plane's a0 in every
// lane, bit for bit (llvmpipe's LP_INTERP_CONSTANT: no arithmetic that
// could quiet a NaN pattern, flush a denormal or turn -0 into +0, since an
// int varying travels in those bits).
void interpolate_lanes(const Plane* planes, int varying_count, uint32_t components,
                       const Interpolations& interpolation, const LaneGroup* groups, bool front_facing,
                       FragmentLanes& out);

}  // namespace st
