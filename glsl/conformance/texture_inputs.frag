#version 450 core
// texture_inputs.frag: built-ins of inputs chosen on the host, one per
// pixel, read exactly with texelFetch from a float texture (the scene's
// file, rgba32f), for inputs too rare to meet by enumerating bit patterns.
// `group` picks the function (one scene each):
//   0: atan(v), on the 8163 floats in [0, 1] where x^11 A11 and
//      (x^9 A11) x^2 round apart (docs/llvmpipe/glsl-builtins.md 3.5),
//      every other one negated
// Twin: kernels/conformance/texture_inputs_frag.cpp.
layout(location = 0) out vec4 frag_colour;
uniform sampler2D inputs;
uniform int group;

void main() {
    float v = texelFetch(inputs, ivec2(gl_FragCoord.xy), 0).r;
    frag_colour = vec4(atan(v), v, 0.0, 1.0);
}
