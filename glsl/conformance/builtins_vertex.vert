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
//  16: uaddCarry's sum, usubBorrow's difference, umulExtended's and imulExtended's msb
//  17: the carry and the borrow, umulExtended's and imulExtended's lsb, bitfieldExtract (int)
//  18: bitfieldExtract (uint), bitfieldInsert, packUnorm4x8, packSnorm2x16
//  19: unpackUnorm2x16, unpackSnorm2x16, unpackUnorm4x8, unpackSnorm4x8 (a component each)
//  20: the vector relational functions as bits, radians, degrees, modf's fraction
//  21: mix(x, w, t) (the fast form), mix(1.0, w, u) (from one), mix(x, w, bvec), abs
//  22: GLSL's * of glm matrices: mat3 * vec3, vec4 * mat4, mat2x3 * mat3x2, mat4x3 * vec4
//      (summed in another order than glm's own), matrixCompMult, determinant (mat2), inverse (mat4)
//  23: floor and ceil of a double        24: trunc and roundEven of a double
//  25: mod(x, y) and max(x, y) of doubles, fract, sqrt (each double's 64 bits as two channels,
//      25 picking by the index)
//  26: dmat3: determinant, inverse, dmat3 * dvec3, dvec3 * dmat3 (of finite doubles)
// x takes both signs, every exponent (zeros, denormals, infinities and NaNs
// among them) and eight mantissa patterns: 4096 cells on 64x64; y comes from
// a table of edges, w and z from it with NaN's place taken by -2 (where two
// NaNs meet in one + or *, the payload is the compiler's operand order:
// glsl-builtins.md 0.3). Groups 5, 6, 12 and 13 take finite values (value()).
// Integer results travel as their bits (intBitsToFloat). Groups 16-19 take
// ua and ub, hashes of the index with 0, 0xFFFFFFFF and 0x80000000 among
// them, and offset and count past the spec's range (as builtins_integer.frag);
// f.yw, the packed floats' other lanes, a ramp through [-1.28, 1.28] and
// values next to the 8-bit rounding ties. t and u are blend weights (0, 1,
// halves, the float below 1, -0.5, 1.5, NaN, inf, ...); the two mixes of
// group 21 share neither (x, t) nor (w, t), so each keeps its own form
// (glsl-builtins.md 2.13).
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
// Blend weights: 0, 1, 0.5, 0.25, 0.1, 0.9, 1e-8, the float below 1, -0.5,
// 1.5, -0, 2, NaN, inf, 0.3, 0.7.
const int weights[16] = int[16](0x00000000, 0x3F800000, 0x3F000000, 0x3E800000, 0x3DCCCCCD, 0x3F666666,
                                0x322BCC77, 0x3F7FFFFF, int(0xBF000000), 0x3FC00000, int(0x80000000), 0x40000000,
                                0x7FC00000, 0x7F800000, 0x3E99999A, 0x3F333333);

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
    float t = intBitsToFloat(weights[(index ^ (index >> 5)) & 15]);
    float u = intBitsToFloat(weights[((index >> 3) ^ (index >> 9) ^ 9) & 15]);
    uint ua = uint(index) * 2654435761u + 12345u;
    uint ub = (ua ^ (ua >> 15)) * 2246822519u;
    int kind = index & 15;
    if (kind == 0) ua = 0u;
    if (kind == 1) ua = 0xFFFFFFFFu;
    if (kind == 2) ua = 0x80000000u;
    if (kind == 3) ub = 0xFFFFFFFFu;
    int offset = int(ub & 31u) + ((index >> 4) & 1);
    int count = int((ub >> 5) & 31u) + ((index >> 5) & 1);
    vec4 f = vec4(x, float((index & 1023) - 512) / 400.0, y, (float(index & 255) + 0.5) / 255.0);
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
    } else if (group == 16) {
        uint carry, borrow, umsb, ulsb;
        int imsb, ilsb;
        umulExtended(ua, ub, umsb, ulsb);
        imulExtended(int(ua), int(ub), imsb, ilsb);
        r = vec4(uintBitsToFloat(uaddCarry(ua, ub, carry)), uintBitsToFloat(usubBorrow(ua, ub, borrow)),
                 uintBitsToFloat(umsb), intBitsToFloat(imsb));
    } else if (group == 17) {
        uint carry, borrow, umsb, ulsb;
        int imsb, ilsb;
        uaddCarry(ua, ub, carry);
        usubBorrow(ua, ub, borrow);
        umulExtended(ua, ub, umsb, ulsb);
        imulExtended(int(ua), int(ub), imsb, ilsb);
        r = vec4(float(carry) + 2.0 * float(borrow), uintBitsToFloat(ulsb), intBitsToFloat(ilsb),
                 intBitsToFloat(bitfieldExtract(int(ua), offset, count)));
    } else if (group == 18) {
        r = vec4(uintBitsToFloat(bitfieldExtract(ua, offset, count)), uintBitsToFloat(bitfieldInsert(ua, ub, offset, count)),
                 uintBitsToFloat(packUnorm4x8(f)), uintBitsToFloat(packSnorm2x16(f.zw)));
    } else if (group == 19) {
        r = vec4(unpackUnorm2x16(ua)[index & 1], unpackSnorm2x16(ua)[(index >> 1) & 1],
                 unpackUnorm4x8(ua)[index & 3], unpackSnorm4x8(ua)[(index >> 2) & 3]);
    } else if (group == 20) {
        bvec3 le = lessThanEqual(f.xyz, f.yzw);
        bvec3 gt = greaterThan(f.xyz, f.yzw);
        bvec3 eq = equal(f.xyz, f.zwx);
        bvec3 ne = notEqual(f.xyz, f.zwx);
        bvec2 ule = lessThanEqual(uvec2(ua, ub), uvec2(ub, ua));
        bvec2 igt = greaterThan(ivec2(ua, ub), ivec2(ub, int(ua)));
        bvec2 beq = equal(bvec2(le.x, gt.y), bvec2(eq.z, ne.x));
        int relations = int(any(le)) | (int(all(gt)) << 1) | (int(any(not(eq))) << 2) | (int(all(ne)) << 3) |
                        (int(le.y) << 4) | (int(any(ule)) << 5) | (int(all(igt)) << 6) | (int(any(beq)) << 7) |
                        (int(notEqual(ivec2(ua, ub), ivec2(ub, ua)).y) << 8);
        float whole;
        r = vec4(float(relations), radians(x), degrees(x), modf(x, whole));
    } else if (group == 21) {
        r = vec4(mix(x, w, t), mix(1.0, w, u), mix(x, w, (index & 2) != 0), abs(x));
    } else if (group == 22) {
        mat3 m3 = mat3(a, b, vec3(value(index, 6), value(index, 7), value(index, 8)));
        mat4 m4 = mat4(vec4(a, b.x), vec4(b.yz, a.xy), vec4(value(index, 6), value(index, 7), value(index, 8), a.z),
                       vec4(b, 1.0));
        mat2x3 m23 = mat2x3(a, b);
        mat3x2 m32 = mat3x2(value(index, 18), value(index, 19), value(index, 20), value(index, 21), value(index, 22),
                            value(index, 23));
        mat4x3 m43 = mat4x3(b, a, a.zxy, vec3(value(index, 11), value(index, 12), value(index, 13)));
        vec4 v4 = vec4(value(index, 14), value(index, 15), value(index, 16), value(index, 17));
        int k = index & 3;
        // One product per channel, picked by the index (a selection rounds nothing): a sum of two
        // would be a sum NIR may reassociate (compiler-rewrites.md, entry 5). No two factors of a
        // product's terms are the same value, or NIR factors them (entry 0): m3 * a with a in m3 does.
        r = vec4((index & 4) != 0 ? (m3 * v4.xyz)[k % 3] : (v4 * m4)[k],
                 (index & 8) != 0 ? (m23 * m32)[k % 3][(k + 1) % 3] : (m43 * v4)[(k + 2) % 3],
                 (index & 16) != 0 ? matrixCompMult(m3, transpose(m3))[k % 3].y : determinant(mat2(a.xy, b.yz)),
                 inverse(m4)[k][(index >> 2) & 3]);
    } else if (group >= 23 && group <= 25) {
        // Doubles of every bit pattern (zeros, denormals, infinities, NaNs among them) from the hashes.
        double dx = packDouble2x32(uvec2(ua, ub));
        double dy = packDouble2x32(uvec2(ub, ua ^ 0x3FF00000u));
        dvec2 d = group == 23 ? dvec2(floor(dx), ceil(dx))
                : group == 24 ? dvec2(trunc(dx), roundEven(dx))
                : (index & 2) != 0 ? dvec2(mod(dx, dy), max(dx, dy)) : dvec2(fract(dx), sqrt(dx));
        r = vec4(uintBitsToFloat(unpackDouble2x32(d.x)), uintBitsToFloat(unpackDouble2x32(d.y)));
    } else if (group == 26) {
        // Divided by constants (one rounding each, no rewrite: compiler-rewrites.md, entry 10) to fill the mantissas.
        dvec3 da = dvec3(a) / 7.0lf, db = dvec3(b) / 3.0lf;
        dvec3 dc = dvec3(value(index, 6), value(index, 7), value(index, 8)) / 5.0lf;
        dvec3 dv = dvec3(value(index, 9), value(index, 10), value(index, 11)) / 9.0lf;
        dmat3 dm = dmat3(da, db, dc);
        int k = index % 3;
        dvec2 d = (index & 2) != 0 ? dvec2(determinant(dm), (dm * dv)[k]) : dvec2(inverse(dm)[1][k], (dv * dm)[k]);
        r = vec4(uintBitsToFloat(unpackDouble2x32(d.x)), uintBitsToFloat(unpackDouble2x32(d.y)));
    } else {
        mat3 m = mat3(a, b, vec3(value(index, 6), value(index, 7), value(index, 8)));
        mat3 inv = inverse(m);
        r = vec4(determinant(m), inv[0].x, inv[1].y, inv[2].z);
    }
    uvec4 bits = floatBitsToUint(r);
    v_colour = vec4(bits >> 16u);
    v_uv = vec4(bits & 0xFFFFu);
}
