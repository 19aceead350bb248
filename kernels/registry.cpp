// registry.cpp: the one list of the built-in twins. Adding a built-in
// technique adds lines here (see docs/adding-a-technique.md); a user's tool
// adds its own to the same registry (sdk/technique.h).
#include "kernels/registry.h"

#include "kernels/conformance/conformance.h"
#include "kernels/thin_slab/background.h"
#include "kernels/harness/coverage.h"
#include "kernels/profile/profile.h"
#include "kernels/relief/relief.h"
#include "kernels/triangles/interp.h"
#include "kernels/relief/bloom.h"
#include "kernels/triangles/textured.h"
#include "kernels/thin_slab/thin_slab.h"

namespace st {

namespace {

void add_builtin_twins(TwinRegistry& r) {
    r.add_vertex("interp", [] { return std::make_unique<InterpVertex>(); });
    r.add_vertex("textured", [] { return std::make_unique<TexturedVertex>(); });
    r.add_vertex("background", [] { return std::make_unique<BackgroundVertex>(); });
    r.add_vertex("thin_slab", [] { return std::make_unique<ThinSlabVertex>(); });
    r.add_vertex("thin_slab_vertex", [] { return std::make_unique<ThinSlabVertexVariant>(); });
    r.add_vertex("thin_slab_host", [] { return std::make_unique<ThinSlabHostVertex>(); });
    r.add_vertex("relief", [] { return std::make_unique<ReliefVertex>(); });
    r.add_vertex("texture_space", [] { return std::make_unique<TextureSpaceVertex>(); });
    r.add_vertex("profile", [] { return std::make_unique<ProfileVertex>(); });
    r.add_vertex("builtins_vertex", [] { return std::make_unique<BuiltinsVertex>(); });
    r.add_vertex("varyings", [] { return std::make_unique<VaryingsVertex>(); });

    r.add_fragment("interp", [] { return std::make_unique<InterpFragment>(); });
    r.add_fragment("coverage", [] { return std::make_unique<CoverageFragment>(); });
    r.add_fragment("textured", [] { return std::make_unique<TexturedFragment>(); });
    r.add_fragment("background", [] { return std::make_unique<BackgroundFragment>(); });
    r.add_fragment("thin_slab", [] { return std::make_unique<ThinSlabFragment>(); });
    r.add_fragment("thin_slab_lit", [] { return std::make_unique<ThinSlabLitFragment>(); });
    r.add_fragment("thin_slab_baseline", [] { return std::make_unique<ThinSlabBaselineFragment>(); });
    r.add_fragment("thin_slab_sweep", [] { return std::make_unique<ThinSlabSweepFragment>(); });
    r.add_fragment("loop_exit", [] { return std::make_unique<LoopExitFragment>(); });
    r.add_fragment("parallax_loop", [] { return std::make_unique<ParallaxLoopFragment>(); });
    r.add_fragment("branch_texture", [] { return std::make_unique<BranchTextureFragment>(); });
    r.add_fragment("derivatives", [] { return std::make_unique<DerivativesFragment>(); });
    r.add_fragment("discard", [] { return std::make_unique<DiscardFragment>(); });
    r.add_fragment("non_finite", [] { return std::make_unique<NonFiniteFragment>(); });
    r.add_fragment("builtins_exponential", [] { return std::make_unique<BuiltinsExponentialFragment>(); });
    r.add_fragment("builtins_common", [] { return std::make_unique<BuiltinsCommonFragment>(); });
    r.add_fragment("builtins_trigonometry", [] { return std::make_unique<BuiltinsTrigonometryFragment>(); });
    r.add_fragment("builtins_geometric", [] { return std::make_unique<BuiltinsGeometricFragment>(); });
    r.add_fragment("builtins_integer", [] { return std::make_unique<BuiltinsIntegerFragment>(); });
    r.add_fragment("builtins_double", [] { return std::make_unique<BuiltinsDoubleFragment>(); });
    r.add_fragment("builtins_matrix", [] { return std::make_unique<BuiltinsMatrixFragment>(); });
    r.add_fragment("compiler_rewrites", [] { return std::make_unique<CompilerRewritesFragment>(); });
    r.add_fragment("vertex_result", [] { return std::make_unique<VertexResultFragment>(); });
    r.add_fragment("varyings", [] { return std::make_unique<VaryingsFragment>(); });
    r.add_fragment("uniform_block", [] { return std::make_unique<UniformBlockFragment>(); });
    r.add_fragment("uniform_types", [] { return std::make_unique<UniformTypesFragment>(); });
    r.add_fragment("outputs", [] { return std::make_unique<OutputsFragment>(); });
    r.add_fragment("outputs_two", [] { return std::make_unique<OutputsTwoFragment>(); });
    r.add_vertex("unlocated", [] { return std::make_unique<UnlocatedVertex>(); });
    r.add_fragment("unlocated", [] { return std::make_unique<UnlocatedFragment>(); });
    r.add_fragment("unlocated_outputs", [] { return std::make_unique<UnlocatedOutputsFragment>(); });
    r.add_fragment("probe_demo", [] { return std::make_unique<ProbeDemoFragment>(); });
    r.add_fragment("loop_budget", [] { return std::make_unique<LoopBudgetFragment>(); });
    r.add_fragment("sample_implicit", [] { return std::make_unique<SampleImplicitFragment>(); });
    r.add_fragment("sample_lod", [] { return std::make_unique<SampleLodFragment>(); });
    r.add_fragment("sample_bias", [] { return std::make_unique<SampleBiasFragment>(); });
    r.add_fragment("sample_grad", [] { return std::make_unique<SampleGradFragment>(); });
    r.add_fragment("texel_fetch", [] { return std::make_unique<TexelFetchFragment>(); });
    r.add_fragment("texture_inputs", [] { return std::make_unique<TextureInputsFragment>(); });
    r.add_fragment("sample_cube", [] { return std::make_unique<SampleCubeFragment>(); });
    r.add_fragment("sample_cube_lod", [] { return std::make_unique<SampleCubeLodFragment>(); });
    r.add_fragment("sample_cube_bias", [] { return std::make_unique<SampleCubeBiasFragment>(); });
    r.add_fragment("sample_cube_grad", [] { return std::make_unique<SampleCubeGradFragment>(); });
    r.add_fragment("normal_mapping", [] { return std::make_unique<NormalMappingFragment>(); });
    r.add_fragment("relief_mapping", [] { return std::make_unique<ReliefMappingFragment>(); });
    r.add_fragment("bloom_bright", [] { return std::make_unique<BloomBrightFragment>(); });
    r.add_fragment("bloom_blur", [] { return std::make_unique<BloomBlurFragment>(); });
    r.add_fragment("bloom_composite", [] { return std::make_unique<BloomCompositeFragment>(); });
    r.add_fragment("two_layer", [] { return std::make_unique<TwoLayerFragment>(); });
    r.add_fragment("irradiance", [] { return std::make_unique<IrradianceFragment>(); });
    r.add_fragment("surface", [] { return std::make_unique<SurfaceFragment>(); });
    r.add_fragment("gather", [] { return std::make_unique<GatherFragment>(); });
    r.add_fragment("gather_thin", [] { return std::make_unique<GatherThinFragment>(); });
}

}  // namespace

TwinRegistry& twin_registry() {
    static TwinRegistry registry = [] {
        TwinRegistry r;
        add_builtin_twins(r);
        return r;
    }();
    return registry;
}

const TwinLibrary& twins() { return twin_registry(); }

std::unique_ptr<VertexTwin> make_vertex_twin(const std::string& name) { return twins().make_vertex(name); }
std::unique_ptr<FragmentTwin> make_fragment_twin(const std::string& name) { return twins().make_fragment(name); }
std::vector<std::string> vertex_twin_names() { return twins().vertex_names(); }
std::vector<std::string> fragment_twin_names() { return twins().fragment_names(); }

}  // namespace st
