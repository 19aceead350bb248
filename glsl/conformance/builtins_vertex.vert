#version 450 core
// builtins_vertex.vert: the built-ins in the vertex stage, where a twin
// computes them one vertex at a time in float and glm vectors (the scalar
// forms of shading/builtins/), for one input per cell of a `cells` scene
// (the cell's index in uv.x, the same at its three corners). `group` picks
// the functions (one scene each):
//   0: log2, log, pow(x, y), pow(|x|, y)   1: exp2, exp, sqrt, inversesqrt
//   2: sin, cos, tan, atan(x, y)           3: asin, acos, atan, tanh
//   4: floor, fract, mod(x, y), max(x, y)
//   5: length, dot, reflect, refract       6: determinant, inverse (mat3)
//   7: sinh, cosh, asinh, atanh            8: sign, trunc, round, roundEven
//   9: ceil, clamp, step, smoothstep      10: bitCount, findLSB, findMSB, bitfieldReverse
//  11: packUnorm2x16, packSnorm4x8, packHalf2x16, unpackHalf2x16
//  12: cross, faceforward, distance, normalize
//  13: determinant (mat4), inverse (mat2), outerProduct, transpose
//  14: mix(x, w, 0.25), fma(x, w, z), ldexp(x, e), frexp's mantissa
//  15: isnan and isinf, frexp's exponent, any(lessThan), all(greaterThanEqual)
// x takes both signs, every exponent (zeros, denormals, infinities and NaNs
// among them) and eight mantissa patterns: 4096 cells on 64x64; y comes from
// a table of edges, w and z from it with NaN's place taken by -2 (where two
// NaNs meet in one + or *, the payload is the compiler's operand order:
// glsl-builtins.md 0.3). Groups 5, 6, 12 and 13 take finite values (value()).
// Integer results travel as their bits (intBitsToFloat).
// The result's bits travel as two 16-bit halves in integer-valued floats
// (v_colour the high, v_uv the low), which every plane through three equal
// values keeps exactly, infinities and NaN payloads included;
// vertex_result.frag puts them back together.
// Twin: kernels/conformance/builtins_vertex_vert.cpp.
layout(location = 0) in vec4 position;
layout(location = 1) in vec4 colour;
layout(location = 2) in vec4 uv;
layout(location = 0) out vec4 v_colour;
layout(location = 1) out vec4 v_uv;
uniform int group;

const int mantissas[8] = int[8](0, 1, 0x400000, 0x7FFFFF, 0x2AAAAA, 0x555555, 0x123457, 0x7FFFFE);
// 0, -0, 1, -1, 0.5, 2.5, -3.75, 1e-30, -1e30, 3e38, inf, -inf, NaN,
// a denormal, 0.1, 7.
const int edges[16] = int[16](0x00000000, int(0x80000000), 0x3F800000, int(0xBF800000), 0x3F000000, 0x40200000,
                              int(0xC0700000), 0x0DA24260, int(0xF149F2CA), 0x7F61B1E6, 0x7F800000, int(0xFF800000),
                              0x7FC00000, 0x00400000, 0x3DCCCCCD, 0x40E00000);
const int exponents[16] = int[16](0, 1, -1, 127, -127, 128, -126, 254, -254, 10, -10, 255, -300, 300, 23, -23);
const int others[16] = int[16](0x00000000, int(0x80000000), 0x3F800000, int(0xBF800000), 0x3F000000, 0x40200000,
                               int(0xC0700000), 0x0DA24260, int(0xF149F2CA), 0x7F61B1E6, 0x7F800000, int(0xFF800000),
                               int(0xC0000000), 0x00400000, 0x3DCCCCCD, 0x40E00000);

// A finite value for component k: one of 1024 steps of 0.0137 around zero,
// scaled by 2^-6 ... 2^9.
float value(int index, int k) {
    int h = (index * (2 * k + 37) + k * 101) & 1023;
    int e = ((index >> (k & 7)) + k) & 15;
    return float(h - 512) * 0.0137 * intBitsToFloat((e + 121) << 23);
}

void main() {
    gl_Position = position;
    int index = int(uv.x);
    int sign_bit = index & 1;
    int exponent = (index >> 1) & 255;
    int mantissa = mantissas[(index >> 9) & 7];
    float x = intBitsToFloat((sign_bit << 31) | (exponent << 23) | mantissa);
    float y = intBitsToFloat(edges[(index ^ (index >> 4) ^ (index >> 8)) & 15]);
    float w = intBitsToFloat(others[(index ^ (index >> 4) ^ (index >> 8)) & 15]);
    float z = intBitsToFloat(others[((index >> 2) ^ (index >> 7) ^ 5) & 15]);
    int ix = floatBitsToInt(x);
    int e = exponents[((index >> 1) ^ (index >> 6)) & 15];
    vec3 a = vec3(value(index, 0), value(index, 1), value(index, 2));
    vec3 b = vec3(value(index, 3), value(index, 4), value(index, 5));
    vec4 r;
    if (group == 0) {
        r = vec4(log2(x), log(x), pow(x, y), pow(abs(x), y));
    } else if (group == 1) {
        r = vec4(exp2(x), exp(x), sqrt(x), inversesqrt(x));
    } else if (group == 2) {
        r = vec4(sin(x), cos(x), tan(x), atan(x, y));
    } else if (group == 3) {
        r = vec4(asin(x), acos(x), atan(x), tanh(x));
    } else if (group == 4) {
        r = vec4(floor(x), fract(x), mod(x, y), max(x, y));
    } else if (group == 5) {
        vec3 n = normalize(b);
        r = vec4(length(a), dot(a, b), reflect(a, n).x, refract(normalize(a), n, 0.66).y);
    } else if (group == 7) {
        r = vec4(sinh(x), cosh(x), asinh(x), atanh(x));
    } else if (group == 8) {
        r = vec4(sign(x), trunc(x), round(x), roundEven(x));
    } else if (group == 9) {
        r = vec4(ceil(x), clamp(x, min(w, z), max(w, z)), step(w, x), smoothstep(min(w, z), max(w, z), x));
    } else if (group == 10) {
        r = vec4(intBitsToFloat(bitCount(ix)), intBitsToFloat(findLSB(ix)), intBitsToFloat(findMSB(ix)),
                 intBitsToFloat(bitfieldReverse(ix)));
    } else if (group == 11) {
        r = vec4(uintBitsToFloat(packUnorm2x16(vec2(x, w))), uintBitsToFloat(packSnorm4x8(vec4(x, w, z, 0.5))),
                 uintBitsToFloat(packHalf2x16(vec2(x, w))), unpackHalf2x16(uint(ix)).x);
    } else if (group == 12) {
        r = vec4(cross(a, b).y, faceforward(a, b, a.yzx).z, distance(a, b), normalize(a).x);
    } else if (group == 13) {
        mat2 m2 = mat2(a.xy, b.xy);
        mat4 m4 = mat4(vec4(a, b.x), vec4(b.yz, a.xy), vec4(value(index, 6), value(index, 7), value(index, 8), a.z),
                       vec4(b, 1.0));
        r = vec4(determinant(m4), inverse(m2)[1].x, outerProduct(a, b)[2].y, transpose(m4)[0].w);
    } else if (group == 14) {
        int fe;
        r = vec4(mix(x, w, 0.25), fma(x, w, z), ldexp(x, e), frexp(x, fe));
    } else if (group == 15) {
        int fe;
        float m = frexp(x, fe);
        r = vec4(float(isnan(x)) + 2.0 * float(isinf(x)), intBitsToFloat(fe),
                 float(any(lessThan(vec2(x, w), vec2(z, x)))), float(all(greaterThanEqual(vec3(x, w, z), vec3(z, x, w)))));
    } else {
        mat3 m = mat3(a, b, vec3(value(index, 6), value(index, 7), value(index, 8)));
        mat3 inv = inverse(m);
        r = vec4(determinant(m), inv[0].x, inv[1].y, inv[2].z);
    }
    uvec4 bits = floatBitsToUint(r);
    v_colour = vec4(bits >> 16u);
    v_uv = vec4(bits & 0xFFFFu);
}
