// texture_patterns.cpp: see texture_patterns.h.
#include "scene/texture_patterns.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>

#include "scene/input_error.h"
#include "scene/param_space.h"
#include "scene/scene_spaces.h"
#include "scene/texture_files.h"
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
    if (holds_bytes(format)) texels8.resize(n);
    else texels32.resize(n);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 4; ++c) {
                const size_t i = (size_t(y) * size_t(width) + size_t(x)) * 4 + size_t(c);
                uint32_t h = hash32(seed * 0x9e3779b9u ^ hash32(uint32_t(i)));
                if (checker) h = ((x / 4 + y / 4) % 2) ? 0xe0000000u + (uint32_t(c) << 26) : 0x20000000u;
                if (c == 3 && !checker) h |= 0x80000000u;  // alpha in [0.5, 1)
                if (holds_bytes(format)) texels8[i] = uint8_t(h >> 24);
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

void TexelBudget::take(uint64_t bytes, const std::string& field) {
    used_ += bytes;
    if (used_ > kBytes)
        throw InputError("field '" + field + "': the scene's textures would hold " +
                         std::to_string((used_ + (uint64_t(1) << 20) - 1) >> 20) + " MiB of texels, more than the " +
                         std::to_string(kBytes >> 20) + " MiB a scene's generated textures may");
}

Texture read_texture_field(JsonReader& scene, const std::string& key, const std::string& sampler,
                           TexelBudget& budget) {
    JsonReader r = scene.object(key);
    return read_texture_object(r, sampler, budget);
}

Texture read_texture_object(JsonReader& r, const std::string& sampler, TexelBudget& budget) {
    // One space per field path, declared the first time it is read and
    // kept (a reader holds a pointer to it).
    static std::mutex mutex;
    static std::map<std::string, std::unique_ptr<ParamSpace>> spaces;
    const std::string path = ParamSpace::normalise(r.path());  // an array's elements share "layers[]"
    const ParamSpace* space = nullptr;
    {
        const std::lock_guard<std::mutex> lock(mutex);
        std::unique_ptr<ParamSpace>& s = spaces[path];
        if (!s) {
            s = std::make_unique<ParamSpace>("texture");
            s->include(pattern_texture_fields(false), path);
        }
        space = s.get();
    }
    r.bind(*space);
    return read_pattern_texture(r, sampler, budget);
}

Texture read_pattern_texture(JsonReader& r, const std::string& sampler, TexelBudget& budget) {
    Texture t;
    t.sampler = sampler;
    // Every field's domain and default: pattern_texture_fields() in scene/shared_spaces.cpp.
    const std::string format = r.choice("format");
    t.format = format == "rgba8"          ? TextureFormat::RGBA8
               : format == "r32f"         ? TextureFormat::R32F
               : format == "rgba16f"      ? TextureFormat::RGBA16F
               : format == "srgb8_alpha8" ? TextureFormat::SRGB8_ALPHA8
                                          : TextureFormat::RGBA32F;
    // wrap_s and wrap_t default to wrap, mag_filter and min_filter to filter.
    const std::string wrap = r.choice("wrap");
    t.wrap_s = wrap_named(r.has("wrap_s") ? r.choice("wrap_s") : wrap);
    t.wrap_t = wrap_named(r.has("wrap_t") ? r.choice("wrap_t") : wrap);
    const std::string filter = r.choice("filter");
    t.mag_filter = filter_named(r.has("mag_filter") ? r.choice("mag_filter") : filter);
    const std::string min = r.has("min_filter") ? r.choice("min_filter") : filter;
    t.min_filter = filter_named(min);
    t.mip_filter = mip_filter_named(min);
    t.lod_bias = float(r.number("lod_bias"));
    t.min_lod = float(r.number("min_lod"));
    t.max_lod = float(r.number("max_lod"));
    // Where the kind declares `target` (a kind with render targets); where
    // not, a `target` is an unknown field.
    if (r.space()->find(ParamSpace::normalise(r.field("target"))) && r.has("target")) {
        // A render target: its size, format and levels are the target's.
        t.target = r.text("target");
        r.finish();
        return t;
    }
    const std::string pattern = r.choice("pattern");
    const bool from_files = pattern == "file";
    if (from_files) {
        read_texture_files(r, t, budget);  // size, faces and level 0
    } else {
        t.width = r.integer("width");
        t.height = r.integer("height");
        t.cube = r.boolean("cube");
        if (t.cube && t.width != t.height)
            throw InputError("field '" + r.field("height") + "': a cube map's faces must be square (width " +
                             std::to_string(t.width) + ", height " + std::to_string(t.height) + ")");
    }
    if (t.cube && t.format == TextureFormat::SRGB8_ALPHA8)
        throw InputError("field '" + r.field("format") + "': an srgb8_alpha8 cube map is not modelled (2D textures only)");
    if (t.cube && t.min_filter != t.mag_filter)
        throw InputError("field '" + r.field("mag_filter") +
                         "': a cube map needs the same min and mag filter (the switch is not modelled)");
    // Mip levels: none, a box filter of level 0 ("box"), or each level its
    // own pattern ("distinct", seeded per level), which shows in every texel
    // which level a sample took.
    const std::string mipmaps = r.choice("mipmaps");
    if (from_files && mipmaps == "distinct")
        throw InputError("field '" + r.field("mipmaps") + "': `distinct` levels are generated patterns; a file's "
                         "chain is `box` (or `none`)");
    const int full = full_chain_levels(t.width, t.height);
    const int levels = mipmaps == "none" ? 1 : r.has("levels") ? r.integer_in("levels", 1, full) : full;
    // (Float formats are held as four floats a texel, RGBA8 as four bytes;
    // a file's level 0 is already taken.)
    uint64_t bytes = 0;
    for (int level = from_files ? 1 : 0; level < levels; ++level)
        bytes += uint64_t(std::max(1, t.width >> level)) * uint64_t(std::max(1, t.height >> level)) *
                 uint64_t(t.faces()) * (holds_bytes(t.format) ? 4u : 16u);
    budget.take(bytes, r.field(from_files ? "mipmaps" : "width"));
    const bool checker = pattern == "checker";
    const auto seed = from_files ? 0u : uint32_t(r.integer("seed"));
    if (!from_files) fill_faces(t, t.width, t.height, checker, seed, t.texels8, t.texels32);
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
