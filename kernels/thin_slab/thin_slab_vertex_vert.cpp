// thin_slab_vertex_vert.cpp: twin of glsl/thin_slab_vertex.vert, line for line.
#include "shading/glsl_math.h"
#include "kernels/thin_slab/thin_slab.h"
#include "kernels/thin_slab/thin_slab_model.h"

namespace st {

namespace {
constexpr int position = 0, normal = 1, uv = 2;  // inputs
constexpr int v_radiance = 0, v_uv = 1;          // outputs
}  // namespace

void ThinSlabVertexVariant::bind(const Bindings& b) {
    view_proj_ = b.get_mat4("view_proj");
    u_.read(b, true);
}

void ThinSlabVertexVariant::run(const glm::vec4* attributes, VertexOut& out) const {
    out.position = glsl::mul(view_proj_, attributes[position]);
    out.varyings[v_radiance] = thin_slab(glm::vec3(attributes[position]), glsl::normalize(glm::vec3(attributes[normal])),
                                         u_.eye, u_.light, u_.power, u_.tau1, u_.albedo);
    out.varyings[v_uv] = attributes[uv];
}

}  // namespace st
