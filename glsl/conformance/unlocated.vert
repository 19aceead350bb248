#version 330 core
// unlocated.vert: the conformance vertex program as GLSL 3.30 shaders ship,
// without a layout(location) anywhere (issue 29): GL gives the inputs
// locations of its own, and the scene's attribute columns reach them by
// name (VertexArray::names); the outputs reach unlocated.frag by name,
// which declares them in another order.
// Twin: kernels/conformance/unlocated_vert.cpp.
in vec4 position;
in vec4 colour;
in vec4 uv;
out vec4 vColour;
out vec2 vUV;

void main() {
    gl_Position = position;
    vColour = colour;
    vUV = uv.xy;
}
