#version 450 core
// broken.frag: one colour. Twin: tests/sdk/broken/broken.cpp.
layout(location = 0) out vec4 frag_colour;

void main() {
    frag_colour = vec4(1.0, 0.5, 0.25, 1.0);
}
