// conformance_space.cpp: the fields of a "conformance" scene (one small
// fragment program from glsl/conformance/ on a list of triangles, with its
// uniforms, textures, render targets and passes; scene/conformance_scene.cpp
// builds it), with their domains. The scene's own pass and each of `passes`
// have the same fields, declared once below and included twice.
#include "scene/json_reader.h"
#include "scene/scene_spaces.h"

#include <initializer_list>
#include <string>
#include <tuple>

namespace st {

namespace {

// What every pass says: where it draws and what.
ParamSpace pass_fields() {
    ParamSpace s("pass");
    s.text("target", nullptr, "a name from `targets` (a pass before the scene's own; the scene's own draws the image)");
    s.integer("level", 0, 12, 0, "the level of `target` drawn, below its `levels`").edge({0, 1}).only_if_present();
    s.object("outputs", false,
             "several render targets: the targets the fragment outputs at locations 1, 2, 3 draw into, each the "
             "size of the pass (location 0 is `target`, or the image), cleared and blended as it is",
             0, 3)
        .only_if_present();
    s.text("outputs[].target", "required", "a name from `targets`");
    s.integer("outputs[].level", 0, 12, 0, "the level drawn, below its target's `levels`").edge({0}).only_if_present();
    s.numbers("viewport", 4, 4, 0, 8192, nullptr,
              "[x, y, width, height] in whole pixels within the target (level), width and height at least 1 "
              "(default: all of it)")
        .draws(0, 64)
        .whole();
    s.boolean("clear", true, "clear first; false keeps what earlier passes left (and then allows no depth test)");
    s.numbers("clear_colour", 4, 4, -kMaxAttribute, kMaxAttribute, nlohmann::json::array({0.0, 0.0, 0.0, 0.0}),
              "the colour the target is cleared to")
        .draws(0, 1).edge({0, 1});
    s.text("fragment", "required", "the program: glsl/conformance/<fragment>.frag");
    s.texts("output_names", 1, 4, nullptr,
            "for a program whose several outputs have no layout(location): the output at location 0, 1, ..., "
            "bound by name as glBindFragDataLocation does")
        .only_if_present()
        .not_explored();
    s.text("vertex", "textured",
           "the vertex program: `textured` (glsl/triangles/textured.vert: position, colour and uv passed on) or one "
           "of glsl/conformance/ with the same inputs and outputs");
    s.object("cells", false,
             "instead of `triangles`: a grid of cells over the target (viewport), two triangles each, whose three "
             "corners carry the cell's index (row-major from the bottom left) in uv.x and white, so that what a vertex "
             "program makes of its cell is the same at all three")
        .only_if_present();  // instead of triangles: the explorer keeps the form given
    s.integer("cells.columns", 1, 256, "required", "cells across").explore_at_most(64).edge({1, 64});
    s.integer("cells.rows", 1, 256, "required", "cells up").explore_at_most(64).edge({1, 64});
    s.object("uniforms", false, "the program's uniforms; each has a name and exactly one value", 0, 64);
    s.text("uniforms[].name", "required",
           "the GLSL uniform's name; a name beginning `twin_` is a switch only the twin reads (to break it on "
           "purpose in a test), which the explorer never changes");
    // A uniform's value keeps the type its program declares: the explorer
    // changes the one given, never adds another. Values end at 1e6 as
    // colours do (kMaxAttribute): a scale of 1e30 made the derivatives
    // program's products infinite on both pipelines (explore --seed 2026).
    s.number("uniforms[].float", -kMaxAttribute, kMaxAttribute, nullptr, "a float's value").draws(-10, 10).edge({0, 1, -1})
        .only_if_present();
    s.numbers("uniforms[].vec2", 2, 2, -kMaxAttribute, kMaxAttribute, nullptr, "a vec2's value").draws(-10, 10).edge({0, 1})
        .only_if_present();
    s.numbers("uniforms[].vec3", 3, 3, -kMaxAttribute, kMaxAttribute, nullptr, "a vec3's value").draws(-10, 10).edge({0, 1})
        .only_if_present();
    s.numbers("uniforms[].vec4", 4, 4, -kMaxAttribute, kMaxAttribute, nullptr, "a vec4's value").draws(-10, 10).edge({0, 1})
        .only_if_present();
    s.integer("uniforms[].int", INT32_MIN, INT32_MAX, nullptr, "an int's value")
        .draws(-100, 100).edge({0, 1, -1})
        .only_if_present();
    for (int n = 2; n <= 4; ++n)
        s.numbers("uniforms[].ivec" + std::to_string(n), n, n, INT32_MIN, INT32_MAX, nullptr,
                  "an ivec" + std::to_string(n) + "'s value, whole numbers")
            .draws(-100, 100).edge({0, 1})
            .only_if_present();
    s.number("uniforms[].uint", 0, 4294967295.0, nullptr, "a uint's value, a whole number (glUniform1ui)")
        .draws(0, 100).edge({0, 1, 4294967295.0})
        .only_if_present();
    for (int n = 2; n <= 4; ++n)
        s.numbers("uniforms[].uvec" + std::to_string(n), n, n, 0, 4294967295.0, nullptr,
                  "a uvec" + std::to_string(n) + "'s value, whole numbers")
            .draws(0, 100).edge({0, 1})
            .only_if_present();
    s.boolean("uniforms[].bool", false, "a bool's value (set as an int, glUniform1i)").only_if_present();
    for (int n = 2; n <= 4; ++n)
        s.numbers("uniforms[].bvec" + std::to_string(n), n, n, 0, 1, nullptr,
                  "a bvec" + std::to_string(n) + "'s value: 0 or 1 each (set as an ivec" + std::to_string(n) + ")")
            .draws(0, 1).edge({0, 1})
            .only_if_present();
    for (const auto& [name, c, rows] : std::initializer_list<std::tuple<const char*, int, int>>{
             {"mat2", 2, 2}, {"mat3", 3, 3}, {"mat4", 4, 4}, {"mat2x3", 2, 3}, {"mat2x4", 2, 4}, {"mat3x2", 3, 2},
             {"mat3x4", 3, 4}, {"mat4x2", 4, 2}, {"mat4x3", 4, 3}})
        s.numbers(std::string("uniforms[].") + name, size_t(c * rows), size_t(c * rows), -kMaxAttribute, kMaxAttribute,
                  nullptr, std::string("a ") + name + "'s value, column-major (glUniformMatrix*fv)")
            .draws(-10, 10).edge({0, 1})
            .only_if_present();
    s.number("uniforms[].double", -kMaxAttribute, kMaxAttribute, nullptr, "a double's value (glUniform1d)")
        .draws(-10, 10).edge({0, 1, -1})
        .only_if_present();
    for (int n = 2; n <= 4; ++n)
        s.numbers("uniforms[].dvec" + std::to_string(n), n, n, -kMaxAttribute, kMaxAttribute, nullptr,
                  "a dvec" + std::to_string(n) + "'s value")
            .draws(-10, 10).edge({0, 1})
            .only_if_present();
    for (int n = 2; n <= 4; ++n)
        s.numbers("uniforms[].dmat" + std::to_string(n), n * n, n * n, -kMaxAttribute, kMaxAttribute, nullptr,
                  "a dmat" + std::to_string(n) + "'s value, column-major (glUniformMatrix" + std::to_string(n) + "dv)")
            .draws(-10, 10).edge({0, 1})
            .only_if_present();
    s.object("textures", false, "procedural textures or render targets, bound to units in order", 0, 8);
    s.text("textures[].sampler", "required", "the GLSL sampler's name");
    s.include(pattern_texture_fields(true), "textures[]");
    s.boolean("depth_test", false, "GL_LESS against a 32-bit float depth buffer cleared to 1");
    s.choice("blend",
             {"zero", "one", "src_colour", "one_minus_src_colour", "src_alpha", "one_minus_src_alpha", "dst_colour",
              "one_minus_dst_colour", "dst_alpha", "one_minus_dst_alpha"},
             nullptr, "glBlendFuncSeparate(src_rgb, dst_rgb[, src_alpha, dst_alpha]), GL_FUNC_ADD: 2 or 4 factors")
        .listed(2, 4);
    s.include(triangle_list_fields(true, true, true, kMaxAttribute, false));
    return s;
}

}  // namespace

const ParamSpace& conformance_space() {
    static const ParamSpace space = [] {
        ParamSpace s("conformance");
        s.include(common_space());
        const ParamSpace pass = pass_fields();
        s.include(pass);

        s.object("targets", false, "named render targets, each an output beside the image", 1, 16);
        s.text("targets[].name", "required", "its name (not empty, not repeated)");
        s.integer("targets[].width", 1, 4096, "required", "texels across").explore_at_most(512).edge({1, 2, 3, 64});
        s.integer("targets[].height", 1, 4096, "required", "texels up").explore_at_most(512).edge({1, 2, 3, 64});
        s.choice("targets[].format", {"rgba16f", "rgba32f"}, "rgba32f", "texel format");
        s.integer("targets[].levels", 1, 13, 1, "mip levels, at most the full chain of width x height").edge({1, 2});

        s.object("passes", false, "passes drawn before the scene's own, in order", 1, 64).explore_at_most(8);
        s.include(pass, "passes[]");
        return s;
    }();
    return space;
}

}  // namespace st
