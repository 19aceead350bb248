// relief_maps.h: the generated assets of the relief-mapping scenes
// (Timonen): height fields for the solid layer (stones) and for the surface
// of the translucent medium (drops on a film of liquid), the relief maps
// made from them (normal in RGB, height in A, as Policarpo et al. pack
// them), and the stones' colour map. Deterministic for a seed, tileable
// (REPEAT wraps them seamlessly), computed in double and stored as RGBA8
// with full mip chains; nothing is downloaded and nothing is written to disk.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "frame/frame.h"

namespace st {

// Heights in [0, 1] on a size x size torus: 1 is the top of the layer's
// bounding box, 0 its floor. Row 0 is t near 0 (texture order).
struct HeightField {
    int size = 0;
    std::vector<double> h;  // [y * size + x]
    double at(int x, int y) const;  // wraps both coordinates
};

struct StoneParams {
    int size = 256;     // texels per side
    int cells = 5;      // stones per side (a jittered Voronoi grid)
    uint32_t seed = 1;
    double mortar = 0.06;  // half-width of the joints, in cells
    double bevel = 0.22;   // width of a stone's rounded edge, in cells
};
HeightField stone_heights(const StoneParams& p);

struct DropParams {
    int size = 256;
    int drops = 14;
    uint32_t seed = 2;
    double level = 0.25;       // the film between the drops (0: none above the floor)
    double min_radius = 0.04;  // in texture coordinates
    double max_radius = 0.11;
    double min_peak = 0.55, max_peak = 0.95;  // height of a drop's apex
};
HeightField drop_heights(const DropParams& p);

// The tangent-space normal of the surface z = depth * h(u, v) (u, v in
// texture coordinates, depth the layer's thickness in the same units), by
// central differences, packed n * 0.5 + 0.5 in RGB and h in A; RGBA8,
// trilinear (LINEAR_MIPMAP_LINEAR), REPEAT, box-filtered mips.
Texture relief_texture(const HeightField& field, double depth, const std::string& sampler);

// The stones' colour: a hue and brightness per stone, fine grain, lighter
// joints. RGBA8 (alpha 1), trilinear, REPEAT, box-filtered mips.
Texture stone_colour_texture(const StoneParams& p, const std::string& sampler);

// An HDR sky for the environment (the paper's Fig. 9 reflects one): a
// zenith-to-horizon gradient, a sun of `sun_radiance` in a disc of
// `sun_radius_deg` with a glow around it, and dark ground below the horizon;
// z is up (the surface's normal). Six square RGBA32F faces of `size`
// texels in GL's order and orientation, LINEAR, no mips.
Texture sky_cube_texture(int size, glm::dvec3 sun_direction, double sun_radiance, double sun_radius_deg,
                         const std::string& sampler);

}  // namespace st
