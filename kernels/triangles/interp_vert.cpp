// interp_vert.cpp: twin of glsl/interp.vert, line for line.
#include "kernels/triangles/interp.h"

namespace st {

namespace {
constexpr int position = 0, colour = 1;  // inputs
constexpr int v_colour = 0;              // outputs
}  // namespace

void InterpVertex::run(const glm::vec4* attributes, VertexOut& out) const {
    out.position = attributes[position];
    out.varyings[v_colour] = attributes[colour];
}

}  // namespace st
