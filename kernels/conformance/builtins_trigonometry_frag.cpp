// builtins_trigonometry_frag.cpp: twin of
// glsl/conformance/builtins_trigonometry.frag, line for line.
#include "kernels/conformance/conformance.h"

#include "kernels/conformance/builtin_inputs.h"

namespace st {


Vec4 BuiltinsTrigonometryFragment::main(const Fragment& frag) const {
    using namespace glsl;
    using namespace builtin_inputs;
    const Int index = pixel_index(frag);
    const Float x = select(index < Int(4096), from_bits_of(index), float_of(index - Int(6144)) * 0.0123f);
    const Float y = edge_of(index);
    if (group_ == 0) return Vec4(sin(x), cos(x), tan(x), radians(x));
    if (group_ == 1) return Vec4(asin(x), acos(x), atan(x), degrees(x));
    if (group_ == 2) return Vec4(atan(x, y), atan(y, x), sinh(x), cosh(x));
    return Vec4(tanh(x), asinh(x), acosh(x), atanh(x));
}

}  // namespace st
