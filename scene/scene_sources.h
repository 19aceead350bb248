// scene_sources.h: where a tool's named scenes come from, and where each
// one's golden hashes are kept. The built-in scenes (scenes/, goldens in
// tests/golden/hashes.json, or share/shadertwin/ once installed) are one
// source; each technique of a user's tool (sdk/technique.h) adds its own,
// with its own golden file. A name belongs to one source only.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace st {

struct SceneSource {
    std::string technique;           // "built-in", or the user technique's name
    std::vector<std::string> paths;  // scene files (.json) and folders of them
    std::string golden_file;         // where `golden` keeps these scenes' hashes
};

// One named scene: its file and the golden file its hashes go to.
struct SceneEntry {
    std::string name, path, golden_file, technique;
};

class SceneSources {
public:
    // Starts with the built-in source alone.
    SceneSources();

    // Moves the built-in source (an installed tool reads share/shadertwin/).
    void set_builtin(const std::string& scene_dir, const std::string& golden_file);
    // Adds a user technique's scenes. Throws InputError when a path is
    // neither a .json file nor a folder, or a name repeats within it.
    void add(SceneSource source);

    // Every named scene, sorted by name. Throws InputError when two sources
    // (or two folders of one) hold the same name.
    std::vector<SceneEntry> entries() const;
    std::optional<SceneEntry> find(const std::string& name) const;

    // The golden file of a scene given as a path outside every source: the
    // first user technique's, or the built-in one in a tool without any.
    std::string default_golden_file() const;

private:
    std::vector<SceneSource> sources_;  // the built-in one first
};

// The tool's one set of sources, which load_scene and the commands read.
SceneSources& scene_sources();

}  // namespace st
