// wrap_scene.cpp: the "wrap" scene kind. A unit sphere, tessellated on the
// host so that both backends draw the same triangles, seen from +z through
// a perspective camera and lit by one directional light.
//
// Fields (every one checked by the JsonReader; unknown fields are refused):
//   light_dir [x, y, z]  towards the light (normalised here)
//   albedo, scatter_tint [r, g, b]
//   wrap                 in [0, 1]
//   segments             around the sphere, 8..512 (rings: half as many)
#include <cmath>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/input_error.h"
#include "scene/uniform_values.h"
#include "wrap.h"

namespace {

glm::vec3 vec3_field(st::JsonReader& scene, const std::string& key, double lo, double hi) {
    const std::vector<double> v = scene.numbers(key, 3, 3, lo, hi);
    return glm::vec3(float(v[0]), float(v[1]), float(v[2]));
}

}  // namespace

st::Frame build_wrap_scene(st::JsonReader& scene, st::SceneSize size) {
    glm::vec3 light_dir = vec3_field(scene, "light_dir", -1e3, 1e3);
    if (!(glm::length(light_dir) > 1e-6f)) throw st::InputError(scene.field("light_dir") + " must not be zero");
    light_dir = glm::normalize(light_dir);
    const glm::vec3 albedo = vec3_field(scene, "albedo", 0, 1);
    const glm::vec3 scatter_tint = vec3_field(scene, "scatter_tint", 0, 1);
    const float wrap = float(scene.number("wrap", 0, 1));
    const int segments = scene.integer_or("segments", 64, 8, 512), rings = segments / 2;

    st::DrawCall draw;
    draw.vertex = draw.fragment = "wrap";
    draw.state.depth_test = true;
    draw.vertices.attribute_count = 2;  // position, normal
    for (int r = 0; r <= rings; ++r) {
        const double theta = std::numbers::pi * r / rings;
        for (int s = 0; s <= segments; ++s) {
            const double phi = 2 * std::numbers::pi * s / segments;
            const glm::vec4 p(float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)),
                              float(std::sin(theta) * std::sin(phi)), 1.0f);
            draw.vertices.data.push_back(p);
            draw.vertices.data.push_back(glm::vec4(p.x, p.y, p.z, 0.0f));
        }
    }
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const uint32_t a = uint32_t(r * (segments + 1) + s), b = a + uint32_t(segments + 1);
            draw.indices.insert(draw.indices.end(), {a, b, a + 1, a + 1, b, b + 1});
        }

    const glm::mat4 projection =
        glm::perspective(glm::radians(40.0f), float(size.width) / float(size.height), 0.5f, 10.0f);
    const glm::mat4 view = glm::lookAt(glm::vec3(0, 0, 3.2f), glm::vec3(0), glm::vec3(0, 1, 0));
    draw.uniforms = {st::uniform("mvp", projection * view), st::uniform("light_dir", light_dir),
                     st::uniform("albedo", albedo), st::uniform("scatter_tint", scatter_tint),
                     st::uniform("wrap", wrap)};

    st::Pass pass;
    pass.width = size.width;
    pass.height = size.height;
    pass.clear_colour = glm::vec4(0.02f, 0.02f, 0.03f, 1.0f);
    pass.draws.push_back(std::move(draw));
    st::Frame frame;
    frame.passes.push_back(std::move(pass));
    return frame;
}
