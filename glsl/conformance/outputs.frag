#version 450 core
// outputs.frag: three fragment outputs into three targets of one pass
// (issue 29): location 0 the pass's colour buffer, 1 and 2 the targets its
// `outputs` name, each of its own format; blending, the depth test and
// discard apply to all three alike.
// Twin: kernels/conformance/outputs_frag.cpp.
layout(location = 0) in vec4 v_colour;
layout(location = 1) in vec4 v_uv;
layout(location = 0) out vec4 albedo;
layout(location = 1) out vec4 normal;
layout(location = 2) out vec4 bright;

uniform float exposure;
uniform float cut;

void main() {
    if (v_uv.x > cut) discard;
    albedo = v_colour;
    normal = vec4(v_uv.xy * 2.0 - 1.0, v_uv.x * v_uv.y, 0.75);
    bright = vec4(v_colour.rgb * exposure, v_uv.y);
}
