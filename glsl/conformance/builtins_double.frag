#version 450 core
// builtins_double.frag: GLSL's double arithmetic, its double (genDType)
// built-ins and double uniforms, of inputs enumerated by pixel. A pixel's
// index gives the input (its low 10 bits) and which of its group's four
// results it carries (the top 2 bits); a uniform picks the group (one scene
// each):
//   0: abs, sign, floor, ceil
//   1: trunc, round, roundEven, fract
//   2: sqrt, inversesqrt, min(x, y), max(x, y)
//   3: mod(x, y), clamp(x, lo, hi), step(y, x), smoothstep(lo, hi, x)
//   4: mix(x, y, t) (fast), mix(x, y, 0.3) (strict), mix(1.0, y, t) (from one), mix(x, y, bool)
//   5: x + y, x - y, x * y, x / y
//   6: double(float(x)), double(int(x)) in int's range (not in (-1, 0): NIR runs
//      it as trunc(x), whose -0.0 there depends on the host's vector width),
//      isnan + 2 isinf, the comparisons as bits
//   7: dot, length, distance, normalize(a).x of finite dvec3s
//   8: the uniforms: scale * x, x + offset.y, (basis * dvec3(x, 0.5, -2)).z, dot(corner, dvec4(x, 0.25, 3, -1.5))
//   9: frexp's significand and exponent, ldexp(x, e), ldexp(frexp(x)) (e from a table past the range)
//  10: dmat: determinant, inverse, products (m * v, v * m, m * m), transpose, matrixCompMult,
//      outerProduct, of finite doubles (the index picks the shape and the element)
//  11: the relational functions of dvec3s as bits, reflect, refract, faceforward and cross,
//      fma (not fused), modf's whole part and mix(x, y, bvec)
// x takes both signs, 64 exponents (zeros, denormals, the float range's
// edges, 2^52 and 2^53, infinities and NaNs) and eight mantissa patterns
// (one is a tie for float(x)); y and z come from a table of edges, t from a
// table of weights, both with NaN's place taken by -2 (where two NaNs meet
// in one operation, the payload is the operand order: glsl-builtins.md 0.3).
// The result's 64 bits travel as four 16-bit quarters in integer-valued
// floats, so every bit of every double, NaN payloads included, reaches the
// RGBA32F image exactly.
// Twin: kernels/conformance/builtins_double_frag.cpp.
layout(location = 0) out vec4 frag_colour;
uniform int group;
uniform double scale;
uniform dvec3 offset;
uniform dmat3 basis;
uniform dvec4 corner;

const int exponents[64] = int[64](0, 1, 2, 50, 400, 800, 872, 873, 874, 896, 897, 898, 920, 960, 990, 1000,
                                  1010, 1015, 1018, 1019, 1020, 1021, 1022, 1023, 1024, 1025, 1026, 1027, 1028, 1029,
                                  1030, 1031, 1033, 1036, 1040, 1045, 1050, 1053, 1054, 1055, 1056, 1060, 1070, 1074,
                                  1075, 1076, 1077, 1080, 1100, 1126, 1150, 1151, 1152, 1170, 1300, 1600, 1900, 2000,
                                  2030, 2040, 2044, 2045, 2046, 2047);
// The mantissa's high 20 and low 32 bits: 0, the lowest bit, a half, all
// ones, 0x5..., a tie for float(x) (bit 28 alone), a mix, next to 2.
const uint mantissas_hi[8] = uint[8](0u, 0u, 0x80000u, 0xFFFFFu, 0x55555u, 0u, 0x12345u, 0xFFFFFu);
const uint mantissas_lo[8] = uint[8](0u, 1u, 0u, 0xFFFFFFFFu, 0x55555555u, 0x10000000u, 0x6789ABCDu, 0xF0000000u);
// 0, -0, 1, -1, 0.5, 2.5, -3.75, 1e-300, -1e300, 1e30, inf, -inf, -2, a
// denormal, 0.1, 7 (high and low words).
const uint edges_hi[16] = uint[16](0x0u, 0x80000000u, 0x3FF00000u, 0xBFF00000u, 0x3FE00000u, 0x40040000u,
                                   0xC00E0000u, 0x01A56E1Fu, 0xFE37E43Cu, 0x46293E59u, 0x7FF00000u, 0xFFF00000u,
                                   0xC0000000u, 0x8u, 0x3FB99999u, 0x401C0000u);
const uint edges_lo[16] = uint[16](0u, 0u, 0u, 0u, 0u, 0u, 0u, 0xC2F8F359u, 0x8800759Cu, 0x39A08CEAu, 0u, 0u, 0u, 0u,
                                   0x9999999Au, 0u);
// 0, 1, 0.5, 0.25, 0.1, 0.9, 1e-8, the double below 1, -0.5, 1.5, -0, 2,
// -2, inf, 0.3, 0.7.
const uint weights_hi[16] = uint[16](0x0u, 0x3FF00000u, 0x3FE00000u, 0x3FD00000u, 0x3FB99999u, 0x3FECCCCCu,
                                     0x3E45798Eu, 0x3FEFFFFFu, 0xBFE00000u, 0x3FF80000u, 0x80000000u, 0x40000000u,
                                     0xC0000000u, 0x7FF00000u, 0x3FD33333u, 0x3FE66666u);
const uint weights_lo[16] = uint[16](0u, 0u, 0u, 0u, 0x9999999Au, 0xCCCCCCCDu, 0xE2308C3Au, 0xFFFFFFFFu, 0u, 0u, 0u,
                                     0u, 0u, 0u, 0x33333333u, 0x66666666u);

const int exponent_steps[16] = int[16](0, 1, -1, 1023, -1022, 1024, -1074, 2046, -2046, 10, -10, 2047, -3000, 3000,
                                       52, -52);

double edge(int k) { return packDouble2x32(uvec2(edges_lo[k], edges_hi[k])); }

// A finite double for component k: one of 1024 steps around zero, scaled
// by 2^-6 ... 2^9 (exact), divided by 73 to fill the mantissa (a division
// by a constant stays one: compiler-rewrites.md, entry 10; a chain of
// products with constants would be reassociated, entry 3).
double value(int index, int k) {
    int h = (index * (2 * k + 37) + k * 101) & 1023;
    int e = ((index >> (k & 7)) + k) & 15;
    return double(h - 512) * double(intBitsToFloat((e + 121) << 23)) / 73.0lf;
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    int index = p.y * 64 + p.x;
    int i = index & 1023;
    int which = index >> 10;
    uint hi = (uint(i & 1) << 31) | (uint(exponents[(i >> 1) & 63]) << 20) | mantissas_hi[(i >> 7) & 7];
    double x = packDouble2x32(uvec2(mantissas_lo[(i >> 7) & 7], hi));
    double y = edge((i ^ (i >> 4) ^ (i >> 8)) & 15);
    double z = edge(((i >> 2) ^ (i >> 7) ^ 5) & 15);
    int k = (i ^ (i >> 5)) & 15;
    double t = packDouble2x32(uvec2(weights_lo[k], weights_hi[k]));
    double lo = min(y, z), hi_edge = max(y, z);
    double r;
    if (group == 0) {
        r = which == 0 ? abs(x) : which == 1 ? sign(x) : which == 2 ? floor(x) : ceil(x);
    } else if (group == 1) {
        r = which == 0 ? trunc(x) : which == 1 ? round(x) : which == 2 ? roundEven(x) : fract(x);
    } else if (group == 2) {
        r = which == 0 ? sqrt(x) : which == 1 ? inversesqrt(x) : which == 2 ? min(x, y) : max(x, y);
    } else if (group == 3) {
        r = which == 0 ? mod(x, y) : which == 1 ? clamp(x, lo, hi_edge) : which == 2 ? step(y, x)
                                                                       : smoothstep(lo, hi_edge, x);
    } else if (group == 4) {
        r = which == 0 ? mix(x, y, t) : which == 1 ? mix(x, z, 0.3lf) : which == 2 ? mix(1.0lf, y, t)
                                                                      : mix(x, y, (i & 2) != 0);
    } else if (group == 5) {
        r = which == 0 ? x + y : which == 1 ? x - y : which == 2 ? x * y : x / y;
    } else if (group == 6) {
        int relations = int(x < y) | (int(x <= y) << 1) | (int(x == y) << 2) | (int(x != y) << 3) |
                        (int(x > y) << 4) | (int(x >= y) << 5);
        r = which == 0 ? double(float(x))
          : which == 1 ? (abs(x) < 2147483648.0lf && (x >= 0.0lf || x <= -1.0lf) ? double(int(x)) : x)
          : which == 2 ? double(int(isnan(x)) + 2 * int(isinf(x)))
          : double(relations);
    } else if (group == 7) {
        dvec3 a = dvec3(value(index, 0), value(index, 1), value(index, 2));
        dvec3 b = dvec3(value(index, 3), value(index, 4), value(index, 5));
        r = which == 0 ? dot(a, b) : which == 1 ? length(a) : which == 2 ? distance(a, b) : normalize(a).x;
    } else if (group == 9) {
        int fe;
        double m = frexp(x, fe);
        int e = exponent_steps[(i ^ (i >> 6)) & 15];
        r = which == 0 ? m : which == 1 ? double(fe) : which == 2 ? ldexp(x, e) : ldexp(m, fe);
    } else if (group == 10) {
        dmat2 m2 = dmat2(value(index, 0), value(index, 1), value(index, 2), value(index, 3));
        dmat3 m3 = dmat3(value(index, 4), value(index, 5), value(index, 6), value(index, 7), value(index, 8),
                         value(index, 9), value(index, 10), value(index, 11), value(index, 12));
        dmat3 n3 = dmat3(value(index, 13), value(index, 14), value(index, 15), value(index, 16), value(index, 17),
                         value(index, 18), value(index, 19), value(index, 20), value(index, 21));
        dmat4 m4 = dmat4(dvec4(value(index, 22), value(index, 23), value(index, 24), value(index, 25)),
                         dvec4(value(index, 26), value(index, 27), value(index, 28), value(index, 29)),
                         dvec4(value(index, 30), value(index, 31), value(index, 32), value(index, 33)),
                         dvec4(value(index, 34), value(index, 35), value(index, 36), value(index, 37)));
        dvec3 v = dvec3(value(index, 38), value(index, 39), value(index, 40));
        dvec2 w = dvec2(value(index, 41), value(index, 42));
        int j = i & 3, c = (i >> 2) % 3, e = (i >> 4) % 3;
        double d = j == 0 ? determinant(m2) : j == 1 ? determinant(m3) : j == 2 ? determinant(m4) : (m3 * n3)[c][e];
        double inv = j == 0 ? inverse(m2)[c & 1][e & 1] : j == 1 ? inverse(m3)[c][e] : inverse(m4)[c][e + (i & 1)];
        double prod = j == 0 ? (m3 * v)[c] : j == 1 ? (v * m3)[c] : j == 2 ? (dmat2x3(m3) * w)[c] : (m4 * dvec4(v, value(index, 43)))[e];
        double other = j == 0 ? transpose(m4)[c][e] : j == 1 ? matrixCompMult(m3, n3)[c][e] : outerProduct(v, w)[c & 1][e];
        r = which == 0 ? d : which == 1 ? inv : which == 2 ? prod : other;
    } else if (group == 11) {
        dvec3 a = dvec3(value(index, 0), value(index, 1), value(index, 2));
        dvec3 b = dvec3(value(index, 3), value(index, 4), value(index, 5));
        dvec3 n = normalize(dvec3(value(index, 6), value(index, 7), value(index, 8)));
        int k = (i >> 2) % 3;
        int relations = int(any(lessThan(dvec3(x, y, z), dvec3(y, z, x)))) |
                        (int(all(greaterThanEqual(dvec3(x, y, z), dvec3(z, x, y)))) << 1) |
                        (int(any(equal(dvec2(x, y), dvec2(z, x)))) << 2) | (int(all(notEqual(dvec2(x, y), dvec2(y, z)))) << 3) |
                        (int(lessThanEqual(dvec2(x, t), dvec2(t, y)).y) << 4) | (int(greaterThan(dvec2(x, z), dvec2(y, t)).x) << 5);
        double whole;
        double f = modf(x, whole);
        r = which == 0 ? ((i & 1) != 0 ? double(relations) : fma(x, y, z))
          : which == 1 ? ((i & 1) != 0 ? reflect(a, n)[k] : refract(normalize(a), n, scale)[k])
          : which == 2 ? ((i & 1) != 0 ? faceforward(a, b, n)[k] : cross(a, b)[k])
          : ((i & 2) != 0 ? whole : (i & 1) != 0 ? f : mix(x, y, (i & 4) != 0));
    } else {
        // Only x brings infinities and NaNs here: with y or z among them, a zero basis or corner (GL's value
        // for a uniform the scene leaves out) would make two NaNs meet in one sum, whose payload is the
        // order LLVM emits the add in (glsl-builtins.md 0.3; explore conformance --seed 31).
        r = which == 0 ? scale * x : which == 1 ? x + offset.y : which == 2 ? (basis * dvec3(x, 0.5lf, -2.0lf)).z
                                                               : dot(corner, dvec4(x, 0.25lf, 3.0lf, -1.5lf));
    }
    uvec2 bits = unpackDouble2x32(r);
    frag_colour = vec4(float(bits.x & 0xFFFFu), float(bits.x >> 16), float(bits.y & 0xFFFFu), float(bits.y >> 16));
}
