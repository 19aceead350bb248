#version 450 core
// non_finite.frag: a shader that writes infinities and NaNs (x / 0 and
// 0 / 0 with x from the varyings), and compares against a NaN, which GLSL's
// ordered < is false for and != true. The twin must write the same bits.
// Twin: kernels/conformance/non_finite_frag.cpp.
layout(location = 0) in vec4 v_colour;
layout(location = 1) in vec4 v_uv;
layout(location = 0) out vec4 frag_colour;
uniform float zero;

void main() {
    vec2 uv = v_uv.xy - 0.5;
    float inf = uv.x / zero;
    float nan = uv.y * zero / zero;
    float picked = nan < 1.0 ? 1.0 : 2.0;
    float differs = nan != nan ? 4.0 : 8.0;
    frag_colour = vec4(inf, nan, picked + differs, uv.x * inf);
}
