// folded.h: what Mesa computes for a built-in whose arguments are all
// constants, after inlining, constant propagation and loop unrolling: the
// host C library's value, at compile time, not gallivm's polynomial at run
// time (docs/llvmpipe/glsl-builtins.md 0.4; compiler-rewrites.md, entries
// 15 and 16). So sin(1.0) in GLSL is glsl::folded::sin(1.0f) in a twin,
// while sin(u) of a uniform u is glsl::sin. The one place twins get such
// values from.
#pragma once

#include <cmath>

namespace st::glsl::folded {

// GLSL IR's and NIR's constant folding: sinf, cosf, expf, exp2f, logf, log2f.
inline float sin(float x) { return std::sin(x); }
inline float cos(float x) { return std::cos(x); }
inline float exp(float x) { return std::exp(x); }
inline float exp2(float x) { return std::exp2(x); }
inline float log(float x) { return std::log(x); }
inline float log2(float x) { return std::log2(x); }
// pow of constants as GLSL IR folds it (powf). NIR, folding a pow that
// became constant only later, rounds the double pow instead (nir_opcodes.py).
inline float pow(float x, float y) { return std::pow(x, y); }
inline float pow_nir(float x, float y) { return float(std::pow(double(x), double(y))); }

}  // namespace st::glsl::folded
