// shader_files.cpp: see shader_files.h.
#include "gl/shader_files.h"

#include <filesystem>
#include <stdexcept>

namespace st {

namespace fs = std::filesystem;

ShaderFiles::ShaderFiles(const std::string& glsl_dir) : dir_(glsl_dir) {
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(glsl_dir, ec); !ec && it != fs::recursive_directory_iterator();
         it.increment(ec)) {
        const fs::path& p = it->path();
        const std::string ext = p.extension().string();
        if (!it->is_regular_file() || (ext != ".vert" && ext != ".frag" && ext != ".glsl")) continue;
        const auto [entry, added] = paths_.emplace(p.filename().string(), p.string());
        if (!added)
            throw std::runtime_error("shader " + p.filename().string() + " is in two folders: " + entry->second +
                                     " and " + p.string());
    }
    if (ec) throw std::runtime_error("cannot read shader folder " + glsl_dir + ": " + ec.message());
}

const std::string& ShaderFiles::path(const std::string& name, const std::string& extension) const {
    const auto it = paths_.find(name + extension);
    if (it == paths_.end()) throw std::runtime_error("no shader " + name + extension + " under " + dir_);
    return it->second;
}

}  // namespace st
