#version 450 core
// interp.vert: the plain interpolating program of the triangles-* scenes.
// Positions arrive in clip space; the colour is interpolated perspective-correct.
// Twin: kernels/triangles/interp_vert.cpp.
layout(location = 0) in vec4 position;
layout(location = 1) in vec4 colour;
layout(location = 0) out vec4 v_colour;

void main() {
    gl_Position = position;
    v_colour = colour;
}
