// wrap.h: twins of glsl/wrap.vert and glsl/wrap.frag, and the scene kind
// that draws them.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "scene/scene_kinds.h"
#include "shading/program.h"

class WrapVertex final : public st::VertexTwin {
public:
    int varying_count() const override { return 1; }
    void bind(const st::Bindings& b) override { mvp_ = b.get_mat4("mvp"); }
    void run(const glm::vec4* attributes, st::VertexOut& out) const override;

private:
    glm::mat4 mvp_{1.0f};
};

class WrapFragment final : public st::FragmentProgram<WrapFragment> {
public:
    void bind(const st::Bindings& b) override;
    uint32_t inputs_read() const override;
    st::Vec4 main(const st::Fragment& frag) const;

private:
    glm::vec3 light_dir_{0.0f}, albedo_{0.0f}, scatter_tint_{0.0f};
    float wrap_ = 0.0f;
};

// The "wrap" scene kind: a unit sphere seen from +z, lit by wrap.frag.
st::Frame build_wrap_scene(st::JsonReader& scene, st::SceneSize size);
