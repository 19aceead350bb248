// irradiance_frag.cpp: twin of glsl/profile/irradiance.frag, line for line.
#include "kernels/profile/profile.h"

#include "kernels/profile/profile_optics.h"
#include "shading/glsl_math.h"
#include "texture/sampler2d.h"

namespace st {

namespace {
constexpr int v_position = 0, v_normal = 1;  // inputs
}  // namespace

void IrradianceFragment::bind(const Bindings& b) {
    light_direction_ = b.get_vec3("light_direction");
    light_irradiance_ = b.get_vec3("light_irradiance");
    eta_ = b.get_float("eta");
    rough_ = b.get_int("rough") == 1;
    rho_dt_ = &b.sampler("rho_dt");
    back_offset_ = b.get_float("back_offset");
    spot_ = b.get_vec4("spot");
    edge_ = b.get_vec4("edge");
}

uint32_t IrradianceFragment::inputs_read() const { return reads(v_position, "xyz") | reads(v_normal, "xyz"); }

Vec4 IrradianceFragment::main(const Fragment& frag) const {
    const Vec3 n0 = glsl::normalize(frag.varying(v_normal).xyz());
    const bool back = back_offset_ > 0.0f;
    const Vec3 n = back ? Vec3(-n0.x, -n0.y, -n0.z) : n0;
    const Vec3 p = frag.varying(v_position).xyz() - Float(back_offset_) * n0;
    const Float cos_i = glsl::max(glsl::dot(n, Vec3(light_direction_)), Float(0.0f));
    const Float t = profile::transmittance_in(glsl::min(cos_i, Float(1.0f)), Float(eta_), rough_, *rho_dt_);
    const Float e = cos_i * t * profile::light_pattern(Vec2(p.x, p.y), spot_, edge_);
    return Vec4(Vec3(light_irradiance_) * e, Float(1.0f));
}

}  // namespace st
