// geometric.h: GLSL's geometric built-ins (dot, length, distance, cross,
// normalize, faceforward, reflect, refract) as llvmpipe computes them, for
// float and every vector, lanes and glm (docs/llvmpipe/glsl-builtins.md,
// section 4; proved by the scenes conformance-builtins-geometric-*).
// - dot() is products, unfused, summed from the last component back
//   (lower_fdot's reduction): ((w w' + z z') + y y') + x x'. Not fsum's left
//   to right, and not a fused chain.
// - normalize(v) = v * inversesqrt(dot(v, v)), so normalize(0) is NaN; for a
//   float, normalize(x) is sign(x). length(v) = sqrt(dot(v, v)); for a
//   float, sqrt(x * x), and distance(a, b) = abs(a - b).
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "shading/builtins/common.h"
#include "shading/builtins/exponential.h"
#include "shading/builtins/selection.h"

namespace st::glsl {

// Calls below are qualified: for glm vectors, unqualified ones would find
// glm's own dot, length, ... (which sum left to right) by argument lookup.

// dot(a, b): the products, then from the last component back.
ST_INLINE float dot(float a, float b) { return a * b; }
ST_INLINE Float dot(Float a, Float b) { return a * b; }
template <class V>
    requires componentwise::is_vector<V>
ST_INLINE auto dot(const V& a, const V& b) {
    constexpr int n = componentwise::Traits<V>::size;
    auto sum = a.y * b.y + a.x * b.x;  // n == 2
    if constexpr (n == 3) sum = (a.z * b.z + a.y * b.y) + a.x * b.x;
    if constexpr (n == 4) sum = ((a.w * b.w + a.z * b.z) + a.y * b.y) + a.x * b.x;
    return sum;
}

ST_INLINE float length(float x) { return scalar::sqrt(x * x); }
ST_INLINE Float length(Float x) { return simd::sqrt(x * x); }
template <class V>
    requires componentwise::is_vector<V>
ST_INLINE auto length(const V& v) {
    return glsl::sqrt(glsl::dot(v, v));
}

ST_INLINE float distance(float a, float b) { return glsl::abs(a - b); }
ST_INLINE Float distance(Float a, Float b) { return glsl::abs(a - b); }
template <class V>
    requires componentwise::is_vector<V>
ST_INLINE auto distance(const V& a, const V& b) {
    return glsl::length(a - b);
}

// cross(a, b) as Mesa's builtin writes it: a.yzx * b.zxy - a.zxy * b.yzx,
// two products and one difference per component.
template <class V>
    requires(componentwise::is_vector<V> && componentwise::Traits<V>::size == 3)
ST_INLINE V cross(const V& a, const V& b) {
    return V(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

ST_INLINE float normalize(float x) { return glsl::sign(x); }
ST_INLINE Float normalize(Float x) { return glsl::sign(x); }
template <class V>
    requires componentwise::is_vector<V>
ST_INLINE V normalize(const V& v) {
    const auto s = glsl::inversesqrt(glsl::dot(v, v));
    return componentwise::map<V>([&](const auto& c) { return c * s; }, v);
}

// faceforward(N, I, Nref): N where dot(Nref, I) < 0, else -N (ordered: a
// NaN dot gives -N).
ST_INLINE float faceforward(float n, float i, float nref) { return glsl::dot(nref, i) < 0.0f ? n : -n; }
ST_INLINE Float faceforward(Float n, Float i, Float nref) { return glsl::select(glsl::dot(nref, i) < Float(0.0f), n, -n); }
template <class V>
    requires componentwise::is_vector<V>
ST_INLINE V faceforward(const V& n, const V& i, const V& nref) {
    const auto front = glsl::dot(nref, i) < componentwise::ScalarOf<V>(0.0f);
    return componentwise::map<V>([&](const auto& c) { return glsl::select(front, c, -c); }, n);
}

// GLSL reflect(I, N): Mesa's built-in writes I - 2 * (dot(N, I) * N), and
// nir_opt_algebraic moves the constant inward ((a * b) * #c -> (a * #c) * b,
// the inner product used once), so llvmpipe runs I - (dot(N, I) * 2) * N.
// The same value unless dot(N, I) * 2 overflows: then llvmpipe's is
// infinite (found by conformance-builtins-geometric-reflect).
ST_INLINE float reflect(float i, float n) { return i - (glsl::dot(n, i) * 2.0f) * n; }
ST_INLINE Float reflect(Float i, Float n) { return i - (glsl::dot(n, i) * Float(2.0f)) * n; }
template <class V>
    requires componentwise::is_vector<V>
ST_INLINE V reflect(const V& i, const V& n) {
    using S = componentwise::ScalarOf<V>;
    const S d2 = glsl::dot(n, i) * S(2.0f);
    return componentwise::map<V>([&](const S& ic, const S& nc) { return ic - d2 * nc; }, i, n);
}

// GLSL refract(I, N, eta), as Mesa's built-in writes it:
// k = 1 - eta * (eta * (1 - dot(N, I) * dot(N, I))); the zero vector where
// k < 0 (total internal reflection; a NaN k takes the other side), else
// eta * I - (eta * dot(N, I) + sqrt(k)) * N.
template <class V, class S>
ST_INLINE V refract_of(const V& i, const V& n, S eta, bool constant_eta = false) {
    const S n_dot_i = glsl::dot(n, i);
    const S k = constant_eta ? S(1.0f) - (eta * eta) * (S(1.0f) - n_dot_i * n_dot_i)
                             : S(1.0f) - eta * (eta * (S(1.0f) - n_dot_i * n_dot_i));
    const S f = eta * n_dot_i + glsl::sqrt(k);
    const auto total = k < S(0.0f);
    if constexpr (componentwise::is_vector<V>)
        return componentwise::map<V>([&](const S& ic, const S& nc) { return glsl::select(total, S(0.0f), eta * ic - f * nc); },
                                     i, n);
    else
        return glsl::select(total, S(0.0f), eta * i - f * n);
}
ST_INLINE float refract(float i, float n, float eta) { return refract_of(i, n, eta); }
ST_INLINE Float refract(Float i, Float n, Float eta) { return refract_of(i, n, eta); }
template <class V>
    requires componentwise::is_vector<V>
ST_INLINE V refract(const V& i, const V& n, const componentwise::ScalarOf<V>& eta) {
    return refract_of(i, n, eta);
}
// refract() with eta a constant (a literal, or a const the compiler
// propagates): NIR folds eta * (eta * x) to (eta * eta) * x, the product of
// the two constants rounded once (nir_opt_algebraic's #a * (b * #c) rule,
// constant folding in float), which differs from refract() in the last bit
// (compiler-rewrites.md, entry 20; conformance-builtins-vertex-geometric).
ST_INLINE float refract_constant_eta(float i, float n, float eta) { return refract_of(i, n, eta, true); }
ST_INLINE Float refract_constant_eta(Float i, Float n, Float eta) { return refract_of(i, n, eta, true); }
template <class V>
    requires componentwise::is_vector<V>
ST_INLINE V refract_constant_eta(const V& i, const V& n, const componentwise::ScalarOf<V>& eta) {
    return refract_of(i, n, eta, true);
}

}  // namespace st::glsl
