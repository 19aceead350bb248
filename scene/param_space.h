// param_space.h: the settings a scene kind accepts, declared once per kind.
//
// Every field a user may set in a scene file of a kind is declared here
// with its type, its domain (range, set, length) and its default; the
// kind's builder reads its fields through the space (JsonReader bound to
// it), so the range a field is refused outside of is the one declared,
// `shadertwin fields` prints the tables docs/scenes.md holds, and the
// explorer's sampler (scene/param_sampler.h) draws from the same domains.
// Paths are dotted as in error messages; "[]" stands for any index of an
// array ("triangles[].colour").
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace st {

enum class FieldType { Number, Integer, Boolean, Choice, Numbers, Text, Object };

struct FieldSpec {
    std::string path;
    FieldType type = FieldType::Number;
    double lo = 0, hi = 0;            // Number, Integer and each of Numbers
    size_t min_len = 0, max_len = 0;  // Numbers; arrays of objects; a Choice's list (below)
    // Numbers given as `rows` arrays of min_len..max_len numbers each (a
    // triangle's corners: "triangles[].positions"); 0: one flat array.
    size_t rows = 0;
    // Choice; with max_len > 0 an array of min_len..max_len of them (a
    // blend's factors).
    std::vector<std::string> choices;
    nlohmann::json fallback;          // the default; null: required, or absent means "none"
    bool required = false;
    std::string meaning;

    // Bounds that are another field's value (the same object's, by path):
    // `liquid.max_radius` is at least `liquid.min_radius`.
    std::string lo_field, hi_field;
    // Read only where the field `when_field` has one of `when_values`
    // (`liquid.ior` only for the two-layer rows); elsewhere it is unknown.
    std::string when_field;
    std::vector<std::string> when_values;

    // For the sampler only. Uniform draws come from [draw_lo, draw_hi]
    // (the domain unless narrowed: a coordinate's domain is +-1e30, its
    // useful draws a few units), on a log scale where `log_scale`; edge
    // draws take the domain's bounds and the `edges` listed.
    double draw_lo = 0, draw_hi = 0;
    bool log_scale = false;
    std::vector<double> edges;
    // Not drawn at all: the pass criteria, free text, file paths.
    bool explore = true;
    // An object whose fields are declared and documented elsewhere (the
    // criteria, a paper's timing): read without the space.
    bool opaque = false;
    // The most the explorer draws (cost, not validity: a 4096-texel map is
    // valid and takes seconds); 0: the domain's bound.
    double explore_hi = 0;

    // Modifiers, so that declarations read as one line each.
    FieldSpec& at_least(std::string field) { lo_field = std::move(field); return *this; }
    FieldSpec& at_most(std::string field) { hi_field = std::move(field); return *this; }
    FieldSpec& when(std::string field, std::vector<std::string> values) {
        when_field = std::move(field), when_values = std::move(values);
        return *this;
    }
    FieldSpec& draws(double lo_, double hi_) { draw_lo = lo_, draw_hi = hi_; return *this; }
    FieldSpec& log() { log_scale = true; return *this; }
    FieldSpec& edge(std::vector<double> values) { edges = std::move(values); return *this; }
    FieldSpec& not_explored() { explore = false; return *this; }
    FieldSpec& opaque_object() { opaque = true, explore = false; return *this; }
    FieldSpec& explore_at_most(double hi_) { explore_hi = hi_; return *this; }
    // A choice the explorer draws only from these (a value that needs a
    // file, which it cannot make up, left out).
    FieldSpec& explore_choices(std::vector<std::string> c) { drawn_choices = std::move(c); return *this; }
    std::vector<std::string> drawn_choices;
    FieldSpec& in_rows(size_t n) { rows = n; return *this; }
    // The explorer changes this field (or what an object holds) only where
    // the document has it, never adds it: one of several exclusive forms
    // (a uniform's float or vec3), or an object whose presence asks for
    // more elsewhere (a texture needs every triangle's uvs).
    FieldSpec& only_if_present() { if_present = true; return *this; }
    // Numbers that must be whole (a viewport in pixels): drawn as integers.
    FieldSpec& whole() { integers = true; return *this; }
    bool integers = false;
    bool if_present = false;
    FieldSpec& listed(size_t lo_, size_t hi_) { min_len = lo_, max_len = hi_; return *this; }
    // A file's path (Text, or a list of them): relative to the scene
    // file's folder (its builder reads it with JsonReader::file_path;
    // resolve_scene_paths() in scene/scene.h makes it absolute in a
    // document that moves).
    FieldSpec& file_path() { is_file_path = true; return *this; }
    bool is_file_path = false;

    // The domain as docs and error messages say it: "1..512", "[0, 89]",
    // "one of a, b", "3 numbers in [-1e6, 1e6]".
    std::string domain_text() const;
    std::string type_text() const;
};

class ParamSpace {
public:
    explicit ParamSpace(std::string kind);

    const std::string& kind() const { return kind_; }
    const std::vector<FieldSpec>& fields() const { return fields_; }
    // The field at a normalised path ("triangles[].colour"), or null.
    const FieldSpec* find(const std::string& path) const;
    // The field at a reader's path ("triangles.12.colour": indices become
    // "[]"); throws std::logic_error when undeclared (a builder reading a
    // field its kind does not declare is a defect, not bad input).
    const FieldSpec& at(const std::string& path) const;
    static std::string normalise(const std::string& path);

    // Declarations (in the order docs list them).
    FieldSpec& number(std::string path, double lo, double hi, nlohmann::json fallback, std::string meaning);
    FieldSpec& integer(std::string path, int lo, int hi, nlohmann::json fallback, std::string meaning);
    FieldSpec& boolean(std::string path, bool fallback, std::string meaning);
    FieldSpec& choice(std::string path, std::vector<std::string> choices, nlohmann::json fallback,
                      std::string meaning);
    FieldSpec& numbers(std::string path, size_t min_len, size_t max_len, double lo, double hi,
                       nlohmann::json fallback, std::string meaning);
    FieldSpec& text(std::string path, nlohmann::json fallback, std::string meaning);
    // A list of min_len..max_len strings (a cube map's six files).
    FieldSpec& texts(std::string path, size_t min_len, size_t max_len, nlohmann::json fallback, std::string meaning);
    // An object, or an array of objects with min_len..max_len entries
    // (max_len 0: one object). Its own fields are declared under its path.
    FieldSpec& object(std::string path, bool required, std::string meaning, size_t min_len = 0, size_t max_len = 0);
    // Every field of `other` (the common fields, a shared block) under `prefix`.
    void include(const ParamSpace& other, const std::string& prefix = "");

    // Markdown: one table of every field, for docs/scenes.md.
    std::string markdown() const;

private:
    FieldSpec& add(FieldSpec spec);
    std::string kind_;
    std::vector<FieldSpec> fields_;
    std::map<std::string, size_t> index_;
};

// The fields every scene has (kind, description, width, height, criteria, paper).
const ParamSpace& common_space();
// The declared space of a built-in kind (common fields included), or null.
const ParamSpace* kind_space(const std::string& kind);
// Kinds with a declared space, for `shadertwin fields` and the explorer.
std::vector<std::string> spaced_kinds();
void register_kind_space(const std::string& kind, const ParamSpace* space);

}  // namespace st
