// lane_vec.h: GLSL's vector types with one invocation per lane: Vec2, Vec3,
// Vec4 of simd::Float (vecN), IVecN of Int (ivecN), UVecN of UInt (uvecN),
// BVecN of Mask (bvecN).
// A fragment twin writes `Vec3 n = normalize(Vec3(frag.varying(v_normal)));`
// where its GLSL writes `vec3 n = normalize(v_normal.xyz);`, `c.rgb() * 0.5f`
// where it writes `c.rgb * 0.5`, and `p.set_xz(q)` for `p.xz = q`. Only
// constructors, swizzles and componentwise operators live here; the GLSL
// built-ins (dot, normalize, exp, ...) are in shading/glsl_math.h, with
// llvmpipe's operation order.
#pragma once

#include <initializer_list>
#include <type_traits>
#include <utility>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "simd/lane_double.h"
#include "simd/lane_swizzle.h"
#include "simd/lane_uint.h"
#include "simd/lanes.h"

namespace st {

using simd::Float;
using simd::Int;
using simd::Mask;
using simd::UInt;
using simd::Double;
using simd::kLanes;

// GLSL's vecN (T = Float), ivecN (Int) and bvecN (Mask), N = 2, 3, 4, with
// one invocation per lane. Components are x, y, z, w; swizzles read and
// write as lane_swizzle.h says; constructors are GLSL's (a broadcast, the
// components, smaller vectors and scalars side by side, the first
// components of a larger vector, another component type converted).
template <class T, int N> struct LaneVec;

namespace lane_vec_detail {

// GLSL's conversions between component types in a constructor: float(int)
// rounds to nearest, int(float) truncates (NaN and out of range give
// INT32_MIN, as llvmpipe's cvttps2dq), float(bool) and int(bool) are 1 or
// 0, bool(x) is x != 0.
template <class To> struct Convert;
template <> struct Convert<Float> {
    static ST_INLINE Float from(Float x) { return x; }
    static ST_INLINE Float from(Double x) { return simd::to_float(x); }
    static ST_INLINE Float from(Int x) { return simd::to_float(x); }
    static ST_INLINE Float from(Mask m) { return simd::select(m, Float(1.0f), Float(0.0f)); }
    static ST_INLINE Float from(UInt x) { return simd::to_float(x); }
};
template <> struct Convert<Int> {
    static ST_INLINE Int from(Int x) { return x; }
    static ST_INLINE Int from(Double x) { return simd::itrunc(x); }
    static ST_INLINE Int from(Float x) { return simd::itrunc(x); }
    static ST_INLINE Int from(Mask m) { return simd::select(m, Int(1), Int(0)); }
    static ST_INLINE Int from(UInt x) { return simd::int_bits(x); }
};
template <> struct Convert<UInt> {  // uint(i) keeps the bits; uint(f) truncates (lane_uint.h)
    static ST_INLINE UInt from(UInt x) { return x; }
    static ST_INLINE UInt from(Float x) { return simd::to_uint(x); }
    static ST_INLINE UInt from(Int x) { return UInt(x); }
    static ST_INLINE UInt from(Mask m) { return simd::select(m, UInt(1u), UInt(0u)); }
};
// double(x): exact from float, int and uint; 1.0 or 0.0 from bool.
template <> struct Convert<Double> {
    static ST_INLINE Double from(Double x) { return x; }
    static ST_INLINE Double from(Float x) { return Double(x); }
    static ST_INLINE Double from(Int x) { return simd::to_double(x); }
    static ST_INLINE Double from(UInt x) {
        return simd::to_double(Int(simd::IntV(x.u() >> 1))) * Double(2.0) + simd::to_double(Int(x.v & 1));
    }
    static ST_INLINE Double from(Mask m) { return simd::select(m, Double(1.0), Double(0.0)); }
};
template <> struct Convert<Mask> {
    static ST_INLINE Mask from(UInt x) { return x != UInt(0u); }
    static ST_INLINE Mask from(Double x) { return x != Double(0.0); }
    static ST_INLINE Mask from(Mask m) { return m; }
    static ST_INLINE Mask from(Float x) { return x != Float(0.0f); }
    static ST_INLINE Mask from(Int x) { return x != Int(0); }
};

constexpr bool distinct(std::initializer_list<int> is) {
    for (auto a = is.begin(); a != is.end(); ++a)
        for (auto b = a + 1; b != is.end(); ++b)
            if (*a == *b) return false;
    return true;
}

// f(std::integral_constant<int, i>) for i = 0 .. N-1, in order.
template <int N, class F> ST_INLINE void for_each_index(F&& f) {
    [&]<int... I>(std::integer_sequence<int, I...>) { (f(std::integral_constant<int, I>()), ...); }(
        std::make_integer_sequence<int, N>());
}

}  // namespace lane_vec_detail

// What every size shares: components by index (at compile time, so that
// each component stays a register), swizzles, conversions. A write through
// a swizzle that repeats a component fails to compile where it is used.
#define ST_LANE_VEC_COMMON(N_)                                                                     \
    static constexpr int size = N_;                                                                \
    template <int I> ST_INLINE const T& component() const {                                        \
        return const_cast<LaneVec*>(this)->template component<I>();                                \
    }                                                                                              \
    /* v[i] for an index known or not at compile time (matrices' m[c][r]); */                    \
    /* an index outside the vector gives x, where GLSL leaves it undefined. */                     \
    ST_INLINE T& operator[](int i) {                                                               \
        T* r = &component<0>();                                                                    \
        lane_vec_detail::for_each_index<N_>([&](auto k) {                                          \
            if (i == decltype(k)::value) r = &component<decltype(k)::value>();                     \
        });                                                                                        \
        return *r;                                                                                 \
    }                                                                                              \
    ST_INLINE const T& operator[](int i) const { return (*const_cast<LaneVec*>(this))[i]; }        \
    template <int... I> ST_INLINE void assign(const LaneVec<T, int(sizeof...(I))>& v) {            \
        static_assert(lane_vec_detail::distinct({I...}), "GLSL refuses a write repeating a component"); \
        assign_from<0, I...>(v);                                                                   \
    }                                                                                              \
    template <class U> explicit LaneVec(const LaneVec<U, N_>& o) {                                 \
        lane_vec_detail::for_each_index<N_>([&](auto i) {                                          \
            constexpr int k = decltype(i)::value;                                                  \
            component<k>() = lane_vec_detail::Convert<T>::from(o.template component<k>());         \
        });                                                                                        \
    }                                                                                              \
    ST_SWIZZLES(N_)                                                                                \
                                                                                                   \
private:                                                                                           \
    template <int K, int I, int... Rest, int M> ST_INLINE void assign_from(const LaneVec<T, M>& v) { \
        component<I>() = v.template component<K>();                                                \
        if constexpr (sizeof...(Rest) > 0) assign_from<K + 1, Rest...>(v);                         \
    }                                                                                              \
                                                                                                   \
public:

template <class T> struct LaneVec<T, 2> {
    T x, y;
    LaneVec() = default;
    explicit LaneVec(T s) : x(s), y(s) {}
    LaneVec(T x_, T y_) : x(x_), y(y_) {}
    explicit LaneVec(const LaneVec<T, 3>& v) : x(v.x), y(v.y) {}
    explicit LaneVec(const LaneVec<T, 4>& v) : x(v.x), y(v.y) {}
    // A uniform (glm::vec2, ivec2 or bvec2), the same in every lane.
    template <class U, glm::qualifier Q> explicit LaneVec(const glm::vec<2, U, Q>& u) : x(T(u.x)), y(T(u.y)) {}
    template <int I> ST_INLINE T& component() {
        static_assert(I >= 0 && I < 2, "vec2 has x and y");
        if constexpr (I == 0) return x;
        else return y;
    }
    ST_LANE_VEC_COMMON(2)
};

template <class T> struct LaneVec<T, 3> {
    T x, y, z;
    LaneVec() = default;
    explicit LaneVec(T s) : x(s), y(s), z(s) {}
    LaneVec(T x_, T y_, T z_) : x(x_), y(y_), z(z_) {}
    LaneVec(const LaneVec<T, 2>& v, T z_) : x(v.x), y(v.y), z(z_) {}
    LaneVec(T x_, const LaneVec<T, 2>& v) : x(x_), y(v.x), z(v.y) {}
    explicit LaneVec(const LaneVec<T, 4>& v) : x(v.x), y(v.y), z(v.z) {}
    template <class U, glm::qualifier Q>
    explicit LaneVec(const glm::vec<3, U, Q>& u) : x(T(u.x)), y(T(u.y)), z(T(u.z)) {}
    template <int I> ST_INLINE T& component() {
        static_assert(I >= 0 && I < 3, "vec3 has x, y and z");
        if constexpr (I == 0) return x;
        else if constexpr (I == 1) return y;
        else return z;
    }
    ST_LANE_VEC_COMMON(3)
};

template <class T> struct LaneVec<T, 4> {
    T x, y, z, w;
    LaneVec() = default;
    explicit LaneVec(T s) : x(s), y(s), z(s), w(s) {}
    LaneVec(T x_, T y_, T z_, T w_) : x(x_), y(y_), z(z_), w(w_) {}
    LaneVec(const LaneVec<T, 3>& v, T w_) : x(v.x), y(v.y), z(v.z), w(w_) {}
    LaneVec(T x_, const LaneVec<T, 3>& v) : x(x_), y(v.x), z(v.y), w(v.z) {}
    LaneVec(const LaneVec<T, 2>& a, const LaneVec<T, 2>& b) : x(a.x), y(a.y), z(b.x), w(b.y) {}
    LaneVec(const LaneVec<T, 2>& v, T z_, T w_) : x(v.x), y(v.y), z(z_), w(w_) {}
    LaneVec(T x_, const LaneVec<T, 2>& v, T w_) : x(x_), y(v.x), z(v.y), w(w_) {}
    LaneVec(T x_, T y_, const LaneVec<T, 2>& v) : x(x_), y(y_), z(v.x), w(v.y) {}
    template <class U, glm::qualifier Q>
    explicit LaneVec(const glm::vec<4, U, Q>& u) : x(T(u.x)), y(T(u.y)), z(T(u.z)), w(T(u.w)) {}
    template <int I> ST_INLINE T& component() {
        static_assert(I >= 0 && I < 4, "vec4 has x, y, z and w");
        if constexpr (I == 0) return x;
        else if constexpr (I == 1) return y;
        else if constexpr (I == 2) return z;
        else return w;
    }
    ST_LANE_VEC_COMMON(4)
};

#undef ST_LANE_VEC_COMMON

// GLSL's scalar constructors that convert: float(i), float(b), int(x),
// int(b), bool(x), bool(i), with the rules above.
template <class T> ST_INLINE Float float_of(T v) { return lane_vec_detail::Convert<Float>::from(v); }
template <class T> ST_INLINE Int int_of(T v) { return lane_vec_detail::Convert<Int>::from(v); }
template <class T> ST_INLINE Mask bool_of(T v) { return lane_vec_detail::Convert<Mask>::from(v); }
template <class T> ST_INLINE UInt uint_of(T v) { return lane_vec_detail::Convert<UInt>::from(v); }
template <class T> ST_INLINE Double double_of(T v) { return lane_vec_detail::Convert<Double>::from(v); }

using Vec2 = LaneVec<Float, 2>;
using Vec3 = LaneVec<Float, 3>;
using Vec4 = LaneVec<Float, 4>;
using IVec2 = LaneVec<Int, 2>;
using IVec3 = LaneVec<Int, 3>;
using IVec4 = LaneVec<Int, 4>;
using BVec2 = LaneVec<Mask, 2>;
using BVec3 = LaneVec<Mask, 3>;
using BVec4 = LaneVec<Mask, 4>;
using UVec2 = LaneVec<UInt, 2>;
using UVec3 = LaneVec<UInt, 3>;
using UVec4 = LaneVec<UInt, 4>;
using DVec2 = LaneVec<Double, 2>;
using DVec3 = LaneVec<Double, 3>;
using DVec4 = LaneVec<Double, 4>;

namespace lane_vec_detail {
// LaneVec<R, N>(f(a[0], b[0]), ...) (or f(a[i])): built in place from its
// components, not default-constructed and then assigned, which left the
// zeroing stores of Float() in the hot loops (a relief frame 13 % slower).
template <class R, class T, int N, class F, int... I>
ST_INLINE LaneVec<R, N> each(const LaneVec<T, N>& a, F f, std::integer_sequence<int, I...>) {
    return LaneVec<R, N>(f(a.template component<I>())...);
}
template <class R, class T, int N, class F, int... I>
ST_INLINE LaneVec<R, N> each(const LaneVec<T, N>& a, const LaneVec<T, N>& b, F f, std::integer_sequence<int, I...>) {
    return LaneVec<R, N>(f(a.template component<I>(), b.template component<I>())...);
}
template <class R, class T, int N, class F> ST_INLINE LaneVec<R, N> each(const LaneVec<T, N>& a, F f) {
    return each<R>(a, f, std::make_integer_sequence<int, N>());
}
template <class R, class T, int N, class F>
ST_INLINE LaneVec<R, N> each(const LaneVec<T, N>& a, const LaneVec<T, N>& b, F f) {
    return each<R>(a, b, f, std::make_integer_sequence<int, N>());
}
}  // namespace lane_vec_detail

// Componentwise arithmetic, as GLSL's operators on vectors: vector op
// vector, vector op scalar and scalar op vector (the scalar taken as the
// same operand on every component, each operation rounded once, the
// operands in the order written). Float and Int vectors; % and the bit
// operators are Int's.
#define ST_LANE_VEC_OP(op)                                                                                    \
    template <class T, int N> ST_INLINE LaneVec<T, N> operator op(const LaneVec<T, N>& a, const LaneVec<T, N>& b) { \
        return lane_vec_detail::each<T>(a, b, [](const T& p, const T& q) { return p op q; });                 \
    }                                                                                                         \
    template <class T, int N>                                                                                 \
    ST_INLINE LaneVec<T, N> operator op(const LaneVec<T, N>& a, const std::type_identity_t<T>& s) {           \
        return lane_vec_detail::each<T>(a, [&](const T& p) { return p op s; });                               \
    }                                                                                                         \
    template <class T, int N>                                                                                 \
    ST_INLINE LaneVec<T, N> operator op(const std::type_identity_t<T>& s, const LaneVec<T, N>& a) {           \
        return lane_vec_detail::each<T>(a, [&](const T& p) { return s op p; });                               \
    }                                                                                                         \
    template <class T, int N, class U>                                                                        \
    ST_INLINE LaneVec<T, N>& operator op##=(LaneVec<T, N>& a, const U& b) {                                   \
        return a = a op b;                                                                                    \
    }
ST_LANE_VEC_OP(+)
ST_LANE_VEC_OP(-)
ST_LANE_VEC_OP(*)
ST_LANE_VEC_OP(/)
ST_LANE_VEC_OP(&)
ST_LANE_VEC_OP(|)
ST_LANE_VEC_OP(^)
#undef ST_LANE_VEC_OP

template <class T, int N> ST_INLINE LaneVec<T, N> operator-(const LaneVec<T, N>& a) {
    return lane_vec_detail::each<T>(a, [](const T& p) { return -p; });
}

// GLSL's == and != on whole vectors: one bool, all components equal (or
// not), per lane.
template <class T, int N> ST_INLINE Mask operator==(const LaneVec<T, N>& a, const LaneVec<T, N>& b) {
    Mask all = a.x == b.x;
    lane_vec_detail::for_each_index<N>([&](auto i) {
        constexpr int k = decltype(i)::value;
        if constexpr (k > 0) all = all && (a.template component<k>() == b.template component<k>());
    });
    return all;
}
template <class T, int N> ST_INLINE Mask operator!=(const LaneVec<T, N>& a, const LaneVec<T, N>& b) {
    return !(a == b);
}

// Each lane takes a's components where m is set, b's elsewhere.
template <class T, int N> ST_INLINE LaneVec<T, N> select(Mask m, const LaneVec<T, N>& a, const LaneVec<T, N>& b) {
    return lane_vec_detail::each<T>(a, b, [&](const T& p, const T& q) { return simd::select(m, p, q); });
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
