// scene.cpp: scene files to Frames (see scene.h).
#include "scene/scene.h"

#include <algorithm>
#include <fnmatch.h>
#include <filesystem>
#include <fstream>

#include "scene/input_error.h"
#include "scene/json_reader.h"
#include "scene/param_space.h"
#include "scene/scene_kinds.h"
#include "scene/scene_sources.h"

namespace st {

namespace fs = std::filesystem;

// Resolution bounds: a zero-sized target is meaningless, and past 8192 a
// single RGBA32F target alone passes half a gigabyte.
constexpr int kMaxResolution = 8192;

static std::map<std::string, SceneBuilder>& builders() {
    static std::map<std::string, SceneBuilder> builders = {
        {"triangles", build_triangles_scene},
        {"conformance", build_conformance_scene},
        {"thin-slab", build_thin_slab_scene},
        {"thin-slab-sweep", build_thin_slab_sweep_scene},
        {"relief", build_relief_scene},
        {"profile", build_profile_scene},
    };
    return builders;
}

const std::map<std::string, SceneBuilder>& scene_builders() { return builders(); }

void register_scene_kind(const std::string& kind, SceneBuilder builder) {
    if (kind.empty()) throw InputError("a scene kind with an empty name");
    if (!builder) throw InputError("scene kind '" + kind + "' has no builder");
    if (!builders().emplace(kind, std::move(builder)).second)
        throw InputError("scene kind '" + kind + "' registered twice");
}

static QualityResolver& quality_resolver() {
    static QualityResolver resolver;
    return resolver;
}

std::vector<std::string> builtin_scene_names() {
    std::vector<std::string> names;
    for (const SceneEntry& e : scene_sources().entries()) names.push_back(e.name);
    return names;
}

std::vector<std::string> expand_scene_patterns(const std::vector<std::string>& patterns) {
    std::vector<std::string> out;
    const auto add = [&out](const std::string& name) {
        if (std::find(out.begin(), out.end(), name) == out.end()) out.push_back(name);
    };
    for (const std::string& p : patterns) {
        if (p.find_first_of("*?[") == std::string::npos) {
            add(p);
            continue;
        }
        bool matched = false;
        for (const std::string& name : builtin_scene_names())
            if (fnmatch(p.c_str(), name.c_str(), 0) == 0) {
                add(name);
                matched = true;
            }
        if (!matched) throw InputError("no scene matches '" + p + "' (shadertwin list shows them)");
    }
    return out;
}

void apply_override(nlohmann::json& document, const std::string& assignment) {
    const auto eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0)
        throw InputError("--set expects PATH=VALUE, got '" + assignment + "'");
    const std::string path = assignment.substr(0, eq), text = assignment.substr(eq + 1);
    nlohmann::json value = parse_json(text, "--set " + path);
    if (value.is_discarded()) value = text;

    nlohmann::json* node = &document;
    size_t start = 0;
    for (;;) {
        const size_t dot = path.find('.', start);
        const std::string key = path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
        const bool last = dot == std::string::npos;
        if (key.empty()) throw InputError("--set: empty segment in '" + path + "'");
        if (node->is_array()) {
            if (!std::all_of(key.begin(), key.end(), ::isdigit))
                throw InputError("--set: '" + key + "' in '" + path + "' must be an array index");
            // At most nine digits: std::stoul of a longer one may overflow.
            const size_t i = key.size() <= 9 ? std::stoul(key) : node->size();
            if (i >= node->size())
                throw InputError("--set: index " + key + " in '" + path + "' is beyond the array's " +
                                 std::to_string(node->size()) + " entries");
            node = &(*node)[i];
        } else if (node->is_object()) {
            if (!last && !node->contains(key))
                throw InputError("--set: no field '" + path.substr(0, dot) + "' in the scene");
            node = &(*node)[key];
        } else {
            throw InputError("--set: '" + path.substr(0, start - 1) + "' has no fields");
        }
        if (last) break;
        start = dot + 1;
    }
    *node = value;
}

Scene load_scene(const std::string& name_or_path, const std::vector<std::string>& overrides) {
    fs::path path = name_or_path;
    const bool is_path = name_or_path.find('/') != std::string::npos ||
                         path.extension() == ".json";
    std::string golden = scene_sources().default_golden_file();
    if (!is_path) {
        const std::optional<SceneEntry> entry = scene_sources().find(name_or_path);
        if (!entry) throw InputError("unknown scene '" + name_or_path + "' (shadertwin list shows the built-in ones)");
        path = entry->path;
        golden = entry->golden_file;
    } else {
        // A file of a source keeps that source's golden file.
        std::error_code ec;
        const fs::path canonical = fs::weakly_canonical(path, ec);
        if (!ec)
            for (const SceneEntry& e : scene_sources().entries())
                if (fs::path(e.path).filename() == canonical.filename() && fs::weakly_canonical(e.path, ec) == canonical && !ec)
                    golden = e.golden_file;
    }
    std::ifstream in(path);
    if (!in) {
        if (is_path) throw InputError("cannot read scene file " + path.string());
        throw InputError("unknown scene '" + name_or_path + "' (shadertwin list shows the built-in ones)");
    }
    nlohmann::json document = parse_json(in, path.string());
    if (document.is_discarded()) throw InputError(path.string() + ": malformed JSON");
    if (!document.is_object()) throw InputError(path.string() + ": a scene must be a JSON object");
    for (const std::string& o : overrides) apply_override(document, o);
    Scene scene = load_scene_document(path.stem().string(), std::move(document), path.string());
    scene.golden_file = golden;
    return scene;
}

void resolve_scene_paths(nlohmann::json& document, const std::string& folder) {
    if (folder.empty() || !document.is_object() || !document.contains("kind") || !document["kind"].is_string()) return;
    const ParamSpace* space = kind_space(document["kind"].get<std::string>());
    if (!space) return;
    const auto resolve = [&](nlohmann::json& v) {
        if (!v.is_string()) return;  // the reader refuses it, naming the field
        const fs::path p = v.get<std::string>();
        if (!p.empty() && p.is_relative()) v = (fs::path(folder) / p).lexically_normal().string();
    };
    const auto walk = [&](auto& self, nlohmann::json& node, const std::string& path) -> void {
        if (node.is_array()) {
            for (size_t i = 0; i < node.size(); ++i) self(self, node[i], path + "." + std::to_string(i));
            return;
        }
        if (!node.is_object()) return;
        for (auto it = node.begin(); it != node.end(); ++it) {
            const std::string p = path.empty() ? it.key() : path + "." + it.key();
            const FieldSpec* f = space->find(ParamSpace::normalise(p));
            if (f && f->is_file_path) {
                if (it->is_array())
                    for (auto& e : *it) resolve(e);
                else
                    resolve(*it);
            } else if (!f || !f->opaque) {
                self(self, *it, p);
            }
        }
    };
    walk(walk, document, "");
}

void set_quality_resolver(QualityResolver resolver) { quality_resolver() = std::move(resolver); }

static FrameCheck& frame_check() {
    static FrameCheck check;
    return check;
}

void set_frame_check(FrameCheck check) { frame_check() = std::move(check); }

Scene load_scene_document(const std::string& name, nlohmann::json document, const std::string& where) {
    Scene scene;
    scene.name = name;
    scene.document = std::move(document);
    try {
        if (scene.document.contains("quality")) {
            if (!quality_resolver()) throw InputError("field 'quality' needs shadertwin's measuring, not available here");
            scene.quality = quality_resolver()(name, scene.document);
        }
        JsonReader r(scene.document, "");
        // Files the scene names sit beside it (a document without a file:
        // the working directory).
        if (!where.empty()) r.set_folder(fs::path(where).parent_path().string());
        scene.kind = r.string("kind");
        // A kind with a declared space reads every field through it.
        if (const ParamSpace* space = kind_space(scene.kind)) r.bind(*space);
        scene.description = r.string_or("description", "");
        const SceneSize size{r.integer("width", 1, kMaxResolution), r.integer("height", 1, kMaxResolution)};
        scene.criteria = Criteria::read(r);
        scene.paper = PaperTiming::read(r);
        auto builder = scene_builders().find(scene.kind);
        if (builder == scene_builders().end()) throw InputError("unknown scene kind '" + scene.kind + "'");
        scene.frame = builder->second(r, size);
        r.finish();
        if (frame_check()) frame_check()(scene.frame);
    } catch (const InputError& e) {
        throw InputError(where.empty() ? std::string(e.what()) : where + ": " + e.what());
    }
    return scene;
}

}  // namespace st
