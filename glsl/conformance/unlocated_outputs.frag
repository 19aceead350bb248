#version 330 core
// unlocated_outputs.frag: a GLSL 3.30 fragment shader with two outputs and
// no layout(location) (issue 29), as shaders written for
// glBindFragDataLocation ship: the scene binds `normal` to location 0 and
// `colour` to 1 by name (output_names), against their declaration order.
// Twin: kernels/conformance/unlocated_outputs_frag.cpp.
in vec2 vUV;
in vec4 vColour;
out vec4 colour;
out vec4 normal;

uniform vec3 tint;

void main() {
    colour = vec4(vColour.rgb * tint, vColour.a);
    normal = vec4(vUV * 2.0 - 1.0, vUV.x * vUV.y, 0.5);
}
