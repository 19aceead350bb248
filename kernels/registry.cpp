// registry.cpp: the one list of twins. Adding a technique adds lines here
// (see docs/adding-a-technique.md).
#include "kernels/registry.h"

#include <functional>
#include <map>

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

template <class T> using Factory = std::function<std::unique_ptr<T>()>;

const std::map<std::string, Factory<VertexTwin>>& vertex_twins() {
    static const std::map<std::string, Factory<VertexTwin>> twins = {
        {"interp", [] { return std::make_unique<InterpVertex>(); }},
        {"textured", [] { return std::make_unique<TexturedVertex>(); }},
        {"background", [] { return std::make_unique<BackgroundVertex>(); }},
        {"thin_slab", [] { return std::make_unique<ThinSlabVertex>(); }},
        {"thin_slab_vertex", [] { return std::make_unique<ThinSlabVertexVariant>(); }},
        {"thin_slab_host", [] { return std::make_unique<ThinSlabHostVertex>(); }},
        {"relief", [] { return std::make_unique<ReliefVertex>(); }},
        {"texture_space", [] { return std::make_unique<TextureSpaceVertex>(); }},
        {"profile", [] { return std::make_unique<ProfileVertex>(); }},
    };
    return twins;
}

const std::map<std::string, Factory<FragmentTwin>>& fragment_twins() {
    static const std::map<std::string, Factory<FragmentTwin>> twins = {
        {"interp", [] { return std::make_unique<InterpFragment>(); }},
        {"coverage", [] { return std::make_unique<CoverageFragment>(); }},
        {"textured", [] { return std::make_unique<TexturedFragment>(); }},
        {"background", [] { return std::make_unique<BackgroundFragment>(); }},
        {"thin_slab", [] { return std::make_unique<ThinSlabFragment>(); }},
        {"thin_slab_lit", [] { return std::make_unique<ThinSlabLitFragment>(); }},
        {"thin_slab_baseline", [] { return std::make_unique<ThinSlabBaselineFragment>(); }},
        {"thin_slab_sweep", [] { return std::make_unique<ThinSlabSweepFragment>(); }},
        {"loop_exit", [] { return std::make_unique<LoopExitFragment>(); }},
        {"branch_texture", [] { return std::make_unique<BranchTextureFragment>(); }},
        {"derivatives", [] { return std::make_unique<DerivativesFragment>(); }},
        {"discard", [] { return std::make_unique<DiscardFragment>(); }},
        {"non_finite", [] { return std::make_unique<NonFiniteFragment>(); }},
        {"loop_budget", [] { return std::make_unique<LoopBudgetFragment>(); }},
        {"sample_implicit", [] { return std::make_unique<SampleImplicitFragment>(); }},
        {"sample_lod", [] { return std::make_unique<SampleLodFragment>(); }},
        {"sample_bias", [] { return std::make_unique<SampleBiasFragment>(); }},
        {"sample_grad", [] { return std::make_unique<SampleGradFragment>(); }},
        {"texel_fetch", [] { return std::make_unique<TexelFetchFragment>(); }},
        {"sample_cube", [] { return std::make_unique<SampleCubeFragment>(); }},
        {"sample_cube_lod", [] { return std::make_unique<SampleCubeLodFragment>(); }},
        {"sample_cube_bias", [] { return std::make_unique<SampleCubeBiasFragment>(); }},
        {"sample_cube_grad", [] { return std::make_unique<SampleCubeGradFragment>(); }},
        {"normal_mapping", [] { return std::make_unique<NormalMappingFragment>(); }},
        {"relief_mapping", [] { return std::make_unique<ReliefMappingFragment>(); }},
        {"bloom_bright", [] { return std::make_unique<BloomBrightFragment>(); }},
        {"bloom_blur", [] { return std::make_unique<BloomBlurFragment>(); }},
        {"bloom_composite", [] { return std::make_unique<BloomCompositeFragment>(); }},
        {"two_layer", [] { return std::make_unique<TwoLayerFragment>(); }},
        {"irradiance", [] { return std::make_unique<IrradianceFragment>(); }},
        {"surface", [] { return std::make_unique<SurfaceFragment>(); }},
        {"gather", [] { return std::make_unique<GatherFragment>(); }},
        {"gather_thin", [] { return std::make_unique<GatherThinFragment>(); }},
    };
    return twins;
}

template <class T>
std::unique_ptr<T> make(const std::map<std::string, Factory<T>>& table, const std::string& name) {
    auto it = table.find(name);
    return it == table.end() ? nullptr : it->second();
}

template <class T>
std::vector<std::string> names(const std::map<std::string, Factory<T>>& table) {
    std::vector<std::string> out;
    for (const auto& [name, factory] : table) out.push_back(name);
    return out;
}

class BuiltinTwins final : public TwinLibrary {
public:
    std::unique_ptr<VertexTwin> make_vertex(const std::string& name) const override {
        return make(vertex_twins(), name);
    }
    std::unique_ptr<FragmentTwin> make_fragment(const std::string& name) const override {
        return make(fragment_twins(), name);
    }
    std::vector<std::string> vertex_names() const override { return names(vertex_twins()); }
    std::vector<std::string> fragment_names() const override { return names(fragment_twins()); }
};

}  // namespace

const TwinLibrary& builtin_twins() {
    static const BuiltinTwins library;
    return library;
}

std::unique_ptr<VertexTwin> make_vertex_twin(const std::string& name) {
    return make(vertex_twins(), name);
}
std::unique_ptr<FragmentTwin> make_fragment_twin(const std::string& name) {
    return make(fragment_twins(), name);
}
std::vector<std::string> vertex_twin_names() { return names(vertex_twins()); }
std::vector<std::string> fragment_twin_names() { return names(fragment_twins()); }

}  // namespace st
