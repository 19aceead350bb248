// unlocated_vert.cpp: twin of glsl/conformance/unlocated.vert, line for line.
#include "kernels/conformance/conformance.h"

namespace st {

namespace {
constexpr int position = 0, colour = 1, uv = 2;  // attribute columns, bound by name on the GL side
constexpr int vColour = 0, vUV = 1;               // output slots (output_names())
}  // namespace

void UnlocatedVertex::run(const glm::vec4* attributes, VertexOut& out) const {
    out.position = attributes[position];
    out.varyings[vColour] = attributes[colour];
    out.varyings[vUV] = glm::vec4(glm::vec2(attributes[uv]), 0.0f, 0.0f);
}

}  // namespace st
