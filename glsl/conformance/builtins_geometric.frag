#version 450 core
// builtins_geometric.frag: the geometric built-ins of vectors enumerated by
// pixel, written to RGBA32F, in six groups chosen by a uniform (one scene
// each):
//   0: dot of vec2, vec3 and vec4, length of a float
//   1: length of vec2, vec3 and vec4, distance of vec3
//   2: normalize of a vec3, normalize of a float
//   3: cross, distance of floats
//   4: reflect, faceforward of floats
//   5: refract (eta from 0.4 to 2.5, total internal reflection among them),
//      faceforward of vec4
// Components are finite values of many magnitudes from the pixel's index
// (value() below); in the lower 64x64 pixels a.x instead takes its bits
// from the index (both signs, every exponent with zeros, denormals,
// infinities and NaNs, eight mantissa patterns), so the functions meet
// every kind of float in one operand. Nothing is a constant, so nothing is
// folded.
// Twin: kernels/conformance/builtins_geometric_frag.cpp.
layout(location = 0) out vec4 frag_colour;
uniform int group;

const int mantissas[8] = int[8](0, 1, 0x400000, 0x7FFFFF, 0x2AAAAA, 0x555555, 0x123457, 0x7FFFFE);

// A finite value for component k: one of 1024 steps of 0.0137 around zero,
// scaled by 2^-6 ... 2^7.
float value(int index, int k) {
    int h = (index * (2 * k + 37) + k * 101) & 1023;
    int e = ((index >> (k & 7)) + k) & 15;
    return float(h - 512) * 0.0137 * intBitsToFloat((e + 121) << 23);
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    int index = p.y * 64 + p.x;
    vec4 a = vec4(value(index, 0), value(index, 1), value(index, 2), value(index, 3));
    vec4 b = vec4(value(index, 4), value(index, 5), value(index, 6), value(index, 7));
    if (index < 4096) {
        int sign_bit = index & 1;
        int exponent = (index >> 1) & 255;
        int mantissa = mantissas[(index >> 9) & 7];
        a.x = intBitsToFloat((sign_bit << 31) | (exponent << 23) | mantissa);
    }
    if (group == 0) {
        frag_colour = vec4(dot(a.xy, b.xy), dot(a.xyz, b.xyz), dot(a, b), length(a.x));
    } else if (group == 1) {
        frag_colour = vec4(length(a.xy), length(a.xyz), length(a), distance(a.xyz, b.xyz));
    } else if (group == 2) {
        frag_colour = vec4(normalize(a.xyz), normalize(a.x));
    } else if (group == 3) {
        frag_colour = vec4(cross(a.xyz, b.xyz), distance(a.x, b.x));
    } else if (group == 4) {
        frag_colour = vec4(reflect(a.xyz, normalize(b.xyz)), faceforward(a.w, b.w, a.z));
    } else {
        float eta = 0.4 + float(index & 63) * 0.0333;
        frag_colour = vec4(refract(a.xyz, normalize(b.xyz), eta), faceforward(a, b, a.yzwx).x);
    }
}
