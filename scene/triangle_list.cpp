// triangle_list.cpp: see triangle_list.h.
#include "scene/triangle_list.h"

#include <algorithm>
#include <cstdio>

#include "raster/setup_reach.h"
#include "scene/input_error.h"
#include "scene/param_space.h"

namespace st {

namespace {

constexpr size_t kCorners = 3;  // each of positions, colours and uvs: one entry per corner

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

// Vertex i's position, the first attribute of each vertex.
const glm::vec4& position_of(const DrawCall& draw, size_t i) {
    return draw.vertices.data[size_t(draw.indices[i]) * size_t(draw.vertices.attribute_count)];
}

std::string short_float(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.7g", double(v));
    return buf;
}

}  // namespace

glm::vec4 rgba(const std::vector<double>& v) {
    return glm::vec4(float(v[0]), float(v[1]), float(v[2]), v.size() > 3 ? float(v[3]) : 1.0f);
}

// Error paths are built only when a value is refused (JsonReader's lazy
// checked_number): a mesh of a million triangles has eighteen million
// numbers, and naming each one cost more than reading it. For the same
// reason the per-triangle fields are read with their declared lengths and
// ranges (triangle_list_fields() in scene/shared_spaces.cpp), taken from the
// space once here rather than looked up per triangle.
void read_triangle_list(JsonReader& scene, SceneSize size, const Viewport& viewport, TriangleListFormat format,
                        DrawCall& draw) {
    const FieldSpec& list = scene.spec("triangles");
    const FieldSpec& pos = scene.spec("triangles[].positions");
    const FieldSpec& one = scene.spec("triangles[].colour");
    const FieldSpec& each = scene.spec("triangles[].colours");
    const FieldSpec* uv = format.uvs ? &scene.spec("triangles[].uvs") : nullptr;
    // Pixels give x, y and at most a window depth, which lies in [0, 1].
    const size_t pos_max = format.pixels ? std::min<size_t>(pos.max_len, 3) : pos.max_len;
    const std::vector<double> white = format.colour_optional ? one.fallback.get<std::vector<double>>()
                                                             : std::vector<double>();
    if (scene.has("triangles")) {  // (a missing or malformed list is refused just below)
        const size_t corners = 3 * scene.array("triangles", list.min_len, list.max_len).size();
        draw.indices.reserve(draw.indices.size() + corners);
        draw.vertices.data.reserve(draw.vertices.data.size() + corners * (format.uvs ? 3 : 2));
    }
    std::vector<double> p;
    std::vector<double> colours[3];
    scene.for_each_object("triangles", list.min_len, list.max_len, [&](JsonReader& t) {
        const auto& positions = t.array("positions", kCorners, kCorners);
        if (format.colour_optional && !t.has("colour") && !t.has("colours")) {
            for (auto& colour : colours) colour = white;
        } else if (t.has("colour")) {
            const auto c = t.numbers("colour", one.min_len, one.max_len, one.lo, one.hi);
            for (auto& colour : colours) colour = c;
        } else {
            const auto& cs = t.array("colours", kCorners, kCorners);
            for (size_t i = 0; i < kCorners; ++i) {
                auto where = [&] { return t.field("colours") + "." + std::to_string(i); };
                if (!cs[i].is_array() || cs[i].size() < each.min_len || cs[i].size() > each.max_len)
                    throw InputError("field '" + where() + "' must be an array of " + std::to_string(each.min_len) +
                                     " or " + std::to_string(each.max_len) + " numbers");
                colours[i].clear();
                for (size_t k = 0; k < cs[i].size(); ++k)
                    colours[i].push_back(JsonReader::checked_number(
                        cs[i][k], [&] { return where() + "." + std::to_string(k); }, each.lo, each.hi));
            }
        }
        const nlohmann::json* uvs = uv ? &t.array("uvs", kCorners, kCorners) : nullptr;
        for (size_t i = 0; i < kCorners; ++i) {
            auto where = [&] { return t.field("positions") + "." + std::to_string(i); };
            if (!positions[i].is_array() || positions[i].size() < pos.min_len || positions[i].size() > pos_max)
                throw InputError("field '" + where() + "' must be an array of " + std::to_string(pos.min_len) + " to " +
                                 std::to_string(pos_max) + " numbers");
            p.clear();
            for (size_t k = 0; k < positions[i].size(); ++k) {
                const bool is_depth = format.pixels && k == 2;
                p.push_back(JsonReader::checked_number(positions[i][k],
                                                       [&] { return where() + "." + std::to_string(k); },
                                                       is_depth ? 0.0 : pos.lo, is_depth ? 1.0 : pos.hi));
            }
            // As a float, which is what the pipeline sees: 1e-50 is 0 there.
            if (!format.pixels && p.size() == 4 && float(p[3]) == 0.0f)
                throw InputError("field '" + where() + ".3' (w) must not be 0 (as a 32-bit float)");
            draw.indices.push_back(uint32_t(draw.vertices.vertex_count()));
            draw.vertices.data.push_back(format.pixels ? pixel_to_clip(p, size) : clip_position(p));
            draw.vertices.data.push_back(rgba(colours[i]));
            if (uvs) {
                auto uv_where = [&] { return t.field("uvs") + "." + std::to_string(i); };
                const auto& c = (*uvs)[i];
                if (!c.is_array() || c.size() < uv->min_len || c.size() > uv->max_len)
                    throw InputError("field '" + uv_where() + "' must be an array of " + std::to_string(uv->max_len) +
                                     " numbers");
                draw.vertices.data.push_back(glm::vec4(
                    float(JsonReader::checked_number(c[0], [&] { return uv_where() + ".0"; }, uv->lo, uv->hi)),
                    float(JsonReader::checked_number(c[1], [&] { return uv_where() + ".1"; }, uv->lo, uv->hi)),
                    0.0f, 1.0f));
            }
        }
        const size_t first = draw.indices.size() - kCorners;
        if (const auto w = first_unsnappable_position(position_of(draw, first), position_of(draw, first + 1),
                                                      position_of(draw, first + 2), viewport))
            throw InputError("field '" + t.field("positions") + "': clipped to the view volume, this triangle has a " +
                             "vertex at window (" + short_float(w->x) + ", " + short_float(w->y) +
                             "), beyond the +-2^20 pixels setup can snap (llvmpipe wraps such a position in int32 " +
                             "and draws garbage): clipping rounds in float, and coordinates this far apart lose " +
                             "the clipped vertex's place");

        t.finish();
    });
}

}  // namespace st
