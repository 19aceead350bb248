// probe_demo_frag.cpp: twin of glsl/conformance/probe_demo.frag, with the
// same probes. twin_breaks_ 1, 2 or 3 writes the factored sum, the matrix
// chain or the mix as the GLSL reads, which `shadertwin probe` must find.
#include "kernels/conformance/conformance.h"

#include "kernels/conformance/builtin_inputs.h"
#include "shading/probe.h"
#include "simd/lane_mat.h"

namespace st {

namespace {
// value() of the GLSL (builtin_inputs.h).
Float value(Int index, int k) { return builtin_inputs::finite_value(index, k); }
Vec4 column(Int index, int k) { return builtin_inputs::finite_column(index, k); }
}  // namespace

Vec4 ProbeDemoFragment::main(const Fragment& frag) const {
    using namespace glsl;
    const Int index = builtin_inputs::pixel_index(frag);
    const Vec3 colour(column(index, 0));
    const Vec3 diff(column(index, 1));
    const Float t = float_of(index & 1023) / 1023.0f;
    probe(frag, "t", t);
    // 0.1 * colour + diff * colour runs as colour * (0.1 + diff).
    const Vec3 lit = twin_breaks_ == 1 ? 0.1f * colour + diff * colour : colour * (0.1f + diff);
    probe(frag, "lit", lit);
    const Mat4 A(column(index, 2), column(index, 3), column(index, 4), column(index, 5));
    const Mat4 B(column(index, 6), column(index, 7), column(index, 8), column(index, 9));
    const Mat4 C(column(index, 10), column(index, 11), column(index, 12), column(index, 13));
    // A * B * C * v runs as A * (B * (C * v)).
    const Vec4 v(lit, Float(1.0f));
    const Vec4 projected = twin_breaks_ == 2 ? ((A * B) * C) * v : A * (B * (C * v));
    probe(frag, "projected", projected);
    // mix with constant ends takes the fast form.
    const Float layers = twin_breaks_ == 3 ? mix_strict(Float(32.0f), Float(8.0f), t) : mix(Float(32.0f), Float(8.0f), t);
    probe(frag, "layers", layers);
    return Vec4(projected.xyz() * layers, projected.w);
}

}  // namespace st
