// uniform_values.h: Uniform values from glm types, for scene builders that
// compute their uniforms on the host.
#pragma once

#include <string>

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

// An int (or a bool, which glUniform1i sets too), stored exactly as a float.
inline Uniform int_uniform(const std::string& name, int v) {
    Uniform u{name, UniformType::Int, {}};
    u.value[0] = float(v);
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

// Column-major, as glUniformMatrix4fv takes it.
inline Uniform uniform(const std::string& name, const glm::mat4& m) {
    Uniform u{name, UniformType::Mat4, {}};
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) u.value[size_t(c * 4 + r)] = m[c][r];
    return u;
}

}  // namespace st
