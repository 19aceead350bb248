// shader_files.h: finds a program's GLSL file by name. Shaders live under
// glsl/<technique>/<name>.vert|.frag, and a user tool adds its own files or
// folders; a draw names only <name>, so every file name must be unique
// across all of them.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace st {

class ShaderFiles {
public:
    // Indexes every .vert, .frag and .glsl file below each root that is a
    // folder, and each root that is such a file. Throws std::runtime_error
    // when two places hold the same file name or a root does not exist.
    explicit ShaderFiles(const std::vector<std::string>& roots);
    // Path of <name><extension> (extension ".vert" or ".frag"); throws
    // std::runtime_error naming the file when there is none.
    const std::string& path(const std::string& name, const std::string& extension) const;

private:
    void add(const std::string& path);

    std::string where_;  // the roots, for messages
    std::map<std::string, std::string> paths_;  // file name -> path
};

}  // namespace st
