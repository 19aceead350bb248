// tool.cpp: see tool.h.
#include "sdk/tool.h"

#include <algorithm>
#include <filesystem>
#include <set>

#include "app/cli.h"
#include "app/tool_data.h"
#include "scene/input_error.h"
#include "scene/scene_sources.h"
#include "sdk/declarations.h"

namespace st {

namespace fs = std::filesystem;

namespace {

// Every GLSL file a technique names exists, and each twin it registers has
// the file it mirrors among them (the built-in twins' rule, checked by
// kernels/twin_correspondence_test.cpp).
void check_glsl(const TechniqueDeclaration& d, const TechniqueRegistry& registry) {
    std::set<std::string> files;
    for (const std::string& path : d.glsl) {
        std::error_code ec;
        if (!fs::is_regular_file(path, ec))
            throw InputError("technique " + d.name + ": no GLSL file " + path);
        files.insert(fs::path(path).filename().string());
    }
    for (const std::string& name : registry.vertex_names())
        if (!files.count(name + ".vert"))
            throw InputError("technique " + d.name + ": vertex twin '" + name + "' has no " + name +
                             ".vert among the technique's GLSL files");
    for (const std::string& name : registry.fragment_names())
        if (!files.count(name + ".frag"))
            throw InputError("technique " + d.name + ": fragment twin '" + name + "' has no " + name +
                             ".frag among the technique's GLSL files");
}

void take_in_techniques(const std::string& executable) {
    std::vector<const TechniqueDeclaration*> declared = declared_techniques();
    std::sort(declared.begin(), declared.end(),
              [](const TechniqueDeclaration* a, const TechniqueDeclaration* b) { return a->name < b->name; });
    for (size_t i = 1; i < declared.size(); ++i)
        if (declared[i]->name == declared[i - 1]->name)
            throw InputError("technique " + declared[i]->name + " declared twice");

    // A user's tool reads the built-in data of the package it was built
    // against; an installed `shadertwin` the share folder beside it; a build
    // tree's tool the source tree (the default).
    std::string data_dir = declared.empty() ? installed_data_dir_beside(executable) : declared.front()->data_dir;
    if (!data_dir.empty()) set_builtin_data_dir(data_dir);

    for (const TechniqueDeclaration* d : declared) {
        TechniqueRegistry registry(d->name);
        d->register_fn(registry);
        check_glsl(*d, registry);
        add_glsl_roots(d->glsl);
        if (!d->scenes.empty()) scene_sources().add({d->name, d->scenes, d->golden_file});
    }
    scene_sources().entries();  // a name in two sources is refused now, not by the first command to list
}

}  // namespace

int run_tool(int argc, char** argv) {
    std::error_code ec;
    const std::string executable = fs::read_symlink("/proc/self/exe", ec).string();
    if (argc > 0 && argv[0]) set_tool_name(fs::path(argv[0]).filename().string());
    return run_cli(argc, argv, [&executable] { take_in_techniques(executable); });
}

}  // namespace st
