// relief_shading.cpp: twin of glsl/relief/relief_shading.glsl, function for
// function.
#include "kernels/relief/relief_shading.h"

#include "shading/glsl_math.h"

namespace st::relief {

Vec3 blinn_phong(const Vec3& albedo, const Vec3& n, const Vec3& l, const Vec3& v, Float ambient, Float specular) {
    const Float diffuse = glsl::max(glsl::dot(n, l), Float(0.0f));
    const Vec3 h = glsl::normalize(l + v);
    Float s = glsl::max(glsl::dot(n, h), Float(0.0f));
    s = s * s;
    s = s * s;
    s = s * s;
    s = s * s;
    s = s * s;
    return albedo * (ambient + diffuse) + Vec3(specular * s);
}

Vec3 decode_normal(const Vec4& texel) {
    return glsl::normalize(texel.xyz() * Float(2.0f) - Vec3(Float(1.0f)));
}

}  // namespace st::relief
