// textured_frag.cpp: twin of glsl/textured.frag, line for line.
#include "kernels/triangles/textured.h"

#include "texture/sampler2d.h"

namespace st {

namespace {
constexpr int v_colour = 0, v_uv = 1;  // inputs
}  // namespace

uint32_t TexturedFragment::inputs_read() const { return reads(v_colour, "xyzw") | reads(v_uv, "xy"); }

Vec4 TexturedFragment::main(const Fragment& frag) const {
    return frag.varying(v_colour) * tex_->sample(frag.varying(v_uv).xy());
}

}  // namespace st
