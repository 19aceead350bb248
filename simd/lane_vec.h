// lane_vec.h: GLSL's vec2, vec3 and vec4 with one invocation per lane
// (Vec2, Vec3, Vec4 of simd::Float), and bool as Mask. A fragment twin
// writes `Vec3 n = normalize(Vec3(frag.varying(v_normal)));` where its GLSL
// writes `vec3 n = normalize(v_normal.xyz);`. Only componentwise operators
// live here; the GLSL built-ins (dot, normalize, exp, ...) are in
// glsl_math.h, with llvmpipe's operation order.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "simd/lanes.h"

namespace st {

using simd::Float;
using simd::Int;
using simd::Mask;
using simd::kLanes;

struct Vec2 {
    Float x, y;
    Vec2() = default;
    Vec2(Float x_, Float y_) : x(x_), y(y_) {}
    explicit Vec2(const glm::vec2& u) : x(u.x), y(u.y) {}  // a uniform, in every lane
};

struct Vec3 {
    Float x, y, z;
    Vec3() = default;
    explicit Vec3(Float s) : x(s), y(s), z(s) {}
    Vec3(Float x_, Float y_, Float z_) : x(x_), y(y_), z(z_) {}
    explicit Vec3(const glm::vec3& u) : x(u.x), y(u.y), z(u.z) {}
};

struct Vec4 {
    Float x, y, z, w;
    Vec4() = default;
    explicit Vec4(Float s) : x(s), y(s), z(s), w(s) {}
    Vec4(Float x_, Float y_, Float z_, Float w_) : x(x_), y(y_), z(z_), w(w_) {}
    Vec4(const Vec3& v, Float w_) : x(v.x), y(v.y), z(v.z), w(w_) {}
    explicit Vec4(const glm::vec4& u) : x(u.x), y(u.y), z(u.z), w(u.w) {}
    Vec2 xy() const { return {x, y}; }
    Vec3 xyz() const { return {x, y, z}; }
};

#define ST_LANE_VEC_OPS(V, ...)                                                              \
    ST_INLINE V operator+(const V& a, const V& b) { return {__VA_ARGS__(+)}; }               \
    ST_INLINE V operator-(const V& a, const V& b) { return {__VA_ARGS__(-)}; }               \
    ST_INLINE V operator*(const V& a, const V& b) { return {__VA_ARGS__(*)}; }               \
    ST_INLINE V operator/(const V& a, const V& b) { return {__VA_ARGS__(/)}; }
#define ST_VEC2_EACH(op) a.x op b.x, a.y op b.y
#define ST_VEC3_EACH(op) a.x op b.x, a.y op b.y, a.z op b.z
#define ST_VEC4_EACH(op) a.x op b.x, a.y op b.y, a.z op b.z, a.w op b.w
ST_LANE_VEC_OPS(Vec2, ST_VEC2_EACH)
ST_LANE_VEC_OPS(Vec3, ST_VEC3_EACH)
ST_LANE_VEC_OPS(Vec4, ST_VEC4_EACH)
#undef ST_LANE_VEC_OPS
#undef ST_VEC2_EACH
#undef ST_VEC3_EACH
#undef ST_VEC4_EACH

// vecN * float and float * vecN: each component times the scalar; vecN +
// float adds it to each.
ST_INLINE Vec2 operator*(const Vec2& a, Float s) { return {a.x * s, a.y * s}; }
ST_INLINE Vec2 operator+(const Vec2& a, Float s) { return {a.x + s, a.y + s}; }
ST_INLINE Vec2 operator-(const Vec2& a, Float s) { return {a.x - s, a.y - s}; }
ST_INLINE Vec3 operator*(const Vec3& a, Float s) { return {a.x * s, a.y * s, a.z * s}; }
ST_INLINE Vec3 operator*(Float s, const Vec3& a) { return {s * a.x, s * a.y, s * a.z}; }
ST_INLINE Vec4 operator*(const Vec4& a, Float s) { return {a.x * s, a.y * s, a.z * s, a.w * s}; }

ST_INLINE Vec2 select(Mask m, const Vec2& a, const Vec2& b) { return {select(m, a.x, b.x), select(m, a.y, b.y)}; }
ST_INLINE Vec3 select(Mask m, const Vec3& a, const Vec3& b) {
    return {select(m, a.x, b.x), select(m, a.y, b.y), select(m, a.z, b.z)};
}
ST_INLINE Vec4 select(Mask m, const Vec4& a, const Vec4& b) {
    return {select(m, a.x, b.x), select(m, a.y, b.y), select(m, a.z, b.z), select(m, a.w, b.w)};
}

// The types a shader function has when it is written once for both: F is
// `float` (vertex twins, host code) or `Float` (fragment twins).
template <class F> struct ShaderTypes;
template <> struct ShaderTypes<float> {
    using Bool = bool;
    using V3 = glm::vec3;
    using V4 = glm::vec4;
};
template <> struct ShaderTypes<Float> {
    using Bool = Mask;
    using V3 = Vec3;
    using V4 = Vec4;
};
template <class F> using BoolOf = typename ShaderTypes<F>::Bool;
template <class F> using Vec3Of = typename ShaderTypes<F>::V3;
template <class F> using Vec4Of = typename ShaderTypes<F>::V4;

}  // namespace st
