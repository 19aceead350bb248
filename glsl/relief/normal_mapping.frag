#version 450 core
// normal_mapping.frag: Table 1's first row, "normal and color mapping": the
// colour and normal maps read at the surface's own coordinates (no search),
// lit by a point light. Twin: kernels/relief/normal_mapping_frag.cpp.
#include "relief_shading.glsl"
layout(location = 0) in vec4 v_position;
layout(location = 1) in vec4 v_uv;
layout(location = 0) out vec4 frag_colour;
uniform sampler2D relief_map;  // rgb: normal, a: height
uniform sampler2D colour_map;
uniform vec3 eye;
uniform vec3 light;
uniform float ambient;
uniform float specular;

void main() {
    vec2 uv = v_uv.xy;
    vec3 p = v_position.xyz;
    vec3 n = decode_normal(texture(relief_map, uv));
    vec3 albedo = texture(colour_map, uv).rgb;
    vec3 l = normalize(light - p);
    vec3 v = normalize(eye - p);
    frag_colour = vec4(blinn_phong(albedo, n, l, v, ambient, specular), 1.0);
}
