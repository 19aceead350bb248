#version 450 core
// derivatives.frag: dFdx, dFdy and fwidth of values the shader computes (a
// polynomial, its square and a step function), not only of inputs.
// Twin: kernels/conformance/derivatives_frag.cpp.
layout(location = 0) in vec4 v_colour;
layout(location = 1) in vec4 v_uv;
layout(location = 0) out vec4 frag_colour;
uniform float scale;

void main() {
    vec2 uv = v_uv.xy;
    float f = uv.x * uv.y * scale + uv.x * uv.x;
    vec2 g = vec2(dFdx(f), dFdy(f));
    float w = fwidth(f * f);
    float h = floor(f * 4.0);
    frag_colour = vec4(g * 10.0, w, dFdx(h) + dFdy(h) * 0.5);
}
