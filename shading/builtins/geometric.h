// geometric.h: GLSL's geometric built-ins (dot, cross, length,
// normalize, reflect, refract) as llvmpipe computes them
// (docs/llvmpipe/glsl-builtins.md, section 4).
// - dot() is lowered to products, unfused (lower_fdot), and for vec3 summed
//   as x + (y + z): measured bit for bit, though fsum3 reads left to right.
// - normalize(v) = v * inversesqrt(dot(v, v)); length(v) = sqrt(dot(v, v)).
#pragma once

#include <glm/vec3.hpp>

#include "shading/builtins/exponential.h"
#include "shading/builtins/selection.h"

namespace st::glsl {

// Measured against llvmpipe (thin-slab scenes, bit for bit): the three
// products are summed as x + (y + z), not left to right as fsum3 reads.
template <class V> ST_INLINE auto dot3(const V& a, const V& b) {
    const auto xx = a.x * b.x, yy = a.y * b.y, zz = a.z * b.z;
    const auto yz = yy + zz;
    return xx + yz;
}
ST_INLINE float dot(const glm::vec3& a, const glm::vec3& b) { return dot3(a, b); }
ST_INLINE Float dot(const Vec3& a, const Vec3& b) { return dot3(a, b); }

// dot(vec2, vec2): one sum of two products, so no order to choose.
ST_INLINE Float dot(const Vec2& a, const Vec2& b) { return a.x * b.x + a.y * b.y; }

// cross(a, b) as Mesa's builtin writes it: a.yzx * b.zxy - a.zxy * b.yzx,
// two products and one difference per component.
ST_INLINE Vec3 cross(const Vec3& a, const Vec3& b) {
    return Vec3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

ST_INLINE float length(const glm::vec3& v) { return std::sqrt(dot(v, v)); }
ST_INLINE Float length(const Vec3& v) { return simd::sqrt(dot(v, v)); }

ST_INLINE glm::vec3 normalize(const glm::vec3& v) {
    const float s = inversesqrt(dot(v, v));
    return glm::vec3(v.x * s, v.y * s, v.z * s);
}
ST_INLINE Vec3 normalize(const Vec3& v) {
    const Float s = inversesqrt(dot(v, v));
    return Vec3(v.x * s, v.y * s, v.z * s);
}

// GLSL reflect(I, N), as Mesa's built-in writes it: I - 2 * (dot(N, I) * N)
// (the factor 2 is exact, so its place in the product does not matter).
ST_INLINE Vec3 reflect(const Vec3& i, const Vec3& n) {
    const Float d = dot(n, i);
    return i - Vec3(Float(2.0f)) * (Vec3(d) * n);
}

// GLSL refract(I, N, eta), as Mesa's built-in writes it:
// k = 1 - eta * (eta * (1 - dot(N, I) * dot(N, I))); the zero vector where
// k < 0 (total internal reflection), else eta * I - (eta * dot(N, I) + sqrt(k)) * N.
ST_INLINE Vec3 refract(const Vec3& i, const Vec3& n, Float eta) {
    const Float n_dot_i = dot(n, i);
    const Float k = Float(1.0f) - eta * (eta * (Float(1.0f) - n_dot_i * n_dot_i));
    const Vec3 r = Vec3(eta) * i - Vec3(eta * n_dot_i + simd::sqrt(k)) * n;
    return glsl::select(k < Float(0.0f), Vec3(Float(0.0f)), r);
}

}  // namespace st::glsl
