#version 450 core
// branch_texture.frag: texture reads on both sides of a divergent branch,
// from two textures of different formats and filters. llvmpipe runs both
// sides on every lane and keeps each lane's own side.
// Twin: kernels/conformance/branch_texture_frag.cpp.
layout(location = 0) in vec4 v_colour;
layout(location = 1) in vec4 v_uv;
layout(location = 0) out vec4 frag_colour;
uniform sampler2D tex_a;
uniform sampler2D tex_b;
uniform float split;

void main() {
    vec2 uv = v_uv.xy;
    vec4 c = vec4(0.0);
    if (uv.x * uv.x + uv.y > split) {
        c = texture(tex_a, uv * 3.0);
    } else {
        c = texture(tex_b, uv.yx + 0.25) * v_colour;
    }
    frag_colour = c;
}
