// triangle_list.cpp: see triangle_list.h.
#include "scene/triangle_list.h"

#include "scene/input_error.h"

namespace st {

namespace {

constexpr size_t kMaxTriangles = 1 << 20;

// Pixel positions map to clip space with w = 1: x_clip = x * (2/W) - 1. For
// power-of-two sizes every step is exact, so a vertex given at 12.5 lands
// on window x = 12.5 to the bit on both backends.
glm::vec4 pixel_to_clip(const std::vector<double>& p, SceneSize size) {
    const float x = float(p[0]) * (2.0f / float(size.width)) - 1.0f;
    const float y = float(p[1]) * (2.0f / float(size.height)) - 1.0f;
    const float depth = p.size() > 2 ? float(p[2]) : 0.5f;
    return glm::vec4(x, y, depth * 2.0f - 1.0f, 1.0f);
}

glm::vec4 clip_position(const std::vector<double>& p) {
    return glm::vec4(float(p[0]), float(p[1]), p.size() > 2 ? float(p[2]) : 0.0f,
                     p.size() > 3 ? float(p[3]) : 1.0f);
}

}  // namespace

glm::vec4 rgba(const std::vector<double>& v) {
    return glm::vec4(float(v[0]), float(v[1]), float(v[2]), v.size() > 3 ? float(v[3]) : 1.0f);
}

// Error paths are built only when a value is refused (JsonReader's lazy
// checked_number): a mesh of a million triangles has eighteen million
// numbers, and naming each one cost more than reading it.
void read_triangle_list(JsonReader& scene, SceneSize size, TriangleListFormat format, DrawCall& draw) {
    if (scene.has("triangles")) {  // (a missing or malformed list is refused just below)
        const size_t corners = 3 * scene.array("triangles", 1, kMaxTriangles).size();
        draw.indices.reserve(draw.indices.size() + corners);
        draw.vertices.data.reserve(draw.vertices.data.size() + corners * (format.uvs ? 3 : 2));
    }
    std::vector<double> p;
    std::vector<double> colours[3];
    scene.for_each_object("triangles", 1, kMaxTriangles, [&](JsonReader& t) {
        const auto& positions = t.array("positions", 3, 3);
        if (format.colour_optional && !t.has("colour") && !t.has("colours")) {
            for (auto& colour : colours) colour.assign({1.0, 1.0, 1.0, 1.0});
        } else if (t.has("colour")) {
            const auto one = t.numbers("colour", 3, 4, -kHuge, kHuge);
            for (auto& colour : colours) colour = one;
        } else {
            const auto& cs = t.array("colours", 3, 3);
            for (size_t i = 0; i < 3; ++i) {
                auto where = [&] { return t.field("colours") + "." + std::to_string(i); };
                if (!cs[i].is_array() || cs[i].size() < 3 || cs[i].size() > 4)
                    throw InputError("field '" + where() + "' must be an array of 3 or 4 numbers");
                colours[i].clear();
                for (size_t k = 0; k < cs[i].size(); ++k)
                    colours[i].push_back(JsonReader::checked_number(
                        cs[i][k], [&] { return where() + "." + std::to_string(k); }, -kHuge, kHuge));
            }
        }
        const nlohmann::json* uvs = format.uvs ? &t.array("uvs", 3, 3) : nullptr;
        for (size_t i = 0; i < 3; ++i) {
            auto where = [&] { return t.field("positions") + "." + std::to_string(i); };
            const size_t max_len = format.pixels ? 3 : 4;
            if (!positions[i].is_array() || positions[i].size() < 2 || positions[i].size() > max_len)
                throw InputError("field '" + where() + "' must be an array of 2 to " +
                                 std::to_string(max_len) + " numbers");
            p.clear();
            for (size_t k = 0; k < positions[i].size(); ++k) {
                const bool is_depth = format.pixels && k == 2;
                p.push_back(JsonReader::checked_number(positions[i][k],
                                                       [&] { return where() + "." + std::to_string(k); },
                                                       is_depth ? 0.0 : -kHuge, is_depth ? 1.0 : kHuge));
            }
            // As a float, which is what the pipeline sees: 1e-50 is 0 there.
            if (!format.pixels && p.size() == 4 && float(p[3]) == 0.0f)
                throw InputError("field '" + where() + ".3' (w) must not be 0 (as a 32-bit float)");
            draw.indices.push_back(uint32_t(draw.vertices.vertex_count()));
            draw.vertices.data.push_back(format.pixels ? pixel_to_clip(p, size) : clip_position(p));
            draw.vertices.data.push_back(rgba(colours[i]));
            if (uvs) {
                auto uv_where = [&] { return t.field("uvs") + "." + std::to_string(i); };
                const auto& uv = (*uvs)[i];
                if (!uv.is_array() || uv.size() != 2)
                    throw InputError("field '" + uv_where() + "' must be an array of 2 numbers");
                draw.vertices.data.push_back(glm::vec4(
                    float(JsonReader::checked_number(uv[0], [&] { return uv_where() + ".0"; }, -kHuge, kHuge)),
                    float(JsonReader::checked_number(uv[1], [&] { return uv_where() + ".1"; }, -kHuge, kHuge)),
                    0.0f, 1.0f));
            }
        }
        t.finish();
    });
}

}  // namespace st
