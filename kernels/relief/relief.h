// relief.h: twins of the relief-mapping programs (glsl/relief/, Timonen),
// one class per GLSL file, each .cpp named after its GLSL file.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "shading/program.h"

namespace st {

class Sampler2D;

class ReliefVertex final : public VertexTwin {  // relief.vert
public:
    int varying_count() const override { return 2; }
    void bind(const Bindings& b) override { view_proj_ = b.get_mat4("view_proj"); }
    void run(const glm::vec4* attributes, VertexOut& out) const override;

private:
    glm::mat4 view_proj_{1.0f};
};

// The uniforms every relief fragment program reads.
struct ReliefLighting {
    const Sampler2D* relief_map = nullptr;  // rgb: normal, a: height
    const Sampler2D* colour_map = nullptr;
    glm::vec3 eye{0.0f}, light{0.0f};
    float ambient = 0.0f, specular = 0.0f;
    void read(const Bindings& b);
};

class NormalMappingFragment final : public FragmentProgram<NormalMappingFragment> {  // normal_mapping.frag
public:
    void bind(const Bindings& b) override { u_.read(b); }
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;

private:
    ReliefLighting u_;
};

class ReliefMappingFragment final : public FragmentProgram<ReliefMappingFragment> {  // relief_mapping.frag
public:
    void bind(const Bindings& b) override;
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;

private:
    ReliefLighting u_;
    float depth_ = 0.0f, world_depth_ = 0.0f;
    int linear_steps_ = 1, binary_steps_ = 0;
    bool secant_ = false;
};

}  // namespace st
