// varyings_vert.cpp: twin of glsl/conformance/varyings.vert, line for line.
// The int and uint outputs travel in their slots' float bits
// (intBitsToFloat), which flat interpolation hands to the fragment twin
// untouched (program.h, Interpolation).
#include "kernels/conformance/conformance.h"

namespace st {

namespace {
constexpr int position = 0, colour = 1, uv = 2;                               // inputs
constexpr int v_smooth = 0, v_linear = 1, v_bits = 2, v_flat = 3, v_index = 4;  // outputs

constexpr int32_t patterns[8] = {0x7F800001, int32_t(0xFFC0ABCDu), 0x7F800000, int32_t(0xFF800000u),
                                 int32_t(0x80000000u), 0x00000001, int32_t(0x807FFFFFu), 0x3F800000};
}  // namespace

void VaryingsVertex::run(const glm::vec4* attributes, VertexOut& out) const {
    const glm::vec4 &p = attributes[position], &c = attributes[colour], &t = attributes[uv];
    const float w = t.x;
    out.position = glm::vec4(glm::vec2(p) * reach_ * w, (p.z - t.y) * w, w);
    // Scene colours are whole numbers here and lie within +-1e6 (the
    // triangle list's bound), so int() is in range and -i cannot overflow.
    const int32_t i = int32_t(c.w);
    out.varyings[v_smooth] = c;
    out.varyings[v_linear] = c;
    const glm::ivec4 bits{patterns[i & 7], patterns[(i >> 3) & 7] ^ (i << 8), int32_t(uint32_t(i) * 0x010101u), -i};
    out.varyings[v_bits] = glsl::intBitsToFloat(bits);
    out.varyings[v_flat] = glm::vec4(glsl::intBitsToFloat(patterns[(i + 2) & 7]), c.x, c.y,
                                     glsl::intBitsToFloat(patterns[(i + 5) & 7] ^ (i << 4)));
    const glm::uvec2 index{uint32_t(i), uint32_t(i) * 2654435761u};
    out.varyings[v_index] = glm::vec4(glsl::uintBitsToFloat(index), 0.0f, 0.0f);
}

}  // namespace st
