#version 450 core
// background.vert: a screen-filling quad in clip space for the painting.
// Twin: kernels/thin_slab/background_vert.cpp.
layout(location = 0) in vec4 position;
layout(location = 1) in vec4 uv;
layout(location = 0) out vec4 v_uv;

void main() {
    gl_Position = position;
    v_uv = uv;
}
