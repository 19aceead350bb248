// selection.h: GLSL's choices between values per invocation: the ternary
// and an if/else that only assigns (select), and an if/else whose sides
// are expensive (if_else, which skips a side no lane takes).
#pragma once

#include <glm/vec3.hpp>

#include "simd/lane_vec.h"

namespace st::glsl {

// GLSL's c ? a : b (NIR bcsel): both sides are evaluated, and each lane
// takes one. A small if/else that only assigns is the same after NIR's
// peephole_select; twins write it this way so one source serves both types.
ST_INLINE float select(bool c, float a, float b) { return c ? a : b; }
ST_INLINE double select(bool c, double a, double b) { return c ? a : b; }
ST_INLINE glm::vec3 select(bool c, const glm::vec3& a, const glm::vec3& b) { return c ? a : b; }
using simd::select;  // Float, Int and Mask per lane
ST_INLINE Vec3 select(Mask c, const Vec3& a, const Vec3& b) { return st::select(c, a, b); }
ST_INLINE Vec4 select(Mask c, const Vec4& a, const Vec4& b) { return st::select(c, a, b); }

// GLSL's `if (c) return then(); else return otherwise();` (or a ternary
// whose sides are expensive): each lane gets the side its condition picks,
// and a side that no lane takes is not evaluated, as a GPU skips a branch
// no invocation takes. Twin functions have no side effects, so this gives
// the bits of select(c, then(), otherwise()) at a fraction of the cost
// when a whole vector goes one way.
template <class Then, class Otherwise>
ST_INLINE auto if_else(bool c, Then then, Otherwise otherwise) {
    return c ? then() : otherwise();
}
template <class Then, class Otherwise>
ST_INLINE auto if_else(Mask c, Then then, Otherwise otherwise) {
    const unsigned lanes = simd::bits(c);
    if (lanes == (1u << kLanes) - 1) return then();
    if (lanes == 0) return otherwise();
    return glsl::select(c, then(), otherwise());
}

}  // namespace st::glsl

namespace st::glsl {

// GLSL's a[i] of a constant int array with i varying per lane (the tables
// of the conformance programs). An index outside the array reads nothing
// and gives 0: GLSL leaves it undefined, and no program here relies on it.
template <size_t N> ST_INLINE Int element(const int32_t (&table)[N], Int i) {
    const Mask inside = !(i < Int(0)) && (i < Int(int32_t(N)));
    return simd::gather(table, i, inside);
}
template <size_t N> ST_INLINE int32_t element(const int32_t (&table)[N], int32_t i) {
    return i >= 0 && size_t(i) < N ? table[i] : 0;
}

}  // namespace st::glsl
