#version 450 core
// wrap.frag: wrap lighting (Green, "Real-time approximations to subsurface
// scattering", GPU Gems, 2004): the diffuse term (N.L + w) / (1 + w) lets
// light reach past the terminator, and what it adds there is tinted, as
// light that travelled under the surface is. Twin: kernels/wrap_frag.cpp.
layout(location = 0) in vec4 v_normal;
layout(location = 0) out vec4 frag_colour;
uniform vec3 light_dir;  // towards the light, unit length
uniform vec3 albedo;
uniform vec3 scatter_tint;
uniform float wrap;      // 0: Lambert; 1: light reaches the far pole

void main() {
    vec3 n = normalize(v_normal.xyz);
    float n_dot_l = dot(n, light_dir);
    float lambert = max(n_dot_l, 0.0);
    float wrapped = max((n_dot_l + wrap) / (1.0 + wrap), 0.0);
    vec3 colour = albedo * lambert + scatter_tint * (wrapped - lambert);
    frag_colour = vec4(colour, 1.0);
}
