// textured_vert.cpp: twin of glsl/textured.vert, line for line.
#include "kernels/triangles/textured.h"

namespace st {

namespace {
constexpr int position = 0, colour = 1, uv = 2;  // inputs
constexpr int v_colour = 0, v_uv = 1;            // outputs
}  // namespace

void TexturedVertex::run(const glm::vec4* attributes, VertexOut& out) const {
    out.position = attributes[position];
    out.varyings[v_colour] = attributes[colour];
    out.varyings[v_uv] = attributes[uv];
}

}  // namespace st
