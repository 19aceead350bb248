#version 450 core
// thin_slab_baseline.frag: the paper's Figure 2 top row: Lambert-shaded flag
// when lit from the viewer's side, black when back-lit, source colour scaled
// by 0.8 and a constant alpha of 0.2 for the same blend (Eq. 9).
// Twin: kernels/thin_slab/thin_slab_baseline_frag.cpp.
#include "thin_slab_model.glsl"
layout(location = 0) in vec4 v_position;
layout(location = 1) in vec4 v_normal;
layout(location = 2) in vec4 v_uv;
layout(location = 0) out vec4 frag_colour;
uniform vec3 eye;
uniform vec3 light;
uniform float power;
uniform vec3 albedo;
uniform sampler2D flag;

void main() {
    vec3 texel = texture(flag, v_uv.xy).rgb;
    // The 0.8 scales the albedo: the compiler moves it there anyway (measured),
    // so the source says what is computed.
    vec3 lit = lambert_baseline(v_position.xyz, normalize(v_normal.xyz), eye, light, power, albedo * texel * 0.8);
    frag_colour = vec4(lit, 0.2);
}
