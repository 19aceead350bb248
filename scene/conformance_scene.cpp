// conformance_scene.cpp: the "conformance" kind: one small fragment program
// from glsl/conformance/ (twin in kernels/conformance/) on a list of
// triangles, with its uniforms and textures named in the file. Each such
// scene pins one behaviour of the shading runtime against llvmpipe: a loop
// whose lanes leave at different passes, a texture read in a divergent
// branch, discard, derivatives of computed values, non-finite outputs.
// The vertex stage is glsl/triangles/textured.vert: position, colour, uv.
#include <algorithm>
#include <cmath>
#include <set>

#include "scene/input_error.h"
#include "scene/param_space.h"
#include "scene/scene_kinds.h"
#include "scene/texture_patterns.h"
#include "scene/triangle_list.h"
#include "texture/mip_generation.h"

namespace st {

namespace {

// Every field's domain and default: scene/conformance_space.cpp.

// The objects of an array field, as many as its declaration allows.
std::vector<JsonReader> declared_objects(JsonReader& r, const std::string& key) {
    const FieldSpec& f = r.spec(key);
    return r.objects(key, f.min_len, f.max_len);
}

// {"name": "steps", "int": 40} | {"name": "dir", "vec2": [0.1, 0.2]} | ...:
// every glUniform type by its GLSL name; bool as true or false, bvecN and
// the integer vectors as whole numbers, matrices column-major.
Uniform read_uniform(JsonReader& r) {
    Uniform u;
    u.name = r.text("name");
    enum Kind { Floats, Doubles, Ints, UInts, Bools };
    const struct { const char* key; UniformType type; size_t n; Kind kind; } kinds[] = {
        {"float", UniformType::Float, 1, Floats},     {"vec2", UniformType::Vec2, 2, Floats},
        {"vec3", UniformType::Vec3, 3, Floats},       {"vec4", UniformType::Vec4, 4, Floats},
        {"int", UniformType::Int, 1, Ints},           {"ivec2", UniformType::IVec2, 2, Ints},
        {"ivec3", UniformType::IVec3, 3, Ints},       {"ivec4", UniformType::IVec4, 4, Ints},
        {"uint", UniformType::UInt, 1, UInts},        {"uvec2", UniformType::UVec2, 2, UInts},
        {"uvec3", UniformType::UVec3, 3, UInts},      {"uvec4", UniformType::UVec4, 4, UInts},
        {"bool", UniformType::Int, 1, Bools},         {"bvec2", UniformType::IVec2, 2, Ints},
        {"bvec3", UniformType::IVec3, 3, Ints},       {"bvec4", UniformType::IVec4, 4, Ints},
        {"mat2", UniformType::Mat2, 4, Floats},       {"mat3", UniformType::Mat3, 9, Floats},
        {"mat4", UniformType::Mat4, 16, Floats},      {"mat2x3", UniformType::Mat2x3, 6, Floats},
        {"mat2x4", UniformType::Mat2x4, 8, Floats},   {"mat3x2", UniformType::Mat3x2, 6, Floats},
        {"mat3x4", UniformType::Mat3x4, 12, Floats},  {"mat4x2", UniformType::Mat4x2, 8, Floats},
        {"mat4x3", UniformType::Mat4x3, 12, Floats},  {"double", UniformType::Double, 1, Doubles},
        {"dvec2", UniformType::DVec2, 2, Doubles},    {"dvec3", UniformType::DVec3, 3, Doubles},
        {"dvec4", UniformType::DVec4, 4, Doubles},    {"dmat2", UniformType::DMat2, 4, Doubles},
        {"dmat3", UniformType::DMat3, 9, Doubles},    {"dmat4", UniformType::DMat4, 16, Doubles}};
    int found = 0;
    for (const auto& k : kinds) {
        if (!r.has(k.key)) continue;
        ++found;
        u.type = k.type;
        if (k.kind == Bools) {
            u.value[0] = r.boolean(k.key) ? 1.0 : 0.0;
            continue;
        }
        const std::vector<double> v = k.type == UniformType::Int ? std::vector<double>{double(r.integer(k.key))}
                                      : k.n == 1                ? std::vector<double>{r.number(k.key)}
                                                                : r.numbers(k.key);
        for (size_t i = 0; i < k.n; ++i) {
            // A float's value is rounded to a float once, here; a double's
            // and an integer's are kept exactly (the space bounds them).
            if ((k.kind == Ints || k.kind == UInts) && v[i] != std::floor(v[i]))
                throw InputError("field '" + r.path() + "." + k.key + "': " + k.key + " holds whole numbers");
            u.value[i] = k.kind == Floats ? double(float(v[i])) : v[i];
        }
    }
    if (found != 1)
        throw InputError("field '" + r.path() + "' needs exactly one value: float, vecN, int, ivecN, uint, uvecN, bool, "
                         "bvecN, matN, matCxR, double, dvecN or dmatN");
    r.finish();
    return u;
}

BlendFactor factor_named(const std::string& name, const std::string& field) {
    static const std::pair<const char*, BlendFactor> names[] = {
        {"zero", BlendFactor::Zero},
        {"one", BlendFactor::One},
        {"src_colour", BlendFactor::SrcColor},
        {"one_minus_src_colour", BlendFactor::OneMinusSrcColor},
        {"src_alpha", BlendFactor::SrcAlpha},
        {"one_minus_src_alpha", BlendFactor::OneMinusSrcAlpha},
        {"dst_colour", BlendFactor::DstColor},
        {"one_minus_dst_colour", BlendFactor::OneMinusDstColor},
        {"dst_alpha", BlendFactor::DstAlpha},
        {"one_minus_dst_alpha", BlendFactor::OneMinusDstAlpha}};
    for (const auto& [n, f] : names)
        if (name == n) return f;
    throw InputError("field '" + field + "': unknown blend factor '" + name + "'");
}

// "blend": [src, dst] or [src_rgb, dst_rgb, src_alpha, dst_alpha], GL_FUNC_ADD.
void read_blend(JsonReader& r, DrawState& state) {
    if (!r.has("blend")) return;
    const FieldSpec& spec = r.spec("blend");
    const auto& a = r.array("blend", spec.min_len, spec.max_len);
    if (a.size() == 3) throw InputError("field '" + r.field("blend") + "' needs 2 or 4 factor names");
    std::vector<BlendFactor> f;
    for (size_t i = 0; i < a.size(); ++i) {
        const std::string where = r.field("blend") + "." + std::to_string(i);
        if (!a[i].is_string()) throw InputError("field '" + where + "' must be a factor name");
        f.push_back(factor_named(a[i].get<std::string>(), where));
    }
    state.blend = BlendMode::Factors;
    state.factors = a.size() == 2 ? BlendFactors{f[0], f[1], f[0], f[1]} : BlendFactors{f[0], f[1], f[2], f[3]};
}

// The fields every pass has, the scene's own (final) pass included.
// `cells`: columns x rows cells over the viewport in clip space, two
// triangles each; every corner of cell c (row-major from the bottom left)
// has uv (c, 0, 0, 0) and white, so a vertex program's result for the cell
// reaches each of its pixels unchanged (a plane through three equal values
// is that value).
void add_cells(int columns, int rows, DrawCall& draw) {
    const auto at = [](int k, int n) { return float(-1.0 + 2.0 * double(k) / double(n)); };
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < columns; ++i) {
            const glm::vec4 uv(float(j * columns + i), 0.0f, 0.0f, 0.0f);
            const float x0 = at(i, columns), x1 = at(i + 1, columns), y0 = at(j, rows), y1 = at(j + 1, rows);
            for (const glm::vec2 corner : {glm::vec2(x0, y0), glm::vec2(x1, y0), glm::vec2(x1, y1), glm::vec2(x0, y0),
                                           glm::vec2(x1, y1), glm::vec2(x0, y1)}) {
                draw.indices.push_back(uint32_t(draw.vertices.vertex_count()));
                draw.vertices.data.push_back(glm::vec4(corner, 0.0f, 1.0f));
                draw.vertices.data.push_back(glm::vec4(1.0f));
                draw.vertices.data.push_back(uv);
            }
        }
}

const RenderTarget& target_named(const std::vector<RenderTarget>& targets, const std::string& name,
                                 const std::string& field) {
    for (const RenderTarget& t : targets)
        if (t.name == name) return t;
    throw InputError("field '" + field + "': no target named '" + name + "'");
}

Pass read_pass(JsonReader& r, const std::vector<RenderTarget>& targets, SceneSize image, TexelBudget& budget) {
    Pass pass;
    SceneSize size = image;
    if (r.has("target")) {
        pass.target = r.text("target");
        const RenderTarget* rt = &target_named(targets, pass.target, r.field("target"));
        pass.level = r.integer_in("level", 0, rt->levels - 1);
        pass.format = rt->format;
        size = {std::max(1, rt->width >> pass.level), std::max(1, rt->height >> pass.level)};
    }
    pass.width = size.width;
    pass.height = size.height;
    if (r.has("viewport")) {
        const auto v = r.numbers("viewport");
        for (double x : v)
            if (x != std::floor(x)) throw InputError("field '" + r.field("viewport") + "' needs whole pixels");
        if (v[2] < 1 || v[3] < 1 || v[0] + v[2] > size.width || v[1] + v[3] > size.height)
            throw InputError("field '" + r.field("viewport") + "' must lie within the " + std::to_string(size.width) +
                             "x" + std::to_string(size.height) + " target");
        pass.viewport_x = int(v[0]), pass.viewport_y = int(v[1]);
        pass.viewport_width = int(v[2]), pass.viewport_height = int(v[3]);
    }
    if (r.has("outputs"))
        for (JsonReader& o : declared_objects(r, "outputs")) {
            PassOutput out;
            out.target = o.text("target");
            const RenderTarget* rt = &target_named(targets, out.target, o.field("target"));
            out.level = o.integer_in("level", 0, rt->levels - 1);
            out.format = rt->format;
            if (std::max(1, rt->width >> out.level) != size.width || std::max(1, rt->height >> out.level) != size.height)
                throw InputError("field '" + o.field("target") + "': '" + out.target + "' level " +
                                 std::to_string(out.level) + " is not the pass's " + std::to_string(size.width) + "x" +
                                 std::to_string(size.height));
            if (out.target == pass.target || std::any_of(pass.outputs.begin(), pass.outputs.end(), [&](const PassOutput& p) {
                    return p.target == out.target;
                }))
                throw InputError("field '" + o.field("target") + "': the pass draws into '" + out.target + "' twice");
            o.finish();
            pass.outputs.push_back(out);
        }
    pass.clear = r.boolean("clear");
    const auto c = r.numbers("clear_colour");
    pass.clear_colour = glm::vec4(float(c[0]), float(c[1]), float(c[2]), float(c[3]));
    DrawCall draw;
    draw.vertex = r.text("vertex");
    draw.fragment = r.text("fragment");
    if (r.has("output_names")) draw.output_names = r.texts("output_names");
    if (r.has("uniforms"))
        for (JsonReader& u : declared_objects(r, "uniforms")) draw.uniforms.push_back(read_uniform(u));
    if (r.has("textures"))
        for (JsonReader& t : declared_objects(r, "textures")) {
            const std::string sampler = t.text("sampler");
            draw.textures.push_back(read_pattern_texture(t, sampler, budget));
        }
    draw.state.depth_test = r.boolean("depth_test");
    if (draw.state.depth_test && !pass.clear)
        throw InputError("field '" + r.field("clear") + "': a pass that keeps its colour cannot test depth");
    read_blend(r, draw.state);
    draw.vertices.attribute_count = 3;  // position, colour, uv
    // Bound by name on the GL side, so that a vertex program without
    // locations (unlocated.vert) gets them too.
    draw.vertices.names = {"position", "colour", "uv"};
    // The viewport as the pipeline takes it (0 width: the whole target).
    const Viewport viewport{float(pass.viewport_x), float(pass.viewport_y),
                            float(pass.viewport_width ? pass.viewport_width : pass.width),
                            float(pass.viewport_height ? pass.viewport_height : pass.height), 0, 1};
    if (r.has("cells") == r.has("triangles"))
        throw InputError("field '" + r.field("triangles") + "': give `triangles` or `cells`, not " +
                         (r.has("cells") ? "both" : "neither"));
    if (r.has("cells")) {
        JsonReader c = r.object("cells");
        add_cells(c.integer("columns"), c.integer("rows"), draw);
        c.finish();
    } else {
        read_triangle_list(r, size, viewport, TriangleListFormat{true, true, true}, draw);
    }
    pass.draws.push_back(std::move(draw));
    return pass;
}

RenderTarget read_target(JsonReader& r) {
    RenderTarget t;
    t.name = r.text("name");
    if (t.name.empty()) throw InputError("field '" + r.field("name") + "' must not be empty");
    t.width = r.integer("width");
    t.height = r.integer("height");
    t.format = r.choice("format") == "rgba16f" ? TargetFormat::RGBA16F : TargetFormat::RGBA32F;
    t.levels = r.integer_in("levels", 1, full_chain_levels(t.width, t.height));
    r.finish();
    return t;
}

// Each texture that reads a target must read one an earlier pass wrote, and
// not the one its own pass writes.
void check_target_reads(const Frame& frame, const std::vector<std::string>& where) {
    std::set<std::string> written;
    for (size_t p = 0; p < frame.passes.size(); ++p) {
        const Pass& pass = frame.passes[p];
        for (const DrawCall& d : pass.draws)
            for (size_t i = 0; i < d.textures.size(); ++i) {
                const std::string& name = d.textures[i].target;
                if (name.empty()) continue;
                const std::string field = where[p] + "textures." + std::to_string(i) + ".target";
                bool known = false;
                for (const RenderTarget& t : frame.targets) known |= t.name == name;
                if (!known) throw InputError("field '" + field + "': no target named '" + name + "'");
                const bool writes = name == pass.target || std::any_of(pass.outputs.begin(), pass.outputs.end(),
                                                                       [&](const PassOutput& o) { return o.target == name; });
                if (writes)
                    throw InputError("field '" + field + "': a pass cannot read the target it writes ('" + name + "')");
                if (!written.count(name))
                    throw InputError("field '" + field + "': target '" + name + "' is not written by an earlier pass");
            }
        if (!pass.target.empty()) written.insert(pass.target);
        for (const PassOutput& o : pass.outputs) written.insert(o.target);
    }
    for (size_t t = 0; t < frame.targets.size(); ++t)
        if (!written.count(frame.targets[t].name))
            throw InputError("field 'targets." + std::to_string(t) + "': no pass writes target '" +
                             frame.targets[t].name + "'");
}

}  // namespace

Frame build_conformance_scene(JsonReader& scene, SceneSize size) {
    Frame frame;
    std::vector<std::string> where;
    if (scene.has("targets")) {
        for (JsonReader& t : declared_objects(scene, "targets")) {
            frame.targets.push_back(read_target(t));
            for (size_t i = 0; i + 1 < frame.targets.size(); ++i)
                if (frame.targets[i].name == frame.targets.back().name)
                    throw InputError("field '" + t.field("name") + "': target '" + frame.targets.back().name +
                                     "' is named twice");
        }
    }
    TexelBudget budget;  // the textures of every pass together
    if (scene.has("passes"))
        for (JsonReader& p : declared_objects(scene, "passes")) {
            where.push_back(p.path() + ".");
            frame.passes.push_back(read_pass(p, frame.targets, size, budget));
            p.finish();
        }
    where.push_back("");
    frame.passes.push_back(read_pass(scene, frame.targets, size, budget));
    if (!frame.passes.back().target.empty())
        throw InputError("field 'target': the scene's own pass draws the image; put target passes in 'passes'");
    check_target_reads(frame, where);
    return frame;
}

}  // namespace st
