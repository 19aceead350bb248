// builtins_matrix_frag.cpp: twin of glsl/conformance/builtins_matrix.frag,
// line for line, but for the chain A * B * C * v, which the twin writes as
// GLSL IR runs it: A * (B * (C * v)).
#include "kernels/conformance/conformance.h"

#include "kernels/conformance/builtin_inputs.h"
#include "simd/lane_mat.h"

namespace st {

namespace {
// value() of the GLSL (builtin_inputs.h).
Float value(Int index, int k) { return builtin_inputs::finite_value(index, k); }
// column() of the GLSL (builtin_inputs.h).
Vec4 column(Int index, int k) { return builtin_inputs::finite_column(index, k); }
}  // namespace

Vec4 BuiltinsMatrixFragment::main(const Fragment& frag) const {
    using namespace glsl;
    const Int index = builtin_inputs::pixel_index(frag);
    Mat4 A(column(index, 0), column(index, 1), column(index, 2), column(index, 3));
    const Mat4 B(column(index, 4), column(index, 5), column(index, 6), column(index, 7));
    const Mat4 C(column(index, 8), column(index, 9), column(index, 10), column(index, 11));
    const Vec4 v = column(index, 12);
    A[3] = select((index & 3) == Int(0), A[0] + A[1] * 0.001f, A[3]);
    if (group_ == 0) {
        const Mat2 m(A);
        return Vec4(m * v.xy(), v.zw() * m);
    } else if (group_ == 1) {
        return Vec4(Mat3(A) * v.xyz(), determinant(Mat2(B)));
    } else if (group_ == 2) {
        return Vec4(v.xyz() * Mat3(A), determinant(Mat3(A)));
    } else if (group_ == 3) {
        return A * v;
    } else if (group_ == 4) {
        return v * A;
    } else if (group_ == 5) {
        return (A * B)[1];
    } else if (group_ == 6) {
        const Mat2 i = inverse(Mat2(A));
        return Vec4(determinant(A), i[0], i[1].x);
    } else if (group_ == 7) {
        const Mat3 i = inverse(Mat3(A));
        return Vec4(i[0], i[2].z);
    } else if (group_ == 8) {
        return inverse(A)[0];
    } else if (group_ == 9) {
        return inverse(A)[3];
    } else if (group_ == 10) {
        return A * (B * (C * v));
    } else if (group_ == 11) {
        const Mat2x3 m(Vec3(A[0].xyz()), Vec3(B[1].yzw()));
        return Vec4(m * v.xy(), (v.yzw() * m).y);
    }
    const Mat3x4 m(matrixCompMult(A, B));
    const Mat4 back{Mat3(C)};
    return Vec4(transpose(m)[2], outerProduct(v.xyz(), v.zw())[1].x + back[3].w);
}

}  // namespace st
