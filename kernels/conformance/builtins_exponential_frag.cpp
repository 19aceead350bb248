// builtins_exponential_frag.cpp: twin of
// glsl/conformance/builtins_exponential.frag, line for line.
#include "kernels/conformance/conformance.h"

#include "kernels/conformance/builtin_inputs.h"

namespace st {


Vec4 BuiltinsExponentialFragment::main(const Fragment& frag) const {
    const Int index = builtin_inputs::pixel_index(frag);
    const Float x = builtin_inputs::from_bits_of(index);
    const Float y = simd::to_float((index >> 3) & 15) * 0.5f - 3.0f;
    if (group_ == 0) return Vec4(glsl::log2(x), glsl::log(x), glsl::pow(x, y), glsl::pow(glsl::abs(x), y));
    return Vec4(glsl::exp2(x), glsl::exp(x), simd::sqrt(x), glsl::inversesqrt(x));
}

}  // namespace st
