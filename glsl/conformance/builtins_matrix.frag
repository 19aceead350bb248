#version 450 core
// builtins_matrix.frag: the matrix products and built-ins of matrices
// enumerated by pixel, written to RGBA32F, in thirteen groups chosen by a
// uniform (one scene each):
//   0: mat2 * vec2, vec2 * mat2
//   1: mat3 * vec3, determinant(mat2)
//   2: vec3 * mat3, determinant(mat3)
//   3: mat4 * vec4
//   4: vec4 * mat4
//   5: (mat4 * mat4)[1]
//   6: determinant(mat4), inverse(mat2)[0], inverse(mat2)[1].x
//   7: inverse(mat3)[0], inverse(mat3)[2].z
//   8: inverse(mat4)[0]
//   9: inverse(mat4)[3]
//  10: A * B * C * v, which GLSL IR runs as A * (B * (C * v))
//  11: mat2x3 * vec2, (vec3 * mat2x3).y
//  12: transpose(mat3x4)[2], outerProduct(vec3, vec2)[1].x, with
//      matrixCompMult and mat3(mat4) / mat4(mat3) constructors around them
// Elements are finite values of many magnitudes from the pixel's index
// (value() below); in every fourth pixel A's last column is nearly A's
// first, so determinants are small and inverses large. Nothing is a
// constant, so nothing is folded. Non-finite inputs are left out: there
// the sums of NaNs meet, and which NaN comes out is the compilers' operand
// order (docs/llvmpipe/glsl-builtins.md section 2).
// Twin: kernels/conformance/builtins_matrix_frag.cpp.
layout(location = 0) out vec4 frag_colour;
uniform int group;

float value(int index, int k) {
    int h = (index * (2 * k + 37) + k * 101) & 1023;
    int e = ((index >> (k & 7)) + k) & 15;
    return float(h - 512) * 0.0137 * intBitsToFloat((e + 121) << 23);
}

vec4 column(int index, int k) {
    return vec4(value(index, 4 * k), value(index, 4 * k + 1), value(index, 4 * k + 2), value(index, 4 * k + 3));
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    int index = p.y * 64 + p.x;
    mat4 A = mat4(column(index, 0), column(index, 1), column(index, 2), column(index, 3));
    mat4 B = mat4(column(index, 4), column(index, 5), column(index, 6), column(index, 7));
    mat4 C = mat4(column(index, 8), column(index, 9), column(index, 10), column(index, 11));
    vec4 v = column(index, 12);
    if ((index & 3) == 0)
        A[3] = A[0] + A[1] * 0.001;
    if (group == 0) {
        mat2 m = mat2(A);
        frag_colour = vec4(m * v.xy, v.zw * m);
    } else if (group == 1) {
        frag_colour = vec4(mat3(A) * v.xyz, determinant(mat2(B)));
    } else if (group == 2) {
        frag_colour = vec4(v.xyz * mat3(A), determinant(mat3(A)));
    } else if (group == 3) {
        frag_colour = A * v;
    } else if (group == 4) {
        frag_colour = v * A;
    } else if (group == 5) {
        frag_colour = (A * B)[1];
    } else if (group == 6) {
        mat2 i = inverse(mat2(A));
        frag_colour = vec4(determinant(A), i[0], i[1].x);
    } else if (group == 7) {
        mat3 i = inverse(mat3(A));
        frag_colour = vec4(i[0], i[2].z);
    } else if (group == 8) {
        frag_colour = inverse(A)[0];
    } else if (group == 9) {
        frag_colour = inverse(A)[3];
    } else if (group == 10) {
        frag_colour = A * B * C * v;
    } else if (group == 11) {
        mat2x3 m = mat2x3(A[0].xyz, B[1].yzw);
        frag_colour = vec4(m * v.xy, (v.yzw * m).y);
    } else {
        mat3x4 m = mat3x4(matrixCompMult(A, B));
        mat4 back = mat4(mat3(C));
        frag_colour = vec4(transpose(m)[2], outerProduct(v.xyz, v.zw)[1].x + back[3].w);
    }
}
