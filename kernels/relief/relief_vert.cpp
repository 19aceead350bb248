// relief_vert.cpp: twin of glsl/relief/relief.vert, line for line.
#include "kernels/relief/relief.h"

#include "shading/glsl_math.h"

namespace st {

namespace {
constexpr int position = 0, uv = 1;      // inputs
constexpr int v_position = 0, v_uv = 1;  // outputs
}  // namespace

void ReliefVertex::run(const glm::vec4* attributes, VertexOut& out) const {
    out.position = glsl::mul(view_proj_, attributes[position]);
    out.varyings[v_position] = attributes[position];
    out.varyings[v_uv] = attributes[uv];
}

}  // namespace st
