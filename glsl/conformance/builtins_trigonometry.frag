#version 450 core
// builtins_trigonometry.frag: the angle and trigonometry built-ins of
// inputs enumerated by pixel, written to RGBA32F, in four groups chosen by a
// uniform (one scene each):
//   0: sin, cos, tan, radians        (of x)
//   1: asin, acos, atan, degrees     (of x)
//   2: atan(x, y), atan(y, x), sinh, cosh
//   3: tanh, asinh, acosh, atanh     (of x)
// The lower 64x64 pixels take x from its bits: both signs, every exponent
// (zeros, denormals, infinities and NaNs among them) and eight mantissa
// patterns. The upper 64x64 take x on a ramp through [-25.2, 25.2] in steps
// of 0.0123, where the functions have their shape (octants, |x| near 1).
// y comes from a table of edges (signed zeros, ones, huge, tiny, a denormal,
// infinities, NaN) indexed by a mix of the pixel's bits. Inputs come from
// the pixel's index and tables, not from constants, so nothing is folded.
// Twin: kernels/conformance/builtins_trigonometry_frag.cpp.
layout(location = 0) out vec4 frag_colour;
uniform int group;

const int mantissas[8] = int[8](0, 1, 0x400000, 0x7FFFFF, 0x2AAAAA, 0x555555, 0x123457, 0x7FFFFE);
// 0, -0, 1, -1, 0.5, 2.5, -3.75, 1e-30, -1e30, 3e38, inf, -inf, NaN,
// a denormal, 0.1, 7.
const int edges[16] = int[16](0x00000000, int(0x80000000), 0x3F800000, int(0xBF800000), 0x3F000000, 0x40200000,
                              int(0xC0700000), 0x0DA24260, int(0xF149F2CA), 0x7F61B1E6, 0x7F800000, int(0xFF800000),
                              0x7FC00000, 0x00400000, 0x3DCCCCCD, 0x40E00000);

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    int index = p.y * 64 + p.x;
    float x;
    if (index < 4096) {
        int sign_bit = index & 1;
        int exponent = (index >> 1) & 255;
        int mantissa = mantissas[(index >> 9) & 7];
        x = intBitsToFloat((sign_bit << 31) | (exponent << 23) | mantissa);
    } else {
        x = float(index - 6144) * 0.0123;
    }
    float y = intBitsToFloat(edges[(index ^ (index >> 4) ^ (index >> 8)) & 15]);
    if (group == 0)
        frag_colour = vec4(sin(x), cos(x), tan(x), radians(x));
    else if (group == 1)
        frag_colour = vec4(asin(x), acos(x), atan(x), degrees(x));
    else if (group == 2)
        frag_colour = vec4(atan(x, y), atan(y, x), sinh(x), cosh(x));
    else
        frag_colour = vec4(tanh(x), asinh(x), acosh(x), atanh(x));
}
