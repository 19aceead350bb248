// wrap_vert.cpp: twin of glsl/wrap.vert, line for line.
#include "wrap.h"

#include "shading/glsl_math.h"

namespace {
constexpr int position = 0, normal = 1;  // inputs
constexpr int v_normal = 0;              // outputs
}  // namespace

void WrapVertex::run(const glm::vec4* attributes, st::VertexOut& out) const {
    out.position = st::glsl::mul(mvp_, attributes[position]);  // mvp * position
    out.varyings[v_normal] = attributes[normal];
}
