// glsl_math.h: GLSL built-in functions as llvmpipe evaluates them, the one
// place where twins get them. Every transcendental function a twin calls
// comes from here, so all twins round alike and one fix reaches all.
//
// What llvmpipe does (Mesa 22.3, NIR + gallivm), for an FMA3 host:
// - exp(x) is exp2(x * fl(log2 e)) (glsl_to_nir), exp2 is lp_build_exp2: clamp
//   to [-126.99999, 128], split into floor and fraction, 2^fraction from a
//   degree-5 minimax polynomial evaluated with fused multiply-adds (odd and
//   even terms apart), times 2^floor built in the exponent bits.
// - inversesqrt(x) is 1 / sqrt(x), two correctly rounded operations.
// - dot() is lowered to products, unfused (lower_fdot), and for vec3 summed
//   as x + (y + z): measured bit for bit, though fsum3 reads left to right;
//   normalize(v) = v * inversesqrt(dot(v, v)); length(v) = sqrt(dot(v, v)).
// - mat4 * vec4 is the column sum ((c0 v.x + c1 v.y) + c2 v.z) + c3 v.w,
//   each product rounded (GLSL IR's matrix lowering).
// - a*b + c in GLSL is never fused (lower_ffma32): twins write it plainly,
//   and -ffp-contract=off keeps the compiler from fusing it.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace st::glsl {

float exp2(float x);
float exp(float x);
float inversesqrt(float x);
float dot(const glm::vec3& a, const glm::vec3& b);
float length(const glm::vec3& v);
glm::vec3 normalize(const glm::vec3& v);
glm::vec4 mul(const glm::mat4& m, const glm::vec4& v);  // GLSL m * v

}  // namespace st::glsl
