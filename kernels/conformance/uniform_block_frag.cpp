// uniform_block_frag.cpp: twin of glsl/conformance/uniform_block.frag, line
// for line; the blocks' members are uniforms by their GL names.
#include "kernels/conformance/conformance.h"

namespace st {

namespace {
constexpr int v_colour = 0, v_uv = 1;  // inputs
}  // namespace

void UniformBlockFragment::bind(const Bindings& b) {
    light_.colour = b.get_vec3("Light.colour");
    light_.power = b.get_float("Light.power");
    light_.offset = b.get_vec2("Light.offset");
    tint_ = b.get_vec4("tint");
    for (int i = 0; i < 3; ++i) gain_[size_t(i)] = b.get_float("gain[" + std::to_string(i) + "]");
    count_ = b.get_int("count");
}

uint32_t UniformBlockFragment::inputs_read() const { return reads(v_colour, "xyzw") | reads(v_uv, "xy"); }

Vec4 UniformBlockFragment::main(const Fragment& frag) const {
    const Vec2 p = frag.varying(v_uv).xy() + Vec2(light_.offset);
    // (a + b) + c of two products runs as (a + c) + b (compiler-rewrites.md, entry 5's second step).
    const Float g = (Float(gain_[0]) * p.x + Float(gain_[2])) + Float(gain_[1]) * p.y;
    const Vec3 c = Vec3(light_.colour) * Float(light_.power) * g;
    return Vec4(c, Float(float(count_))) * Vec4(tint_) * frag.varying(v_colour);
}

}  // namespace st
