#version 450 core
// wrap.vert: a unit sphere's vertex to clip space; the object-space normal
// goes on to the fragment stage. Twin: kernels/wrap_vert.cpp.
layout(location = 0) in vec4 position;
layout(location = 1) in vec4 normal;
layout(location = 0) out vec4 v_normal;
uniform mat4 mvp;

void main() {
    gl_Position = mvp * position;
    v_normal = normal;
}
