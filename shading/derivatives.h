// derivatives.h: dFdx and dFdy of any value a fragment twin computes, from
// the 2x2 quad its lane belongs to. In lane order (x, y), (x+1, y),
// (x, y+1), (x+1, y+1): dFdx is the difference along the lane's own row and
// dFdy along its own column, which is what llvmpipe computes for the fine
// and the coarse forms alike (docs/llvmpipe/).
#pragma once

#include "simd/lane_vec.h"
#include "simd/quad.h"

namespace st {

ST_INLINE Float dFdx(Float v) { return simd::quad_ddx(v); }
ST_INLINE Float dFdy(Float v) { return simd::quad_ddy(v); }
// fwidth(p) = abs(dFdx(p)) + abs(dFdy(p)) (Mesa's builtin_functions.cpp).
ST_INLINE Float fwidth(Float v) { return simd::abs(dFdx(v)) + simd::abs(dFdy(v)); }
ST_INLINE Vec2 dFdx(const Vec2& v) { return {dFdx(v.x), dFdx(v.y)}; }
ST_INLINE Vec2 dFdy(const Vec2& v) { return {dFdy(v.x), dFdy(v.y)}; }
ST_INLINE Vec3 dFdx(const Vec3& v) { return {dFdx(v.x), dFdx(v.y), dFdx(v.z)}; }
ST_INLINE Vec3 dFdy(const Vec3& v) { return {dFdy(v.x), dFdy(v.y), dFdy(v.z)}; }
ST_INLINE Vec4 dFdx(const Vec4& v) { return {dFdx(v.x), dFdx(v.y), dFdx(v.z), dFdx(v.w)}; }
ST_INLINE Vec4 dFdy(const Vec4& v) { return {dFdy(v.x), dFdy(v.y), dFdy(v.z), dFdy(v.w)}; }

}  // namespace st
