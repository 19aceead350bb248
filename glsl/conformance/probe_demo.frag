#version 450 core
// probe_demo.frag: the example of docs/commands.md's `probe`, and its test:
// the three rewrites the issue that asked for probes met (a*b + a*c
// factored, a matrix chain, mix with constant ends), one after another,
// each value marked with ST_PROBE. The twin's uniform `twin_breaks` (twin
// only; this program has none, GL ignores it) writes one of them as the
// GLSL reads instead of as llvmpipe runs it, and `shadertwin probe` must
// name that probe (cli.probe).
// Twin: kernels/conformance/probe_demo_frag.cpp.
#ifndef ST_PROBE
#define ST_PROBE(name, value)
#endif
layout(location = 0) out vec4 frag_colour;

float value(int index, int k) {
    int h = (index * (2 * k + 37) + k * 101) & 1023;
    int e = ((index >> (k & 7)) + k) & 15;
    return float(h - 512) * 0.0137 * intBitsToFloat((e + 121) << 23);
}

vec4 column(int index, int k) {
    return vec4(value(index, 4 * k), value(index, 4 * k + 1), value(index, 4 * k + 2), value(index, 4 * k + 3));
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    int index = p.y * 64 + p.x;
    vec3 colour = column(index, 0).xyz;
    vec3 diff = column(index, 1).xyz;
    float t = float(index & 1023) / 1023.0;
    ST_PROBE(t, t);
    vec3 lit = 0.1 * colour + diff * colour;
    ST_PROBE(lit, lit);
    mat4 A = mat4(column(index, 2), column(index, 3), column(index, 4), column(index, 5));
    mat4 B = mat4(column(index, 6), column(index, 7), column(index, 8), column(index, 9));
    mat4 C = mat4(column(index, 10), column(index, 11), column(index, 12), column(index, 13));
    vec4 projected = A * B * C * vec4(lit, 1.0);
    ST_PROBE(projected, projected);
    float layers = mix(32.0, 8.0, t);
    ST_PROBE(layers, layers);
    frag_colour = vec4(projected.xyz * layers, projected.w);
}
