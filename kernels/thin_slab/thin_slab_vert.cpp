// thin_slab_vert.cpp: twin of glsl/thin_slab.vert, line for line.
#include "shading/glsl_math.h"
#include "kernels/thin_slab/thin_slab.h"

namespace st {

namespace {
constexpr int position = 0, normal = 1, uv = 2;      // inputs
constexpr int v_position = 0, v_normal = 1, v_uv = 2;  // outputs
}  // namespace

void ThinSlabVertex::run(const glm::vec4* attributes, VertexOut& out) const {
    out.position = glsl::mul(view_proj_, attributes[position]);
    out.varyings[v_position] = attributes[position];
    out.varyings[v_normal] = attributes[normal];
    out.varyings[v_uv] = attributes[uv];
}

}  // namespace st
