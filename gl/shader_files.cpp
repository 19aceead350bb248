// shader_files.cpp: see shader_files.h.
#include "gl/shader_files.h"

#include <filesystem>
#include <stdexcept>

namespace st {

namespace fs = std::filesystem;

namespace {

bool is_shader(const fs::path& p) {
    const std::string ext = p.extension().string();
    return ext == ".vert" || ext == ".frag" || ext == ".glsl";
}

}  // namespace

ShaderFiles::ShaderFiles(const std::vector<std::string>& roots) {
    for (const std::string& root : roots) {
        where_ += (where_.empty() ? "" : ", ") + root;
        std::error_code ec;
        if (fs::is_regular_file(root, ec)) {
            if (!is_shader(root)) throw std::runtime_error("shader " + root + " is not a .vert, .frag or .glsl file");
            add(root);
            continue;
        }
        if (!fs::is_directory(root, ec)) throw std::runtime_error("no shader file or folder " + root);
        for (auto it = fs::recursive_directory_iterator(root, ec); !ec && it != fs::recursive_directory_iterator();
             it.increment(ec))
            if (it->is_regular_file() && is_shader(it->path())) add(it->path().string());
        if (ec) throw std::runtime_error("cannot read shader folder " + root + ": " + ec.message());
    }
}

void ShaderFiles::add(const std::string& path) {
    const std::string name = fs::path(path).filename().string();
    const auto [entry, added] = paths_.emplace(name, path);
    if (!added && fs::weakly_canonical(entry->second) != fs::weakly_canonical(path))
        throw std::runtime_error("shader " + name + " is in two places: " + entry->second + " and " + path);
}

const std::string& ShaderFiles::path(const std::string& name, const std::string& extension) const {
    const auto it = paths_.find(name + extension);
    if (it == paths_.end()) throw std::runtime_error("no shader " + name + extension + " under " + where_);
    return it->second;
}

}  // namespace st
