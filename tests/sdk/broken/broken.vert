#version 450 core
// broken.vert: passes positions through. Twin: tests/sdk/broken/broken.cpp.
layout(location = 0) in vec4 position;

void main() {
    gl_Position = position;
}
