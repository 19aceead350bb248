#version 450 core
// surface.frag: the texture-space targets the gather reads besides the
// irradiance: channel 0 each texel's world position and the world area it
// covers (mm^2, from the derivatives across the target), channel 1 its
// unit normal. A thickness map displaces the position along the normal
// (the leaf's veins, scene/profile_thickness.h), which lengthens the
// gather's distances across them; `displacement` 0 leaves it as it is.
// Twin: kernels/profile/surface_frag.cpp.
layout(location = 0) in vec4 v_position;
layout(location = 1) in vec4 v_normal;
layout(location = 0) out vec4 frag_colour;
uniform int channel;
uniform sampler2D thickness_map;  // one texel per target texel; r in [0, 1]
uniform float displacement;       // mm at 1

void main() {
    vec3 p = v_position.xyz;
    if (displacement > 0.0) {
        float h = texelFetch(thickness_map, ivec2(gl_FragCoord.xy), 0).r;
        p = p + normalize(v_normal.xyz) * (displacement * h);
    }
    vec3 dpdx = dFdx(p);
    vec3 dpdy = dFdy(p);
    float area = length(cross(dpdx, dpdy));
    vec4 position_area = vec4(p, area);
    vec4 normal = vec4(normalize(v_normal.xyz), 1.0);
    frag_colour = channel == 0 ? position_area : normal;
}
