// uniform_values.h: Uniform values from glm types, for scene builders that
// compute their uniforms on the host.
#pragma once

#include <string>

#include <type_traits>

#include <glm/mat2x2.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "frame/frame.h"

namespace st {

inline Uniform uniform(const std::string& name, float v) {
    Uniform u{name, UniformType::Float, {}};
    u.value[0] = v;
    return u;
}

// An int (or a bool, which glUniform1i sets too).
inline Uniform int_uniform(const std::string& name, int v) {
    Uniform u{name, UniformType::Int, {}};
    u.value[0] = v;
    return u;
}

inline Uniform uniform(const std::string& name, const glm::vec2& v) {
    Uniform u{name, UniformType::Vec2, {}};
    for (int c = 0; c < 2; ++c) u.value[size_t(c)] = v[c];
    return u;
}

inline Uniform uniform(const std::string& name, const glm::vec3& v) {
    Uniform u{name, UniformType::Vec3, {}};
    for (int c = 0; c < 3; ++c) u.value[size_t(c)] = v[c];
    return u;
}

inline Uniform uniform(const std::string& name, const glm::vec4& v) {
    Uniform u{name, UniformType::Vec4, {}};
    for (int c = 0; c < 4; ++c) u.value[size_t(c)] = v[c];
    return u;
}

// ivecN, uvecN (and bvecN, set as ivecN).
template <int N, class T, glm::qualifier Q>
inline Uniform uniform(const std::string& name, const glm::vec<N, T, Q>& v)
    requires(std::is_integral_v<T> && N >= 2)
{
    constexpr bool is_signed = std::is_signed_v<T>;
    constexpr UniformType types[2][3] = {{UniformType::UVec2, UniformType::UVec3, UniformType::UVec4},
                                         {UniformType::IVec2, UniformType::IVec3, UniformType::IVec4}};
    Uniform u{name, types[is_signed][N - 2], {}};
    for (int c = 0; c < N; ++c) u.value[size_t(c)] = double(v[c]);
    return u;
}

inline Uniform uint_uniform(const std::string& name, uint32_t v) {
    Uniform u{name, UniformType::UInt, {}};
    u.value[0] = v;
    return u;
}

// A double (GLSL double; named apart from uniform(name, float), which a
// double argument such as 0.5 still reaches).
inline Uniform double_uniform(const std::string& name, double v) {
    Uniform u{name, UniformType::Double, {}};
    u.value[0] = v;
    return u;
}

// dvecN.
template <int N, glm::qualifier Q>
inline Uniform uniform(const std::string& name, const glm::vec<N, double, Q>& v)
    requires(N >= 2)
{
    constexpr UniformType types[3] = {UniformType::DVec2, UniformType::DVec3, UniformType::DVec4};
    Uniform u{name, types[N - 2], {}};
    for (int c = 0; c < N; ++c) u.value[size_t(c)] = v[c];
    return u;
}

// dmatCxR, column-major as glUniformMatrixCxRdv takes it.
template <int C, int R, glm::qualifier Q>
inline Uniform uniform(const std::string& name, const glm::mat<C, R, double, Q>& m) {
    constexpr UniformType types[3][3] = {{UniformType::DMat2, UniformType::DMat2x3, UniformType::DMat2x4},
                                         {UniformType::DMat3x2, UniformType::DMat3, UniformType::DMat3x4},
                                         {UniformType::DMat4x2, UniformType::DMat4x3, UniformType::DMat4}};
    Uniform u{name, types[C - 2][R - 2], {}};
    for (int c = 0; c < C; ++c)
        for (int r = 0; r < R; ++r) u.value[size_t(c * R + r)] = m[c][r];
    return u;
}

inline Uniform uniform(const std::string& name, const glm::mat2& m) {
    Uniform u{name, UniformType::Mat2, {}};
    for (int c = 0; c < 2; ++c)
        for (int r = 0; r < 2; ++r) u.value[size_t(c * 2 + r)] = m[c][r];
    return u;
}

inline Uniform uniform(const std::string& name, const glm::mat3& m) {
    Uniform u{name, UniformType::Mat3, {}};
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) u.value[size_t(c * 3 + r)] = m[c][r];
    return u;
}

// matCxR (C != R), column-major as glUniformMatrixCxRfv takes it.
template <int C, int R, glm::qualifier Q>
inline Uniform uniform(const std::string& name, const glm::mat<C, R, float, Q>& m)
    requires(C != R)
{
    constexpr UniformType types[3][3] = {{UniformType::Mat2, UniformType::Mat2x3, UniformType::Mat2x4},
                                         {UniformType::Mat3x2, UniformType::Mat3, UniformType::Mat3x4},
                                         {UniformType::Mat4x2, UniformType::Mat4x3, UniformType::Mat4}};
    Uniform u{name, types[C - 2][R - 2], {}};
    for (int c = 0; c < C; ++c)
        for (int r = 0; r < R; ++r) u.value[size_t(c * R + r)] = m[c][r];
    return u;
}

// Column-major, as glUniformMatrix4fv takes it.
inline Uniform uniform(const std::string& name, const glm::mat4& m) {
    Uniform u{name, UniformType::Mat4, {}};
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) u.value[size_t(c * 4 + r)] = m[c][r];
    return u;
}

}  // namespace st
