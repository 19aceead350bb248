// program.cpp: uniform and sampler look-up for twins.
#include "shading/program.h"

#include <stdexcept>
#include <type_traits>

namespace st {

namespace {

const Uniform& find(const std::vector<Uniform>* uniforms, const std::string& name, UniformType type) {
    if (uniforms)
        for (const Uniform& u : *uniforms)
            if (u.name == name) {
                if (u.type != type) throw std::runtime_error("uniform '" + name + "' has the wrong type");
                return u;
            }
    throw std::runtime_error("uniform '" + name + "' is not set");
}

}  // namespace

float Bindings::get_float(const std::string& name) const {
    return float(find(uniforms, name, UniformType::Float).value[0]);
}

int Bindings::get_int(const std::string& name) const {
    return int32_t(uniform_integer_bits(find(uniforms, name, UniformType::Int).value[0]));
}

bool Bindings::get_bool(const std::string& name) const {
    if (uniforms)
        for (const Uniform& u : *uniforms)
            if (u.name == name && u.type == UniformType::UInt) return uniform_integer_bits(u.value[0]) != 0;
    return get_int(name) != 0;
}

bool Bindings::has(const std::string& name) const {
    if (uniforms)
        for (const Uniform& u : *uniforms)
            if (u.name == name) return true;
    return false;
}

int Bindings::get_int_or(const std::string& name, int fallback) const {
    if (uniforms)
        for (const Uniform& u : *uniforms)
            if (u.name == name && u.type == UniformType::Int) return int32_t(uniform_integer_bits(u.value[0]));
    return fallback;
}

namespace {

// A matCxR uniform as glm holds it: C columns of R rows, column-major, of
// float or double T.
template <int C, int R, class T = float> glm::mat<C, R, T> matrix_of(const Uniform& u) {
    glm::mat<C, R, T> m;
    for (int c = 0; c < C; ++c)
        for (int r = 0; r < R; ++r) m[c][r] = T(u.value[size_t(c * R + r)]);
    return m;
}

// An N-vector uniform of element type T (the Uniform holds each exactly).
template <int N, class T> glm::vec<N, T> vector_of(const Uniform& u) {
    glm::vec<N, T> v;
    for (int i = 0; i < N; ++i) {
        if constexpr (std::is_integral_v<T>) v[i] = T(uniform_integer_bits(u.value[size_t(i)]));
        else v[i] = T(u.value[size_t(i)]);
    }
    return v;
}

}  // namespace

glm::vec2 Bindings::get_vec2(const std::string& name) const { return vector_of<2, float>(find(uniforms, name, UniformType::Vec2)); }
glm::vec3 Bindings::get_vec3(const std::string& name) const { return vector_of<3, float>(find(uniforms, name, UniformType::Vec3)); }
glm::vec4 Bindings::get_vec4(const std::string& name) const { return vector_of<4, float>(find(uniforms, name, UniformType::Vec4)); }
glm::ivec2 Bindings::get_ivec2(const std::string& name) const { return vector_of<2, int>(find(uniforms, name, UniformType::IVec2)); }
glm::ivec3 Bindings::get_ivec3(const std::string& name) const { return vector_of<3, int>(find(uniforms, name, UniformType::IVec3)); }
glm::ivec4 Bindings::get_ivec4(const std::string& name) const { return vector_of<4, int>(find(uniforms, name, UniformType::IVec4)); }
glm::uvec2 Bindings::get_uvec2(const std::string& name) const { return vector_of<2, uint32_t>(find(uniforms, name, UniformType::UVec2)); }
glm::uvec3 Bindings::get_uvec3(const std::string& name) const { return vector_of<3, uint32_t>(find(uniforms, name, UniformType::UVec3)); }
glm::uvec4 Bindings::get_uvec4(const std::string& name) const { return vector_of<4, uint32_t>(find(uniforms, name, UniformType::UVec4)); }

uint32_t Bindings::get_uint(const std::string& name) const {
    return uniform_integer_bits(find(uniforms, name, UniformType::UInt).value[0]);
}

glm::mat2 Bindings::get_mat2(const std::string& name) const { return matrix_of<2, 2>(find(uniforms, name, UniformType::Mat2)); }
glm::mat3 Bindings::get_mat3(const std::string& name) const { return matrix_of<3, 3>(find(uniforms, name, UniformType::Mat3)); }
glm::mat4 Bindings::get_mat4(const std::string& name) const { return matrix_of<4, 4>(find(uniforms, name, UniformType::Mat4)); }
glm::mat2x3 Bindings::get_mat2x3(const std::string& name) const { return matrix_of<2, 3>(find(uniforms, name, UniformType::Mat2x3)); }
glm::mat2x4 Bindings::get_mat2x4(const std::string& name) const { return matrix_of<2, 4>(find(uniforms, name, UniformType::Mat2x4)); }
glm::mat3x2 Bindings::get_mat3x2(const std::string& name) const { return matrix_of<3, 2>(find(uniforms, name, UniformType::Mat3x2)); }
glm::mat3x4 Bindings::get_mat3x4(const std::string& name) const { return matrix_of<3, 4>(find(uniforms, name, UniformType::Mat3x4)); }
glm::mat4x2 Bindings::get_mat4x2(const std::string& name) const { return matrix_of<4, 2>(find(uniforms, name, UniformType::Mat4x2)); }
glm::mat4x3 Bindings::get_mat4x3(const std::string& name) const { return matrix_of<4, 3>(find(uniforms, name, UniformType::Mat4x3)); }

double Bindings::get_double(const std::string& name) const { return find(uniforms, name, UniformType::Double).value[0]; }
glm::dvec2 Bindings::get_dvec2(const std::string& name) const { return vector_of<2, double>(find(uniforms, name, UniformType::DVec2)); }
glm::dvec3 Bindings::get_dvec3(const std::string& name) const { return vector_of<3, double>(find(uniforms, name, UniformType::DVec3)); }
glm::dvec4 Bindings::get_dvec4(const std::string& name) const { return vector_of<4, double>(find(uniforms, name, UniformType::DVec4)); }
glm::dmat2 Bindings::get_dmat2(const std::string& name) const { return matrix_of<2, 2, double>(find(uniforms, name, UniformType::DMat2)); }
glm::dmat3 Bindings::get_dmat3(const std::string& name) const { return matrix_of<3, 3, double>(find(uniforms, name, UniformType::DMat3)); }
glm::dmat4 Bindings::get_dmat4(const std::string& name) const { return matrix_of<4, 4, double>(find(uniforms, name, UniformType::DMat4)); }
glm::dmat2x3 Bindings::get_dmat2x3(const std::string& name) const { return matrix_of<2, 3, double>(find(uniforms, name, UniformType::DMat2x3)); }
glm::dmat2x4 Bindings::get_dmat2x4(const std::string& name) const { return matrix_of<2, 4, double>(find(uniforms, name, UniformType::DMat2x4)); }
glm::dmat3x2 Bindings::get_dmat3x2(const std::string& name) const { return matrix_of<3, 2, double>(find(uniforms, name, UniformType::DMat3x2)); }
glm::dmat3x4 Bindings::get_dmat3x4(const std::string& name) const { return matrix_of<3, 4, double>(find(uniforms, name, UniformType::DMat3x4)); }
glm::dmat4x2 Bindings::get_dmat4x2(const std::string& name) const { return matrix_of<4, 2, double>(find(uniforms, name, UniformType::DMat4x2)); }
glm::dmat4x3 Bindings::get_dmat4x3(const std::string& name) const { return matrix_of<4, 3, double>(find(uniforms, name, UniformType::DMat4x3)); }

const Sampler2D& Bindings::sampler(const std::string& name) const {
    for (size_t i = 0; i < sampler_names.size(); ++i)
        if (sampler_names[i] == name) return *samplers[i];
    throw std::runtime_error("sampler '" + name + "' is not bound");
}

const SamplerCube& Bindings::sampler_cube(const std::string& name) const {
    for (size_t i = 0; i < cube_sampler_names.size(); ++i)
        if (cube_sampler_names[i] == name) return *cube_samplers[i];
    throw std::runtime_error("samplerCube '" + name + "' is not bound");
}

}  // namespace st
