// builtins_double_frag.cpp: twin of glsl/conformance/builtins_double.frag,
// line for line, in Double lanes (simd/lane_double.h).
#include "kernels/conformance/conformance.h"

#include "kernels/conformance/builtin_inputs.h"

namespace st {

namespace {
constexpr int32_t kExponents[64] = {0,    1,    2,    50,   400,  800,  872,  873,  874,  896,  897,  898,  920,
                                    960,  990,  1000, 1010, 1015, 1018, 1019, 1020, 1021, 1022, 1023, 1024, 1025,
                                    1026, 1027, 1028, 1029, 1030, 1031, 1033, 1036, 1040, 1045, 1050, 1053, 1054,
                                    1055, 1056, 1060, 1070, 1074, 1075, 1076, 1077, 1080, 1100, 1126, 1150, 1151,
                                    1152, 1170, 1300, 1600, 1900, 2000, 2030, 2040, 2044, 2045, 2046, 2047};
constexpr uint32_t kMantissasHi[8] = {0u, 0u, 0x80000u, 0xFFFFFu, 0x55555u, 0u, 0x12345u, 0xFFFFFu};
constexpr uint32_t kMantissasLo[8] = {0u, 1u, 0u, 0xFFFFFFFFu, 0x55555555u, 0x10000000u, 0x6789ABCDu, 0xF0000000u};
constexpr uint32_t kEdgesHi[16] = {0x0u,        0x80000000u, 0x3FF00000u, 0xBFF00000u, 0x3FE00000u, 0x40040000u,
                                   0xC00E0000u, 0x01A56E1Fu, 0xFE37E43Cu, 0x46293E59u, 0x7FF00000u, 0xFFF00000u,
                                   0xC0000000u, 0x8u,        0x3FB99999u, 0x401C0000u};
constexpr uint32_t kEdgesLo[16] = {0u, 0u, 0u, 0u, 0u, 0u, 0u, 0xC2F8F359u, 0x8800759Cu, 0x39A08CEAu, 0u, 0u, 0u, 0u,
                                   0x9999999Au, 0u};
constexpr uint32_t kWeightsHi[16] = {0x0u,        0x3FF00000u, 0x3FE00000u, 0x3FD00000u, 0x3FB99999u, 0x3FECCCCCu,
                                     0x3E45798Eu, 0x3FEFFFFFu, 0xBFE00000u, 0x3FF80000u, 0x80000000u, 0x40000000u,
                                     0xC0000000u, 0x7FF00000u, 0x3FD33333u, 0x3FE66666u};
constexpr int32_t kExponentSteps[16] = {0, 1, -1, 1023, -1022, 1024, -1074, 2046, -2046, 10, -10, 2047, -3000, 3000,
                                        52, -52};
constexpr uint32_t kWeightsLo[16] = {0u, 0u, 0u, 0u, 0x9999999Au, 0xCCCCCCCDu, 0xE2308C3Au, 0xFFFFFFFFu,
                                     0u, 0u, 0u, 0u, 0u,          0u,          0x33333333u, 0x66666666u};

// table[k] per lane (the GLSL's constant-array index; k is masked in range).
template <size_t N> UInt element(const uint32_t (&table)[N], Int k) {
    UInt r;
    for (int l = 0; l < kLanes; ++l) r.set(l, table[size_t(k[l]) % N]);
    return r;
}

Double edge(Int k) { return glsl::packDouble2x32(UVec2(element(kEdgesLo, k), element(kEdgesHi, k))); }

Double value(Int index, int k) {
    const Int h = (index * Int(2 * k + 37) + Int(k * 101)) & 1023;
    const Int e = ((index >> (k & 7)) + Int(k)) & 15;
    return double_of(h - Int(512)) * Double(glsl::intBitsToFloat((e + Int(121)) << 23)) / Double(73.0);
}

// The GLSL's a ? b : c chains: every side computed, one kept per lane.
Double pick(Int which, Double r0, Double r1, Double r2, Double r3) {
    return select(which == Int(0), r0, select(which == Int(1), r1, select(which == Int(2), r2, r3)));
}
}  // namespace

void BuiltinsDoubleFragment::bind(const Bindings& b) {
    group_ = b.get_int("group");
    // Groups 8, 11 and any other past 9 read them; a scene that leaves one unset reads 0, as GL does.
    scale_ = b.has("scale") ? b.get_double("scale") : 0.0;
    offset_ = b.has("offset") ? b.get_dvec3("offset") : glm::dvec3(0.0);
    basis_ = b.has("basis") ? b.get_dmat3("basis") : glm::dmat3(0.0);
    corner_ = b.has("corner") ? b.get_dvec4("corner") : glm::dvec4(0.0);
}

Vec4 BuiltinsDoubleFragment::main(const Fragment& frag) const {
    using namespace glsl;
    const Int index = builtin_inputs::pixel_index(frag);
    const Int i = index & 1023;
    const Int which = index >> 10;
    const UInt hi = (UInt(i & 1) << 31) | (UInt(glsl::element(kExponents, (i >> 1) & 63)) << 20) |
                    element(kMantissasHi, (i >> 7) & 7);
    const Double x = packDouble2x32(UVec2(element(kMantissasLo, (i >> 7) & 7), hi));
    const Double y = edge((i ^ (i >> 4) ^ (i >> 8)) & 15);
    const Double z = edge(((i >> 2) ^ (i >> 7) ^ 5) & 15);
    const Int k = (i ^ (i >> 5)) & 15;
    const Double t = packDouble2x32(UVec2(element(kWeightsLo, k), element(kWeightsHi, k)));
    const Double lo = min(y, z), hi_edge = max(y, z);
    Double r;
    if (group_ == 0) {
        r = pick(which, abs(x), sign(x), floor(x), ceil(x));
    } else if (group_ == 1) {
        r = pick(which, trunc(x), round(x), roundEven(x), fract(x));
    } else if (group_ == 2) {
        r = pick(which, sqrt(x), inversesqrt(x), min(x, y), max(x, y));
    } else if (group_ == 3) {
        r = pick(which, mod(x, y), clamp(x, lo, hi_edge), step(y, x), smoothstep(lo, hi_edge, x));
    } else if (group_ == 4) {
        // Double mix has one form whatever its operands, t * y + (1 - t) * x (glsl-builtins.md 8).
        r = pick(which, mix(x, y, t), mix(x, z, Double(0.3)), mix(Double(1.0), y, t), select((i & 2) != Int(0), y, x));
    } else if (group_ == 5) {
        r = pick(which, x + y, x - y, x * y, x / y);
    } else if (group_ == 6) {
        const Int relations = int_of(x < y) | (int_of(x <= y) << 1) | (int_of(x == y) << 2) | (int_of(x != y) << 3) |
                              (int_of(x > y) << 4) | (int_of(x >= y) << 5);
        // double(int(x)) runs as trunc(x) (NIR's ~i2f(f2i(a)) -> ftrunc(a)), the rounding instruction's.
        const Mask in_range = abs(x) < Double(2147483648.0) && (x >= Double(0.0) || x <= Double(-1.0));
        r = pick(which, Double(float_of(x)), select(in_range, simd::trunc_pd(x), x),
                 double_of(int_of(isnan(x)) + Int(2) * int_of(isinf(x))), double_of(relations));
    } else if (group_ == 7) {
        const DVec3 a(value(index, 0), value(index, 1), value(index, 2));
        const DVec3 b(value(index, 3), value(index, 4), value(index, 5));
        r = pick(which, dot(a, b), length(a), distance(a, b), normalize(a).x);
    } else if (group_ == 9) {
        Int fe;
        const Double m = frexp(x, fe);
        const Int e = glsl::element(kExponentSteps, (i ^ (i >> 6)) & 15);
        r = pick(which, m, double_of(fe), ldexp(x, e), ldexp(m, fe));
    } else if (group_ == 10) {
        const DMat2 m2(value(index, 0), value(index, 1), value(index, 2), value(index, 3));
        const DMat3 m3(value(index, 4), value(index, 5), value(index, 6), value(index, 7), value(index, 8), value(index, 9),
                       value(index, 10), value(index, 11), value(index, 12));
        const DMat3 n3(value(index, 13), value(index, 14), value(index, 15), value(index, 16), value(index, 17),
                       value(index, 18), value(index, 19), value(index, 20), value(index, 21));
        const DMat4 m4(DVec4(value(index, 22), value(index, 23), value(index, 24), value(index, 25)),
                       DVec4(value(index, 26), value(index, 27), value(index, 28), value(index, 29)),
                       DVec4(value(index, 30), value(index, 31), value(index, 32), value(index, 33)),
                       DVec4(value(index, 34), value(index, 35), value(index, 36), value(index, 37)));
        const DVec3 v(value(index, 38), value(index, 39), value(index, 40));
        const DVec2 w(value(index, 41), value(index, 42));
        // The GLSL indexes by per-pixel ints; each lane picks its own element here.
        Double d, inv, prod, other;
        for (int l = 0; l < kLanes; ++l) {
            const int il = i[l], j = il & 3, c = (il >> 2) % 3, e = (il >> 4) % 3;
            d.set(l, (j == 0 ? determinant(m2) : j == 1 ? determinant(m3) : j == 2 ? determinant(m4) : (m3 * n3)[c][e])[l]);
            inv.set(l, (j == 0 ? inverse(m2)[c & 1][e & 1] : j == 1 ? inverse(m3)[c][e] : inverse(m4)[c][e + (il & 1)])[l]);
            prod.set(l, (j == 0 ? (m3 * v)[c] : j == 1 ? (v * m3)[c] : j == 2 ? (DMat2x3(m3) * w)[c]
                                                                            : (m4 * DVec4(v, value(index, 43)))[e])[l]);
            other.set(l, (j == 0 ? transpose(m4)[c][e] : j == 1 ? matrixCompMult(m3, n3)[c][e] : outerProduct(v, w)[c & 1][e])[l]);
        }
        r = pick(which, d, inv, prod, other);
    } else if (group_ == 11) {
        const DVec3 a(value(index, 0), value(index, 1), value(index, 2));
        const DVec3 b(value(index, 3), value(index, 4), value(index, 5));
        const DVec3 n = normalize(DVec3(value(index, 6), value(index, 7), value(index, 8)));
        const Int relations = int_of(any(lessThan(DVec3(x, y, z), DVec3(y, z, x)))) |
                              (int_of(all(greaterThanEqual(DVec3(x, y, z), DVec3(z, x, y)))) << 1) |
                              (int_of(any(equal(DVec2(x, y), DVec2(z, x)))) << 2) |
                              (int_of(all(notEqual(DVec2(x, y), DVec2(y, z)))) << 3) |
                              (int_of(lessThanEqual(DVec2(x, t), DVec2(t, y)).y) << 4) |
                              (int_of(greaterThan(DVec2(x, z), DVec2(y, t)).x) << 5);
        Double whole;
        const Double f = modf(x, whole);
        const DVec3 reflected = reflect(a, n), refracted = refract(normalize(a), n, Double(scale_));
        const DVec3 faced = faceforward(a, b, n), crossed = cross(a, b);
        Double r1, r2;
        for (int l = 0; l < kLanes; ++l) {
            const int k = (i[l] >> 2) % 3;
            r1.set(l, reflected[k][l]);
            r2.set(l, faced[k][l]);
            const Double refr_k = refracted[k], cross_k = crossed[k];
            if ((i[l] & 1) == 0) {
                r1.set(l, refr_k[l]);
                r2.set(l, cross_k[l]);
            }
        }
        const Mask odd = (i & 1) != Int(0);
        r = pick(which, select(odd, double_of(relations), fma(x, y, z)), r1, r2,
                 select((i & 2) != Int(0), whole, select(odd, f, mix(x, y, (i & 4) != Int(0)))));
    } else {
        // basis * v: the columns scaled and summed left to right (simd/lane_mat.h's order).
        const DVec3 v(x, Double(0.5), Double(-2.0));
        const Double column_sum = (Double(basis_[0].z) * v.x + Double(basis_[1].z) * v.y) + Double(basis_[2].z) * v.z;
        r = pick(which, Double(scale_) * x, x + Double(offset_.y), column_sum,
                 dot(DVec4(corner_), DVec4(x, Double(0.25), Double(3.0), Double(-1.5))));
    }
    const UVec2 bits = unpackDouble2x32(r);
    return Vec4(float_of(bits.x & UInt(0xFFFFu)), float_of(bits.x >> 16), float_of(bits.y & UInt(0xFFFFu)),
                float_of(bits.y >> 16));
}

}  // namespace st
