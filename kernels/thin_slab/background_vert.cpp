// background_vert.cpp: twin of glsl/background.vert, line for line.
#include "kernels/thin_slab/background.h"

namespace st {

namespace {
constexpr int position = 0, uv = 1;  // inputs
constexpr int v_uv = 0;              // outputs
}  // namespace

void BackgroundVertex::run(const glm::vec4* attributes, VertexOut& out) const {
    out.position = attributes[position];
    out.varyings[v_uv] = attributes[uv];
}

}  // namespace st
