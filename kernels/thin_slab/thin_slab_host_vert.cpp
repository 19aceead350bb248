// thin_slab_host_vert.cpp: twin of glsl/thin_slab_host.vert, line for line.
#include "shading/glsl_math.h"
#include "kernels/thin_slab/thin_slab.h"

namespace st {

namespace {
constexpr int position = 0, radiance = 1, uv = 2;  // inputs
constexpr int v_radiance = 0, v_uv = 1;            // outputs
}  // namespace

void ThinSlabHostVertex::run(const glm::vec4* attributes, VertexOut& out) const {
    out.position = glsl::mul(view_proj_, attributes[position]);
    out.varyings[v_radiance] = attributes[radiance];
    out.varyings[v_uv] = attributes[uv];
}

}  // namespace st
