// glsl_math_test.cpp: the GLSL built-ins give the same bits on lanes as for
// one float (they are one template), if_else picks per lane and skips a side
// no lane takes, and dFdx/dFdy of computed values stay inside each quad.
#include "shading/glsl_math.h"

#include <bit>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <xmmintrin.h>

#include "shading/derivatives.h"
#include "simd/lanes.h"

namespace st {

namespace {

std::vector<float> inputs() {
    std::vector<float> v = {0.0f, -0.0f, 1e-40f, 127.99f, 128.0f, 129.0f, -126.99999f, -127.0f, -200.0f, 88.7f,
                            -88.7f, std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                            std::numeric_limits<float>::quiet_NaN()};
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> wide(-150.0f, 150.0f), narrow(-1.0f, 1.0f);
    for (int i = 0; i < 20000; ++i) v.push_back(i % 2 ? wide(rng) : narrow(rng));
    return v;
}

// The shading threads' float environment (raster/float_env.h): flush to
// zero and denormals are zero, which roundps obeys and a C library's
// floorf may not.
class ShadingFloatEnv {
public:
    ShadingFloatEnv() : saved_(_mm_getcsr()) { _mm_setcsr(saved_ | 0x8040u); }
    ~ShadingFloatEnv() { _mm_setcsr(saved_); }

private:
    unsigned saved_;
};

template <class LaneFn, class ScalarFn>
void same_bits(LaneFn lanes, ScalarFn scalar, const char* what) {
    const ShadingFloatEnv env;
    const std::vector<float> v = inputs();
    for (size_t i = 0; i + kLanes <= v.size(); i += kLanes) {
        const Float r = lanes(Float::load(&v[i]));
        for (int lane = 0; lane < kLanes; ++lane)
            ASSERT_EQ(std::bit_cast<uint32_t>(r[lane]), std::bit_cast<uint32_t>(scalar(v[i + size_t(lane)])))
                << what << "(" << v[i + size_t(lane)] << ")";
    }
}

}  // namespace

TEST(GlslMath, LanesGiveTheScalarBits) {
    same_bits([](Float x) { return glsl::exp2(x); }, [](float x) { return glsl::exp2(x); }, "exp2");
    same_bits([](Float x) { return glsl::exp(x); }, [](float x) { return glsl::exp(x); }, "exp");
    same_bits([](Float x) { return glsl::inversesqrt(x); }, [](float x) { return glsl::inversesqrt(x); },
              "inversesqrt");
    same_bits([](Float x) { return glsl::max(x, Float(0.25f)); }, [](float x) { return glsl::max(x, 0.25f); }, "max");
    same_bits([](Float x) { return glsl::min(Float(-0.0f), x); }, [](float x) { return glsl::min(-0.0f, x); }, "min");
    same_bits([](Float x) { return glsl::log2(x); }, [](float x) { return glsl::log2(x); }, "log2");
    same_bits([](Float x) { return glsl::log(x); }, [](float x) { return glsl::log(x); }, "log");
    same_bits([](Float x) { return glsl::pow(glsl::abs(x), Float(2.5f)); },
              [](float x) { return glsl::pow(glsl::abs(x), 2.5f); }, "pow");
    same_bits([](Float x) { return glsl::length(Vec3(x, x * Float(0.5f), Float(2.0f))); },
              [](float x) { return glsl::length(glm::vec3(x, x * 0.5f, 2.0f)); }, "length");
}

TEST(GlslMath, CommonLanesGiveTheScalarBits) {
    using namespace glsl;
    same_bits([](Float x) { return sign(x); }, [](float x) { return sign(x); }, "sign");
    same_bits([](Float x) { return ceil(x); }, [](float x) { return ceil(x); }, "ceil");
    same_bits([](Float x) { return trunc(x); }, [](float x) { return trunc(x); }, "trunc");
    same_bits([](Float x) { return round(x); }, [](float x) { return round(x); }, "round");
    same_bits([](Float x) { return fract(x); }, [](float x) { return fract(x); }, "fract");
    same_bits([](Float x) { return mod(x, Float(0.75f)); }, [](float x) { return mod(x, 0.75f); }, "mod");
    same_bits([](Float x) { return clamp(x, Float(-0.5f), Float(0.5f)); }, [](float x) { return clamp(x, -0.5f, 0.5f); },
              "clamp");
    same_bits([](Float x) { return smoothstep(Float(-1.0f), Float(2.0f), x); },
              [](float x) { return smoothstep(-1.0f, 2.0f, x); }, "smoothstep");
    same_bits([](Float x) { return mix(Float(3.0f), x, x * 0.125f); }, [](float x) { return mix(3.0f, x, x * 0.125f); },
              "mix");
    same_bits([](Float x) { return mix_strict(Float(3.0f), x, Float(0.3f)); },
              [](float x) { return mix_strict(3.0f, x, 0.3f); }, "mix_strict");
    same_bits([](Float x) { return fma(x, x, Float(-1.0f)); }, [](float x) { return fma(x, x, -1.0f); }, "fma");
    same_bits([](Float x) { return ldexp(x, simd::itrunc(x)); }, [](float x) {
        return ldexp(x, std::isnan(x) || std::fabs(x) >= 2147483648.0f ? INT32_MIN : int32_t(x)); }, "ldexp");
    same_bits([](Float x) { Int e; return frexp(x, e); }, [](float x) { int32_t e; return frexp(x, e); }, "frexp");
    same_bits([](Float x) { Int e; frexp(x, e); return simd::to_float(e); },
              [](float x) { int32_t e; frexp(x, e); return float(e); }, "frexp's exponent");
}

// The common built-ins' edges as llvmpipe has them (glsl-builtins.md 2).
TEST(GlslMath, CommonEdgesAreLlvmpipes) {
    using namespace glsl;
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    const auto bits = [](float x) { return std::bit_cast<uint32_t>(x); };
    EXPECT_EQ(bits(sign(-0.0f)), 0u);  // +0, not -0
    EXPECT_EQ(bits(sign(nan)), 0u);
    EXPECT_EQ(sign(-inf), -1.0f);
    EXPECT_EQ(fract(-1e-10f), 1.0f);  // no clamp below 1
    EXPECT_TRUE(std::isnan(fract(inf)));
    EXPECT_EQ(round(0.5f), 0.0f);  // round is roundEven
    EXPECT_EQ(round(2.5f), 2.0f);
    EXPECT_EQ(bits(round(-0.5f)), bits(-0.0f));
    float whole = 0.0f;
    EXPECT_EQ(bits(modf(-3.0f, whole)), 0u);  // -3 - (-3) is +0
    EXPECT_EQ(whole, -3.0f);
    EXPECT_TRUE(std::isnan(mod(1.0f, 0.0f)));
    EXPECT_TRUE(std::isnan(mod(1.0f, inf)));
    EXPECT_EQ(mod(-1e-10f, 1.0f), 1.0f);  // the result can equal y
    EXPECT_EQ(clamp(nan, 0.25f, 1.0f), 0.25f);
    EXPECT_EQ(bits(clamp(-0.0f, 0.0f, 1.0f)), 0u);
    EXPECT_EQ(step(nan, 1.0f), 0.0f);
    EXPECT_EQ(smoothstep(0.0f, 1.0f, nan), 0.0f);
    // The mix forms differ at t = 1: the fast one loses y to rounding.
    EXPECT_EQ(mix(1e38f, 1.0f, 1.0f), 0.0f);
    EXPECT_EQ(mix_strict(1e38f, 1.0f, 1.0f), 1.0f);
    EXPECT_EQ(mix_from_one(4.0f, 0.5f), 2.5f);
    EXPECT_EQ(mix_from_minus_one(4.0f, 0.5f), 1.5f);
    // Not fused: (1 + 2^-12)^2 - 1 loses the 2^-24 a fused one keeps.
    volatile float a = 1.0f + 0x1p-12f;
    EXPECT_EQ(fma(float(a), float(a), -1.0f), 0x1p-11f);
    EXPECT_NE(std::fma(float(a), float(a), -1.0f), 0x1p-11f);
    int32_t e = 0;
    EXPECT_EQ(frexp(inf, e), 0.5f);
    EXPECT_EQ(e, 129);
    EXPECT_EQ(frexp(-6.0f, e), -0.75f);
    EXPECT_EQ(e, 3);
    EXPECT_EQ(bits(frexp(-0.0f, e)), bits(-0.0f));
    EXPECT_EQ(e, 0);
    EXPECT_EQ(ldexp(1.0f, 128), inf);
    EXPECT_EQ(ldexp(1.0f, 127), 0x1p127f);
    EXPECT_EQ(bits(ldexp(-1.0f, -127)), bits(-0.0f));  // below 2^-126: +-0
    EXPECT_EQ(ldexp(3.0f, -2), 0.75f);
    EXPECT_EQ(ldexp(-inf, -300), -inf);
    // be + e is not guarded (the spec leaves a huge e undefined): it wraps to
    // a negative exponent, so +-0, and the twin does so without UB.
    EXPECT_EQ(bits(ldexp(1.5f, INT32_MAX)), 0u);
    EXPECT_TRUE(isinf(-inf));
    EXPECT_FALSE(isinf(nan));
    EXPECT_TRUE(isnan(nan));
}

// The vector forms are the scalar one per component, with GLSL's mixed
// vector and scalar shapes, for lanes and for glm.
TEST(GlslMath, CommonVectorFormsArePerComponent) {
    using namespace glsl;
    const Vec3 v(Float(-1.5f), Float(0.25f), Float(7.0f));
    const Vec3 c = clamp(v, Float(0.0f), Float(1.0f));
    EXPECT_EQ(c.x[0], 0.0f);
    EXPECT_EQ(c.y[0], 0.25f);
    EXPECT_EQ(c.z[0], 1.0f);
    const Vec3 s = smoothstep(Float(0.0f), Float(1.0f), v);
    EXPECT_EQ(s.y[0], smoothstep(0.0f, 1.0f, 0.25f));
    const Vec3 m = mix(v, Vec3(Float(2.0f)), BVec3(Mask(true), Mask(false), Mask(true)));
    EXPECT_EQ(m.x[0], 2.0f);
    EXPECT_EQ(m.y[0], 0.25f);
    const Vec3 st = step(Float(0.5f), v);
    EXPECT_EQ(st.z[0], 1.0f);
    EXPECT_EQ(st.y[0], 0.0f);
    const IVec3 b = floatBitsToInt(v);
    EXPECT_EQ(b.y[0], std::bit_cast<int32_t>(0.25f));
    EXPECT_EQ(intBitsToFloat(b).z[0], 7.0f);
    // glm's own mix, fract, ... are found too for glm types: qualify.
    const glm::vec3 g = glsl::mod(glm::vec3(5.5f, -1.0f, 3.0f), 2.0f);
    EXPECT_EQ(g, glm::vec3(1.5f, 1.0f, 1.0f));
    EXPECT_EQ(glsl::mix(glm::vec3(0.0f), glm::vec3(2.0f), glm::vec3(0.5f)), glm::vec3(1.0f));
    EXPECT_EQ(glsl::fract(glm::vec2(1.25f, -0.25f)), glm::vec2(0.25f, 0.75f));
}

// pow, exp2, log2, ... on vectors: each component the scalar's bits (a PBR
// shader's pow(color, vec3(1.0/2.2)) found them missing).
TEST(GlslMath, ExponentialVectorFormsArePerComponent) {
    using namespace glsl;
    const Vec3 v(Float(0.3f), Float(2.5f), Float(17.0f));
    const Vec3 p = pow(v, Vec3(Float(1.0f / 2.2f)));
    const Vec3 e = exp2(v), l = log(v), r = inversesqrt(v);
    for (int c = 0; c < 3; ++c) {
        const float x = v[c][0];
        EXPECT_EQ(std::bit_cast<uint32_t>(p[c][0]), std::bit_cast<uint32_t>(pow(x, 1.0f / 2.2f)));
        EXPECT_EQ(std::bit_cast<uint32_t>(e[c][0]), std::bit_cast<uint32_t>(exp2(x)));
        EXPECT_EQ(std::bit_cast<uint32_t>(l[c][0]), std::bit_cast<uint32_t>(log(x)));
        EXPECT_EQ(std::bit_cast<uint32_t>(r[c][0]), std::bit_cast<uint32_t>(inversesqrt(x)));
    }
    EXPECT_EQ(glsl::pow(glm::vec2(4.0f, 9.0f), glm::vec2(0.5f)), glm::vec2(glsl::pow(4.0f, 0.5f), glsl::pow(9.0f, 0.5f)));
}

TEST(GlslMath, TrigonometryLanesGiveTheScalarBits) {
    using namespace glsl;
    same_bits([](Float x) { return sin(x); }, [](float x) { return sin(x); }, "sin");
    same_bits([](Float x) { return cos(x); }, [](float x) { return cos(x); }, "cos");
    same_bits([](Float x) { return tan(x); }, [](float x) { return tan(x); }, "tan");
    same_bits([](Float x) { return asin(x * 0.01f); }, [](float x) { return asin(x * 0.01f); }, "asin");
    same_bits([](Float x) { return acos(x * 0.01f); }, [](float x) { return acos(x * 0.01f); }, "acos");
    same_bits([](Float x) { return atan(x); }, [](float x) { return atan(x); }, "atan");
    same_bits([](Float x) { return atan(x, Float(-0.5f)); }, [](float x) { return atan(x, -0.5f); }, "atan2");
    same_bits([](Float x) { return sinh(x); }, [](float x) { return sinh(x); }, "sinh");
    same_bits([](Float x) { return cosh(x); }, [](float x) { return cosh(x); }, "cosh");
    same_bits([](Float x) { return tanh(x); }, [](float x) { return tanh(x); }, "tanh");
    same_bits([](Float x) { return asinh(x); }, [](float x) { return asinh(x); }, "asinh");
    same_bits([](Float x) { return acosh(x); }, [](float x) { return acosh(x); }, "acosh");
    same_bits([](Float x) { return atanh(x * 0.01f); }, [](float x) { return atanh(x * 0.01f); }, "atanh");
}

// The values glsl-builtins.md section 3 predicts, which the conformance
// scenes confirmed bit for bit against llvmpipe.
TEST(GlslMath, TrigonometryEdgesAreLlvmpipes) {
    using namespace glsl;
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    const auto bits = [](float x) { return std::bit_cast<uint32_t>(x); };
    EXPECT_EQ(bits(atan(1.0f)), 0x3F490FA3u);  // not pi/4 (0x3F490FDB)
    EXPECT_EQ(bits(atan(0.0f, 0.0f)), 0x4016CBD6u);  // 3 pi / 4 by way of atan(1)
    EXPECT_EQ(bits(atan(-0.0f, 0.0f)), 0xC016CBD6u);
    EXPECT_EQ(bits(atan(0.0f, -1.0f)), 0x40490FDBu);  // pi
    EXPECT_EQ(bits(atan(nan)), 0u);
    EXPECT_EQ(bits(atan(-0.0f)), 0u);
    EXPECT_EQ(bits(sin(inf)), 0x7FC00000u);
    EXPECT_EQ(bits(cos(nan)), 0x7FC00000u);
    EXPECT_EQ(bits(sin(-0.0f)), bits(-0.0f));
    EXPECT_EQ(cos(0.0f), 1.0f);
    EXPECT_EQ(tanh(nan), -1.0f);  // the clamp gives -10
    EXPECT_EQ(bits(asin(-0.0f)), 0u);
    EXPECT_EQ(bits(asin(1.0f)), 0x3FC90FDBu);
    EXPECT_TRUE(std::isnan(asin(1.5f)));
    EXPECT_EQ(atanh(1.0f), inf);
    EXPECT_EQ(radians(180.0f), 180.0f * 0.0174532925f);
    // sinh and cosh of NaN: x's own NaN, quieted.
    EXPECT_EQ(bits(sinh(std::bit_cast<float>(0xFF923457u))), 0xFFD23457u);
    EXPECT_EQ(bits(cosh(std::bit_cast<float>(0x7F923457u))), 0x7FD23457u);
}

// The geometric built-ins: lanes, glm and float forms agree, dot sums from
// the last component back, and reflect doubles the dot first (llvmpipe's
// order, which overflows where the written one does not).
TEST(GlslMath, GeometricFormsAgreeAndKeepLlvmpipesOrder) {
    const auto bits = [](float x) { return std::bit_cast<uint32_t>(x); };
    const glm::vec4 a(1e-8f, 3.0f, -7.5f, 1.0f), b(1.0f, 1e8f, 0.25f, -1e8f);
    EXPECT_EQ(bits(glsl::dot(a, b)), bits(((a.w * b.w + a.z * b.z) + a.y * b.y) + a.x * b.x));
    const Vec4 la(a), lb(b);
    EXPECT_EQ(bits(glsl::dot(la, lb)[0]), bits(glsl::dot(a, b)));
    EXPECT_EQ(bits(glsl::length(Vec3(la))[0]), bits(glsl::length(glm::vec3(a))));
    EXPECT_EQ(bits(glsl::normalize(Vec2(la.xy())).y[0]), bits(glsl::normalize(glm::vec2(a)).y));
    EXPECT_EQ(glsl::normalize(-3.0f), -1.0f);  // a float's normalize is sign
    EXPECT_EQ(glsl::distance(2.0f, 5.0f), 3.0f);
    const glm::vec3 c = glsl::cross(glm::vec3(1, 0, 0), glm::vec3(0, 1, 0));
    EXPECT_EQ(c, glm::vec3(0, 0, 1));
    // dot(N, I) * 2 overflows: llvmpipe's order gives infinity.
    const glm::vec3 r = glsl::reflect(glm::vec3(3e38f, 0.0f, 0.0f), glm::vec3(0.6f, 0.8f, 0.0f));
    EXPECT_TRUE(std::isinf(r.y));
    EXPECT_EQ(bits(glsl::reflect(Vec3(la.xyz()), Vec3(lb.xyz())).z[0]),
              bits(glsl::reflect(glm::vec3(a), glm::vec3(b)).z));
    EXPECT_EQ(glsl::faceforward(glm::vec2(1.0f), glm::vec2(1.0f), glm::vec2(1.0f)), glm::vec2(-1.0f));
    EXPECT_EQ(glsl::refract(glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), 2.0f), glm::vec3(0.0f));  // total reflection
}

// Integer and packing built-ins: the spec's values, llvmpipe's where the
// spec leaves them open (masked shift counts), lanes equal to one int.
TEST(GlslMath, IntegerAndPackingValues) {
    using namespace glsl;
    uint32_t carry = 0, borrow = 0;
    EXPECT_EQ(uaddCarry(0xFFFFFFFFu, 2u, carry), 1u);
    EXPECT_EQ(carry, 1u);
    EXPECT_EQ(usubBorrow(1u, 2u, borrow), 0xFFFFFFFFu);
    EXPECT_EQ(borrow, 1u);
    uint32_t msb = 0, lsb = 0;
    umulExtended(0xFFFFFFFFu, 0xFFFFFFFFu, msb, lsb);
    EXPECT_EQ(msb, 0xFFFFFFFEu);
    EXPECT_EQ(lsb, 1u);
    int32_t imsb = 0, ilsb = 0;
    imulExtended(-2, 3, imsb, ilsb);
    EXPECT_EQ(imsb, -1);
    EXPECT_EQ(ilsb, -6);
    EXPECT_EQ(bitfieldExtract(int32_t(0xF0), 4, 4), -1);  // sign-extended
    EXPECT_EQ(bitfieldExtract(0xF0u, 4, 4), 0xFu);
    EXPECT_EQ(bitfieldExtract(int32_t(0x12345678), 0, 0), 0);
    EXPECT_EQ(bitfieldExtract(0x12345678u, 0, 32), 0x12345678u);
    EXPECT_EQ(bitfieldInsert(0xFFFFFFFFu, 0u, 8, 8), 0xFFFF00FFu);
    EXPECT_EQ(bitfieldInsert(1u, 7u, 3, 32), 7u);  // bits > 31: insert
    EXPECT_EQ(bitfieldReverse(1u), 0x80000000u);
    EXPECT_EQ(bitCount(int32_t(-1)), 32);
    EXPECT_EQ(findLSB(0u), -1);
    EXPECT_EQ(findMSB(0u), -1);
    EXPECT_EQ(findMSB(int32_t(-1)), -1);
    EXPECT_EQ(findMSB(int32_t(-2)), 0);
    EXPECT_EQ(findMSB(0x80000000u), 31);
    // Ties go to even; NaN packs as 0 (Unorm) and as -1's code (Snorm).
    EXPECT_EQ(packUnorm4x8(glm::vec4(0.5f / 255.0f, 1.5f / 255.0f, 1.0f, std::nanf(""))), 0x00FF0200u);
    EXPECT_EQ(packSnorm2x16(glm::vec2(std::nanf(""), 1.0f)), 0x7FFF8001u);
    EXPECT_EQ(packHalf2x16(glm::vec2(1.0f, -std::numeric_limits<float>::infinity())), 0xFC003C00u);
    EXPECT_EQ(packHalf2x16(glm::vec2(-std::nanf(""), 65520.0f)), 0x7C00FFFFu);  // NaN 0x7FFF with its sign
    EXPECT_EQ(std::bit_cast<uint32_t>(unpackHalf2x16(0x7C01u).x), 0x7FFFFFFFu);
    EXPECT_EQ(unpackHalf2x16(0x00013C00u), glm::vec2(1.0f, 0x1p-24f));
    EXPECT_EQ(unpackSnorm4x8(0x80u).x, -1.0f);  // -128 clamps to -1
    EXPECT_EQ(unpackUnorm4x8(0xFFu).x, 1.0f);
    // Lanes give each lane's one-int answer.
    UInt a, b;
    Int off, bits;
    for (int l = 0; l < kLanes; ++l) {
        a.set(l, 0x9E3779B9u * uint32_t(l + 1));
        b.set(l, 0x85EBCA6Bu * uint32_t(l + 3));
        off.set(l, l * 5 % 33);
        bits.set(l, l * 7 % 34);
    }
    const UInt ins = bitfieldInsert(a, b, off, bits);
    const Int ext = bitfieldExtract(int_of(a), off, bits);
    const UInt packed = packHalf2x16(Vec2(uintBitsToFloat(a), uintBitsToFloat(b)));
    for (int l = 0; l < kLanes; ++l) {
        EXPECT_EQ(ins[l], bitfieldInsert(a[l], b[l], off[l], bits[l]));
        EXPECT_EQ(ext[l], bitfieldExtract(int32_t(a[l]), off[l], bits[l]));
        EXPECT_EQ(packed[l], packHalf2x16(glm::vec2(std::bit_cast<float>(a[l]), std::bit_cast<float>(b[l]))));
    }
    const BVec2 lt = lessThan(UVec2(UInt(1u), UInt(0x80000000u)), UVec2(UInt(2u), UInt(1u)));
    EXPECT_TRUE(lt.x[0]);
    EXPECT_FALSE(lt.y[0]);  // unsigned: 0x80000000 > 1
    EXPECT_TRUE(any(lt)[0]);
    EXPECT_FALSE(all(lt)[0]);
    EXPECT_TRUE(not_(lt).y[0]);
    const Float nan(std::nanf(""));
    EXPECT_TRUE(notEqual(Vec2(nan), Vec2(nan)).x[0]);  // unordered
    EXPECT_FALSE(equal(Vec2(nan), Vec2(nan)).x[0]);
}

// Matrices: lanes and glm give the same bits, the products keep GLSL IR's
// order, and inverse(mat4)'s determinant is summed right-nested.
TEST(GlslMath, MatrixFormsAgreeAndKeepMesasOrder) {
    glm::mat4 g;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) g[c][r] = float((c * 7 + r * 3) % 11) * 0.37f - 1.5f + (c == r ? 3.0f : 0.0f);
    const Mat4 m(g);
    const auto bits = [](float x) { return std::bit_cast<uint32_t>(x); };
    EXPECT_EQ(bits(glsl::determinant(m)[0]), bits(glsl::determinant(g)));
    const glm::mat4 gi = glsl::inverse(g);
    const Mat4 mi = glsl::inverse(m);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_EQ(bits(mi[c][r][0]), bits(gi[c][r]));
    const glm::mat4 id = g * gi;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_NEAR(id[c][r], c == r ? 1.0f : 0.0f, 1e-5f);
    // m * v is the column sum left to right, as glsl::mul for glm.
    const glm::vec4 v(0.3f, -1.7f, 2.2f, 1e-3f);
    const Vec4 lv(v);
    const Vec4 mv = m * lv;
    EXPECT_EQ(bits(mv.z[0]), bits(glsl::mul(g, v).z));
    // v * m is dot(v, m[j]), from the last term back.
    const Vec4 vm = lv * m;
    EXPECT_EQ(bits(vm.y[0]), bits(glsl::dot(v, g[1])));
    EXPECT_EQ(bits(glsl::determinant(glm::mat3(g))), bits(glsl::determinant(Mat3(m))[0]));
    EXPECT_EQ(bits(glsl::inverse(glm::mat2(g))[1][0]), bits(glsl::inverse(Mat2(m))[1][0][0]));
    const Mat3x4 t(m);
    EXPECT_EQ(glsl::transpose(t)[2][1][0], g[1][2]);
}

// glsl::mul of glm matrices (vertex twins) gives the bits of the lane
// operators (fragment twins) for every shape and all three products; and
// glm's own v * m sums in another order, which is why mul exists.
template <int C, int R, int K> void expect_mul_matches_lanes(std::mt19937& rng, int& glm_differs) {
    std::uniform_real_distribution<float> d(-3.0f, 3.0f);
    glm::mat<C, R, float> a;
    glm::mat<K, C, float> b;
    glm::vec<C, float> v;
    glm::vec<R, float> u;
    for (int c = 0; c < C; ++c)
        for (int r = 0; r < R; ++r) a[c][r] = d(rng);
    for (int k = 0; k < K; ++k)
        for (int c = 0; c < C; ++c) b[k][c] = d(rng);
    for (int c = 0; c < C; ++c) v[c] = d(rng);
    for (int r = 0; r < R; ++r) u[r] = d(rng);
    const auto bits = [](float x) { return std::bit_cast<uint32_t>(x); };
    const LaneMat<C, R> la(a);
    const LaneMat<K, C> lb(b);
    LaneVec<Float, C> lv;
    LaneVec<Float, R> lu;
    for (int c = 0; c < C; ++c) lv[c] = Float(v[c]);
    for (int r = 0; r < R; ++r) lu[r] = Float(u[r]);
    const auto mv = glsl::mul(a, v);
    const auto lmv = la * lv;
    for (int r = 0; r < R; ++r) EXPECT_EQ(bits(mv[r]), bits(lmv[r][0])) << C << "x" << R << " m * v, row " << r;
    const auto um = glsl::mul(u, a);
    const auto lum = lu * la;
    for (int c = 0; c < C; ++c) {
        EXPECT_EQ(bits(um[c]), bits(lum[c][0])) << C << "x" << R << " v * m, column " << c;
        glm_differs += bits((u * a)[c]) != bits(um[c]);
    }
    const auto ab = glsl::mul(a, b);
    const auto lab = la * lb;
    for (int k = 0; k < K; ++k)
        for (int r = 0; r < R; ++r) EXPECT_EQ(bits(ab[k][r]), bits(lab[k][r][0])) << C << "x" << R << " a * b";
}

TEST(GlslMath, MulOfGlmMatricesIsTheLaneOperators) {
    std::mt19937 rng(27);
    int glm_differs = 0;
    for (int trial = 0; trial < 200; ++trial) {
        expect_mul_matches_lanes<2, 2, 3>(rng, glm_differs);
        expect_mul_matches_lanes<3, 3, 3>(rng, glm_differs);
        expect_mul_matches_lanes<4, 4, 4>(rng, glm_differs);
        expect_mul_matches_lanes<2, 3, 3>(rng, glm_differs);
        expect_mul_matches_lanes<3, 2, 4>(rng, glm_differs);
        expect_mul_matches_lanes<4, 3, 2>(rng, glm_differs);
        expect_mul_matches_lanes<3, 4, 4>(rng, glm_differs);
        expect_mul_matches_lanes<2, 4, 2>(rng, glm_differs);
        expect_mul_matches_lanes<4, 2, 3>(rng, glm_differs);
    }
    EXPECT_GT(glm_differs, 0) << "glm's v * m summed as GLSL does on every input: the order test proves nothing";
}

// Doubles: the lanes give the scalar bits, and the lowered forms answer as
// llvmpipe measured (conformance-builtins-double-*): ceil and trunc of
// (-1, 0) are +0.0, floor and ceil of infinity are infinity, round is to
// even, mix is t * y + (1 - t) * x, and under the shading threads' DAZ min
// and max return a denormal as 0.
TEST(GlslMath, DoubleLanesGiveTheScalarBitsAndLlvmpipesLowering) {
    ShadingFloatEnv daz;
    const double inf = std::numeric_limits<double>::infinity();
    const double xs[] = {0.0, -0.0, 0.5, -0.5, 1.5, 2.5, -2.5, 3.5, -1.0, 1e300, -1e-300, 4.9e-324, -4.9e-324,
                         inf, -inf, std::nan(""), 4503599627370495.5, -4503599627370497.0, 0.49999999999999994};
    const auto bits = [](double x) { return std::bit_cast<uint64_t>(x); };
    for (double x : xs) {
        const Double lx(x);
        const double y = 0.75;
        EXPECT_EQ(bits(glsl::floor(lx)[0]), bits(glsl::floor(x))) << x;
        EXPECT_EQ(bits(glsl::ceil(lx)[0]), bits(glsl::ceil(x))) << x;
        EXPECT_EQ(bits(glsl::trunc(lx)[0]), bits(glsl::trunc(x))) << x;
        EXPECT_EQ(bits(glsl::roundEven(lx)[0]), bits(glsl::roundEven(x))) << x;
        EXPECT_EQ(bits(glsl::fract(lx)[0]), bits(glsl::fract(x))) << x;
        EXPECT_EQ(bits(glsl::sign(lx)[0]), bits(glsl::sign(x))) << x;
        EXPECT_EQ(bits(glsl::mod(lx, Double(y))[0]), bits(glsl::mod(x, y))) << x;
        EXPECT_EQ(bits(glsl::max(lx, Double(y))[0]), bits(glsl::max(x, y))) << x;
        EXPECT_EQ(bits(glsl::min(lx, Double(-y))[0]), bits(glsl::min(x, -y))) << x;
        EXPECT_EQ(bits(glsl::mix(lx, Double(y), Double(0.3))[0]), bits(glsl::mix(x, y, 0.3))) << x;
        EXPECT_EQ(bits(glsl::inversesqrt(lx)[0]), bits(glsl::inversesqrt(x))) << x;
        EXPECT_EQ(std::bit_cast<uint32_t>(to_float(lx)[0]), std::bit_cast<uint32_t>(float(x))) << x;
    }
    EXPECT_EQ(bits(glsl::ceil(-0.5)), bits(0.0));
    EXPECT_EQ(bits(glsl::trunc(-0.5)), bits(0.0));
    EXPECT_EQ(glsl::floor(-inf), -inf);
    EXPECT_EQ(glsl::ceil(inf), inf);
    EXPECT_EQ(glsl::round(2.5), 2.0);
    EXPECT_EQ(glsl::round(-2.5), -2.0);
    EXPECT_EQ(glsl::round(3.5), 4.0);
    EXPECT_EQ(bits(glsl::sign(-0.0)), bits(0.0));
    EXPECT_EQ(bits(glsl::max(4.9e-324, -1.0)), bits(0.0));  // DAZ: the denormal comes back as 0
    // frexp and ldexp: GLSL IR's integer lowering, zero's quirk included (conformance-builtins-double-frexp-ldexp).
    int32_t e = 0;
    EXPECT_EQ(glsl::frexp(12.0, e), 0.75);
    EXPECT_EQ(e, 4);
    EXPECT_EQ(glsl::ldexp(0.75, 4), 12.0);
    EXPECT_EQ(glsl::ldexp(0.0, 0), 0.5);  // the exponent field 1022 + e over zero's mantissa
    EXPECT_EQ(bits(glsl::ldexp(-3.0, -2000)), bits(-0.0));
    for (double x : xs) {
        Int le;
        const double m = glsl::frexp(x, e);
        EXPECT_EQ(bits(glsl::frexp(Double(x), le)[0]), bits(m)) << x;
        EXPECT_EQ(le[0], e) << x;
        EXPECT_EQ(bits(glsl::ldexp(Double(x), Int(-7))[0]), bits(glsl::ldexp(x, -7))) << x;
    }
    const DVec3 a(Double(0.1), Double(-2.0), Double(3.0)), b(Double(7.0), Double(0.5), Double(-0.25));
    const glm::dvec3 ga(0.1, -2.0, 3.0), gb(7.0, 0.5, -0.25);
    EXPECT_EQ(bits(glsl::dot(a, b)[0]), bits(glsl::dot(ga, gb)));
    EXPECT_EQ(bits(glsl::normalize(a).y[0]), bits(glsl::normalize(ga).y));
    EXPECT_EQ(bits(glsl::dot(ga, gb)), bits((3.0 * -0.25 + -2.0 * 0.5) + 0.1 * 7.0));  // from the last term back
}

// gallivm's fmax/fmin (docs/llvmpipe/glsl-builtins.md 2.8): a tie gives the
// second operand, one NaN the other operand. The twin gave -0.0 for
// max(-0.0, 0.0) where llvmpipe gives +0.0 (explore profile --seed 2026).
TEST(GlslMath, MaxAndMinAreGallivmsOnTiesAndNaN) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    auto bits = [](float x) { return std::bit_cast<uint32_t>(x); };
    EXPECT_EQ(bits(glsl::max(-0.0f, 0.0f)), bits(0.0f));
    EXPECT_EQ(bits(glsl::max(0.0f, -0.0f)), bits(-0.0f));
    EXPECT_EQ(bits(glsl::min(0.0f, -0.0f)), bits(-0.0f));
    EXPECT_EQ(bits(glsl::min(-0.0f, 0.0f)), bits(0.0f));
    EXPECT_EQ(glsl::max(nan, 2.0f), 2.0f);
    EXPECT_EQ(glsl::max(2.0f, nan), 2.0f);
    EXPECT_EQ(glsl::min(nan, -2.0f), -2.0f);
    EXPECT_EQ(glsl::min(-2.0f, nan), -2.0f);
    const Float l = glsl::max(Float(-0.0f), Float(0.0f)), m = glsl::min(Float(nan), Float(3.0f));
    for (int lane = 0; lane < kLanes; ++lane) {
        EXPECT_EQ(bits(l[lane]), bits(0.0f));
        EXPECT_EQ(m[lane], 3.0f);
    }
}

// log2 and pow at their edges, as lp_build_log2_safe and lp_build_pow give
// them (docs/llvmpipe/glsl-builtins.md 1.3, 1.5); the conformance scene
// compares them with llvmpipe itself.
TEST(GlslMath, Log2AndPowEdgesAreGallivms) {
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    auto bits = [](float x) { return std::bit_cast<uint32_t>(x); };
    EXPECT_EQ(glsl::log2(1.0f), 0.0f);
    EXPECT_EQ(glsl::log2(8.0f), 3.0f);
    EXPECT_EQ(glsl::log2(0.125f), -3.0f);
    EXPECT_EQ(glsl::log2(0.0f), -inf);
    EXPECT_EQ(glsl::log2(-0.0f), -inf);
    EXPECT_EQ(glsl::log2(inf), inf);
    EXPECT_EQ(bits(glsl::log2(-1.0f)), 0x7FC00000u);
    EXPECT_EQ(bits(glsl::log2(-nan)), 0x7FC00000u);  // the payload and sign are lost
    EXPECT_NEAR(glsl::log2(3.0f), 1.5849625f, 2e-7f);
    EXPECT_EQ(bits(glsl::pow(nan, 1.0f)), bits(0.0f));
    EXPECT_EQ(bits(glsl::pow(0.0f, -1.0f)), bits(0.0f));
    EXPECT_EQ(bits(glsl::pow(-0.0f, 3.0f)), bits(0.0f));
    EXPECT_TRUE(std::isnan(glsl::pow(-8.0f, 2.0f)));
    EXPECT_EQ(glsl::pow(5.0f, 0.0f), 1.0f);
    // exp2 of a signalling NaN is its quiet NaN, as llvmpipe's arithmetic
    // leaves it (volatile: no compile-time folding).
    volatile uint32_t snan = 0xFF923457u;
    const float x = std::bit_cast<float>(uint32_t(snan));
    EXPECT_EQ(bits(glsl::exp2(x)), 0xFFD23457u);
    EXPECT_EQ(std::bit_cast<uint32_t>(glsl::exp2(Float(x))[0]), 0xFFD23457u);
}

TEST(GlslMath, IfElseTakesEachLanesSideAndSkipsAnUntakenOne) {
    Float x;
    for (int lane = 0; lane < kLanes; ++lane) x.set(lane, float(lane) - 3.5f);
    int then_runs = 0, else_runs = 0;
    auto pick = [&](Mask c) {
        return glsl::if_else(
            c, [&] { ++then_runs; return x * Float(2.0f); }, [&] { ++else_runs; return -x; });
    };
    const Float mixed = pick(x < Float(0.0f));
    EXPECT_EQ(then_runs, 1);
    EXPECT_EQ(else_runs, 1);
    for (int lane = 0; lane < kLanes; ++lane) EXPECT_EQ(mixed[lane], x[lane] < 0 ? x[lane] * 2.0f : -x[lane]);
    then_runs = else_runs = 0;
    pick(Mask(true));
    EXPECT_EQ(then_runs, 1);
    EXPECT_EQ(else_runs, 0);
    pick(Mask(false));
    EXPECT_EQ(else_runs, 1);
    EXPECT_EQ(glsl::if_else(true, [] { return 1.0f; }, [] { return 2.0f; }), 1.0f);
}

// Lane order in a quad: (x, y), (x+1, y), (x, y+1), (x+1, y+1). For
// v = x^2 + 3y per lane, dFdx is the row's difference and dFdy the
// column's, and no quad sees another's values.
TEST(Derivatives, OfComputedValuesStayInTheQuad) {
    Float v;
    for (int lane = 0; lane < kLanes; ++lane) {
        const int quad = lane / 4, dx = lane & 1, dy = lane >> 1 & 1;
        const float x = float(10 * quad + dx), y = float(dy);
        v.set(lane, x * x + 3.0f * y);
    }
    const Float ddx = dFdx(v), ddy = dFdy(v);
    for (int lane = 0; lane < kLanes; ++lane) {
        const int quad = lane / 4, dy = lane >> 1 & 1;
        const float x0 = float(10 * quad);
        const float row_left = x0 * x0 + 3.0f * float(dy), row_right = (x0 + 1) * (x0 + 1) + 3.0f * float(dy);
        EXPECT_EQ(ddx[lane], row_right - row_left) << lane;
        EXPECT_EQ(ddy[lane], 3.0f) << lane;
    }
}

}  // namespace st
