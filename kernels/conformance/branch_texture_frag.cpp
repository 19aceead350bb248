// branch_texture_frag.cpp: twin of glsl/conformance/branch_texture.frag, line
// for line.
#include "kernels/conformance/conformance.h"

#include "texture/sampler2d.h"

namespace st {

namespace {
constexpr int v_colour = 0, v_uv = 1;  // inputs
}  // namespace

void BranchTextureFragment::bind(const Bindings& b) {
    tex_a_ = &b.sampler("tex_a");
    tex_b_ = &b.sampler("tex_b");
    split_ = b.get_float("split");
}

uint32_t BranchTextureFragment::inputs_read() const { return reads(v_colour, "xyzw") | reads(v_uv, "xy"); }

Vec4 BranchTextureFragment::main(const Fragment& frag) const {
    Exec& exec = frag.exec();
    const Vec2 uv = frag.varying(v_uv).xy();
    Vec4 c(0.0f);
    exec.if_else(
        uv.x * uv.x + uv.y > Float(split_), [&] { exec.assign(c, tex_a_->sample(uv * 3.0f)); },
        [&] { exec.assign(c, tex_b_->sample(Vec2(uv.y, uv.x) + 0.25f) * frag.varying(v_colour)); });
    return c;
}

}  // namespace st
