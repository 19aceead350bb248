// new_technique.cpp: see new_technique.h. The files are written into a
// folder beside the target and renamed into place, so an error leaves
// nothing behind.
#include "app/commands/new_technique.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <unistd.h>

#include "app/interface/glsl_declarations.h"
#include "app/new_technique/skeleton_files.h"
#include "gl/gl_renderer.h"
#include "kernels/registry.h"
#include "scene/input_error.h"
#include "scene/scene_kinds.h"

namespace st {

namespace fs = std::filesystem;

namespace {

std::string glsl_text(const std::string& path) {
    if (!std::ifstream(path)) throw InputError("cannot read " + path);
    try {
        return read_glsl_source(path);
    } catch (const std::runtime_error& e) {
        throw InputError(e.what());
    }
}

void check_name(const std::string& name) {
    const bool identifier = !name.empty() && name.size() <= 40 && std::islower((unsigned char)name[0]) &&
                            std::all_of(name.begin(), name.end(), [](char c) {
                                return std::islower((unsigned char)c) || std::isdigit((unsigned char)c) || c == '_';
                            });
    if (!identifier)
        throw InputError("technique name '" + name + "': a lower-case C identifier of at most 40 characters (pom, skin_sss)");
    for (const auto& names : {vertex_twin_names(), fragment_twin_names()})
        if (std::find(names.begin(), names.end(), name) != names.end())
            throw InputError("technique name '" + name + "': the tool already has a twin of that name");
    if (scene_builders().count(name)) throw InputError("technique name '" + name + "': the tool already has a scene kind of that name");
}

}  // namespace

int cmd_new_technique(const std::string& name, const std::string& vert, const std::string& frag, std::string out_dir) {
    check_name(name);
    if (out_dir.empty()) out_dir = name;
    std::error_code ec;
    if (fs::exists(out_dir, ec) && !(fs::is_directory(out_dir, ec) && fs::is_empty(out_dir, ec)))
        throw InputError(out_dir + " exists and is not an empty folder: choose another --out");
    // With any #include "file" spliced in, as the GL side reads a shader:
    // the project's copies are then whole.
    const std::string vert_source = glsl_text(vert), frag_source = glsl_text(frag);
    const GlslStage v = parse_glsl_stage(vert_source, vert);
    const GlslStage f = parse_glsl_stage(frag_source, frag);
    const std::vector<skeleton::ProjectFile> files = skeleton::skeleton_files(name, v, vert_source, f, frag_source);

    const fs::path target = fs::absolute(out_dir).lexically_normal();
    const fs::path staging = target.parent_path() / ("." + target.filename().string() + ".new-technique-" + std::to_string(::getpid()));
    try {
        for (const skeleton::ProjectFile& file : files) {
            const fs::path p = staging / file.path;
            fs::create_directories(p.parent_path());
            std::ofstream out(p, std::ios::binary);
            out << file.text;
            if (!out.flush()) throw InputError("cannot write " + (target / file.path).string());
        }
        fs::remove(target, ec);  // an empty folder, if any
        fs::rename(staging, target);
    } catch (const std::exception& e) {
        fs::remove_all(staging, ec);
        if (dynamic_cast<const InputError*>(&e)) throw;
        throw InputError("cannot write " + target.string() + ": " + e.what());
    }
    std::cout << "wrote " << out_dir << "/ (" << files.size() << " files):";
    for (const skeleton::ProjectFile& file : files) std::cout << " " << file.path;
    std::cout << "\nnext: build it against this shadertwin's install and compare (it fails, saying what is left to write):\n"
              << "  cmake -S " << out_dir << " -B " << out_dir << "/build -DCMAKE_PREFIX_PATH=<shadertwin prefix> -DCMAKE_BUILD_TYPE=RelWithDebInfo\n"
              << "  cmake --build " << out_dir << "/build -j 2\n"
              << "  " << out_dir << "/build/" << name << "twin compare " << name << "-first --out " << out_dir << "/out\n"
              << "then write the twins' bodies (kernels/" << name << "_vert.cpp, kernels/" << name
              << "_frag.cpp) from the GLSL in their comments, and make scenes/" << name << "-first.json yours.\n";
    return 0;
}

}  // namespace st
