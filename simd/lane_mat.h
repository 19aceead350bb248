// lane_mat.h: GLSL's matrix types with one invocation per lane: MatCxR is
// C columns of R-component lane vectors (GLSL's matCxR; Mat2, Mat3, Mat4
// are the square ones; DMatCxR the dmat ones, of Double lanes), m[c] a
// column and m[c][r] an element, as in GLSL.
// Constructors are GLSL's: a diagonal from one scalar, the columns, the
// C * R scalars column by column, another matrix's top-left with the
// identity elsewhere, a uniform glm matrix. The operators do what GLSL IR's
// lower_mat_op_to_vec makes of them (docs/llvmpipe/glsl-builtins.md 5.1),
// each product and sum rounded on its own, in this order:
// - m * v: ((m[0] v.x + m[1] v.y) + m[2] v.z) + m[3] v.w, left to right;
// - v * m: component j is dot(v, m[j]), summed from the last term back;
// - a * b: column j is a * b[j];
// - m * s, m / s (a real division of each element), m + n, m - n, -m:
//   element by element.
// A chain (a * b) * v is rewritten by GLSL IR as a * (b * v): a twin writes
// it that way (shading/builtins/matrix.h says more).
#pragma once

#include <glm/matrix.hpp>

#include "simd/lane_vec.h"

namespace st {

// T is Float (GLSL's matCxR) or Double (dmatCxR).
template <int C, int R, class T = Float> struct LaneMat {
    using Column = LaneVec<T, R>;
    // The host type of one element (a uniform's glm matrix holds these).
    using Host = std::conditional_t<std::is_same_v<T, Double>, double, float>;
    Column col[C];

    LaneMat() = default;
    // s on the diagonal, 0 elsewhere (GLSL mat3(s)).
    explicit LaneMat(T s) {
        for (int c = 0; c < C; ++c)
            for (int r = 0; r < R; ++r) col[c][r] = c == r ? s : T(0.0f);
    }
    // The columns.
    template <class... Cols>
        requires(sizeof...(Cols) == C && (std::is_same_v<Cols, Column> && ...))
    LaneMat(const Cols&... cols) : col{cols...} {}
    // C * R scalars, column by column (GLSL mat2(a, b, c, d)).
    template <class... S>
        requires(sizeof...(S) == C * R && C * R > 1 && (std::is_convertible_v<S, T> && ...))
    LaneMat(const S&... s) {
        const T e[] = {T(s)...};
        for (int c = 0; c < C; ++c)
            for (int r = 0; r < R; ++r) col[c][r] = e[c * R + r];
    }
    // Another matrix's top-left; the identity's elements elsewhere.
    template <int C2, int R2>
        requires(C2 != C || R2 != R)
    explicit LaneMat(const LaneMat<C2, R2, T>& m) {
        for (int c = 0; c < C; ++c)
            for (int r = 0; r < R; ++r) col[c][r] = c < C2 && r < R2 ? m[c][r] : T(c == r ? 1.0f : 0.0f);
    }
    // A uniform, the same in every lane.
    template <glm::qualifier Q> explicit LaneMat(const glm::mat<C, R, Host, Q>& m) {
        for (int c = 0; c < C; ++c)
            for (int r = 0; r < R; ++r) col[c][r] = T(m[c][r]);
    }

    ST_INLINE Column& operator[](int c) { return col[c]; }
    ST_INLINE const Column& operator[](int c) const { return col[c]; }
};

using Mat2 = LaneMat<2, 2>;
using Mat3 = LaneMat<3, 3>;
using Mat4 = LaneMat<4, 4>;
using Mat2x3 = LaneMat<2, 3>;
using Mat2x4 = LaneMat<2, 4>;
using Mat3x2 = LaneMat<3, 2>;
using Mat3x4 = LaneMat<3, 4>;
using Mat4x2 = LaneMat<4, 2>;
using Mat4x3 = LaneMat<4, 3>;
using DMat2 = LaneMat<2, 2, Double>;
using DMat3 = LaneMat<3, 3, Double>;
using DMat4 = LaneMat<4, 4, Double>;
using DMat2x3 = LaneMat<2, 3, Double>;
using DMat2x4 = LaneMat<2, 4, Double>;
using DMat3x2 = LaneMat<3, 2, Double>;
using DMat3x4 = LaneMat<3, 4, Double>;
using DMat4x2 = LaneMat<4, 2, Double>;
using DMat4x3 = LaneMat<4, 3, Double>;

// m * v: the columns scaled by v's components, summed left to right.
template <int C, int R, class T> ST_INLINE LaneVec<T, R> operator*(const LaneMat<C, R, T>& m, const LaneVec<T, C>& v) {
    LaneVec<T, R> sum = m[0] * v.x;
    for (int c = 1; c < C; ++c) sum = sum + m[c] * v[c];
    return sum;
}
// v * m: dot(v, m[j]) per column, the products summed from the last back
// (NIR's lowered dot).
template <int C, int R, class T> ST_INLINE LaneVec<T, C> operator*(const LaneVec<T, R>& v, const LaneMat<C, R, T>& m) {
    LaneVec<T, C> r;
    for (int j = 0; j < C; ++j) {
        T sum = v[R - 1] * m[j][R - 1];
        for (int k = R - 2; k >= 0; --k) sum = sum + v[k] * m[j][k];
        r[j] = sum;
    }
    return r;
}
// a * b: column j is a * b[j].
template <int K, int R, int C, class T>
ST_INLINE LaneMat<C, R, T> operator*(const LaneMat<K, R, T>& a, const LaneMat<C, K, T>& b) {
    LaneMat<C, R, T> p;
    for (int j = 0; j < C; ++j) p[j] = a * b[j];
    return p;
}

// Element by element.
template <int C, int R, class T, class F> ST_INLINE LaneMat<C, R, T> each_column(const LaneMat<C, R, T>& m, F f) {
    LaneMat<C, R, T> r;
    for (int c = 0; c < C; ++c) r[c] = f(m[c], c);
    return r;
}
template <int C, int R, class T> ST_INLINE LaneMat<C, R, T> operator*(const LaneMat<C, R, T>& m, std::type_identity_t<T> s) {
    return each_column(m, [&](const LaneVec<T, R>& v, int) { return v * s; });
}
template <int C, int R, class T> ST_INLINE LaneMat<C, R, T> operator*(std::type_identity_t<T> s, const LaneMat<C, R, T>& m) {
    return each_column(m, [&](const LaneVec<T, R>& v, int) { return s * v; });
}
template <int C, int R, class T> ST_INLINE LaneMat<C, R, T> operator/(const LaneMat<C, R, T>& m, std::type_identity_t<T> s) {
    return each_column(m, [&](const LaneVec<T, R>& v, int) { return v / s; });
}
template <int C, int R, class T> ST_INLINE LaneMat<C, R, T> operator+(const LaneMat<C, R, T>& a, const LaneMat<C, R, T>& b) {
    return each_column(a, [&](const LaneVec<T, R>& v, int c) { return v + b[c]; });
}
template <int C, int R, class T> ST_INLINE LaneMat<C, R, T> operator-(const LaneMat<C, R, T>& a, const LaneMat<C, R, T>& b) {
    return each_column(a, [&](const LaneVec<T, R>& v, int c) { return v - b[c]; });
}
template <int C, int R, class T> ST_INLINE LaneMat<C, R, T> operator-(const LaneMat<C, R, T>& m) {
    return each_column(m, [&](const LaneVec<T, R>& v, int) { return -v; });
}

}  // namespace st
