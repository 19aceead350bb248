// discard_frag.cpp: twin of glsl/conformance/discard.frag, line for line.
#include "kernels/conformance/conformance.h"

namespace st {

namespace {
constexpr int v_colour = 0, v_uv = 1;  // inputs
}  // namespace

uint32_t DiscardFragment::inputs_read() const { return reads(v_colour, "xyz") | reads(v_uv, "xy"); }

Vec4 DiscardFragment::main(const Fragment& frag) const {
    Exec& exec = frag.exec();
    const Vec2 uv = frag.varying(v_uv).xy();
    exec.discard_if(uv.x > uv.y * 1.5f);
    Float s = 0.0f;
    Int i = 0;
    exec.loop([&](Loop& loop) {
        loop.break_if(!(i < Int(steps_)));
        exec.assign(s, s + uv.x);
        exec.discard_if(s > 2.0f + uv.y);
        exec.assign(i, i + 1);
    });
    return Vec4(frag.varying(v_colour).xyz() * s, 1.0f);
}

}  // namespace st
