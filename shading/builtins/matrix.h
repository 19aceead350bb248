// matrix.h: GLSL's matrix built-ins (matrixCompMult, outerProduct,
// transpose, determinant, inverse) as llvmpipe computes them, for lane
// matrices (simd/lane_mat.h) and glm matrices alike
// (docs/llvmpipe/glsl-builtins.md 5; proved by the scenes
// conformance-builtins-matrix-*). The products are lane_mat.h's operators.
// Where llvmpipe is not what a reader expects:
// - determinant and inverse are Mesa's cofactor expansions, every product
//   and difference rounded alone; inverse divides each adjugate element by
//   the determinant (a real division).
// - inverse(mat4) sums its determinant right-nested, m00 a00 + (m01 a10 +
//   (m02 a20 + m03 a30)), and determinant(mat4) as a dot product (from the
//   last term back): the two determinants of one matrix can differ.
// - A chain P * V * M * v runs as P * (V * (M * v)) (GLSL IR's
//   do_algebraic, one level per pass, twice): a twin writes it so.
// glm's own determinant and inverse round differently: for glm matrices
// call these as glsl::determinant, glsl::inverse.
#pragma once

#include <glm/matrix.hpp>

#include "simd/lane_mat.h"

namespace st::glsl {

namespace matrix_detail {
// N for a square N x N matrix, lanes or glm; 0 for anything else.
template <class M> inline constexpr int square_size = 0;
template <int N, class T> inline constexpr int square_size<LaneMat<N, N, T>> = N;
template <int N, glm::qualifier Q> inline constexpr int square_size<glm::mat<N, N, float, Q>> = N;
template <int N, glm::qualifier Q> inline constexpr int square_size<glm::mat<N, N, double, Q>> = N;  // dmatN: the same expansions
}  // namespace matrix_detail

// matrixCompMult: element by element.
template <int C, int R, class T> ST_INLINE LaneMat<C, R, T> matrixCompMult(const LaneMat<C, R, T>& a, const LaneMat<C, R, T>& b) {
    LaneMat<C, R, T> r;
    for (int c = 0; c < C; ++c) r[c] = a[c] * b[c];
    return r;
}

// outerProduct(c, r): column i is c * r[i].
template <int R, int C, class T> ST_INLINE LaneMat<C, R, T> outerProduct(const LaneVec<T, R>& c, const LaneVec<T, C>& r) {
    LaneMat<C, R, T> m;
    for (int i = 0; i < C; ++i) m[i] = c * r[i];
    return m;
}

template <int C, int R, class T> ST_INLINE LaneMat<R, C, T> transpose(const LaneMat<C, R, T>& m) {
    LaneMat<R, C, T> t;
    for (int c = 0; c < C; ++c)
        for (int r = 0; r < R; ++r) t[r][c] = m[c][r];
    return t;
}

// determinant of mat2: m00 m11 - m10 m01.
template <class M>
    requires(matrix_detail::square_size<M> == 2)
ST_INLINE auto determinant(const M& m) {
    return m[0][0] * m[1][1] - m[1][0] * m[0][1];
}
// Mesa's a b - c d, the pattern of every cofactor below.
template <class S> ST_INLINE S ab_cd(const S& a, const S& b, const S& c, const S& d) { return a * b - c * d; }

// determinant of mat3: (m00 f1 - m01 f2) + m02 f3.
template <class M>
    requires(matrix_detail::square_size<M> == 3)
ST_INLINE auto determinant(const M& m) {
    const auto f1 = ab_cd(m[1][1], m[2][2], m[1][2], m[2][1]);
    const auto f2 = ab_cd(m[1][0], m[2][2], m[1][2], m[2][0]);
    const auto f3 = ab_cd(m[1][0], m[2][1], m[1][1], m[2][0]);
    return (m[0][0] * f1 - m[0][1] * f2) + m[0][2] * f3;
}

namespace matrix_detail {
// Mesa's SubFactor00 ... SubFactor18 of a mat4.
template <class M> ST_INLINE auto sub_factors(const M& m) {
    using S = std::decay_t<decltype(m[0][0])>;
    struct Factors {
        S f[19];
    } s;
    s.f[0] = ab_cd(m[2][2], m[3][3], m[3][2], m[2][3]);
    s.f[1] = ab_cd(m[2][1], m[3][3], m[3][1], m[2][3]);
    s.f[2] = ab_cd(m[2][1], m[3][2], m[3][1], m[2][2]);
    s.f[3] = ab_cd(m[2][0], m[3][3], m[3][0], m[2][3]);
    s.f[4] = ab_cd(m[2][0], m[3][2], m[3][0], m[2][2]);
    s.f[5] = ab_cd(m[2][0], m[3][1], m[3][0], m[2][1]);
    s.f[6] = ab_cd(m[1][2], m[3][3], m[3][2], m[1][3]);
    s.f[7] = ab_cd(m[1][1], m[3][3], m[3][1], m[1][3]);
    s.f[8] = ab_cd(m[1][1], m[3][2], m[3][1], m[1][2]);
    s.f[9] = ab_cd(m[1][0], m[3][3], m[3][0], m[1][3]);
    s.f[10] = ab_cd(m[1][0], m[3][2], m[3][0], m[1][2]);
    s.f[11] = ab_cd(m[1][1], m[3][3], m[3][1], m[1][3]);
    s.f[12] = ab_cd(m[1][0], m[3][1], m[3][0], m[1][1]);
    s.f[13] = ab_cd(m[1][2], m[2][3], m[2][2], m[1][3]);
    s.f[14] = ab_cd(m[1][1], m[2][3], m[2][1], m[1][3]);
    s.f[15] = ab_cd(m[1][1], m[2][2], m[2][1], m[1][2]);
    s.f[16] = ab_cd(m[1][0], m[2][3], m[2][0], m[1][3]);
    s.f[17] = ab_cd(m[1][0], m[2][2], m[2][0], m[1][2]);
    s.f[18] = ab_cd(m[1][0], m[2][1], m[2][0], m[1][1]);
    return s;
}
// (a p - b q) + c r: each cofactor's bracket.
template <class S> ST_INLINE S bracket(const S& a, const S& p, const S& b, const S& q, const S& c, const S& r) {
    return (a * p - b * q) + c * r;
}
}  // namespace matrix_detail

// determinant of mat4: dot(m[0], adj0), adj0 the first column of cofactors
// (NIR's dot: ((m03 a3 + m02 a2) + m01 a1) + m00 a0).
template <class M>
    requires(matrix_detail::square_size<M> == 4)
ST_INLINE auto determinant(const M& m) {
    using matrix_detail::bracket;
    const auto factors = matrix_detail::sub_factors(m);
    const auto& s = factors.f;
    const auto a0 = bracket(m[1][1], s[0], m[1][2], s[1], m[1][3], s[2]);
    const auto a1 = -bracket(m[1][0], s[0], m[1][2], s[3], m[1][3], s[4]);
    const auto a2 = bracket(m[1][0], s[1], m[1][1], s[3], m[1][3], s[5]);
    const auto a3 = -bracket(m[1][0], s[2], m[1][1], s[4], m[1][2], s[5]);
    return ((m[0][3] * a3 + m[0][2] * a2) + m[0][1] * a1) + m[0][0] * a0;
}

// inverse of mat2: [[m11, -m01], [-m10, m00]] / (m00 m11 - m10 m01).
template <class M>
    requires(matrix_detail::square_size<M> == 2)
ST_INLINE M inverse(const M& m) {
    M adj = m;
    adj[0][0] = m[1][1];
    adj[0][1] = -m[0][1];
    adj[1][0] = -m[1][0];
    adj[1][1] = m[0][0];
    const auto det = m[0][0] * m[1][1] - m[1][0] * m[0][1];
    for (int c = 0; c < 2; ++c)
        for (int r = 0; r < 2; ++r) adj[c][r] = adj[c][r] / det;
    return adj;
}

// inverse of mat3: the cofactors, then each divided by
// (m00 f11_22_21_12 - m01 f10_22_20_12) + m02 f10_21_20_11.
template <class M>
    requires(matrix_detail::square_size<M> == 3)
ST_INLINE M inverse(const M& m) {
    const auto f11_22_21_12 = ab_cd(m[1][1], m[2][2], m[2][1], m[1][2]);
    const auto f10_22_20_12 = ab_cd(m[1][0], m[2][2], m[2][0], m[1][2]);
    const auto f10_21_20_11 = ab_cd(m[1][0], m[2][1], m[2][0], m[1][1]);
    M adj = m;
    adj[0][0] = f11_22_21_12;
    adj[1][0] = -f10_22_20_12;
    adj[2][0] = f10_21_20_11;
    adj[0][1] = -ab_cd(m[0][1], m[2][2], m[2][1], m[0][2]);
    adj[1][1] = ab_cd(m[0][0], m[2][2], m[2][0], m[0][2]);
    adj[2][1] = -ab_cd(m[0][0], m[2][1], m[2][0], m[0][1]);
    adj[0][2] = ab_cd(m[0][1], m[1][2], m[1][1], m[0][2]);
    adj[1][2] = -ab_cd(m[0][0], m[1][2], m[1][0], m[0][2]);
    adj[2][2] = ab_cd(m[0][0], m[1][1], m[1][0], m[0][1]);
    const auto det = (m[0][0] * f11_22_21_12 - m[0][1] * f10_22_20_12) + m[0][2] * f10_21_20_11;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) adj[c][r] = adj[c][r] / det;
    return adj;
}

// inverse of mat4: Mesa's 16 cofactors from the sub-factors, each divided
// by the right-nested m00 a00 + (m01 a10 + (m02 a20 + m03 a30)).
template <class M>
    requires(matrix_detail::square_size<M> == 4)
ST_INLINE M inverse(const M& m) {
    using matrix_detail::bracket;
    const auto factors = matrix_detail::sub_factors(m);
    const auto& s = factors.f;
    M adj = m;
    adj[0][0] = bracket(m[1][1], s[0], m[1][2], s[1], m[1][3], s[2]);
    adj[1][0] = -bracket(m[1][0], s[0], m[1][2], s[3], m[1][3], s[4]);
    adj[2][0] = bracket(m[1][0], s[1], m[1][1], s[3], m[1][3], s[5]);
    adj[3][0] = -bracket(m[1][0], s[2], m[1][1], s[4], m[1][2], s[5]);
    adj[0][1] = -bracket(m[0][1], s[0], m[0][2], s[1], m[0][3], s[2]);
    adj[1][1] = bracket(m[0][0], s[0], m[0][2], s[3], m[0][3], s[4]);
    adj[2][1] = -bracket(m[0][0], s[1], m[0][1], s[3], m[0][3], s[5]);
    adj[3][1] = bracket(m[0][0], s[2], m[0][1], s[4], m[0][2], s[5]);
    adj[0][2] = bracket(m[0][1], s[6], m[0][2], s[7], m[0][3], s[8]);
    adj[1][2] = -bracket(m[0][0], s[6], m[0][2], s[9], m[0][3], s[10]);
    adj[2][2] = bracket(m[0][0], s[11], m[0][1], s[9], m[0][3], s[12]);
    adj[3][2] = -bracket(m[0][0], s[8], m[0][1], s[10], m[0][2], s[12]);
    adj[0][3] = -bracket(m[0][1], s[13], m[0][2], s[14], m[0][3], s[15]);
    adj[1][3] = bracket(m[0][0], s[13], m[0][2], s[16], m[0][3], s[17]);
    adj[2][3] = -bracket(m[0][0], s[14], m[0][1], s[16], m[0][3], s[18]);
    adj[3][3] = bracket(m[0][0], s[15], m[0][1], s[17], m[0][2], s[18]);
    const auto det = m[0][0] * adj[0][0] + (m[0][1] * adj[1][0] + (m[0][2] * adj[2][0] + m[0][3] * adj[3][0]));
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) adj[c][r] = adj[c][r] / det;
    return adj;
}

}  // namespace st::glsl
