// texture_files.cpp: see texture_files.h.
#include "scene/texture_files.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

#include "image/image_io.h"
#include "texture/srgb.h"
#include "scene/input_error.h"

namespace st {

namespace {

// The largest side a texture has (pattern_texture_fields' width domain).
constexpr int kMaxTextureSide = 4096;

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

// "auto": what the file says, else what its pixels suggest. Integer pixels
// (PNG, JPEG) are sRGB as painted and photographed unless the file calls
// itself linear; float pixels (EXR, HDR) are linear unless it says sRGB.
bool decodes_srgb(const std::string& colour_space, const ImageFileFormat& format) {
    if (colour_space != "auto") return colour_space == "srgb";
    const std::string said = lower(format.colour_space);
    const bool says_linear = said.find("linear") != std::string::npos || said.rfind("lin_", 0) == 0 || said == "raw";
    const bool says_srgb = !says_linear && said.find("srgb") != std::string::npos;
    return format.integer_pixels() ? !says_linear : says_srgb;
}

// An integer file's value as the exact fraction code / (2^bits - 1):
// OpenImageIO's own conversion to float may multiply by a rounded
// reciprocal, which the texture should not depend on.
double stored_value(float v, const ImageFileFormat& format) {
    const double top = format.pixel_type == "uint8" ? 255.0 : format.pixel_type == "uint16" ? 65535.0 : 0.0;
    if (top == 0.0 || !(v >= 0.0f && v <= 1.0f)) return v;
    return std::nearbyint(double(v) * top) / top;
}

// One face: the file's texels as the texture holds them (t.format), rows
// bottom-up when `flip` (t near 0 is the picture's bottom row).
void face_texels(const Image& image, const ImageFileFormat& format, bool srgb, bool flip, const Texture& t,
                 std::vector<uint8_t>& texels8, std::vector<float>& texels32) {
    const size_t w = size_t(image.width), h = size_t(image.height);
    for (size_t row = 0; row < h; ++row) {
        const size_t from = flip ? h - 1 - row : row;
        for (size_t x = 0; x < w; ++x) {
            const float* p = &image.rgba[(from * w + x) * 4];
            // Grey (and grey with alpha) is grey in every colour channel,
            // as image loaders expand it; read_image left it in red (and
            // the alpha in green).
            float rgba[4] = {p[0], p[1], p[2], p[3]};
            if (format.channels <= 2) rgba[1] = rgba[2] = p[0], rgba[3] = format.channels == 2 ? p[1] : 1.0f;
            for (int c = 0; c < 4; ++c) {
                double v = stored_value(rgba[c], format);
                if (srgb && c < 3) v = srgb_to_linear(v);  // alpha is stored linear
                if (t.format == TextureFormat::SRGB8_ALPHA8 && c < 3)  // encoded again: a PNG's bytes come through
                    texels8.push_back(unit_to_byte(linear_to_srgb(v)));
                else if (holds_bytes(t.format)) texels8.push_back(unit_to_byte(std::isnan(v) ? 0.0 : v));
                else texels32.push_back(float(v));
            }
        }
    }
}

}  // namespace

void read_texture_files(JsonReader& r, Texture& t, TexelBudget& budget) {
    // Every field's domain and default: pattern_texture_fields() in scene/shared_spaces.cpp.
    t.cube = r.boolean("cube");
    if (t.cube && r.has("file"))
        throw InputError("field '" + r.field("file") + "': a cube map reads six `files` (+x, -x, +y, -y, +z, -z)");
    if (!t.cube && r.has("files"))
        throw InputError("field '" + r.field("files") + "': six files make a cube map: set `cube` to true, or give one `file`");
    const std::string key = t.cube ? "files" : "file";
    if (!r.has(key)) throw InputError("missing field '" + r.field(key) + "' (pattern \"file\")");
    std::vector<std::string> paths = t.cube ? r.texts("files") : std::vector<std::string>{r.text("file")};
    for (std::string& p : paths) p = r.file_path(p);
    const std::string field = r.field(key);
    const std::string colour_space = r.choice("colour_space");
    // A cube's faces run top row first in GL's convention (its t axis
    // points down each face), so they are uploaded as stored.
    const bool upright = r.choice("orientation") == "upright";
    const bool flip = !t.cube && upright;
    for (size_t face = 0; face < paths.size(); ++face) {
        const std::string where = "field '" + field + (t.cube ? "." + std::to_string(face) : "") + "' (" + paths[face] + ")";
        Image image;
        ImageFileFormat format;
        try {
            image = read_image(paths[face], nullptr, &format);
        } catch (const std::runtime_error& e) {
            throw InputError("field '" + field + (t.cube ? "." + std::to_string(face) : "") + "': " + e.what());
        }
        if (image.width > kMaxTextureSide || image.height > kMaxTextureSide)
            throw InputError(where + ": " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                             " texels; a texture has at most " + std::to_string(kMaxTextureSide) + " a side");
        if (face == 0) {
            t.width = image.width, t.height = image.height;
            if (t.cube && t.width != t.height)
                throw InputError(where + ": a cube map's faces must be square (" + std::to_string(t.width) + "x" +
                                 std::to_string(t.height) + ")");
            budget.take(uint64_t(t.width) * uint64_t(t.height) * uint64_t(t.faces()) *
                            (holds_bytes(t.format) ? 4u : 16u),
                        field);
        } else if (image.width != t.width || image.height != t.height) {
            throw InputError(where + ": " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                             ", but the first face is " + std::to_string(t.width) + "x" + std::to_string(t.height));
        }
        face_texels(image, format, decodes_srgb(colour_space, format), flip, t, t.texels8, t.texels32);
    }
}

}  // namespace st
