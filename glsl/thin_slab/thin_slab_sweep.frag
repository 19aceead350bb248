#version 450 core
// thin_slab_sweep.frag: evaluates the thin-slab model at inputs stored per
// pixel, for the sweeps over tau1 and mu (docs/thin-slab.md). Output:
// r = Eq. 4 bracket, g = Eq. 5 bracket, b = alpha, a = 1 - exp(-tau1).
// Twin: kernels/thin_slab/thin_slab_sweep_frag.cpp.
#include "thin_slab_model.glsl"
layout(location = 0) out vec4 frag_colour;
uniform sampler2D inputs;  // r = tau1, g = mu, b = mu0

void main() {
    vec4 p = texelFetch(inputs, ivec2(gl_FragCoord.xy), 0);
    float mu = max(p.g, MU_MIN);
    float mu0 = max(p.b, MU_MIN);
    frag_colour = vec4(frontlit_factor(p.r, mu, mu0), backlit_factor(p.r, mu, mu0), exp(-p.r / mu),
                       one_minus_exp_neg(p.r));
}
