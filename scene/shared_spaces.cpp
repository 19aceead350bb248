// shared_spaces.cpp: blocks of fields more than one kind declares (see
// scene_spaces.h): a procedural texture (scene/texture_patterns.cpp reads
// it) and a list of triangles (scene/triangle_list.cpp).
#include "scene/json_reader.h"
#include "scene/scene_spaces.h"

namespace st {

ParamSpace pattern_texture_fields(bool render_targets) {
    ParamSpace s("texture");
    const std::vector<std::string> wraps = {"repeat", "clamp", "mirrored_repeat"};
    const std::vector<std::string> mins = {"nearest", "linear", "nearest_mipmap_nearest", "linear_mipmap_nearest",
                                           "nearest_mipmap_linear", "linear_mipmap_linear"};
    s.choice("format", {"rgba8", "r32f", "rgba16f", "rgba32f", "srgb8_alpha8"}, "rgba32f",
             "texel format; `srgb8_alpha8` holds sRGB-encoded bytes that the sampler decodes per texel before "
             "filtering, as GL_SRGB8_ALPHA8 (2D textures)");
    s.choice("wrap", wraps, "repeat", "both directions' wrap mode (clamp: to edge)");
    s.choice("wrap_s", wraps, nullptr, "the s direction's (default: `wrap`)");
    s.choice("wrap_t", wraps, nullptr, "the t direction's (default: `wrap`)");
    s.choice("filter", {"linear", "nearest"}, "linear", "both filters");
    s.choice("mag_filter", {"linear", "nearest"}, nullptr, "magnification filter (default: `filter`)");
    s.choice("min_filter", mins, nullptr, "minification filter and mip filter (default: `filter`)");
    s.number("lod_bias", -1000, 1000, 0.0, "GL_TEXTURE_LOD_BIAS").draws(-4, 4).edge({0, -0.5, 0.5});
    s.number("min_lod", -1000, 1000, -1000.0, "GL_TEXTURE_MIN_LOD").draws(-2, 12).edge({0});
    s.number("max_lod", -1000, 1000, 1000.0, "GL_TEXTURE_MAX_LOD").draws(-2, 12).edge({0});
    if (render_targets)
        s.text("target", nullptr,
               "the texture is this render target as earlier passes left it; then only the filter, wrap and LOD "
               "fields apply");
    // A generated pattern or image files (no `target`):
    s.choice("pattern", {"checker", "noise", "file"}, "noise",
             "4x4-texel checks, hashed texels with alpha in [0.5, 1), or image files (`file`, or `files` for a cube)")
        .explore_choices({"checker", "noise"});  // a file it cannot make up
    const std::vector<std::string> generated = {"checker", "noise"};
    s.integer("width", 1, 4096, "required",
              "texels across (a scene's textures hold at most 1 GiB, levels and faces included)")
        .explore_at_most(1024)
        .edge({1, 2, 3, 64, 65})
        .when("pattern", generated);
    s.integer("height", 1, 4096, "required", "texels up (a cube's faces are square)").explore_at_most(1024)
        .edge({1, 2, 3, 64, 65})
        .when("pattern", generated);
    s.boolean("cube", false, "six square faces, sampled with seamless filtering (min and mag filter alike)")
        .not_explored();  // the program's sampler type (sampler2D or samplerCube) decides it
    s.integer("seed", 0, 1 << 30, 1, "the noise's hash seed").when("pattern", generated);
    s.text("file", nullptr,
           "a 2D texture's image (PNG, EXR, HDR, JPEG, TIFF: whatever OpenImageIO reads), relative to the scene "
           "file's folder; its size is the texture's, at most 4096 a side; values as stored (an 8- or 16-bit file's "
           "exact fractions, colour not multiplied by alpha), grey in red, green and blue, a missing alpha 1")
        .when("pattern", {"file"})
        .file_path();
    s.texts("files", 6, 6, nullptr,
            "a cube map's six faces in GL's order +x, -x, +y, -y, +z, -z (`cube` true), square and of one size, "
            "each relative to the scene file's folder")
        .when("pattern", {"file"})
        .file_path();
    s.choice("colour_space", {"auto", "srgb", "linear"}, "auto",
             "the files' encoding: `srgb` is decoded to linear on load (IEC 61966-2-1, alpha as stored), as an asset "
             "pipeline does, and the texture holds linear values in `format`; `linear` is taken as stored; `auto` is "
             "what the file says it is, else sRGB for integer pixels (PNG, JPEG) and linear for float ones (EXR, "
             "HDR). With `format` `srgb8_alpha8` the texels are encoded back to sRGB bytes, which the sampler decodes")
        .when("pattern", {"file"});
    s.choice("orientation", {"upright", "as_stored"}, "upright",
             "`upright`: a 2D texture's t = 1 is the picture's top row (the rows are flipped on upload, as OpenGL "
             "programs that load images do); `as_stored`: the file's first row is t near 0. Cube faces are uploaded "
             "as stored either way (GL's faces run top row first)")
        .when("pattern", {"file"});
    s.choice("mipmaps", {"none", "box", "distinct"}, "none",
             "mip levels: none, a box filter of level 0, or each level its own pattern (not for files)");
    s.integer("levels", 1, 13, nullptr, "mip levels, at most the full chain of width x height (default: all of it)")
        .when("mipmaps", {"box", "distinct"}).edge({1, 2});
    return s;
}

ParamSpace triangle_list_fields(bool pixels_only, bool colour_optional, bool uvs_always, double max_uv,
                                bool required) {
    ParamSpace s("triangles");
    FieldSpec& triangles = s.object("triangles", required,
                                    required ? "the triangles, in draw order" : "the triangles, in draw order (or `cells`)",
                                    1, 1 << 20);
    triangles.explore_at_most(10000);
    if (!required) triangles.only_if_present();  // one of two forms: the explorer keeps the one given
    const std::string clip = "clip space: [x, y], [x, y, z] or [x, y, z, w] (z defaults to 0, w to 1, w must not be "
                             "0 as a float)";
    const std::string pixels = "window pixels (y up, origin bottom-left): [x, y] or [x, y, depth], depth in [0, 1] "
                               "defaulting to 0.5";
    // Clipping in float can throw a vertex of a triangle whose coordinates
    // lie ~1e20 apart far off the frame (issue 26): raster/setup_reach.h.
    const std::string snap = "; clipped as the pipeline clips, a triangle's window positions must stay within "
                             "+-2^20 pixels";
    s.numbers("triangles[].positions", 2, pixels_only ? 3 : 4, -kHuge, kHuge, "required",
              (pixels_only ? pixels : "`coordinates` \"clip\": " + clip + "; \"pixels\": " + pixels) + snap)
        .in_rows(3).draws(-2, 2);
    // Colours end at a million (issue 26, found by explore --seed 2026 on
    // triangles): colours of 1e30 made the blends' products (colour x alpha)
    // infinite on both pipelines. A million is far past any radiance a scene
    // needs. A clear colour likewise (1e30 under a blend reading the
    // destination).
    s.numbers("triangles[].colour", 3, 4, -kMaxAttribute, kMaxAttribute,
              colour_optional ? nlohmann::json::array({1.0, 1.0, 1.0, 1.0}) : nlohmann::json(),
              colour_optional ? "one colour for all three corners (alpha defaults to 1; no colour: white)"
                              : "one colour for all three corners, instead of `colours` (alpha defaults to 1)")
        .draws(0, 1).edge({0, 1}).only_if_present();  // one of colour, colours: the explorer keeps the one given
    s.numbers("triangles[].colours", 3, 4, -kMaxAttribute, kMaxAttribute, nullptr,
              colour_optional ? "per-corner colours (alpha defaults to 1), instead of `colour`"
                              : "per-corner colours (alpha defaults to 1); this or `colour` is required")
        .in_rows(3).draws(0, 1).edge({0, 1}).only_if_present();
    // Texture coordinates: the triangles kind samples them as they are and
    // takes any (kHuge; the nearest texel at 1e9 and beyond follows
    // llvmpipe's integer conversions, texture/texel_math.h). A conformance
    // program computes with them: its derivatives program squared 1e30 to
    // infinity on both pipelines (explore conformance --seed 2026), so there
    // they end at a million as colours do.
    s.numbers("triangles[].uvs", 2, 2, -max_uv, max_uv, uvs_always ? nlohmann::json("required") : nlohmann::json(),
              uvs_always ? "per-corner texture coordinates" : "per-corner texture coordinates, required with `texture`")
        .in_rows(3).draws(-2, 2).edge({0, 1}).only_if_present();  // only with a texture
    return s;
}

}  // namespace st
