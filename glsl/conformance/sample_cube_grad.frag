#version 450 core
// sample_cube_grad.frag: textureGrad() on a seamless cube map with the
// direction's derivatives scaled per pixel.
// Twin: kernels/conformance/sample_cube_grad_frag.cpp.
layout(location = 0) in vec4 v_colour;
layout(location = 1) in vec4 v_uv;
layout(location = 0) out vec4 frag_colour;
uniform samplerCube env;
uniform float grad_scale;

void main() {
    vec3 dir = vec3(v_uv.x, v_uv.y, v_colour.b * 2.0 - 1.0);
    vec3 dx = dFdx(dir) * (v_colour.r * grad_scale);
    vec3 dy = dFdy(dir) * (v_colour.r * grad_scale);
    frag_colour = vec4(textureGrad(env, dir, dx, dy).rgb, 1.0);
}
