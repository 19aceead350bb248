// profile_thickness.h: a thickness map for thin profile geometry (Donner
// and Jensen Sec. 4, the leaf of Figure 6): "effectively used as a
// displacement map, which increases the distance of the diffused lighting".
// surface.frag moves each texel's position along its normal by height_mm
// times the map, so that the gather's distances between texels grow across
// the veins; the profiles themselves stay those of the stack's thickness
// (the paper's approximation, and ours).
#pragma once

#include "frame/frame.h"
#include "scene/json_reader.h"
#include "scene/profile_shape.h"

namespace st {

struct ThicknessMap {
    double height_mm = 0;      // displacement at map value 1; 0: no map
    double vein_spacing_mm = 4;
    double vein_width_mm = 0.25;
};

// Reads geometry.thickness_map (absent: none); InputError names a bad field.
ThicknessMap read_thickness_map(JsonReader& geometry, const ProfileShape& shape);

// The map at the texture-space targets' size, one texel per target texel
// (surface.frag reads it with texelFetch): a leaf's veins, a midrib along
// the layout's v through u = 1/2 and side veins leaving it at 40 degrees
// every vein_spacing_mm, each a Gaussian ridge of the given width. A 1x1
// zero when there is no map.
Texture thickness_texture(const ThicknessMap& map, const ProfileShape& shape, int size);

}  // namespace st
