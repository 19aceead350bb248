#version 450 core
// loop_budget.frag: llvmpipe's one budget of 65535 loop passes per 8-lane
// vector and invocation. Two chosen pixels loop `long_steps` times, which
// spends their vector's budget (also when the pixel is an uncovered helper
// lane), so the short loop after it runs once in that vector and
// `short_steps` times everywhere else.
// Twin: kernels/conformance/loop_budget_frag.cpp.
layout(location = 0) out vec4 frag_colour;
uniform int long_steps;
uniform int short_steps;
uniform vec2 slow_a;
uniform vec2 slow_b;

void main() {
    vec2 p = floor(gl_FragCoord.xy);
    bool slow = (p.x == slow_a.x && p.y == slow_a.y) || (p.x == slow_b.x && p.y == slow_b.y);
    int n = slow ? long_steps : short_steps;
    float a = 0.0;
    for (int i = 0; i < n; ++i) {
        a += 1.0;
    }
    float b = 0.0;
    for (int j = 0; j < short_steps; ++j) {
        b += 1.0;
    }
    frag_colour = vec4(a / 65536.0, b / float(short_steps), 0.25, 1.0);
}
