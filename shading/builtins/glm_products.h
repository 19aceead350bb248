// glm_products.h: GLSL's `*` of matrices for vertex twins, which hold glm
// types: glsl::mul(m, v), glsl::mul(v, m) and glsl::mul(a, b) for every
// matCxR, in the order GLSL IR's lower_mat_op_to_vec gives them (the same
// as simd/lane_mat.h's operators for fragment twins;
// docs/llvmpipe/glsl-builtins.md 5.1), each product and sum rounded on its
// own:
// - m * v: ((m[0] v.x + m[1] v.y) + m[2] v.z) + m[3] v.w, left to right;
// - v * m: component j is dot(v, m[j]), summed from the last term back;
// - a * b: column j is a * b[j].
// glm's own mat4 * vec4 sums in pairs, (m[0] v.x + m[1] v.y) + (m[2] v.z +
// m[3] v.w), and its v * m sums left to right: a twin that writes glm's `*`
// there is off by an ulp where the sums round. (glm's m * v of the other
// shapes and its a * b happen to sum as GLSL does; mul is right for all.)
// A chain (a * b) * v runs as a * (b * v) (compiler-rewrites.md, entry 12).
#pragma once

#include <glm/matrix.hpp>

#include "simd/lanes.h"

namespace st::glsl {

template <int C, int R, class T, glm::qualifier Q>
ST_INLINE glm::vec<R, T, Q> mul(const glm::mat<C, R, T, Q>& m, const glm::vec<C, T, Q>& v) {
    glm::vec<R, T, Q> sum = m[0] * v[0];
    for (int c = 1; c < C; ++c) sum = sum + m[c] * v[c];
    return sum;
}

template <int C, int R, class T, glm::qualifier Q>
ST_INLINE glm::vec<C, T, Q> mul(const glm::vec<R, T, Q>& v, const glm::mat<C, R, T, Q>& m) {
    glm::vec<C, T, Q> r;
    for (int j = 0; j < C; ++j) {
        T sum = v[R - 1] * m[j][R - 1];
        for (int k = R - 2; k >= 0; --k) sum = sum + v[k] * m[j][k];
        r[j] = sum;
    }
    return r;
}

template <int K, int R, int C, class T, glm::qualifier Q>
ST_INLINE glm::mat<C, R, T, Q> mul(const glm::mat<K, R, T, Q>& a, const glm::mat<C, K, T, Q>& b) {
    glm::mat<C, R, T, Q> p;
    for (int j = 0; j < C; ++j) p[j] = mul(a, b[j]);
    return p;
}

}  // namespace st::glsl
