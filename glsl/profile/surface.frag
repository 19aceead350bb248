#version 450 core
// surface.frag: the texture-space targets the gather reads besides the
// irradiance: channel 0 each texel's world position and the world area it
// covers (mm^2, from the derivatives across the target), channel 1 its
// unit normal. Twin: kernels/profile/surface_frag.cpp.
layout(location = 0) in vec4 v_position;
layout(location = 1) in vec4 v_normal;
layout(location = 0) out vec4 frag_colour;
uniform int channel;

void main() {
    vec3 dpdx = dFdx(v_position.xyz);
    vec3 dpdy = dFdy(v_position.xyz);
    float area = length(cross(dpdx, dpdy));
    vec4 position_area = vec4(v_position.xyz, area);
    vec4 normal = vec4(normalize(v_normal.xyz), 1.0);
    frag_colour = channel == 0 ? position_area : normal;
}
