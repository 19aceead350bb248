// shader_files.h: finds a program's GLSL file by name. Shaders live under
// glsl/<technique>/<name>.vert|.frag; a draw names only <name>, so every
// file name must be unique across the technique folders.
#pragma once

#include <map>
#include <string>

namespace st {

class ShaderFiles {
public:
    // Indexes every .vert, .frag and .glsl file below `glsl_dir`. Throws
    // std::runtime_error when two folders hold the same file name.
    explicit ShaderFiles(const std::string& glsl_dir);
    // Path of <name><extension> (extension ".vert" or ".frag"); throws
    // std::runtime_error naming the file when there is none.
    const std::string& path(const std::string& name, const std::string& extension) const;

private:
    std::string dir_;
    std::map<std::string, std::string> paths_;  // file name -> path
};

}  // namespace st
