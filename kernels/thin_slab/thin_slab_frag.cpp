// thin_slab_frag.cpp: twin of glsl/thin_slab.frag, line for line.
#include "shading/glsl_math.h"
#include "kernels/thin_slab/thin_slab.h"
#include "kernels/thin_slab/thin_slab_model.h"
#include "texture/sampler2d.h"

namespace st {

namespace {
constexpr int v_position = 0, v_normal = 1, v_uv = 2;  // inputs
}  // namespace

void ThinSlabFragment::bind(const Bindings& b) {
    u_.read(b, true);
    flag_ = &b.sampler("flag");
}

glm::vec4 ThinSlabFragment::main(const Fragment& frag) const {
    glm::vec3 texel = glm::vec3(flag_->sample(glm::vec2(frag.varying(v_uv))));
    return thin_slab(glm::vec3(frag.varying(v_position)), glsl::normalize(glm::vec3(frag.varying(v_normal))),
                     u_.eye, u_.light, u_.power, u_.tau1, u_.albedo * texel);
}

}  // namespace st
