#version 450 core
// profile.vert: the camera's view of a diffusion-profile mesh, for the
// gather pass; world position, normal and texture coordinates go on to it.
// Twin: kernels/profile/profile_vert.cpp.
layout(location = 0) in vec4 position;  // world, mm, w = 1
layout(location = 1) in vec4 normal;    // unit, w = 0
layout(location = 2) in vec4 uv;
layout(location = 0) out vec4 v_position;
layout(location = 1) out vec4 v_normal;
layout(location = 2) out vec4 v_uv;
uniform mat4 view_proj;

void main() {
    gl_Position = view_proj * position;
    v_position = position;
    v_normal = normal;
    v_uv = uv;
}
