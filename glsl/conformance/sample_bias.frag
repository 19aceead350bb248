#version 450 core
// sample_bias.frag: texture() with a bias per pixel (the quad's LOD plus
// the lane's bias, which also turns off llvmpipe's NEAREST shortcut).
// Twin: kernels/conformance/sample_bias_frag.cpp.
layout(location = 0) in vec4 v_colour;
layout(location = 1) in vec4 v_uv;
layout(location = 0) out vec4 frag_colour;
uniform sampler2D tex;
uniform float lod_min;
uniform float lod_max;

void main() {
    float bias = lod_min + v_colour.r * (lod_max - lod_min);
    frag_colour = vec4(texture(tex, v_uv.xy, bias).rgb, 1.0);
}
