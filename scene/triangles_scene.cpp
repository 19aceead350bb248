// triangles_scene.cpp: the "triangles" kind: triangles listed in the file,
// drawn in order with the interpolating program (glsl/interp.*) in one draw.
#include "scene/input_error.h"
#include "scene/scene_kinds.h"
#include "scene/texture_patterns.h"
#include "scene/triangle_list.h"

namespace st {

namespace {


BlendMode parse_blend(const std::string& name) {
    if (name == "one_src_alpha") return BlendMode::OneSrcAlpha;
    if (name == "alpha") return BlendMode::SrcAlphaOneMinusSrcAlpha;
    return BlendMode::None;
}

}  // namespace

Frame build_triangles_scene(JsonReader& scene, SceneSize size) {
    Pass pass;
    pass.width = size.width;
    pass.height = size.height;
    // Every field's domain and default: scene/triangles_space.cpp.
    pass.clear_colour = rgba(scene.numbers("clear_colour"));

    const bool pixels = scene.choice("coordinates") == "pixels";
    DrawCall draw;
    // With a texture, the textured program (colour x texel, per-vertex uvs).
    const bool textured = scene.has("texture");
    if (textured) {
        JsonReader tex = scene.object("texture");
        TexelBudget budget;
        draw.textures.push_back(read_pattern_texture(tex, "tex", budget));
    }
    draw.vertex = draw.fragment = textured ? "textured" : "interp";
    draw.state.depth_test = scene.boolean("depth_test");
    draw.state.blend = parse_blend(scene.choice("blend"));
    draw.vertices.attribute_count = textured ? 3 : 2;  // position, colour[, uv]

    read_triangle_list(scene, size, Viewport{0, 0, float(size.width), float(size.height), 0, 1},
                       TriangleListFormat{pixels, textured, false}, draw);
    pass.draws.push_back(std::move(draw));
    Frame frame;
    frame.passes.push_back(std::move(pass));
    return frame;
}

}  // namespace st
