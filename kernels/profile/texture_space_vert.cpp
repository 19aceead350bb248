// texture_space_vert.cpp: twin of glsl/profile/texture_space.vert, line for line.
#include "kernels/profile/profile.h"

namespace st {

namespace {
constexpr int position = 0, normal = 1, uv = 2;  // inputs
constexpr int v_position = 0, v_normal = 1;      // outputs
}  // namespace

void TextureSpaceVertex::run(const glm::vec4* attributes, VertexOut& out) const {
    const glm::vec4& t = attributes[uv];
    out.position = glm::vec4(t.x * 2.0f - 1.0f, t.y * 2.0f - 1.0f, 0.0f, 1.0f);
    out.varyings[v_position] = attributes[position];
    out.varyings[v_normal] = attributes[normal];
}

}  // namespace st
