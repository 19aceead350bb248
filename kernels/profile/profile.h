// profile.h: twins of the diffusion-profile programs (glsl/profile/, Donner
// and Jensen Sec. 3), one class per GLSL file, each .cpp named after it.
// The passes: irradiance and surface draw the mesh in texture space
// (texture_space.vert), the gather draws it from the camera (profile.vert).
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "shading/program.h"

namespace st {

class Sampler2D;

class TextureSpaceVertex final : public VertexTwin {  // texture_space.vert
public:
    int varying_count() const override { return 2; }
    void run(const glm::vec4* attributes, VertexOut& out) const override;
};

class ProfileVertex final : public VertexTwin {  // profile.vert
public:
    int varying_count() const override { return 3; }
    void bind(const Bindings& b) override { view_proj_ = b.get_mat4("view_proj"); }
    void run(const glm::vec4* attributes, VertexOut& out) const override;

private:
    glm::mat4 view_proj_{1.0f};
};

class IrradianceFragment final : public FragmentProgram<IrradianceFragment> {  // irradiance.frag
public:
    void bind(const Bindings& b) override;
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;

private:
    glm::vec3 light_direction_{0.0f}, light_irradiance_{0.0f};
    float eta_ = 1.0f, back_offset_ = 0.0f;
    bool rough_ = false;
    const Sampler2D* rho_dt_ = nullptr;
    glm::vec4 spot_{0.0f}, edge_{0.0f};
};

class SurfaceFragment final : public FragmentProgram<SurfaceFragment> {  // surface.frag
public:
    void bind(const Bindings& b) override;
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;

private:
    int channel_ = 0;
    const Sampler2D* thickness_map_ = nullptr;
    float displacement_ = 0.0f;
};

// The uniforms of profile_gather.glsl.
struct GatherInputs {
    const Sampler2D* irradiance = nullptr;
    const Sampler2D* irradiance_back = nullptr;  // gather_thin only
    const Sampler2D* position_area = nullptr;
    const Sampler2D* surface_normal = nullptr;
    const Sampler2D* profile_R = nullptr;
    const Sampler2D* profile_T = nullptr;
    const Sampler2D* pattern = nullptr;
    int samples = 0;
    float r_max = 1.0f, profile_size = 2.0f, texel_uv = 1.0f;
    // The rough boundary's reflection (surface_reflection).
    bool rough = false;
    float eta = 1.0f, inv_m2 = 0.0f, beckmann_norm = 0.0f;
    glm::vec3 eye{0.0f}, light_direction{0.0f}, light_irradiance{0.0f};
    glm::vec4 spot{0.0f}, edge{0.0f};
    void read(const Bindings& b, bool thin);
};

class GatherFragment final : public FragmentProgram<GatherFragment> {  // gather.frag
public:
    void bind(const Bindings& b) override;
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;

private:
    GatherInputs u_;
    const Sampler2D* albedo_ = nullptr;
};

class GatherThinFragment final : public FragmentProgram<GatherThinFragment> {  // gather_thin.frag
public:
    void bind(const Bindings& b) override;
    uint32_t inputs_read() const override;
    Vec4 main(const Fragment& frag) const;

private:
    GatherInputs u_;
    const Sampler2D* albedo_ = nullptr;
};

}  // namespace st
