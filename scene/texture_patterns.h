// texture_patterns.h: deterministic procedural textures for scenes, so no
// image file has to ship and both backends get the same texels.
#pragma once

#include <cstdint>
#include <string>

#include "frame/frame.h"
#include "scene/json_reader.h"

namespace st {

// A 32-bit integer hash (lowbias32): cheap, well mixed, platform-independent;
// the one every generated texture draws its randomness from.
uint32_t hash32(uint32_t x);

// A value in [0, 1] as an 8-bit texel, rounded to nearest (clamped first).
uint8_t unit_to_byte(double v);

// Reads a texture object: {"format": "rgba8"|"rgba32f", "filter":
// "linear"|"nearest", "wrap": "repeat"|"clamp", "width", "height",
// "pattern": "checker"|"noise", "seed"}. `sampler` is the GLSL uniform name.
Texture read_pattern_texture(JsonReader& r, const std::string& sampler);

}  // namespace st
