#version 450 core
// textured.frag: the interpolated colour times a bilinear (or nearest) texel.
// Twin: kernels/triangles/textured_frag.cpp.
layout(location = 0) in vec4 v_colour;
layout(location = 1) in vec4 v_uv;
layout(location = 0) out vec4 frag_colour;
uniform sampler2D tex;

void main() {
    frag_colour = v_colour * texture(tex, v_uv.xy);
}
