// builtins_integer_frag.cpp: twin of glsl/conformance/builtins_integer.frag,
// line for line.
#include "kernels/conformance/conformance.h"

#include "kernels/conformance/builtin_inputs.h"

namespace st {

namespace {
// halves() of the GLSL: a uint's low and high 16 bits as two floats.
Vec2 halves(UInt r) { return Vec2(float_of(r & UInt(0xFFFFu)), float_of(r >> 16)); }
Int int_of_bool(Mask m) { return int_of(m); }
}  // namespace

Vec4 BuiltinsIntegerFragment::main(const Fragment& frag) const {
    using namespace glsl;
    using namespace builtin_inputs;
    const Int index = pixel_index(frag);
    UInt a = UInt(index) * UInt(2654435761u) + UInt(12345u);
    UInt b = (a ^ (a >> 15)) * UInt(2246822519u);
    const Int kind = index & 15;
    a = select(kind == Int(0), UInt(0u), a);
    a = select(kind == Int(1), UInt(0xFFFFFFFFu), a);
    a = select(kind == Int(2), UInt(0x80000000u), a);
    b = select(kind == Int(3), UInt(0xFFFFFFFFu), b);
    const Int offset = int_of(b & UInt(31u)) + ((index >> 4) & 1);
    const Int bits = int_of((b >> 5) & UInt(31u)) + ((index >> 5) & 1);
    const Vec4 f(from_bits_of(index), float_of((index & 1023) - Int(512)) / 400.0f, edge_of(index),
                 (float_of(index & 255) + 0.5f) / 255.0f);
    if (group_ == 0) {
        UInt carry, borrow;
        return Vec4(halves(uaddCarry(a, b, carry)), halves(usubBorrow(a, b, borrow)));
    } else if (group_ == 1) {
        UInt carry, borrow;
        uaddCarry(a, b, carry);
        usubBorrow(a, b, borrow);
        return Vec4(float_of(carry), float_of(borrow), float_of(findLSB(a)), float_of(findMSB(a)));
    } else if (group_ == 2) {
        UInt msb, lsb;
        umulExtended(a, b, msb, lsb);
        return Vec4(halves(msb), halves(lsb));
    } else if (group_ == 3) {
        Int msb, lsb;
        imulExtended(int_of(a), int_of(b), msb, lsb);
        return Vec4(halves(UInt(msb)), halves(UInt(lsb)));
    } else if (group_ == 4) {
        return Vec4(halves(UInt(bitfieldExtract(int_of(a), offset, bits))), halves(bitfieldExtract(a, offset, bits)));
    } else if (group_ == 5) {
        return Vec4(halves(bitfieldInsert(a, b, offset, bits)), halves(bitfieldReverse(a)));
    } else if (group_ == 6) {
        const BVec3 lt = lessThan(f.xyz(), f.yzw());
        const BVec3 ge = greaterThanEqual(f.xyz(), f.yzw());
        const BVec3 eq = equal(f.xyz(), f.zwx());
        const BVec3 ne = notEqual(f.xyz(), f.zwx());
        const BVec2 ult = lessThan(UVec2(a, b), UVec2(b, a));
        const BVec2 ieq = equal(IVec2(int_of(a), int_of(b)), IVec2(int_of(b), int_of(a)));
        const Int relations = int_of_bool(any(lt)) | (int_of_bool(all(ge)) << 1) | (int_of_bool(any(not_(eq))) << 2) |
                              (int_of_bool(all(ne)) << 3) | (int_of_bool(lt.y) << 4) | (int_of_bool(any(ult)) << 5) |
                              (int_of_bool(all(ult)) << 6) | (int_of_bool(any(ieq)) << 7);
        return Vec4(float_of(bitCount(a)), float_of(findMSB(int_of(a))), float_of(findLSB(int_of(b))),
                    float_of(relations));
    } else if (group_ == 7) {
        return Vec4(halves(packUnorm2x16(f.xy())), halves(packSnorm4x8(f)));
    } else if (group_ == 8) {
        return Vec4(halves(packHalf2x16(f.xy())), halves(packUnorm4x8(f)));
    } else if (group_ == 9) {
        return Vec4(halves(packSnorm2x16(f.zw())), unpackUnorm2x16(a));
    } else if (group_ == 10) {
        return Vec4(unpackSnorm2x16(a), unpackHalf2x16(a));
    } else if (group_ == 11) {
        return unpackUnorm4x8(a);
    } else if (group_ == 12) {
        return unpackSnorm4x8(a);
    }
    // In range only: outside, GLSL leaves the conversion undefined.
    const Float u = float_of(a) * (float_of(b & UInt(0xFFFFu)) / 65536.0f);
    const Float i = float_of(int_of(a)) * (float_of(b >> 16) / 65536.0f);
    return Vec4(halves(uint_of(u)), halves(UInt(int_of(i))));
}

}  // namespace st
