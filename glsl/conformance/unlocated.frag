#version 330 core
// unlocated.frag: a GLSL 3.30 fragment shader without locations (issue 29):
// its inputs in another order than unlocated.vert writes them (GL links
// them by name; the twins name their slots), its one output at the location
// GL gives a lone output, 0.
// Twin: kernels/conformance/unlocated_frag.cpp.
in vec2 vUV;
in vec4 vColour;
out vec4 fragColour;

uniform vec3 tint;

void main() {
    vec3 c = vColour.rgb * tint;
    fragColour = vec4(c.r * vUV.x, c.g * vUV.y, c.b, vColour.a);
}
