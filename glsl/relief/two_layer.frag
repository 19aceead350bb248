#version 450 core
// two_layer.frag: Table 1's third row, two-layer translucency (Timonen
// Algorithm 1). Two relief layers with their own boxes below the polygon:
// the solid one (stones, relief_map) and the surface of the translucent
// medium (liquid_map). The view ray meets the nearer of the two; on the
// solid layer the fragment is shaded as in relief mapping; on the medium the
// unpolarised Fresnel terms split it: the refracted ray is traced to the
// solid layer, the reflected ray into the surface, taking the environment
// cube map where it leaves the box. Only the first encounter with the
// medium is followed, as the paper does.
// Twin: kernels/relief/two_layer_frag.cpp.
#include "relief_shading.glsl"
#include "relief_search.glsl"
layout(location = 0) in vec4 v_position;
layout(location = 1) in vec4 v_uv;
layout(location = 0) out vec4 frag_colour;
uniform sampler2D relief_map;  // the solid layer: rgb normal, a height
uniform sampler2D colour_map;
uniform sampler2D liquid_map;  // the medium's surface: rgb normal, a height
uniform samplerCube environment;
uniform vec3 eye;
uniform vec3 light;
uniform float ambient;
uniform float specular;
uniform float depth;         // the solid layer's box, texture units
uniform float liquid_depth;  // the medium's box, texture units
uniform float world_per_uv;  // world units per texture unit
uniform float ior;           // the medium's index of refraction (outside: 1)
uniform int linear_steps;
uniform int binary_steps;
uniform bool secant;

// The solid layer at a hit: its normal and colour there, lit from the
// light, seen along to_viewer.
vec3 shade_solid(vec2 uv, vec3 pos, vec3 to_viewer, vec2 dx, vec2 dy) {
    vec3 n = decode_normal(textureGrad(relief_map, uv, dx, dy));
    vec3 albedo = textureGrad(colour_map, uv, dx, dy).rgb;
    return blinn_phong(albedo, n, normalize(light - pos), to_viewer, ambient, specular);
}

void main() {
    vec2 uv = v_uv.xy;
    vec3 p = v_position.xyz;
    vec3 v = normalize(eye - p);  // tangent space = world space; v.z > 0
    vec2 dx = dFdx(uv);
    vec2 dy = dFdy(uv);
    // The view ray through both boxes, each from its top to its floor;
    // z is the depth below the polygon, in texture units.
    float t_solid = trace_height_field(relief_map, uv, -v.xy * (depth / v.z), dx, dy, linear_steps, binary_steps,
                                       secant);
    float t_liquid = trace_height_field(liquid_map, uv, -v.xy * (liquid_depth / v.z), dx, dy, linear_steps,
                                        binary_steps, secant);
    float z_solid = t_solid * depth;
    float z_liquid = t_liquid * liquid_depth;
    vec3 colour;
    if (z_solid <= z_liquid) {
        colour = shade_solid(uv - v.xy * (z_solid / v.z), p - v * (z_solid * world_per_uv / v.z), v, dx, dy);
    } else {
        vec2 at_uv = uv - v.xy * (z_liquid / v.z);
        vec3 at = p - v * (z_liquid * world_per_uv / v.z);
        vec3 n = decode_normal(textureGrad(liquid_map, at_uv, dx, dy));
        vec3 refracted = refract(-v, n, 1.0 / ior);
        vec3 reflected = reflect(-v, n);
        float cos_i = max(dot(n, v), 0.0);
        float cos_t = max(-dot(n, refracted), 0.0);
        // Total internal reflection (refract's zero vector) reflects all.
        float r = dot(refracted, refracted) == 0.0 ? 1.0 : fresnel_reflectance(1.0, ior, cos_i, cos_t);
        // The hit's height in the solid layer's units (1 at the top).
        float a = 1.0 - z_liquid / depth;
        bool hit;
        // Refraction: down to the solid layer's floor, which stops it.
        float down = (depth - z_liquid) / max(-refracted.z, 1e-4);
        vec2 down_offset = refracted.xy * down;
        float s = trace_segment(relief_map, at_uv, down_offset, a, -a, 1.0, dx, dy, linear_steps, binary_steps, secant,
                                hit);
        vec3 refraction = shade_solid(at_uv + down_offset * s, at + refracted * (s * down * world_per_uv),
                                      -refracted, dx, dy);
        // Reflection: up to the top of the box, meeting the solid layer on
        // the way or leaving for the environment.
        float up = z_liquid / max(reflected.z, 1e-4);
        vec2 up_offset = reflected.xy * up;
        float s_up = trace_segment(relief_map, at_uv, up_offset, a, 1.0 - a, 1.0, dx, dy, linear_steps, binary_steps,
                                   secant, hit);
        vec3 local = shade_solid(at_uv + up_offset * s_up, at + reflected * (s_up * up * world_per_uv), -reflected,
                                 dx, dy);
        vec3 reflection = hit ? local : textureLod(environment, reflected, 0.0).rgb;
        colour = (1.0 - r) * refraction + r * reflection;
    }
    frag_colour = vec4(colour, 1.0);
}
