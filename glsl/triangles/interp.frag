#version 450 core
// interp.frag: writes the interpolated vertex colour.
// Twin: kernels/triangles/interp_frag.cpp.
layout(location = 0) in vec4 v_colour;
layout(location = 0) out vec4 frag_colour;

void main() {
    frag_colour = v_colour;
}
