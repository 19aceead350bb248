// param_space.cpp: see param_space.h.
#include "scene/param_space.h"

#include <cctype>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "scene/scene_spaces.h"

namespace st {

namespace {

// 1073741824, 0.001, 1e6, 1e-30: as a reader writes them.
std::string short_number(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", x);
    std::string s = buf;
    const auto e = s.find('e');
    if (e == std::string::npos) return s;
    std::string mantissa = s.substr(0, e), exponent = s.substr(e + 1);
    const bool negative = exponent[0] == '-';
    exponent.erase(0, exponent.find_first_not_of("+-0"));
    return mantissa + "e" + (negative ? "-" : "") + exponent;
}

std::string fallback_text(const FieldSpec& f) {
    if (f.required) return "required";
    if (f.fallback.is_null()) return "none";
    if (f.fallback.is_string()) return "`\"" + f.fallback.get<std::string>() + "\"`";
    if (f.fallback.is_number_float()) return "`" + short_number(f.fallback.get<double>()) + "`";
    if (f.fallback.is_array()) {
        std::string out = "`[";
        for (size_t i = 0; i < f.fallback.size(); ++i)
            out += (i ? ", " : "") + (f.fallback[i].is_number_float() ? short_number(f.fallback[i].get<double>())
                                                                       : f.fallback[i].dump());
        return out + "]`";
    }
    return "`" + f.fallback.dump() + "`";
}

}  // namespace

std::string FieldSpec::type_text() const {
    switch (type) {
    case FieldType::Number: return "number";
    case FieldType::Integer: return "integer";
    case FieldType::Boolean: return "boolean";
    case FieldType::Choice:
        if (!max_len) return "string";
        return min_len == max_len ? std::to_string(min_len) + " strings"
                                  : std::to_string(min_len) + " to " + std::to_string(max_len) + " strings";
    case FieldType::Numbers: {
        const std::string each = min_len == max_len ? std::to_string(min_len) + " numbers"
                                                    : std::to_string(min_len) + " to " + std::to_string(max_len) + " numbers";
        return rows ? std::to_string(rows) + " arrays of " + each : each;
    }
    case FieldType::Text:
        if (!max_len) return "string";
        return min_len == max_len ? std::to_string(min_len) + " strings"
                                  : std::to_string(min_len) + " to " + std::to_string(max_len) + " strings";
    case FieldType::Object: return max_len ? "array of objects" : "object";
    }
    return "?";
}

std::string FieldSpec::domain_text() const {
    const std::string lo_s = lo_field.empty() ? short_number(lo) : "`" + lo_field + "`";
    const std::string hi_s = hi_field.empty() ? short_number(hi) : "`" + hi_field + "`";
    switch (type) {
    case FieldType::Number: return "[" + lo_s + ", " + hi_s + "]";
    case FieldType::Integer:  // every digit (a seed's 1073741824, not 1.07374e+09)
        return (lo_field.empty() ? std::to_string((long long)lo) : lo_s) + ".." +
               (hi_field.empty() ? std::to_string((long long)hi) : hi_s);
    case FieldType::Numbers: return "each in [" + lo_s + ", " + hi_s + "]";
    case FieldType::Choice: {
        std::string out;
        for (const auto& c : choices) out += (out.empty() ? "" : ", ") + ("`" + c + "`");
        return max_len ? "each one of " + out : out;
    }
    case FieldType::Object:
        return max_len ? std::to_string(min_len) + ".." + std::to_string(max_len) + " entries" : "";
    case FieldType::Boolean:
    case FieldType::Text: return "";
    }
    return "";
}

ParamSpace::ParamSpace(std::string kind) : kind_(std::move(kind)) {}

std::string ParamSpace::normalise(const std::string& path) {
    std::string out;
    size_t start = 0;
    for (;;) {
        const size_t dot = path.find('.', start);
        const std::string seg = path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
        const bool index = !seg.empty() && std::all_of(seg.begin(), seg.end(), [](char c) { return std::isdigit((unsigned char)c); });
        if (index)
            out += "[]";
        else
            out += (out.empty() ? "" : ".") + seg;
        if (dot == std::string::npos) break;
        start = dot + 1;
    }
    return out;
}

const FieldSpec* ParamSpace::find(const std::string& path) const {
    const auto it = index_.find(path);
    return it == index_.end() ? nullptr : &fields_[it->second];
}

const FieldSpec& ParamSpace::at(const std::string& path) const {
    const std::string n = normalise(path);
    if (const FieldSpec* f = find(n)) return *f;
    throw std::logic_error("scene kind '" + kind_ + "' reads field '" + n + "', which its space does not declare");
}

FieldSpec& ParamSpace::add(FieldSpec spec) {
    if (index_.count(spec.path)) throw std::logic_error("field '" + spec.path + "' declared twice in kind " + kind_);
    if (spec.draw_lo == 0 && spec.draw_hi == 0) spec.draw_lo = spec.lo, spec.draw_hi = spec.hi;
    index_[spec.path] = fields_.size();
    fields_.push_back(std::move(spec));
    return fields_.back();
}

FieldSpec& ParamSpace::number(std::string path, double lo, double hi, nlohmann::json fallback, std::string meaning) {
    FieldSpec f;
    f.path = std::move(path), f.type = FieldType::Number, f.lo = lo, f.hi = hi;
    f.required = fallback.is_string() && fallback.get<std::string>() == "required";
    if (!f.required) f.fallback = std::move(fallback);
    f.meaning = std::move(meaning);
    return add(std::move(f));
}

FieldSpec& ParamSpace::integer(std::string path, int lo, int hi, nlohmann::json fallback, std::string meaning) {
    FieldSpec& f = number(std::move(path), lo, hi, std::move(fallback), std::move(meaning));
    f.type = FieldType::Integer;
    return f;
}

FieldSpec& ParamSpace::boolean(std::string path, bool fallback, std::string meaning) {
    FieldSpec f;
    f.path = std::move(path), f.type = FieldType::Boolean, f.fallback = fallback, f.meaning = std::move(meaning);
    return add(std::move(f));
}

FieldSpec& ParamSpace::choice(std::string path, std::vector<std::string> choices, nlohmann::json fallback,
                              std::string meaning) {
    FieldSpec f;
    f.path = std::move(path), f.type = FieldType::Choice, f.choices = std::move(choices);
    f.required = fallback.is_string() && fallback.get<std::string>() == "required";
    if (!f.required) f.fallback = std::move(fallback);
    f.meaning = std::move(meaning);
    return add(std::move(f));
}

FieldSpec& ParamSpace::numbers(std::string path, size_t min_len, size_t max_len, double lo, double hi,
                               nlohmann::json fallback, std::string meaning) {
    FieldSpec& f = number(std::move(path), lo, hi, std::move(fallback), std::move(meaning));
    f.type = FieldType::Numbers, f.min_len = min_len, f.max_len = max_len;
    return f;
}

FieldSpec& ParamSpace::text(std::string path, nlohmann::json fallback, std::string meaning) {
    FieldSpec f;
    f.path = std::move(path), f.type = FieldType::Text;
    f.required = fallback.is_string() && fallback.get<std::string>() == "required";
    if (!f.required) f.fallback = std::move(fallback);
    f.meaning = std::move(meaning), f.explore = false;
    return add(std::move(f));
}

FieldSpec& ParamSpace::texts(std::string path, size_t min_len, size_t max_len, nlohmann::json fallback,
                             std::string meaning) {
    FieldSpec& f = text(std::move(path), std::move(fallback), std::move(meaning));
    f.min_len = min_len, f.max_len = max_len;
    return f;
}

FieldSpec& ParamSpace::object(std::string path, bool required, std::string meaning, size_t min_len, size_t max_len) {
    FieldSpec f;
    f.path = std::move(path), f.type = FieldType::Object, f.required = required;
    f.min_len = min_len, f.max_len = max_len, f.meaning = std::move(meaning);
    return add(std::move(f));
}

void ParamSpace::include(const ParamSpace& other, const std::string& prefix) {
    for (FieldSpec f : other.fields_) {
        if (!prefix.empty()) {
            f.path = prefix + "." + f.path;
            if (!f.when_field.empty()) f.when_field = prefix + "." + f.when_field;
            if (!f.lo_field.empty()) f.lo_field = prefix + "." + f.lo_field;
            if (!f.hi_field.empty()) f.hi_field = prefix + "." + f.hi_field;
        }
        add(std::move(f));
    }
}

std::string ParamSpace::markdown() const {
    std::string out = "| field | type | domain | default | meaning |\n| --- | --- | --- | --- | --- |\n";
    for (const FieldSpec& f : fields_) {
        if (common_space().find(f.path) && &common_space() != this) continue;  // listed once, above
        std::string meaning = f.meaning;
        if (!f.when_field.empty()) {
            std::string values;
            for (const auto& v : f.when_values) values += (values.empty() ? "" : ", ") + ("`" + v + "`");
            meaning += (meaning.empty() ? "" : " ") + std::string("(only with `") + f.when_field + "` " + values + ")";
        }
        if (f.explore_hi > 0) meaning += " (the explorer draws up to " + short_number(f.explore_hi) + ")";
        out += "| `" + f.path + "` | " + f.type_text() + " | " + f.domain_text() + " | " + fallback_text(f) + " | " +
               meaning + " |\n";
    }
    return out;
}

namespace {

std::map<std::string, const ParamSpace*>& spaces() {
    static std::map<std::string, const ParamSpace*> spaces = {
        {"conformance", &conformance_space()},
        {"profile", &profile_space()},
        {"relief", &relief_space()},
        {"thin-slab", &thin_slab_space()},
        {"triangles", &triangles_space()},
    };
    return spaces;
}

}  // namespace

const ParamSpace& common_space() {
    static const ParamSpace space = [] {
        ParamSpace s("common");
        s.text("kind", "required", "which builder turns the scene into draws");
        s.text("description", "", "free text");
        s.integer("width", 1, 8192, "required", "render target width in pixels").explore_at_most(400).edge({1, 2, 3, 7, 64, 65});
        s.integer("height", 1, 8192, "required", "render target height in pixels").explore_at_most(300).edge({1, 2, 3, 7, 64, 65});
        s.object("criteria", false, "what `compare` requires (below)").opaque_object();
        s.object("paper", false, "the frame rate a paper published for this scene (below)").opaque_object();
        return s;
    }();
    return space;
}

const ParamSpace* kind_space(const std::string& kind) {
    const auto it = spaces().find(kind);
    return it == spaces().end() ? nullptr : it->second;
}

std::vector<std::string> spaced_kinds() {
    std::vector<std::string> out;
    for (const auto& [k, s] : spaces()) out.push_back(k);
    return out;
}

void register_kind_space(const std::string& kind, const ParamSpace* space) { spaces()[kind] = space; }

}  // namespace st
