#version 450 core
// textured.vert: the triangles-* program with a texture coordinate.
// Twin: kernels/triangles/textured_vert.cpp.
layout(location = 0) in vec4 position;
layout(location = 1) in vec4 colour;
layout(location = 2) in vec4 uv;
layout(location = 0) out vec4 v_colour;
layout(location = 1) out vec4 v_uv;

void main() {
    gl_Position = position;
    v_colour = colour;
    v_uv = uv;
}
