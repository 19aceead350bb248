#version 450 core
// sample_lod.frag: textureLod() with a LOD per pixel, from the vertex
// colour's red channel mapped to [lod_min, lod_max], through level
// boundaries and below the base and past the last level.
// Twin: kernels/conformance/sample_lod_frag.cpp.
layout(location = 0) in vec4 v_colour;
layout(location = 1) in vec4 v_uv;
layout(location = 0) out vec4 frag_colour;
uniform sampler2D tex;
uniform float lod_min;
uniform float lod_max;

void main() {
    float lod = lod_min + v_colour.r * (lod_max - lod_min);
    frag_colour = vec4(textureLod(tex, v_uv.xy, lod).rgb, 1.0);
}
