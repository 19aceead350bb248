// derivatives.h: dFdx and dFdy of any value a fragment twin computes, from
// the 2x2 quad its lane belongs to. In lane order (x, y), (x+1, y),
// (x, y+1), (x+1, y+1): dFdx is the difference along the lane's own row and
// dFdy along its own column, which is what llvmpipe computes for the fine
// and the coarse forms alike (docs/llvmpipe/).
#pragma once

#include "simd/lane_vec.h"

namespace st {

namespace detail {
// Lane indices of each lane's right (left) neighbour in its row and top
// (bottom) neighbour in its column, quad by quad.
#define ST_QUAD(q, a, b, c, d) 4 * q + a, 4 * q + b, 4 * q + c, 4 * q + d
#if ST_LANES == 8
#define ST_QUAD_LANES(a, b, c, d) {ST_QUAD(0, a, b, c, d), ST_QUAD(1, a, b, c, d)}
#else
#define ST_QUAD_LANES(a, b, c, d) \
    {ST_QUAD(0, a, b, c, d), ST_QUAD(1, a, b, c, d), ST_QUAD(2, a, b, c, d), ST_QUAD(3, a, b, c, d)}
#endif
inline constexpr simd::IntV kRowRight = ST_QUAD_LANES(1, 1, 3, 3), kRowLeft = ST_QUAD_LANES(0, 0, 2, 2);
inline constexpr simd::IntV kColumnTop = ST_QUAD_LANES(2, 3, 2, 3), kColumnBottom = ST_QUAD_LANES(0, 1, 0, 1);
#undef ST_QUAD_LANES
#undef ST_QUAD
}  // namespace detail

ST_INLINE Float dFdx(Float v) { return shuffle(v, detail::kRowRight) - shuffle(v, detail::kRowLeft); }
ST_INLINE Float dFdy(Float v) { return shuffle(v, detail::kColumnTop) - shuffle(v, detail::kColumnBottom); }
// fwidth(p) = abs(dFdx(p)) + abs(dFdy(p)) (Mesa's builtin_functions.cpp).
ST_INLINE Float fwidth(Float v) { return simd::abs(dFdx(v)) + simd::abs(dFdy(v)); }
ST_INLINE Vec2 dFdx(const Vec2& v) { return {dFdx(v.x), dFdx(v.y)}; }
ST_INLINE Vec2 dFdy(const Vec2& v) { return {dFdy(v.x), dFdy(v.y)}; }
ST_INLINE Vec4 dFdx(const Vec4& v) { return {dFdx(v.x), dFdx(v.y), dFdx(v.z), dFdx(v.w)}; }
ST_INLINE Vec4 dFdy(const Vec4& v) { return {dFdy(v.x), dFdy(v.y), dFdy(v.z), dFdy(v.w)}; }

}  // namespace st
