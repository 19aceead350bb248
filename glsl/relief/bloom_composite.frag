#version 450 core
// bloom_composite.frag: light blooming (Timonen Sec. 3.2), last pass: the
// blurred HDR part, up-sampled bilinearly, added back to the frame's
// displayable part. Twin: kernels/relief/bloom_composite_frag.cpp.
layout(location = 0) in vec4 v_colour;
layout(location = 1) in vec4 v_uv;
layout(location = 0) out vec4 frag_colour;
uniform sampler2D hdr;
uniform sampler2D bloom;
uniform float strength;

void main() {
    vec2 uv = v_uv.xy;
    vec3 ldr = min(texture(hdr, uv).rgb, vec3(1.0));
    frag_colour = vec4(ldr + strength * texture(bloom, uv).rgb, 1.0);
}
