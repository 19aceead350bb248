// registry.h: the twins of the built-in techniques, by name. A name here is
// also the stem of the GLSL file it mirrors (glsl/<technique>/<name>.vert or
// .frag), and the twin sits beside it in kernels/<technique>/.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "shading/twin_library.h"

namespace st {

// The one library of built-in twins, for CpuRenderer and the tools.
const TwinLibrary& builtin_twins();

// Shorthands for builtin_twins(): nullptr when no twin has that name.
std::unique_ptr<VertexTwin> make_vertex_twin(const std::string& name);
std::unique_ptr<FragmentTwin> make_fragment_twin(const std::string& name);

std::vector<std::string> vertex_twin_names();
std::vector<std::string> fragment_twin_names();

}  // namespace st
