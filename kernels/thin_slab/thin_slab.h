// thin_slab.h: twins of the thin-slab programs (glsl/thin_slab*.vert/.frag),
// one class per GLSL file; each .cpp is named after its GLSL file.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "shading/program.h"

namespace st {

class Sampler2D;

// Uniforms of the model, read once per draw.
struct ThinSlabUniforms {
    glm::vec3 eye{0.0f}, light{0.0f}, albedo{1.0f};
    float power = 0.0f, tau1 = 0.0f;
    void read(const Bindings& b, bool with_tau1);
};

class ThinSlabVertex final : public VertexTwin {  // thin_slab.vert
public:
    int varying_count() const override { return 3; }
    void bind(const Bindings& b) override { view_proj_ = b.get_mat4("view_proj"); }
    void run(const glm::vec4* attributes, VertexOut& out) const override;

private:
    glm::mat4 view_proj_{1.0f};
};

class ThinSlabFragment final : public FragmentProgram<ThinSlabFragment> {  // thin_slab.frag
public:
    void bind(const Bindings& b) override;
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;

private:
    ThinSlabUniforms u_;
    const Sampler2D* flag_ = nullptr;
};

class ThinSlabVertexVariant final : public VertexTwin {  // thin_slab_vertex.vert
public:
    int varying_count() const override { return 2; }
    void bind(const Bindings& b) override;
    void run(const glm::vec4* attributes, VertexOut& out) const override;

private:
    glm::mat4 view_proj_{1.0f};
    ThinSlabUniforms u_;
};

class ThinSlabHostVertex final : public VertexTwin {  // thin_slab_host.vert
public:
    int varying_count() const override { return 2; }
    void bind(const Bindings& b) override { view_proj_ = b.get_mat4("view_proj"); }
    void run(const glm::vec4* attributes, VertexOut& out) const override;

private:
    glm::mat4 view_proj_{1.0f};
};

class ThinSlabLitFragment final : public FragmentProgram<ThinSlabLitFragment> {  // thin_slab_lit.frag
public:
    void bind(const Bindings& b) override;
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;

private:
    const Sampler2D* flag_ = nullptr;
};

class ThinSlabBaselineFragment final : public FragmentProgram<ThinSlabBaselineFragment> {  // thin_slab_baseline.frag
public:
    void bind(const Bindings& b) override;
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;

private:
    ThinSlabUniforms u_;
    const Sampler2D* flag_ = nullptr;
};

class ThinSlabSweepFragment final : public FragmentProgram<ThinSlabSweepFragment> {  // thin_slab_sweep.frag
public:
    void bind(const Bindings& b) override;
    uint32_t inputs_read() const override { return 0; }
    Vec4 main(const Fragment& frag) const;

private:
    const Sampler2D* inputs_ = nullptr;
};

}  // namespace st
