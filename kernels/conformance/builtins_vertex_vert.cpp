// builtins_vertex_vert.cpp: twin of glsl/conformance/builtins_vertex.vert,
// line for line, one vertex at a time: the scalar forms of the built-ins
// (float and glm), as a user's vertex twin calls them.
#include "kernels/conformance/conformance.h"

#include <bit>
#include <glm/matrix.hpp>

#include "kernels/conformance/builtin_inputs.h"

namespace st {

namespace {
constexpr int position = 0, uv = 2;    // inputs
constexpr int v_colour = 0, v_uv = 1;  // outputs
}  // namespace

float BuiltinsVertex::value(int index, int k) {
    const int h = (index * (2 * k + 37) + k * 101) & 1023;
    const int e = ((index >> (k & 7)) + k) & 15;
    return float(h - 512) * 0.0137f * glsl::intBitsToFloat((e + 121) << 23);
}

void BuiltinsVertex::run(const glm::vec4* attributes, VertexOut& out) const {
    namespace in = builtin_inputs;
    out.position = attributes[position];
    const int index = int(attributes[uv].x);
    const uint32_t sign_bit = uint32_t(index & 1);
    const uint32_t exponent = uint32_t((index >> 1) & 255);
    const uint32_t mantissa = uint32_t(in::kMantissas[(index >> 9) & 7]);
    const float x = std::bit_cast<float>((sign_bit << 31) | (exponent << 23) | mantissa);
    const float y = std::bit_cast<float>(in::kEdges[(index ^ (index >> 4) ^ (index >> 8)) & 15]);
    const float w = std::bit_cast<float>(in::kOthers[(index ^ (index >> 4) ^ (index >> 8)) & 15]);
    const float z = std::bit_cast<float>(in::kOthers[((index >> 2) ^ (index >> 7) ^ 5) & 15]);
    const int ix = glsl::floatBitsToInt(x);
    const int e = in::kExponents[((index >> 1) ^ (index >> 6)) & 15];
    const glm::vec3 a(value(index, 0), value(index, 1), value(index, 2));
    const glm::vec3 b(value(index, 3), value(index, 4), value(index, 5));
    const float t = std::bit_cast<float>(in::kWeights[(index ^ (index >> 5)) & 15]);
    const float u = std::bit_cast<float>(in::kWeights[((index >> 3) ^ (index >> 9) ^ 9) & 15]);
    uint32_t ua = uint32_t(index) * 2654435761u + 12345u;
    uint32_t ub = (ua ^ (ua >> 15)) * 2246822519u;
    const int kind = index & 15;
    if (kind == 0) ua = 0u;
    if (kind == 1) ua = 0xFFFFFFFFu;
    if (kind == 2) ua = 0x80000000u;
    if (kind == 3) ub = 0xFFFFFFFFu;
    const int offset = int(ub & 31u) + ((index >> 4) & 1);
    const int count = int((ub >> 5) & 31u) + ((index >> 5) & 1);
    const glm::vec4 f(x, float((index & 1023) - 512) / 400.0f, y, (float(index & 255) + 0.5f) / 255.0f);
    glm::vec4 r;
    if (group_ == 0) {
        r = glm::vec4(glsl::log2(x), glsl::log(x), glsl::pow(x, y), glsl::pow(glsl::abs(x), y));
    } else if (group_ == 1) {
        r = glm::vec4(glsl::exp2(x), glsl::exp(x), glsl::sqrt(x), glsl::inversesqrt(x));
    } else if (group_ == 2) {
        r = glm::vec4(glsl::sin(x), glsl::cos(x), glsl::tan(x), glsl::atan(x, y));
    } else if (group_ == 3) {
        r = glm::vec4(glsl::asin(x), glsl::acos(x), glsl::atan(x), glsl::tanh(x));
    } else if (group_ == 4) {
        r = glm::vec4(glsl::floor(x), glsl::fract(x), glsl::mod(x, y), glsl::max(x, y));
    } else if (group_ == 5) {
        const glm::vec3 n = glsl::normalize(b);
        r = glm::vec4(glsl::length(a), glsl::dot(a, b), glsl::reflect(a, n).x,
                      glsl::refract_constant_eta(glsl::normalize(a), n, 0.66f).y);
    } else if (group_ == 7) {
        r = glm::vec4(glsl::sinh(x), glsl::cosh(x), glsl::asinh(x), glsl::atanh(x));
    } else if (group_ == 8) {
        r = glm::vec4(glsl::sign(x), glsl::trunc(x), glsl::round(x), glsl::roundEven(x));
    } else if (group_ == 9) {
        r = glm::vec4(glsl::ceil(x), glsl::clamp(x, glsl::min(w, z), glsl::max(w, z)), glsl::step(w, x),
                      glsl::smoothstep(glsl::min(w, z), glsl::max(w, z), x));
    } else if (group_ == 10) {
        r = glm::vec4(glsl::intBitsToFloat(glsl::bitCount(ix)), glsl::intBitsToFloat(glsl::findLSB(ix)),
                      glsl::intBitsToFloat(glsl::findMSB(ix)), glsl::intBitsToFloat(glsl::bitfieldReverse(ix)));
    } else if (group_ == 11) {
        r = glm::vec4(glsl::uintBitsToFloat(glsl::packUnorm2x16(glm::vec2(x, w))),
                      glsl::uintBitsToFloat(glsl::packSnorm4x8(glm::vec4(x, w, z, 0.5f))),
                      glsl::uintBitsToFloat(glsl::packHalf2x16(glm::vec2(x, w))),
                      glsl::unpackHalf2x16(std::bit_cast<uint32_t>(ix)).x);
    } else if (group_ == 12) {
        r = glm::vec4(glsl::cross(a, b).y, glsl::faceforward(a, b, glm::vec3(a.y, a.z, a.x)).z, glsl::distance(a, b),
                      glsl::normalize(a).x);
    } else if (group_ == 13) {
        const glm::mat2 m2{glm::vec2(a), glm::vec2(b)};
        const glm::mat4 m4(glm::vec4(a, b.x), glm::vec4(b.y, b.z, a.x, a.y),
                           glm::vec4(value(index, 6), value(index, 7), value(index, 8), a.z), glm::vec4(b, 1.0f));
        // outerProduct and transpose round nothing (one product, or none, per element): glm's are exact.
        r = glm::vec4(glsl::determinant(m4), glsl::inverse(m2)[1].x, glm::outerProduct(a, b)[2].y, glm::transpose(m4)[0].w);
    } else if (group_ == 14) {
        int fe = 0;
        // A constant t: the strict form (compiler-rewrites.md, entries 1 and 2).
        r = glm::vec4(glsl::mix_strict(x, w, 0.25f), glsl::fma(x, w, z), glsl::ldexp(x, e), glsl::frexp(x, fe));
    } else if (group_ == 15) {
        int fe = 0;
        [[maybe_unused]] const float m = glsl::frexp(x, fe);
        // Comparisons round nothing: glm's lessThan and greaterThanEqual are GLSL's (false with a NaN).
        r = glm::vec4(float(glsl::isnan(x)) + 2.0f * float(glsl::isinf(x)), glsl::intBitsToFloat(fe),
                      float(glm::any(glm::lessThan(glm::vec2(x, w), glm::vec2(z, x)))),
                      float(glm::all(glm::greaterThanEqual(glm::vec3(x, w, z), glm::vec3(z, x, w)))));
    } else if (group_ == 16) {
        uint32_t carry = 0, borrow = 0, umsb = 0, ulsb = 0;
        int32_t imsb = 0, ilsb = 0;
        glsl::umulExtended(ua, ub, umsb, ulsb);
        glsl::imulExtended(int32_t(ua), int32_t(ub), imsb, ilsb);
        r = glm::vec4(glsl::uintBitsToFloat(glsl::uaddCarry(ua, ub, carry)),
                      glsl::uintBitsToFloat(glsl::usubBorrow(ua, ub, borrow)), glsl::uintBitsToFloat(umsb),
                      glsl::intBitsToFloat(imsb));
    } else if (group_ == 17) {
        uint32_t carry = 0, borrow = 0, umsb = 0, ulsb = 0;
        int32_t imsb = 0, ilsb = 0;
        glsl::uaddCarry(ua, ub, carry);
        glsl::usubBorrow(ua, ub, borrow);
        glsl::umulExtended(ua, ub, umsb, ulsb);
        glsl::imulExtended(int32_t(ua), int32_t(ub), imsb, ilsb);
        r = glm::vec4(float(carry) + 2.0f * float(borrow), glsl::uintBitsToFloat(ulsb), glsl::intBitsToFloat(ilsb),
                      glsl::intBitsToFloat(glsl::bitfieldExtract(int32_t(ua), offset, count)));
    } else if (group_ == 18) {
        r = glm::vec4(glsl::uintBitsToFloat(glsl::bitfieldExtract(ua, offset, count)),
                      glsl::uintBitsToFloat(glsl::bitfieldInsert(ua, ub, offset, count)),
                      glsl::uintBitsToFloat(glsl::packUnorm4x8(f)),
                      glsl::uintBitsToFloat(glsl::packSnorm2x16(glm::vec2(f.z, f.w))));
    } else if (group_ == 19) {
        r = glm::vec4(glsl::unpackUnorm2x16(ua)[index & 1], glsl::unpackSnorm2x16(ua)[(index >> 1) & 1],
                      glsl::unpackUnorm4x8(ua)[index & 3], glsl::unpackSnorm4x8(ua)[(index >> 2) & 3]);
    } else if (group_ == 20) {
        // Comparisons round nothing: glm's relational functions are GLSL's (false with a NaN, but notEqual).
        const glm::vec3 fxyz(f.x, f.y, f.z), fyzw(f.y, f.z, f.w), fzwx(f.z, f.w, f.x);
        const glm::bvec3 le = glm::lessThanEqual(fxyz, fyzw);
        const glm::bvec3 gt = glm::greaterThan(fxyz, fyzw);
        const glm::bvec3 eq = glm::equal(fxyz, fzwx);
        const glm::bvec3 ne = glm::notEqual(fxyz, fzwx);
        const glm::bvec2 ule = glm::lessThanEqual(glm::uvec2(ua, ub), glm::uvec2(ub, ua));
        const glm::bvec2 igt = glm::greaterThan(glm::ivec2(int32_t(ua), int32_t(ub)), glm::ivec2(int32_t(ub), int32_t(ua)));
        const glm::bvec2 beq = glm::equal(glm::bvec2(le.x, gt.y), glm::bvec2(eq.z, ne.x));
        const int relations = int(glm::any(le)) | (int(glm::all(gt)) << 1) | (int(glm::any(glm::not_(eq))) << 2) |
                              (int(glm::all(ne)) << 3) | (int(le.y) << 4) | (int(glm::any(ule)) << 5) |
                              (int(glm::all(igt)) << 6) | (int(glm::any(beq)) << 7) | (int(ua != ub) << 8);
        float whole = 0.0f;
        r = glm::vec4(float(relations), glsl::radians(x), glsl::degrees(x), glsl::modf(x, whole));
    } else if (group_ == 21) {
        // t varies and neither mix shares (x, t) or (w, t) with another: the fast form; a constant 1.0 for x:
        // from one; a bool: a selection (compiler-rewrites.md, notes on 1 and 2).
        r = glm::vec4(glsl::mix(x, w, t), glsl::mix_from_one(w, u), (index & 2) != 0 ? w : x, glsl::abs(x));
    } else if (group_ == 22) {
        const glm::mat3 m3(a, b, glm::vec3(value(index, 6), value(index, 7), value(index, 8)));
        const glm::mat4 m4(glm::vec4(a, b.x), glm::vec4(b.y, b.z, a.x, a.y),
                           glm::vec4(value(index, 6), value(index, 7), value(index, 8), a.z), glm::vec4(b, 1.0f));
        const glm::mat2x3 m23(a, b);
        const glm::mat3x2 m32(value(index, 18), value(index, 19), value(index, 20), value(index, 21), value(index, 22),
                              value(index, 23));
        const glm::mat4x3 m43(b, a, glm::vec3(a.z, a.x, a.y),
                              glm::vec3(value(index, 11), value(index, 12), value(index, 13)));
        const glm::vec4 v4(value(index, 14), value(index, 15), value(index, 16), value(index, 17));
        const int k = index & 3;
        // glsl::mul, not glm's `*` (glm_products.h); matrixCompMult and transpose round one product or none.
        r = glm::vec4((index & 4) != 0 ? glsl::mul(m3, glm::vec3(v4))[k % 3] : glsl::mul(v4, m4)[k],
                      (index & 8) != 0 ? glsl::mul(m23, m32)[k % 3][(k + 1) % 3] : glsl::mul(m43, v4)[(k + 2) % 3],
                      (index & 16) != 0 ? glm::matrixCompMult(m3, glm::transpose(m3))[k % 3].y
                                        : glsl::determinant(glm::mat2(glm::vec2(a.x, a.y), glm::vec2(b.y, b.z))),
                      glsl::inverse(m4)[k][(index >> 2) & 3]);
    } else if (group_ >= 23 && group_ <= 25) {
        // The scalar double forms (llvmpipe's lowering of each: glsl-builtins.md 8).
        const double dx = glsl::packDouble2x32(glm::uvec2(ua, ub));
        const double dy = glsl::packDouble2x32(glm::uvec2(ub, ua ^ 0x3FF00000u));
        const glm::dvec2 d = group_ == 23 ? glm::dvec2(glsl::floor(dx), glsl::ceil(dx))
                           : group_ == 24 ? glm::dvec2(glsl::trunc(dx), glsl::roundEven(dx))
                           : (index & 2) != 0 ? glm::dvec2(glsl::mod(dx, dy), glsl::max(dx, dy))
                                              : glm::dvec2(glsl::fract(dx), glsl::sqrt(dx));
        const glm::uvec2 hx = glsl::unpackDouble2x32(d.x), hy = glsl::unpackDouble2x32(d.y);
        r = glm::vec4(glsl::uintBitsToFloat(hx.x), glsl::uintBitsToFloat(hx.y), glsl::uintBitsToFloat(hy.x),
                      glsl::uintBitsToFloat(hy.y));
    } else if (group_ == 26) {
        const glm::dvec3 da = glm::dvec3(a) / 7.0, db = glm::dvec3(b) / 3.0;
        const glm::dvec3 dc = glm::dvec3(value(index, 6), value(index, 7), value(index, 8)) / 5.0;
        const glm::dvec3 dv = glm::dvec3(value(index, 9), value(index, 10), value(index, 11)) / 9.0;
        const glm::dmat3 dm(da, db, dc);
        const int k = index % 3;
        // Mesa's cofactor expansions and GLSL's products, as for float matrices.
        const glm::dvec2 d = (index & 2) != 0 ? glm::dvec2(glsl::determinant(dm), glsl::mul(dm, dv)[k])
                                              : glm::dvec2(glsl::inverse(dm)[1][k], glsl::mul(dv, dm)[k]);
        const glm::uvec2 hx = glsl::unpackDouble2x32(d.x), hy = glsl::unpackDouble2x32(d.y);
        r = glm::vec4(glsl::uintBitsToFloat(hx.x), glsl::uintBitsToFloat(hx.y), glsl::uintBitsToFloat(hy.x),
                      glsl::uintBitsToFloat(hy.y));
    } else {
        const glm::mat3 m(a, b, glm::vec3(value(index, 6), value(index, 7), value(index, 8)));
        const glm::mat3 inv = glsl::inverse(m);
        r = glm::vec4(glsl::determinant(m), inv[0].x, inv[1].y, inv[2].z);
    }
    for (int c = 0; c < 4; ++c) {
        const uint32_t bits = std::bit_cast<uint32_t>(r[c]);
        out.varyings[v_colour][c] = float(bits >> 16u);
        out.varyings[v_uv][c] = float(bits & 0xFFFFu);
    }
}

}  // namespace st
