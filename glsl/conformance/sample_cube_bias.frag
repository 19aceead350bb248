#version 450 core
// sample_cube_bias.frag: texture() with a bias on a seamless cube map (the
// pixel's LOD from the quad plus the bias from the vertex colour's red).
// Twin: kernels/conformance/sample_cube_bias_frag.cpp.
layout(location = 0) in vec4 v_colour;
layout(location = 1) in vec4 v_uv;
layout(location = 0) out vec4 frag_colour;
uniform samplerCube env;
uniform float lod_min;
uniform float lod_max;

void main() {
    vec3 dir = vec3(v_uv.x, v_uv.y, v_colour.b * 2.0 - 1.0);
    float bias = lod_min + v_colour.r * (lod_max - lod_min);
    frag_colour = vec4(texture(env, dir, bias).rgb, 1.0);
}
