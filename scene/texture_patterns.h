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

// What one scene's generated textures may hold, levels and faces included,
// counted as each is read, before its texels are made: a scene asking for
// more is refused, naming the texture. (The memory check of
// app/memory_budget.h runs after loading; without this, 65 passes of 8
// cube maps could ask the host for a terabyte first.)
class TexelBudget {
public:
    // 1 GiB: eight 1024 x 1024 cube maps in RGBA32F with their mip chains;
    // one 4096 x 4096 cube map in RGBA32F (2 GiB with its chain) is refused.
    static constexpr uint64_t kBytes = uint64_t(1) << 30;
    // Adds a texture's bytes; InputError naming `field` past kBytes.
    void take(uint64_t bytes, const std::string& field);

private:
    uint64_t used_ = 0;
};

// Reads a texture object: {"format": "rgba8"|"rgba32f", "filter":
// "linear"|"nearest", "wrap": "repeat"|"clamp", "width", "height",
// "pattern": "checker"|"noise", "seed"}. `sampler` is the GLSL uniform name;
// the texels are taken from the scene's `budget`.
Texture read_pattern_texture(JsonReader& r, const std::string& sampler, TexelBudget& budget);

// The texture object at `key` of a scene kind that declares no space (a
// user's technique): the same fields, domains and defaults as the built-in
// kinds' textures (docs/scenes.md: a generated pattern or image files
// beside the scene, filters, wraps, LOD and mips), for the GLSL sampler
// `sampler`.
Texture read_texture_field(JsonReader& scene, const std::string& key, const std::string& sampler,
                           TexelBudget& budget);
// The same for a texture object already at hand (an element of an array of
// samplers: `"textures": [{...}, {...}]` for `uniform sampler2D textures[2]`).
Texture read_texture_object(JsonReader& r, const std::string& sampler, TexelBudget& budget);

}  // namespace st
