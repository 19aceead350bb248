#version 450 core
// outputs_two.frag: two fragment outputs (issue 29), for a pass that draws
// into a level of one target and a level of another.
// Twin: kernels/conformance/outputs_two_frag.cpp.
layout(location = 0) in vec4 v_colour;
layout(location = 1) in vec4 v_uv;
layout(location = 0) out vec4 colour;
layout(location = 1) out vec4 coordinates;

uniform float exposure;

void main() {
    colour = vec4(v_colour.rgb * exposure, v_colour.a);
    coordinates = vec4(v_uv.xy, v_uv.x - v_uv.y, 1.0);
}
