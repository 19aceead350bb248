#version 450 core
// bloom_bright.frag: light blooming (Timonen Sec. 3.2), first pass: the HDR
// part of the rendered frame, "separated ... using a square root based value
// controlling". Read here as sqrt(max(c - threshold, 0)) per channel: what
// exceeds the display's range, compressed so that a sun a hundred times
// brighter than white blooms wider, not a hundred times brighter
// (docs/relief.md). Twin: kernels/relief/bloom_bright_frag.cpp.
layout(location = 0) in vec4 v_colour;
layout(location = 1) in vec4 v_uv;
layout(location = 0) out vec4 frag_colour;
uniform sampler2D hdr;
uniform float threshold;

void main() {
    vec3 c = texture(hdr, v_uv.xy).rgb;
    frag_colour = vec4(sqrt(max(c - vec3(threshold), vec3(0.0))), 1.0);
}
