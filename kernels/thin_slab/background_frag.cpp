// background_frag.cpp: twin of glsl/background.frag, line for line.
#include "kernels/thin_slab/background.h"
#include "texture/sampler2d.h"

namespace st {

namespace {
constexpr int v_uv = 0;  // inputs
}  // namespace

uint32_t BackgroundFragment::inputs_read() const { return reads(v_uv, "xy"); }

Vec4 BackgroundFragment::main(const Fragment& frag) const {
    return painting_->sample(frag.varying(v_uv).xy());
}

}  // namespace st
