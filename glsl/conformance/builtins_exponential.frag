#version 450 core
// builtins_exponential.frag: the exponential built-ins of inputs enumerated
// by pixel, written to RGBA32F, in two groups chosen by a uniform (one
// scene each): 0 is log2, log, pow(x, y), pow(|x|, y); 1 is exp2, exp,
// sqrt, inversesqrt. The inputs: both signs, every
// exponent (zeros, denormals, infinities and NaNs among them) and eight
// mantissa patterns, 4096 inputs on 64x64 pixels; pow's exponent steps
// through -3 ... 4.5 with the pixel. Inputs come from the pixel's index, not
// from constants, so nothing is folded at compile time.
// Twin: kernels/conformance/builtins_exponential_frag.cpp.
layout(location = 0) out vec4 frag_colour;
uniform int group;

const int mantissas[8] = int[8](0, 1, 0x400000, 0x7FFFFF, 0x2AAAAA, 0x555555, 0x123457, 0x7FFFFE);

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    int index = p.y * 64 + p.x;
    int sign_bit = index & 1;
    int exponent = (index >> 1) & 255;
    int mantissa = mantissas[(index >> 9) & 7];
    float x = intBitsToFloat((sign_bit << 31) | (exponent << 23) | mantissa);
    float y = float((index >> 3) & 15) * 0.5 - 3.0;
    if (group == 0)
        frag_colour = vec4(log2(x), log(x), pow(x, y), pow(abs(x), y));
    else
        frag_colour = vec4(exp2(x), exp(x), sqrt(x), inversesqrt(x));
}
