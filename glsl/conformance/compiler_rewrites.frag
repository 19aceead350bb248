#version 450 core
// compiler_rewrites.frag: one expression per group (one scene each) that
// GLSL IR or NIR rewrites before llvmpipe runs it, so that its last bits
// are those of another expression (docs/llvmpipe/compiler-rewrites.md, one
// entry per group):
//   0: 0.1 * colour + diff * colour      runs as colour * (0.1 + diff)
//   1: mix(32.0, 8.0, t)                 the fast form, 32 + (8 - 32) t
//   2: mix(vec3(a), colour, t)           the strict form (shared x and t)
//   3: a * b * 3.0                       runs as (a * 3.0) * b
//   4: a + b + 1.0                       runs as (a + 1.0) + b
//   5: a + b + c + d                     runs as (a + (c + d)) + b: rebalanced
//                                        to (a + b) + (c + d), then, a and b
//                                        being products, reassociated
//   6: (a + b) - a                       runs as b
//   7: 1.0 / exp2(x)                     runs as exp2(-x)
//   8: pow(a, 2.0), pow(b, 4.0), pow(2.0, x)   run as a a, (b b)(b b), exp2(x)
//   9: dot(p, n) - 0.75 (vec2)           runs as p.x n.x + (p.y n.y - 0.75)
//  10: x / 3.0                           stays a division
//  11: exp(x) * exp(y)                   runs as exp2((x + y) log2 e)
//  12: A * B * C * v (mat4)              runs as A * (B * (C * v))
//  13: reflect(i, n)                     runs as i - (dot(n, i) * 2) n, which
//                                        overflows where i - 2 (dot(n, i) n) does not
//  14: fma(a, b, c)                      runs as a * b + c, not fused
//  15: sin(1.0), cos(2.0), exp(1.7), pow(3.0, 0.7)   folded by the compiler
//                                        with the host C library (sinf, ...)
//  16: a loop of sin(float(i) * 0.7 + 1.1), unrolled and then folded
//  17: 1.0 / inversesqrt(q)              runs as sqrt(q)
//  18: exp(log(q)), exp2(log2(q))        run as q
//  19: 1.0 / (1.0 / q)                   runs as q
//  20: refract(i, n, 0.66)               runs with k = 1 - (0.66 * 0.66) (1 - d d),
//                                        the constants' product folded
//  21: float(int(x))                     runs as trunc(x): -0.0 for x in (-1, 0),
//                                        x itself past int's range
//  22: t * (a - 1.0) + 1.0                found to be lrp(1, a, t), runs as
//                                        (1 - t) + a t; c + (b - c) * t, found
//                                        too, runs as written (the fast lrp)
//  23: length(v) * length(v), sqrt(q) * sqrt(q)   run as dot(v, v), abs(q)
// Operands are finite values of many magnitudes from the pixel's index;
// nothing is a constant but what the expression writes, so nothing else is
// folded. The twin writes what llvmpipe runs; its uniform `twin_naive` (twin
// only: this program has none, GL ignores it) makes it write the
// expression as it stands, which cli.compiler_rewrites shows to fail.
// Twin: kernels/conformance/compiler_rewrites_frag.cpp.
layout(location = 0) out vec4 frag_colour;
uniform int group;

float value(int index, int k) {
    int h = (index * (2 * k + 37) + k * 101) & 1023;
    int e = ((index >> (k & 7)) + k) & 15;
    return float(h - 512) * 0.0137 * intBitsToFloat((e + 121) << 23);
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    int index = p.y * 64 + p.x;
    float a = value(index, 0), b = value(index, 1), c = value(index, 2), d = value(index, 3);
    vec3 colour = vec3(value(index, 4), value(index, 5), value(index, 6));
    vec3 diff = vec3(value(index, 7), value(index, 8), value(index, 9));
    float t = float(index & 1023) / 1023.0;
    float x = float((index & 2047) - 1024) / 100.0;
    float y = float(((index >> 3) & 1023) - 512) / 50.0;
    if (group == 0)
        frag_colour = vec4(0.1 * colour + diff * colour, 0.0);
    else if (group == 1)
        frag_colour = vec4(mix(32.0, 8.0, t), 0.0, 0.0, 0.0);
    else if (group == 2)
        frag_colour = vec4(mix(vec3(a), colour, t), 0.0);
    else if (group == 3)
        frag_colour = vec4(a * b * 3.0, 0.0, 0.0, 0.0);
    else if (group == 4)
        frag_colour = vec4(a + b + 1.0, 0.0, 0.0, 0.0);
    else if (group == 5)
        frag_colour = vec4(a + b + c + d, 0.0, 0.0, 0.0);
    else if (group == 6)
        frag_colour = vec4((a + b) - a, 0.0, 0.0, 0.0);
    else if (group == 7)
        frag_colour = vec4(1.0 / exp2(x), 0.0, 0.0, 0.0);
    else if (group == 8)
        frag_colour = vec4(pow(a, 2.0), pow(b, 4.0), pow(2.0, x), 0.0);
    else if (group == 9)
        frag_colour = vec4(dot(colour.xy, diff.xy) - 0.75, 0.0, 0.0, 0.0);
    else if (group == 10)
        frag_colour = vec4(x / 3.0, 0.0, 0.0, 0.0);
    else if (group == 11)
        frag_colour = vec4(exp(x) * exp(y), 0.0, 0.0, 0.0);
    else if (group == 12) {
        mat4 A = mat4(vec4(a, b, c, d), vec4(colour, t), vec4(diff, x), vec4(y, a, c, b));
        mat4 B = mat4(vec4(diff, a), vec4(b, colour), vec4(t, c, x, d), vec4(colour.zyx, y));
        mat4 C = mat4(vec4(x, y, t, a), vec4(diff.zxy, b), vec4(c, d, colour.xy), vec4(colour.yz, diff.yz));
        frag_colour = A * B * C * vec4(colour, d);
    } else if (group == 13)
        frag_colour = vec4(reflect(colour * 8e34, normalize(diff)), 0.0);
    else if (group == 14)
        frag_colour = vec4(fma(a, b, c), fma(colour, diff, vec3(d)));
    else if (group == 15)
        frag_colour = vec4(sin(1.0), cos(2.0), exp(1.7), pow(3.0, 0.7));
    else if (group == 17)
        frag_colour = vec4(1.0 / inversesqrt(abs(a)), 0.0, 0.0, 0.0);
    else if (group == 18)
        frag_colour = vec4(exp(log(abs(a))), exp2(log2(abs(b))), 0.0, 0.0);
    else if (group == 19)
        frag_colour = vec4(1.0 / (1.0 / a), 0.0, 0.0, 0.0);
    else if (group == 20)
        frag_colour = vec4(refract(normalize(colour), normalize(diff), 0.66), 0.0);
    else if (group == 21)
        frag_colour = vec4(float(int(x)), float(int(a * 1e7)), float(int(t - 0.5)), 0.0);
    else if (group == 22)
        frag_colour = vec4(t * (a - 1.0) + 1.0, c + (b - c) * t, 0.0, 0.0);
    else if (group == 23)
        frag_colour = vec4(length(colour) * length(colour), sqrt(abs(a)) * sqrt(abs(a)), 0.0, 0.0);
    else {
        float s = 0.0;
        for (int i = 0; i < 8; ++i)
            s += sin(float(i) * 0.7 + 1.1);
        frag_colour = vec4(s, 0.0, 0.0, 0.0);
    }
}
