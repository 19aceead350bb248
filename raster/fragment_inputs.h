// fragment_inputs.h: fills a FragmentQuad from a triangle's plane equations
// (perspective-correct varyings, gl_FragCoord), as llvmpipe's interpolation
// does it (lp_bld_interp.c): numerators and 1/w interpolated linearly on the
// screen, w = 1 / (1/w) per pixel, varying = numerator * w.
#pragma once

#include "shading/program.h"
#include "raster/plane.h"
#include "raster/tile_raster.h"

namespace st {

void interpolate_quad(const Plane* planes, int varying_count, const QuadCoverage& quad,
                      bool front_facing, FragmentQuad& out);

}  // namespace st
