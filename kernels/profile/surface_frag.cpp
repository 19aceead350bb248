// surface_frag.cpp: twin of glsl/profile/surface.frag, line for line.
#include "kernels/profile/profile.h"

#include "shading/derivatives.h"
#include "shading/glsl_math.h"
#include "texture/sampler2d.h"

namespace st {

namespace {
constexpr int v_position = 0, v_normal = 1;  // inputs
}  // namespace

uint32_t SurfaceFragment::inputs_read() const { return reads(v_position, "xyz") | reads(v_normal, "xyz"); }

void SurfaceFragment::bind(const Bindings& b) {
    channel_ = b.get_int("channel");
    thickness_map_ = &b.sampler("thickness_map");
    displacement_ = b.get_float("displacement");
}

Vec4 SurfaceFragment::main(const Fragment& frag) const {
    Vec3 p = frag.varying(v_position).xyz();
    if (displacement_ > 0.0f) {
        const Float h = thickness_map_->fetch(simd::itrunc(frag.frag_coord().x), simd::itrunc(frag.frag_coord().y),
                                              Int(0)).x;
        p = p + glsl::normalize(frag.varying(v_normal).xyz()) * (Float(displacement_) * h);
    }
    const Vec3 dpdx = dFdx(p);
    const Vec3 dpdy = dFdy(p);
    const Float area = glsl::length(glsl::cross(dpdx, dpdy));
    const Vec4 position_area(p, area);
    const Vec4 normal(glsl::normalize(frag.varying(v_normal).xyz()), Float(1.0f));
    return channel_ == 0 ? position_area : normal;
}

}  // namespace st
