// conformance_scene.cpp: the "conformance" kind: one small fragment program
// from glsl/conformance/ (twin in kernels/conformance/) on a list of
// triangles, with its uniforms and textures named in the file. Each such
// scene pins one behaviour of the shading runtime against llvmpipe: a loop
// whose lanes leave at different passes, a texture read in a divergent
// branch, discard, derivatives of computed values, non-finite outputs.
// The vertex stage is glsl/triangles/textured.vert: position, colour, uv.
#include <cmath>

#include "scene/input_error.h"
#include "scene/scene_kinds.h"
#include "scene/texture_patterns.h"
#include "scene/triangle_list.h"

namespace st {

namespace {

constexpr double kHuge = 1e30;
constexpr size_t kMaxUniforms = 64;
constexpr size_t kMaxTextures = 8;

// {"name": "steps", "int": 40} | {"name": "dir", "vec2": [0.1, 0.2]} | ...
Uniform read_uniform(JsonReader& r) {
    Uniform u;
    u.name = r.string("name");
    int found = 0;
    const struct { const char* key; UniformType type; size_t n; } kinds[] = {
        {"float", UniformType::Float, 1}, {"vec2", UniformType::Vec2, 2}, {"vec3", UniformType::Vec3, 3},
        {"vec4", UniformType::Vec4, 4},   {"int", UniformType::Int, 1}};
    for (const auto& k : kinds) {
        if (!r.has(k.key)) continue;
        ++found;
        u.type = k.type;
        if (k.type == UniformType::Int) {
            u.value[0] = float(r.integer(k.key, -(1 << 24), 1 << 24));  // exact as a float
        } else if (k.n == 1) {
            u.value[0] = float(r.number(k.key, -kHuge, kHuge));
        } else {
            const auto v = r.numbers(k.key, k.n, k.n, -kHuge, kHuge);
            for (size_t i = 0; i < k.n; ++i) u.value[i] = float(v[i]);
        }
    }
    if (found != 1)
        throw InputError("field '" + r.path() + "' needs exactly one of float, vec2, vec3, vec4, int");
    r.finish();
    return u;
}

}  // namespace

Frame build_conformance_scene(JsonReader& scene, SceneSize size) {
    Pass pass;
    pass.width = size.width;
    pass.height = size.height;
    if (scene.has("clear_colour")) {
        const auto c = scene.numbers("clear_colour", 4, 4, -kHuge, kHuge);
        pass.clear_colour = glm::vec4(float(c[0]), float(c[1]), float(c[2]), float(c[3]));
    }
    DrawCall draw;
    draw.vertex = "textured";
    draw.fragment = scene.string("fragment");
    if (scene.has("uniforms"))
        for (JsonReader& u : scene.objects("uniforms", 0, kMaxUniforms)) draw.uniforms.push_back(read_uniform(u));
    if (scene.has("textures"))
        for (JsonReader& t : scene.objects("textures", 0, kMaxTextures)) {
            const std::string sampler = t.string("sampler");
            draw.textures.push_back(read_pattern_texture(t, sampler));
        }
    draw.state.depth_test = scene.boolean_or("depth_test", false);
    draw.vertices.attribute_count = 3;  // position, colour, uv
    read_triangle_list(scene, size, TriangleListFormat{true, true, true}, draw);
    pass.draws.push_back(std::move(draw));
    Frame frame;
    frame.passes.push_back(std::move(pass));
    return frame;
}

}  // namespace st
