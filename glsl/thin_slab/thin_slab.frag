#version 450 core
// thin_slab.frag: the `fragment` variant, Eq. 4-9 per fragment. The flag's
// texel multiplies the albedo per channel. Twin: kernels/thin_slab/thin_slab_frag.cpp.
#include "thin_slab_model.glsl"
layout(location = 0) in vec4 v_position;
layout(location = 1) in vec4 v_normal;
layout(location = 2) in vec4 v_uv;
layout(location = 0) out vec4 frag_colour;
uniform vec3 eye;
uniform vec3 light;
uniform float power;
uniform float tau1;
uniform vec3 albedo;
uniform sampler2D flag;

void main() {
    vec3 texel = texture(flag, v_uv.xy).rgb;
    frag_colour = thin_slab(v_position.xyz, normalize(v_normal.xyz), eye, light, power, tau1, albedo * texel);
}
