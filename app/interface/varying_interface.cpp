// varying_interface.cpp: see varying_interface.h. Each stage's inputs and
// outputs are listed as GL names them (a block member "Block.member"), with
// their location (explicit, or counted from the block's), type and
// qualifier, and whether the stage's code names them; the twins' slots are
// then looked up by name or location.
#include "app/interface/varying_interface.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <regex>
#include <set>

#include "scene/input_error.h"

namespace st {

namespace {

// The stage's code (function bodies) without comments.
std::string code_of(const GlslStage& s) {
    std::string code, out;
    for (const GlslFunction& f : s.functions) code += f.body + "\n";
    for (size_t p = 0; p < code.size();) {
        if (code.compare(p, 2, "//") == 0) {
            p = std::min(code.find('\n', p), code.size());
        } else if (code.compare(p, 2, "/*") == 0) {
            const size_t end = code.find("*/", p + 2);
            p = end == std::string::npos ? code.size() : end + 2;
            out += ' ';
        } else {
            out += code[p++];
        }
    }
    return out;
}

// Whether `code` names `name` (not as a member: `x.name` does not count),
// or with an instance, `instance.name`.
bool names(const std::string& code, const std::string& instance, const std::string& name) {
    const std::string pattern = instance.empty() ? "(^|[^A-Za-z0-9_.])" + name + "\\b"
                                                 : "\\b" + instance + "\\s*\\.\\s*" + name + "\\b";
    return std::regex_search(code, std::regex(pattern));
}

// Components of a varying type (a scalar or vector); 0 for what a twin's
// vec4 slot cannot hold (a matrix, a struct, a double vector).
int components(const std::string& type) {
    if (type == "float" || type == "int" || type == "uint" || type == "bool") return 1;
    for (const char* prefix : {"vec", "ivec", "uvec", "bvec"}) {
        const std::string p = prefix;
        if (type.size() == p.size() + 1 && type.compare(0, p.size(), p) == 0 && type.back() >= '2' && type.back() <= '4')
            return type.back() - '0';
    }
    return 0;
}

Interpolation interpolation_of(const std::vector<std::string>& qualifiers) {
    for (const std::string& q : qualifiers) {
        if (q == "flat") return Interpolation::Flat;
        if (q == "noperspective") return Interpolation::NoPerspective;
    }
    return Interpolation::Smooth;
}

const char* qualifier_name(Interpolation i) {
    return i == Interpolation::Flat ? "flat" : i == Interpolation::NoPerspective ? "noperspective" : "smooth";
}

struct Varying {
    std::string name;  // as GL names it
    std::string type;
    int location = -1;  // -1: none given
    int array_size = 0;
    Interpolation interpolation = Interpolation::Smooth;
    bool used = false;  // named by the stage's code
};

std::vector<Varying> interface_of(const GlslStage& s, const std::string& storage) {
    const std::string code = code_of(s);
    std::vector<Varying> out;
    for (const GlslVariable& v : storage == "in" ? s.inputs : s.outputs)
        out.push_back({v.name, v.type, v.location, v.array_size, interpolation_of(v.qualifiers), names(code, "", v.name)});
    for (const GlslBlock& b : s.blocks) {
        if (b.storage != storage || b.array_size > 0) continue;
        int next = b.location;
        for (const GlslVariable& m : b.members) {
            const int location = m.location >= 0 ? m.location : next;
            out.push_back({b.name + "." + m.name, m.type, location, m.array_size, interpolation_of(m.qualifiers),
                           names(code, b.instance, m.name)});
            next = location < 0 ? -1 : location + std::max(1, m.array_size);
        }
    }
    return out;
}

std::string slot_list(const std::vector<Varying>& vars) {
    std::string out;
    for (const Varying& v : vars)
        out += (out.empty() ? "" : ", ") + v.name + (v.location >= 0 ? " at " + std::to_string(v.location) : "");
    return out.empty() ? "none" : out;
}

// Slot -> the GLSL variable it holds, by the twin's names or else by location.
std::map<int, const Varying*> slots_of(const std::vector<Varying>& vars, const SlotNames& twin_names,
                                       const std::string& twin, const std::string& file, const char* what) {
    std::map<int, const Varying*> slots;
    if (twin_names.empty()) {
        for (const Varying& v : vars)
            if (v.location >= 0) slots[v.location] = &v;
        return slots;
    }
    for (size_t slot = 0; slot < twin_names.size(); ++slot) {
        const std::string& n = twin_names[slot];
        if (n.empty()) continue;
        const auto v = std::find_if(vars.begin(), vars.end(), [&](const Varying& x) { return x.name == n; });
        if (v == vars.end())
            throw InputError(twin + " names slot " + std::to_string(slot) + " '" + n + "', which " + file +
                             " does not declare as an " + what + " (its " + what + "s: " + slot_list(vars) + ")");
        if (v->location >= 0 && v->location != int(slot))
            throw InputError(twin + " holds '" + n + "' in slot " + std::to_string(slot) + "; " + file +
                             " declares it at location " + std::to_string(v->location));
        slots[int(slot)] = &*v;
    }
    return slots;
}

}  // namespace

void check_twin_varyings(const GlslStage& vs, const VertexTwin& vertex_twin, const GlslStage& fs,
                         const FragmentTwin& fragment_twin, const VertexArray& vertices, int targets,
                         const std::vector<std::string>& output_names) {
    const std::string vfile = vs.file_name(), ffile = fs.file_name();
    const std::string vtwin = "the twin of " + vfile, ftwin = "the twin of " + ffile;

    // Vertex inputs: attribute column a is location a, or the input the
    // draw names for it.
    const int attribute_count = vertices.attribute_count;
    const std::vector<Varying> attributes = interface_of(vs, "in");
    const std::vector<std::string>& names = vertices.names;
    if (!names.empty() && names.size() != size_t(attribute_count))
        throw InputError("the draw names " + std::to_string(names.size()) + " vertex attributes and gives " +
                         std::to_string(attribute_count));
    for (size_t column = 0; column < names.size(); ++column) {
        if (names[column].empty()) continue;  // a column no input reads
        const auto a = std::find_if(attributes.begin(), attributes.end(), [&](const Varying& x) { return x.name == names[column]; });
        if (a == attributes.end())
            throw InputError("the draw names attribute " + std::to_string(column) + " '" + names[column] + "', which " +
                             vfile + " does not declare as an input (its inputs: " + slot_list(attributes) + ")");
        if (a->location >= 0 && a->location != int(column))
            throw InputError("the draw gives '" + a->name + "' as attribute " + std::to_string(column) + "; " + vfile +
                             " declares it at location " + std::to_string(a->location));
    }
    for (const Varying& a : attributes) {
        if (!a.used) continue;
        const bool named = std::find(names.begin(), names.end(), a.name) != names.end();
        if (!names.empty() && !named)
            throw InputError(vfile + " uses input '" + a.name + "', which no attribute of the draw names");
        if (names.empty() && a.location < 0)
            throw InputError(vfile + " uses input '" + a.name + "' without a location, and the draw does not name its "
                             "attributes (VertexArray::names)");
        if (names.empty() && a.location >= attribute_count)
            throw InputError(vfile + " reads input '" + a.name + "' at location " + std::to_string(a.location) +
                             ", and the draw gives " + std::to_string(attribute_count) + " attributes");
    }

    // Fragment outputs: locations 0 to targets - 1, one per colour buffer
    // of the pass, and the twin writes as many.
    std::vector<Varying> outputs = interface_of(fs, "out");
    // Locations the draw binds by name (glBindFragDataLocation), for
    // outputs the shader gives none.
    for (size_t k = 0; k < output_names.size(); ++k) {
        const auto o = std::find_if(outputs.begin(), outputs.end(), [&](const Varying& x) { return x.name == output_names[k]; });
        if (o == outputs.end())
            throw InputError("the draw binds output '" + output_names[k] + "' to location " + std::to_string(k) + ", and " +
                             ffile + " declares no such output (its outputs: " + slot_list(outputs) + ")");
        if (o->location >= 0 && o->location != int(k))
            throw InputError("the draw binds output '" + o->name + "' to location " + std::to_string(k) + "; " + ffile +
                             " declares it at location " + std::to_string(o->location));
        o->location = int(k);
    }
    std::set<int> locations;
    for (const Varying& o : outputs) {
        if (o.location < 0 && outputs.size() > 1)
            throw InputError(ffile + " declares outputs " + slot_list(outputs) + ", '" + o.name +
                             "' without a location: with several outputs give each its layout(location = N), or "
                             "bind them by name (DrawCall::output_names)");
        if (o.array_size > 0) throw InputError(ffile + ": output array '" + o.name + "' is not modelled");
        locations.insert(std::max(o.location, 0));
    }
    std::set<int> wanted;
    for (int k = 0; k < targets; ++k) wanted.insert(k);
    if (locations != wanted)
        throw InputError(ffile + " declares outputs " + slot_list(outputs) + ", and the pass draws into " +
                         std::to_string(targets) + (targets == 1 ? " target (location 0)" : " targets (locations 0 to " +
                                                                         std::to_string(targets - 1) + ")"));
    if (fragment_twin.output_count() != targets)
        throw InputError(ftwin + " writes " + std::to_string(fragment_twin.output_count()) + " output" +
                         (fragment_twin.output_count() == 1 ? "" : "s") + ", and " + ffile + " declares " +
                         std::to_string(targets));

    const std::vector<Varying> inputs = interface_of(fs, "in");
    const std::vector<Varying> vs_outputs = interface_of(vs, "out");
    // What GL's link would refuse with a page of log: an input the fragment
    // shader uses that no vertex output meets, by location or by name.
    for (const Varying& v : inputs) {
        if (!v.used) continue;
        const bool met = std::any_of(vs_outputs.begin(), vs_outputs.end(), [&](const Varying& o) {
            return v.location >= 0 && o.location >= 0 ? o.location == v.location : o.name == v.name;
        });
        if (!met)
            throw InputError(ffile + " reads '" + v.name + "'" +
                             (v.location >= 0 ? " at location " + std::to_string(v.location) : std::string()) + ", which " +
                             vfile + " does not write (its outputs: " + slot_list(vs_outputs) + ")");
    }
    const std::map<int, const Varying*> in_slots = slots_of(inputs, fragment_twin.input_names(), ftwin, ffile, "input");
    const std::map<int, const Varying*> out_slots =
        slots_of(vs_outputs, vertex_twin.output_names(), vtwin, vfile, "output");
    // The same name in both twins' slots.
    for (const auto& [slot, in] : in_slots)
        for (const auto& [out_slot, out] : out_slots)
            if (in->name == out->name && slot != out_slot)
                throw InputError(vtwin + " writes '" + in->name + "' to slot " + std::to_string(out_slot) + ", and " +
                                 ftwin + " reads it from slot " + std::to_string(slot));

    const uint32_t read = fragment_twin.inputs_read();
    const Interpolations interpolations = fragment_twin.interpolations();
    const bool said = read != ~0u;  // the default: every component, nothing said
    for (int slot = 0; slot < kMaxVaryings; ++slot) {
        const uint32_t bits = (read >> (4 * slot)) & 0xFu;
        const auto mapped = in_slots.find(slot);
        const Varying* v = mapped == in_slots.end() ? nullptr : mapped->second;
        if (said && bits && !v)
            throw InputError(ftwin + " reads varying slot " + std::to_string(slot) + ", where " + ffile +
                             " declares no input (its inputs: " + slot_list(inputs) + ")");
        if (said && bits && slot >= vertex_twin.varying_count())
            throw InputError(ftwin + " reads varying slot " + std::to_string(slot) + ", and " + vtwin + " writes " +
                             std::to_string(vertex_twin.varying_count()) + " slots");
        if (!v) continue;
        const int n = components(v->type);
        if (said && n > 0 && v->array_size == 0 && (bits >> n) != 0)
            throw InputError(ftwin + " reads component " + std::string(1, "xyzw"[31 - __builtin_clz(bits)]) +
                             " of slot " + std::to_string(slot) + ", '" + v->name + "', " + with_article(v->type) + " in " + ffile);
        if (v->interpolation != interpolations[size_t(slot)])
            throw InputError("'" + v->name + "' is " + qualifier_name(v->interpolation) + " in " + ffile + ", and " +
                             ftwin + "'s interpolations() has slot " + std::to_string(slot) + " " +
                             qualifier_name(interpolations[size_t(slot)]));
        if (said && v->used && !bits)
            throw InputError(ffile + " uses input '" + v->name + "' (slot " + std::to_string(slot) + "), which " + ftwin +
                             "'s inputs_read() leaves out: it would read NaN");
    }
    for (const Varying& v : inputs) {
        if (!v.used) continue;
        const bool placed = std::any_of(in_slots.begin(), in_slots.end(), [&](const auto& s) { return s.second == &v; });
        if (!placed)
            throw InputError(ffile + " uses input '" + v.name + "'" +
                             (v.location < 0 ? " without a location, and " + ftwin + " names no slot for it (input_names())"
                                             : ", which no slot of " + ftwin + " holds"));
    }
}

}  // namespace st
