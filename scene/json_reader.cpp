// json_reader.cpp: see json_reader.h.
#include "scene/json_reader.h"

#include <cmath>
#include <sstream>

#include "scene/input_error.h"

namespace st {

namespace {

template <class Text> nlohmann::json parse_bounded(Text& text, const std::string& what) {
    const nlohmann::json::parser_callback_t bound = [&](int depth, nlohmann::json::parse_event_t,
                                                        nlohmann::json&) {
        if (depth > kMaxJsonDepth)
            throw InputError(what + ": nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
        return true;
    };
    return nlohmann::json::parse(text, bound, false);
}

}  // namespace

nlohmann::json parse_json(std::istream& text, const std::string& what) { return parse_bounded(text, what); }
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
    if (!object_.contains(key)) throw InputError("missing field '" + field(key) + "'");
    read_.insert(key);
    return object_.at(key);
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
    for (size_t i = 0; i < v.size(); ++i)
        out.push_back(checked_number(v[i], field(key) + "." + std::to_string(i), lo, hi));
    return out;
}

JsonReader JsonReader::object(const std::string& key) { return JsonReader(get(key), field(key)); }

std::optional<JsonReader> JsonReader::object_if(const std::string& key) {
    if (!has(key)) return std::nullopt;
    return object(key);
}

std::vector<JsonReader> JsonReader::objects(const std::string& key, size_t min_len, size_t max_len) {
    const nlohmann::json& v = array(key, min_len, max_len);
    std::vector<JsonReader> out;
    for (size_t i = 0; i < v.size(); ++i) out.emplace_back(v[i], field(key) + "." + std::to_string(i));
    return out;
}

void JsonReader::finish() const {
    for (const auto& [key, value] : object_.items())
        if (!read_.count(key)) throw InputError("unknown field '" + field(key) + "'");
}

}  // namespace st
