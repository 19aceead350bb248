// registry.h: the twins a tool can run, by name. A name is also the stem of
// the GLSL file it mirrors (glsl/<technique>/<name>.vert or .frag), and a
// built-in twin sits beside it in kernels/<technique>/. The registry starts
// with the built-in techniques; a user's tool adds its own before any
// command runs (sdk/technique.h).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "shading/twin_registry.h"

namespace st {

// The one registry of twins, for CpuRenderer and the tools.
TwinRegistry& twin_registry();
const TwinLibrary& twins();

// Shorthands for twins(): nullptr when no twin has that name.
std::unique_ptr<VertexTwin> make_vertex_twin(const std::string& name);
std::unique_ptr<FragmentTwin> make_fragment_twin(const std::string& name);

std::vector<std::string> vertex_twin_names();
std::vector<std::string> fragment_twin_names();

}  // namespace st
