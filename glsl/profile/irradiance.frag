#version 450 core
// irradiance.frag: the light entering the surface at each point of the
// texture-space target (Donner and Jensen Sec. 3): the directional light's
// irradiance times the boundary's transmittance (Fresnel, or rho_dt of a
// rough surface, Eq. 26), under the light's pattern. For thin geometry the
// same pass runs again with `back_offset` = the thickness: then each texel
// holds the light entering the other face, below the point along -normal
// and facing away, which the gather carries through with the transmittance
// profile. The pattern is the ground truth's sharp-edged light, a spot and a
// shadow edge (light_pattern, profile_optics.glsl), each texel lit by the
// share of its footprint that is. Alpha 1 marks
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

void main() {
    vec3 n0 = normalize(v_normal.xyz);
    bool back = back_offset > 0.0;
    vec3 n = back ? -n0 : n0;
    vec3 p = v_position.xyz - back_offset * n0;
    float cos_i = max(dot(n, light_direction), 0.0);
    float t = transmittance_in(min(cos_i, 1.0), eta, rough == 1, rho_dt);
    float e = cos_i * t * light_pattern(p.xy, spot, edge);
    frag_colour = vec4(light_irradiance * e, 1.0);
}
