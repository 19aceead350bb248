// skeleton_files.cpp: see skeleton_files.h. First the interface the two
// stages share (attributes, varying slots, the output, the uniforms), then
// one function per file written from it.
#include "app/new_technique/skeleton_files.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "scene/input_error.h"
#include "scene/uniform_fields.h"

namespace st::skeleton {

namespace {

constexpr int kSlots = 8;        // shading/program.h kMaxVaryings
constexpr int kAttributes = 16;  // vec4 attributes a vertex may have
constexpr int kMaxOutputs = 4;   // frame/frame.h kMaxFragmentOutputs

// ---- the interface ------------------------------------------------------

struct Attribute {
    std::string name, type;
    int location = 0;
};

struct Varying {
    std::string vertex_name;    // as the vertex GLSL writes it: "v_uv", "vs_out.uv"
    std::string fragment_name;  // as the fragment GLSL reads it
    std::string constant;       // the vertex twin's slot constant: "v_uv", "vs_out_uv"
    std::string fragment_constant;  // the fragment twin's: "v_uv", "fs_in_uv"
    std::string gl_name;        // as GL names it, the same in both stages: "v_uv", "VS_OUT.uv"
    std::string type;
    int slot = 0;
    std::string interpolation = "smooth";  // the fragment input's: smooth, noperspective or flat
};

struct Interface {
    std::vector<Attribute> attributes;
    std::vector<GlslVariable> outputs;  // the fragment outputs, by location
    bool outputs_by_name = false;       // some of several have no location: the scene binds them
    std::vector<Varying> varyings;
    std::vector<GlslVariable> vertex_uniforms, fragment_uniforms, uniforms;  // uniforms: both, each once
    std::vector<GlslStruct> structs;                                        // those the uniforms use
};

// Each variable's location: its layout(location), else the next one no
// variable declares, in declaration order (attribute columns, varying
// slots and outputs are all placed so).
std::vector<int> locations_of(const std::vector<GlslVariable>& vars) {
    std::set<int> taken;
    for (const GlslVariable& v : vars)
        if (v.location >= 0) taken.insert(v.location);
    std::vector<int> out;
    int next = 0;
    for (const GlslVariable& v : vars) {
        if (v.location >= 0) {
            out.push_back(v.location);
            continue;
        }
        while (taken.count(next)) ++next;
        taken.insert(next);
        out.push_back(next);
    }
    return out;
}

// What the fragment twin's main() returns: one Vec4, or one per output location.
std::string result_type(const Interface& in) {
    return in.outputs.size() == 1 ? "st::Vec4" : "st::FragmentOutputs<" + std::to_string(in.outputs.size()) + ">";
}

[[noreturn]] void refuse(const GlslStage& s, int line, const std::string& why) {
    throw InputError(s.path + ":" + std::to_string(line) + ": " + why);
}

int components(const std::string& type) {
    if (type == "float") return 1;
    if (type == "vec2") return 2;
    if (type == "vec3") return 3;
    if (type == "vec4") return 4;
    return 0;
}

// A varying's type: how many components, and of what ('f' float, 'i' int,
// 'u' uint; ints travel in their float slot's bits, flat). 0 components:
// not a type a varying slot carries.
struct VaryingType {
    int components = 0;
    char kind = 'f';
};
VaryingType varying_type(const std::string& type) {
    if (const int c = components(type)) return {c, 'f'};
    if (type == "int" || type == "uint") return {1, type[0]};
    if (type.size() == 5 && (type.rfind("ivec", 0) == 0 || type.rfind("uvec", 0) == 0) && type[4] >= '2' && type[4] <= '4')
        return {type[4] - '0', type[0]};
    return {0, 'f'};
}

const char* swizzle(int n) { return n == 1 ? "x" : n == 2 ? "xy" : n == 3 ? "xyz" : "xyzw"; }
const char* lane_type(int n) { return n == 1 ? "Float" : n == 2 ? "Vec2" : n == 3 ? "Vec3" : "Vec4"; }

std::string constant_name(const std::string& glsl_name) {
    std::string c = glsl_name;
    std::replace(c.begin(), c.end(), '.', '_');
    return c;
}

bool is_sampler(const std::string& type) { return type == "sampler2D" || type == "samplerCube"; }

// Every member of a stage's in (out) blocks as variables named as GL does.
std::vector<GlslVariable> block_members(const GlslStage& s, const std::string& storage) {
    std::vector<GlslVariable> out;
    for (const GlslBlock& b : s.blocks) {
        if (b.storage != storage) continue;
        if (b.array_size) refuse(s, b.line, "an arrayed block '" + b.name + "': not modelled");
        int location = b.location;
        for (GlslVariable m : b.members) {
            m.name = b.instance.empty() ? m.name : b.instance + "." + m.name;
            if (m.location < 0 && location >= 0) m.location = location;
            if (m.location >= 0) location = m.location + 1;
            out.push_back(std::move(m));
        }
    }
    return out;
}

// The block member name without its instance ("vs_out.uv" -> "Block.uv"),
// which is how GL matches a block's members between stages.
std::string block_key(const GlslStage& s, const std::string& storage, const std::string& name) {
    for (const GlslBlock& b : s.blocks)
        if (b.storage == storage && !b.instance.empty() && name.rfind(b.instance + ".", 0) == 0)
            return b.name + "." + name.substr(b.instance.size() + 1);
        else if (b.storage == storage && b.instance.empty())
            for (const GlslVariable& m : b.members)
                if (m.name == name) return b.name + "." + name;
    return name;
}

void check_uniform_type(const GlslStage& s, const GlslVariable& u, std::set<std::string>& structs_used) {
    if (is_sampler(u.type)) {

        return;
    }
    if (is_uniform_field_type(u.type)) return;
    if (const GlslStruct* st = s.struct_named(u.type)) {
        structs_used.insert(st->name);
        for (const GlslVariable& m : st->members) {
            if (is_sampler(m.type)) refuse(s, m.line, "a sampler in a struct ('" + u.name + "." + m.name + "'): not modelled");
            check_uniform_type(s, m, structs_used);
        }
        return;
    }
    refuse(s, u.line, "uniform " + u.type + " " + u.name + ": shadertwin sets float, double, int, uint, bool, their "
                      "vectors and matrices, sampler2D, samplerCube, and structs and arrays of them");
}

Interface interface_of(const GlslStage& vert, const GlslStage& frag) {
    Interface in;
    // Uniform blocks: GL names a member "Block.member" when the block has
    // an instance name (the twin holds the instance as a struct of the
    // block's type), else "member" (a uniform of its own); the GL side fills
    // each block's buffer from the uniforms so named (gl/uniform_blocks.h).
    std::vector<GlslStruct> block_types;
    std::vector<std::vector<GlslVariable>> block_uniforms(2);
    for (int k = 0; k < 2; ++k) {
        const GlslStage& s = k == 0 ? vert : frag;
        for (const GlslBlock& b : s.blocks) {
            if (b.storage != "uniform") continue;
            if (b.array_size) refuse(s, b.line, "an arrayed uniform block ('" + b.name + "'): not modelled");
            if (b.instance.empty()) {
                for (const GlslVariable& m : b.members) block_uniforms[size_t(k)].push_back(m);
                continue;
            }
            block_types.push_back({b.name, b.members});
            GlslVariable v;
            v.type = b.name, v.name = b.instance, v.gl_name = b.name, v.line = b.line;
            block_uniforms[size_t(k)].push_back(v);
        }
    }
    // Attributes: column N of each vertex is location N, and an input
    // without a location takes the next free column (the scene names every
    // column's input, so GL binds it by name: VertexArray::names).
    const std::vector<int> columns = locations_of(vert.inputs);
    for (size_t k = 0; k < vert.inputs.size(); ++k) {
        const GlslVariable& v = vert.inputs[k];
        if (!components(v.type) || v.array_size)
            refuse(vert, v.line, "input " + v.type + " " + v.name + ": attributes are float, vec2, vec3 or vec4");
        const int column = columns[k];
        if (column >= kAttributes) refuse(vert, v.line, "input '" + v.name + "' in column " + std::to_string(column) + ": at most 16 attributes");
        in.attributes.push_back({v.name, v.type, column});
    }
    std::sort(in.attributes.begin(), in.attributes.end(), [](const Attribute& a, const Attribute& b) { return a.location < b.location; });
    // Varyings: the vertex outputs' slots (its location, else the next free one).
    std::vector<GlslVariable> outs = vert.outputs;
    for (const GlslVariable& m : block_members(vert, "out")) outs.push_back(m);
    const std::vector<int> slots = locations_of(outs);
    for (size_t k = 0; k < outs.size(); ++k) {
        const GlslVariable& v = outs[k];
        if (!varying_type(v.type).components || v.array_size)
            refuse(vert, v.line, "output " + v.type + " " + v.name + ": varyings are float, int and uint and their vectors "
                                 "(one slot each; arrays, structs, doubles and matrices are not modelled)");
        Varying y;
        y.vertex_name = v.name, y.constant = constant_name(v.name), y.type = v.type;
        y.gl_name = block_key(vert, "out", v.name);
        y.slot = slots[k];
        if (y.slot >= kSlots) refuse(vert, v.line, "output '" + v.name + "' in slot " + std::to_string(y.slot) + ": at most 8 varyings (slots 0-7)");
        in.varyings.push_back(y);
    }
    // Fragment inputs find theirs by location, else by name.
    std::vector<GlslVariable> ins = frag.inputs;
    for (const GlslVariable& m : block_members(frag, "in")) ins.push_back(m);
    for (const GlslVariable& v : ins) {
        Varying* match = nullptr;
        for (Varying& y : in.varyings) {
            const bool by_location = v.location >= 0 && y.slot == v.location;
            const bool by_name = v.location < 0 && block_key(vert, "out", y.vertex_name) == block_key(frag, "in", v.name);
            if (by_location || by_name) match = &y;
        }
        if (!match) refuse(frag, v.line, "input '" + v.name + "' has no vertex output of its " + (v.location >= 0 ? "location" : "name"));
        if (v.type != match->type)
            refuse(frag, v.line, "input " + v.type + " " + v.name + " meets output " + match->type + " " + match->vertex_name);
        // The fragment input's qualifier decides (GLSL 4.50, 4.5); centroid
        // and sample change nothing on a single-sampled target.
        for (const std::string& q : v.qualifiers)
            if (q == "flat" || q == "noperspective" || q == "smooth") match->interpolation = q;
        if (varying_type(v.type).kind != 'f' && match->interpolation != "flat")
            refuse(frag, v.line, "input " + v.type + " " + v.name + ": an integer input must be qualified flat (GLSL 4.50, 4.5)");
        match->fragment_name = v.name;
        match->fragment_constant = constant_name(v.name);
    }
    // One vec4 out (location 0).
    // Outputs: float ... vec4 at locations 0 ... N-1 (a lone one may have
    // none: GL puts it at 0), one colour buffer each.
    if (frag.outputs.empty()) refuse(frag, 1, "the fragment stage has no output");
    if (int(frag.outputs.size()) > kMaxOutputs)
        refuse(frag, frag.outputs.back().line, "at most " + std::to_string(kMaxOutputs) + " outputs (locations 0-3)");
    // Several outputs without locations take the free ones in declaration
    // order, and the scene binds them by name (glBindFragDataLocation).
    const std::vector<int> locations = locations_of(frag.outputs);
    for (size_t k = 0; k < frag.outputs.size(); ++k) {
        const GlslVariable& v = frag.outputs[k];
        if (!components(v.type) || v.array_size)
            refuse(frag, v.line, "output " + v.type + " " + v.name + ": outputs are float, vec2, vec3 or vec4 (float targets)");
        if (v.location < 0 && frag.outputs.size() > 1) in.outputs_by_name = true;
        GlslVariable o = v;
        o.location = locations[k];
        in.outputs.push_back(o);
    }
    std::sort(in.outputs.begin(), in.outputs.end(), [](const GlslVariable& a, const GlslVariable& b) { return a.location < b.location; });
    for (size_t k = 0; k < in.outputs.size(); ++k)
        if (in.outputs[k].location != int(k))
            refuse(frag, in.outputs[k].line, "output '" + in.outputs[k].name + "' at location " +
                                                 std::to_string(in.outputs[k].location) + ": the outputs' locations must be 0 to " +
                                                 std::to_string(in.outputs.size() - 1));
    // Uniforms: each stage's, and all of them once.
    std::set<std::string> structs_used;
    GlslStage vert_types = vert, frag_types = frag;  // the stages' structs and the blocks' types
    for (const GlslStruct& t : block_types) vert_types.structs.push_back(t), frag_types.structs.push_back(t);
    for (int k = 0; k < 2; ++k) {
        const GlslStage* s = k == 0 ? &vert_types : &frag_types;
        std::vector<GlslVariable> all = (k == 0 ? vert : frag).uniforms;
        for (const GlslVariable& b : block_uniforms[size_t(k)]) all.push_back(b);
        for (const GlslVariable& u : all) {
            check_uniform_type(*s, u, structs_used);
            (k == 0 ? in.vertex_uniforms : in.fragment_uniforms).push_back(u);
            const auto same = std::find_if(in.uniforms.begin(), in.uniforms.end(), [&](const GlslVariable& o) { return o.gl() == u.gl(); });
            if (same == in.uniforms.end()) in.uniforms.push_back(u);
            else if (same->type != u.type || same->array_size != u.array_size)
                refuse(*s, u.line, "uniform '" + u.name + "' is " + same->type + " in the other stage");
        }
    }
    for (const GlslStage* s : {&vert_types, &frag_types})
        for (const GlslStruct& st : s->structs)
            if (structs_used.count(st.name) &&
                std::none_of(in.structs.begin(), in.structs.end(), [&](const GlslStruct& o) { return o.name == st.name; }))
                in.structs.push_back(st);
    return in;
}

// ---- C++ spelling -------------------------------------------------------

std::string camel(const std::string& name) {
    std::string out;
    bool up = true;
    for (char c : name) {
        if (c == '_') {
            up = true;
            continue;
        }
        out += up ? char(std::toupper((unsigned char)c)) : c;
        up = false;
    }
    return out;
}

// A uniform's member type in a twin (the host's value, broadcast to lanes where used).
std::string member_type(const std::string& t) {
    static const std::map<std::string, std::string> types = {
        {"float", "float"},          {"vec2", "glm::vec2"},       {"vec3", "glm::vec3"},       {"vec4", "glm::vec4"},
        {"int", "int"},              {"ivec2", "glm::ivec2"},     {"ivec3", "glm::ivec3"},     {"ivec4", "glm::ivec4"},
        {"uint", "uint32_t"},        {"uvec2", "glm::uvec2"},     {"uvec3", "glm::uvec3"},     {"uvec4", "glm::uvec4"},
        {"bool", "bool"},            {"bvec2", "glm::bvec2"},     {"bvec3", "glm::bvec3"},     {"bvec4", "glm::bvec4"},
        {"mat2", "glm::mat2"},       {"mat3", "glm::mat3"},       {"mat4", "glm::mat4"},
        {"mat2x2", "glm::mat2"},     {"mat3x3", "glm::mat3"},     {"mat4x4", "glm::mat4"},
        {"mat2x3", "glm::mat2x3"},   {"mat2x4", "glm::mat2x4"},   {"mat3x2", "glm::mat3x2"},
        {"mat3x4", "glm::mat3x4"},   {"mat4x2", "glm::mat4x2"},   {"mat4x3", "glm::mat4x3"},
        {"double", "double"},        {"dvec2", "glm::dvec2"},     {"dvec3", "glm::dvec3"},     {"dvec4", "glm::dvec4"},
        {"dmat2", "glm::dmat2"},     {"dmat3", "glm::dmat3"},     {"dmat4", "glm::dmat4"},
        {"dmat2x2", "glm::dmat2"},   {"dmat3x3", "glm::dmat3"},   {"dmat4x4", "glm::dmat4"},
        {"dmat2x3", "glm::dmat2x3"}, {"dmat2x4", "glm::dmat2x4"}, {"dmat3x2", "glm::dmat3x2"},
        {"dmat3x4", "glm::dmat3x4"}, {"dmat4x2", "glm::dmat4x2"}, {"dmat4x3", "glm::dmat4x3"},
        {"sampler2D", "const st::Sampler2D*"}, {"samplerCube", "const st::SamplerCube*"}};
    const auto it = types.find(t);
    return it == types.end() ? t : it->second;  // a struct: its mirror
}

std::string member_decl(const GlslVariable& u, const std::string& suffix) {
    const std::string t = member_type(u.type);
    const std::string init = is_sampler(u.type) ? " = nullptr" : "{}";
    if (u.array_size) return "std::array<" + t + ", " + std::to_string(u.array_size) + "> " + u.name + suffix + "{};";
    return t + " " + u.name + suffix + init + ";";
}

// The Bindings call that reads a uniform of this type by its GL name (an
// expression of std::string `gl`).
std::string getter(const std::string& t, const std::string& gl) {
    if (t == "sampler2D") return "&b.sampler(" + gl + ")";
    if (t == "samplerCube") return "&b.sampler_cube(" + gl + ")";
    if (t.rfind("bvec", 0) == 0) return "glm::" + t + "(b.get_i" + t.substr(1) + "(" + gl + "))";
    if (t == "mat2x2" || t == "mat3x3" || t == "mat4x4") return "b.get_" + t.substr(0, 4) + "(" + gl + ")";
    if (t == "dmat2x2" || t == "dmat3x3" || t == "dmat4x4") return "b.get_" + t.substr(0, 5) + "(" + gl + ")";
    return "b.get_" + t + "(" + gl + ")";
}

// bind() lines for one uniform (`target` is the member's C++ path, `gl`
// the GL name as a C++ string expression), through structs and arrays.
void bind_lines(const Interface& in, const GlslVariable& u, const std::string& target, const std::string& gl,
                const std::string& indent, std::ostringstream& o) {
    const GlslStruct* st = nullptr;
    for (const GlslStruct& s : in.structs)
        if (s.name == u.type) st = &s;
    const auto one = [&](const std::string& t, const std::string& g, const std::string& ind) {
        if (!st) {
            o << ind << t << " = " << getter(u.type, g) << ";\n";
            return;
        }
        for (const GlslVariable& m : st->members)
            bind_lines(in, m, t + "." + m.name, "std::string(" + g + ") + \"." + m.name + "\"", ind, o);
    };
    if (u.array_size && !st && !is_sampler(u.type)) {  // a whole array of values in one call
        o << indent << target << " = b.array<" << member_type(u.type) << ", " << u.array_size << ">(" << gl << ");\n";
    } else if (u.array_size) {
        const std::string i = "i" + std::to_string(indent.size() / 4);  // apart from an enclosing loop's
        o << indent << "for (int " << i << " = 0; " << i << " < " << u.array_size << "; ++" << i << ")";
        o << (st ? " {\n" : "\n");
        one(target + "[size_t(" + i + ")]", "std::string(" + gl + ") + \"[\" + std::to_string(" + i + ") + \"]\"", indent + "    ");
        if (st) o << indent << "}\n";
    } else {
        one(target, gl, indent);
    }
}

std::string as_comment(const std::string& text, const std::string& indent) {
    std::istringstream in(text);
    std::ostringstream o;
    std::string line;
    while (std::getline(in, line)) {
        while (!line.empty() && (line.back() == ' ' || line.back() == '\t' || line.back() == '\r')) line.pop_back();
        o << indent << "//" << (line.empty() ? "" : " ") << line << "\n";
    }
    return o.str();
}

std::string function_text(const GlslFunction& f) {
    return f.return_type + " " + f.name + "(" + f.parameters + ") " + f.body;
}

// ---- files ----------------------------------------------------------------

struct Names {
    std::string name, camel, vertex_class, fragment_class, header;
};

std::string header_file(const Names& n, const Interface& in) {
    std::ostringstream o;
    o << "// " << n.name << ".h: twins of glsl/" << n.name << ".vert and glsl/" << n.name
      << ".frag, and the scene kind\n// that draws them. Written by `shadertwin new-technique`; the twins' bodies are "
         "yours\n// to write (docs/adding-a-technique.md).\n#pragma once\n\n#include <array>\n#include <cstdint>\n#include "
         "<string>\n\n#include <glm/glm.hpp>\n\n#include \"scene/scene_kinds.h\"\n#include \"shading/program.h\"\n";
    for (const GlslStruct& s : in.structs) {
        o << "\n// GLSL struct " << s.name << ", as the twins hold it.\nstruct " << s.name << " {\n";
        for (const GlslVariable& m : s.members) o << "    " << member_decl(m, "") << "\n";
        o << "};\n";
    }
    int varying_count = 0;
    for (const Varying& y : in.varyings) varying_count = std::max(varying_count, y.slot + 1);
    // Each slot's GLSL name, as GL names it: how every run finds the GLSL
    // variable a slot holds when the shader gives no locations.
    auto slot_names = [&](bool inputs) {
        std::vector<std::string> names(static_cast<size_t>(varying_count));
        for (const Varying& y : in.varyings)
            if (!inputs || !y.fragment_name.empty()) names[size_t(y.slot)] = y.gl_name;
        while (!names.empty() && names.back().empty()) names.pop_back();
        std::string list;
        for (const std::string& name : names) list += (list.empty() ? "\"" : ", \"") + name + "\"";
        return "{" + list + "}";
    };
    o << "\nclass " << n.vertex_class << " final : public st::VertexTwin {\npublic:\n    int varying_count() const override { return "
      << varying_count << "; }\n"
      << "    // The GLSL outputs in slots 0, 1, ... (checked against the GLSL on every run).\n"
      << "    st::SlotNames output_names() const override { return " << slot_names(false) << "; }\n";
    if (!in.vertex_uniforms.empty()) o << "    void bind(const st::Bindings& b) override;\n";
    o << "    void run(const glm::vec4* attributes, st::VertexOut& out) const override;\n"
      << "    // Delete once run() is written: until then `compare` fails, saying so.\n"
      << "    const char* unwritten() const override {\n        return \"write run() in kernels/" << n.name
      << "_vert.cpp from the GLSL in its comments, then delete unwritten() in kernels/" << n.name << ".h\";\n    }\n";
    if (!in.vertex_uniforms.empty()) {
        o << "\nprivate:\n";
        for (const GlslVariable& u : in.vertex_uniforms) o << "    " << member_decl(u, "_") << "  // uniform " << u.type << " " << u.name << "\n";
    }
    o << "};\n\nclass " << n.fragment_class << " final : public st::FragmentProgram<" << n.fragment_class << "> {\npublic:\n";
    if (!in.fragment_uniforms.empty()) o << "    void bind(const st::Bindings& b) override;\n";
    o << "    // The GLSL inputs in slots 0, 1, ... (checked against the GLSL on every run).\n"
      << "    st::SlotNames input_names() const override { return " << slot_names(true) << "; }\n"
      << "    // The varying components main() reads: only these are interpolated.\n"
      << "    uint32_t inputs_read() const override;\n";
    if (std::any_of(in.varyings.begin(), in.varyings.end(),
                    [](const Varying& y) { return !y.fragment_name.empty() && y.interpolation != "smooth"; }))
        o << "    // The inputs' interpolation qualifiers (flat, noperspective).\n"
          << "    st::Interpolations interpolations() const override;\n";
    o << "    " << result_type(in) << " main(const st::Fragment& frag) const;\n"
      << "    // Delete once main() is written: until then `compare` fails, saying so.\n"
      << "    const char* unwritten() const override {\n        return \"write main() in kernels/" << n.name
      << "_frag.cpp from the GLSL in its comments, then delete unwritten() in kernels/" << n.name << ".h\";\n    }\n";
    if (!in.fragment_uniforms.empty()) {
        o << "\nprivate:\n";
        for (const GlslVariable& u : in.fragment_uniforms) o << "    " << member_decl(u, "_") << "  // uniform " << u.type << " " << u.name << "\n";
    }
    o << "};\n\n// The \"" << n.name << "\" scene kind (scenes/*.json with \"kind\": \"" << n.name << "\").\nst::Frame build_"
      << n.name << "_scene(st::JsonReader& scene, st::SceneSize size);\n";
    return o.str();
}

void other_functions(const GlslStage& s, const char* lanes, std::ostringstream& o) {
    for (const GlslFunction& f : s.functions) {
        if (f.name == "main") continue;
        o << "\n// GLSL " << f.return_type << " " << f.name << "(" << f.parameters << "), line " << f.line
          << ": write it here, under its name, over " << lanes << " (a member function if it reads a uniform):\n//\n"
          << as_comment(function_text(f), "");
    }
}

void bind_function(const Interface& in, const std::vector<GlslVariable>& uniforms, const std::string& cls, std::ostringstream& o) {
    if (uniforms.empty()) return;
    o << "\nvoid " << cls << "::bind(const st::Bindings& b) {\n";
    for (const GlslVariable& u : uniforms) bind_lines(in, u, u.name + "_", "\"" + u.gl() + "\"", "    ", o);
    o << "}\n";
}

std::string vertex_file(const Names& n, const Interface& in, const GlslStage& vert) {
    std::ostringstream o;
    o << "// " << n.name << "_vert.cpp: twin of glsl/" << n.name << ".vert, line for line, one vertex at a time.\n#include \""
      << n.name << ".h\"\n\n#include \"shading/glsl_math.h\"\n#include \"shading/glsl_texture.h\"\n\nnamespace {\n";
    for (const Attribute& a : in.attributes)
        o << "constexpr int " << a.name << " = " << a.location << ";  // attribute " << a.location << ": in " << a.type << " " << a.name << "\n";
    for (const Varying& y : in.varyings)
        o << "constexpr int " << y.constant << " = " << y.slot << ";  // varying slot: out " << y.type << " " << y.vertex_name << "\n";
    o << "}  // namespace\n";
    other_functions(vert, "floats and glm vectors", o);
    bind_function(in, in.vertex_uniforms, n.vertex_class, o);
    o << "\nvoid " << n.vertex_class << "::run(const glm::vec4* attributes, st::VertexOut& out) const {\n"
      << "    using namespace st::glsl;\n"
      << "    // The GLSL's names, as the twin reads and writes them:\n";
    for (const Attribute& a : in.attributes)
        o << "    //   " << a.name << "  ->  " << (a.type == "vec4" ? "attributes[" + a.name + "]" : a.type == "float" ? "attributes[" + a.name + "].x" : "glm::" + a.type + "(attributes[" + a.name + "])") << "\n";
    o << "    //   gl_Position  ->  out.position\n";
    for (const Varying& y : in.varyings) {
        const VaryingType t = varying_type(y.type);
        // An int's bits travel in the float slot (flat keeps them).
        const std::string v = t.kind == 'i' ? "intBitsToFloat(v)" : t.kind == 'u' ? "uintBitsToFloat(v)" : "v";
        o << "    //   " << y.vertex_name << " = v  ->  out.varyings[" << y.constant << "] = "
          << (t.components == 4 ? (t.kind == 'f' ? v : "glm::vec4(" + v + ")")
              : t.components == 1 ? "glm::vec4(" + v + ", 0, 0, 0)" : "glm::vec4(" + v + ", ...)") << "\n";
    }
    o << "    //   uniforms: their members (light_dir -> light_dir_); glsl::mul(m, v) for m * v on glm\n"
      << "    // GLSL main(), to write here:\n    //\n" << as_comment(function_text(*vert.function("main")), "    ")
      << "    out.position = " << (in.attributes.empty() ? "glm::vec4(0.0f)" : "attributes[" + in.attributes.front().name + "]")
      << ";  // until run() is written (unwritten() says so)\n}\n";
    return o.str();
}

std::string fragment_file(const Names& n, const Interface& in, const GlslStage& frag) {
    std::ostringstream o;
    o << "// " << n.name << "_frag.cpp: twin of glsl/" << n.name << ".frag, line for line, on all lanes at once.\n#include \""
      << n.name << ".h\"\n\n#include \"shading/glsl_math.h\"\n#include \"shading/glsl_texture.h\"\n\nnamespace {\n";
    std::vector<const Varying*> read;
    for (const Varying& y : in.varyings)
        if (!y.fragment_name.empty()) {
            read.push_back(&y);
            o << "constexpr int " << y.fragment_constant << " = " << y.slot << ";  // in " << y.type << " " << y.fragment_name << "\n";
        }
    o << "}  // namespace\n";
    other_functions(frag, "lanes (Float, Vec2 ... Vec4, Mat3)", o);
    bind_function(in, in.fragment_uniforms, n.fragment_class, o);
    o << "\n// Every component of every input; narrow it to what main() reads.\nuint32_t " << n.fragment_class << "::inputs_read() const { return ";
    if (read.empty()) o << "0";
    for (size_t i = 0; i < read.size(); ++i)
        o << (i ? " | " : "") << "st::reads(" << read[i]->fragment_constant << ", \"" << swizzle(varying_type(read[i]->type).components) << "\")";
    o << "; }\n";
    if (std::any_of(read.begin(), read.end(), [](const Varying* y) { return y->interpolation != "smooth"; })) {
        o << "\n// Each input's interpolation qualifier, as the GLSL declares it (smooth unless named).\nst::Interpolations "
          << n.fragment_class << "::interpolations() const {\n    st::Interpolations q{};\n";
        for (const Varying* y : read)
            if (y->interpolation != "smooth")
                o << "    q[" << y->fragment_constant << "] = st::Interpolation::" << (y->interpolation == "flat" ? "Flat" : "NoPerspective")
                  << ";  // " << y->interpolation << " in " << y->type << " " << y->fragment_name << "\n";
        o << "    return q;\n}\n";
    }
    o << "\n" << result_type(in) << " " << n.fragment_class << "::main(const st::Fragment& frag) const {\n"
      << "    using namespace st;\n    using namespace st::glsl;\n"
      << "    // The GLSL's names, as the twin reads them:\n";
    for (const Varying* y : read) {
        const VaryingType t = varying_type(y->type);
        const int c = t.components;
        const std::string value = "frag.varying(" + y->fragment_constant + ")" + (c == 4 ? "" : c == 1 ? ".x" : std::string(".") + swizzle(c) + "()");
        o << "    //   " << y->fragment_name << "  ->  "
          << (t.kind == 'i' ? "floatBitsToInt(" + value + ")" : t.kind == 'u' ? "floatBitsToUint(" + value + ")" : value) << ";\n";
    }
    for (const GlslVariable& u : in.fragment_uniforms) {
        const std::string at = u.array_size ? "[i]" : "";
        if (is_sampler(u.type)) o << "    //   texture(" << u.name << at << ", p)  ->  texture(*" << u.name << "_" << at << ", p)\n";
        else if (components(u.type))
            o << "    //   " << u.name << at << "  ->  " << lane_type(components(u.type)) << "(" << u.name << "_" << at << ")\n";
        else if (u.type == "double" || u.type.rfind("dvec", 0) == 0)
            o << "    //   " << u.name << at << "  ->  " << (u.type == "double" ? "Double" : "DVec" + u.type.substr(4)) << "(" << u.name
              << "_" << at << ") (Double lanes: simd/lane_double.h)\n";
        else o << "    //   " << u.name << at << "  ->  " << u.name << "_" << at << " (" << member_type(u.type) << "; Vec3(v) makes lanes of a glm::vec3 v)\n";
    }
    o << "    //   gl_FragCoord  ->  frag.frag_coord();  discard, loops, ifs that assign: frag.exec()\n"
      << "    // GLSL main(), to write here (" << (in.outputs.size() == 1 ? "its output is the value returned" : "its outputs are the values returned, by location")
      << "):\n";
    for (const GlslVariable& out : in.outputs)
        if (components(out.type) < 4)
            o << "    //   out " << out.type << " " << out.name << ": return Vec4(" << out.name
              << ", ...) with 0.0 for the components it lacks, as llvmpipe writes them (its outputs start at zero)\n";
    o << "    //\n" << as_comment(function_text(*frag.function("main")), "    ");
    if (in.outputs.size() == 1)
        o << "    return Vec4(Float(0.0f));  // until main() is written (unwritten() says so)\n}\n";
    else
        o << "    return {};  // until main() is written (unwritten() says so): one Vec4 per location\n}\n";
    return o.str();
}

// What an attribute holds on the grid, by what its name says.
std::string attribute_value(const Attribute& a, std::string& role) {
    std::string n = a.name;
    std::transform(n.begin(), n.end(), n.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    const auto has = [&](const char* w) { return n.find(w) != std::string::npos; };
    if (has("pos") || has("vert")) return role = "position", "x, y, 0.0f, 1.0f";
    if (has("bitangent") || has("binormal")) return role = "bitangent", "0.0f, 1.0f, 0.0f, 0.0f";
    if (has("tangent")) return role = "tangent (w: handedness)", "1.0f, 0.0f, 0.0f, 1.0f";
    if (has("norm")) return role = "normal", "0.0f, 0.0f, 1.0f, 0.0f";
    if (has("uv") || has("tex") || has("coord")) return role = "texture coordinates", "u, v, 0.0f, 0.0f";
    if (has("col")) return role = "colour", "1.0f, 1.0f, 1.0f, 1.0f";
    return role = "no role its name says: the grid's u, v", "u, v, 0.0f, 1.0f";
}

// The scene kind's reading of a uniform: `r` is the reader's C++ name,
// `gl` a C++ expression of the name GL knows it by (empty: its own name),
// `depth` keeps nested names apart.
void read_lines(const Interface& in, const GlslVariable& u, const std::string& r, const std::string& gl,
                const std::string& indent, int depth, std::ostringstream& o) {
    const GlslStruct* st = nullptr;
    for (const GlslStruct& s : in.structs)
        if (s.name == u.type) st = &s;
    const std::string d = std::to_string(depth);
    if (is_sampler(u.type) && u.array_size) {  // at the top only (check_uniform_type): one texture object each
        const std::string n = std::to_string(u.array_size);
        o << indent << "{  // uniform " << u.type << " " << u.name << "[" << n << "]\n"
          << indent << "    std::vector<st::JsonReader> items" << d << " = " << r << ".objects(\"" << u.name << "\", " << n
          << ", " << n << ");\n"
          << indent << "    for (int i" << d << " = 0; i" << d << " < " << n << "; ++i" << d << ")\n"
          << indent << "        draw.textures.push_back(st::read_texture_object(items" << d << "[size_t(i" << d
          << ")], \"" << u.name << "[\" + std::to_string(i" << d << ") + \"]\", budget));\n"
          << indent << "}\n";
        return;
    }
    if (is_sampler(u.type)) {  // at the top only (check_uniform_type)
        o << indent << "draw.textures.push_back(st::read_texture_field(" << r << ", \"" << u.name << "\", \"" << u.name
          << "\", budget));  // uniform " << u.type << " " << u.name << "\n";
        return;
    }
    const std::string array = u.array_size ? "[" + std::to_string(u.array_size) + "]" : "";
    if (!st) {
        o << indent << "st::read_uniform_field(" << r << ", \"" << u.name << "\", \"" << u.type << "\", " << u.array_size
          << ", draw.uniforms" << (gl.empty() ? "" : ", " + gl) << ");  // " << u.type << " " << u.name << array << "\n";
        return;
    }
    const std::string name = gl.empty() ? "std::string(\"" + u.gl() + "\")" : gl;
    o << indent << "{  // " << u.type << " " << u.gl() << array << "\n";
    if (u.array_size) {
        const std::string n = std::to_string(u.array_size), item = "items" + d + "[size_t(i" + d + ")]";
        o << indent << "    std::vector<st::JsonReader> items" << d << " = " << r << ".objects(\"" << u.name << "\", " << n
          << ", " << n << ");\n" << indent << "    for (int i" << d << " = 0; i" << d << " < " << n << "; ++i" << d << ") {\n";
        for (const GlslVariable& m : st->members)
            read_lines(in, m, item, name + " + \"[\" + std::to_string(i" + d + ") + \"]." + m.name + "\"", indent + "        ",
                       depth + 1, o);
        o << indent << "        " << item << ".finish();\n" << indent << "    }\n";
    } else {
        o << indent << "    st::JsonReader fields" << d << " = " << r << ".object(\"" << u.gl() << "\");\n";
        for (const GlslVariable& m : st->members)
            read_lines(in, m, "fields" + d, name + " + \"." + m.name + "\"", indent + "    ", depth + 1, o);
        o << indent << "    fields" << d << ".finish();\n";
    }
    o << indent << "}\n";
}

std::string scene_file(const Names& n, const Interface& in) {
    std::ostringstream o;
    o << "// " << n.name << "_scene.cpp: the \"" << n.name
      << "\" scene kind. Each uniform is a field of the scene file\n// named as the uniform (scene/uniform_fields.h: "
         "numbers, booleans, \"identity\" for a\n// matrix; a sampler's field is a texture object, docs/scenes.md), and the "
         "mesh is a\n// grid of quads in the plane z = 0 with each attribute filled by what its name\n// says. Make it the "
         "scene your shader was written for.\n"
      << "#include \"scene/input_error.h\"\n#include \"scene/texture_patterns.h\"\n#include \"scene/uniform_fields.h\"\n#include \""
      << n.name << ".h\"\n\nst::Frame build_" << n.name << "_scene(st::JsonReader& scene, st::SceneSize size) {\n"
      << "    st::DrawCall draw;\n    draw.vertex = draw.fragment = \"" << n.name << "\";  // glsl/" << n.name
      << ".vert + .frag, and their twins\n    st::TexelBudget budget;\n";
    for (const GlslVariable& u : in.uniforms) read_lines(in, u, "scene", "", "    ", 0, o);
    int count = 0;
    for (const Attribute& a : in.attributes) count = std::max(count, a.location + 1);
    o << "\n    // The mesh: grid x grid quads over [-0.9, 0.9]^2 (clip space with identity\n"
      << "    // matrices), u and v running 0 to 1 across it.\n"
      << "    const int grid = scene.integer_or(\"grid\", 8, 1, 256);\n"
      << "    draw.vertices.attribute_count = " << count << ";\n"
      << "    draw.vertices.names = {" << [&] {
             // Each column's vertex input, by which GL binds it.
             std::string list;
             for (int l = 0; l < count; ++l) {
                 const auto a = std::find_if(in.attributes.begin(), in.attributes.end(), [&](const Attribute& x) { return x.location == l; });
                 list += std::string(l ? ", " : "") + "\"" + (a == in.attributes.end() ? "" : a->name) + "\"";
             }
             return list;
         }() << "};  // attribute N feeds the vertex input of that name\n"
      << "    for (int j = 0; j <= grid; ++j)\n        for (int i = 0; i <= grid; ++i) {\n"
      << "            const float u = float(i) / float(grid), v = float(j) / float(grid);\n"
      << "            [[maybe_unused]] const float x = -0.9f + 1.8f * u, y = -0.9f + 1.8f * v;\n";
    for (int l = 0; l < count; ++l) {
        const auto a = std::find_if(in.attributes.begin(), in.attributes.end(), [&](const Attribute& x) { return x.location == l; });
        if (a == in.attributes.end()) {
            o << "            draw.vertices.data.push_back({0.0f, 0.0f, 0.0f, 0.0f});  // attribute " << l << ": unused\n";
            continue;
        }
        std::string role;
        const std::string value = attribute_value(*a, role);
        o << "            draw.vertices.data.push_back({" << value << "});  // attribute " << l << " (" << a->type << " "
          << a->name << "): " << role << "\n";
    }
    o << "        }\n    for (int j = 0; j < grid; ++j)\n        for (int i = 0; i < grid; ++i) {\n"
      << "            const uint32_t a = uint32_t(j * (grid + 1) + i), b = a + uint32_t(grid + 1);\n"
      << "            draw.indices.insert(draw.indices.end(), {a, a + 1, b + 1, a, b + 1, b});\n        }\n\n"
      << "    st::Pass pass;\n    pass.width = size.width;\n    pass.height = size.height;\n"
      << "    pass.draws.push_back(std::move(draw));\n    st::Frame frame;\n";
    if (in.outputs.size() > 1)
        o << "    // Output 0 is the image; each other output draws into a target of its\n"
          << "    // name, the image's size (compared and hashed as the image is).\n";
    if (in.outputs_by_name) {
        o << "    // The outputs by location, bound by name (glBindFragDataLocation): the\n"
          << "    // shader gives them none.\n    pass.draws.back().output_names = {";
        for (size_t k = 0; k < in.outputs.size(); ++k) o << (k ? ", " : "") << "\"" << in.outputs[k].name << "\"";
        o << "};\n";
    }
    for (size_t k = 1; k < in.outputs.size(); ++k)
        o << "    frame.targets.push_back({\"" << in.outputs[k].name << "\", size.width, size.height});  // out "
          << in.outputs[k].type << " " << in.outputs[k].name << ", location " << k << "\n"
          << "    pass.outputs.push_back({\"" << in.outputs[k].name << "\"});\n";
    o << "    frame.passes.push_back(std::move(pass));\n"
      << "    return frame;\n}\n";
    return o.str();
}

// A first value for a uniform in the scene file (each texture its own seed).
nlohmann::ordered_json default_value(const Interface& in, const GlslVariable& u, int& seed) {
    const GlslStruct* st = nullptr;
    for (const GlslStruct& s : in.structs)
        if (s.name == u.type) st = &s;
    nlohmann::ordered_json one;
    std::string n = u.name;
    std::transform(n.begin(), n.end(), n.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    const int c = components(u.type);
    if (st) {
        one = nlohmann::ordered_json::object();
        for (const GlslVariable& m : st->members) one[m.name] = default_value(in, m, seed);
    } else if (u.type == "sampler2D") {
        one = {{"pattern", "noise"}, {"seed", ++seed},  {"width", 64},  {"height", 64},
               {"format", "rgba8"},  {"mipmaps", "box"}, {"min_filter", "linear_mipmap_linear"}};
    } else if (u.type == "samplerCube") {
        one = {{"cube", true}, {"pattern", "noise"}, {"seed", ++seed}, {"width", 16}, {"height", 16}, {"format", "rgba8"}};
    } else if (u.type.rfind("mat", 0) == 0 || u.type.rfind("dmat", 0) == 0) {
        one = "identity";
    } else if (u.type == "double") {
        one = 0.5;
    } else if (u.type == "bool") {
        one = false;
    } else if (u.type.rfind("bvec", 0) == 0) {
        one = nlohmann::ordered_json::array();
        for (int i = 0; i < u.type.back() - '0'; ++i) one.push_back(false);
    } else if (u.type == "int" || u.type == "uint") {
        one = 1;
    } else if (u.type.find("vec") != std::string::npos && !c) {  // ivecN, uvecN
        one = nlohmann::ordered_json::array();
        for (int i = 0; i < u.type.back() - '0'; ++i) one.push_back(1);
    } else if (c == 1) {
        one = 0.5;
    } else {
        const bool direction = n.find("dir") != std::string::npos || n.find("pos") != std::string::npos;
        const double d[4] = {0.3, 0.5, 0.8, 1.0};
        one = nlohmann::ordered_json::array();
        for (int i = 0; i < c; ++i) one.push_back(direction ? d[i] : n.find("col") != std::string::npos ? 1.0 : 0.5);
    }
    if (!u.array_size) return one;
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (int i = 0; i < u.array_size; ++i) list.push_back(one);
    return list;
}

std::string scene_json(const Names& n, const Interface& in) {
    // One line per field, as a person writes a scene.
    std::vector<std::pair<std::string, nlohmann::ordered_json>> fields = {
        {"kind", n.name},
        {"description", "The first scene of " + n.name + ", written by shadertwin new-technique: a grid of quads and "
                        "a value for each uniform. Make it one your shader was written for."},
        {"width", 128},
        {"height", 128},
        {"grid", 8}};
    int seed = 0;
    for (const GlslVariable& u : in.uniforms) fields.push_back({u.gl(), default_value(in, u, seed)});
    std::string out = "{\n";
    for (size_t i = 0; i < fields.size(); ++i)
        out += "  " + nlohmann::json(fields[i].first).dump() + ": " + fields[i].second.dump() + (i + 1 < fields.size() ? ",\n" : "\n");
    return out + "}\n";
}

std::string technique_file(const Names& n) {
    std::ostringstream o;
    o << "// " << n.name << "_technique.cpp: what the technique adds to the tool: each twin under\n// the stem of the GLSL "
         "file it mirrors, and its scene kind.\n#include \"sdk/technique.h\"\n#include \"" << n.name << ".h\"\n\n"
      << "SHADERTWIN_TECHNIQUE(" << n.name << ", technique) {\n    technique.vertex_twin<" << n.vertex_class << ">(\""
      << n.name << "\");\n    technique.fragment_twin<" << n.fragment_class << ">(\"" << n.name
      << "\");\n    technique.scene_kind(\"" << n.name << "\", build_" << n.name << "_scene);\n}\n";
    return o.str();
}

std::string cmake_file(const Names& n) {
    std::ostringstream o;
    o << "# " << n.name << ": a GLSL program, its C++ twins and a scene kind, from `shadertwin\n# new-technique`. Built "
         "against an installed shadertwin:\n#     cmake -S . -B build -DCMAKE_PREFIX_PATH=<shadertwin prefix> "
         "-DCMAKE_BUILD_TYPE=RelWithDebInfo\n#     cmake --build build -j 2\n#     build/" << n.name << "twin compare "
      << n.name << "-first --out out\ncmake_minimum_required(VERSION 3.25)\nproject(" << n.name
      << " LANGUAGES CXX)\nenable_testing()\n\nfind_package(shadertwin REQUIRED)\n\nshadertwin_add_technique(\n  NAME "
      << n.name << "\n  TOOL " << n.name << "twin\n  GLSL glsl/" << n.name << ".vert glsl/" << n.name << ".frag\n  TWINS kernels/"
      << n.name << "_vert.cpp kernels/" << n.name << "_frag.cpp kernels/" << n.name << "_scene.cpp kernels/" << n.name
      << "_technique.cpp\n  SCENES scenes\n  GOLDEN golden/hashes.json)\n";
    return o.str();
}

}  // namespace

std::vector<ProjectFile> skeleton_files(const std::string& name, const GlslStage& vert, const std::string& vert_source,
                                        const GlslStage& frag, const std::string& frag_source) {
    const Interface in = interface_of(vert, frag);
    Names n;
    n.name = name;
    n.camel = camel(name);
    n.vertex_class = n.camel + "Vertex";
    n.fragment_class = n.camel + "Fragment";
    return {
        {"CMakeLists.txt", cmake_file(n)},
        {"glsl/" + name + ".vert", vert_source},
        {"glsl/" + name + ".frag", frag_source},
        {"kernels/" + name + ".h", header_file(n, in)},
        {"kernels/" + name + "_vert.cpp", vertex_file(n, in, vert)},
        {"kernels/" + name + "_frag.cpp", fragment_file(n, in, frag)},
        {"kernels/" + name + "_scene.cpp", scene_file(n, in)},
        {"kernels/" + name + "_technique.cpp", technique_file(n)},
        {"scenes/" + name + "-first.json", scene_json(n, in)},
    };
}

}  // namespace st::skeleton
