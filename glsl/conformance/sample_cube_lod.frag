#version 450 core
// sample_cube_lod.frag: textureLod() on a seamless cube map, the LOD from
// the vertex colour's red channel mapped to [lod_min, lod_max].
// Twin: kernels/conformance/sample_cube_lod_frag.cpp.
layout(location = 0) in vec4 v_colour;
layout(location = 1) in vec4 v_uv;
layout(location = 0) out vec4 frag_colour;
uniform samplerCube env;
uniform float lod_min;
uniform float lod_max;

void main() {
    vec3 dir = vec3(v_uv.x, v_uv.y, v_colour.b * 2.0 - 1.0);
    float lod = lod_min + v_colour.r * (lod_max - lod_min);
    frag_colour = vec4(textureLod(env, dir, lod).rgb, 1.0);
}
