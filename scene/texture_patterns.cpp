// texture_patterns.cpp: see texture_patterns.h.
#include "scene/texture_patterns.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "scene/input_error.h"
#include "texture/mip_generation.h"

namespace st {

uint32_t hash32(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

uint8_t unit_to_byte(double v) { return uint8_t(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); }

namespace {

// Fills one level with the pattern.
void fill(int width, int height, TextureFormat format, bool checker, uint32_t seed, std::vector<uint8_t>& texels8,
          std::vector<float>& texels32) {
    const size_t n = size_t(width) * size_t(height) * 4;
    if (format == TextureFormat::RGBA8) texels8.resize(n);
    else texels32.resize(n);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 4; ++c) {
                const size_t i = (size_t(y) * size_t(width) + size_t(x)) * 4 + size_t(c);
                uint32_t h = hash32(seed * 0x9e3779b9u ^ hash32(uint32_t(i)));
                if (checker) h = ((x / 4 + y / 4) % 2) ? 0xe0000000u + (uint32_t(c) << 26) : 0x20000000u;
                if (c == 3 && !checker) h |= 0x80000000u;  // alpha in [0.5, 1)
                if (format == TextureFormat::RGBA8) texels8[i] = uint8_t(h >> 24);
                else texels32[i] = float(h >> 8) * (1.0f / 16777216.0f);  // 24 bits: exact
            }
}

// Every face of a level (one for a 2D texture), each face seeded apart.
void fill_faces(const Texture& t, int width, int height, bool checker, uint32_t seed, std::vector<uint8_t>& texels8,
                std::vector<float>& texels32) {
    std::vector<uint8_t> face8;
    std::vector<float> face32;
    for (int face = 0; face < t.faces(); ++face) {
        fill(width, height, t.format, checker, seed + uint32_t(face) * 101u, face8, face32);
        texels8.insert(texels8.end(), face8.begin(), face8.end());
        texels32.insert(texels32.end(), face32.begin(), face32.end());
    }
}

TextureWrap wrap_named(const std::string& name) {
    if (name == "clamp") return TextureWrap::ClampToEdge;
    if (name == "mirrored_repeat") return TextureWrap::MirroredRepeat;
    return TextureWrap::Repeat;
}

TextureFilter filter_named(const std::string& name) {
    return name.rfind("linear", 0) == 0 ? TextureFilter::Linear : TextureFilter::Nearest;
}

MipFilter mip_filter_named(const std::string& name) {
    const auto at = name.find("_mipmap_");
    if (at == std::string::npos) return MipFilter::None;
    return name.substr(at + 8) == "linear" ? MipFilter::Linear : MipFilter::Nearest;
}

}  // namespace

Texture read_pattern_texture(JsonReader& r, const std::string& sampler) {
    Texture t;
    t.sampler = sampler;
    const std::string format = r.choice_or("format", "rgba32f", {"rgba8", "r32f", "rgba16f", "rgba32f"});
    t.format = format == "rgba8"     ? TextureFormat::RGBA8
               : format == "r32f"    ? TextureFormat::R32F
               : format == "rgba16f" ? TextureFormat::RGBA16F
                                     : TextureFormat::RGBA32F;
    const std::vector<std::string> wraps = {"repeat", "clamp", "mirrored_repeat"};
    const std::string wrap = r.choice_or("wrap", "repeat", wraps);
    t.wrap_s = wrap_named(r.choice_or("wrap_s", wrap, wraps));
    t.wrap_t = wrap_named(r.choice_or("wrap_t", wrap, wraps));
    const std::string filter = r.choice_or("filter", "linear", {"linear", "nearest"});
    t.mag_filter = filter_named(r.choice_or("mag_filter", filter, {"linear", "nearest"}));
    const std::string min = r.choice_or("min_filter", filter,
                                        {"nearest", "linear", "nearest_mipmap_nearest", "linear_mipmap_nearest",
                                         "nearest_mipmap_linear", "linear_mipmap_linear"});
    t.min_filter = filter_named(min);
    t.mip_filter = mip_filter_named(min);
    t.lod_bias = float(r.number_or("lod_bias", 0.0, -1000.0, 1000.0));
    t.min_lod = float(r.number_or("min_lod", -1000.0, -1000.0, 1000.0));
    t.max_lod = float(r.number_or("max_lod", 1000.0, -1000.0, 1000.0));
    if (r.has("target")) {
        // A render target: its size, format and levels are the target's.
        t.target = r.string("target");
        r.finish();
        return t;
    }
    t.width = r.integer("width", 1, 4096);
    t.height = r.integer("height", 1, 4096);
    t.cube = r.boolean_or("cube", false);
    if (t.cube && t.width != t.height)
        throw InputError("field '" + r.field("height") + "': a cube map's faces must be square (width " +
                         std::to_string(t.width) + ", height " + std::to_string(t.height) + ")");
    if (t.cube && t.min_filter != t.mag_filter)
        throw InputError("field '" + r.field("mag_filter") +
                         "': a cube map needs the same min and mag filter (the switch is not modelled)");
    const bool checker = r.choice_or("pattern", "noise", {"checker", "noise"}) == "checker";
    const auto seed = uint32_t(r.integer_or("seed", 1, 0, 1 << 30));
    fill_faces(t, t.width, t.height, checker, seed, t.texels8, t.texels32);

    // Mip levels: none, a box filter of level 0 ("box"), or each level its
    // own pattern ("distinct", seeded per level), which shows in every texel
    // which level a sample took.
    const std::string mipmaps = r.choice_or("mipmaps", "none", {"none", "box", "distinct"});
    const int full = full_chain_levels(t.width, t.height);
    const int levels = mipmaps == "none" ? 1 : r.integer_or("levels", full, 1, full);
    if (mipmaps == "box") generate_box_mips(t, levels);
    if (mipmaps == "distinct")
        for (int level = 1; level < levels; ++level) {
            TextureLevel l;
            l.width = std::max(1, t.width >> level);
            l.height = std::max(1, t.height >> level);
            fill_faces(t, l.width, l.height, checker, seed + uint32_t(level) * 7919u, l.texels8, l.texels32);
            t.mips.push_back(std::move(l));
        }
    r.finish();
    return t;
}

}  // namespace st
