// bilinear_taps.h: where a bilinear textureLod at level 0 reads, computed
// once for several textures of one shape. A gather reads its texture-space
// targets (position, normal, irradiance) at the same point and its R(r) and
// T(r) tables at the same radius; the taps, weights and lane offsets
// depend only on the coordinate and the textures' size and wrap, so they
// are found once and each texture only loads and filters
// (Sampler2D::bilinear_taps, Sampler2D::sample_lod(taps)).
#pragma once

#include "simd/lane_vec.h"

namespace st {

struct BilinearTaps {
    Vec2 st;                        // the coordinate: a texture of another shape samples it afresh
    int width = 0, height = 0;      // the shape the taps are for (0: the first texture is no clamped bilinear one)
    simd::LaneOffsets row0{Int(0)};  // per lane, the float offset of the left tap in the lower row
    simd::LaneOffsets row1{Int(0)};  // and in the upper row (unused for a texture one texel high)
    Mask at_last_column;            // the right tap is the left one (CLAMP_TO_EDGE at the last column)
    Float wu, wv;                   // the weights along s and t
};

}  // namespace st
