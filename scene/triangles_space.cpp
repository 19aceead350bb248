// triangles_space.cpp: the fields of a "triangles" scene (triangles listed in
// the file, drawn in order in one draw; scene/triangles_scene.cpp builds
// it), with their domains. The triangle list and the texture are blocks the
// conformance kind shares (scene/shared_spaces.cpp).
#include "scene/json_reader.h"
#include "scene/scene_spaces.h"

namespace st {

const ParamSpace& triangles_space() {
    static const ParamSpace space = [] {
        ParamSpace s("triangles");
        s.include(common_space());
        s.include(triangle_list_fields(false, false, false, kHuge));
        s.choice("coordinates", {"clip", "pixels"}, "clip", "how positions are given: clip space, or window pixels");
        s.numbers("clear_colour", 4, 4, -kMaxAttribute, kMaxAttribute, nlohmann::json::array({0.0, 0.0, 0.0, 0.0}),
                  "the colour the target is cleared to")
            .draws(0, 1).edge({0, 1});
        s.boolean("depth_test", false, "GL_LESS against a 32-bit float depth buffer cleared to 1");
        s.choice("blend", {"none", "one_src_alpha", "alpha"}, "none",
                 "glBlendFunc(GL_ONE, GL_SRC_ALPHA) or (GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA)");
        s.object("texture", false,
                 "a procedural texture, sampled by glsl/triangles/textured.* (colour x texel); every triangle then "
                 "needs `uvs`")
            .only_if_present();  // the explorer never adds one: every triangle would need uvs
        s.include(pattern_texture_fields(false), "texture");
        return s;
    }();
    return space;
}

}  // namespace st
