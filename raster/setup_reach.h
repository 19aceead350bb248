// setup_reach.h: can a triangle given in clip space be set up as llvmpipe
// sets it up? Clipped to the view volume (clipper.h), every window position
// it ends with must lie on the fixed-point grid setup snaps to
// (fixed_point.h). Where one does not, llvmpipe converts it to INT32_MIN and
// rasterizes whatever its wrapped int32 edge arithmetic yields (measured: a
// 64-pixel bar or a lit tile where nothing was asked for), which no twin
// should reproduce; the CPU renderer refuses such a pass.
//
// A scene reader whose positions reach the clipper unchanged (a pass-through
// vertex program) asks this of each triangle it reads, so that the refusal
// names the field before anything renders. The usual cause is not one large
// number but a range: clipping interpolates in float, so a triangle whose
// coordinates span more than about 2^23 of each other loses the clipped
// vertex's position in the rounding (1e21 pixels off for a vertex at 1e30).
#pragma once

#include <optional>

#include <glm/vec4.hpp>

#include "raster/viewport.h"

namespace st {

// The first window position of triangle (a, b, c) that setup cannot snap,
// after clipping as the binner clips, or nothing when every one can (or the
// triangle is clipped away whole).
std::optional<WindowPos> first_unsnappable_position(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c,
                                                    const Viewport& viewport);

}  // namespace st
