// builtins_geometric_frag.cpp: twin of
// glsl/conformance/builtins_geometric.frag, line for line.
#include "kernels/conformance/conformance.h"

#include "kernels/conformance/builtin_inputs.h"

namespace st {

namespace {
// value() of the GLSL (builtin_inputs.h).
Float value(Int index, int k) { return builtin_inputs::finite_value(index, k); }
}  // namespace

Vec4 BuiltinsGeometricFragment::main(const Fragment& frag) const {
    using namespace glsl;
    using namespace builtin_inputs;
    const Int index = pixel_index(frag);
    Vec4 a(value(index, 0), value(index, 1), value(index, 2), value(index, 3));
    const Vec4 b(value(index, 4), value(index, 5), value(index, 6), value(index, 7));
    a.x = select(index < Int(4096), from_bits_of(index), a.x);
    if (group_ == 0) return Vec4(dot(a.xy(), b.xy()), dot(a.xyz(), b.xyz()), dot(a, b), length(a.x));
    if (group_ == 1) return Vec4(length(a.xy()), length(a.xyz()), length(a), distance(a.xyz(), b.xyz()));
    if (group_ == 2) return Vec4(normalize(a.xyz()), normalize(a.x));
    if (group_ == 3) return Vec4(cross(a.xyz(), b.xyz()), distance(a.x, b.x));
    if (group_ == 4) return Vec4(reflect(a.xyz(), normalize(b.xyz())), faceforward(a.w, b.w, a.z));
    const Float eta = 0.4f + float_of(index & 63) * 0.0333f;
    return Vec4(refract(a.xyz(), normalize(b.xyz()), eta), faceforward(a, b, a.yzwx()).x);
}

}  // namespace st
