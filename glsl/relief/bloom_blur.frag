#version 450 core
// bloom_blur.frag: light blooming (Timonen Sec. 3.2), the Gaussian blur of the
// down-sampled HDR part, one axis per pass (texel_step is one texel along
// it): nine taps, sigma 2 texels, weights exp(-i^2 / 8) normalised to sum
// 1. Twin: kernels/relief/bloom_blur_frag.cpp.
layout(location = 0) in vec4 v_colour;
layout(location = 1) in vec4 v_uv;
layout(location = 0) out vec4 frag_colour;
uniform sampler2D src;
uniform vec2 texel_step;

const float w0 = 0.20416369;
const float w1 = 0.18017382;
const float w2 = 0.12383154;
const float w3 = 0.06628225;
const float w4 = 0.02763055;

vec3 pair(vec2 uv, float k) {
    return texture(src, uv - k * texel_step).rgb + texture(src, uv + k * texel_step).rgb;
}

void main() {
    vec2 uv = v_uv.xy;
    vec3 c = w0 * texture(src, uv).rgb;
    c = c + w1 * pair(uv, 1.0);
    c = c + w2 * pair(uv, 2.0);
    c = c + w3 * pair(uv, 3.0);
    c = c + w4 * pair(uv, 4.0);
    frag_colour = vec4(c, 1.0);
}
