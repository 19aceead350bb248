// attribute_setup.h: plane equations for depth, 1/w and the varyings of one
// triangle, with llvmpipe's arithmetic (lp_state_setup.c), so that the
// interpolated values agree with the GL reference to the bit.
#pragma once

#include <vector>

#include "raster/plane.h"
#include "raster/triangle_setup.h"
#include "shading/program.h"

namespace st {

// Appends, in this order: z (window depth, interpolated linearly), 1/w, then
// for each varying slot its four components: for a smooth slot premultiplied
// by 1/w (the perspective-correct numerators), for a noperspective one as
// they are, for a flat one v2's value as a0 (v2 is the provoking vertex:
// setup_triangle never moves it), read without arithmetic.
void setup_attribute_planes(const SetupVertex& v0, const SetupVertex& v1, const SetupVertex& v2,
                            int varying_count, const Interpolations& interpolation, std::vector<Plane>& planes);

}  // namespace st
