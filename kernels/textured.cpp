// textured.cpp: twin of glsl/textured.vert and glsl/textured.frag, line for line.
#include "kernels/textured.h"

#include "raster/sampler2d.h"

namespace st {

namespace {
// layout(location = ...) of glsl/textured.vert and textured.frag
constexpr int position = 0, colour = 1, uv = 2;
constexpr int v_colour = 0, v_uv = 1;
}  // namespace

void TexturedVertex::run(const glm::vec4* attributes, VertexOut& out) const {
    out.position = attributes[position];
    out.varyings[v_colour] = attributes[colour];
    out.varyings[v_uv] = attributes[uv];
}

glm::vec4 TexturedFragment::main(const Fragment& frag) const {
    return frag.varying(v_colour) * tex_->sample(glm::vec2(frag.varying(v_uv)));
}

}  // namespace st
