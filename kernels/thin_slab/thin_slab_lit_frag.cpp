// thin_slab_lit_frag.cpp: twin of glsl/thin_slab_lit.frag, line for line.
#include "kernels/thin_slab/thin_slab.h"
#include "texture/sampler2d.h"

namespace st {

namespace {
constexpr int v_radiance = 0, v_uv = 1;  // inputs
}  // namespace

uint32_t ThinSlabLitFragment::inputs_read() const { return reads(v_radiance, "xyzw") | reads(v_uv, "xy"); }

void ThinSlabLitFragment::bind(const Bindings& b) { flag_ = &b.sampler("flag"); }

Vec4 ThinSlabLitFragment::main(const Fragment& frag) const {
    Vec3 texel = flag_->sample(frag.varying(v_uv).xy()).xyz();
    const Vec4& radiance = frag.varying(v_radiance);
    return Vec4(radiance.xyz() * texel, radiance.w);
}

}  // namespace st
