// interp.cpp: twin of glsl/interp.vert and glsl/interp.frag, line for line.
#include "kernels/interp.h"

namespace st {

namespace {
// layout(location = ...) of glsl/interp.vert and interp.frag
constexpr int position = 0, colour = 1;
constexpr int v_colour = 0;
}  // namespace

void InterpVertex::run(const glm::vec4* attributes, VertexOut& out) const {
    out.position = attributes[position];
    out.varyings[v_colour] = attributes[colour];
}

glm::vec4 InterpFragment::main(const Fragment& frag) const {
    return frag.varying(v_colour);
}

}  // namespace st
