// json_reader.h: strict, typed reading of a JSON object.
//
// Every accessor checks type and range and names the offending field by its
// dotted path ("triangles.2.colours.0"); finish() rejects fields nobody read,
// so a typo in a scene file is an error, not a silent default.
#pragma once

#include <cmath>
#include <concepts>
#include <istream>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace st {

// JSON text parsed as nlohmann::json::parse(text, nullptr, false) parses it
// (a discarded value when malformed), but refusing nesting deeper than
// kMaxJsonDepth with an InputError that names `what`: no scene, layer file
// or --set value needs more than a handful of levels, and the bound keeps
// every later walk of the document (copies, comparisons, dumps) shallow.
inline constexpr int kMaxJsonDepth = 64;
nlohmann::json parse_json(std::istream& text, const std::string& what);
nlohmann::json parse_json(const std::string& text, const std::string& what);

// The range of a number with no natural one (a coordinate, a colour, a
// uniform): beyond +-1e30 a value is a typo, and infinities stay out.
inline constexpr double kHuge = 1e30;

class ParamSpace;
struct FieldSpec;

class JsonReader {
public:
    JsonReader(const nlohmann::json& object, std::string path);

    // Reads through a declared space (scene/param_space.h): the one-argument
    // accessors below take the field's type, domain and default from it.
    // Readers of its objects inherit it.
    void bind(const ParamSpace& space) { space_ = &space; }
    const ParamSpace* space() const { return space_; }
    // The scene file's folder (empty: the working directory), which a
    // relative file path in the scene is relative to; readers of its
    // objects inherit it. file_path() resolves one.
    void set_folder(std::string folder) { folder_ = std::move(folder); }
    std::string file_path(const std::string& path) const;
    const FieldSpec& spec(const std::string& key) const;
    // A declared field: its value, or its default when absent (a missing
    // required field is an error naming it).
    double number(const std::string& key);
    int integer(const std::string& key);
    bool boolean(const std::string& key);
    std::string choice(const std::string& key);
    std::vector<double> numbers(const std::string& key);
    std::string text(const std::string& key);
    std::vector<std::string> texts(const std::string& key);
    // A declared field whose bounds are other fields' values (the spec's
    // at_least/at_most): [lo, hi] as those values are, within the domain.
    double number_in(const std::string& key, double lo, double hi);
    int integer_in(const std::string& key, int lo, int hi);

    bool has(const std::string& key) const;
    double number(const std::string& key, double lo, double hi);
    double number_or(const std::string& key, double fallback, double lo, double hi);
    int integer(const std::string& key, int lo, int hi);
    int integer_or(const std::string& key, int fallback, int lo, int hi);
    bool boolean_or(const std::string& key, bool fallback);
    std::string string(const std::string& key);
    std::string string_or(const std::string& key, const std::string& fallback);
    // One of `allowed`.
    std::string choice_or(const std::string& key, const std::string& fallback,
                          const std::vector<std::string>& allowed);
    // An array of numbers of length in [min_len, max_len], each in [lo, hi].
    std::vector<double> numbers(const std::string& key, size_t min_len, size_t max_len, double lo,
                                double hi);
    JsonReader object(const std::string& key);
    std::optional<JsonReader> object_if(const std::string& key);
    // The object at `key`, or an empty one when absent, so that a bound
    // reader's fields take their declared defaults either way.
    JsonReader object_or_defaults(const std::string& key);
    std::vector<JsonReader> objects(const std::string& key, size_t min_len, size_t max_len);
    // The same, one object at a time: for arrays as long as a mesh's
    // triangles, whose readers need not all exist at once.
    template <class Visit> void for_each_object(const std::string& key, size_t min_len, size_t max_len, Visit&& visit);
    // The raw value at `key` (marked as read; InputError when missing), for
    // a field whose shape its reader checks (scene/uniform_fields.h).
    const nlohmann::json& raw(const std::string& key) { return get(key); }
    // The raw array at `key` (marked as read), for arrays of arrays.
    const nlohmann::json& array(const std::string& key, size_t min_len, size_t max_len);

    // Throws InputError naming the first field that was never read.
    void finish() const;

    const std::string& path() const { return path_; }
    std::string field(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

    // Checks a JSON value is a finite number in [lo, hi]; `where` names it.
    static double checked_number(const nlohmann::json& v, const std::string& where, double lo, double hi);
    // The same with the name made only when the value is refused: a mesh's
    // millions of numbers are read without building a path for each.
    template <std::invocable Where> static double checked_number(const nlohmann::json& v, Where&& where, double lo, double hi) {
        if (v.is_number()) {
            const double x = v.get<double>();
            if (std::isfinite(x) && x >= lo && x <= hi) return x;
        }
        return checked_number(v, std::string(where()), lo, hi);  // throws
    }

private:
    const nlohmann::json& get(const std::string& key);
    // A reader of one of this object's objects: bound to the space unless
    // that object is opaque (`bound` is inherits(key), computed once per array).
    bool inherits(const std::string& key) const;
    JsonReader child(const nlohmann::json& value, bool bound, std::string path) const;
    const nlohmann::json& object_;
    std::string path_;
    const ParamSpace* space_ = nullptr;
    std::string folder_;
    std::vector<const nlohmann::json*> read_;  // the members read (an object has a handful)
};

template <class Visit>
void JsonReader::for_each_object(const std::string& key, size_t min_len, size_t max_len, Visit&& visit) {
    const nlohmann::json& v = array(key, min_len, max_len);
    const std::string prefix = field(key) + ".";
    const bool bound = inherits(key);
    for (size_t i = 0; i < v.size(); ++i) {
        JsonReader item = child(v[i], bound, prefix + std::to_string(i));
        visit(item);
    }
}

}  // namespace st
