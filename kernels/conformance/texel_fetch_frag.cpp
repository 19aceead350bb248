// texel_fetch_frag.cpp: twin of glsl/conformance/texel_fetch.frag, line for
// line. GLSL's int() truncates and integer / rounds toward zero.
#include "kernels/conformance/conformance.h"

#include "texture/sampler2d.h"

namespace st {

namespace {
constexpr int v_colour = 0;  // input

// ivec2 / 2 for possibly negative values: C++'s / also truncates.
Int div2(Int x) { return (x + ((x >> 31) & Int(1))) >> 1; }
}  // namespace

uint32_t TexelFetchFragment::inputs_read() const { return reads(v_colour, "x"); }

Vec4 TexelFetchFragment::main(const Fragment& frag) const {
    const Int level = simd::itrunc(frag.varying(v_colour).x * 7.0f) - Int(1);
    const Int px = div2(simd::itrunc(frag.frag_coord().x)) - Int(3);
    const Int py = div2(simd::itrunc(frag.frag_coord().y)) - Int(2);
    const Vec4 t = tex_->fetch(px, py, level);
    const Int size_x = tex_->size_x(level), size_y = tex_->size_y(level);
    return Vec4(t.x, t.y, t.z + t.w, simd::to_float(size_x) + simd::to_float(size_y) * 0.001f);
}

}  // namespace st
