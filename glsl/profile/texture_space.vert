#version 450 core
// texture_space.vert: the mesh drawn at its texture coordinates (Donner and
// Jensen Sec. 3, the irradiance that the gather pass later reads by surface
// position): uv in [0, 1]^2 covers the texture-space target, so each texel
// is one point of the surface. Its world position and normal go on to the
// fragment stage. Twin: kernels/profile/texture_space_vert.cpp.
layout(location = 0) in vec4 position;  // world, mm, w = 1
layout(location = 1) in vec4 normal;    // unit, w = 0
layout(location = 2) in vec4 uv;
layout(location = 0) out vec4 v_position;
layout(location = 1) out vec4 v_normal;

void main() {
    gl_Position = vec4(uv.xy * 2.0 - 1.0, 0.0, 1.0);
    v_position = position;
    v_normal = normal;
}
