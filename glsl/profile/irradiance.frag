#version 450 core
// irradiance.frag: the light entering the surface at each point of the
// texture-space target (Donner and Jensen Sec. 3): the directional light's
// irradiance times the boundary's transmittance (Fresnel, or rho_dt of a
// rough surface, Eq. 26), under the light's pattern. For thin geometry the
// same pass runs again with `back_offset` = the thickness: then each texel
// holds the light entering the other face, below the point along -normal
// and facing away, which the gather carries through with the transmittance
// profile. The pattern is the ground truth's sharp-edged light, a spot and a
// shadow edge on the plane of x and y (reference/profile_convolution.h):
// where either is given, only points inside the spot or beyond the edge are
// lit, each texel by the share of its footprint that is. Alpha 1 marks
// texels the mesh covers.
// Twin: kernels/profile/irradiance_frag.cpp.
#include "profile_optics.glsl"
layout(location = 0) in vec4 v_position;
layout(location = 1) in vec4 v_normal;
layout(location = 0) out vec4 frag_colour;
uniform vec3 light_direction;  // unit, towards the light
uniform vec3 light_irradiance; // on a surface facing the light, per channel
uniform float eta;
uniform int rough;             // 1: rho_dt from the table
uniform sampler2D rho_dt;
uniform float back_offset;     // 0: this face; the thickness: the other one
uniform vec4 spot;             // xy centre (mm), z radius; z <= 0: no spot
uniform vec4 edge;             // lit where dot(p.xy, edge.xy) > edge.z; w <= 0: no edge

// The lit share of a texel across the pattern's boundary, s the signed
// distance from it (> 0 lit): a box filter as wide as the texel's footprint
// across the boundary (|ds/dx| + |ds/dy| of a linear s), so that bilinear
// reads of the target put the edge where it is between texel centres, not
// at the nearest one.
float coverage(float s) {
    float w = max(fwidth(s), 1e-30);
    return min(max(s / w + 0.5, 0.0), 1.0);
}

float light_pattern(vec2 p) {
    float in_spot = spot.z > 0.0 ? coverage(spot.z - length(p - spot.xy)) : 0.0;
    // dot(p, edge.xy) - edge.z as NIR reassociates it (docs/llvmpipe/nir-algebraic.md).
    float beyond_edge = edge.w > 0.0 ? coverage(p.x * edge.x + (p.y * edge.y - edge.z)) : 0.0;
    bool patterned = spot.z > 0.0 || edge.w > 0.0;
    return patterned ? max(in_spot, beyond_edge) : 1.0;
}

void main() {
    vec3 n0 = normalize(v_normal.xyz);
    bool back = back_offset > 0.0;
    vec3 n = back ? -n0 : n0;
    vec3 p = v_position.xyz - back_offset * n0;
    float cos_i = max(dot(n, light_direction), 0.0);
    float t = transmittance_in(min(cos_i, 1.0), eta, rough == 1, rho_dt);
    float e = cos_i * t * light_pattern(p.xy);
    frag_colour = vec4(light_irradiance * e, 1.0);
}
