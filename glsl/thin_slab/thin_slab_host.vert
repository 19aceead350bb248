#version 450 core
// thin_slab_host.vert: the `host` variant's vertex stage. Eq. 4-8 were
// evaluated per vertex on the CPU (the same model functions, in C++), so this
// only transforms and passes them on. Twin: kernels/thin_slab/thin_slab_host_vert.cpp.
layout(location = 0) in vec4 position;
layout(location = 1) in vec4 radiance;  // host-computed: rgb = L_source / texel, a = alpha
layout(location = 2) in vec4 uv;
layout(location = 0) out vec4 v_radiance;
layout(location = 1) out vec4 v_uv;
uniform mat4 view_proj;

void main() {
    gl_Position = view_proj * position;
    v_radiance = radiance;
    v_uv = uv;
}
