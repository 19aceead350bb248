// thin_slab_baseline_frag.cpp: twin of glsl/thin_slab_baseline.frag, line for line.
#include "shading/glsl_math.h"
#include "kernels/thin_slab/thin_slab.h"
#include "kernels/thin_slab/thin_slab_model.h"
#include "texture/sampler2d.h"

namespace st {

namespace {
constexpr int v_position = 0, v_normal = 1, v_uv = 2;  // inputs
}  // namespace

uint32_t ThinSlabBaselineFragment::inputs_read() const {
    return reads(v_position, "xyz") | reads(v_normal, "xyz") | reads(v_uv, "xy");
}

void ThinSlabBaselineFragment::bind(const Bindings& b) {
    u_.read(b, false);
    flag_ = &b.sampler("flag");
}

Vec4 ThinSlabBaselineFragment::main(const Fragment& frag) const {
    Vec3 texel = flag_->sample(frag.varying(v_uv).xy()).xyz();
    Vec3 lit = lambert_baseline(frag.varying(v_position).xyz(), glsl::normalize(frag.varying(v_normal).xyz()),
                                Vec3(u_.eye), Vec3(u_.light), Float(u_.power), Vec3(u_.albedo) * texel * 0.8f);
    return Vec4(lit, 0.2f);
}

}  // namespace st
