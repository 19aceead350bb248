// scene.h: loading a scene file (built-in name or path), applying --set
// overrides, validating it and turning it into a Frame. Schema:
// docs/scenes.md.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "frame/frame.h"
#include "scene/criteria.h"
#include "scene/paper_timing.h"

namespace st {

struct Scene {
    std::string name;         // built-in name, or the file's stem
    std::string kind;         // "triangles", ...
    std::string description;
    nlohmann::json document;  // after overrides
    Criteria criteria;
    std::optional<PaperTiming> paper;  // a published frame rate for this scene's technique
    Frame frame;
    std::string golden_file;  // where `golden` keeps its hashes (scene_sources.h)
    // What `quality: auto` chose and measured (the resolver's record: the
    // setting, its error, its frame time, the most accurate one's); null
    // when the scene did not ask.
    nlohmann::json quality;
};

// Throws InputError with one line on any problem: unknown scene, malformed
// JSON, unknown/missing/mistyped field, out-of-range value, bad override.
Scene load_scene(const std::string& name_or_path, const std::vector<std::string>& overrides);
// The same from a document already read and overridden; `where` prefixes
// its errors (the file's path; none when empty).
Scene load_scene_document(const std::string& name, nlohmann::json document, const std::string& where);

// Puts `folder` in front of every relative file path the document's kind
// declares (FieldSpec::file_path: a texture's `file`, a cube's `files`),
// so that a document copied elsewhere (an explorer's reproducer) still
// finds them. (Loading a scene file needs none of this: its builder reads
// each path relative to the file's folder, JsonReader::file_path.) An
// empty folder changes nothing.
void resolve_scene_paths(nlohmann::json& document, const std::string& folder);

// A scene's top-level "quality" field ("auto": the cheapest settings within
// an image-error budget, app/quality/quality_resolver.h) is resolved by
// measuring, which needs renderers this layer does not know: the app sets a
// resolver, which rewrites the document (its chosen fields in, "quality"
// out) before the scene is built and returns its record (Scene::quality).
// Without one, such a scene is refused.
using QualityResolver = std::function<nlohmann::json(const std::string& name, nlohmann::json& document)>;
void set_quality_resolver(QualityResolver resolver);

// A check of a built frame against what its programs declare (the app's:
// app/interface/uniform_interface.h), run by load_scene_document on every
// scene before anything renders; it throws InputError with one line.
using FrameCheck = std::function<void(const Frame& frame)>;
void set_frame_check(FrameCheck check);

// Every named scene of the tool (scene_sources.h), sorted: the built-in
// ones and a user tool's own.
std::vector<std::string> builtin_scene_names();
// Scene names and paths, with shell patterns (`relief-*`, `*-rgba8-*`)
// expanded against the named scenes, in the order given (each once). A
// pattern that matches nothing is refused with InputError.
std::vector<std::string> expand_scene_patterns(const std::vector<std::string>& patterns);

// Applies "dotted.path=value" to a document: the value is parsed as JSON when
// it parses (numbers, booleans, arrays), else taken as a string. The parent
// of the last segment must exist; the field itself may be new (validation
// then rejects names the schema does not know).
void apply_override(nlohmann::json& document, const std::string& assignment);

}  // namespace st
