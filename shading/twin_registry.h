// twin_registry.h: a TwinLibrary that twins are added to by name, the
// built-in techniques' (kernels/registry.cpp) and then a user tool's own
// (sdk/technique.h). A name is the stem of the GLSL file the twin mirrors;
// adding a name twice is refused, so a user's twin never silently replaces
// another.
#pragma once

#include <functional>
#include <map>

#include "shading/twin_library.h"

namespace st {

class TwinRegistry final : public TwinLibrary {
public:
    using VertexFactory = std::function<std::unique_ptr<VertexTwin>()>;
    using FragmentFactory = std::function<std::unique_ptr<FragmentTwin>()>;

    // Throw std::invalid_argument ("vertex twin 'name' registered twice")
    // when the name is taken, or for an empty name.
    void add_vertex(const std::string& name, VertexFactory factory);
    void add_fragment(const std::string& name, FragmentFactory factory);

    std::unique_ptr<VertexTwin> make_vertex(const std::string& name) const override;
    std::unique_ptr<FragmentTwin> make_fragment(const std::string& name) const override;
    std::vector<std::string> vertex_names() const override;
    std::vector<std::string> fragment_names() const override;

private:
    std::map<std::string, VertexFactory> vertex_;
    std::map<std::string, FragmentFactory> fragment_;
};

}  // namespace st
