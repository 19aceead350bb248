// componentwise.h: GLSL's vector forms of the componentwise built-ins,
// written once. A built-in defined for float and Float gets, from one macro
// line, its vecN forms for fragment twins (LaneVec<Float, N>) and vertex
// twins (glm::vec<N, float>), and its dvecN forms where it has double ones
// (LaneVec<Double, N>, glm::dvecN): each component computed alone, as NIR's
// lower_alu_to_scalar splits it. The forms GLSL has with a scalar among
// vectors (mod(vec3, float), clamp(vec3, float, float), mix(vec3, vec3,
// float), step(float, vec3), ...) take that scalar as every component.
#pragma once

#include <cstdint>

#include <glm/vector_relational.hpp>

#include "simd/lane_vec.h"

namespace st::glsl::componentwise {

template <class V> struct Traits;
template <int N> struct Traits<LaneVec<Float, N>> {
    using Scalar = Float;
    static constexpr int size = N;
    template <class R> using With = LaneVec<R, N>;
    template <int I> static ST_INLINE const Float& get(const LaneVec<Float, N>& v) { return v.template component<I>(); }
};
template <int N> struct Traits<LaneVec<Double, N>> {
    using Scalar = Double;
    static constexpr int size = N;
    template <class R> using With = LaneVec<R, N>;
    template <int I> static ST_INLINE const Double& get(const LaneVec<Double, N>& v) { return v.template component<I>(); }
};
// Integer vectors, for the built-ins that take them (the bit casts).
template <class T, int N> struct LaneTraits {
    using Scalar = T;
    static constexpr int size = N;
    template <class R> using With = LaneVec<R, N>;
    template <int I> static ST_INLINE const T& get(const LaneVec<T, N>& v) { return v.template component<I>(); }
};
template <int N> struct Traits<LaneVec<Int, N>> : LaneTraits<Int, N> {};
template <int N> struct Traits<LaneVec<UInt, N>> : LaneTraits<UInt, N> {};
template <class T, int N, glm::qualifier Q> struct GlmTraits {
    using Scalar = T;
    static constexpr int size = N;
    template <class R> using With = glm::vec<N, R, Q>;
    template <int I> static ST_INLINE const T& get(const glm::vec<N, T, Q>& v) { return v[I]; }
};
template <int N, glm::qualifier Q> struct Traits<glm::vec<N, int32_t, Q>> : GlmTraits<int32_t, N, Q> {};
template <int N, glm::qualifier Q> struct Traits<glm::vec<N, uint32_t, Q>> : GlmTraits<uint32_t, N, Q> {};
template <int N, glm::qualifier Q> struct Traits<glm::vec<N, double, Q>> {
    using Scalar = double;
    static constexpr int size = N;
    template <class R> using With = glm::vec<N, R, Q>;
    template <int I> static ST_INLINE const double& get(const glm::vec<N, double, Q>& v) { return v[I]; }
};
template <int N, glm::qualifier Q> struct Traits<glm::vec<N, float, Q>> {
    using Scalar = float;
    static constexpr int size = N;
    template <class R> using With = glm::vec<N, R, Q>;
    template <int I> static ST_INLINE const float& get(const glm::vec<N, float, Q>& v) { return v[I]; }
};

// A vector argument's component I, or a scalar argument itself.
template <int I, class V, class A> ST_INLINE decltype(auto) part(const A& a) {
    if constexpr (std::is_same_v<A, V>) return Traits<V>::template get<I>(a);
    else return typename Traits<V>::Scalar(a);
}

// f of every argument's component I.
template <int I, class V, class F, class... A> ST_INLINE auto at(F& f, const A&... args) {
    return f(part<I, V>(args)...);
}
// R-vector of f(part<0>(args)...), f(part<1>(args)...), ...
template <class V, class R, class F, class... A, int... I>
ST_INLINE auto apply(F f, std::integer_sequence<int, I...>, const A&... args) {
    return typename Traits<V>::template With<R>(at<I, V>(f, args...)...);
}
template <class V, class F, class... A> ST_INLINE auto map(F f, const A&... args) {
    using R = decltype(f(part<0, V>(args)...));
    return apply<V, R>(f, std::make_integer_sequence<int, Traits<V>::size>(), args...);
}

template <class T> inline constexpr bool is_vector = requires { Traits<T>::size; };
template <class V> using ScalarOf = typename Traits<V>::Scalar;

}  // namespace st::glsl::componentwise

// name(v) for every vector type, from name(x) for its component type.
#define ST_GLSL_COMPONENTWISE_1(name)                                                              \
    template <class V>                                                                             \
        requires componentwise::is_vector<V>                                                       \
    ST_INLINE auto name(const V& v) {                                                              \
        return componentwise::map<V>([](const auto& x) { return name(x); }, v);                    \
    }
// name(a, b) for vectors, and with either argument the component type.
#define ST_GLSL_COMPONENTWISE_2(name)                                                              \
    template <class V>                                                                             \
        requires componentwise::is_vector<V>                                                       \
    ST_INLINE auto name(const V& a, const V& b) {                                                  \
        return componentwise::map<V>([](const auto& x, const auto& y) { return name(x, y); }, a, b); \
    }                                                                                              \
    template <class V>                                                                             \
        requires componentwise::is_vector<V>                                                       \
    ST_INLINE auto name(const V& a, const componentwise::ScalarOf<V>& b) {          \
        return componentwise::map<V>([](const auto& x, const auto& y) { return name(x, y); }, a, b); \
    }                                                                                              \
    template <class V>                                                                             \
        requires componentwise::is_vector<V>                                                       \
    ST_INLINE auto name(const componentwise::ScalarOf<V>& a, const V& b) {          \
        return componentwise::map<V>([](const auto& x, const auto& y) { return name(x, y); }, a, b); \
    }
// name(a, b, c) in GLSL's four shapes: all vectors; the last, or the last
// two, the component type (clamp(v, lo, hi), mix(a, b, t)); the first two
// (smoothstep(e0, e1, v)).
#define ST_GLSL_COMPONENTWISE_3_BODY(name)                                                         \
    {                                                                                              \
        return componentwise::map<V>(                                                              \
            [](const auto& x, const auto& y, const auto& z) { return name(x, y, z); }, a, b, c);   \
    }
#define ST_GLSL_COMPONENTWISE_3(name)                                                              \
    template <class V>                                                                             \
        requires componentwise::is_vector<V>                                                       \
    ST_INLINE auto name(const V& a, const V& b, const V& c) ST_GLSL_COMPONENTWISE_3_BODY(name)     \
    template <class V>                                                                             \
        requires componentwise::is_vector<V>                                                       \
    ST_INLINE auto name(const V& a, const V& b, const componentwise::ScalarOf<V>& c)               \
        ST_GLSL_COMPONENTWISE_3_BODY(name)                                                         \
    template <class V>                                                                             \
        requires componentwise::is_vector<V>                                                       \
    ST_INLINE auto name(const V& a, const componentwise::ScalarOf<V>& b, const componentwise::ScalarOf<V>& c) \
        ST_GLSL_COMPONENTWISE_3_BODY(name)                                                         \
    template <class V>                                                                             \
        requires componentwise::is_vector<V>                                                       \
    ST_INLINE auto name(const componentwise::ScalarOf<V>& a, const componentwise::ScalarOf<V>& b, const V& c) \
        ST_GLSL_COMPONENTWISE_3_BODY(name)
