#version 450 core
// texel_fetch.frag: texelFetch() at every level and outside the chain and
// the level's bounds (which read 0), and textureSize() of a per-pixel
// level (llvmpipe takes lane 0's for its 8-lane vector).
// Twin: kernels/conformance/texel_fetch_frag.cpp.
layout(location = 0) in vec4 v_colour;
layout(location = 1) in vec4 v_uv;
layout(location = 0) out vec4 frag_colour;
uniform sampler2D tex;

void main() {
    int level = int(v_colour.r * 7.0) - 1;
    ivec2 p = ivec2(gl_FragCoord.xy) / 2 - ivec2(3, 2);
    vec4 t = texelFetch(tex, p, level);
    ivec2 size = textureSize(tex, level);
    frag_colour = vec4(t.rg, t.b + t.a, float(size.x) + float(size.y) * 0.001);
}
