// program.h: the interface a C++ twin of a GLSL stage implements.
//
// A vertex twin mirrors a .vert file: it reads vec4 attributes and uniforms
// and writes the clip-space position and vec4 varyings (slot N is the GLSL
// varying declared with layout(location = N)), one vertex at a time. A
// fragment twin mirrors a .frag file and runs on kLanes fragments at once
// (simd/lanes.h), whole 2x2 quads as the GPU does, so that dFdx/dFdy of any
// value come from the quad (shading/derivatives.h). Derive from
// FragmentProgram (below).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <glm/mat2x2.hpp>
#include <glm/mat2x3.hpp>
#include <glm/mat2x4.hpp>
#include <glm/mat3x2.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat3x4.hpp>
#include <glm/mat4x2.hpp>
#include <glm/mat4x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "frame/frame.h"
#include "shading/control_flow.h"
#include "simd/lane_vec.h"

namespace st {

class Sampler2D;
class SamplerCube;

inline constexpr int kMaxVaryings = 8;

// GLSL's interpolation qualifier of a fragment input, which decides how the
// rasterizer carries a varying from the vertices to a fragment (the fragment
// shader's qualifier is the one that counts, as in GL since 4.30):
// - Smooth: perspective-correct (the default);
// - NoPerspective: linear in window space;
// - Flat: the provoking (last) vertex's value in every fragment, its bits
//   untouched, which is how int and uint varyings travel: the vertex twin
//   writes intBitsToFloat(i), the fragment twin reads floatBitsToInt.
enum class Interpolation : uint8_t { Smooth, NoPerspective, Flat };
using Interpolations = std::array<Interpolation, kMaxVaryings>;  // [slot]

// A twin's varying slots by the GLSL names they mirror, as GL names them
// ("Normal"; a block member "VS_OUT.Normal"): entry N names slot N ("" for
// none). Empty: the slots are the GLSL's explicit locations. Every run
// checks either against the GLSL (app/interface/varying_interface.h).
using SlotNames = std::vector<std::string>;

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
    std::vector<const SamplerCube*> cube_samplers;
    std::vector<std::string> cube_sampler_names;

    // Throws std::runtime_error naming the uniform when it is absent or of
    // another type, so a scene that forgets one fails loudly.
    float get_float(const std::string& name) const;
    int get_int(const std::string& name) const;
    // Whether the draw sets a uniform of this name (GL reads an unset one as 0).
    bool has(const std::string& name) const;
    // An int the scene may leave out (the condition map's perturbation).
    int get_int_or(const std::string& name, int fallback) const;
    glm::vec2 get_vec2(const std::string& name) const;
    glm::vec3 get_vec3(const std::string& name) const;
    glm::vec4 get_vec4(const std::string& name) const;
    glm::mat4 get_mat4(const std::string& name) const;
    glm::mat3 get_mat3(const std::string& name) const;
    glm::mat2 get_mat2(const std::string& name) const;
    // The non-square ones, glm's mat<C, R>: C columns of R rows.
    glm::mat2x3 get_mat2x3(const std::string& name) const;
    glm::mat2x4 get_mat2x4(const std::string& name) const;
    glm::mat3x2 get_mat3x2(const std::string& name) const;
    glm::mat3x4 get_mat3x4(const std::string& name) const;
    glm::mat4x2 get_mat4x2(const std::string& name) const;
    glm::mat4x3 get_mat4x3(const std::string& name) const;
    // bool is set as an int (glUniform1i) or a uint (glUniform1ui), bvecN
    // as ivecN.
    bool get_bool(const std::string& name) const;
    glm::ivec2 get_ivec2(const std::string& name) const;
    glm::ivec3 get_ivec3(const std::string& name) const;
    glm::ivec4 get_ivec4(const std::string& name) const;
    uint32_t get_uint(const std::string& name) const;
    glm::uvec2 get_uvec2(const std::string& name) const;
    glm::uvec3 get_uvec3(const std::string& name) const;
    glm::uvec4 get_uvec4(const std::string& name) const;
    // double, dvecN, dmatN (glm's double types; a fragment twin broadcasts
    // them to Double lanes, simd/lane_double.h).
    double get_double(const std::string& name) const;
    glm::dvec2 get_dvec2(const std::string& name) const;
    glm::dvec3 get_dvec3(const std::string& name) const;
    glm::dvec4 get_dvec4(const std::string& name) const;
    glm::dmat2 get_dmat2(const std::string& name) const;
    glm::dmat3 get_dmat3(const std::string& name) const;
    glm::dmat4 get_dmat4(const std::string& name) const;
    glm::dmat2x3 get_dmat2x3(const std::string& name) const;
    glm::dmat2x4 get_dmat2x4(const std::string& name) const;
    glm::dmat3x2 get_dmat3x2(const std::string& name) const;
    glm::dmat3x4 get_dmat3x4(const std::string& name) const;
    glm::dmat4x2 get_dmat4x2(const std::string& name) const;
    glm::dmat4x3 get_dmat4x3(const std::string& name) const;
    const Sampler2D& sampler(const std::string& name) const;
    const SamplerCube& sampler_cube(const std::string& name) const;

    // The uniform as the C++ type that mirrors its GLSL type (float, int,
    // uint32_t, bool, double, glm's vecN, ivecN, uvecN, dvecN, matCxR,
    // dmatCxR): b.get<glm::mat3>("normalMatrix"). Throws as the getters
    // above do.
    template <class T> T get(const std::string& name) const;
    // A uniform array's elements as GL names them, name[0] ... name[N-1]:
    // b.array<glm::vec3, 4>("lightPositions") for `uniform vec3
    // lightPositions[4]`. Throws naming the first element the draw does not set.
    template <class T, size_t N> std::array<T, N> array(const std::string& name) const {
        std::array<T, N> out{};
        for (size_t i = 0; i < N; ++i) out[i] = get<T>(name + "[" + std::to_string(i) + "]");
        return out;
    }
};

template <class T> T Bindings::get(const std::string& name) const {
    if constexpr (std::is_same_v<T, float>) return get_float(name);
    else if constexpr (std::is_same_v<T, int>) return get_int(name);
    else if constexpr (std::is_same_v<T, uint32_t>) return get_uint(name);
    else if constexpr (std::is_same_v<T, bool>) return get_bool(name);
    else if constexpr (std::is_same_v<T, double>) return get_double(name);
    else if constexpr (std::is_same_v<T, glm::vec2>) return get_vec2(name);
    else if constexpr (std::is_same_v<T, glm::vec3>) return get_vec3(name);
    else if constexpr (std::is_same_v<T, glm::vec4>) return get_vec4(name);
    else if constexpr (std::is_same_v<T, glm::ivec2>) return get_ivec2(name);
    else if constexpr (std::is_same_v<T, glm::ivec3>) return get_ivec3(name);
    else if constexpr (std::is_same_v<T, glm::ivec4>) return get_ivec4(name);
    else if constexpr (std::is_same_v<T, glm::uvec2>) return get_uvec2(name);
    else if constexpr (std::is_same_v<T, glm::uvec3>) return get_uvec3(name);
    else if constexpr (std::is_same_v<T, glm::uvec4>) return get_uvec4(name);
    else if constexpr (std::is_same_v<T, glm::bvec2>) return glm::bvec2(get_ivec2(name));
    else if constexpr (std::is_same_v<T, glm::bvec3>) return glm::bvec3(get_ivec3(name));
    else if constexpr (std::is_same_v<T, glm::bvec4>) return glm::bvec4(get_ivec4(name));
    else if constexpr (std::is_same_v<T, glm::dvec2>) return get_dvec2(name);
    else if constexpr (std::is_same_v<T, glm::dvec3>) return get_dvec3(name);
    else if constexpr (std::is_same_v<T, glm::dvec4>) return get_dvec4(name);
    else if constexpr (std::is_same_v<T, glm::mat2>) return get_mat2(name);
    else if constexpr (std::is_same_v<T, glm::mat3>) return get_mat3(name);
    else if constexpr (std::is_same_v<T, glm::mat4>) return get_mat4(name);
    else if constexpr (std::is_same_v<T, glm::mat2x3>) return get_mat2x3(name);
    else if constexpr (std::is_same_v<T, glm::mat2x4>) return get_mat2x4(name);
    else if constexpr (std::is_same_v<T, glm::mat3x2>) return get_mat3x2(name);
    else if constexpr (std::is_same_v<T, glm::mat3x4>) return get_mat3x4(name);
    else if constexpr (std::is_same_v<T, glm::mat4x2>) return get_mat4x2(name);
    else if constexpr (std::is_same_v<T, glm::mat4x3>) return get_mat4x3(name);
    else if constexpr (std::is_same_v<T, glm::dmat2>) return get_dmat2(name);
    else if constexpr (std::is_same_v<T, glm::dmat3>) return get_dmat3(name);
    else if constexpr (std::is_same_v<T, glm::dmat4>) return get_dmat4(name);
    else if constexpr (std::is_same_v<T, glm::dmat2x3>) return get_dmat2x3(name);
    else if constexpr (std::is_same_v<T, glm::dmat2x4>) return get_dmat2x4(name);
    else if constexpr (std::is_same_v<T, glm::dmat3x2>) return get_dmat3x2(name);
    else if constexpr (std::is_same_v<T, glm::dmat3x4>) return get_dmat3x4(name);
    else if constexpr (std::is_same_v<T, glm::dmat4x2>) return get_dmat4x2(name);
    else if constexpr (std::is_same_v<T, glm::dmat4x3>) return get_dmat4x3(name);
    else static_assert(sizeof(T) == 0, "no GLSL uniform type is mirrored by this C++ type");
}

class VertexTwin {
public:
    virtual ~VertexTwin() = default;
    // Number of varying slots written (0..kMaxVaryings).
    virtual int varying_count() const = 0;
    // Called once per draw, before any run(): read uniforms here.
    virtual void bind(const Bindings&) {}
    virtual void run(const glm::vec4* attributes, VertexOut& out) const = 0;
    // The GLSL outputs its varying slots hold (SlotNames above).
    virtual SlotNames output_names() const { return {}; }
    // Non-null while the twin is still the skeleton `shadertwin
    // new-technique` wrote: what is left to write. `compare` fails every
    // scene that draws with it, saying so.
    virtual const char* unwritten() const { return nullptr; }
};

// The fragments a fragment twin shades at once: kLanes lanes, that is
// kLanes / 4 quads of one 4x4 block, in llvmpipe's order: quads (0,0),
// (2,0), (0,2), (2,2) of the block, and in each quad the pixels (x, y),
// (x+1, y), (x, y+1), (x+1, y+1) in GL window coordinates (y up). Lanes
// outside the triangle (helper lanes) hold extrapolated inputs and are
// shaded as on a GPU, so that derivatives exist; the pipeline drops their
// results.
struct FragmentLanes {
    Vec4 frag_coord;                                // gl_FragCoord
    std::array<Vec4, kMaxVaryings> varyings;        // [slot], one value per lane
    bool front_facing = true;
    Mask covered;                                   // false on helper lanes
};

struct FragmentResult {
    Vec4 colour;                                    // layout(location = 0) out
    Mask discarded;                                 // lanes that executed discard
    // layout(location = 1, 2, ...) out, where the pass draws into several
    // targets: kMaxFragmentOutputs - 1 values; null when it does not.
    Vec4* outputs = nullptr;
};

// What a fragment twin's main() returns for a shader with several outputs:
// entry N is layout(location = N) out.
template <int N> using FragmentOutputs = std::array<Vec4, N>;

// Bit 4 * slot + c: component c (x, y, z, w) of varying `slot`, as a twin
// declares what its main() reads: reads(v_uv, "xy") | reads(v_normal, "xyz").
constexpr uint32_t reads(int slot, const char* components) {
    uint32_t bits = 0;
    for (const char* c = components; *c; ++c) bits |= 1u << (4 * slot + (*c == 'w' ? 3 : *c - 'x'));
    return bits;
}

class FragmentTwin {
public:
    virtual ~FragmentTwin() = default;
    virtual void bind(const Bindings&) {}
    virtual void shade(const FragmentLanes& in, FragmentResult& out) const = 0;
    // The varying components main() reads (reads() above). The pipeline
    // interpolates only these, as llvmpipe interpolates only the inputs a
    // shader uses, and fills the others with NaN, so that a component read
    // but not declared shows in every comparison.
    virtual uint32_t inputs_read() const { return ~0u; }
    // Each input slot's interpolation qualifier (all Smooth unless the GLSL
    // says `flat` or `noperspective`).
    virtual Interpolations interpolations() const { return {}; }
    // The GLSL inputs its varying slots hold (SlotNames above).
    virtual SlotNames input_names() const { return {}; }
    // As VertexTwin::unwritten().
    virtual const char* unwritten() const { return nullptr; }
    // How many outputs (locations 0 ... N-1) main() writes.
    virtual int output_count() const { return 1; }
};

// What a twin's main() reads: the inputs of every lane at once, and the
// execution state its control flow runs under (shading/control_flow.h).
class Fragment {
public:
    Fragment(const FragmentLanes& lanes, Exec& exec) : lanes_(lanes), exec_(exec) {}
    const Vec4& varying(int slot) const { return lanes_.varyings[size_t(slot)]; }
    const Vec4& frag_coord() const { return lanes_.frag_coord; }
    bool front_facing() const { return lanes_.front_facing; }
    Exec& exec() const { return exec_; }

private:
    const FragmentLanes& lanes_;
    Exec& exec_;
};

// Adapter: Derived implements `Vec4 main(const Fragment&) const`, the twin
// of the shader's main(), on all lanes at once; or, for a shader with
// outputs at locations 0 ... N-1, `FragmentOutputs<N> main(...)`.
template <class Derived>
class FragmentProgram : public FragmentTwin {
public:
    void shade(const FragmentLanes& in, FragmentResult& out) const override {
        Exec exec;  // one invocation: fresh masks and loop budget
        const Derived& twin = *static_cast<const Derived*>(this);
        using Result = std::decay_t<decltype(twin.main(Fragment(in, exec)))>;
        if constexpr (std::is_same_v<Result, Vec4>) {
            out.colour = twin.main(Fragment(in, exec));
        } else {
            const Result result = twin.main(Fragment(in, exec));
            out.colour = result[0];
            if (out.outputs)
                for (size_t k = 1; k < result.size(); ++k) out.outputs[k - 1] = result[k];
        }
        out.discarded = exec.discarded();
    }
    int output_count() const override {
        using Result = std::decay_t<decltype(std::declval<const Derived&>().main(std::declval<const Fragment&>()))>;
        if constexpr (std::is_same_v<Result, Vec4>) return 1;
        else return int(std::tuple_size_v<Result>);
    }
};

}  // namespace st
