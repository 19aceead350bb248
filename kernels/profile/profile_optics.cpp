// profile_optics.cpp: twin of glsl/profile/profile_optics.glsl, function for
// function.
#include "kernels/profile/profile_optics.h"

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

}  // namespace st::profile
