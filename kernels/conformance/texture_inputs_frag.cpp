// texture_inputs_frag.cpp: twin of glsl/conformance/texture_inputs.frag,
// line for line.
#include "kernels/conformance/conformance.h"

#include "texture/sampler2d.h"

namespace st {

Vec4 TextureInputsFragment::main(const Fragment& frag) const {
    const Float v = inputs_->fetch(simd::itrunc(frag.frag_coord().x), simd::itrunc(frag.frag_coord().y), Int(0)).x;
    return Vec4(glsl::atan(v), v, Float(0.0f), Float(1.0f));
}

}  // namespace st
