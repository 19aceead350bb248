#version 450 core
// sample_implicit.frag: texture() with the LOD llvmpipe derives from each
// 2x2 quad, times the vertex colour: level selection, mip filters, wraps and
// formats, magnified and minified.
// Twin: kernels/conformance/sample_implicit_frag.cpp.
layout(location = 0) in vec4 v_colour;
layout(location = 1) in vec4 v_uv;
layout(location = 0) out vec4 frag_colour;
uniform sampler2D tex;

void main() {
    frag_colour = texture(tex, v_uv.xy) * v_colour;
}
