#version 450 core
// relief_mapping.frag: Table 1's second row, "relief mapping": the view
// ray traced into the stones' height field (relief_search.glsl), and the
// colour and normal maps read where it hits, lit at the hit point.
// Twin: kernels/relief/relief_mapping_frag.cpp.
#include "relief_shading.glsl"
#include "relief_search.glsl"
layout(location = 0) in vec4 v_position;
layout(location = 1) in vec4 v_uv;
layout(location = 0) out vec4 frag_colour;
uniform sampler2D relief_map;  // rgb: normal, a: height
uniform sampler2D colour_map;
uniform vec3 eye;
uniform vec3 light;
uniform float ambient;
uniform float specular;
uniform float depth;        // the layer's thickness, texture units
uniform float world_depth;  // the same in world units
uniform int linear_steps;
// > 0: the linear steps scaled by the view angle, common practice (the
// offset is short where the view is steep): mix(linear_steps,
// min_linear_steps, dot(N, V)), N = (0, 0, 1), truncated; 0: always
// linear_steps.
uniform int min_linear_steps;
uniform int binary_steps;
uniform bool secant;

void main() {
    vec2 uv = v_uv.xy;
    vec3 p = v_position.xyz;
    vec3 v = normalize(eye - p);  // tangent space = world space; v.z > 0
    vec2 dx = dFdx(uv);
    vec2 dy = dFdy(uv);
    vec2 offset = -v.xy * (depth / v.z);
    // mix() written out: the same operations on both pipelines.
    int steps = min_linear_steps > 0
                    ? int(float(linear_steps) + (float(min_linear_steps) - float(linear_steps)) * v.z)
                    : linear_steps;
    float t = trace_height_field(relief_map, uv, offset, dx, dy, steps, binary_steps, secant);
    vec2 hit_uv = uv + offset * t;
    vec3 hit = p - v * (t * world_depth / v.z);
    vec3 n = decode_normal(textureGrad(relief_map, hit_uv, dx, dy));
    vec3 albedo = textureGrad(colour_map, hit_uv, dx, dy).rgb;
    vec3 l = normalize(light - hit);
    frag_colour = vec4(blinn_phong(albedo, n, l, v, ambient, specular), 1.0);
}
