#version 450 core
// discard.frag: pixels discard on a pattern, one of them inside a loop; a
// discarded pixel writes neither colour nor depth, and leaves the loop at
// the end of its pass.
// Twin: kernels/conformance/discard_frag.cpp.
layout(location = 0) in vec4 v_colour;
layout(location = 1) in vec4 v_uv;
layout(location = 0) out vec4 frag_colour;
uniform int steps;

void main() {
    vec2 uv = v_uv.xy;
    if (uv.x > uv.y * 1.5) discard;
    float s = 0.0;
    for (int i = 0; i < steps; ++i) {
        s += uv.x;
        if (s > 2.0 + uv.y) discard;
    }
    frag_colour = vec4(v_colour.rgb * s, 1.0);
}
