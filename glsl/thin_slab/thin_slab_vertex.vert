#version 450 core
// thin_slab_vertex.vert: the `vertex` variant, Eq. 4-8 per vertex (front- or
// back-lit decided per vertex). The radiance leaves without the flag's
// texel, which thin_slab_lit.frag applies per fragment (the model is linear
// in the albedo). Twin: kernels/thin_slab/thin_slab_vertex_vert.cpp.
#include "thin_slab_model.glsl"
layout(location = 0) in vec4 position;
layout(location = 1) in vec4 normal;
layout(location = 2) in vec4 uv;
layout(location = 0) out vec4 v_radiance;  // rgb = L_source / texel, a = alpha
layout(location = 1) out vec4 v_uv;
uniform mat4 view_proj;
uniform vec3 eye;
uniform vec3 light;
uniform float power;
uniform float tau1;
uniform vec3 albedo;

void main() {
    gl_Position = view_proj * position;
    v_radiance = thin_slab(position.xyz, normalize(normal.xyz), eye, light, power, tau1, albedo);
    v_uv = uv;
}
