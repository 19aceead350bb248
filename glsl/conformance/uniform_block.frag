#version 450 core
// uniform_block.frag: uniforms in two std140 blocks, one with an instance
// name (its members set as "Light.colour", ...) and one without ("tint",
// "gain[1]", ...): a vec3 followed by a float in one 16-byte slot, a vec2
// after them, an array of floats 16 bytes apart, an int. The GL side fills
// each block's buffer at the offsets GL reports (gl/uniform_blocks.h); the
// result mixes every member with the pixel, so a member in the wrong place
// shows.
// Twin: kernels/conformance/uniform_block_frag.cpp.
layout(location = 0) in vec4 v_colour;
layout(location = 1) in vec4 v_uv;
layout(location = 0) out vec4 frag_colour;

layout(std140) uniform Light {
    vec3 colour;
    float power;
    vec2 offset;
} light;

layout(std140) uniform Params {
    vec4 tint;
    float gain[3];
    int count;
};

void main() {
    vec2 p = v_uv.xy + light.offset;
    float g = gain[0] * p.x + gain[1] * p.y + gain[2];
    vec3 c = light.colour * light.power * g;
    frag_colour = vec4(c, float(count)) * tint * v_colour;
}
