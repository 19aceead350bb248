#version 450 core
// varyings.frag: the inputs of varyings.vert, one qualifier per scene
// (`show`):
//   0: the flat ivec4's bits           1: the flat vec4 as it arrives
//   2: the noperspective vec4          3: the smooth vec4
//   4: one of each in one pixel: smooth x, noperspective y, a flat int
//      after an integer add, a flat uint's bits
// Every input is read whatever `show` says, so each scene interpolates
// all five slots, as llvmpipe does.
// Twin: kernels/conformance/varyings_frag.cpp.
layout(location = 0) in vec4 v_smooth;
layout(location = 1) noperspective in vec4 v_linear;
layout(location = 2) flat in ivec4 v_bits;
layout(location = 3) flat in vec4 v_flat;
layout(location = 4) flat in uvec2 v_index;
layout(location = 0) out vec4 frag_colour;
uniform int show;

void main() {
    if (show == 0) {
        frag_colour = intBitsToFloat(v_bits);
    } else if (show == 1) {
        frag_colour = v_flat;
    } else if (show == 2) {
        frag_colour = v_linear;
    } else if (show == 3) {
        frag_colour = v_smooth;
    } else {
        frag_colour = vec4(v_smooth.x, v_linear.y, intBitsToFloat(v_bits.y + 1), uintBitsToFloat(v_index.y));
    }
}
