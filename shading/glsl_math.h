// glsl_math.h: GLSL's built-in functions as llvmpipe evaluates them, the
// one place where twins get them. Every transcendental function a twin
// calls comes from here, so all twins round alike and one fix reaches all.
// Each is written once, as a template over the number type: `float` for
// vertex twins and host code, `Float` (one invocation per lane,
// simd/lane_vec.h) for fragment twins; both give the same bits per value.
//
// One header per family of GLSL 4.50's built-ins, under shading/builtins/,
// each saying what llvmpipe does differently from the obvious reading:
// - exponential.h: pow, exp, log, exp2, log2, sqrt, inversesqrt;
// - common.h: abs, sign, floor ... smoothstep, isnan, fma, frexp, ldexp,
//   and the three forms of mix;
// - geometric.h: dot, cross, length, normalize, reflect, refract;
// - trigonometry.h: radians ... atanh, atan of one and two arguments;
// - relational.h: lessThan ... notEqual, any, all, not_ (lane vectors);
// - matrix.h: matrixCompMult, outerProduct, transpose, determinant, inverse
//   (the products are simd/lane_mat.h's operators for lanes;
//   glm_products.h's glsl::mul for vertex twins' glm matrices);
// - integer.h: uaddCarry ... findMSB; packing.h: pack/unpack Unorm, Snorm, Half;
// - folded.h: the host C library's values, which built-ins of constants fold to;
// - selection.h: the ternary per lane, and if/else that skips a side;
// - primitives.h: the instructions the others are written in.
// docs/llvmpipe/glsl-builtins.md has the reading of Mesa behind each one.
// Everywhere: a*b + c in GLSL is never fused (lower_ffma32), so twins
// write it plainly and -ffp-contract=off keeps the compiler from fusing it.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "shading/builtins/common.h"
#include "shading/builtins/exponential.h"
#include "shading/builtins/folded.h"
#include "shading/builtins/geometric.h"
#include "shading/builtins/glm_products.h"
#include "shading/builtins/integer.h"
#include "shading/builtins/matrix.h"
#include "shading/builtins/packing.h"
#include "shading/builtins/relational.h"
#include "shading/builtins/selection.h"
#include "shading/builtins/trigonometry.h"
