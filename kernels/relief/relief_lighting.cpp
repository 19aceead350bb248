// relief_lighting.cpp: the uniforms the relief twins share.
#include "kernels/relief/relief.h"

namespace st {

void ReliefLighting::read(const Bindings& b) {
    relief_map = &b.sampler("relief_map");
    colour_map = &b.sampler("colour_map");
    eye = b.get_vec3("eye");
    light = b.get_vec3("light");
    ambient = b.get_float("ambient");
    specular = b.get_float("specular");
}

}  // namespace st
