// quad.h: differences across each 2x2 quad of lanes, in lane order (x, y),
// (x+1, y), (x, y+1), (x+1, y+1): ddx is the difference along the lane's
// own row and ddy along its own column, one float subtraction, which is
// what llvmpipe computes for dFdx/dFdy (fine and coarse alike) and for a
// cube map's implicit derivatives (lp_bld_quad.c). GLSL's dFdx and dFdy are
// these (shading/derivatives.h).
#pragma once

#include "simd/lanes.h"

namespace st::simd {

namespace quad_detail {
// Lane indices of each lane's right (left) neighbour in its row and top
// (bottom) neighbour in its column, quad by quad.
#define ST_QUAD(q, a, b, c, d) 4 * q + a, 4 * q + b, 4 * q + c, 4 * q + d
#if ST_LANES == 8
#define ST_QUAD_LANES(a, b, c, d) {ST_QUAD(0, a, b, c, d), ST_QUAD(1, a, b, c, d)}
#else
#define ST_QUAD_LANES(a, b, c, d) \
    {ST_QUAD(0, a, b, c, d), ST_QUAD(1, a, b, c, d), ST_QUAD(2, a, b, c, d), ST_QUAD(3, a, b, c, d)}
#endif
inline constexpr IntV kRowRight = ST_QUAD_LANES(1, 1, 3, 3), kRowLeft = ST_QUAD_LANES(0, 0, 2, 2);
inline constexpr IntV kColumnTop = ST_QUAD_LANES(2, 3, 2, 3), kColumnBottom = ST_QUAD_LANES(0, 1, 0, 1);
#undef ST_QUAD_LANES
#undef ST_QUAD
}  // namespace quad_detail

ST_INLINE Float quad_ddx(Float v) { return shuffle(v, quad_detail::kRowRight) - shuffle(v, quad_detail::kRowLeft); }
ST_INLINE Float quad_ddy(Float v) {
    return shuffle(v, quad_detail::kColumnTop) - shuffle(v, quad_detail::kColumnBottom);
}

}  // namespace st::simd
