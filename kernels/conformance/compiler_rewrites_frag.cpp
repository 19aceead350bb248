// compiler_rewrites_frag.cpp: twin of glsl/conformance/compiler_rewrites.frag.
// Each group writes what llvmpipe runs, with the GLSL as written beside it
// (the `naive_` branch, for cli.compiler_rewrites: the scene must fail with
// it). docs/llvmpipe/compiler-rewrites.md names the pass behind each.
#include "kernels/conformance/conformance.h"

#include "kernels/conformance/builtin_inputs.h"
#include "simd/lane_mat.h"

namespace st {

namespace {
// value() of the GLSL (builtin_inputs.h).
Float value(Int index, int k) { return builtin_inputs::finite_value(index, k); }
}  // namespace

void CompilerRewritesFragment::bind(const Bindings& b) {
    group_ = b.get_int("group");
    naive_ = b.get_int("twin_naive") != 0;
}

Vec4 CompilerRewritesFragment::main(const Fragment& frag) const {
    using namespace glsl;
    const Int index = builtin_inputs::pixel_index(frag);
    const Float a = value(index, 0), b = value(index, 1), c = value(index, 2), d = value(index, 3);
    const Vec3 colour(value(index, 4), value(index, 5), value(index, 6));
    const Vec3 diff(value(index, 7), value(index, 8), value(index, 9));
    const Float t = float_of(index & 1023) / 1023.0f;
    const Float x = float_of((index & 2047) - Int(1024)) / 100.0f;
    const Float y = float_of(((index >> 3) & 1023) - Int(512)) / 50.0f;
    const Float zero(0.0f);
    switch (group_) {
    case 0:  // nir_opt_algebraic: a*b + a*c -> a*(b + c)
        return Vec4(naive_ ? 0.1f * colour + diff * colour : colour * (0.1f + diff), zero);
    case 1:  // nir_lower_flrp: constant x and y -> the fast form
        return Vec4(naive_ ? mix_strict(Float(32.0f), Float(8.0f), t) : mix(Float(32.0f), Float(8.0f), t), zero, zero,
                    zero);
    case 2:  // nir_lower_flrp: three flrps share (x, t) -> the strict form
        return Vec4(naive_ ? mix(Vec3(a), colour, t) : mix_strict(Vec3(a), colour, t), zero);
    case 3:  // nir_opt_algebraic: (a*b)*#c -> (a*#c)*b
        return Vec4(naive_ ? (a * b) * 3.0f : (a * 3.0f) * b, zero, zero, zero);
    case 4:  // nir_opt_algebraic: (a + b) + #c -> (a + #c) + b
        return Vec4(naive_ ? (a + b) + 1.0f : (a + 1.0f) + b, zero, zero, zero);
    case 5:  // GLSL IR do_rebalance_tree: (a + b) + (c + d); then, a and b being
             // products, nir_opt_algebraic's (fmul + fmul) + c -> (fmul + c) + fmul
        return Vec4(naive_ ? ((a + b) + c) + d : (a + (c + d)) + b, zero, zero, zero);
    case 6:  // nir_opt_algebraic: -a + (a + b) -> b
        return Vec4(naive_ ? (a + b) - a : b, zero, zero, zero);
    case 7:  // GLSL IR do_algebraic: rcp(exp2(x)) -> exp2(-x)
        return Vec4(naive_ ? 1.0f / exp2(x) : exp2(-x), zero, zero, zero);
    case 8:  // GLSL IR do_algebraic: pow(x, 2), pow(x, 4), pow(2, x)
        if (naive_) return Vec4(pow(a, Float(2.0f)), pow(b, Float(4.0f)), pow(Float(2.0f), x), zero);
        return Vec4(a * a, (b * b) * (b * b), exp2(x), zero);
    case 9:  // lower_fdot, then nir_opt_algebraic: (fmul + fmul) + c -> (fmul + c) + fmul
        if (naive_) return Vec4(dot(colour.xy(), diff.xy()) - 0.75f, zero, zero, zero);
        return Vec4(colour.x * diff.x + (colour.y * diff.y - 0.75f), zero, zero, zero);
    case 10:  // no rewrite: a division by a constant stays a division
        return Vec4(naive_ ? x * (1.0f / 3.0f) : x / 3.0f, zero, zero, zero);
    case 11:  // exp(x) * exp(y): fexp2(x L) * fexp2(y L) -> fexp2(x L + y L) -> fexp2(L (x + y))
        if (naive_) return Vec4(exp(x) * exp(y), zero, zero, zero);
        return Vec4(exp2(kLog2e * (x + y)), zero, zero, zero);
    case 12: {  // GLSL IR do_algebraic: (A * B) * v -> A * (B * v), twice
        const Mat4 A(Vec4(a, b, c, d), Vec4(colour, t), Vec4(diff, x), Vec4(y, a, c, b));
        const Mat4 B(Vec4(diff, a), Vec4(b, colour), Vec4(t, c, x, d), Vec4(colour.zyx(), y));
        const Mat4 C(Vec4(x, y, t, a), Vec4(diff.zxy(), b), Vec4(c, d, colour.xy()), Vec4(colour.yz(), diff.yz()));
        const Vec4 v(colour, d);
        return naive_ ? ((A * B) * C) * v : A * (B * (C * v));
    }
    case 13: {  // nir_opt_algebraic: 2 * (d * n) -> (d * 2) * n (glsl::reflect does so)
        const Vec3 i = colour * 8e34f, n = normalize(diff);
        return Vec4(naive_ ? i - 2.0f * (dot(n, i) * n) : reflect(i, n), zero);
    }
    case 14:  // lower_ffma32: GLSL's fma is a * b + c, two roundings (glsl::fma)
        if (naive_)
            return Vec4(simd::fmuladd(a, b, c), simd::fmuladd(colour.x, diff.x, d), simd::fmuladd(colour.y, diff.y, d),
                        simd::fmuladd(colour.z, diff.z, d));
        return Vec4(fma(a, b, c), fma(colour, diff, Vec3(d)));
    case 15:  // constant folding with the host C library (glsl::folded)
        if (naive_) return Vec4(sin(Float(1.0f)), cos(Float(2.0f)), exp(Float(1.7f)), pow(Float(3.0f), Float(0.7f)));
        return Vec4(Float(folded::sin(1.0f)), Float(folded::cos(2.0f)), Float(folded::exp(1.7f)),
                    Float(folded::pow(3.0f, 0.7f)));
    case 17:  // GLSL IR do_algebraic: rcp(rsq(q)) -> sqrt(q)
        return Vec4(naive_ ? 1.0f / inversesqrt(abs(a)) : sqrt(abs(a)), zero, zero, zero);
    case 18:  // GLSL IR do_algebraic: exp(log(q)) -> q, exp2(log2(q)) -> q
        if (naive_) return Vec4(exp(log(abs(a))), exp2(log2(abs(b))), zero, zero);
        return Vec4(abs(a), abs(b), zero, zero);
    case 19:  // GLSL IR do_algebraic: rcp(rcp(q)) -> q
        return Vec4(naive_ ? 1.0f / (1.0f / a) : a, zero, zero, zero);
    case 20: {  // nir_opt_algebraic: #a * (b * #c) -> (#a * #c) * b, the constants folded
        const Vec3 i = normalize(colour), n = normalize(diff);
        return Vec4(naive_ ? refract(i, n, Float(0.66f)) : refract_constant_eta(i, n, Float(0.66f)), zero);
    }
    case 21:  // nir_opt_algebraic: ~i2f(f2i(a)) -> ftrunc(a), so -0.0 in (-1, 0) and no int range
        if (naive_) return Vec4(float_of(int_of(x)), float_of(int_of(a * 1e7f)), float_of(int_of(t - 0.5f)), zero);
        return Vec4(trunc(x), trunc(a * 1e7f), trunc(t - 0.5f), zero);
    case 22:  // GLSL IR opt_algebraic: (-x + y) * t + x -> lrp(x, y, t); nir_lower_flrp: x = 1 ->
              // (1 - t) + y t (the values of mix_strict(1, y, t)); other x, nothing shared -> the
              // fast form x + t (y - x), the expression as written
        if (naive_) return Vec4(t * (a - 1.0f) + 1.0f, c + (b - c) * t, zero, zero);
        return Vec4(mix_strict(Float(1.0f), a, t), c + (b - c) * t, zero, zero);
    case 23:  // nir_opt_algebraic: sqrt(a) * sqrt(a) -> abs(a); length(v) is sqrt(dot(v, v))
        if (naive_) return Vec4(length(colour) * length(colour), sqrt(abs(a)) * sqrt(abs(a)), zero, zero);
        return Vec4(abs(dot(colour, colour)), abs(a), zero, zero);
    default: {  // 16 and any other group, as the GLSL's last else: the loop unrolled (NIR), then
                //  each sin and the sums folded
        float s = 0.0f;
        for (int i = 0; i < 8; ++i) s += folded::sin(float(i) * 0.7f + 1.1f);
        if (naive_) {
            Float n(0.0f);
            for (int i = 0; i < 8; ++i) n = n + sin(Float(float(i) * 0.7f + 1.1f));
            return Vec4(n, zero, zero, zero);
        }
        return Vec4(Float(s), zero, zero, zero);
    }
    }
}

}  // namespace st
