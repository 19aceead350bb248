// relief_shading.cpp: twin of glsl/relief/relief_shading.glsl, function for
// function.
#include "kernels/relief/relief_shading.h"

#include "shading/glsl_math.h"

namespace st::relief {

Float highlight32(const Vec3& n, const Vec3& l, const Vec3& v) {
    const Vec3 h = glsl::normalize(l + v);
    Float s = glsl::max(glsl::dot(n, h), Float(0.0f));
    s = s * s;
    s = s * s;
    s = s * s;
    s = s * s;
    s = s * s;
    return s;
}

Vec3 lit_blinn_phong(const Vec3& albedo, const Vec3& n, const Vec3& l, const Vec3& v, Float ambient, Float specular,
                     const Vec3& light) {
    const Float diffuse = glsl::max(glsl::dot(n, l), Float(0.0f));
    const Float s = highlight32(n, l, v);
    return albedo * (Vec3(ambient) + Vec3(diffuse) * light) + Vec3(specular * s) * light;
}

Vec3 blinn_phong(const Vec3& albedo, const Vec3& n, const Vec3& l, const Vec3& v, Float ambient, Float specular) {
    return lit_blinn_phong(albedo, n, l, v, ambient, specular, Vec3(Float(1.0f)));
}

Vec3 decode_normal(const Vec4& texel) {
    return glsl::normalize(texel.xyz() * Float(2.0f) - Vec3(Float(1.0f)));
}

Float fresnel_reflectance(Float n1, Float n2, Float cos_i, Float cos_t) {
    const Float rs = (n1 * cos_i - n2 * cos_t) / glsl::max(n1 * cos_i + n2 * cos_t, Float(1e-6f));
    const Float rp = (n1 * cos_t - n2 * cos_i) / glsl::max(n1 * cos_t + n2 * cos_i, Float(1e-6f));
    return (rs * rs + rp * rp) * Float(0.5f);
}

}  // namespace st::relief
