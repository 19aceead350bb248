// thin_slab_uniforms.cpp: the uniforms the thin-slab twins share.
#include "kernels/thin_slab/thin_slab.h"

namespace st {

void ThinSlabUniforms::read(const Bindings& b, bool with_tau1) {
    eye = b.get_vec3("eye");
    light = b.get_vec3("light");
    power = b.get_float("power");
    albedo = b.get_vec3("albedo");
    if (with_tau1) tau1 = b.get_float("tau1");
}

}  // namespace st
