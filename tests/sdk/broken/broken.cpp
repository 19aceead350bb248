// broken.cpp: twins of broken.vert and broken.frag, a scene kind, and a
// registration that goes wrong as SHADERTWIN_TEST_BREAK says.
#include <cstdlib>
#include <string>

#include "scene/scene_kinds.h"
#include "sdk/technique.h"
#include "shading/program.h"

namespace {

class BrokenVertex final : public st::VertexTwin {
public:
    int varying_count() const override { return 0; }
    void run(const glm::vec4* attributes, st::VertexOut& out) const override { out.position = attributes[0]; }
};

class BrokenFragment final : public st::FragmentProgram<BrokenFragment> {
public:
    uint32_t inputs_read() const override { return 0; }
    st::Vec4 main(const st::Fragment&) const {
        return st::Vec4(st::Float(1.0f), st::Float(0.5f), st::Float(0.25f), st::Float(1.0f));
    }
};

// A twin that disagrees with broken.frag, for compare's failure path.
class WrongFragment final : public st::FragmentProgram<WrongFragment> {
public:
    uint32_t inputs_read() const override { return 0; }
    st::Vec4 main(const st::Fragment&) const {
        return st::Vec4(st::Float(1.0f), st::Float(0.5f), st::Float(0.5f), st::Float(1.0f));
    }
};

st::Frame build_broken_scene(st::JsonReader&, st::SceneSize size) {
    st::DrawCall draw;
    draw.vertex = draw.fragment = "broken";
    draw.vertices.attribute_count = 1;
    draw.vertices.data = {{-1, -1, 0, 1}, {1, -1, 0, 1}, {0, 1, 0, 1}};
    draw.indices = {0, 1, 2};
    st::Pass pass;
    pass.width = size.width;
    pass.height = size.height;
    pass.draws.push_back(std::move(draw));
    st::Frame frame;
    frame.passes.push_back(std::move(pass));
    return frame;
}

}  // namespace

SHADERTWIN_TECHNIQUE(broken, technique) {
    const char* env = std::getenv("SHADERTWIN_TEST_BREAK");
    const std::string how = env ? env : "";
    technique.vertex_twin<BrokenVertex>("broken");
    if (how == "twin-differs") technique.fragment_twin<WrongFragment>("broken");
    else technique.fragment_twin<BrokenFragment>("broken");
    technique.scene_kind("broken", build_broken_scene);
    if (how == "twin-twice") technique.fragment_twin<BrokenFragment>("broken");
    if (how == "builtin-twin") technique.vertex_twin<BrokenVertex>("interp");
    if (how == "kind-twice") technique.scene_kind("triangles", build_broken_scene);
    if (how == "no-builder") technique.scene_kind("nothing", nullptr);
    if (how == "no-glsl") technique.fragment_twin<BrokenFragment>("ghost");
}
