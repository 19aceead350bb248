#version 450 core
// background.frag: the background painting, as it is.
// Twin: kernels/thin_slab/background_frag.cpp.
layout(location = 0) in vec4 v_uv;
layout(location = 0) out vec4 frag_colour;
uniform sampler2D painting;

void main() {
    frag_colour = texture(painting, v_uv.xy);
}
