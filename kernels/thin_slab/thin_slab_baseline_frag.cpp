// thin_slab_baseline_frag.cpp: twin of glsl/thin_slab_baseline.frag, line for line.
#include "shading/glsl_math.h"
#include "kernels/thin_slab/thin_slab.h"
#include "kernels/thin_slab/thin_slab_model.h"
#include "texture/sampler2d.h"

namespace st {

namespace {
constexpr int v_position = 0, v_normal = 1, v_uv = 2;  // inputs
}  // namespace

void ThinSlabBaselineFragment::bind(const Bindings& b) {
    u_.read(b, false);
    flag_ = &b.sampler("flag");
}

glm::vec4 ThinSlabBaselineFragment::main(const Fragment& frag) const {
    glm::vec3 texel = glm::vec3(flag_->sample(glm::vec2(frag.varying(v_uv))));
    glm::vec3 lit = lambert_baseline(glm::vec3(frag.varying(v_position)),
                                     glsl::normalize(glm::vec3(frag.varying(v_normal))), u_.eye, u_.light,
                                     u_.power, u_.albedo * texel * 0.8f);
    return glm::vec4(lit, 0.2f);
}

}  // namespace st
