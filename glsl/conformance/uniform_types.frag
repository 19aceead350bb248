#version 450 core
// uniform_types.frag: uniforms of the kinds shaders as they ship declare
// (issue 29): an array read at a constant and at a per-pixel index, an array
// of structs read at a per-pixel index, int, uint, bool, bvec2, ivec3 and
// uvec2, mat2, mat3 and the non-square mat2x3, mat3x2 and mat4x3, and a
// std140 block (binding 2) whose members mix those types (a bool, a uvec2, a float
// array 16 bytes apart, a mat3 and a mat2x3 at their std140 strides). The
// pixel's column picks one of twelve groups, each writing a few of the
// values untouched or through one matrix product, so a value read from the
// wrong place shows where it is read.
// Twin: kernels/conformance/uniform_types_frag.cpp.
layout(location = 0) in vec4 v_colour;
layout(location = 1) in vec4 v_uv;
layout(location = 0) out vec4 frag_colour;

struct Light {
    vec3 colour;
    float power;
    int kind;
    bool on;
};

uniform vec3 palette[4];
uniform Light lights[2];
uniform int count;
uniform uint mask;
uniform bool flip;
uniform bvec2 axes;
uniform ivec3 steps;
uniform uvec2 bits;
uniform mat2 rot;
uniform mat3 basis;
uniform mat2x3 skew;
uniform mat3x2 squash;
uniform mat4x3 affine;

layout(std140, binding = 2) uniform Mixed {
    float a;
    vec3 b;
    int c;
    mat3 d;
    bool e;
    uvec2 f;
    float g[3];
    mat2x3 h;
} mixed;

void main() {
    int cell = int(v_uv.x * 12.0);
    int i = cell & 3;         // a per-pixel index into palette
    int l = (cell >> 2) & 1;  // and into lights
    vec2 p = v_uv.xy;
    vec4 r;
    if (cell == 0) r = vec4(palette[1], 1.0);
    else if (cell == 1) r = vec4(palette[i], float(i));
    else if (cell == 2) r = vec4(lights[l].colour, lights[l].power);
    else if (cell == 3) r = vec4(float(lights[l].kind), lights[l].on ? 1.0 : 0.0, float(count), float(mask & 0xFFFFu));
    else if (cell == 4) r = vec4(rot * p, vec2(axes));
    else if (cell == 5) r = vec4(basis * vec3(p, v_colour.x), float(steps.y));
    else if (cell == 6) r = vec4(skew * p, (squash * vec3(p, v_colour.y)).x);
    else if (cell == 7) r = vec4(affine * vec4(p, v_colour.xy), flip ? -1.0 : 1.0);
    else if (cell == 8) r = vec4(mixed.b, mixed.a);
    else if (cell == 9) r = vec4(mixed.d * vec3(p, v_colour.z), float(mixed.c));
    else if (cell == 10) r = vec4(mixed.e ? mixed.g[1] : mixed.g[2], float(mixed.f.x & 0xFFFFu), float(mixed.f.y >> 16), mixed.g[0]);
    else r = vec4(mixed.h * p, float(bits.x & 0xFFFFu) + float(steps.z));
    frag_colour = r * v_colour;
}
