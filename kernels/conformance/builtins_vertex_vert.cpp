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
constexpr int kExponents[16] = {0, 1, -1, 127, -127, 128, -126, 254, -254, 10, -10, 255, -300, 300, 23, -23};
// The edges with NaN's place taken by -2 (the GLSL's `others`).
constexpr int32_t kOthers[16] = {0x00000000, INT32_MIN,  0x3F800000,          int32_t(0xBF800000),
                                 0x3F000000, 0x40200000, int32_t(0xC0700000), 0x0DA24260,
                                 int32_t(0xF149F2CA), 0x7F61B1E6, 0x7F800000, int32_t(0xFF800000),
                                 int32_t(0xC0000000), 0x00400000, 0x3DCCCCCD, 0x40E00000};
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
    const float w = std::bit_cast<float>(kOthers[(index ^ (index >> 4) ^ (index >> 8)) & 15]);
    const float z = std::bit_cast<float>(kOthers[((index >> 2) ^ (index >> 7) ^ 5) & 15]);
    const int ix = glsl::floatBitsToInt(x);
    const int e = kExponents[((index >> 1) ^ (index >> 6)) & 15];
    const glm::vec3 a(value(index, 0), value(index, 1), value(index, 2));
    const glm::vec3 b(value(index, 3), value(index, 4), value(index, 5));
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
