// twin_library.h: where the pipeline gets twins from. The CPU renderer is
// handed a TwinLibrary and asks it for the twin of each program a draw
// names; it never knows which twins exist. kernels/registry.h provides the
// library of the built-in techniques.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "shading/program.h"

namespace st {

class TwinLibrary {
public:
    virtual ~TwinLibrary() = default;
    // nullptr when the library has no twin of that name.
    virtual std::unique_ptr<VertexTwin> make_vertex(const std::string& name) const = 0;
    virtual std::unique_ptr<FragmentTwin> make_fragment(const std::string& name) const = 0;
    virtual std::vector<std::string> vertex_names() const = 0;
    virtual std::vector<std::string> fragment_names() const = 0;
};

}  // namespace st
