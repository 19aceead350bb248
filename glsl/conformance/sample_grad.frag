#version 450 core
// sample_grad.frag: textureGrad() with derivatives the shader scales per
// pixel, so each lane has its own LOD and anisotropy.
// Twin: kernels/conformance/sample_grad_frag.cpp.
layout(location = 0) in vec4 v_colour;
layout(location = 1) in vec4 v_uv;
layout(location = 0) out vec4 frag_colour;
uniform sampler2D tex;
uniform float grad_scale;

void main() {
    vec2 uv = v_uv.xy;
    vec2 dx = dFdx(uv) * (v_colour.r * grad_scale);
    vec2 dy = dFdy(uv) * (v_colour.g * grad_scale);
    frag_colour = vec4(textureGrad(tex, uv, dx, dy).rgb, 1.0);
}
