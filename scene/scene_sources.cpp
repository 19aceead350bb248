// scene_sources.cpp: see scene_sources.h.
#include "scene/scene_sources.h"

#include <algorithm>
#include <filesystem>
#include <map>

#include "scene/input_error.h"

#if !defined(SHADERTWIN_SCENE_DIR) || !defined(SHADERTWIN_GOLDEN_FILE)
#error "SHADERTWIN_SCENE_DIR and SHADERTWIN_GOLDEN_FILE must name the built-in scenes and their goldens"
#endif

namespace st {

namespace fs = std::filesystem;

namespace {

void collect(const SceneSource& source, const std::string& path, std::map<std::string, SceneEntry>& out) {
    auto add = [&](const fs::path& file) {
        SceneEntry e{file.stem().string(), file.string(), source.golden_file, source.technique};
        const auto [it, added] = out.emplace(e.name, e);
        if (!added)
            throw InputError("scene '" + e.name + "' is in two places: " + it->second.path + " (" +
                             it->second.technique + ") and " + e.path + " (" + e.technique + ")");
    };
    std::error_code ec;
    if (fs::is_directory(path, ec)) {
        std::vector<fs::path> files;
        for (auto it = fs::directory_iterator(path, ec); !ec && it != fs::directory_iterator(); it.increment(ec))
            if (it->path().extension() == ".json") files.push_back(it->path());
        if (ec) throw InputError("cannot read scene folder " + path + ": " + ec.message());
        std::sort(files.begin(), files.end());
        for (const fs::path& f : files) add(f);
    } else if (fs::path(path).extension() == ".json" && fs::is_regular_file(path, ec)) {
        add(path);
    } else {
        throw InputError("technique " + source.technique + ": scene " + path + " is not a .json file or a folder");
    }
}

}  // namespace

SceneSources::SceneSources() : sources_{{"built-in", {SHADERTWIN_SCENE_DIR}, SHADERTWIN_GOLDEN_FILE}} {}

void SceneSources::set_builtin(const std::string& scene_dir, const std::string& golden_file) {
    sources_.front() = {"built-in", {scene_dir}, golden_file};
}

void SceneSources::add(SceneSource source) {
    std::map<std::string, SceneEntry> check;
    for (const std::string& p : source.paths) collect(source, p, check);
    sources_.push_back(std::move(source));
}

std::vector<SceneEntry> SceneSources::entries() const {
    std::map<std::string, SceneEntry> all;
    for (const SceneSource& s : sources_)
        for (const std::string& p : s.paths) collect(s, p, all);
    std::vector<SceneEntry> out;
    for (auto& [name, entry] : all) out.push_back(std::move(entry));
    return out;
}

std::optional<SceneEntry> SceneSources::find(const std::string& name) const {
    for (SceneEntry& e : entries())
        if (e.name == name) return std::move(e);
    return std::nullopt;
}

std::string SceneSources::default_golden_file() const {
    return sources_.size() > 1 ? sources_[1].golden_file : sources_.front().golden_file;
}

SceneSources& scene_sources() {
    static SceneSources sources;
    return sources;
}

}  // namespace st
