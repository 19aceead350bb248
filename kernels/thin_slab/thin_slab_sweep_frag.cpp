// thin_slab_sweep_frag.cpp: twin of glsl/thin_slab_sweep.frag, line for line.
#include <cmath>

#include "shading/glsl_math.h"
#include "kernels/thin_slab/thin_slab.h"
#include "kernels/thin_slab/thin_slab_model.h"
#include "texture/sampler2d.h"

namespace st {

void ThinSlabSweepFragment::bind(const Bindings& b) { inputs_ = &b.sampler("inputs"); }

Vec4 ThinSlabSweepFragment::main(const Fragment& frag) const {
    Vec4 p = inputs_->fetch(simd::itrunc(frag.frag_coord().x), simd::itrunc(frag.frag_coord().y));
    Float mu = glsl::max(p.y, Float(MU_MIN));
    Float mu0 = glsl::max(p.z, Float(MU_MIN));
    return Vec4(frontlit_factor(p.x, mu, mu0), backlit_factor(p.x, mu, mu0), glsl::exp(-p.x / mu),
                one_minus_exp_neg(p.x));
}

}  // namespace st
