// program.cpp: uniform and sampler look-up for twins.
#include "shading/program.h"

#include <stdexcept>

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
    return find(uniforms, name, UniformType::Float).value[0];
}

int Bindings::get_int(const std::string& name) const {
    return int(find(uniforms, name, UniformType::Int).value[0]);
}

int Bindings::get_int_or(const std::string& name, int fallback) const {
    if (uniforms)
        for (const Uniform& u : *uniforms)
            if (u.name == name && u.type == UniformType::Int) return int(u.value[0]);
    return fallback;
}

glm::vec2 Bindings::get_vec2(const std::string& name) const {
    const auto& v = find(uniforms, name, UniformType::Vec2).value;
    return glm::vec2(v[0], v[1]);
}

glm::vec3 Bindings::get_vec3(const std::string& name) const {
    const auto& v = find(uniforms, name, UniformType::Vec3).value;
    return glm::vec3(v[0], v[1], v[2]);
}

glm::mat4 Bindings::get_mat4(const std::string& name) const {
    const auto& v = find(uniforms, name, UniformType::Mat4).value;
    glm::mat4 m;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) m[c][r] = v[size_t(c * 4 + r)];
    return m;
}

glm::mat3 Bindings::get_mat3(const std::string& name) const {
    const auto& v = find(uniforms, name, UniformType::Mat3).value;
    glm::mat3 m;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) m[c][r] = v[size_t(c * 3 + r)];
    return m;
}

glm::mat2 Bindings::get_mat2(const std::string& name) const {
    const auto& v = find(uniforms, name, UniformType::Mat2).value;
    return glm::mat2(v[0], v[1], v[2], v[3]);
}

namespace {

// A matCxR uniform as glm holds it: C columns of R rows, column-major.
template <int C, int R> glm::mat<C, R, float> matrix_of(const Uniform& u) {
    glm::mat<C, R, float> m;
    for (int c = 0; c < C; ++c)
        for (int r = 0; r < R; ++r) m[c][r] = u.value[size_t(c * R + r)];
    return m;
}

}  // namespace

glm::mat2x3 Bindings::get_mat2x3(const std::string& name) const { return matrix_of<2, 3>(find(uniforms, name, UniformType::Mat2x3)); }
glm::mat2x4 Bindings::get_mat2x4(const std::string& name) const { return matrix_of<2, 4>(find(uniforms, name, UniformType::Mat2x4)); }
glm::mat3x2 Bindings::get_mat3x2(const std::string& name) const { return matrix_of<3, 2>(find(uniforms, name, UniformType::Mat3x2)); }
glm::mat3x4 Bindings::get_mat3x4(const std::string& name) const { return matrix_of<3, 4>(find(uniforms, name, UniformType::Mat3x4)); }
glm::mat4x2 Bindings::get_mat4x2(const std::string& name) const { return matrix_of<4, 2>(find(uniforms, name, UniformType::Mat4x2)); }
glm::mat4x3 Bindings::get_mat4x3(const std::string& name) const { return matrix_of<4, 3>(find(uniforms, name, UniformType::Mat4x3)); }

glm::ivec2 Bindings::get_ivec2(const std::string& name) const {
    const auto& v = find(uniforms, name, UniformType::IVec2).value;
    return glm::ivec2(int(v[0]), int(v[1]));
}

glm::ivec3 Bindings::get_ivec3(const std::string& name) const {
    const auto& v = find(uniforms, name, UniformType::IVec3).value;
    return glm::ivec3(int(v[0]), int(v[1]), int(v[2]));
}

glm::ivec4 Bindings::get_ivec4(const std::string& name) const {
    const auto& v = find(uniforms, name, UniformType::IVec4).value;
    return glm::ivec4(int(v[0]), int(v[1]), int(v[2]), int(v[3]));
}

uint32_t Bindings::get_uint(const std::string& name) const {
    return uint32_t(find(uniforms, name, UniformType::UInt).value[0]);
}

glm::uvec2 Bindings::get_uvec2(const std::string& name) const {
    const auto& v = find(uniforms, name, UniformType::UVec2).value;
    return glm::uvec2(uint32_t(v[0]), uint32_t(v[1]));
}

glm::uvec3 Bindings::get_uvec3(const std::string& name) const {
    const auto& v = find(uniforms, name, UniformType::UVec3).value;
    return glm::uvec3(uint32_t(v[0]), uint32_t(v[1]), uint32_t(v[2]));
}

glm::uvec4 Bindings::get_uvec4(const std::string& name) const {
    const auto& v = find(uniforms, name, UniformType::UVec4).value;
    return glm::uvec4(uint32_t(v[0]), uint32_t(v[1]), uint32_t(v[2]), uint32_t(v[3]));
}

glm::vec4 Bindings::get_vec4(const std::string& name) const {
    const auto& v = find(uniforms, name, UniformType::Vec4).value;
    return glm::vec4(v[0], v[1], v[2], v[3]);
}

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
