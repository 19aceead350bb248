#version 450 core
// thin_slab_lit.frag: fragment stage of the `vertex` and `host` variants:
// interpolated radiance times the flag's texel, interpolated alpha.
// Twin: kernels/thin_slab/thin_slab_lit_frag.cpp.
layout(location = 0) in vec4 v_radiance;
layout(location = 1) in vec4 v_uv;
layout(location = 0) out vec4 frag_colour;
uniform sampler2D flag;

void main() {
    vec3 texel = texture(flag, v_uv.xy).rgb;
    frag_colour = vec4(v_radiance.rgb * texel, v_radiance.a);
}
