// thin_slab_sweep_frag.cpp: twin of glsl/thin_slab_sweep.frag, line for line.
#include <cmath>

#include "shading/glsl_math.h"
#include "kernels/thin_slab/thin_slab.h"
#include "kernels/thin_slab/thin_slab_model.h"
#include "texture/sampler2d.h"

namespace st {

void ThinSlabSweepFragment::bind(const Bindings& b) { inputs_ = &b.sampler("inputs"); }

glm::vec4 ThinSlabSweepFragment::main(const Fragment& frag) const {
    glm::vec4 p = inputs_->fetch(int(frag.frag_coord().x), int(frag.frag_coord().y));
    float mu = std::fmax(p.g, MU_MIN);
    float mu0 = std::fmax(p.b, MU_MIN);
    return glm::vec4(frontlit_factor(p.r, mu, mu0), backlit_factor(p.r, mu, mu0), glsl::exp(-p.r / mu),
                     one_minus_exp_neg(p.r));
}

}  // namespace st
