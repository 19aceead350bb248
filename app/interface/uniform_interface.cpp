// uniform_interface.cpp: see uniform_interface.h. The declarations are
// flattened into the names GL gives each value ("lights[2].colour",
// "Matrices.projection"), each with its GLSL type and its file; a draw's
// uniforms and textures are looked up by name, and GL's active uniforms
// (where the run has GL) in the names the draw set.
#include "app/interface/uniform_interface.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <tuple>

#include "app/interface/varying_interface.h"
#include "app/tool_data.h"
#include "gl/gl_renderer.h"
#include "gl/shader_files.h"
#include "kernels/registry.h"
#include "scene/input_error.h"
#include "scene/scene.h"

namespace st {

namespace {

bool is_sampler(const std::string& type) { return type.find("sampler") != std::string::npos; }

// One value a draw can set: a uniform of a basic type or a sampler.
struct Leaf {
    std::string type;   // GLSL: "vec3", "bool", "sampler2D"
    std::string where;  // the declaring stage's file
};

constexpr size_t kMaxLeaves = 1 << 16;

class Flattened {
public:
    void add_stage(const GlslStage& s) {
        for (const GlslVariable& v : s.uniforms) expand(s, v.name, v.type, v.array_size);
        for (const GlslBlock& b : s.blocks) {
            if (b.storage != "uniform") continue;
            const std::string prefix = b.instance.empty() ? "" : b.name + ".";
            for (const GlslVariable& m : b.members) expand(s, prefix + m.name, m.type, m.array_size);
        }
    }
    const std::map<std::string, Leaf>& leaves() const { return leaves_; }

private:
    void expand(const GlslStage& s, const std::string& name, const std::string& type, int array_size) {
        if (array_size > 0)
            for (int i = 0; i < array_size; ++i) expand_one(s, name + "[" + std::to_string(i) + "]", type);
        else
            expand_one(s, name, type);
    }
    void expand_one(const GlslStage& s, const std::string& name, const std::string& type) {
        if (const GlslStruct* st = s.struct_named(type)) {
            for (const GlslVariable& m : st->members) expand(s, name + "." + m.name, m.type, m.array_size);
            return;
        }
        if (leaves_.size() >= kMaxLeaves)
            throw InputError(s.file_name() + ": more than " + std::to_string(kMaxLeaves) + " uniform values");
        leaves_.emplace(name, Leaf{type, s.file_name()});  // a uniform both stages declare: the first
    }

    std::map<std::string, Leaf> leaves_;
};

std::string glsl_name(UniformType t) {
    static const char* const names[] = {
        "float",   "vec2",    "vec3",    "vec4",    "int",     "mat4",    "ivec2",   "ivec3",   "ivec4",
        "uint",    "uvec2",   "uvec3",   "uvec4",   "mat2",    "mat3",    "mat2x3",  "mat2x4",  "mat3x2",
        "mat3x4",  "mat4x2",  "mat4x3",  "double",  "dvec2",   "dvec3",   "dvec4",   "dmat2",   "dmat3",
        "dmat4",   "dmat2x3", "dmat2x4", "dmat3x2", "dmat3x4", "dmat4x2", "dmat4x3"};
    static_assert(std::size(names) == size_t(UniformType::DMat4x3) + 1, "one name per UniformType, in order");
    return names[size_t(t)];
}

// Whether a value of type t sets a uniform declared as `glsl` (GL's rules:
// bool and bvecN take glUniform*i and *ui; matN is matNxN).
bool sets(UniformType t, std::string glsl) {
    if (glsl == "mat2x2" || glsl == "mat3x3" || glsl == "mat4x4" || glsl == "dmat2x2" || glsl == "dmat3x3" ||
        glsl == "dmat4x4")
        glsl.resize(glsl.size() - 2);
    const std::string name = glsl_name(t);
    if (glsl == "bool") return name == "int" || name == "uint";
    if (glsl.size() == 5 && glsl.compare(0, 4, "bvec") == 0)
        return name == "ivec" + glsl.substr(4) || name == "uvec" + glsl.substr(4);
    return name == glsl;
}

// Why `name` names nothing the stages declare, walking its path
// (base, [index], .member) through the declarations of either stage.
std::string why_undeclared(const std::string& name, const GlslStage& vs, const GlslStage& fs) {
    size_t p = 0;
    while (p < name.size() && (std::isalnum((unsigned char)name[p]) || name[p] == '_')) ++p;
    const std::string base = name.substr(0, p);
    const GlslStage* stage = nullptr;
    const GlslVariable* var = nullptr;
    GlslVariable block_member;  // a block's member found through "Block."
    for (const GlslStage* s : {&vs, &fs}) {
        for (const GlslVariable& v : s->uniforms)
            if (v.name == base) stage = s, var = &v;
        for (const GlslBlock& b : s->blocks) {
            if (b.storage != "uniform") continue;
            for (const GlslVariable& m : b.members) {
                if (b.instance.empty() && m.name == base) stage = s, var = &m;
                if (!b.instance.empty() && b.name == base && name.compare(p, 1, ".") == 0) {
                    size_t q = p + 1;
                    while (q < name.size() && (std::isalnum((unsigned char)name[q]) || name[q] == '_')) ++q;
                    if (name.substr(p + 1, q - p - 1) == m.name) stage = s, block_member = m, var = &block_member, p = q;
                }
            }
            if (!b.instance.empty() && b.name == base && !var)
                return "'" + name + "': uniform block " + b.name + " (" + s->file_name() + ") has no such member";
        }
        if (var) break;
    }
    if (!var)
        return "the scene sets uniform '" + name + "', which neither " + vs.file_name() + " nor " + fs.file_name() +
               " declares (a typo? a uniform only the twin reads is named twin_*)";
    std::string type = var->type;
    int array_size = var->array_size;
    std::string path = name.substr(0, p);
    while (p < name.size()) {
        if (name[p] == '[') {
            const size_t close = name.find(']', p);
            const std::string index = close == std::string::npos ? "" : name.substr(p + 1, close - p - 1);
            if (array_size == 0) return "uniform '" + name + "': " + path + " is " + with_article(type) + " in " + stage->file_name() + ", not an array";
            const bool digits = !index.empty() && index.size() < 9 &&
                                std::all_of(index.begin(), index.end(), [](char c) { return std::isdigit((unsigned char)c); });
            if (!digits || std::stoi(index) >= array_size)
                return "uniform '" + name + "': " + path + " is " + type + "[" + std::to_string(array_size) + "] in " +
                       stage->file_name() + " (indices 0 to " + std::to_string(array_size - 1) + ")";
            array_size = 0;
            path = name.substr(0, close + 1);
            p = close + 1;
        } else if (name[p] == '.') {
            size_t q = p + 1;
            while (q < name.size() && (std::isalnum((unsigned char)name[q]) || name[q] == '_')) ++q;
            const std::string member = name.substr(p + 1, q - p - 1);
            const GlslStruct* st = stage->struct_named(type);
            if (!st || array_size > 0)
                return "uniform '" + name + "': " + path + " is " + with_article(type) + (array_size ? "[]" : "") + " in " +
                       stage->file_name() + ", which has no member '" + member + "'";
            const auto m = std::find_if(st->members.begin(), st->members.end(),
                                        [&](const GlslVariable& v) { return v.name == member; });
            if (m == st->members.end())
                return "uniform '" + name + "': struct " + type + " (" + stage->file_name() + ") has no member '" + member + "'";
            type = m->type;
            array_size = m->array_size;
            path = name.substr(0, q);
            p = q;
        } else {
            return "the scene sets uniform '" + name + "', which is no name GL gives a uniform";
        }
    }
    return "uniform '" + name + "' is " + with_article(type) + (array_size ? "[" + std::to_string(array_size) + "]" : "") + " in " +
           stage->file_name() + ": set each " + (array_size ? "element ('" + name + "[0]', ...)" : "member") +
           " as GL names it";
}

}  // namespace

void check_draw_uniforms(const DrawCall& draw, const GlslStage& vs, const GlslStage& fs, const ActiveUniforms* active) {
    Flattened flat;
    flat.add_stage(vs);
    flat.add_stage(fs);
    const std::map<std::string, Leaf>& leaves = flat.leaves();
    // GL sets an array's element 0 by the array's name too.
    auto find = [&](const std::string& name) {
        auto it = leaves.find(name);
        return it != leaves.end() ? it : leaves.find(name + "[0]");
    };
    std::set<std::string> set;
    for (const Uniform& u : draw.uniforms) {
        if (u.name.rfind("twin_", 0) == 0) continue;
        const auto leaf = find(u.name);
        if (leaf == leaves.end()) throw InputError(why_undeclared(u.name, vs, fs));
        if (!set.insert(leaf->first).second) throw InputError("uniform '" + u.name + "' is set twice in one draw");
        const Leaf& l = leaf->second;
        if (is_sampler(l.type))
            throw InputError("uniform '" + u.name + "' is " + with_article(l.type) + " in " + l.where +
                             ": bind a texture to it, not a value");
        if (!sets(u.type, l.type))
            throw InputError("uniform '" + u.name + "' is " + with_article(l.type) + " in " + l.where +
                             ", and the scene sets " + with_article(glsl_name(u.type)));
    }
    for (const Texture& t : draw.textures) {
        const auto leaf = find(t.sampler);
        if (leaf == leaves.end() || !is_sampler(leaf->second.type))
            throw InputError("a texture is bound to sampler '" + t.sampler + "', which neither " + vs.file_name() +
                             " nor " + fs.file_name() + " declares as a sampler");
        const bool cube = leaf->second.type.find("Cube") != std::string::npos;
        if (cube != t.cube)
            throw InputError("sampler '" + t.sampler + "' is " + with_article(leaf->second.type) + " in " + leaf->second.where +
                             ", and the scene binds a " + (t.cube ? "cube map" : "2D texture") + " to it");
        if (!set.insert(leaf->first).second) throw InputError("sampler '" + t.sampler + "' has two textures bound in one draw");
    }
    if (!active) return;
    for (const GlRenderer::ActiveUniform& a : *active) {
        if (a.name.rfind("gl_", 0) == 0) continue;  // GL's own state (gl_DepthRange), no scene's to set
        // An array is reported once, as "name[0]", with its size.
        const bool array = a.name.size() > 3 && a.name.compare(a.name.size() - 3, 3, "[0]") == 0;
        const std::string base = array ? a.name.substr(0, a.name.size() - 3) : a.name;
        for (int i = 0; i < (array ? a.size : 1); ++i) {
            const std::string name = array ? base + "[" + std::to_string(i) + "]" : a.name;
            const auto leaf = find(name);
            if (leaf != leaves.end() && set.count(leaf->first)) continue;
            const std::string type = leaf == leaves.end() ? "" : leaf->second.type + " in " + leaf->second.where + ", ";
            if (leaf != leaves.end() && is_sampler(leaf->second.type))
                throw InputError("sampler '" + name + "' (" + type + "active in the program) has no texture bound: GL would sample unit 0");
            throw InputError("uniform '" + name + "' (" + type + "active in the program) is never set by the scene: GL would read 0");
        }
    }
}

void check_frame_uniforms(const Frame& frame, const std::vector<std::string>& glsl_roots, const ActiveUniformsOf& active) {
    // Each file is read and parsed once per process; the roots are indexed
    // once per set of roots.
    static std::mutex mutex;
    static std::map<std::vector<std::string>, std::unique_ptr<ShaderFiles>> indexes;
    static std::map<std::string, std::shared_ptr<const GlslStage>> stages;
    static std::map<std::pair<std::string, std::string>, ActiveUniforms> programs;
    static std::set<std::tuple<std::string, std::string, int, std::vector<std::string>, int, std::vector<std::string>>>
        twins_checked;
    std::lock_guard<std::mutex> lock(mutex);
    auto& files = indexes[glsl_roots];
    auto stage = [&](const std::string& name, const char* extension) {
        const std::string& path = files->path(name, extension);
        auto& s = stages[path];
        if (!s) s = std::make_shared<const GlslStage>(parse_glsl_stage(read_glsl_source(path), path));
        return s;
    };
    for (const Pass& pass : frame.passes)
        for (const DrawCall& draw : pass.draws) {
            std::shared_ptr<const GlslStage> vs, fs;
            const ActiveUniforms* program = nullptr;
            try {
                if (!files) files = std::make_unique<ShaderFiles>(glsl_roots);
                vs = stage(draw.vertex, ".vert");
                fs = stage(draw.fragment, ".frag");
            } catch (const InputError&) {
                throw;
            } catch (const std::runtime_error& e) {  // no such file
                throw InputError(e.what());
            }
            // The twins' slots against the GLSL's inputs and outputs, once per
            // program and attribute columns (a program without twins runs on GL
            // only); before GL links it, whose log says less.
            const int targets = 1 + int(pass.outputs.size());
            const auto key = std::make_tuple(draw.vertex, draw.fragment, draw.vertices.attribute_count,
                                             draw.vertices.names, targets, draw.output_names);
            if (!twins_checked.count(key)) {
                const std::unique_ptr<VertexTwin> vt = make_vertex_twin(draw.vertex);
                const std::unique_ptr<FragmentTwin> ft = make_fragment_twin(draw.fragment);
                if (vt && ft) check_twin_varyings(*vs, *vt, *fs, *ft, draw.vertices, targets, draw.output_names);
                twins_checked.insert(key);
            }
            // A program GL cannot compile fails here as it would at render.
            if (active) {
                const auto pair = std::make_pair(draw.vertex, draw.fragment);
                auto it = programs.find(pair);
                if (it == programs.end()) it = programs.emplace(pair, active(draw.vertex, draw.fragment)).first;
                program = &it->second;
            }
            check_draw_uniforms(draw, *vs, *fs, program);
        }
}

void install_frame_check(GlPlatform platform) {
    set_frame_check([platform](const Frame& frame) {
        static std::mutex mutex;
        // Never destroyed: at exit OSMesa has torn its state down before a
        // static's destructor would run, and making the context current
        // then crashes. Reachable to the end, so no leak check reports it.
        static GlRenderer* gl = nullptr;
        static bool no_gl = false;
        {
            std::lock_guard<std::mutex> lock(mutex);
            if (!gl && !no_gl) {
                try {
                    gl = new GlRenderer(glsl_roots(), platform);
                } catch (const std::exception&) {
                    no_gl = true;  // rendering with GL would fail too, and say why
                }
            }
        }
        ActiveUniformsOf active;
        if (gl)
            active = [](const std::string& vertex, const std::string& fragment) {
                std::lock_guard<std::mutex> lock(mutex);
                return gl->active_uniforms(vertex, fragment);
            };
        check_frame_uniforms(frame, glsl_roots(), active);
    });
}

}  // namespace st
