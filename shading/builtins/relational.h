// relational.h: GLSL's vector relational built-ins for lane vectors:
// lessThan, lessThanEqual, greaterThan, greaterThanEqual, equal, notEqual
// (of vec, ivec and uvec, giving a bvec), any, all and not_ (GLSL's `not`,
// a C++ keyword). Float compares are NIR's: <, <=, >, >= and == ordered
// (false with a NaN), != unordered (true with a NaN), as Float's operators
// already are. For glm vectors glm's own functions mean the same.
#pragma once

#include "simd/lane_vec.h"

namespace st::glsl {

#define ST_GLSL_RELATIONAL(name, op)                                                               \
    template <class T, int N> ST_INLINE LaneVec<Mask, N> name(const LaneVec<T, N>& a, const LaneVec<T, N>& b) { \
        return lane_vec_detail::each<Mask>(a, b, [](const T& p, const T& q) { return p op q; });    \
    }
ST_GLSL_RELATIONAL(lessThan, <)
ST_GLSL_RELATIONAL(lessThanEqual, <=)
ST_GLSL_RELATIONAL(greaterThan, >)
ST_GLSL_RELATIONAL(greaterThanEqual, >=)
ST_GLSL_RELATIONAL(equal, ==)
ST_GLSL_RELATIONAL(notEqual, !=)
#undef ST_GLSL_RELATIONAL

template <int N> ST_INLINE Mask any(const LaneVec<Mask, N>& b) {
    Mask r = b.x;
    lane_vec_detail::for_each_index<N>([&](auto i) {
        if constexpr (decltype(i)::value > 0) r = r || b.template component<decltype(i)::value>();
    });
    return r;
}
template <int N> ST_INLINE Mask all(const LaneVec<Mask, N>& b) {
    Mask r = b.x;
    lane_vec_detail::for_each_index<N>([&](auto i) {
        if constexpr (decltype(i)::value > 0) r = r && b.template component<decltype(i)::value>();
    });
    return r;
}
template <int N> ST_INLINE LaneVec<Mask, N> not_(const LaneVec<Mask, N>& b) {
    return lane_vec_detail::each<Mask>(b, [](const Mask& m) { return !m; });
}

}  // namespace st::glsl
