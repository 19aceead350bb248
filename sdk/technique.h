// technique.h: the one header a user's technique includes to join a
// shadertwin tool (docs/adding-a-technique.md walks through it).
//
// A technique is GLSL programs, their C++ twins and scene kinds. In CMake,
//     shadertwin_add_technique(NAME glow TOOL glowtwin GLSL ... TWINS ... SCENES ... GOLDEN ...)
// builds the twins into the tool `glowtwin`, which has every shadertwin
// command for the technique's scenes as well as the built-in ones. In C++,
// the technique says which twin mirrors which GLSL file and which function
// builds each scene kind:
//
//     SHADERTWIN_TECHNIQUE(glow, technique) {
//         technique.vertex_twin<GlowVertex>("glow");      // glsl .../glow.vert
//         technique.fragment_twin<GlowFragment>("glow");  // glsl .../glow.frag
//         technique.scene_kind("glow", build_glow_scene);
//     }
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "frame/frame.h"
#include "scene/json_reader.h"
#include "scene/scene_kinds.h"
#include "shading/program.h"

namespace st {

class TechniqueRegistry {
public:
    explicit TechniqueRegistry(std::string technique) : technique_(std::move(technique)) {}

    // The twin of <name>.vert or <name>.frag among the technique's GLSL files.
    template <class Twin> void vertex_twin(const std::string& name) {
        add_vertex(name, [] { return std::unique_ptr<VertexTwin>(std::make_unique<Twin>()); });
    }
    template <class Twin> void fragment_twin(const std::string& name) {
        add_fragment(name, [] { return std::unique_ptr<FragmentTwin>(std::make_unique<Twin>()); });
    }
    // Scenes whose "kind" is `kind` are built by `builder` (scene/scene_kinds.h).
    void scene_kind(const std::string& kind, SceneBuilder builder);

    void add_vertex(const std::string& name, std::function<std::unique_ptr<VertexTwin>()> factory);
    void add_fragment(const std::string& name, std::function<std::unique_ptr<FragmentTwin>()> factory);

    const std::string& technique() const { return technique_; }
    const std::vector<std::string>& vertex_names() const { return vertex_names_; }
    const std::vector<std::string>& fragment_names() const { return fragment_names_; }

private:
    std::string technique_;
    std::vector<std::string> vertex_names_, fragment_names_;
};

// What shadertwin_add_technique() knows of a technique, declared by the
// source file it generates; the tool takes every declaration in when it
// starts (sdk/tool.h), in order of name.
struct TechniqueDeclaration {
    using Register = void (*)(TechniqueRegistry&);
    TechniqueDeclaration(std::string name, Register register_fn, std::vector<std::string> glsl,
                         std::vector<std::string> scenes, std::string golden_file, std::string data_dir);

    std::string name;
    Register register_fn;
    std::vector<std::string> glsl;    // .vert, .frag and .glsl files, absolute
    std::vector<std::string> scenes;  // .json files and folders, absolute
    std::string golden_file;          // where `golden` keeps its scenes' hashes
    std::string data_dir;             // the installed share/shadertwin of the package it was built against
};

}  // namespace st

// Defines the technique's registration function; see the example above.
#define SHADERTWIN_TECHNIQUE(name, registry) void shadertwin_technique_##name(::st::TechniqueRegistry& registry)
