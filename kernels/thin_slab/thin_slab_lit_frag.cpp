// thin_slab_lit_frag.cpp: twin of glsl/thin_slab_lit.frag, line for line.
#include "kernels/thin_slab/thin_slab.h"
#include "texture/sampler2d.h"

namespace st {

namespace {
constexpr int v_radiance = 0, v_uv = 1;  // inputs
}  // namespace

void ThinSlabLitFragment::bind(const Bindings& b) { flag_ = &b.sampler("flag"); }

glm::vec4 ThinSlabLitFragment::main(const Fragment& frag) const {
    glm::vec3 texel = glm::vec3(flag_->sample(glm::vec2(frag.varying(v_uv))));
    const glm::vec4& radiance = frag.varying(v_radiance);
    return glm::vec4(glm::vec3(radiance) * texel, radiance.a);
}

}  // namespace st
