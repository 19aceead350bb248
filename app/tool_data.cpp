// tool_data.cpp: see tool_data.h.
#include "app/tool_data.h"

#include <filesystem>
#include <map>
#include <stdexcept>

#include "scene/scene_sources.h"

#if !defined(SHADERTWIN_GLSL_DIR) || !defined(SHADERTWIN_MATERIALS_DIR) || !defined(SHADERTWIN_DOCS_DIR)
#error "SHADERTWIN_GLSL_DIR, SHADERTWIN_MATERIALS_DIR and SHADERTWIN_DOCS_DIR must name the source tree's folders"
#endif

namespace st {

namespace fs = std::filesystem;

namespace {

struct ToolData {
    std::vector<std::string> glsl_roots = {SHADERTWIN_GLSL_DIR};
    std::string materials = SHADERTWIN_MATERIALS_DIR;
    // The sweeps' last runs kept with the tool (docs/ here; sweeps/<kind>/
    // in an install), whose charts the report shows.
    std::map<std::string, std::string> sweep_charts = {{"relief", SHADERTWIN_DOCS_DIR "/relief-sweep"},
                                                       {"profile", SHADERTWIN_DOCS_DIR "/profile-sweep"},
                                                       {"thin-slab", SHADERTWIN_DOCS_DIR "/thin-slab-speed"}};
    std::string tool_name = "shadertwin";
};

ToolData& data() {
    static ToolData d;
    return d;
}

}  // namespace

void set_builtin_data_dir(const std::string& share_dir) {
    const fs::path share = share_dir;
    for (const char* needed : {"glsl", "scenes", "golden/hashes.json", "materials"}) {
        std::error_code ec;
        if (!fs::exists(share / needed, ec))
            throw std::runtime_error("shadertwin's data folder " + share_dir + " has no " + needed +
                                     " (is the install complete?)");
    }
    data().glsl_roots.front() = (share / "glsl").string();
    data().materials = (share / "materials").string();
    for (auto& [kind, dir] : data().sweep_charts) dir = (share / "sweeps" / kind).string();
    scene_sources().set_builtin((share / "scenes").string(), (share / "golden" / "hashes.json").string());
}

std::string installed_data_dir_beside(const std::string& executable) {
    std::error_code ec;
    const fs::path share = fs::weakly_canonical(executable, ec).parent_path().parent_path() / "share" / "shadertwin";
    return !ec && fs::is_directory(share / "glsl", ec) ? share.string() : std::string();
}

void add_glsl_roots(const std::vector<std::string>& roots) {
    for (const std::string& r : roots) data().glsl_roots.push_back(r);
}

std::vector<std::string> glsl_roots() { return data().glsl_roots; }
std::string materials_dir() { return data().materials; }
std::map<std::string, std::string> sweep_chart_dirs() { return data().sweep_charts; }

void set_tool_name(const std::string& name) {
    if (!name.empty()) data().tool_name = name;
}
const std::string& tool_name() { return data().tool_name; }

}  // namespace st
