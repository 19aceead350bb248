// surface_frag.cpp: twin of glsl/profile/surface.frag, line for line.
#include "kernels/profile/profile.h"

#include "shading/derivatives.h"
#include "shading/glsl_math.h"

namespace st {

namespace {
constexpr int v_position = 0, v_normal = 1;  // inputs
}  // namespace

uint32_t SurfaceFragment::inputs_read() const { return reads(v_position, "xyz") | reads(v_normal, "xyz"); }

Vec4 SurfaceFragment::main(const Fragment& frag) const {
    const Vec3 dpdx = dFdx(frag.varying(v_position).xyz());
    const Vec3 dpdy = dFdy(frag.varying(v_position).xyz());
    const Float area = glsl::length(glsl::cross(dpdx, dpdy));
    const Vec4 position_area(frag.varying(v_position).xyz(), area);
    const Vec4 normal(glsl::normalize(frag.varying(v_normal).xyz()), Float(1.0f));
    return channel_ == 0 ? position_area : normal;
}

}  // namespace st
