#version 450 core
// loop_exit.frag: a search loop whose lanes leave at different passes and
// sample a texture inside it: step along `dir` until a texel's alpha, scaled
// by the vertex colour, passes `threshold`. Lanes that have left keep their
// values while their neighbours go on (docs/llvmpipe/lanes-and-control-flow.md §4).
// Twin: kernels/conformance/loop_exit_frag.cpp.
layout(location = 0) in vec4 v_colour;
layout(location = 1) in vec4 v_uv;
layout(location = 0) out vec4 frag_colour;
uniform sampler2D tex;
uniform int steps;
uniform vec2 dir;
uniform float threshold;

void main() {
    vec2 uv = v_uv.xy;
    float t = 0.0;
    vec4 hit = vec4(0.0);
    for (int i = 0; i < steps; ++i) {
        vec4 c = texture(tex, uv + dir * t);
        if (c.a * v_colour.g > threshold) {
            hit = c;
            break;
        }
        t += 1.0;
    }
    frag_colour = vec4(hit.rgb, t / float(steps));
}
