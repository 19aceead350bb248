// technique.cpp: see technique.h.
#include "sdk/technique.h"

#include <stdexcept>

#include "kernels/registry.h"
#include "scene/input_error.h"
#include "sdk/declarations.h"

namespace st {

void TechniqueRegistry::scene_kind(const std::string& kind, SceneBuilder builder) {
    try {
        register_scene_kind(kind, std::move(builder));
    } catch (const InputError& e) {
        throw InputError("technique " + technique_ + ": " + e.what());
    }
}

void TechniqueRegistry::add_vertex(const std::string& name, std::function<std::unique_ptr<VertexTwin>()> factory) {
    try {
        twin_registry().add_vertex(name, std::move(factory));
    } catch (const std::invalid_argument& e) {
        throw InputError("technique " + technique_ + ": " + e.what());
    }
    vertex_names_.push_back(name);
}

void TechniqueRegistry::add_fragment(const std::string& name,
                                     std::function<std::unique_ptr<FragmentTwin>()> factory) {
    try {
        twin_registry().add_fragment(name, std::move(factory));
    } catch (const std::invalid_argument& e) {
        throw InputError("technique " + technique_ + ": " + e.what());
    }
    fragment_names_.push_back(name);
}

TechniqueDeclaration::TechniqueDeclaration(std::string name_in, Register register_in, std::vector<std::string> glsl_in,
                                           std::vector<std::string> scenes_in, std::string golden_in,
                                           std::string data_dir_in)
    : name(std::move(name_in)),
      register_fn(register_in),
      glsl(std::move(glsl_in)),
      scenes(std::move(scenes_in)),
      golden_file(std::move(golden_in)),
      data_dir(std::move(data_dir_in)) {
    declared_techniques().push_back(this);
}

std::vector<const TechniqueDeclaration*>& declared_techniques() {
    static std::vector<const TechniqueDeclaration*> list;
    return list;
}

}  // namespace st
