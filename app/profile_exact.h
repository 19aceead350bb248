// profile_exact.h: the exact image of a "profile" scene on its flat slab
// (issue 11's ground truth for the gather): per pixel, the point of the slab
// the pixel centre sees, and there the light leaving it, the 2D convolution
// of the irradiance pattern (a spot and a half-plane beyond a shadow edge)
// with the material's R(r) (light entering this face) and T(r) (light
// entering the other face of a thin slab), in double precision
// (reference/profile_convolution.h), shown as the gather shows it, M / pi.
#pragma once

#include <cstdint>
#include <vector>

#include "image/image.h"
#include "scene/scene.h"

namespace st {

struct ProfileExact {
    Image image;                    // RGB M / pi, alpha 1; NaN where the pixel sees no slab
    // 1 where the point lies at least margin_mm inside the slab's edges
    // (where the slab, finite, is the convolution's infinite plane to a
    // thousandth of the profile's total), 2 in the band nearer the edges,
    // 0 off the slab.
    std::vector<uint8_t> region;
    double reach_mm = 0;   // the gather's (the tables' last radius)
    double margin_mm = 0;
    // The convolutions are tabulated against distance from the edge and from
    // the spot's centre and read linearly: the worst error of that, checked
    // at every interval's midpoint, as a share of the profile's total.
    double table_error = 0;
};

// Throws InputError unless the scene is a flat "profile" slab with a smooth
// or rough boundary whose spot lies wholly on the shadowed side of its edge
// (so that the lit region is their disjoint union).
ProfileExact exact_profile_image(const Scene& scene);

}  // namespace st
