// conformance.h: twins of the conformance programs (glsl/conformance/*.frag,
// and builtins_vertex.vert), one class per GLSL file, each .cpp named after
// its GLSL file. Their vertex stage is the textured one
// (kernels/triangles/textured.h) unless a scene names another: varying 0 is
// the colour, varying 1 the uv.
#pragma once

#include <array>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "shading/program.h"

namespace st {

class Sampler2D;
class SamplerCube;

class LoopExitFragment final : public FragmentProgram<LoopExitFragment> {  // loop_exit.frag
public:
    void bind(const Bindings& b) override;
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;

private:
    const Sampler2D* tex_ = nullptr;
    int steps_ = 0;
    glm::vec2 dir_{0.0f};
    float threshold_ = 0.0f;
};

class ParallaxLoopFragment final : public FragmentProgram<ParallaxLoopFragment> {  // parallax_loop.frag
public:
    void bind(const Bindings& b) override;
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;

private:
    const Sampler2D* depth_map_ = nullptr;
    const Sampler2D* colour_map_ = nullptr;
    float height_scale_ = 0.0f;
    glm::vec3 light_dir_{0.0f};
};

class BranchTextureFragment final : public FragmentProgram<BranchTextureFragment> {  // branch_texture.frag
public:
    void bind(const Bindings& b) override;
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;

private:
    const Sampler2D* tex_a_ = nullptr;
    const Sampler2D* tex_b_ = nullptr;
    float split_ = 0.0f;
};

class DerivativesFragment final : public FragmentProgram<DerivativesFragment> {  // derivatives.frag
public:
    void bind(const Bindings& b) override { scale_ = b.get_float("scale"); }
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;

private:
    float scale_ = 0.0f;
};

class DiscardFragment final : public FragmentProgram<DiscardFragment> {  // discard.frag
public:
    void bind(const Bindings& b) override { steps_ = b.get_int("steps"); }
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;

private:
    int steps_ = 0;
};

class NonFiniteFragment final : public FragmentProgram<NonFiniteFragment> {  // non_finite.frag
public:
    void bind(const Bindings& b) override { zero_ = b.get_float("zero"); }
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;

private:
    float zero_ = 0.0f;
};

class UniformBlockFragment final : public FragmentProgram<UniformBlockFragment> {  // uniform_block.frag
public:
    void bind(const Bindings& b) override;
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;

private:
    struct Light {  // the block Light, instance light
        glm::vec3 colour{0.0f};
        float power = 0.0f;
        glm::vec2 offset{0.0f};
    } light_;
    glm::vec4 tint_{0.0f};
    std::array<float, 3> gain_{};
    int count_ = 0;
};

class UniformTypesFragment final : public FragmentProgram<UniformTypesFragment> {  // uniform_types.frag
public:
    void bind(const Bindings& b) override;
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;

private:
    struct Light {  // GLSL struct Light
        glm::vec3 colour{0.0f};
        float power = 0.0f;
        int kind = 0;
        bool on = false;
    };
    struct Mixed {  // the std140 block Mixed, instance mixed
        float a = 0.0f;
        glm::vec3 b{0.0f};
        int c = 0;
        glm::mat3 d{0.0f};
        bool e = false;
        glm::uvec2 f{0u};
        std::array<float, 3> g{};
        glm::mat2x3 h{0.0f};
    };
    std::array<glm::vec3, 4> palette_{};
    std::array<Light, 2> lights_{};
    int count_ = 0;
    uint32_t mask_ = 0;
    bool flip_ = false;
    glm::bvec2 axes_{false};
    glm::ivec3 steps_{0};
    glm::uvec2 bits_{0u};
    glm::mat2 rot_{0.0f};
    glm::mat3 basis_{0.0f};
    glm::mat2x3 skew_{0.0f};
    glm::mat3x2 squash_{0.0f};
    glm::mat4x3 affine_{0.0f};
    Mixed mixed_;
};

// outputs.frag and outputs_two.frag: several fragment outputs, one per
// target of the pass; main() returns one value per location.
class OutputsFragment final : public FragmentProgram<OutputsFragment> {  // outputs.frag
public:
    void bind(const Bindings& b) override;
    uint32_t inputs_read() const override;
    FragmentOutputs<3> main(const Fragment& frag) const;

private:
    float exposure_ = 0.0f, cut_ = 0.0f;
};

class OutputsTwoFragment final : public FragmentProgram<OutputsTwoFragment> {  // outputs_two.frag
public:
    void bind(const Bindings& b) override { exposure_ = b.get<float>("exposure"); }
    uint32_t inputs_read() const override;
    FragmentOutputs<2> main(const Fragment& frag) const;

private:
    float exposure_ = 0.0f;
};

// unlocated.vert and unlocated.frag: GLSL 3.30 without locations; the
// twins name their slots, by which every run matches them to the GLSL.
class UnlocatedVertex final : public VertexTwin {  // unlocated.vert
public:
    int varying_count() const override { return 2; }
    SlotNames output_names() const override { return {"vColour", "vUV"}; }
    void run(const glm::vec4* attributes, VertexOut& out) const override;
};

class UnlocatedFragment final : public FragmentProgram<UnlocatedFragment> {  // unlocated.frag
public:
    void bind(const Bindings& b) override { tint_ = b.get<glm::vec3>("tint"); }
    SlotNames input_names() const override { return {"vColour", "vUV"}; }
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;

private:
    glm::vec3 tint_{0.0f};
};

// unlocated_outputs.frag: two outputs without locations, bound by name;
// main() returns them in the order of the locations the scene binds.
class UnlocatedOutputsFragment final : public FragmentProgram<UnlocatedOutputsFragment> {  // unlocated_outputs.frag
public:
    void bind(const Bindings& b) override { tint_ = b.get<glm::vec3>("tint"); }
    SlotNames input_names() const override { return {"vColour", "vUV"}; }
    uint32_t inputs_read() const override;
    FragmentOutputs<2> main(const Fragment& frag) const;

private:
    glm::vec3 tint_{0.0f};
};

// builtins_vertex.vert: the built-ins in the vertex stage, per cell.
class BuiltinsVertex final : public VertexTwin {  // builtins_vertex.vert
public:
    int varying_count() const override { return 2; }
    void bind(const Bindings& b) override { group_ = b.get_int("group"); }
    void run(const glm::vec4* attributes, VertexOut& out) const override;

private:
    static float value(int index, int k);
    int group_ = 0;
};

class VertexResultFragment final : public FragmentProgram<VertexResultFragment> {  // vertex_result.frag
public:
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;
};

// varyings.vert and .frag: an input of each interpolation qualifier,
// through triangles the view volume clips.
class VaryingsVertex final : public VertexTwin {  // varyings.vert
public:
    int varying_count() const override { return 5; }
    void bind(const Bindings& b) override { reach_ = b.get_float("reach"); }
    void run(const glm::vec4* attributes, VertexOut& out) const override;

private:
    float reach_ = 1.0f;
};

class VaryingsFragment final : public FragmentProgram<VaryingsFragment> {  // varyings.frag
public:
    void bind(const Bindings& b) override { show_ = b.get_int("show"); }
    uint32_t inputs_read() const override;
    Interpolations interpolations() const override;
    Vec4 main(const Fragment& frag) const;

private:
    int show_ = 0;
};

// A built-in family's program: the uniform `group` picks which functions
// it writes (one scene each), and its inputs come from the pixel alone.
template <class Derived> class BuiltinsFragment : public FragmentProgram<Derived> {
public:
    void bind(const Bindings& b) override { group_ = b.get_int("group"); }
    uint32_t inputs_read() const override { return 0; }

protected:
    int group_ = 0;
};

class BuiltinsExponentialFragment final : public BuiltinsFragment<BuiltinsExponentialFragment> {  // builtins_exponential.frag
public:
    Vec4 main(const Fragment& frag) const;
};

class BuiltinsCommonFragment final : public BuiltinsFragment<BuiltinsCommonFragment> {  // builtins_common.frag
public:
    Vec4 main(const Fragment& frag) const;
};

class BuiltinsTrigonometryFragment final : public BuiltinsFragment<BuiltinsTrigonometryFragment> {  // builtins_trigonometry.frag
public:
    Vec4 main(const Fragment& frag) const;
};

class BuiltinsGeometricFragment final : public BuiltinsFragment<BuiltinsGeometricFragment> {  // builtins_geometric.frag
public:
    Vec4 main(const Fragment& frag) const;
};

class BuiltinsIntegerFragment final : public BuiltinsFragment<BuiltinsIntegerFragment> {  // builtins_integer.frag
public:
    Vec4 main(const Fragment& frag) const;
};

class BuiltinsMatrixFragment final : public BuiltinsFragment<BuiltinsMatrixFragment> {  // builtins_matrix.frag
public:
    Vec4 main(const Fragment& frag) const;
};

class BuiltinsDoubleFragment final : public FragmentProgram<BuiltinsDoubleFragment> {  // builtins_double.frag
public:
    void bind(const Bindings& b) override;
    uint32_t inputs_read() const override { return 0; }
    Vec4 main(const Fragment& frag) const;

private:
    int group_ = 0;
    double scale_ = 0.0;  // the double uniforms group 8 reads
    glm::dvec3 offset_{};
    glm::dmat3 basis_{};
    glm::dvec4 corner_{};
};

class CompilerRewritesFragment final : public FragmentProgram<CompilerRewritesFragment> {  // compiler_rewrites.frag
public:
    void bind(const Bindings& b) override;
    uint32_t inputs_read() const override { return 0; }
    Vec4 main(const Fragment& frag) const;

private:
    int group_ = 0;
    bool naive_ = false;  // the GLSL as written (twin only), to show the scene fails with it
};

class ProbeDemoFragment final : public FragmentProgram<ProbeDemoFragment> {  // probe_demo.frag
public:
    void bind(const Bindings& b) override { twin_breaks_ = b.get_int("twin_breaks"); }
    uint32_t inputs_read() const override { return 0; }
    Vec4 main(const Fragment& frag) const;

private:
    int twin_breaks_ = 0;  // twin only: which rewrite to write as the GLSL reads (0: none)
};

class LoopBudgetFragment final : public FragmentProgram<LoopBudgetFragment> {  // loop_budget.frag
public:
    void bind(const Bindings& b) override;
    uint32_t inputs_read() const override { return 0; }
    Vec4 main(const Fragment& frag) const;

private:
    int long_steps_ = 0, short_steps_ = 0;
    glm::vec2 slow_a_{0.0f}, slow_b_{0.0f};
};

class SampleImplicitFragment final : public FragmentProgram<SampleImplicitFragment> {  // sample_implicit.frag
public:
    void bind(const Bindings& b) override { tex_ = &b.sampler("tex"); }
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;

private:
    const Sampler2D* tex_ = nullptr;
};

class SampleLodFragment final : public FragmentProgram<SampleLodFragment> {  // sample_lod.frag
public:
    void bind(const Bindings& b) override;
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;

private:
    const Sampler2D* tex_ = nullptr;
    float lod_min_ = 0.0f, lod_max_ = 0.0f;
};

class SampleBiasFragment final : public FragmentProgram<SampleBiasFragment> {  // sample_bias.frag
public:
    void bind(const Bindings& b) override;
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;

private:
    const Sampler2D* tex_ = nullptr;
    float lod_min_ = 0.0f, lod_max_ = 0.0f;
};

class SampleGradFragment final : public FragmentProgram<SampleGradFragment> {  // sample_grad.frag
public:
    void bind(const Bindings& b) override {
        tex_ = &b.sampler("tex");
        grad_scale_ = b.get_float("grad_scale");
    }
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;

private:
    const Sampler2D* tex_ = nullptr;
    float grad_scale_ = 0.0f;
};

class TexelFetchFragment final : public FragmentProgram<TexelFetchFragment> {  // texel_fetch.frag
public:
    void bind(const Bindings& b) override { tex_ = &b.sampler("tex"); }
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;

private:
    const Sampler2D* tex_ = nullptr;
};

class TextureInputsFragment final : public FragmentProgram<TextureInputsFragment> {  // texture_inputs.frag
public:
    void bind(const Bindings& b) override { inputs_ = &b.sampler("inputs"); }
    uint32_t inputs_read() const override { return 0; }
    Vec4 main(const Fragment& frag) const;

private:
    const Sampler2D* inputs_ = nullptr;
};

class SampleCubeFragment final : public FragmentProgram<SampleCubeFragment> {  // sample_cube.frag
public:
    void bind(const Bindings& b) override { env_ = &b.sampler_cube("env"); }
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;

private:
    const SamplerCube* env_ = nullptr;
};

class SampleCubeLodFragment final : public FragmentProgram<SampleCubeLodFragment> {  // sample_cube_lod.frag
public:
    void bind(const Bindings& b) override;
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;

private:
    const SamplerCube* env_ = nullptr;
    float lod_min_ = 0.0f, lod_max_ = 0.0f;
};

class SampleCubeBiasFragment final : public FragmentProgram<SampleCubeBiasFragment> {  // sample_cube_bias.frag
public:
    void bind(const Bindings& b) override;
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;

private:
    const SamplerCube* env_ = nullptr;
    float lod_min_ = 0.0f, lod_max_ = 0.0f;
};

class SampleCubeGradFragment final : public FragmentProgram<SampleCubeGradFragment> {  // sample_cube_grad.frag
public:
    void bind(const Bindings& b) override {
        env_ = &b.sampler_cube("env");
        grad_scale_ = b.get_float("grad_scale");
    }
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;

private:
    const SamplerCube* env_ = nullptr;
    float grad_scale_ = 0.0f;
};

}  // namespace st
