#version 450 core
// thin_slab.vert: vertex stage of the `fragment` and `baseline` variants:
// world position, normal and flag coordinates to the fragment stage.
// Twin: kernels/thin_slab/thin_slab_vert.cpp.
layout(location = 0) in vec4 position;  // world space, w = 1 (displaced on the host)
layout(location = 1) in vec4 normal;    // world space, unit length
layout(location = 2) in vec4 uv;        // flag texture coordinates
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
