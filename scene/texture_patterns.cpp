// texture_patterns.cpp: see texture_patterns.h.
#include "scene/texture_patterns.h"

#include <cstdint>

namespace st {

namespace {

// A 32-bit integer hash (lowbias32): cheap, well mixed, platform-independent.
uint32_t hash32(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

}  // namespace

Texture read_pattern_texture(JsonReader& r, const std::string& sampler) {
    Texture t;
    t.sampler = sampler;
    t.format = r.choice_or("format", "rgba32f", {"rgba8", "rgba32f"}) == "rgba8" ? TextureFormat::RGBA8
                                                                                  : TextureFormat::RGBA32F;
    t.filter = r.choice_or("filter", "linear", {"linear", "nearest"}) == "linear" ? TextureFilter::Linear
                                                                                  : TextureFilter::Nearest;
    t.wrap = r.choice_or("wrap", "repeat", {"repeat", "clamp"}) == "repeat" ? TextureWrap::Repeat
                                                                            : TextureWrap::ClampToEdge;
    t.width = r.integer("width", 1, 4096);
    t.height = r.integer("height", 1, 4096);
    const bool checker = r.choice_or("pattern", "noise", {"checker", "noise"}) == "checker";
    const auto seed = uint32_t(r.integer_or("seed", 1, 0, 1 << 30));

    const size_t n = size_t(t.width) * t.height * 4;
    if (t.format == TextureFormat::RGBA8) t.texels8.resize(n);
    else t.texels32.resize(n);
    for (int y = 0; y < t.height; ++y)
        for (int x = 0; x < t.width; ++x)
            for (int c = 0; c < 4; ++c) {
                const size_t i = (size_t(y) * t.width + x) * 4 + c;
                uint32_t h = hash32(seed * 0x9e3779b9u ^ hash32(uint32_t(i)));
                if (checker) h = ((x / 4 + y / 4) % 2) ? 0xe0000000u + (uint32_t(c) << 26) : 0x20000000u;
                if (c == 3 && !checker) h |= 0x80000000u;  // alpha in [0.5, 1)
                if (t.format == TextureFormat::RGBA8) t.texels8[i] = uint8_t(h >> 24);
                else t.texels32[i] = float(h >> 8) * (1.0f / 16777216.0f);  // 24 bits: exact
            }
    r.finish();
    return t;
}

}  // namespace st
