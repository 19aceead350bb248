// gather_thin_frag.cpp: twin of glsl/profile/gather_thin.frag, line for line.
#include "kernels/profile/profile.h"

#include "kernels/profile/profile_gather.h"
#include "shading/glsl_math.h"
#include "texture/sampler2d.h"

namespace st {

namespace {
constexpr int v_position = 0, v_normal = 1, v_uv = 2;  // inputs
}  // namespace

void GatherThinFragment::bind(const Bindings& b) {
    u_.read(b, true);
    albedo_ = &b.sampler("albedo");
}

uint32_t GatherThinFragment::inputs_read() const {
    return reads(v_position, "xyz") | reads(v_normal, "xyz") | reads(v_uv, "xy");
}

Vec4 GatherThinFragment::main(const Fragment& frag) const {
    const Vec3 n = glsl::normalize(frag.varying(v_normal).xyz());
    const Vec3 m = profile::diffused_light(frag.exec(), u_, frag.varying(v_position).xyz(), n,
                                           frag.varying(v_uv).xy(), true);
    const Vec3 tex = albedo_->sample(frag.varying(v_uv).xy()).xyz();
    Vec3 colour = m * tex * Float(0.31830988f);
    if (u_.rough) colour = colour + profile::surface_reflection(u_, frag.varying(v_position).xyz(), n);
    return Vec4(colour, Float(1.0f));
}

}  // namespace st
