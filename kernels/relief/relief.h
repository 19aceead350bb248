// relief.h: twins of the relief-mapping programs (glsl/relief/, Timonen),
// one class per GLSL file, each .cpp named after its GLSL file.
#pragma once

#include <memory>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "shading/program.h"

namespace st {

class Sampler2D;
class SamplerCube;

// A replacement for the relief searches, for measuring only (the relief
// sweep and `quality: auto`, app/quality/relief_exact.h; GL never sees
// it): the exact answer that relief::trace_segment approximates, per lane,
// on the levels the search's reads would blend. bind() is called from the
// program's bind, once for each height map the program searches.
class ReliefIntersector {
public:
    virtual ~ReliefIntersector() = default;
    virtual void bind(const Sampler2D& map) = 0;
    // The first s in [0, 1] with side * (a + dh s) <= side * h(uv + offset s),
    // h the map's alpha as textureGrad(map, ., dx, dy) reads it; `hit` where
    // there is one, else s = 1. Lanes in `leaving` start at the crossing
    // they leave, which does not count. Only the `active` lanes are traced.
    virtual Float first_crossing(const Sampler2D& map, const Vec2& uv, const Vec2& offset, Float a, Float dh,
                                 Float side, const Vec2& dx, const Vec2& dy, Mask leaving, Mask active,
                                 Mask& hit) const = 0;
};

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
    ReliefMappingFragment() = default;
    // With an intersector, its crossing replaces the search (CPU only).
    explicit ReliefMappingFragment(std::shared_ptr<ReliefIntersector> exact) : exact_(std::move(exact)) {}
    void bind(const Bindings& b) override;
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;

private:
    ReliefLighting u_;
    float depth_ = 0.0f, world_depth_ = 0.0f;
    int linear_steps_ = 1, min_linear_steps_ = 0, binary_steps_ = 0;
    bool secant_ = false;
    int ulp_perturbation_ = 0;  // the condition map's, CPU only (relief_search.h)
    // The sweep's measuring modes, CPU only (relief_mapping_frag.cpp).
    bool output_hit_ = false;
    std::shared_ptr<ReliefIntersector> exact_;
};

class TwoLayerFragment final : public FragmentProgram<TwoLayerFragment> {  // two_layer.frag
public:
    TwoLayerFragment() = default;
    // With an intersector, its crossings replace every search (CPU only).
    explicit TwoLayerFragment(std::shared_ptr<ReliefIntersector> exact) : exact_(std::move(exact)) {}
    void bind(const Bindings& b) override;
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;

private:
    Vec3 surviving(Float d) const;
    Vec3 light_occlusion(Exec& exec, const Vec2& uv, Float z, const Vec3& l, const Vec2& dx, const Vec2& dy) const;
    Vec3 shade_solid(Exec& exec, const Vec2& uv, const Vec3& pos, Float z, const Vec3& to_viewer, const Vec2& dx,
                     const Vec2& dy) const;
    // relief::trace_segment, or the intersector's crossing in its place.
    Float trace(Exec& exec, const Sampler2D& map, const Vec2& uv, const Vec2& offset, Float a, Float dh, Float side,
                const Vec2& dx, const Vec2& dy, bool secant, Mask& hit, Mask leaving = Mask(false)) const;

    ReliefLighting u_;
    const Sampler2D* liquid_map_ = nullptr;
    const SamplerCube* environment_ = nullptr;
    float depth_ = 0.0f, liquid_depth_ = 0.0f, world_per_uv_ = 0.0f, ior_ = 1.0f;
    int linear_steps_ = 1, binary_steps_ = 0;
    bool secant_ = false;
    bool occlusion_ = false, absorption_ = false;
    int max_crossings_ = 0;
    float shadow_bias_ = 0.0f;
    glm::vec3 half_distance_{1.0f};
    float liquid_specular_ = 0.0f;
    bool intensify_ = false;
    bool planar_ = false;  // planar local reflections
    float plane_height_ = 0.5f;
    int ulp_perturbation_ = 0;  // the condition map's, CPU only (relief_search.h)
    std::shared_ptr<ReliefIntersector> exact_;
};

}  // namespace st
