// profile_gather.cpp: twin of glsl/profile/profile_gather.glsl, function for
// function. In the loop, values the GLSL computes and uses in the same pass
// are used as computed (NIR SSA values, unmasked); the stores to the loop's
// variables (m, k) are masked (shading/control_flow.h).
#include "kernels/profile/profile_gather.h"

#include "kernels/profile/profile_optics.h"
#include "shading/glsl_math.h"
#include "texture/sampler2d.h"

namespace st {

void GatherInputs::read(const Bindings& b, bool thin) {
    irradiance = &b.sampler("irradiance");
    irradiance_back = thin ? &b.sampler("irradiance_back") : nullptr;
    position_area = &b.sampler("position_area");
    surface_normal = &b.sampler("surface_normal");
    profile_R = &b.sampler("profile_R");
    profile_T = &b.sampler("profile_T");
    pattern = &b.sampler("pattern");
    samples = b.get_int("samples");
    r_max = b.get_float("r_max");
    profile_size = b.get_float("profile_size");
    texel_uv = b.get_float("texel_uv");
    rough = b.get_int("rough") == 1;
    eta = b.get_float("eta");
    inv_m2 = b.get_float("inv_m2");
    beckmann_norm = b.get_float("beckmann_norm");
    eye = b.get_vec3("eye");
    light_direction = b.get_vec3("light_direction");
    light_irradiance = b.get_vec3("light_irradiance");
    spot = b.get_vec4("spot");
    edge = b.get_vec4("edge");
}

namespace profile {

Vec3 blended_profile(Float c, const Vec3& R, const Vec3& T) {
    return Float(0.5f) * (c + Float(1.0f)) * R + Float(0.5f) * (Float(1.0f) - c) * T;
}

Vec3 diffused_light(Exec& exec, const GatherInputs& u, const Vec3& x, const Vec3& n_s, const Vec2& uv, bool thin) {
    const Float lod0(0.0f);
    const Float here_area = u.position_area->sample_lod(uv, lod0).w;
    const Float uv_per_mm = glsl::inversesqrt(here_area) * Float(u.texel_uv);
    const float table_scale = (u.profile_size - 1.0f) / u.profile_size;
    const float table_offset = 0.5f / u.profile_size;
    Vec3 m(Float(0.0f));
    Int k = 0;
    exec.loop([&](Loop& loop) {
        loop.break_if(!(k < Int(u.samples)));
        const Vec4 s = u.pattern->fetch(k, Int(0), Int(0));
        const Vec2 uv_k = uv + s.xy() * uv_per_mm;
        // The texture-space targets share one shape, the two tables another:
        // each group's taps are found once (texture/bilinear_taps.h).
        const BilinearTaps at_k = u.position_area->bilinear_taps(uv_k);
        const Vec4 at = u.position_area->sample_lod(at_k);
        const Vec3 n_l = u.surface_normal->sample_lod(at_k, texel::kReadRGB).xyz();
        const Float r = glsl::length(at.xyz() - x);
        const Vec2 tc(simd::sqrt(r / Float(u.r_max)) * Float(table_scale) + Float(table_offset), Float(0.5f));
        const BilinearTaps at_r = u.profile_R->bilinear_taps(tc);
        const Vec3 R = u.profile_R->sample_lod(at_r, texel::kReadRGB).xyz();
        const Vec3 T = u.profile_T->sample_lod(at_r, texel::kReadRGB).xyz();
        const Float c = glsl::dot(n_s, n_l);
        Vec3 light = u.irradiance->sample_lod(at_k, texel::kReadRGB).xyz() * blended_profile(c, R, T);
        if (thin) light = light + u.irradiance_back->sample_lod(at_k, texel::kReadRGB).xyz() * blended_profile(-c, R, T);
        const Mask on_layout = uv_k.x >= Float(0.0f) && uv_k.x <= Float(1.0f) && uv_k.y >= Float(0.0f) &&
                               uv_k.y <= Float(1.0f);
        const Float w = glsl::select(r < Float(u.r_max) && on_layout, s.z * (at.w / here_area), Float(0.0f));
        exec.assign(m, m + light * w);
        exec.assign(k, k + Int(1));
    });
    return m;
}

Vec3 surface_reflection(const GatherInputs& u, const Vec3& p, const Vec3& n) {
    const Vec3 v = glsl::normalize(Vec3(u.eye) - p);
    const Vec3 l(u.light_direction);
    const Float cos_i = glsl::max(glsl::dot(n, l), Float(0.0f));
    const Float f_r = torrance_sparrow(n, l, v, Float(u.eta), Float(u.inv_m2), Float(u.beckmann_norm));
    return Vec3(u.light_irradiance) * (f_r * cos_i * light_pattern(Vec2(p.x, p.y), u.spot, u.edge));
}

}  // namespace profile
}  // namespace st
