#version 450 core
// relief.vert: vertex stage of every relief-mapping row (Timonen, Table 1).
// The surface is the plane z = 0 with tangent +x and bitangent +y, so world
// space is tangent space and positions pass through unchanged.
// Twin: kernels/relief/relief_vert.cpp.
layout(location = 0) in vec4 position;  // on the plane, w = 1
layout(location = 1) in vec4 uv;        // texture coordinates of the maps
layout(location = 0) out vec4 v_position;
layout(location = 1) out vec4 v_uv;
uniform mat4 view_proj;

void main() {
    gl_Position = view_proj * position;
    v_position = position;
    v_uv = uv;
}
