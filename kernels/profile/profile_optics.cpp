// profile_optics.cpp: twin of glsl/profile/profile_optics.glsl, function for
// function.
#include "kernels/profile/profile_optics.h"

#include "shading/derivatives.h"
#include "shading/glsl_math.h"
#include "texture/sampler2d.h"

namespace st::profile {

Float fresnel_reflectance(Float eta, Float cos_i, Float cos_t) {
    const Float rs = (cos_i - eta * cos_t) / glsl::max(cos_i + eta * cos_t, Float(1e-6f));
    const Float rp = (cos_t - eta * cos_i) / glsl::max(cos_t + eta * cos_i, Float(1e-6f));
    return (rs * rs + rp * rp) * Float(0.5f);
}

Float transmittance_in(Float cos_i, Float eta, bool rough, const Sampler2D& rho_dt) {
    const Float sin2_t = (Float(1.0f) - cos_i * cos_i) / (eta * eta);
    const Float cos_t = simd::sqrt(glsl::max(Float(1.0f) - sin2_t, Float(0.0f)));
    const Float smooth_t = Float(1.0f) - fresnel_reflectance(eta, cos_i, cos_t);
    // The GLSL reads the table whichever the boundary (both sides of its ?:
    // run); a twin need not, the read changes no bit of the smooth result.
    if (!rough) return smooth_t;
    return rho_dt.sample_lod(Vec2(cos_i, Float(0.5f)), Float(0.0f)).x;
}

Float coverage(Float s) {
    const Float w = glsl::max(fwidth(s), Float(1e-30f));
    return glsl::min(glsl::max(s / w + Float(0.5f), Float(0.0f)), Float(1.0f));
}

Float light_pattern(const Vec2& p, const glm::vec4& spot, const glm::vec4& edge) {
    const Vec2 d = p - Vec2(glm::vec2(spot));
    const Float in_spot = spot.z > 0.0f ? coverage(Float(spot.z) - simd::sqrt(glsl::dot(d, d))) : Float(0.0f);
    const Float beyond_edge =
        edge.w > 0.0f ? coverage(p.x * Float(edge.x) + (p.y * Float(edge.y) - Float(edge.z))) : Float(0.0f);
    const bool patterned = spot.z > 0.0f || edge.w > 0.0f;
    return patterned ? glsl::max(in_spot, beyond_edge) : Float(1.0f);
}

Float torrance_sparrow(const Vec3& n, const Vec3& l, const Vec3& v, Float eta, Float inv_m2, Float beckmann_norm) {
    const Float cos_i = glsl::dot(n, l);
    const Float cos_o = glsl::dot(n, v);
    const Vec3 h = glsl::normalize(l + v);
    const Float nh = glsl::max(glsl::dot(n, h), Float(1e-6f));
    const Float vh = glsl::max(glsl::dot(v, h), Float(1e-6f));
    const Float nh2 = nh * nh;
    const Float tan2 = (Float(1.0f) - nh2) / nh2;
    const Float d = glsl::exp2(-tan2 * Float(glsl::kLog2e) * inv_m2) * beckmann_norm / (nh2 * nh2);
    const Float g =
        glsl::min(glsl::min(Float(2.0f) * nh * cos_o / vh, Float(2.0f) * nh * cos_i / vh), Float(1.0f));
    const Float sin2_t = (Float(1.0f) - vh * vh) / (eta * eta);
    const Float cos_t = simd::sqrt(glsl::max(Float(1.0f) - sin2_t, Float(0.0f)));
    const Float f = fresnel_reflectance(eta, vh, cos_t);
    const Mask lit = cos_i > Float(0.0f) && cos_o > Float(0.0f);
    return glsl::select(lit, d * g * f / glsl::max(Float(4.0f) * cos_i * cos_o, Float(1e-12f)), Float(0.0f));
}

}  // namespace st::profile
