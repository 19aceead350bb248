#version 450 core
// sample_cube.frag: texture() on a seamless cube map with mips: directions
// that cross every face, its edges and its corners; the LOD comes per pixel
// from the quad's derivatives of the direction.
// Twin: kernels/conformance/sample_cube_frag.cpp.
layout(location = 0) in vec4 v_colour;
layout(location = 1) in vec4 v_uv;
layout(location = 0) out vec4 frag_colour;
uniform samplerCube env;

void main() {
    vec3 dir = vec3(v_uv.x, v_uv.y, v_colour.b * 2.0 - 1.0);
    frag_colour = vec4(texture(env, dir).rgb, 1.0);
}
