// glsl_math.cpp: see glsl_math.h. The arithmetic below follows
// gallivm/lp_bld_arit.c (lp_build_exp2, lp_build_polynomial,
// lp_build_ifloor_fract, lp_build_rsqrt); docs/llvmpipe/ has the reading.
#include "shading/glsl_math.h"

#include <bit>
#include <cmath>
#include <cstdint>

namespace st::glsl {

namespace {

// 2^x on [0, 1): minimax fit, the coefficients llvmpipe uses, as floats.
constexpr float kExp2Poly[6] = {
    float(1.000000000000000000000), float(0.693153073200168932794), float(0.240153617044375388211),
    float(0.0558263180532956664775), float(0.00898934009049466391101), float(0.00187757667519147912699),
};

// Even and odd coefficients in two Horner chains over x^2, joined by one
// more multiply-add: c0 + x2 (c2 + x2 c4) + x (c1 + x2 (c3 + x2 c5)).
float exp2_polynomial(float x) {
    const float x2 = x * x;
    float even = kExp2Poly[4];
    even = std::fma(x2, even, kExp2Poly[2]);
    even = std::fma(x2, even, kExp2Poly[0]);
    float odd = kExp2Poly[5];
    odd = std::fma(x2, odd, kExp2Poly[3]);
    odd = std::fma(x2, odd, kExp2Poly[1]);
    return std::fma(odd, x, even);
}

}  // namespace

float exp2(float x) {
    if (std::isnan(x)) return x;
    x = x < 128.0f ? x : 128.0f;  // NaN returned above
    x = x > -126.99999f ? x : -126.99999f;
    const float ipart = std::floor(x);
    const float fpart = x - ipart;
    // 2^ipart through the exponent field; ipart = 128 gives +inf's pattern.
    const auto biased = uint32_t(int32_t(ipart) + 127) << 23;
    const float expipart = std::bit_cast<float>(biased);
    return expipart * exp2_polynomial(fpart);
}

float exp(float x) {
    constexpr float log2e = float(1.44269504088896340736);  // M_LOG2E, as NIR folds it
    return exp2(x * log2e);
}

float inversesqrt(float x) { return 1.0f / std::sqrt(x); }

// Measured against llvmpipe (thin-slab scenes, bit for bit): the three
// products are summed as x + (y + z), not left to right as fsum3 reads.
float dot(const glm::vec3& a, const glm::vec3& b) {
    const float xx = a.x * b.x, yy = a.y * b.y, zz = a.z * b.z;
    const float yz = yy + zz;
    return xx + yz;
}

float length(const glm::vec3& v) { return std::sqrt(dot(v, v)); }

glm::vec3 normalize(const glm::vec3& v) {
    const float s = inversesqrt(dot(v, v));
    return glm::vec3(v.x * s, v.y * s, v.z * s);
}

glm::vec4 mul(const glm::mat4& m, const glm::vec4& v) {
    glm::vec4 r;
    for (int i = 0; i < 4; ++i) {
        const float a = m[0][i] * v.x, b = m[1][i] * v.y, c = m[2][i] * v.z, d = m[3][i] * v.w;
        r[i] = ((a + b) + c) + d;
    }
    return r;
}

}  // namespace st::glsl
