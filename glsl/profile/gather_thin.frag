#version 450 core
// gather_thin.frag: the gather pass of diffusion-profile rendering for
// thin geometry (parchment, a leaf, a slab a few mean free paths thick): both faces' light, the other face's through Eq. 27 with the normal reversed (profile_gather.glsl).
// The light leaves as a Lambertian exitance (L = M / pi: R(r) and T(r) are
// exitance profiles, the boundary's effect on leaving light is inside them),
// scaled by the texture convolved with the profile (Sec. 3.1); a rough
// surface adds its boundary's reflection (Eq. 23).
// Twin: kernels/profile/gather_thin_frag.cpp.
#include "profile_gather.glsl"
layout(location = 0) in vec4 v_position;
layout(location = 1) in vec4 v_normal;
layout(location = 2) in vec4 v_uv;
layout(location = 0) out vec4 frag_colour;
uniform sampler2D albedo;  // Sec. 3.1: convolved with the profile, mean white

void main() {
    vec3 n = normalize(v_normal.xyz);
    vec3 m = diffused_light(v_position.xyz, n, v_uv.xy, true);
    vec3 tex = texture(albedo, v_uv.xy).rgb;
    vec3 colour = m * tex * 0.31830988;
    if (rough == 1) colour = colour + surface_reflection(v_position.xyz, n);
    frag_colour = vec4(colour, 1.0);
}
