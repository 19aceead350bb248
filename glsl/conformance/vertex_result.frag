#version 450 core
// vertex_result.frag: the vertex stage's result put back together from its
// two 16-bit halves (builtins_vertex.vert), bit for bit, as RGBA32F.
// Twin: kernels/conformance/vertex_result_frag.cpp.
layout(location = 0) in vec4 v_colour;
layout(location = 1) in vec4 v_uv;
layout(location = 0) out vec4 frag_colour;

void main() {
    frag_colour = uintBitsToFloat((uvec4(v_colour) << 16u) | uvec4(v_uv));
}
