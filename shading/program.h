// program.h: the interface a C++ twin of a GLSL stage implements.
//
// A vertex twin mirrors a .vert file: it reads vec4 attributes and uniforms
// and writes the clip-space position and vec4 varyings (slot N is the GLSL
// varying declared with layout(location = N)). A fragment twin mirrors a
// .frag file and runs on one 2x2 quad at a time, as the GPU does, so that
// dFdx/dFdy come from the quad. Start with ScalarFragmentTwin (below) unless
// a shader needs derivatives of values it computes itself.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "frame/frame.h"

namespace st {

class Sampler2D;

inline constexpr int kMaxVaryings = 8;

struct VertexOut {
    glm::vec4 position{0.0f};                       // gl_Position
    std::array<glm::vec4, kMaxVaryings> varyings{};
};

// Everything a stage may read besides its per-invocation inputs. Textures are
// already converted to samplers by the pipeline; entry i is unit i.
struct Bindings {
    const std::vector<Uniform>* uniforms = nullptr;
    std::vector<const Sampler2D*> samplers;
    std::vector<std::string> sampler_names;

    // Throws std::runtime_error naming the uniform when it is absent or of
    // another type, so a scene that forgets one fails loudly.
    float get_float(const std::string& name) const;
    glm::vec3 get_vec3(const std::string& name) const;
    glm::vec4 get_vec4(const std::string& name) const;
    glm::mat4 get_mat4(const std::string& name) const;
    const Sampler2D& sampler(const std::string& name) const;
};

class VertexTwin {
public:
    virtual ~VertexTwin() = default;
    // Number of varying slots written (0..kMaxVaryings).
    virtual int varying_count() const = 0;
    // Called once per draw, before any run(): read uniforms here.
    virtual void bind(const Bindings&) {}
    virtual void run(const glm::vec4* attributes, VertexOut& out) const = 0;
};

// One 2x2 quad of fragments. Lanes are ordered (x, y), (x+1, y), (x, y+1),
// (x+1, y+1) in GL window coordinates (y up). Lanes outside the triangle
// (helper lanes) still hold extrapolated inputs and are shaded, as on a GPU;
// their results are discarded by the pipeline.
struct FragmentQuad {
    std::array<glm::vec4, 4> frag_coord;            // gl_FragCoord
    std::array<std::array<glm::vec4, 4>, kMaxVaryings> varyings;  // [slot][lane]
    bool front_facing = true;
    unsigned coverage_mask = 0;                     // bit i = lane i covered
};

struct FragmentOut {
    std::array<glm::vec4, 4> colour;                // layout(location = 0) out
    unsigned discard_mask = 0;                      // bit i = lane i discarded
};

class FragmentTwin {
public:
    virtual ~FragmentTwin() = default;
    virtual void bind(const Bindings&) {}
    virtual void shade(const FragmentQuad& in, FragmentOut& out) const = 0;
};

// Per-lane view of a quad for twins written like a scalar GLSL main().
class Fragment {
public:
    Fragment(const FragmentQuad& quad, int lane) : quad_(quad), lane_(lane) {}
    const glm::vec4& varying(int slot) const { return quad_.varyings[slot][lane_]; }
    const glm::vec4& frag_coord() const { return quad_.frag_coord[lane_]; }
    bool front_facing() const { return quad_.front_facing; }
    // Derivatives of an input varying: per-row/column differences inside the
    // quad, as llvmpipe computes them (fine and coarse agree there).
    glm::vec4 dFdx(int slot) const;
    glm::vec4 dFdy(int slot) const;

private:
    const FragmentQuad& quad_;
    int lane_;
};

// Adapter: Derived implements `glm::vec4 main(const Fragment&) const`.
template <class Derived>
class ScalarFragmentTwin : public FragmentTwin {
public:
    void shade(const FragmentQuad& in, FragmentOut& out) const override {
        for (int lane = 0; lane < 4; ++lane)
            out.colour[lane] = static_cast<const Derived*>(this)->main(Fragment(in, lane));
    }
};

}  // namespace st
