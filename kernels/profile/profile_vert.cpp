// profile_vert.cpp: twin of glsl/profile/profile.vert, line for line.
#include "kernels/profile/profile.h"

#include "shading/glsl_math.h"

namespace st {

namespace {
constexpr int position = 0, normal = 1, uv = 2;            // inputs
constexpr int v_position = 0, v_normal = 1, v_uv = 2;      // outputs
}  // namespace

void ProfileVertex::run(const glm::vec4* attributes, VertexOut& out) const {
    out.position = glsl::mul(view_proj_, attributes[position]);
    out.varyings[v_position] = attributes[position];
    out.varyings[v_normal] = attributes[normal];
    out.varyings[v_uv] = attributes[uv];
}

}  // namespace st
