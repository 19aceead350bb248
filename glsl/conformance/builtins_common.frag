#version 450 core
// builtins_common.frag: the common built-ins of inputs enumerated by pixel,
// written to RGBA32F, in six groups chosen by a uniform (one scene each):
//   0: sign, floor, trunc, ceil                 (of x)
//   1: round, roundEven, fract, modf's fraction (of x)
//   2: modf's whole part, mod(x, y), min(x, y), max(x, y)
//   3: clamp(x, y, z), step(y, x), smoothstep(y, z, x), mix(x, y, t)
//   4: mix(x, y, 0.3), mix(1.0, y, u), mix(x, y, bool), fma(x, y, z)
//   5: frexp's mantissa and exponent, ldexp(x, e), isnan + 2 isinf
// x takes both signs, every exponent (zeros, denormals, infinities and NaNs
// among them) and eight mantissa patterns: 4096 inputs on 64x64 pixels.
// y, z, t, u and e come from tables of edges (signed zeros, one, halves,
// huge, tiny, denormal, infinities, NaN), indexed by mixes of the pixel's
// bits, so each meets x of every kind. Inputs come from the pixel's index
// and tables, not from constants, so nothing is folded at compile time.
// The three mix calls have distinct (x, t) and (y, t) pairs, so NIR gives
// each the form its own arguments call for (docs/llvmpipe/glsl-builtins.md
// 2.13): fast, strict (a constant t), from one (a constant x of 1.0).
// Twin: kernels/conformance/builtins_common_frag.cpp.
layout(location = 0) out vec4 frag_colour;
uniform int group;

const int mantissas[8] = int[8](0, 1, 0x400000, 0x7FFFFF, 0x2AAAAA, 0x555555, 0x123457, 0x7FFFFE);
// 0, -0, 1, -1, 0.5, 2.5, -3.75, 1e-30, -1e30, 3e38, inf, -inf, NaN,
// a denormal, 0.1, 7.
const int edges[16] = int[16](0x00000000, int(0x80000000), 0x3F800000, int(0xBF800000), 0x3F000000, 0x40200000,
                              int(0xC0700000), 0x0DA24260, int(0xF149F2CA), 0x7F61B1E6, 0x7F800000, int(0xFF800000),
                              0x7FC00000, 0x00400000, 0x3DCCCCCD, 0x40E00000);
// The edges with NaN's place taken by -2, for group 4's y and z: where two
// NaNs meet in one + or *, which payload comes out is the operand order the
// compiler emitted (x86 keeps the first operand's), and GCC orders the
// twin's commutative operands its own way, so that case is left out there
// (docs/llvmpipe/glsl-builtins.md 0.3). x still brings every NaN.
const int others[16] = int[16](0x00000000, int(0x80000000), 0x3F800000, int(0xBF800000), 0x3F000000, 0x40200000,
                               int(0xC0700000), 0x0DA24260, int(0xF149F2CA), 0x7F61B1E6, 0x7F800000, int(0xFF800000),
                               int(0xC0000000), 0x00400000, 0x3DCCCCCD, 0x40E00000);
// Blend weights: 0, 1, 0.5, 0.25, 0.1, 0.9, 1e-8, the float below 1, -0.5,
// 1.5, -0, 2, NaN, inf, 0.3, 0.7.
const int weights[16] = int[16](0x00000000, 0x3F800000, 0x3F000000, 0x3E800000, 0x3DCCCCCD, 0x3F666666,
                                0x322BCC77, 0x3F7FFFFF, int(0xBF000000), 0x3FC00000, int(0x80000000), 0x40000000,
                                0x7FC00000, 0x7F800000, 0x3E99999A, 0x3F333333);
const int exponents[16] = int[16](0, 1, -1, 127, -127, 128, -126, 254, -254, 10, -10, 255, -300, 300, 23, -23);

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    int index = p.y * 64 + p.x;
    int sign_bit = index & 1;
    int exponent = (index >> 1) & 255;
    int mantissa = mantissas[(index >> 9) & 7];
    float x = intBitsToFloat((sign_bit << 31) | (exponent << 23) | mantissa);
    float y = intBitsToFloat(edges[(index ^ (index >> 4) ^ (index >> 8)) & 15]);
    float z = intBitsToFloat(edges[((index >> 2) ^ (index >> 7) ^ 5) & 15]);
    float t = intBitsToFloat(weights[(index ^ (index >> 5)) & 15]);
    float u = intBitsToFloat(weights[((index >> 3) ^ (index >> 9) ^ 9) & 15]);
    int e = exponents[((index >> 1) ^ (index >> 6)) & 15];
    if (group == 0) {
        frag_colour = vec4(sign(x), floor(x), trunc(x), ceil(x));
    } else if (group == 1) {
        float whole;
        frag_colour = vec4(round(x), roundEven(x), fract(x), modf(x, whole));
    } else if (group == 2) {
        float whole;
        modf(x, whole);
        frag_colour = vec4(whole, mod(x, y), min(x, y), max(x, y));
    } else if (group == 3) {
        frag_colour = vec4(clamp(x, y, z), step(y, x), smoothstep(y, z, x), mix(x, y, t));
    } else if (group == 4) {
        float y4 = intBitsToFloat(others[(index ^ (index >> 4) ^ (index >> 8)) & 15]);
        float z4 = intBitsToFloat(others[((index >> 2) ^ (index >> 7) ^ 5) & 15]);
        frag_colour = vec4(mix(x, y4, 0.3), mix(1.0, y4, u), mix(x, y, (index & 2) != 0), fma(x, y4, z4));
    } else {
        int frexp_exponent;
        float mantissa_part = frexp(x, frexp_exponent);
        frag_colour = vec4(mantissa_part, float(frexp_exponent), ldexp(x, e), float(isnan(x)) + 2.0 * float(isinf(x)));
    }
}
