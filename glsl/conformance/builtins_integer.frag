#version 450 core
// builtins_integer.frag: the integer, packing and vector relational
// built-ins of inputs enumerated by pixel, in thirteen groups chosen by a
// uniform (one scene each). 32-bit results are written as two floats, their
// low and high 16 bits (exact), so no bit pattern passes through a float.
//   0: uaddCarry's sum, usubBorrow's difference
//   1: uaddCarry's carry, usubBorrow's borrow, findLSB(a), findMSB(a) (uint)
//   2: umulExtended's msb and lsb
//   3: imulExtended's msb and lsb
//   4: bitfieldExtract of int and of uint
//   5: bitfieldInsert, bitfieldReverse
//   6: bitCount, findMSB (int), findLSB (int), the relational functions
//   7: packUnorm2x16, packSnorm4x8
//   8: packHalf2x16, packUnorm4x8
//   9: packSnorm2x16, unpackUnorm2x16
//  10: unpackSnorm2x16, unpackHalf2x16
//  11: unpackUnorm4x8
//  12: unpackSnorm4x8
//  13: uint(f) and int(f) of floats in [0, 2^32) and (-2^31, 2^31)
// a and b are hashes of the pixel's index, with 0, 0xFFFFFFFF and
// 0x80000000 among them; offset and bits go past the spec's range (GLSL
// leaves that undefined; llvmpipe masks shift counts to 5 bits). f, the
// packed floats: x from its bits (every exponent, zeros, denormals,
// infinities, NaNs), a ramp through [-1.28, 1.28], values next to the
// rounding ties of 8 bits, and edges.
// Twin: kernels/conformance/builtins_integer_frag.cpp.
layout(location = 0) out vec4 frag_colour;
uniform int group;

const int mantissas[8] = int[8](0, 1, 0x400000, 0x7FFFFF, 0x2AAAAA, 0x555555, 0x123457, 0x7FFFFE);
// 0, -0, 1, -1, 0.5, 2.5, -3.75, 1e-30, -1e30, 3e38, inf, -inf, NaN,
// a denormal, 0.1, 7.
const int edges[16] = int[16](0x00000000, int(0x80000000), 0x3F800000, int(0xBF800000), 0x3F000000, 0x40200000,
                              int(0xC0700000), 0x0DA24260, int(0xF149F2CA), 0x7F61B1E6, 0x7F800000, int(0xFF800000),
                              0x7FC00000, 0x00400000, 0x3DCCCCCD, 0x40E00000);

vec2 halves(uint r) { return vec2(float(r & 0xFFFFu), float(r >> 16)); }

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    int index = p.y * 64 + p.x;
    uint a = uint(index) * 2654435761u + 12345u;
    uint b = (a ^ (a >> 15)) * 2246822519u;
    int kind = index & 15;
    if (kind == 0) a = 0u;
    if (kind == 1) a = 0xFFFFFFFFu;
    if (kind == 2) a = 0x80000000u;
    if (kind == 3) b = 0xFFFFFFFFu;
    int offset = int(b & 31u) + ((index >> 4) & 1);
    int bits = int((b >> 5) & 31u) + ((index >> 5) & 1);
    int sign_bit = index & 1;
    int exponent = (index >> 1) & 255;
    int mantissa = mantissas[(index >> 9) & 7];
    vec4 f = vec4(intBitsToFloat((sign_bit << 31) | (exponent << 23) | mantissa),
                  float((index & 1023) - 512) / 400.0,
                  intBitsToFloat(edges[(index ^ (index >> 4) ^ (index >> 8)) & 15]),
                  (float(index & 255) + 0.5) / 255.0);
    if (group == 0) {
        uint carry, borrow;
        frag_colour = vec4(halves(uaddCarry(a, b, carry)), halves(usubBorrow(a, b, borrow)));
    } else if (group == 1) {
        uint carry, borrow;
        uaddCarry(a, b, carry);
        usubBorrow(a, b, borrow);
        frag_colour = vec4(float(carry), float(borrow), float(findLSB(a)), float(findMSB(a)));
    } else if (group == 2) {
        uint msb, lsb;
        umulExtended(a, b, msb, lsb);
        frag_colour = vec4(halves(msb), halves(lsb));
    } else if (group == 3) {
        int msb, lsb;
        imulExtended(int(a), int(b), msb, lsb);
        frag_colour = vec4(halves(uint(msb)), halves(uint(lsb)));
    } else if (group == 4) {
        frag_colour = vec4(halves(uint(bitfieldExtract(int(a), offset, bits))), halves(bitfieldExtract(a, offset, bits)));
    } else if (group == 5) {
        frag_colour = vec4(halves(bitfieldInsert(a, b, offset, bits)), halves(bitfieldReverse(a)));
    } else if (group == 6) {
        bvec3 lt = lessThan(f.xyz, f.yzw);
        bvec3 ge = greaterThanEqual(f.xyz, f.yzw);
        bvec3 eq = equal(f.xyz, f.zwx);
        bvec3 ne = notEqual(f.xyz, f.zwx);
        bvec2 ult = lessThan(uvec2(a, b), uvec2(b, a));
        bvec2 ieq = equal(ivec2(a, b), ivec2(b, int(a)));
        int relations = int(any(lt)) | (int(all(ge)) << 1) | (int(any(not(eq))) << 2) | (int(all(ne)) << 3) |
                        (int(lt.y) << 4) | (int(any(ult)) << 5) | (int(all(ult)) << 6) | (int(any(ieq)) << 7);
        frag_colour = vec4(float(bitCount(a)), float(findMSB(int(a))), float(findLSB(int(b))), float(relations));
    } else if (group == 7) {
        frag_colour = vec4(halves(packUnorm2x16(f.xy)), halves(packSnorm4x8(f)));
    } else if (group == 8) {
        frag_colour = vec4(halves(packHalf2x16(f.xy)), halves(packUnorm4x8(f)));
    } else if (group == 9) {
        frag_colour = vec4(halves(packSnorm2x16(f.zw)), unpackUnorm2x16(a));
    } else if (group == 10) {
        frag_colour = vec4(unpackSnorm2x16(a), unpackHalf2x16(a));
    } else if (group == 11) {
        frag_colour = unpackUnorm4x8(a);
    } else if (group == 12) {
        frag_colour = unpackSnorm4x8(a);
    } else {
        // In range only: outside, GLSL leaves the conversion undefined.
        float u = float(a) * (float(b & 0xFFFFu) / 65536.0);
        float i = float(int(a)) * (float(b >> 16) / 65536.0);
        frag_colour = vec4(halves(uint(u)), halves(uint(int(i))));
    }
}
