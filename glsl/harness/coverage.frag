#version 450 core
// coverage.frag: constant white, for the coverage pass that `compare` draws
// with each scene's own vertex stage. Twin: kernels/harness/coverage_frag.cpp.
layout(location = 0) out vec4 frag_colour;

void main() {
    frag_colour = vec4(1.0);
}
