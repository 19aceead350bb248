// registry.h: twins by name. A name here is also the stem of the GLSL file
// (glsl/<name>.vert or glsl/<name>.frag) that the twin mirrors.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "kernels/program.h"

namespace st {

// nullptr when no twin has that name.
std::unique_ptr<VertexTwin> make_vertex_twin(const std::string& name);
std::unique_ptr<FragmentTwin> make_fragment_twin(const std::string& name);

std::vector<std::string> vertex_twin_names();
std::vector<std::string> fragment_twin_names();

}  // namespace st
