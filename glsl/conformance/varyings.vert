#version 450 core
// varyings.vert: a fragment input of each interpolation qualifier (smooth,
// noperspective, flat float, flat int and uint) carried through triangles
// that the view volume clips (varyings.frag shows them). A corner's clip
// position is its pixel position scaled by `reach` about the target's
// centre (reach > 1 pushes corners past the sides), moved in depth by -uv.y
// (uv.y = 2 puts it behind the near plane, -2 beyond the far one) and
// multiplied by its own w, uv.x, so that perspective-correct and
// window-linear interpolation differ and clipping makes new vertices.
// colour.w is the corner's index (three per triangle), so that every corner
// of a triangle carries other flat values and the provoking one shows.
// Twin: kernels/conformance/varyings_vert.cpp.
layout(location = 0) in vec4 position;
layout(location = 1) in vec4 colour;
layout(location = 2) in vec4 uv;
layout(location = 0) out vec4 v_smooth;
layout(location = 1) noperspective out vec4 v_linear;
layout(location = 2) flat out ivec4 v_bits;
layout(location = 3) flat out vec4 v_flat;
layout(location = 4) flat out uvec2 v_index;
uniform float reach;

// Bits that no arithmetic may touch on the way: a signalling NaN and a
// negative quiet one with a payload, both infinities, -0, the smallest
// denormal, the largest negative one, 1.
const int patterns[8] = int[8](0x7F800001, int(0xFFC0ABCD), 0x7F800000, int(0xFF800000), int(0x80000000),
                               0x00000001, int(0x807FFFFF), 0x3F800000);

void main() {
    float w = uv.x;
    gl_Position = vec4(position.xy * reach * w, (position.z - uv.y) * w, w);
    int i = int(colour.w);
    v_smooth = colour;
    v_linear = colour;
    v_bits = ivec4(patterns[i & 7], patterns[(i >> 3) & 7] ^ (i << 8), i * 0x010101, -i);
    v_flat = vec4(intBitsToFloat(patterns[(i + 2) & 7]), colour.xy, intBitsToFloat(patterns[(i + 5) & 7] ^ (i << 4)));
    v_index = uvec2(uint(i), uint(i) * 2654435761u);
}
