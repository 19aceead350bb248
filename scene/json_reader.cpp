// json_reader.cpp: see json_reader.h.
#include "scene/json_reader.h"

#include <filesystem>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "scene/input_error.h"
#include "scene/param_space.h"

namespace st {

namespace {

// nlohmann's own DOM builder behind a depth check on every event. The parse
// callback would do the same check, but its builder revisits the open
// container's members each time an object closes (json_sax_dom_callback_
// parser::end_object), which made a scene of n triangles load in O(n^2).
// Depth counts as the callback counted it: the containers open around a
// value or key, or before a container opens; deeper than kMaxJsonDepth is
// refused when the parser reaches it, so a syntax error before that point
// still reads as malformed text.
class BoundedDomBuilder {
public:
    using json = nlohmann::json;
    BoundedDomBuilder(json& result, const std::string& what) : dom_(result, false), what_(what) {}

    bool null() { return check() && dom_.null(); }
    bool boolean(bool v) { return check() && dom_.boolean(v); }
    bool number_integer(json::number_integer_t v) { return check() && dom_.number_integer(v); }
    bool number_unsigned(json::number_unsigned_t v) { return check() && dom_.number_unsigned(v); }
    bool number_float(json::number_float_t v, const json::string_t& s) { return check() && dom_.number_float(v, s); }
    bool string(json::string_t& v) { return check() && dom_.string(v); }
    bool binary(json::binary_t& v) { return check() && dom_.binary(v); }
    bool key(json::string_t& v) { return check() && dom_.key(v); }
    bool start_object(std::size_t n) { return check() && (++open_, dom_.start_object(n)); }
    bool start_array(std::size_t n) { return check() && (++open_, dom_.start_array(n)); }
    bool end_object() { return --open_, dom_.end_object(); }
    bool end_array() { return --open_, dom_.end_array(); }
    bool parse_error(std::size_t at, const std::string& token, const nlohmann::detail::exception& e) {
        return dom_.parse_error(at, token, e);
    }
    bool errored() const { return dom_.is_errored(); }

private:
    bool check() const {
        if (open_ > kMaxJsonDepth)
            throw InputError(what_ + ": nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
        return true;
    }
    nlohmann::detail::json_sax_dom_parser<json> dom_;
    const std::string& what_;
    int open_ = 0;
};

template <class Text> nlohmann::json parse_bounded(Text& text, const std::string& what) {
    nlohmann::json result;
    BoundedDomBuilder builder(result, what);
    // Malformed text is a discarded value, as nlohmann::json::parse(text, nullptr, false) gives.
    if (!nlohmann::json::sax_parse(text, &builder) || builder.errored()) return nlohmann::json(nlohmann::json::value_t::discarded);
    return result;
}

}  // namespace

nlohmann::json parse_json(std::istream& text, const std::string& what) {
    // Read whole (in one piece where the stream knows its length), then
    // parsed from memory, where nlohmann's lexer runs faster than through a
    // stream buffer one character at a time.
    std::string whole;
    const std::istream::pos_type start = text.tellg();
    if (start != std::istream::pos_type(-1) && text.seekg(0, std::ios::end)) {
        const std::istream::pos_type end = text.tellg();
        text.seekg(start);
        if (end != std::istream::pos_type(-1) && end > start) whole.reserve(size_t(end - start));
    }
    text.clear();
    char chunk[1 << 16];
    while (text.read(chunk, sizeof chunk) || text.gcount() > 0) whole.append(chunk, size_t(text.gcount()));
    return parse_bounded(whole, what);
}
nlohmann::json parse_json(const std::string& text, const std::string& what) { return parse_bounded(text, what); }


namespace {

std::string format_range(double lo, double hi) {
    std::ostringstream s;
    s << "[" << lo << ", " << hi << "]";
    return s.str();
}

}  // namespace

JsonReader::JsonReader(const nlohmann::json& object, std::string path)
    : object_(object), path_(std::move(path)) {
    if (!object_.is_object())
        throw InputError((path_.empty() ? std::string("scene") : path_) + ": expected a JSON object");
}

bool JsonReader::has(const std::string& key) const { return object_.contains(key); }

const nlohmann::json& JsonReader::get(const std::string& key) {
    const auto it = object_.find(key);
    if (it == object_.end()) throw InputError("missing field '" + field(key) + "'");
    read_.push_back(&*it);
    return *it;
}

double JsonReader::checked_number(const nlohmann::json& v, const std::string& where, double lo, double hi) {
    if (!v.is_number()) throw InputError("field '" + where + "' must be a number");
    const double x = v.get<double>();
    if (!std::isfinite(x) || x < lo || x > hi)
        throw InputError("field '" + where + "' is out of range " + format_range(lo, hi));
    return x;
}

double JsonReader::number(const std::string& key, double lo, double hi) {
    return checked_number(get(key), field(key), lo, hi);
}

double JsonReader::number_or(const std::string& key, double fallback, double lo, double hi) {
    return has(key) ? number(key, lo, hi) : fallback;
}

int JsonReader::integer(const std::string& key, int lo, int hi) {
    const nlohmann::json& v = get(key);
    if (!v.is_number_integer()) throw InputError("field '" + field(key) + "' must be an integer");
    const auto x = v.get<long long>();
    if (x < lo || x > hi)
        throw InputError("field '" + field(key) + "' is out of range " + format_range(lo, hi));
    return int(x);
}

int JsonReader::integer_or(const std::string& key, int fallback, int lo, int hi) {
    return has(key) ? integer(key, lo, hi) : fallback;
}

bool JsonReader::boolean_or(const std::string& key, bool fallback) {
    if (!has(key)) return fallback;
    const nlohmann::json& v = get(key);
    if (!v.is_boolean()) throw InputError("field '" + field(key) + "' must be true or false");
    return v.get<bool>();
}

std::string JsonReader::string(const std::string& key) {
    const nlohmann::json& v = get(key);
    if (!v.is_string()) throw InputError("field '" + field(key) + "' must be a string");
    return v.get<std::string>();
}

std::string JsonReader::string_or(const std::string& key, const std::string& fallback) {
    return has(key) ? string(key) : fallback;
}

std::string JsonReader::choice_or(const std::string& key, const std::string& fallback,
                                  const std::vector<std::string>& allowed) {
    const std::string v = string_or(key, fallback);
    for (const auto& a : allowed)
        if (v == a) return v;
    std::string list;
    for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
    throw InputError("field '" + field(key) + "' must be one of: " + list);
}

const nlohmann::json& JsonReader::array(const std::string& key, size_t min_len, size_t max_len) {
    const nlohmann::json& v = get(key);
    if (!v.is_array()) throw InputError("field '" + field(key) + "' must be an array");
    if (v.size() < min_len || v.size() > max_len)
        throw InputError("field '" + field(key) + "' must have " + std::to_string(min_len) +
                         (min_len == max_len ? "" : " to " + std::to_string(max_len)) + " entries");
    return v;
}

std::vector<double> JsonReader::numbers(const std::string& key, size_t min_len, size_t max_len,
                                        double lo, double hi) {
    const nlohmann::json& v = array(key, min_len, max_len);
    std::vector<double> out;
    out.reserve(v.size());
    for (size_t i = 0; i < v.size(); ++i)
        out.push_back(checked_number(v[i], [&] { return field(key) + "." + std::to_string(i); }, lo, hi));
    return out;
}

// An opaque object (the criteria) is read by its own code, unbound.
bool JsonReader::inherits(const std::string& key) const { return space_ && !spec(key).opaque; }

std::string JsonReader::file_path(const std::string& path) const {
    const std::filesystem::path p = path;
    if (folder_.empty() || p.empty() || p.is_absolute()) return path;
    return (std::filesystem::path(folder_) / p).lexically_normal().string();
}

JsonReader JsonReader::child(const nlohmann::json& value, bool bound, std::string path) const {
    JsonReader r(value, std::move(path));
    r.folder_ = folder_;
    if (bound) r.space_ = space_;
    return r;
}

JsonReader JsonReader::object(const std::string& key) { return child(get(key), inherits(key), field(key)); }

std::optional<JsonReader> JsonReader::object_if(const std::string& key) {
    if (!has(key)) return std::nullopt;
    return object(key);
}

JsonReader JsonReader::object_or_defaults(const std::string& key) {
    static const nlohmann::json empty = nlohmann::json::object();
    return has(key) ? object(key) : child(empty, inherits(key), field(key));
}

std::vector<JsonReader> JsonReader::objects(const std::string& key, size_t min_len, size_t max_len) {
    const nlohmann::json& v = array(key, min_len, max_len);
    std::vector<JsonReader> out;
    const bool bound = inherits(key);
    for (size_t i = 0; i < v.size(); ++i) out.push_back(child(v[i], bound, field(key) + "." + std::to_string(i)));
    return out;
}

const FieldSpec& JsonReader::spec(const std::string& key) const {
    if (!space_) throw std::logic_error("field '" + field(key) + "' read through a space, but the reader has none");
    return space_->at(field(key));
}

namespace {

// A declared field's default, of the type asked for.
const nlohmann::json& declared_default(const FieldSpec& f, const std::string& where) {
    if (f.required) throw InputError("missing field '" + where + "'");
    if (f.fallback.is_null())
        throw std::logic_error("field '" + where + "' has no default: its builder must check has() first");
    return f.fallback;
}

void expect_type(const FieldSpec& f, FieldType type, const std::string& where) {
    if (f.type != type) throw std::logic_error("field '" + where + "' is declared as " + f.type_text());
}

}  // namespace

double JsonReader::number(const std::string& key) {
    const FieldSpec& f = spec(key);
    expect_type(f, FieldType::Number, field(key));
    if (!f.lo_field.empty() || !f.hi_field.empty())
        throw std::logic_error("field '" + field(key) + "' has bounds from other fields: read it with number_in");
    return has(key) ? number(key, f.lo, f.hi) : declared_default(f, field(key)).get<double>();
}

double JsonReader::number_in(const std::string& key, double lo, double hi) {
    const FieldSpec& f = spec(key);
    expect_type(f, FieldType::Number, field(key));
    return has(key) ? number(key, std::max(lo, f.lo), std::min(hi, f.hi)) : declared_default(f, field(key)).get<double>();
}

int JsonReader::integer(const std::string& key) {
    const FieldSpec& f = spec(key);
    expect_type(f, FieldType::Integer, field(key));
    if (!f.lo_field.empty() || !f.hi_field.empty())
        throw std::logic_error("field '" + field(key) + "' has bounds from other fields: read it with integer_in");
    return has(key) ? integer(key, int(f.lo), int(f.hi)) : declared_default(f, field(key)).get<int>();
}

int JsonReader::integer_in(const std::string& key, int lo, int hi) {
    const FieldSpec& f = spec(key);
    expect_type(f, FieldType::Integer, field(key));
    return has(key) ? integer(key, std::max(lo, int(f.lo)), std::min(hi, int(f.hi)))
                    : declared_default(f, field(key)).get<int>();
}

bool JsonReader::boolean(const std::string& key) {
    const FieldSpec& f = spec(key);
    expect_type(f, FieldType::Boolean, field(key));
    return boolean_or(key, f.fallback.get<bool>());
}

std::string JsonReader::choice(const std::string& key) {
    const FieldSpec& f = spec(key);
    expect_type(f, FieldType::Choice, field(key));
    if (f.max_len) throw std::logic_error("field '" + field(key) + "' is a list of choices: read it entry by entry");
    if (!has(key)) return declared_default(f, field(key)).get<std::string>();
    return choice_or(key, f.choices.front(), f.choices);
}

std::vector<double> JsonReader::numbers(const std::string& key) {
    const FieldSpec& f = spec(key);
    expect_type(f, FieldType::Numbers, field(key));
    if (f.rows) throw std::logic_error("field '" + field(key) + "' is an array of arrays: read it row by row");
    if (!has(key)) return declared_default(f, field(key)).get<std::vector<double>>();
    return numbers(key, f.min_len, f.max_len, f.lo, f.hi);
}

std::string JsonReader::text(const std::string& key) {
    const FieldSpec& f = spec(key);
    expect_type(f, FieldType::Text, field(key));
    if (f.max_len) throw std::logic_error("field '" + field(key) + "' is a list of strings: read it with texts()");
    return has(key) ? string(key) : declared_default(f, field(key)).get<std::string>();
}

std::vector<std::string> JsonReader::texts(const std::string& key) {
    const FieldSpec& f = spec(key);
    expect_type(f, FieldType::Text, field(key));
    if (!f.max_len) throw std::logic_error("field '" + field(key) + "' is one string: read it with text()");
    if (!has(key)) return declared_default(f, field(key)).get<std::vector<std::string>>();
    const nlohmann::json& v = array(key, f.min_len, f.max_len);
    std::vector<std::string> out;
    for (size_t i = 0; i < v.size(); ++i) {
        if (!v[i].is_string()) throw InputError("field '" + field(key) + "." + std::to_string(i) + "' must be a string");
        out.push_back(v[i].get<std::string>());
    }
    return out;
}

void JsonReader::finish() const {
    for (const auto& [key, value] : object_.items())
        if (std::find(read_.begin(), read_.end(), &value) == read_.end())
            throw InputError("unknown field '" + field(key) + "'");
}

}  // namespace st
